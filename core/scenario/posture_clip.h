#pragma once
// Motion capture as postures (paper §4.1's database): a clip file (BVH, or an animation of a
// glTF file; scenario/clip_file.h) read with its options, retargeted onto the H-Anim 25-joint
// skeleton standing on its floor (anim/clip_retarget.h), and each frame taken as a posture vector
// (motion/posture.h). Whatever rig the performer wore, its postures land in one space.

#include <memory>
#include <string>
#include <vector>

#include "anim/keyframe_clip.h"
#include "motion/posture.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "util/error.h"
#include "util/job.h"

namespace thespis::core::scenario {

struct PostureClip {
    std::string name;                                 ///< the file's name
    std::shared_ptr<const anim::KeyframeClip> frames; ///< on the 25-joint skeleton's layout
    std::vector<std::string> unmatched;               ///< posture joints the file does not move

    double frameRate() const { return frames->frameRate(); }
    int frameCount() const { return frames->frameCount(); }
    /// Every frame as a posture of `set` (frameCount × size floats), or resampled at `rate` frames
    /// per second when given, from `skip` seconds on.
    std::vector<float> postures(motion::PostureSet set, double rate = 0, double skip = 0) const;
};

/// A recording to learn from: a clip file with its options, and the seconds left out at its start
/// (a capture's T-pose and the settling after it).
struct PostureSource {
    ClipAsset clip;
    double skip = 0;
};

/// Every source's whole-body postures at `rate` frames per second, read as a job's stage
/// `stage` (util/job.h: one unit per source); ErrorCode::Cancelled (naming `job`) when stopped.
Result<std::vector<std::vector<float>>> readPostureSources(const std::vector<PostureSource>& sources,
                                                           const Assets& assets, double rate,
                                                           JobContext& context, const std::string& stage,
                                                           const std::string& job);

/// Reads `asset.file` from `assets` onto the posture skeleton. Errors name the file: it cannot be
/// read, or it moves fewer than half of the 25 posture joints (they are listed).
Result<PostureClip> readPostureClip(const ClipAsset& asset, const Assets& assets);

} // namespace thespis::core::scenario
