#pragma once
// Visemes (paper §5.2: "every phoneme corresponds to a different lip position"): a set of mouth
// shapes and which phonemes show each one, with how each blends into its neighbours — the
// dominance α of its coarticulation curve (anim::Curve::dominance, eq. 3), its weight, and its
// spread: how far past its phoneme it reaches, as a fraction of the phoneme's length on each
// side. Three sets are built in: MPEG-4's 14 (the face's own viseme channels), the Oculus 15
// and the SAPI 21 (Microsoft's). Each viseme names the MPEG-4 viseme it shows as on a face of
// MPEG-4 channels — the built-in humanoid, and a model whose morph targets the faces mapping
// drives from those channels — so any set speaks on any face. A set is data, read and written as
// a versioned JSON document ("thespis-visemes"), so a studio can show and edit it.

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "util/error.h"

namespace thespis::core::speech {

inline constexpr std::string_view kVisemeSetFormat = "thespis-visemes";
/// Version 2 adds each viseme's "mpeg4" (version 1 sets are upgraded: parseVisemeSet).
inline constexpr int kVisemeSetVersion = 2;

struct Viseme {
    int id = 0;               ///< 0 is silence; MPEG-4's are 1 … 14
    std::string name;         ///< "p_b_m", "PP", …
    double alpha = 4;         ///< dominance: larger keeps the shape to its own phoneme
    double weight = 1;        ///< how far the shape is reached at the phoneme's centre
    double spread = 0.5;      ///< reach past the phoneme, a fraction of its length on each side
    int mpeg4 = 0;            ///< the MPEG-4 viseme (1 … 14) it shows as on the face; 0: the mouth at rest
    bool operator==(const Viseme&) const = default;
};

struct VisemeSet {
    std::string name;                                     ///< "mpeg4", "oculus", "sapi" or the user's
    std::vector<Viseme> visemes;                          ///< by id, silence (0) included
    std::map<std::string, std::vector<int>> phonemes;     ///< ARPAbet → viseme ids, in the order shown
    bool operator==(const VisemeSet&) const = default;

    const Viseme* find(int id) const;
    /// The visemes `phoneme` (ARPAbet, any case, stress digits ignored) shows; {0} for a pause and
    /// for a phoneme the set leaves out.
    std::vector<int> visemesOf(std::string_view phoneme) const;
    /// Every rule the set must keep, naming the field (and the viseme by its name): ids unique,
    /// 0 … 99, names set, α > 0, weight in 0 … 1, spread in 0 … 2, mpeg4 in 0 … 14, phonemes
    /// ARPAbet and naming visemes the set has.
    Result<void> validate() const;
};

/// MPEG-4's 14 visemes (ISO/IEC 14496-2, FAP 1; ids = the face's viseme channels).
const VisemeSet& mpeg4Visemes();
/// The Oculus Lipsync 15 (sil, PP, FF, TH, DD, kk, CH, SS, nn, RR, aa, E, ih, oh, ou).
const VisemeSet& oculusVisemes();
/// SAPI's 21 (0 silence … 21 p/b/m), as Microsoft's speech services number them.
const VisemeSet& sapiVisemes();
/// A built-in set by name ("mpeg4", "oculus", "sapi"), or nullptr.
const VisemeSet* builtInVisemeSet(std::string_view name);

/// The MPEG-4 viseme of an ARPAbet phoneme (0 for a pause): the number timing files show.
int mpeg4Viseme(std::string_view phoneme);

std::string serializeVisemeSet(const VisemeSet& set);
/// CorruptData naming the field path ("visemes[3].alpha: must be greater than 0"). A version 1
/// set, which had no "mpeg4", is upgraded: a built-in set's name gives its visemes' (a copy of
/// the SAPI set keeps showing as the SAPI set does), otherwise a viseme shows as the MPEG-4
/// viseme of its id — as version 1 showed it — or at rest when its id is above 14.
Result<VisemeSet> parseVisemeSet(std::string_view text);
Result<VisemeSet> loadVisemeSet(const std::filesystem::path& path);
/// Atomic.
Result<void> saveVisemeSet(const std::filesystem::path& path, const VisemeSet& set);

} // namespace thespis::core::speech
