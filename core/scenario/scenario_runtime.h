#pragma once
// Turns a scenario document into runnable blending schedules: loads every clip (motion files
// relative to the scenario's folder, retargeted onto the character; inline keyframes), builds
// each character's skeleton, applies modifiers and placements, resolves masks and fills one
// schedule per layer, nested in one schedule per character and kind (body, face). The document is not changed; problems are errors naming
// the character, action and field.

#include <filesystem>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "anim/blending_schedule.h"
#include "anim/keyframe_clip.h"
#include "anim/root_motion.h"
#include "anim/skeleton.h"
#include "motion/gaze_target.h"
#include "scenario/clip_file.h"
#include "scenario/pointing_cue.h"
#include "scenario/scenario.h"
#include "speech/bml_lexicon.h"
#include "util/error.h"

namespace thespis::core::scenario {

/// A gesture of the character's gesticon as the actions that play it live (gesture_action.h),
/// with and without the dependent-joint filter, so that the studio can compare the two. The
/// filtered one is missing (null source) when the scenario names no posture bases.
struct GestureActions {
    anim::BlendingAction withFilter, withoutFilter;
    bool filter = false; ///< the gesture's own choice
    double fadeIn = 0, fadeOut = 0; ///< seconds
    bool hold = false;              ///< Gesture::hold
    double stroke = -1;             ///< Gesture::stroke, seconds into the clip (−1: none)
    bool face = false;              ///< its clip moves no joint, only the face: it plays on the face track
    const anim::BlendingAction& played() const { return filter ? withFilter : withoutFilter; }
};

/// An action of a gaze layer that plays: from `start` to `end` (seconds) the character looks at
/// `target` (Stage's gaze layer) with `settings` (BML's influence and offset; the rest default).
struct GazeCue {
    double start = 0, end = 0;
    motion::GazeTarget target;
    motion::GazeSettings settings;
};

/// A character's schedules. Every layer is built (so that its actions are checked and can be
/// found by id), but only the layers that play — not muted, and solo when any layer of the
/// character is solo — are nested in `body` / `face`.
struct CharacterRuntime {
    std::string name;
    anim::Skeleton skeleton;
    /// Where the character stands and faces (Character::position, heading).
    anim::Placement placement;
    /// On the skeleton's layout: recorded clips (keyframes) and synthesized ones (idle motion).
    std::map<std::string, anim::BlendablePtr> clips;
    /// The clips with MPEG-4 FAP values, on the face layout.
    std::map<std::string, anim::BlendablePtr> faceClips;
    /// The gesticon, by gesture name (gestures that cannot be built are left out, with a warning).
    std::map<std::string, GestureActions> gestures;
    /// The character's speech lines: what scripts say with voiceService.activateAction.
    std::vector<SpeechLine> speech;
    /// Its BML gesture lexemes → gestures (Character::bmlLexicon, else the defaults), which BML
    /// played on the Stage looks gestures up in.
    speech::BmlLexicon bmlLexicon;
    /// What its gaze layers that play look at, by start.
    std::vector<GazeCue> gaze;
    /// Where its body layers that play point (format 11), by start.
    std::vector<PointingCue> pointing;
    std::shared_ptr<anim::BlendingSchedule> body;       ///< every body layer, nested
    std::shared_ptr<anim::BlendingSchedule> face;       ///< every face layer (MPEG-4 FAPs), nested
    std::vector<std::shared_ptr<anim::BlendingSchedule>> layers; ///< per Layer, same order
    std::vector<std::vector<anim::ActionId>> actionIds; ///< per layer, per ActionSpec
    std::vector<std::string> warnings;                  ///< e.g. unmapped BVH joints
    std::vector<std::string> warningClips;              ///< per warning, the clip it is about ("": none)
    /// What reading each file clip found, by clip name (for the studio's import report).
    std::map<std::string, ClipFileReport> clipReports;

    /// The body at `seconds`: the body schedule, placed where the character stands. Allocates
    /// nothing; `frame` has the skeleton layout's floatCount().
    void evaluateBody(double seconds, std::span<float> frame) const;
    /// Moves a body frame of `layout` (this skeleton's, or the rig it is retargeted onto) to where
    /// the character stands: its root turned by the heading and shifted by the position.
    void place(const anim::FrameLayout& layout, std::span<float> frame) const;
};

struct ScenarioRuntime {
    std::vector<CharacterRuntime> characters;
    Tick duration = 0; ///< Scenario::duration, or the latest end of a finite action
    const CharacterRuntime* findCharacter(const std::string& name) const;
};

/// `assets` is where the scenario's files are found (the scenario file's folder). `cache`
/// (optional) keeps the files read between builds.
Result<ScenarioRuntime> buildRuntime(const Scenario& scenario, const Assets& assets,
                                     AssetCache* cache = nullptr);

/// `previous` (this scenario's runtime before an edit that kept its characters) with only the
/// characters at `characters` built again from `scenario` — what an edit touched
/// (edit::Edit::runtimeScope) — the others shared with it. Errors as buildRuntime's.
Result<ScenarioRuntime> rebuildRuntime(const Scenario& scenario, const Assets& assets, const ScenarioRuntime& previous,
                                       std::span<const int> characters, AssetCache* cache = nullptr);
/// Checks a scenario without keeping the result: every problem found, empty when valid.
std::vector<Error> validateScenario(const Scenario& scenario, const Assets& assets);

} // namespace thespis::core::scenario
