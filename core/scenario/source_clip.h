#pragma once
// A clip of a character as read from its source — a motion file (BVH, glTF), inline keyframes or
// an idle-motion database, or blinks — before the runtime puts it on the character's layout.

#include <memory>
#include <string>

#include "anim/keyframe_clip.h"
#include "motion/blink_synthesizer.h"
#include "motion/idle_database.h"
#include "scenario/clip_file.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

struct SourceClip {
    std::shared_ptr<const anim::KeyframeClip> clip;
    std::shared_ptr<const ClipFile> file;              ///< clips read from a file bring their rig
    std::shared_ptr<const motion::IdleDatabase> idle; ///< idle motion clips: what they play from
    std::shared_ptr<const motion::BlinkSynthesizer> blinks; ///< blink clips: the face they play
    const ClipAsset* asset = nullptr;
};

/// Reads `asset` through `cache`. Errors begin with `where` and name the field or file.
Result<SourceClip> readSourceClip(const ClipAsset& asset, const std::string& where, AssetCache& cache,
                                  const Assets& assets);

} // namespace thespis::core::scenario
