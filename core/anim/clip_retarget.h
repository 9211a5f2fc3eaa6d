#pragma once
// A whole clip played on another skeleton (anim/retarget.h), standing on the ground: motion
// capture rarely agrees with a character about where the floor is (a CMU rig hangs from its root
// at y = 0, its proportions are not the character's). The performer's floor is found in the clip
// itself: where its feet spend most of their time among the lower half of the frames of the 3 s
// around each frame (the densest few millimetres of heights there: the planted foot, not a
// jump's flight nor the odd sample of marker noise below the floor; around each frame, since
// a capture's floor drifts). Each frame's feet are then set that high over the character's
// floor, scaled, so a walk keeps its steps on the ground and a jump its flight. Feet the
// performer does not hold flat when they stand (CMU's rest foot points up from where it stands)
// are turned flat.

#include <memory>
#include <string>
#include <vector>

#include "anim/keyframe_clip.h"
#include "anim/retarget.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::anim {

struct ClipRetargetOptions {
    RetargetOptions retarget;
    /// Find the performer's floor in the clip and keep each frame's feet that high over the
    /// character's (needs feet on both).
    bool fitGround = true;
};

struct ClipRetargetReport {
    double scale = 1; ///< target units per source unit
    FrameRetarget::ScaleSource scaleSource = FrameRetarget::ScaleSource::None;
    bool groundFitted = false;
    double sourceFloor = 0;             ///< source units: the feet's height when planted (footHeight()), median over the clip
    std::vector<double> sourceFloors;   ///< the same in every frame
    int mappedJoints = 0;               ///< target joints the clip moves
    std::vector<std::string> unmatched; ///< target joints the clip does not move (they rest)
};

struct RetargetedClip {
    std::shared_ptr<KeyframeClip> clip; ///< on to.frameLayout(), same rate and name
    ClipRetargetReport report;
};

/// `clip` is on `from`'s layout. Fails (InvalidArgument) when no joint of `to` is in `from`.
Result<RetargetedClip> retargetClip(const KeyframeClip& clip, const Skeleton& from, const Skeleton& to,
                                    const ClipRetargetOptions& options = {});

/// How high the feet are (footHeight() of the soles, body_measure.h) in each frame of `clip`
/// (on `skeleton`'s layout); empty when the skeleton has no feet.
std::vector<double> footHeights(const KeyframeClip& clip, const Skeleton& skeleton);
/// The height the feet have most often among the lower half of `heights` (a clip's footHeights):
/// where they stand on the floor. `bin` is the histogram's resolution (about a centimetre).
double plantedFeetHeight(std::vector<double> heights, double bin);

} // namespace thespis::core::anim
