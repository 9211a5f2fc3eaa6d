#pragma once
// Builds an idle motion database (idle_database.h) from standing recordings (paper §4.3):
//   1. every recording's postures at the database's rate, re-centred on the mean posture of all
//      of them (performers stand differently: the database keeps their motion, not their build,
//      so that transitions cut from different recordings join; the idle stands its feet back
//      on the floor);
//   2. rest-posture categories found in the data: k-means in PC space over each recording, in
//      the leading PCs of its lower body (the root and the legs, where balance shows; eq. 1's
//      weights), the clusters ordered by where the body's weight is (the root's sideways place
//      over the feet: the left foot, both, the right foot), or labels given by hand;
//   3. the labels cleaned of flickers (runs shorter than a minimum rest become their neighbour's);
//   4. a transition segment from the middle of each rest to the middle of the next one, in
//      another category: the motion between two resting postures, as recorded;
//   5. the spread of the small variations: per leading PC, the standard deviation of what is
//      left after a one-second moving average (the balance shifts) is taken away.

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "motion/idle_database.h"
#include "motion/posture_bases.h"
#include "util/error.h"

namespace thespis::core::motion {

struct IdleRecording {
    std::string name;
    std::vector<float> postures; ///< whole-body postures at IdleBuildOptions::frameRate
    /// Per frame, a category given by hand (−1: none). When every frame has one, the recording is
    /// not clustered.
    std::vector<int> labels;
};

struct IdleBuildOptions {
    float frameRate = 30;
    int categoryCount = 3;    ///< 3: "left", "both", "right"; else "rest 1" …
    int clusterPcs = 3;       ///< lower-body PCs the clustering compares (eq. 1)
    double minimumRest = 0.3; ///< seconds; shorter runs of a category are flickers
    int variationPcs = 10;    ///< PCs the small variations move
    /// The bases to measure in; none: trained on the recordings themselves.
    std::optional<PostureBases> bases;
};

struct IdleBuildReport {
    struct Recording {
        std::string name;
        int frames = 0;
        int rests = 0;    ///< runs of one category
        int segments = 0; ///< transitions cut from it
    };
    std::vector<Recording> recordings;
    /// Segments per transition: counts[from][to].
    std::vector<std::vector<int>> counts;
    /// "left → right", … : transitions between categories with no segment.
    std::vector<std::string> missing;
};

/// Per frame of a recording, its category (0 … categoryCount−1) as the builder finds it (steps
/// 2 and 3).
std::vector<int> findRestCategories(const IdleRecording& recording, const IdleBuildOptions& options);

/// Errors: no recordings, a recording of broken postures, no transition found anywhere.
Result<IdleDatabase> buildIdleDatabase(const std::vector<IdleRecording>& recordings, const IdleBuildOptions& options,
                                       IdleBuildReport* report = nullptr);

/// The upper-body postures inside whole-body ones (the same joints' exponential maps).
std::vector<float> upperBodyOf(std::span<const float> wholePostures);

} // namespace thespis::core::motion
