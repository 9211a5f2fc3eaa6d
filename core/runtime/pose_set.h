#pragma once
// PoseSet: what the stage gives for one tick — every character's body frame (its skeleton's
// layout, before placement), where the character stands (its placement, applied by whoever
// draws the body) and its face frame (MPEG-4 FAPs). Sized once by Stage::makePoseSet(), so
// evaluating into it, copying it and publishing it allocate nothing. A pose set is complete in
// itself: a renderer on another thread needs nothing of the stage's runtime to draw it.

#include <string>
#include <vector>

#include "anim/root_motion.h"
#include "util/tick.h"

namespace thespis::core::runtime {

struct CharacterPose {
    std::vector<float> body;
    anim::Placement placement;
    std::vector<float> face;
};

struct PoseSet {
    Tick time = 0;
    std::vector<CharacterPose> characters; ///< in the stage's character order
};

/// Copies `from` into `to` without allocating when both have the same sizes.
inline void copyPoses(const PoseSet& from, PoseSet& to)
{
    to.time = from.time;
    to.characters.resize(from.characters.size());
    for (std::size_t i = 0; i < from.characters.size(); ++i) {
        to.characters[i].body.assign(from.characters[i].body.begin(), from.characters[i].body.end());
        to.characters[i].placement = from.characters[i].placement;
        to.characters[i].face.assign(from.characters[i].face.begin(), from.characters[i].face.end());
    }
}

} // namespace thespis::core::runtime
