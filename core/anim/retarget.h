#pragma once
// Plays a frame of one skeleton on another by joint name: the scenario's animation skeleton
// (H-Anim) drives a character's own skeleton (a glTF rig mapped onto H-Anim names). Both follow
// the world-aligned rest convention (identity rotation = rest pose, rest frames aligned with the
// world), so a joint's rotation carries over unchanged; joints the source lacks stay at rest.
// Translations are scaled by the ratio of the roots' rest heights, so a shorter character does
// not float or sink. Built once, applied per frame without allocation.

#include <span>
#include <vector>

#include "anim/skeleton.h"

namespace thespis::core::anim {

class FrameRetarget {
public:
    FrameRetarget() = default;
    FrameRetarget(const Skeleton& from, const Skeleton& to);

    /// Target joints that found a source joint of the same name.
    int mappedJointCount() const { return m_mappedJoints; }
    /// `toFrame` has the target layout's floatCount().
    void apply(std::span<const float> fromFrame, std::span<float> toFrame) const;

private:
    struct Copy {
        std::size_t from = 0, to = 0;
    };
    struct TranslationCopy {
        std::size_t from = 0, to = 0;
        Vec3 fromRest, toRest; ///< offsets the scaled motion is measured from and added to
    };
    std::vector<Copy> m_rotations;            ///< float offsets of mapped rotations
    std::vector<std::size_t> m_restRotations; ///< float offsets of target rotations left at rest
    std::vector<TranslationCopy> m_translations;
    std::vector<std::pair<std::size_t, Vec3>> m_restTranslations;
    float m_scale = 1.0f;
    int m_mappedJoints = 0;
};

} // namespace thespis::core::anim
