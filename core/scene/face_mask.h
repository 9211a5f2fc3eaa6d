#pragma once
// Face-region masks (paper §5.2: face layers are weighted per FAP region — speech high on the
// mouth, expressions high on the eyes and brows): the face's counterpart of a joint mask. A face
// mask is an anim::JointMask over the face layout (anim::FrameLayout::mpeg4Face) that names the
// face's regions ("mouth", "eyes", "brows" …) and, where one channel differs from its region, the
// channel ("fap19", "viseme3", "expression1"); a channel it does not name takes its region's
// weight, a region it does not name the mask's default. It is stored, shared and edited like any
// other mask (Scenario::masks).
//
// The visemes' weights are in the mouth region. An expression given as its weight (expressionN)
// is one channel, in the "expressions" region: it scales as a whole. An expression recorded as
// FAPs (the face pose editor's clips, the face tables' vectors) is weighted region by region.

#include <array>
#include <string>
#include <string_view>
#include <vector>

#include "anim/joint_mask.h"
#include "anim/quat.h"

namespace thespis::core::scene {

/// The face layout's regions, as FrameLayout::group names them.
inline constexpr std::array<std::string_view, 9> kFaceRegions{"mouth",  "tongue", "eyes", "brows",      "cheeks",
                                                              "nose",   "ears",   "head", "expressions"};

enum class FaceMaskPreset {
    WholeFace,  ///< every channel 1
    Speech,     ///< mouth and tongue 1, cheeks ½ (they follow the jaw), the rest 0
    Expression, ///< eyes, brows, cheeks, nose and expression weights 1, mouth ⅓, the rest 0
    Eyes,       ///< eyes 1 (blinks, gaze), the rest 0
};

anim::JointMask faceMaskPreset(FaceMaskPreset preset);

/// True when `mask` names a face region or a face channel of the face layout ("fap3", "viseme1",
/// "expression2"): the mask editor shows it on the face.
bool isFaceMask(const anim::JointMask& mask);

/// Left and right swapped: each FAP of one side named as its other side's FAP.
anim::JointMask mirroredFaceMask(const anim::JointMask& mask);

/// The FAP that moves the other side of the face the same way (stretch_l_cornerlip ↔
/// stretch_r_cornerlip); a FAP of the middle is its own.
int mirroredFap(int fap);

/// One element of the face mask editor's picture: a region, or one of its channels.
struct FaceMaskElement {
    std::string key;   ///< what the mask names: "mouth", "fap3", "viseme1" …
    std::string label; ///< what a person reads: "mouth", "open_jaw", "viseme p_b_m", "joy"
    int parent = -1;   ///< the region's element for a channel; -1 for a region
    anim::Vec3 position; ///< on the built-in humanoid's neutral face, front view (metres)
};

/// The regions, each followed by its channels, placed at the built-in humanoid's feature points
/// (a channel without one at its region's; visemes in a row under the chin and expressions in a
/// column beside the face). Computed once.
const std::vector<FaceMaskElement>& faceMaskElements();

} // namespace thespis::core::scene
