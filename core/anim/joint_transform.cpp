#include "anim/joint_transform.h"

#include <array>

#include "anim/frame.h"

namespace thespis::core::anim {

void jointTransform(const Skeleton& skeleton, std::span<const float> body, int joint, Vec3d& position,
                    Quatd& orientation)
{
    std::array<int, 128> chain{};
    std::size_t depth = 0;
    for (int j = joint; j >= 0 && depth < chain.size(); j = skeleton.joint(j).parent)
        chain[depth++] = j;
    position = {};
    orientation = {0, 0, 0, 1};
    while (depth-- > 0) {
        const int j = chain[depth];
        Vec3d offset = skeleton.joint(j).offset;
        if (const int element = skeleton.translationElement(j); element >= 0) {
            const std::size_t t = skeleton.frameLayout()->floatOffset(element);
            offset = {body[t], body[t + 1], body[t + 2]};
        }
        position = position + rotate(orientation, offset);
        const Quat& q = rotationAt(body, j);
        orientation = orientation * Quatd{q.x, q.y, q.z, q.w};
    }
}

} // namespace thespis::core::anim
