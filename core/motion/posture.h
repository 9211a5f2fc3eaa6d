#pragma once
// Posture vectors (paper §4.1): a body frame as one vector of R^(3m+3), the exponential map of m
// joint rotations followed by the root's translation, so that postures can be averaged, compared
// and taken apart by PCA. Two sets:
//   - the whole body: the 25 H-Anim joints of hanim::Level::Subset25 and the root's translation,
//     78 numbers;
//   - the upper body: its 15 joints above the pelvis (spine, neck, head, clavicles, arms), without
//     the root, 45 numbers (the paper's is 48: its 25 joints split 16 / 9). The dependent-joint
//     filter works on it.
//
// The whole body is measured in its stance frame: the root's rotation and translation are taken
// from the point on the floor between the ankles, turned so that the feet face +Z. Postures then
// compare wherever and whichever way the performer stood (a capture wanders about the room), and
// a posture played back stands with its feet about the origin, facing +Z, to be placed like a clip.

#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::motion {

enum class PostureSet : std::uint8_t { WholeBody, UpperBody };

struct PostureLayout {
    PostureSet set = PostureSet::WholeBody;
    std::vector<std::string> joints; ///< H-Anim names, parents first
    bool rootTranslation = false;    ///< the last 3 numbers are the root's translation (whole body)

    int size() const { return 3 * int(joints.size()) + (rootTranslation ? 3 : 0); }
    static const PostureLayout& of(PostureSet set);
};

/// "whole body" or "upper body", for people.
std::string_view postureSetName(PostureSet set);

/// A skeleton's frames as postures of one set. The skeleton names its joints in H-Anim (as every
/// scenario skeleton and retargeted clip does) and rests in the H-Anim convention.
class PostureMap {
public:
    PostureMap() = default;
    /// Error (InvalidArgument) naming the joints of the set the skeleton lacks.
    static Result<PostureMap> create(const anim::Skeleton& skeleton, PostureSet set);

    const PostureLayout& layout() const { return *m_layout; }
    const anim::Skeleton& skeleton() const { return m_skeleton; }

    /// The posture of `frame` (on the skeleton's layout) into `posture` (layout().size() floats).
    void toPosture(std::span<const float> frame, std::span<float> posture) const;
    /// Writes the posture's joint rotations (and the root translation) into `frame`; the frame's
    /// other elements keep their values. Allocates nothing.
    void toFrame(std::span<const float> posture, std::span<float> frame) const;

private:
    const PostureLayout* m_layout = nullptr;
    anim::Skeleton m_skeleton;
    std::vector<std::size_t> m_rotationOffsets; ///< float offset in a frame, per posture joint
    std::size_t m_rootTranslation = 0;          ///< float offset of the root translation
    int m_leftAnkle = -1, m_rightAnkle = -1;    ///< skeleton joints for the stance frame
};

/// The skeleton postures are measured on: H-Anim's 25 joints (hanim::Level::Subset25).
const anim::Skeleton& postureSkeleton();

} // namespace thespis::core::motion
