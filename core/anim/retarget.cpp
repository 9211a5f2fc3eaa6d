#include "anim/retarget.h"

namespace thespis::core::anim {

namespace {

Vec3 toFloat(const Vec3d& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}

} // namespace

FrameRetarget::FrameRetarget(const Skeleton& from, const Skeleton& to)
{
    const FrameLayout& fromLayout = *from.frameLayout();
    const FrameLayout& toLayout = *to.frameLayout();
    // Both roots stand on the ground at rest; their heights give the size ratio.
    const double fromHeight = from.joint(0).offset.y;
    const double toHeight = to.joint(0).offset.y;
    if (fromHeight > 1e-6 && toHeight > 1e-6)
        m_scale = float(toHeight / fromHeight);
    for (int j = 0; j < to.jointCount(); ++j) {
        const std::size_t toRotation = toLayout.floatOffset(j);
        const int source = from.find(to.joint(j).name);
        if (source >= 0) {
            m_rotations.push_back({fromLayout.floatOffset(source), toRotation});
            ++m_mappedJoints;
        } else {
            m_restRotations.push_back(toRotation);
        }
        const int toElement = to.translationElement(j);
        if (toElement < 0)
            continue;
        const Vec3 toRest = toFloat(to.joint(j).offset);
        const int fromElement = source >= 0 ? from.translationElement(source) : -1;
        if (fromElement >= 0)
            m_translations.push_back({fromLayout.floatOffset(fromElement), toLayout.floatOffset(toElement),
                                      toFloat(from.joint(source).offset), toRest});
        else
            m_restTranslations.emplace_back(toLayout.floatOffset(toElement), toRest);
    }
}

void FrameRetarget::apply(std::span<const float> fromFrame, std::span<float> toFrame) const
{
    for (const Copy& copy : m_rotations)
        for (std::size_t k = 0; k < 4; ++k)
            toFrame[copy.to + k] = fromFrame[copy.from + k];
    for (std::size_t offset : m_restRotations) {
        toFrame[offset] = toFrame[offset + 1] = toFrame[offset + 2] = 0.0f;
        toFrame[offset + 3] = 1.0f;
    }
    for (const TranslationCopy& copy : m_translations) {
        const float* source = &fromFrame[copy.from];
        toFrame[copy.to] = copy.toRest.x + (source[0] - copy.fromRest.x) * m_scale;
        toFrame[copy.to + 1] = copy.toRest.y + (source[1] - copy.fromRest.y) * m_scale;
        toFrame[copy.to + 2] = copy.toRest.z + (source[2] - copy.fromRest.z) * m_scale;
    }
    for (const auto& [offset, rest] : m_restTranslations) {
        toFrame[offset] = rest.x;
        toFrame[offset + 1] = rest.y;
        toFrame[offset + 2] = rest.z;
    }
}

} // namespace thespis::core::anim
