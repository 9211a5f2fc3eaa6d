#include "anim/clip_retarget.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "anim/body_measure.h"

namespace thespis::core::anim {

std::vector<double> footHeights(const KeyframeClip& clip, const Skeleton& skeleton)
{
    const BodyMeasure body = measureBody(skeleton);
    std::vector<double> heights;
    if (!body.hasFeet() || !(*clip.layout() == *skeleton.frameLayout()))
        return heights;
    std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<Quatd> orientations(positions.size());
    std::vector<double> feet(body.footJoints.size());
    heights.reserve(std::size_t(clip.frameCount()));
    for (int f = 0; f < clip.frameCount(); ++f) {
        skeleton.worldTransforms(clip.frame(f), positions, orientations);
        for (std::size_t k = 0; k < feet.size(); ++k)
            feet[k] = positions[std::size_t(body.footJoints[k])].y;
        heights.push_back(footHeight<double>(feet, body.footSoftness));
    }
    return heights;
}

double plantedFeetHeight(std::vector<double> heights, double bin)
{
    std::sort(heights.begin(), heights.end());
    heights.resize((heights.size() + 1) / 2);
    std::map<long long, int> counts;
    for (double h : heights)
        ++counts[std::llround(std::floor(h / bin))];
    // The densest bin with its neighbours (a planted foot's height spreads over a few), lowest first.
    long long best = counts.begin()->first;
    int bestCount = -1;
    for (const auto& [key, count] : counts) {
        const auto around = [&](long long k) {
            const auto it = counts.find(k);
            return it == counts.end() ? 0 : it->second;
        };
        const int total = around(key - 1) + count + around(key + 1);
        if (total > bestCount) {
            bestCount = total;
            best = key;
        }
    }
    // The median of the heights in that window.
    std::vector<double> window;
    for (double h : heights)
        if (std::abs(std::floor(h / bin) - double(best)) <= 1.0)
            window.push_back(h);
    return window[window.size() / 2];
}

Result<RetargetedClip> retargetClip(const KeyframeClip& clip, const Skeleton& from, const Skeleton& to,
                                    const ClipRetargetOptions& options)
{
    if (!(*clip.layout() == *from.frameLayout()))
        return makeError(ErrorCode::InvalidArgument, "The clip is not on the source skeleton's layout.");
    RetargetedClip result;
    RetargetOptions retargetOptions = options.retarget;
    const BodyMeasure fromBody = measureBody(from);
    if (options.fitGround && fromBody.hasFeet() && measureBody(to).hasFeet() && clip.frameCount() > 0) {
        retargetOptions.sourcePlantedFeet = plantedFeetHeight(footHeights(clip, from), fromBody.footSoftness);
        result.report.groundFitted = true;
        result.report.sourceFloor = *retargetOptions.sourcePlantedFeet;
    }
    const FrameRetarget retarget(from, to, retargetOptions);
    if (retarget.mappedJointCount() == 0)
        return makeError(ErrorCode::InvalidArgument,
                         "None of the clip's joints is a joint of the character's skeleton, so it would not move it.");

    const std::size_t width = to.frameLayout()->floatCount();
    std::vector<float> frames(width * std::size_t(clip.frameCount()));
    for (int f = 0; f < clip.frameCount(); ++f)
        retarget.apply(clip.frame(f), std::span<float>(frames).subspan(std::size_t(f) * width, width));

    result.report.scale = retarget.scale();
    result.report.scaleSource = retarget.scaleSource();
    result.report.mappedJoints = retarget.mappedJointCount();
    for (const Joint& joint : to.joints())
        if (from.find(joint.name) < 0)
            result.report.unmatched.push_back(joint.name);
    auto made = KeyframeClip::create(to.frameLayout(), clip.frameRate(), std::move(frames), clip.name());
    if (!made)
        return made.error();
    result.clip = std::move(made).value();
    return result;
}

} // namespace thespis::core::anim
