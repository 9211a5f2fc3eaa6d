#pragma once
// The scenario document (format "thespis-scenario", version 5): characters with their skeleton,
// body, placement, clips and gesture database (gesticon), layers of actions (the blending
// schedules) with their timeline state (mute / solo / lock), named joint masks, timeline
// markers, the light. Plain data with
// value semantics; io is in scenario_io.h, building runnable schedules in scenario_runtime.h.
// Times are exact integer ticks (util/tick.h). Fields this version does not know are kept in
// `extra` and written back unchanged.

#include <array>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "anim/blending_params.h"
#include "anim/curve.h"
#include "anim/joint_mask.h"
#include "scene/character_mesh.h"
#include "util/tick.h"

namespace thespis::core::scenario {

/// The paper's idle motion synthesizer (§4.3) as a clip (format 5): balance shifts from an idle
/// motion database (core/motion/idle_database.h) and small posture variations, open-ended.
struct IdleSynthesizer {
    std::string database;     ///< an idle motion database file (.idle), relative to the scenario
    std::uint64_t seed = 1;   ///< each character's own motion program (at most 2^53)
    double amplitude = 1;     ///< of the small posture variations: 0 none, 1 as recorded
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const IdleSynthesizer&) const = default;
};

/// Blinks (format 7): a face clip that shuts and opens the eyelids at seeded moments, open-ended
/// (core/motion/blink_synthesizer.h). 17 a minute is a person at rest, 26 one talking.
struct BlinkClip {
    double rate = 17;          ///< blinks a minute
    std::uint64_t seed = 1;
    double closeSeconds = 0.10, shutSeconds = 0.03, openSeconds = 0.25;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const BlinkClip&) const = default;

    struct Problem {
        std::string field; ///< "rate", "openSeconds" …
        std::string message;
    };
    /// What makes these blinks unplayable: a rate outside 1 … 120 a minute, times not positive
    /// (shut may be 0), a blink of 0.4 s or more.
    std::optional<Problem> problem() const;
};

/// A clip a character can play: motion capture in a file beside the scenario (BVH, or an
/// animation of a glTF file), keyframes stored inline, or an idle motion synthesizer. A file's motion is retargeted onto the
/// character's skeleton (anim/clip_retarget.h): resized by the bodies' legs and stood on the
/// floor the performer stood on.
struct ClipAsset {
    std::string name;
    std::string file;                 ///< path relative to the scenario file; empty for inline clips
    double frameRateOverride = 0;     ///< > 0: replaces the BVH header's frame rate
    // Files (format 3).
    std::string animation;            ///< glTF: the animation's name (empty: the file's first)
    /// Metres per file unit (CMU's 0.0564, 0.01 for centimetres); 0: as the file says (glTF is in
    /// metres; a BVH's convention tells, else its size). Sizes the motion where a body has no legs.
    double unit = 0;
    bool fitGround = true;            ///< stand the motion on the performer's floor
    bool keepCalibrationFrame = false;///< keep a BVH's calibration first frame (CMU's T-pose)
    /// File joint name → H-Anim name, replacing the automatic mapping (BVH) or overriding it (glTF).
    std::map<std::string, std::string> mapping;
    // Inline keyframes (file empty), per frame in this order: rotations for `joints` (x y z w
    // each), when `rootTranslation` is set the translation of joints[0] (x y z), then one value
    // per name in `scalars` (e.g. MPEG-4 FAPs "fap3", for face layers).
    double frameRate = 30;
    std::vector<std::string> joints;
    bool rootTranslation = false;
    std::vector<std::string> scalars;
    std::vector<float> frames;
    /// Set: the clip is synthesized (format 5); neither a file nor inline keyframes then.
    std::optional<IdleSynthesizer> idle;
    /// Set: the clip is blinks, for a face layer (format 7); neither a file nor keyframes then.
    std::optional<BlinkClip> blinks;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const ClipAsset&) const = default;

    /// Floats per inline frame: a quaternion per joint, the root translation, the scalars.
    std::size_t valuesPerFrame() const { return 4 * joints.size() + (rootTranslation ? 3 : 0) + scalars.size(); }
};

enum class ModifierKind { TimeStretch, TimeWarp, Loop, Mirror, GlobalTransform, TimeOffset, Trim, DependentJointFilter };

/// One modifier in an action's chain (applied in order, first wraps the clip).
struct ModifierSpec {
    ModifierKind kind = ModifierKind::Loop;
    double factor = 1;        ///< TimeStretch
    anim::Curve warp;         ///< TimeWarp: local time → source time
    double duration = 0;      ///< TimeWarp
    int count = 0;            ///< Loop: 0 = forever
    int axis = 0;             ///< Mirror
    anim::Quat rotation;      ///< GlobalTransform
    anim::Vec3 translation;   ///< GlobalTransform
    double offset = 0;        ///< TimeOffset (seconds)
    double start = 0, end = 0;///< Trim (source seconds)
    /// Loop: each repetition starts where the last one ended (root position and heading), as a
    /// walk goes on, instead of jumping back (format 3).
    bool rootMotion = false;
    /// DependentJointFilter (format 5): upper-body PCs 1 … fadeFrom kept, faded out until muteAbove,
    /// muted above (the scenario's postureBases).
    int fadeFrom = 20, muteAbove = 30;
    nlohmann::json extra = nlohmann::json::object();
    nlohmann::json warpExtra = nlohmann::json::object(); ///< unknown fields of the warp curve
    bool operator==(const ModifierSpec&) const = default;
};

/// Where an action's motion plays (format 3): as recorded (in the character's frame), from the
/// character's place and heading, or on from where the layer's previous action leaves the body.
enum class Placement { World, Character, Continue };

/// What an action on a gaze layer looks at (format 10): the Stage's gaze (motion/gaze_target.h)
/// turned toward `target` while the action lasts, with BML's influence and offset.
struct GazeSpec {
    std::string target = "camera";        ///< "camera", "Creon", "Creon:l_wrist", "0.5 1.6 2"
    std::string influence = "HEAD";       ///< EYES, HEAD, SHOULDER, WAIST
    double offsetAngle = 0;               ///< degrees away from the target …
    std::string offsetDirection;          ///< … toward RIGHT, LEFT, UP, DOWN, UPRIGHT … ("": none)
    bool operator==(const GazeSpec&) const = default;
};

/// Where a body action's gesture points (format 11): BML's <pointing target mode> put on the
/// timeline. While the action plays, the Stage aims the hand's arm (motion/pointing.h) at
/// `target`, as far as the action's weight says.
struct PointingSpec {
    std::string target = "camera";        ///< as GazeSpec::target
    std::string hand = "RIGHT_HAND";      ///< RIGHT_HAND, LEFT_HAND, BOTH_HANDS
    bool operator==(const PointingSpec&) const = default;
};

/// A gaze action lasts this long before its modifiers (a time stretch gives it its length).
inline constexpr double kGazeActionSeconds = 1.0;

struct ActionSpec {
    std::string name;
    std::string clip;                     ///< name of a ClipAsset of the character (none on a gaze layer)
    std::optional<GazeSpec> gaze;         ///< on a gaze layer, and only there
    std::optional<PointingSpec> pointing; ///< on a body layer, and only there
    Tick start = 0;
    std::vector<ModifierSpec> modifiers;
    anim::Curve weight;
    anim::Curve scale;
    std::string mask;                     ///< name of a scenario mask; empty = whole body
    anim::BlendMode mode = anim::BlendMode::Normalized;
    bool renderOutsideDomain = false;
    Placement placement = Placement::World;
    nlohmann::json extra = nlohmann::json::object();
    /// Unknown fields of the weight / scale curve objects (and, under "keys", of their keys).
    nlohmann::json weightExtra = nlohmann::json::object();
    nlohmann::json scaleExtra = nlohmann::json::object();
    bool operator==(const ActionSpec&) const = default;
};

/// Body and face layers blend clips; a gaze layer's actions turn the eyes, head and body toward
/// their targets over all of them (format 10).
enum class LayerKind { Body, Face, Gaze };
/// "body", "face", "gaze": as files write it.
const char* layerKindName(LayerKind kind);

/// A track of actions blended into one schedule; a character's layers of one kind are
/// combined in order, the first as the base and each next one with its own mode.
struct Layer {
    std::string name;
    LayerKind kind = LayerKind::Body;
    anim::BlendMode mode = anim::BlendMode::Normalized;
    std::vector<ActionSpec> actions;
    /// Timeline state (format 2). A muted layer does not play; when any layer of a character is
    /// solo, only its solo layers play. A locked layer is shown but not editable in the studio.
    bool mute = false;
    bool solo = false;
    bool lock = false;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const Layer&) const = default;
};

/// A gesture of the character's gesture database (gesticon, paper §5): a clip with the body part
/// it moves and how it is faded in and out when a speech script or the studio triggers it.
struct Gesture {
    std::string name;
    std::string clip;                  ///< name of a ClipAsset of the character
    std::string mask;                  ///< name of a scenario mask (the body part); empty = whole body
    Tick fadeIn = 0;
    Tick fadeOut = 0;
    /// Run the dependent-joint motion filter (paper §4.3) over the gesture, so that joints the
    /// gesture does not drive (spine, neck) follow it.
    bool dependentJointFilter = false;
    /// The filter's band (format 5, optional): upper-body PCs 1 … filterFadeFrom kept, faded out
    /// until filterMuteAbove, the rest muted. Later starts keep the gesture closer to its keys
    /// (paper §4.4); the paper's 20–30 suits a posture database that holds gestures like it.
    int filterFadeFrom = 20, filterMuteAbove = 30;
    /// How speech fits it to its words (format 10): a holding gesture plays at its own speed and
    /// holds its stroke (or middle) pose while the words last; otherwise it is time-scaled.
    bool hold = false;
    /// Seconds into the clip of its stroke (format 10; −1: none marked), which speech puts on the
    /// first stressed word the gesture spans.
    double stroke = -1;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const Gesture&) const = default;
};

/// A line the character says (format 9): its tagged text (speech/tagged_text.h) and the voice that
/// speaks it, and the audio made from them, which plays from `start` when the scenario does. The
/// visemes and gestures it drove were inserted as actions with it (edit/speech_edits.h); the
/// timing is kept so that the timeline can show the words and phonemes. A line without a start is
/// not on the timeline: a script says it when it likes (`voiceService.activateAction`).
struct SpeechLine {
    std::string name;
    std::optional<Tick> start = Tick(0);
    std::string text;              ///< tagged text as the user wrote it
    std::string voice = "en-us";   ///< espeak-ng voice
    int rate = 175;                ///< words a minute
    int pitch = 50;
    std::string audio;             ///< the speech's sound file, relative to the scenario
    struct Word {
        std::string text;
        double start = 0, end = 0; ///< seconds from the line's start
        bool operator==(const Word&) const = default;
    };
    struct Phoneme {
        std::string phoneme;       ///< ARPAbet or SIL
        double start = 0, end = 0;
        bool operator==(const Phoneme&) const = default;
    };
    std::vector<Word> words;
    std::vector<Phoneme> phonemes;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const SpeechLine&) const = default;
};

struct Character {
    std::string name;
    /// "hanim-loa1", "hanim-loa2", "hanim-25", "model" for the glTF model's own rig (format 3),
    /// or "clip:NAME" to use a BVH clip's own skeleton.
    std::string skeleton = "hanim-loa1";
    /// Where the character stands (metres) and which way it faces (degrees about +Y; 0 faces +Z):
    /// its whole motion is moved so (format 3).
    anim::Vec3 position;
    double heading = 0;
    /// glTF file of the character's body (path relative to the scenario); empty = the built-in
    /// procedural humanoid.
    std::string model;
    /// Receiver / occluder and PI / PD tags of the model's segments (paper §6.1.3), by segment name.
    std::vector<scene::SegmentTag> segmentTags;
    /// The character's PRT transfer bake (a bake file made by the studio's bake panel or
    /// `thespis-cli bake`; path relative to the scenario); empty = unshadowed (DU) transfer. A bake
    /// that is missing or no longer fits the body (its tags changed since) is left out with a warning.
    std::string bake;
    /// The face mapping table its glTF model's face follows (a `thespis-face-mapping` file,
    /// scene/face_mapping.h; path relative to the scenario); empty = the table recognised from the
    /// model's names (format 8). The built-in humanoid has its own face and ignores it (a warning
    /// says so). A table that is missing or cannot be read is left out with a warning.
    std::string faceMapping;
    std::vector<ClipAsset> clips;
    std::vector<Layer> layers;
    std::vector<Gesture> gestures;     ///< format 2
    std::vector<SpeechLine> speech;    ///< format 9
    /// BML gesture lexemes → names of its gestures (format 12; speech/bml_lexicon.h): the table a
    /// <gesture lexeme="BEAT"> is looked up in. nullopt: the defaults (speech::BmlLexicon::defaults()).
    std::optional<std::map<std::string, std::string>> bmlLexicon;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const Character&) const = default;

    const Gesture* findGesture(const std::string& name) const;
    const ClipAsset* findClip(const std::string& name) const;
};

struct NamedMask {
    std::string name;
    anim::JointMask mask;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const NamedMask&) const = default;
};

/// The distant light (paper §6): an HDR probe file (path relative to the scenario) and its layout
/// ("angular", "latlong", "mirrorball", "cross"). No probe: the studio's default light.
struct LightingSpec {
    std::string probe;
    std::string layout = "latlong";
    double rotation = 0;  ///< degrees about the vertical axis (format 3)
    double intensity = 1; ///< a multiplier of the probe's radiance (format 3)
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const LightingSpec&) const = default;
};

/// A real object that hides the characters behind it when they play over video (paper §7.2's
/// phantom objects): drawn into depth only, so the video shows through it and covers what is
/// behind it. In the scenario's world (metres, y up), like the characters (format 5, optional).
struct PhantomOccluder {
    enum class Shape { Box, Plane, Model };
    std::string name;
    Shape shape = Shape::Box;
    /// Box: the centre of its bottom face; plane: the middle of its bottom edge; model: its origin.
    std::array<double, 3> position{};
    /// Box: width (x), height (y), depth (z); plane: width and height (upright, facing +z; the
    /// third is unused); model: its scale along x, y, z.
    std::array<double, 3> size{0.3, 0.3, 0.3};
    double heading = 0;    ///< degrees about the vertical axis
    std::string model;     ///< a glTF file (relative to the scenario) for a Model
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const PhantomOccluder&) const = default;
};

/// How the scenario plays over tracked video (format 5, optional): where its world sits on the
/// tracked target, what real objects hide the characters, and whether their shadows fall on the
/// real ground.
struct ArSpec {
    /// The world's origin on the target's plane: metres from the target's centre along its x and
    /// y axes (the board's or the picture's).
    std::array<double, 2> offset{};
    double heading = 0;  ///< degrees the world turns about the target's normal
    double scale = 1;    ///< of life size: 0.1 stands a 1.8 m character 18 cm tall on a desk
    std::vector<PhantomOccluder> occluders;
    /// Soft shadows of the characters darken the real ground (no ground disc is drawn over video).
    bool shadowCatcher = true;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const ArSpec&) const = default;
};

/// A named point on the timeline (format 2): a cue the animator snaps actions to.
struct Marker {
    std::string name;
    Tick time = 0;
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const Marker&) const = default;
};

/// A Python script kept in the scenario (format 4), run in the studio's Script dock or by
/// `thespis-cli run --script NAME` — only once the user trusts the file it came in.
struct ScriptSpec {
    std::string name;
    std::string source; ///< Python source text
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const ScriptSpec&) const = default;
};

struct Scenario {
    std::string name;
    Tick duration = 0; ///< length of the scenario's timeline (0: up to the last action's end)
    std::vector<Character> characters;
    std::vector<NamedMask> masks;
    LightingSpec lighting;
    std::vector<Marker> markers;       ///< format 2
    std::vector<ScriptSpec> scripts;   ///< format 4
    /// The posture bases (.pca, thespis-cli train-pca; path relative to the scenario) the
    /// dependent-joint filter works in (format 5); empty: no filter can play.
    std::string postureBases;
    ArSpec ar;                         ///< format 5, optional
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const Scenario&) const = default;

    const Character* findCharacter(const std::string& name) const;
    const NamedMask* findMask(const std::string& name) const;
    const ScriptSpec* findScript(const std::string& name) const;
};

/// Names a rebase leaves as they are (a package's entries, which travel with it).
using KeptNames = std::function<bool(const std::string&)>;
/// A file path relative to folder `from`, rewritten to name the same file relative to folder `to`
/// (saving a scenario to another folder). Empty and absolute paths, and those `keep` says, are
/// returned as they are.
std::string rebasedPath(const std::string& path, const std::filesystem::path& from, const std::filesystem::path& to,
                        const KeptNames& keep = {});
/// rebasedPath() on the files a clip names: its motion file or its idle motion database.
void rebaseClip(ClipAsset& clip, const std::filesystem::path& from, const std::filesystem::path& to,
                const KeptNames& keep = {});
/// rebasedPath() on every file path of the scenario: models, bakes, clips, speech audio, the light
/// probe, the posture bases and the phantom occluders' models.
void rebasePaths(Scenario& scenario, const std::filesystem::path& from, const std::filesystem::path& to,
                 const KeptNames& keep = {});

} // namespace thespis::core::scenario
