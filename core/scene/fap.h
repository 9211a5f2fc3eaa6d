#pragma once
// MPEG-4 face animation (ISO/IEC 14496-2, Annex C; paper §4.2, §5.2): the 68 facial animation
// parameters (FAPs), the units they are measured in (FAPU, taken from the neutral face's feature
// points) and the face channels a face frame holds. A face frame (anim::FrameLayout::mpeg4Face)
// is fap1 … fap68 followed by the weights of the 14 visemes and the 6 expressions: FAP 1 and
// FAP 2 are MPEG-4's high-level parameters, which select a viseme or an expression and blend
// two of them; as blendable weights (one channel per viseme and per expression) any number blend,
// and a face expands them into low-level FAPs through its tables (face_tables.h), or drives its
// own viseme and expression targets with them (a glTF model's `viseme_PP`, `Angry`).

#include <array>
#include <optional>
#include <string_view>

namespace thespis::core::scene {

inline constexpr int kFapCount = 68;
inline constexpr int kVisemeCount = 14;    ///< MPEG-4 visemes 1 … 14 (0 is "none")
inline constexpr int kExpressionCount = 6; ///< joy, sadness, anger, fear, disgust, surprise
inline constexpr int kFaceChannelCount = kFapCount + kVisemeCount + kExpressionCount;

/// The channel (scalar index in a face frame) of FAP `number` (1 … 68).
constexpr int fapChannel(int number) { return number - 1; }
/// The channel of viseme `number` (1 … 14).
constexpr int visemeChannel(int number) { return kFapCount + number - 1; }
/// The channel of expression `number` (1 … 6).
constexpr int expressionChannel(int number) { return kFapCount + kVisemeCount + number - 1; }

/// The units FAPs are measured in: each a face distance divided by 1024 (AU: 1e-5 radian).
enum class FapUnit : unsigned char {
    None,  ///< FAPs 1 and 2 (high level)
    IRISD, ///< iris diameter: the distance between the upper and lower eyelid at rest
    ES,    ///< eye separation: between the pupils
    ENS,   ///< eye – nose separation: from the eyes' height to the nose's bottom
    MNS,   ///< mouth – nose separation
    MW,    ///< mouth width
    AU     ///< angle unit, 1e-5 rad
};

/// "IRISD", "ES", "ENS", "MNS", "MW", "AU", or "" for None.
std::string_view fapUnitName(FapUnit unit);

/// A face's FAP units, in metres per FAP unit (the distances over 1024); AU is fixed.
struct FapUnits {
    double irisd = 0, es = 0, ens = 0, mns = 0, mw = 0;
    static constexpr double au = 1e-5;
    /// Metres (radians for AU) per unit of `unit`; 0 for None.
    double of(FapUnit unit) const;
};

struct FapInfo {
    int number;                 ///< 1 … 68
    std::string_view name;      ///< the standard's name: "open_jaw", "close_t_l_eyelid" …
    FapUnit unit;
    bool bidirectional;         ///< false: only positive values are meaningful
    std::string_view direction; ///< of positive motion: "down", "up", "left", "right", "forward" …
    std::string_view featurePoint; ///< the feature point it moves ("2.1"), "" when none
};

/// FAP `number` (1 … 68).
const FapInfo& fapInfo(int number);
/// A FAP by its name ("open_jaw") or as "fapN"; nullopt when unknown.
std::optional<int> findFap(std::string_view name);

/// MPEG-4's viseme names (1 … 14): "p_b_m", "f_v", "T_D", "t_d", "k_g", "tS_dZ_S", "s_z",
/// "n_l", "r", "A:", "e", "I", "Q", "U".
std::string_view visemeName(int number);
/// "joy", "sadness", "anger", "fear", "disgust", "surprise" (1 … 6).
std::string_view expressionName(int number);
std::optional<int> findExpression(std::string_view name);

/// The face channel named `name` in a face frame ("fap3", "open_jaw", "viseme1",
/// "expression2", "sadness"), or nullopt.
std::optional<int> findFaceChannel(std::string_view name);

} // namespace thespis::core::scene
