#include "scenario/posture_clip.h"

#include <cmath>

#include "anim/clip_retarget.h"
#include "anim/hanim.h"
#include "scenario/clip_file.h"
#include "scene/foot_soles.h"

namespace thespis::core::scenario {

std::vector<float> PostureClip::postures(motion::PostureSet set, double rate, double skip) const
{
    const motion::PostureMap map = *motion::PostureMap::create(motion::postureSkeleton(), set); // every set is on it
    const std::size_t d = std::size_t(map.layout().size());
    const anim::TimeDomain domain = frames->domain();
    const double step = rate > 0 ? 1.0 / rate : 1.0 / frameRate();
    std::vector<float> out, frame(frames->layout()->floatCount());
    const double first = domain.start + std::max(0.0, skip);
    const std::size_t count = first > domain.end ? 0 : std::size_t(std::floor((domain.end - first) / step + 1e-9)) + 1;
    out.resize(count * d);
    for (std::size_t i = 0; i < count; ++i) {
        frames->evaluate(first + double(i) * step, frame);
        map.toPosture(frame, std::span<float>(out).subspan(i * d, d));
    }
    return out;
}

Result<std::vector<std::vector<float>>> readPostureSources(const std::vector<PostureSource>& sources,
                                                           const Assets& assets, double rate,
                                                           JobContext& context, const std::string& stage,
                                                           const std::string& job)
{
    context.beginStage(stage, sources.size());
    std::vector<std::vector<float>> postures;
    for (std::size_t i = 0; i < sources.size(); ++i) {
        if (context.stopRequested())
            return cancelledError(job);
        auto clip = readPostureClip(sources[i].clip, assets);
        if (!clip)
            return clip.error();
        postures.push_back(clip->postures(motion::PostureSet::WholeBody, rate, sources[i].skip));
        context.setDone(i + 1);
    }
    return postures;
}

Result<PostureClip> readPostureClip(const ClipAsset& asset, const Assets& assets)
{
    auto file = readClipFile(asset, assets);
    if (!file)
        return file.error();
    anim::ClipRetargetOptions options;
    options.retarget.sourceUnit = asset.unit > 0 ? asset.unit : file->report.unit;
    options.fitGround = asset.fitGround;
    options.retarget.targetSoles = scene::defaultHumanoidSoles(anim::hanim::Level::Subset25);
    auto retargeted = anim::retargetClip(*file->clip, file->skeleton, motion::postureSkeleton(), options);
    if (!retargeted)
        return makeError(retargeted.error().code, asset.file + ": " + retargeted.error().message, retargeted.error().detail);

    PostureClip clip;
    clip.name = asset.file;
    clip.frames = retargeted->clip;
    for (const std::string& joint : motion::PostureLayout::of(motion::PostureSet::WholeBody).joints)
        if (std::find(retargeted->report.unmatched.begin(), retargeted->report.unmatched.end(), joint) !=
            retargeted->report.unmatched.end())
            clip.unmatched.push_back(joint);
    const std::size_t total = motion::PostureLayout::of(motion::PostureSet::WholeBody).joints.size();
    if (2 * clip.unmatched.size() > total) {
        std::string names;
        for (const std::string& joint : clip.unmatched)
            names += (names.empty() ? "" : ", ") + joint;
        return makeError(ErrorCode::InvalidArgument,
                         asset.file + " moves only " + std::to_string(total - clip.unmatched.size()) + " of the " +
                             std::to_string(total) + " posture joints; its joints map onto too little of the H-Anim body "
                             "(not moved: " + names + "). Map its joints in the import dialog, or leave it out.");
    }
    return clip;
}

} // namespace thespis::core::scenario
