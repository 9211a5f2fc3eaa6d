#include "motion/dependent_joint_filter.h"

#include <array>

namespace thespis::core::motion {

namespace {
constexpr std::size_t kUpperFloats = 45;
} // namespace

float filterScale(const FilterBand& band, int index)
{
    if (index <= band.fadeFrom)
        return 1.0f;
    if (index > band.muteAbove)
        return 0.0f;
    return float(band.muteAbove - index + 1) / float(band.muteAbove - band.fadeFrom + 1);
}

Result<std::shared_ptr<DependentJointFilter>> DependentJointFilter::create(anim::BlendablePtr source,
                                                                           const anim::Skeleton& skeleton,
                                                                           std::shared_ptr<const PostureBasis> upper,
                                                                           FilterBand band)
{
    if (!source)
        return makeError(ErrorCode::InvalidArgument, "The dependent-joint filter has nothing to filter.");
    if (!upper || upper->set() != PostureSet::UpperBody || std::size_t(upper->dimension()) != kUpperFloats)
        return makeError(ErrorCode::InvalidArgument, "The dependent-joint filter needs an upper-body posture basis.");
    if (band.fadeFrom < 1 || band.muteAbove < band.fadeFrom || band.muteAbove > upper->dimension())
        return makeError(ErrorCode::InvalidArgument,
                         "The dependent-joint filter's band must keep PCs 1 to fadeFrom and mute above muteAbove, with "
                         "1 <= fadeFrom <= muteAbove <= " + std::to_string(upper->dimension()) + ".");
    if (!(*source->layout() == *skeleton.frameLayout()))
        return makeError(ErrorCode::InvalidArgument, "The dependent-joint filter plays on the skeleton of its source.");
    auto map = PostureMap::create(skeleton, PostureSet::UpperBody);
    if (!map)
        return makeError(map.error().code, "The dependent-joint filter cannot play here: " + map.error().message);
    auto filter = std::shared_ptr<DependentJointFilter>(new DependentJointFilter(std::move(source)));
    filter->m_upper = std::move(upper);
    filter->m_band = band;
    filter->m_map = std::move(map).value();
    for (int i = 1; i <= filter->m_upper->dimension(); ++i)
        filter->m_scales.push_back(filterScale(band, i));
    return filter;
}

void DependentJointFilter::filter(std::span<float> frame) const
{
    std::array<float, kUpperFloats> posture, pcs;
    m_map.toPosture(frame, posture);
    m_upper->project(posture, pcs);
    for (std::size_t i = 0; i < kUpperFloats; ++i)
        pcs[i] *= m_scales[i];
    m_upper->reconstruct(std::span<const float>(pcs.data(), std::size_t(m_band.muteAbove)), posture);
    m_map.toFrame(posture, frame);
}

void DependentJointFilter::evaluate(double t, std::span<float> out) const
{
    m_source->evaluate(t, out);
    filter(out);
}

} // namespace thespis::core::motion
