#pragma once
// PoseSet: what the stage gives for one tick — every character's body frame (its skeleton's
// layout, before placement) and face frame (MPEG-4 FAPs). Sized once by Stage::makePoseSet(),
// so evaluating into it, copying it and publishing it allocate nothing.

#include <string>
#include <vector>

#include "util/tick.h"

namespace thespis::core::runtime {

struct CharacterPose {
    std::vector<float> body;
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
        to.characters[i].face.assign(from.characters[i].face.begin(), from.characters[i].face.end());
    }
}

} // namespace thespis::core::runtime
