#pragma once
// Stage (paper §3, §4.5, §5.3): the live side of the animation service. Per character and track
// (body, face) it plays, bottom to top:
//   1. the open-ended synthesizers put in its slots (idle motion), blended together;
//   2. its authored schedule (the scenario's layers, from a ScenarioRuntime), over them by how
//      much it drives each joint (its coverage);
//   3. the live Normalized actions activated at run time, blended together, over that by their
//      coverage: an action activated while the scenario plays fades in over it, and the
//      motion never jumps;
//   4. the live Override and Additive actions, on top, like gestures.
// With nothing live and no synthesizer, a track is exactly its authored schedule. An action is
// named: a body or face clip of the character, an action of its scenario (source and blending
// parameters), a gesture of its gesticon, or one defined with defineAction(); a gesture wins
// over an action of the same name, which wins over a clip.
//
// Every method locks the stage, so a script thread may activate actions while a player thread
// evaluates. evaluate() is the one place schedules are evaluated: once per tick for everyone.

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "anim/blending_schedule.h"
#include "anim/frame_cache.h"
#include "motion/gaze.h"
#include "motion/gaze_target.h"
#include "motion/pointing.h"
#include "runtime/pose_set.h"
#include "scenario/scenario_runtime.h"
#include "speech/speech_plan.h"
#include "util/error.h"
#include "util/tick.h"

namespace thespis::core::runtime {

enum class Track { Body, Face };

/// What an action plays: a blendable with its blending parameters.
struct ActionTemplate {
    anim::BlendablePtr source;
    anim::BlendingParams params;
    bool renderOutsideDomain = false;
    /// A gesture's fades (seconds), stroke and hold, by which speech fits it to its words
    /// (speech::fitGesture).
    double fadeIn = 0, fadeOut = 0;
    speech::GestureShape shape;
};

struct ActivateOptions {
    /// Replaces the action's weight curve when given.
    std::optional<anim::Curve> weight;
    /// Seconds over which the action fades in over what plays, when its own weight curve does
    /// not start at 0 already (0: at once).
    double fadeIn = 0.25;
};

using motion::GazeTarget;

class Stage {
public:
    /// An empty stage (characters come from addCharacter()).
    Stage() = default;
    /// Every character of a built scenario with its authored schedules; its clips (constant
    /// weight: body clips on the body track, clips with FAP values on the face track), its named
    /// scenario actions (with their parameters) and its gesticon's gestures (with their fades,
    /// body part and dependent-joint filter) are the actions it can play live.
    explicit Stage(scenario::ScenarioRuntime runtime);
    Stage(const Stage&) = delete;
    Stage& operator=(const Stage&) = delete;

    /// The scenario the stage was made from (empty for a stage built by hand). A reference for
    /// the thread that gives the stage new runtimes (its owner); other threads take a copy.
    const scenario::ScenarioRuntime& runtime() const { return m_runtime; }
    scenario::ScenarioRuntime runtimeCopy() const;
    /// Plays new authored schedules of the same characters (after an edit of the scenario),
    /// keeping what plays live. Errors when the characters or their skeletons differ.
    Result<void> setRuntime(scenario::ScenarioRuntime runtime);

    /// Adds a character with nothing authored. Error: the name is taken.
    Result<int> addCharacter(std::string name, const anim::Skeleton& skeleton);
    int characterCount() const;
    std::vector<std::string> characterNames() const;
    /// Index of the character, or −1.
    int findCharacter(const std::string& name) const;
    /// The character's skeleton (what its body frames are laid out on).
    Result<anim::Skeleton> skeleton(const std::string& character) const;
    /// The character's BML gesture lexemes → gestures (CharacterRuntime::bmlLexicon): the
    /// defaults for a character added by hand.
    Result<speech::BmlLexicon> bmlLexicon(const std::string& character) const;

    /// Names (or renames) an action the character can play on a track.
    Result<void> defineAction(const std::string& character, Track track, const std::string& action,
                              ActionTemplate source);
    /// What the named action of the character's library plays; nullopt when it has none of that name.
    Result<std::optional<ActionTemplate>> actionTemplate(const std::string& character, Track track,
                                                         const std::string& action) const;
    /// Sorted names of the actions the character can play on a track.
    Result<std::vector<std::string>> actionNames(const std::string& character, Track track) const;
    /// Puts an open-ended synthesizer in a named slot under the character's authored motion
    /// (null empties the slot).
    Result<void> setSynthesizer(const std::string& character, Track track, const std::string& slot,
                                anim::BlendablePtr source);
    /// Turns a track off for every character (paper: initPlayerScope_face(False)): it is no
    /// longer evaluated and stays at its rest pose.
    void setTrackEnabled(Track track, bool enabled);

    /// Starts the named action at `at`; returns its id in the live schedule.
    Result<anim::ActionId> activateAction(const std::string& character, Track track, const std::string& action,
                                          Tick at, const ActivateOptions& options = {});
    /// Plays `source` as a live action named `action` from `at`, without adding it to what the
    /// character can play (the studio's gesture preview plays a variant this way); cut off and
    /// removed by that name like any other.
    Result<anim::ActionId> playAction(const std::string& character, Track track, const std::string& action,
                                      const ActionTemplate& source, Tick at, const ActivateOptions& options = {});
    /// Fades the latest live activation of the action out over `fadeSeconds` from `at`, or,
    /// when it was not activated live, the authored action of that name playing at `at`.
    /// False when neither plays then.
    Result<bool> cutOffAction(const std::string& character, Track track, const std::string& action, Tick at,
                              double fadeSeconds);
    /// Removes the latest live activation at once; false when there is none.
    Result<bool> removeAction(const std::string& character, Track track, const std::string& action);
    /// True when the action (live, else authored) has started by `at` and not finished.
    Result<bool> isPlaying(const std::string& character, Track track, const std::string& action, Tick at) const;
    /// When the action (live, else authored) ends, in seconds on the stage's time: ∞ when it
    /// never does. Error when it was never activated and is not authored.
    Result<double> actionEnd(const std::string& character, Track track, const std::string& action) const;
    /// Seconds from `at` until the action ends (0 when it has; ∞ when it never does).
    Result<double> timeUntilFinished(const std::string& character, Track track, const std::string& action,
                                     Tick at) const;
    /// Turns the character's eyes, head and body toward `target` from `at` (the gaze layer, over
    /// everything else it plays: motion/gaze.h) with `settings`. A gaze already on takes the new
    /// target and settings and moves on from where it is. Errors: no such character, one without
    /// a head joint, a target character or joint that does not exist.
    Result<void> gaze(const std::string& character, const GazeTarget& target, const motion::GazeSettings& settings,
                      Tick at);
    /// Lets go of the gaze from `at`: the parts turn back to the pose, then the gaze is off.
    /// False when no gaze is on.
    Result<bool> stopGaze(const std::string& character, Tick at);
    /// What the character's gaze does now; nullopt when none is on.
    Result<std::optional<motion::GazeState>> gazeState(const std::string& character) const;
    /// Aims the character's arm (motion/pointing.h) at `target` from `at` for `seconds`, as far
    /// as `weight` (a curve over those seconds: the pointing gesture's fades) says: what BML's
    /// <pointing> adds to its gesture. Turned after the gaze layer, on the pose the body shows; a
    /// new pointing replaces the one on. Errors: no such character, one without that arm, a
    /// target character or joint that does not exist.
    Result<void> point(const std::string& character, const GazeTarget& target, motion::PointingHand hand,
                       anim::Curve weight, Tick at, double seconds);
    /// Fades the pointing out over `fadeSeconds` from `at` (as its gesture is cut off). False
    /// when none is on.
    Result<bool> stopPointing(const std::string& character, Tick at, double fadeSeconds);
    /// Where the camera is in the scene (the viewport's, a render's, AR's tracked camera), which
    /// "camera" targets look at; none: such a gaze waits for one.
    void setCameraPosition(std::optional<anim::Vec3d> position);
    std::optional<anim::Vec3d> cameraPosition() const;

    /// Removes every live action and gaze and empties every synthesizer slot (a script starts over).
    void resetLive();

    /// A pose set sized for this stage (evaluate() then allocates nothing).
    PoseSet makePoseSet() const;
    /// Poses every character at `t`. Live actions finished by `t` are dropped.
    void evaluate(Tick t, PoseSet& out);
    /// How many times evaluate() ran.
    std::uint64_t ticks() const;
    /// Keeps the last `frames` frames of each character's authored motion (paper §4.2's cache of
    /// rendered frames), dropped at every edit of it: where the playhead goes back over times
    /// already shown (the studio's scrubbing) a frame costs a copy. 0 (the default): no cache.
    /// Poses are the same with or without it.
    void setFrameCache(int frames);
    /// Authored frames the cache gave back so far.
    std::uint64_t frameCacheHits() const;

private:
    /// An action that plays or played: live (in `live` for Normalized actions, in `layered` for
    /// the others) or authored (in a layer). A live action dropped once finished keeps its end.
    struct Activation {
        anim::BlendingSchedule* schedule = nullptr; // null once dropped
        anim::ActionId id = 0;
        double start = 0, end = 0;                  // seconds; `end` is kept when dropped
        double endTime() const { return schedule ? schedule->endTime(id) : end; }
        bool finished(double t) const { return !schedule || schedule->isFinished(id, t); }
    };
    class HeldFrame;
    struct TrackState {
        std::shared_ptr<const anim::BlendingSchedule> authored; // null: nothing authored
        std::shared_ptr<anim::CachedBlendable> cache;          // in front of `authored`, when kept
        anim::BlendablePtr played;                              // what plays of it: the cache or itself
        std::vector<std::shared_ptr<anim::BlendingSchedule>> authoredLayers;
        std::shared_ptr<anim::BlendingSchedule> synthesizers; // 1. open-ended, Normalized
        std::shared_ptr<anim::BlendingSchedule> live;         // 3. live Normalized actions
        std::shared_ptr<anim::BlendingSchedule> layered;      // 4. what plays below, then live layered actions
        std::shared_ptr<HeldFrame> below;                     // the frame of 1–3, played first in `layered`
        std::map<std::string, ActionTemplate> library;
        std::map<std::string, Activation> latest; // by action name
        std::vector<Activation> superseded;       // earlier activations still playing
        std::map<std::string, anim::ActionId> synthSlots;
        int liveCount = 0, layeredCount = 0;     // live actions in `live` and `layered`
        std::vector<float> scratch, coverage;    // a frame and its coverage, for 2 and 3
    };
    /// A gaze or pointing target with its character and joint found on this stage.
    struct StageTarget {
        GazeTarget target;
        int character = -1, joint = -1; // of a Joint target (−1 joint: between its eyes)
    };
    struct GazeSlot {
        motion::GazeController controller;
        StageTarget target;
        double start = 0;
        std::optional<double> release;
        bool authored = false; // set by a gaze action of the scenario, not by gaze()
    };
    struct PointSlot {
        StageTarget target;
        std::vector<motion::PointingArm> arms;
        anim::Curve weight;
        double start = 0, end = 0;
        double cutAt = 0, cutFade = 0; // stopPointing(): fading out from cutAt, gone at cutAt + cutFade
        bool authored = false;         // set by a pointing action of the scenario, not by point()
    };
    struct Performer {
        std::string name;
        TrackState body, face;
        anim::Skeleton skeleton;
        std::optional<motion::GazeRig> gazeRig; // none without a head joint
        std::optional<GazeSlot> gaze;
        std::optional<PointSlot> pointing;
        int authoredCue = -1; // the scenario's gaze action playing (CharacterRuntime::gaze), or −1
        int authoredPointing = -1; // the scenario's pointing action playing (CharacterRuntime::pointing), or −1
    };

    static void fillLibrary(Performer& performer, scenario::CharacterRuntime& character);
    Result<anim::ActionId> activate(TrackState& track, const std::string& action, const ActionTemplate& source, Tick at,
                                    const ActivateOptions& options);
    /// An error naming the action when `source` is not on the track's layout.
    static Result<void> fitsTrack(const TrackState& track, const std::string& character, Track kind,
                                  const std::string& action, const ActionTemplate& source);
    void cacheAuthored(TrackState& track) const; // sets `cache` and `played` for m_cacheFrames
    Result<void> initPerformer(Performer& performer, const anim::Skeleton& skeleton,
                               std::shared_ptr<const anim::BlendingSchedule> body,
                               std::shared_ptr<const anim::BlendingSchedule> face);
    Result<Performer*> find(const std::string& character);
    Result<const Performer*> find(const std::string& character) const;
    static TrackState& state(Performer& performer, Track track);
    static const TrackState& state(const Performer& performer, Track track);
    /// The live activation, else the authored action of that name (latest started by `at`).
    std::optional<Activation> lookUp(const TrackState& track, const std::string& action, Tick at) const;
    static void drop(TrackState& track, Activation& activation);
    static void dropFinished(TrackState& track, double seconds);
    void evaluateTrack(TrackState& track, double seconds, std::vector<float>& out) const;
    /// The gaze layer over the poses of every character (runtime/stage_gaze.cpp).
    void applyGazes(double seconds, PoseSet& out);
    /// Points the performer's gaze at `target` from `start` (seconds); errors as gaze()'s.
    Result<void> aim(Performer& performer, const GazeTarget& target, const motion::GazeSettings& settings,
                     double start, bool authored);
    /// Starts the scenario's gaze action playing at `seconds`, or lets go of the one that ended.
    void followAuthoredGaze(Performer& performer, std::span<const scenario::GazeCue> cues, double seconds);
    /// Finds a target's character and joint for `performer` to `verb` ("look at", "point at").
    Result<StageTarget> findTarget(const Performer& performer, const GazeTarget& target, std::string_view verb) const;
    /// Where a target is in the scene now, from the poses in `out`; none for the camera when
    /// none is known.
    std::optional<anim::Vec3d> targetPosition(const StageTarget& target, const PoseSet& out) const;
    /// The pointing layer over the poses of every character (runtime/stage_gaze.cpp).
    void applyPointing(double seconds, PoseSet& out);
    /// Starts the scenario's pointing action playing at `seconds`, or ends the one that ended.
    void followAuthoredPointing(Performer& performer, std::span<const scenario::PointingCue> cues, double seconds);
    /// Where the performer stands: its runtime character's placement (none for one added by hand).
    anim::Placement placement(std::size_t performer) const;

    mutable std::mutex m_mutex;
    std::shared_ptr<const anim::FrameBlender> m_blender = anim::defaultBlender();
    scenario::ScenarioRuntime m_runtime;
    std::vector<Performer> m_performers;
    std::vector<Activation> m_authoredCuts; // authored actions cut off live (resetLive restores them)
    bool m_bodyEnabled = true, m_faceEnabled = true;
    std::optional<anim::Vec3d> m_camera;
    std::uint64_t m_ticks = 0;
    int m_cacheFrames = 0;
};

} // namespace thespis::core::runtime
