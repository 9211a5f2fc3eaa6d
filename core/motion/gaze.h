#pragma once
// Gaze (issue 33; the paper's future work, which SmartBody, Greta and AsapRealizer all have): the
// eyes, head and neck, chest and lower back turn toward a target, over whatever else the body and
// face do (idle motion, gestures, speech). Layered last on the Stage: it reads the pose they
// made and turns it.
//
// - Parts and limits, SmartBody's defaults: eyes ±35° pitch / ±40° heading, neck (with the head)
//   ±45° / ±90°, chest ±6° / ±15°, back ±15° / ±30°. BML's influence says which parts take part.
// - Who turns how far: the eyes take what they can (planned with 85 % of their range: the rest
//   is kept for the parallax of a near target as the body turns); the head takes at least its
//   alignment share of the shift (Pejsa et al.'s head alignment) and whatever the eyes cannot
//   reach; the chest and back share what is left beyond the eyes' and head's limits.
// - How: the eyes lead with a saccade (Eyes Alive's 25 ms + 2.4 ms per degree, minimum-jerk); the
//   head follows after its latency, then the chest and back, each speeding up with its
//   acceleration to at most its top speed and slowing down so as to stop on its goal: no
//   overshoot. While the head moves the eyes' range shrinks (to 75 % at the head's top speed,
//   as Pejsa et al. model after Guitton and Volle), and as the head comes round the eyes turn
//   back, staying on the target (the vestibulo-ocular reflex).
// - Fixating, the eyes make Eyes Alive's small saccades (motion/saccades.h); a large eye shift
//   comes with a blink.
// Angles: heading + turns left, pitch + looks down (MPEG-4's eyeball FAPs' senses); the eyes are
// written to FAPs 23–26, the body's turns to the joints of each part, shared among them.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "anim/quat.h"
#include "anim/simd_types.h"
#include "anim/skeleton.h"
#include "motion/saccades.h"
#include "util/error.h"

namespace thespis::core::motion {

/// How far and how fast one part turns.
struct GazePartLimits {
    double pitch = 0, heading = 0; ///< ± degrees from where the part faces without gaze
    double maxSpeed = 0;           ///< degrees a second (the eyes: their saccades' own speed)
    double acceleration = 0;       ///< degrees a second², speeding up and slowing down
    double latency = 0;            ///< seconds after a shift starts before the part moves
    bool operator==(const GazePartLimits&) const = default;
};

/// The parts that turn, as BML's influence names them: the eyes alone; the eyes and head (and
/// neck); and the chest; and the back.
enum class GazeInfluence { Eyes, Head, Shoulder, Waist };

enum class GazePart { Back, Chest, Neck, Eyes };
inline constexpr int kGazeBodyParts = 3; ///< back, chest, neck: the parts with joints

struct GazeSettings {
    GazePartLimits eyes{35, 40, 0, 0, 0};
    GazePartLimits neck{45, 90, 200, 1200, 0.05};
    GazePartLimits chest{6, 15, 60, 300, 0.10};
    GazePartLimits back{15, 30, 45, 250, 0.12};
    GazeInfluence influence = GazeInfluence::Shoulder;
    /// The share of a shift the head takes even when the eyes could reach the target alone.
    double headAlignment = 0.5;
    /// Degrees away from the target (BML's offsetAngle and offsetDirection).
    double offsetHeading = 0, offsetPitch = 0;
    bool saccades = true;
    bool talking = false;          ///< Eyes Alive's talking mode; listening otherwise
    std::uint64_t seed = 1;
    double blinkAbove = 25;        ///< degrees: an eye shift larger than this closes the lids on the way
    bool operator==(const GazeSettings&) const = default;

    const GazePartLimits& limits(GazePart part) const;
};

/// Where a skeleton's gaze parts are: the H-Anim joints of the back (vl5, vl3, vl1), the chest
/// (vt10, vt6, vt1) and the neck (vc4, vc2, skullbase: the head turns with it), and the point
/// between the eyes in the head's frame.
struct GazeRig {
    /// A joint from the root to the head, parents first: what forward kinematics needs of it.
    struct Link {
        int joint = 0;
        anim::Vec3d offset;        ///< from its parent at rest
        int translation = -1;      ///< float offset of its animated translation in a body frame, or −1
        int part = -1;             ///< GazePart (back, chest, neck) it belongs to, or −1
        double share = 0;          ///< of its part's turn (the part's joints share it evenly)
    };
    std::vector<Link> path;
    std::array<bool, kGazeBodyParts> hasPart{};        ///< back, chest, neck have joints
    anim::Vec3d eyes;                                  ///< between the eyes, in the head's frame
    /// Error when the skeleton has no skullbase. `eyesAtRest` is the point between the eyes in
    /// the rest pose (the humanoid's face knows it); without it, eye joints (l_eyeball_joint,
    /// r_eyeball_joint) give it, else a point in front of the head above the skull base.
    static Result<GazeRig> create(const anim::Skeleton& skeleton, std::optional<anim::Vec3d> eyesAtRest = {});
};

/// What the gaze does now (degrees): each body part's turn from where it faces without gaze,
/// and the eyes' in the head.
struct GazeState {
    std::array<double, kGazeBodyParts> heading{}, pitch{}, speed{}; ///< back, chest, neck
    double eyeHeading = 0, eyePitch = 0;
    bool shifting = false;   ///< a shift is under way (the parts not yet on their goals)
    bool released = false;   ///< going back to no gaze after release()
};

class GazeController {
public:
    GazeController(GazeRig rig, GazeSettings settings);

    const GazeSettings& settings() const { return m_settings; }
    /// New settings from now (a new target needs none: look at it with apply()).
    void setSettings(const GazeSettings& settings);
    /// Lets go of the target: every part turns back to where the pose has it, then
    /// finished() is true and apply() leaves the frames alone.
    void release();
    bool finished() const;

    /// Advances to `t` (seconds) and turns `body` (the skeleton's layout, the pose the other
    /// layers made, before placement) and the eyes of `face` (MPEG-4 FAPs) toward `target`
    /// (in the body frame's space). A time going back or jumping more than a quarter second
    /// settles at once, as scrubbing wants. No allocation.
    void apply(double t, const anim::Vec3d& target, std::span<float> body, std::span<float> face);

    const GazeState& state() const { return m_state; }
    /// The saccades of the fixation going on.
    const SaccadeGenerator& saccades() const { return m_saccades; }

private:
    void moveParts(double t, double dt, bool settle, const std::array<double, kGazeBodyParts>& headingGoal,
                   const std::array<double, kGazeBodyParts>& pitchGoal);
    /// Moves the eyes toward their goal; true while a jump to it is under way.
    bool moveEyes(double t, bool settle, double goalHeading, double goalPitch);

    GazeRig m_rig;
    GazeSettings m_settings;
    GazeState m_state;
    SaccadeGenerator m_saccades;
    std::optional<double> m_last;             // the time apply() last ran
    bool m_released = false, m_finished = false;
    bool m_onGoals = true;                    // every part on its goal
    std::array<double, kGazeBodyParts> m_shiftHeading{}, m_shiftPitch{}; // goals when the shift began
    double m_shiftStart = 0;
    // The eyes: where they were shown, and the saccade that takes them to a new goal.
    double m_goalHeading = 0, m_goalPitch = 0;
    Saccade m_eyeJump;                        // to the goal, from where the eyes were
    std::optional<double> m_blinkStart;
    bool m_fixating = false;
    // The chain's links' offsets, the head's position summed per stretch and the links'
    // orientations in the base's frame (apply(); allocated once).
    std::vector<anim::simd::F4> m_offsets, m_stretches, m_orientations;
};

} // namespace thespis::core::motion
