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
    std::vector<double> soles(body.soles.size());
    heights.reserve(std::size_t(clip.frameCount()));
    for (int f = 0; f < clip.frameCount(); ++f) {
        skeleton.worldTransforms(clip.frame(f), positions, orientations);
        soleHeights(body, positions, orientations, soles);
        heights.push_back(footHeight<double>(soles, body.footSoftness));
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

namespace {

// How far on either side of a frame its floor is looked for, and how often it is measured.
constexpr double kFloorWindowSeconds = 1.5;
constexpr double kFloorStepSeconds = 0.25;

// The performer's floor in every frame: plantedFeetHeight() of the feet over the 3 s around it,
// measured every quarter second and interpolated between, so that a capture whose floor drifts
// (markers slipping, a root that settles) keeps its feet down all along.
std::vector<double> floorOverTime(const std::vector<double>& heights, double frameRate, const BodyMeasure& body)
{
    const int frames = int(heights.size());
    const int half = std::max(1, int(std::lround(kFloorWindowSeconds * frameRate)));
    const int step = std::max(1, int(std::lround(kFloorStepSeconds * frameRate)));
    std::vector<int> at;
    std::vector<double> floor;
    for (int f = 0;; f = std::min(f + step, frames - 1)) {
        const int begin = std::max(0, f - half), end = std::min(frames, f + half + 1);
        at.push_back(f);
        floor.push_back(plantedFeetHeight({heights.begin() + begin, heights.begin() + end}, body.footSoftness));
        if (f == frames - 1)
            break;
    }
    std::vector<double> floors(heights.size());
    for (std::size_t k = 0; k + 1 < at.size() || k == 0; ++k) {
        const int a = at[k], b = at[std::min(k + 1, at.size() - 1)];
        for (int f = a; f <= b; ++f)
            floors[std::size_t(f)] = b > a ? floor[k] + (floor[k + 1] - floor[k]) * (f - a) / double(b - a) : floor[k];
        if (at.size() == 1)
            break;
    }
    return floors;
}

// The turn that makes each source foot joint flat when it stands: world up seen from the joint
// (averaged over the frames where its foot is planted: its soles within 2 cm of the floor and
// its ankle within 2 cm of its lowest), as the smallest rotation from the joint's own up.
std::map<std::string, Quat> flatFeet(const KeyframeClip& clip, const Skeleton& skeleton, const BodyMeasure& body,
                                     double floor)
{
    std::map<std::string, Quat> turns;
    const double cm = (body.hasLegs() ? body.legLength : 0.84) / 84.0;
    std::vector<Vec3d> positions(std::size_t(skeleton.jointCount()));
    std::vector<Quatd> orientations(positions.size());
    std::vector<double> soles(body.soles.size());
    for (const char* side : {"l_", "r_"}) {
        const int ankle = skeleton.find(std::string(side) + "talocrural");
        if (ankle < 0)
            continue;
        std::vector<int> foot; // the ankle and the joints below it
        for (int j : body.footJoints)
            for (int a = j; a >= 0; a = skeleton.joint(a).parent)
                if (a == ankle) {
                    foot.push_back(j);
                    break;
                }
        std::vector<double> ankleHeights, sideHeights;
        for (int f = 0; f < clip.frameCount(); ++f) {
            skeleton.worldTransforms(clip.frame(f), positions, orientations);
            soleHeights(body, positions, orientations, soles);
            double lowest = 1e300;
            for (std::size_t k = 0; k < soles.size(); ++k)
                if (std::find(foot.begin(), foot.end(), body.soles[k].joint) != foot.end())
                    lowest = std::min(lowest, soles[k]);
            sideHeights.push_back(lowest);
            ankleHeights.push_back(positions[std::size_t(ankle)].y);
        }
        std::vector<double> sorted = ankleHeights;
        std::sort(sorted.begin(), sorted.end());
        const double lowAnkle = sorted[sorted.size() / 20];
        std::map<int, Vec3d> up;
        int planted = 0;
        for (int f = 0; f < clip.frameCount(); ++f) {
            if (sideHeights[std::size_t(f)] > floor + 2 * cm || ankleHeights[std::size_t(f)] > lowAnkle + 2 * cm)
                continue;
            skeleton.worldTransforms(clip.frame(f), positions, orientations);
            for (int j : foot)
                up[j] = up[j] + rotate(conjugate(orientations[std::size_t(j)]), Vec3d{0, 1, 0});
            ++planted;
        }
        if (planted < std::max(5, clip.frameCount() / 50))
            continue;
        for (const auto& [j, sum] : up) {
            const double n = std::sqrt(sum.x * sum.x + sum.y * sum.y + sum.z * sum.z);
            if (!(n > 0))
                continue;
            const Vec3d u = sum * (1.0 / n);
            const Quatd q = normalize(Quatd{u.z, 0.0, -u.x, 1.0 + u.y}); // from +Y to u
            turns[skeleton.joint(j).name] = Quat{float(q.x), float(q.y), float(q.z), float(q.w)};
        }
    }
    return turns;
}

} // namespace

Result<RetargetedClip> retargetClip(const KeyframeClip& clip, const Skeleton& from, const Skeleton& to,
                                    const ClipRetargetOptions& options)
{
    if (!(*clip.layout() == *from.frameLayout()))
        return makeError(ErrorCode::InvalidArgument, "The clip is not on the source skeleton's layout.");
    RetargetedClip result;
    RetargetOptions retargetOptions = options.retarget;
    std::vector<double> floors; // per frame, when fitted
    const BodyMeasure fromBody = measureBody(from);
    if (options.fitGround && fromBody.hasFeet() && measureBody(to).hasFeet() && clip.frameCount() > 0) {
        floors = floorOverTime(footHeights(clip, from), clip.frameRate(), fromBody);
        std::vector<double> sorted = floors;
        std::sort(sorted.begin(), sorted.end());
        retargetOptions.sourcePlantedFeet = sorted[sorted.size() / 2];
        if (!fromBody.standsOnGround())
            retargetOptions.flatFeet = flatFeet(clip, from, fromBody, *retargetOptions.sourcePlantedFeet);
        result.report.groundFitted = true;
        result.report.sourceFloor = *retargetOptions.sourcePlantedFeet;
        result.report.sourceFloors = floors;
    }
    const FrameRetarget retarget(from, to, retargetOptions);
    if (retarget.mappedJointCount() == 0)
        return makeError(ErrorCode::InvalidArgument,
                         "None of the clip's joints is a joint of the character's skeleton, so it would not move it.");

    const std::size_t width = to.frameLayout()->floatCount();
    std::vector<float> frames(width * std::size_t(clip.frameCount()));
    for (int f = 0; f < clip.frameCount(); ++f) {
        const std::span<float> out = std::span<float>(frames).subspan(std::size_t(f) * width, width);
        if (floors.empty())
            retarget.apply(clip.frame(f), out);
        else
            retarget.apply(clip.frame(f), out, float(floors[std::size_t(f)]));
    }

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
