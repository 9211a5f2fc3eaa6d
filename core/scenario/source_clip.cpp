#include "scenario/source_clip.h"

#include <cmath>
#include <set>

#include "util/text.h"

namespace thespis::core::scenario {

using anim::KeyframeClip;

Result<SourceClip> readSourceClip(const ClipAsset& asset, const std::string& where, AssetCache& cache,
                                  const Assets& assets)
{
    SourceClip source;
    source.asset = &asset;
    if (asset.blinks) {
        if (!asset.file.empty() || !asset.frames.empty() || !asset.joints.empty() || !asset.scalars.empty())
            return makeError(ErrorCode::InvalidSchedule, where + ": a blink clip has no file and no keyframes.");
        motion::BlinkOptions options;
        options.ratePerMinute = asset.blinks->rate;
        options.seed = asset.blinks->seed;
        options.closeSeconds = asset.blinks->closeSeconds;
        options.shutSeconds = asset.blinks->shutSeconds;
        options.openSeconds = asset.blinks->openSeconds;
        auto blinks = motion::BlinkSynthesizer::create(options);
        if (!blinks)
            return makeError(blinks.error().code, where + ": " + blinks.error().message);
        source.blinks = std::move(blinks).value();
        return source;
    }
    if (asset.idle) {
        if (!asset.file.empty() || !asset.frames.empty() || !asset.joints.empty() || !asset.scalars.empty())
            return makeError(ErrorCode::InvalidSchedule, where + ": an idle motion clip has no file and no keyframes.");
        auto database = cache.idleDatabase(asset.idle->database, assets);
        if (!database) {
            const Error& e = database.error();
            return makeError(e.code, where + ", idle database " + inQuotes(asset.idle->database) + ": " + e.message,
                             "looked for " + assets.where(asset.idle->database) + (e.detail.empty() ? "" : "; " + e.detail));
        }
        source.idle = *database;
        return source;
    }
    if (!asset.file.empty()) {
        if (!asset.frames.empty() || !asset.joints.empty() || !asset.scalars.empty())
            return makeError(ErrorCode::InvalidSchedule, where + ": a clip read from a file cannot also hold inline keyframes.");
        if (asset.frameRateOverride < 0 || !std::isfinite(asset.frameRateOverride))
            return makeError(ErrorCode::InvalidSchedule, where + ": the frame rate override must be a positive number.");
        auto read = cache.clipFile(asset, assets);
        if (!read) {
            const Error& e = read.error();
            return makeError(e.code, where + ", file " + inQuotes(asset.file) + ": " + e.message,
                             "looked for " + assets.where(asset.file) + (e.detail.empty() ? "" : "; " + e.detail));
        }
        const ClipFile& file = **read;
        source.clip = file.clip;
        source.file = *read;
        return source;
    }
    if (asset.joints.empty() && asset.scalars.empty())
        return makeError(ErrorCode::InvalidSchedule, where + ": the clip has neither a file nor inline keyframes.");
    std::set<std::string> seen;
    for (const std::string& name : asset.joints)
        if (name.empty() || !seen.insert(name).second)
            return makeError(ErrorCode::InvalidSchedule, where + ": joint names must be non-empty and unique ("
                                 + inQuotes(name) + ").");
    seen.clear();
    for (const std::string& name : asset.scalars)
        if (name.empty() || !seen.insert(name).second)
            return makeError(ErrorCode::InvalidSchedule, where + ": scalar names must be non-empty and unique ("
                                 + inQuotes(name) + ").");
    if (asset.rootTranslation && asset.joints.empty())
        return makeError(ErrorCode::InvalidSchedule, where + ": a root translation needs a root joint.");
    std::vector<std::string> translations;
    if (asset.rootTranslation)
        translations.push_back(asset.joints.front());
    auto layout = anim::FrameLayout::create(asset.joints, std::move(translations), asset.scalars);
    auto clip = KeyframeClip::create(std::move(layout), asset.frameRate, asset.frames, asset.name);
    if (!clip)
        return makeError(ErrorCode::InvalidSchedule, where + ": " + clip.error().message, clip.error().detail);
    source.clip = std::move(clip).value();
    return source;
}

} // namespace thespis::core::scenario
