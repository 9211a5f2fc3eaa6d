// Bindings of the scenario document (core/scenario): the plain-data model (formats 2 and 3:
// layer mute / solo / lock, gestures, markers, bakes, clip import options, placement), importing
// motion files, reading and writing .thespis files, validation and building runnable schedules.
// Document objects are values: reading a list field (`scenario.characters`) gives a copy, edited
// and assigned back. (Views into the C++ lists would dangle as soon as the list grows, crashing a
// script that kept one.)

#include <map>
#include <optional>
#include <string>
#include <tuple>

#include "bind_common.h"
#include "bind_package.h"
#include "errors.h"
#include "run_job.h"
#include "scenario/clip_import.h"
#include "runtime/motion_bake_job.h"
#include "scenario/scenario.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "util/tick.h"

namespace thespis::python {

using namespace pybind11::literals;
using namespace core::scenario;
namespace anim = core::anim;

namespace {

// Unknown fields (`extra`) cross as plain Python objects through the json module, so they keep
// exactly the JSON they will be written back as.
py::object jsonToPython(const nlohmann::json& value)
{
    return py::module_::import("json").attr("loads")(value.dump());
}

nlohmann::json jsonFromPython(const py::object& value, const char* what)
{
    const std::string text = py::module_::import("json").attr("dumps")(value).cast<std::string>();
    nlohmann::json parsed = nlohmann::json::parse(text, nullptr, false);
    if (parsed.is_discarded() || !parsed.is_object())
        throw py::value_error(std::string(what) + " must be a dict of JSON values.");
    return parsed;
}

// A list field as a property that reads a copy and assigns a whole new list. (def_readwrite
// would hand out references into the C++ vector, which dangle once the vector grows.)
template <class T, class Item>
void defList(py::class_<T>& cls, const char* name, std::vector<Item> T::*member, const char* doc = "")
{
    cls.def_property(
        name, [member](const T& value) { return value.*member; },
        [member](T& value, std::vector<Item> items) { value.*member = std::move(items); }, doc);
}

template <class T>
void defExtra(py::class_<T>& cls)
{
    cls.def_property(
        "extra", [](const T& value) { return jsonToPython(value.extra); },
        [](T& value, const py::object& extra) { value.extra = jsonFromPython(extra, "extra"); },
        "Fields this format version does not know, kept and written back unchanged (a copy).");
}

void bindDocument(py::module_& m)
{
    py::enum_<LayerKind>(m, "LayerKind", "What a layer animates.")
        .value("body", LayerKind::Body)
        .value("face", LayerKind::Face)
        .value("gaze", LayerKind::Gaze);

    py::enum_<Placement>(m, "Placement", "Where an action's motion plays.")
        .value("world", Placement::World, "as recorded, in the character's frame")
        .value("character", Placement::Character, "its first frame where the character stands, facing its way")
        .value("continue_", Placement::Continue, "on from where the layer's previous action leaves the body");

    py::enum_<ModifierKind>(m, "ModifierKind", "Kind of a modifier in an action's chain.")
        .value("time_stretch", ModifierKind::TimeStretch)
        .value("time_warp", ModifierKind::TimeWarp)
        .value("loop", ModifierKind::Loop)
        .value("mirror", ModifierKind::Mirror)
        .value("global_transform", ModifierKind::GlobalTransform)
        .value("time_offset", ModifierKind::TimeOffset)
        .value("trim", ModifierKind::Trim)
        .value("dependent_joint_filter", ModifierKind::DependentJointFilter);

    py::class_<IdleSynthesizer> idle(m, "IdleSynthesizer",
                                     "The paper's idle motion (§4.3) as a clip: balance shifts from an idle motion database "
                                     "(.idle, thespis-cli build-idle) and small posture variations, open-ended.");
    idle.def(py::init([](std::string database, std::uint64_t seed, double amplitude) {
                 return IdleSynthesizer{std::move(database), seed, amplitude};
             }),
             "database"_a, "seed"_a = 1, "amplitude"_a = 1.0)
        .def_readwrite("database", &IdleSynthesizer::database, "The .idle file, relative to the scenario.")
        .def_readwrite("seed", &IdleSynthesizer::seed, "The character's own motion program (at most 2**53).")
        .def_readwrite("amplitude", &IdleSynthesizer::amplitude,
                       "Of the small posture variations: 0 none, 1 as recorded (at most 10).")
        .def("__eq__", [](const IdleSynthesizer& a, const IdleSynthesizer& b) { return a == b; })
        .def("__repr__", [](const IdleSynthesizer& a) {
            return "<thespis.IdleSynthesizer " + a.database + " seed " + std::to_string(a.seed) + ">";
        });
    defExtra(idle);

    py::class_<BlinkClip> blinks(m, "BlinkClip",
                                 "Blinks as a face clip: the eyelids shut and open at seeded moments, `rate` a minute "
                                 "(17 a person at rest, 26 one talking), open-ended.");
    blinks.def(py::init([](double rate, std::uint64_t seed) {
                   BlinkClip b;
                   b.rate = rate;
                   b.seed = seed;
                   return b;
               }),
               "rate"_a = 17.0, "seed"_a = 1)
        .def_readwrite("rate", &BlinkClip::rate, "Blinks a minute (1 to 120).")
        .def_readwrite("seed", &BlinkClip::seed, "Which moments (at most 2**53): the same seed, the same blinks.")
        .def_readwrite("close_seconds", &BlinkClip::closeSeconds, "From open to shut.")
        .def_readwrite("shut_seconds", &BlinkClip::shutSeconds, "Held shut.")
        .def_readwrite("open_seconds", &BlinkClip::openSeconds, "From shut to open (a whole blink under 0.4 s).")
        .def("__eq__", [](const BlinkClip& a, const BlinkClip& b) { return a == b; })
        .def("__repr__", [](const BlinkClip& b) {
            return "<thespis.BlinkClip " + std::to_string(b.rate) + " a minute, seed " + std::to_string(b.seed) + ">";
        });
    defExtra(blinks);

    py::class_<ClipAsset> clip(m, "ClipAsset",
                               "A clip a character can play: a motion file beside the scenario (BVH, or an animation "
                               "of a glTF file), retargeted onto the character, inline keyframes, or idle motion.");
    clip.def(py::init([](std::string name, std::string file) {
                 ClipAsset asset;
                 asset.name = std::move(name);
                 asset.file = std::move(file);
                 return asset;
             }),
             "name"_a = "", "file"_a = "")
        .def_readwrite("name", &ClipAsset::name)
        .def_readwrite("file", &ClipAsset::file, "Path relative to the scenario file; empty for inline clips.")
        .def_readwrite("frame_rate_override", &ClipAsset::frameRateOverride, "> 0: replaces the BVH frame rate.")
        .def_readwrite("frame_rate", &ClipAsset::frameRate, "Inline clips: frames per second.")
        .def_readwrite("animation", &ClipAsset::animation, "glTF files: the animation's name ('' = the first).")
        .def_readwrite("unit", &ClipAsset::unit,
                       "Files: metres per file unit (CMU 0.0564, centimetres 0.01); 0 = as the file tells.")
        .def_readwrite("fit_ground", &ClipAsset::fitGround, "Files: stand the motion on the performer's floor.")
        .def_readwrite("keep_calibration_frame", &ClipAsset::keepCalibrationFrame,
                       "BVH files: keep a first frame that is a calibration pose (CMU's T-pose).")
        .def_readwrite("mapping", &ClipAsset::mapping,
                       "Files: file joint name → H-Anim name, replacing the automatic naming (a copy).")
        .def_readwrite("root_translation", &ClipAsset::rootTranslation,
                       "Inline clips: frames hold the translation of joints[0].")
        .def_property(
            "frames", [](const ClipAsset& a) { return toArray<float>(a.frames); },
            [](ClipAsset& a, const py::array_t<float, py::array::c_style | py::array::forcecast>& frames) {
                a.frames.assign(frames.data(), frames.data() + frames.size());
            },
            "Inline clips: per frame the joints' rotations (x y z w), the root translation, the scalars; flat (a copy).")
        .def_readwrite("idle", &ClipAsset::idle,
                       "An IdleSynthesizer when the clip is synthesized idle motion (then no file, no keyframes); None else.")
        .def_readwrite("blinks", &ClipAsset::blinks,
                       "A BlinkClip when the clip is blinks for a face layer (then no file, no keyframes); None else.")
        .def("__eq__", [](const ClipAsset& a, const ClipAsset& b) { return a == b; })
        .def("__repr__", [](const ClipAsset& a) {
            const std::string kind = a.blinks ? std::string("blinks")
                                     : a.idle ? "idle " + a.idle->database
                                     : a.file.empty() ? std::string("inline")
                                                      : a.file;
            return "<thespis.ClipAsset '" + a.name + "' " + kind + ">";
        });
    defExtra(clip);
    defList(clip, "joints", &ClipAsset::joints, "Inline clips: the joints rotated, in frame order.");
    defList(clip, "scalars", &ClipAsset::scalars, "Inline clips: scalar elements (e.g. MPEG-4 FAPs 'fap3').");

    py::class_<ModifierSpec> modifier(m, "ModifierSpec", "One modifier in an action's chain; the fields its kind uses are set.");
    modifier
        .def(py::init([](ModifierKind kind) {
                 ModifierSpec spec;
                 spec.kind = kind;
                 return spec;
             }),
             "kind"_a = ModifierKind::Loop)
        .def_readwrite("kind", &ModifierSpec::kind)
        .def_readwrite("factor", &ModifierSpec::factor, "time_stretch")
        .def_readwrite("warp", &ModifierSpec::warp, "time_warp: local time → source time")
        .def_readwrite("duration", &ModifierSpec::duration, "time_warp")
        .def_readwrite("count", &ModifierSpec::count, "loop: 0 = forever")
        .def_readwrite("axis", &ModifierSpec::axis, "mirror")
        .def_readwrite("rotation", &ModifierSpec::rotation, "global_transform (x, y, z, w)")
        .def_readwrite("translation", &ModifierSpec::translation, "global_transform")
        .def_readwrite("offset", &ModifierSpec::offset, "time_offset (seconds)")
        .def_readwrite("start", &ModifierSpec::start, "trim (source seconds)")
        .def_readwrite("end", &ModifierSpec::end, "trim (source seconds)")
        .def_readwrite("fade_from", &ModifierSpec::fadeFrom, "dependent_joint_filter: upper-body PCs kept up to it")
        .def_readwrite("mute_above", &ModifierSpec::muteAbove, "dependent_joint_filter: PCs above it muted")
        .def_readwrite("root_motion", &ModifierSpec::rootMotion,
                       "loop: each repetition starts where the last ended, as a walk goes on")
        .def("__eq__", [](const ModifierSpec& a, const ModifierSpec& b) { return a == b; });
    defExtra(modifier);

    py::class_<core::scenario::GazeSpec>(m, "GazeSpec", "What an action of a gaze layer looks at (format 10).")
        .def(py::init([](std::string target, std::string influence, double offsetAngle, std::string offsetDirection) {
                 return core::scenario::GazeSpec{std::move(target), std::move(influence), offsetAngle,
                                                 std::move(offsetDirection)};
             }),
             "target"_a = "camera", "influence"_a = "HEAD", "offset_angle"_a = 0.0, "offset_direction"_a = "")
        .def_readwrite("target", &core::scenario::GazeSpec::target,
                       "'camera', a character ('Creon'), a joint of one ('Creon:r_radiocarpal') or a point ('0.5 1.6 2').")
        .def_readwrite("influence", &core::scenario::GazeSpec::influence, "EYES, HEAD, SHOULDER or WAIST.")
        .def_readwrite("offset_angle", &core::scenario::GazeSpec::offsetAngle, "Degrees away from the target.")
        .def_readwrite("offset_direction", &core::scenario::GazeSpec::offsetDirection,
                       "RIGHT, LEFT, UP, DOWN, UPRIGHT, UPLEFT, DOWNRIGHT, DOWNLEFT.")
        .def("__eq__", [](const core::scenario::GazeSpec& a, const core::scenario::GazeSpec& b) { return a == b; })
        .def("__repr__", [](const core::scenario::GazeSpec& g) {
            return "<thespis.GazeSpec at '" + g.target + "' (" + g.influence + ")>";
        });

    py::class_<core::scenario::PointingSpec>(m, "PointingSpec",
                                             "Where a body action's gesture points its arm (format 11).")
        .def(py::init([](std::string target, std::string hand) {
                 return core::scenario::PointingSpec{std::move(target), std::move(hand)};
             }),
             "target"_a = "camera", "hand"_a = "RIGHT_HAND")
        .def_readwrite("target", &core::scenario::PointingSpec::target, "As GazeSpec.target.")
        .def_readwrite("hand", &core::scenario::PointingSpec::hand, "RIGHT_HAND, LEFT_HAND or BOTH_HANDS.")
        .def("__eq__", [](const core::scenario::PointingSpec& a, const core::scenario::PointingSpec& b) { return a == b; })
        .def("__repr__", [](const core::scenario::PointingSpec& p) {
            return "<thespis.PointingSpec at '" + p.target + "' (" + p.hand + ")>";
        });

    py::class_<ActionSpec> action(m, "ActionSpec", "An action of a layer: which clip, when (ticks), how it blends.");
    action
        .def(py::init([](std::string name, std::string clipName, core::Tick start) {
                 ActionSpec spec;
                 spec.name = std::move(name);
                 spec.clip = std::move(clipName);
                 spec.start = start;
                 return spec;
             }),
             "name"_a = "", "clip"_a = "", "start"_a = core::Tick(0))
        .def_readwrite("name", &ActionSpec::name)
        .def_readwrite("clip", &ActionSpec::clip, "Name of a ClipAsset of the character.")
        .def_readwrite("gaze", &ActionSpec::gaze, "On a gaze layer: what it looks at (a GazeSpec); None elsewhere.")
        .def_readwrite("pointing", &ActionSpec::pointing,
                       "On a body layer: where its gesture's arm points (a PointingSpec); None when it does not.")
        .def_readwrite("start", &ActionSpec::start, "Start time in ticks (thespis.TICKS_PER_SECOND per second).")
        .def_property(
            "start_seconds", [](const ActionSpec& a) { return core::ticksToSeconds(a.start); },
            [](ActionSpec& a, double seconds) { a.start = core::secondsToTicks(seconds); },
            "Start time in seconds (rounded to the nearest tick when set).")
        .def_readwrite("weight", &ActionSpec::weight)
        .def_readwrite("scale", &ActionSpec::scale)
        .def_readwrite("mask", &ActionSpec::mask, "Name of a scenario mask; empty = whole body.")
        .def_readwrite("mode", &ActionSpec::mode)
        .def_readwrite("render_outside_domain", &ActionSpec::renderOutsideDomain)
        .def_readwrite("placement", &ActionSpec::placement,
                       "Where its motion plays: as recorded, from the character's place, or on from the previous action.")
        .def("__eq__", [](const ActionSpec& a, const ActionSpec& b) { return a == b; })
        .def("__repr__", [](const ActionSpec& a) {
            return "<thespis.ActionSpec '" + a.name + "' clip '" + a.clip + "'>";
        });
    defExtra(action);
    defList(action, "modifiers", &ActionSpec::modifiers, "The modifier chain, first wrapping the clip (a copy).");

    py::class_<Layer> layer(m, "Layer", "A track of actions blended into one schedule.");
    layer
        .def(py::init([](std::string name, LayerKind kind, anim::BlendMode mode) {
                 Layer l;
                 l.name = std::move(name);
                 l.kind = kind;
                 l.mode = mode;
                 return l;
             }),
             "name"_a = "", "kind"_a = LayerKind::Body, "mode"_a = anim::BlendMode::Normalized)
        .def_readwrite("name", &Layer::name)
        .def_readwrite("kind", &Layer::kind)
        .def_readwrite("mode", &Layer::mode, "How the layer combines with the layers before it.")
        .def_readwrite("mute", &Layer::mute, "A muted layer does not play.")
        .def_readwrite("solo", &Layer::solo, "When any layer of a character is solo, only its solo layers play.")
        .def_readwrite("lock", &Layer::lock, "A locked layer is shown but not editable in the studio.")
        .def("__eq__", [](const Layer& a, const Layer& b) { return a == b; })
        .def("__repr__", [](const Layer& l) {
            const std::string flags =
                std::string(l.mute ? " muted" : "") + (l.solo ? " solo" : "") + (l.lock ? " locked" : "");
            return "<thespis.Layer '" + l.name + "' " + std::to_string(l.actions.size()) + " actions" + flags + ">";
        });
    defExtra(layer);
    defList(layer, "actions", &Layer::actions, "The layer's actions (a copy).");

    py::class_<Gesture> gesture(m, "Gesture",
                                "A gesture of the character's gesture database (gesticon): a clip, the body part "
                                "it moves and its fades (ticks).");
    gesture
        .def(py::init([](std::string name, std::string clipName, std::string mask) {
                 Gesture g;
                 g.name = std::move(name);
                 g.clip = std::move(clipName);
                 g.mask = std::move(mask);
                 return g;
             }),
             "name"_a = "", "clip"_a = "", "mask"_a = "")
        .def_readwrite("name", &Gesture::name)
        .def_readwrite("clip", &Gesture::clip, "Name of a ClipAsset of the character.")
        .def_readwrite("mask", &Gesture::mask, "Name of a scenario mask (the body part); empty = whole body.")
        .def_readwrite("fade_in", &Gesture::fadeIn, "Fade-in time in ticks.")
        .def_readwrite("fade_out", &Gesture::fadeOut, "Fade-out time in ticks.")
        .def_readwrite("dependent_joint_filter", &Gesture::dependentJointFilter,
                       "Run the dependent-joint motion filter, so that joints the gesture does not drive follow it.")
        .def_readwrite("filter_fade_from", &Gesture::filterFadeFrom, "The filter keeps upper-body PCs up to it (20).")
        .def_readwrite("filter_mute_above", &Gesture::filterMuteAbove, "The filter mutes PCs above it (30).")
        .def_readwrite("hold", &Gesture::hold,
                       "Speech plays it at its own speed and holds its stroke while the words last (else: stretched).")
        .def_readwrite("stroke", &Gesture::stroke,
                       "Seconds into the clip of its stroke, which speech puts on the stressed word (-1: none).")
        .def("__eq__", [](const Gesture& a, const Gesture& b) { return a == b; })
        .def("__repr__", [](const Gesture& g) {
            return "<thespis.Gesture '" + g.name + "' clip '" + g.clip + "'>";
        });
    defExtra(gesture);

    py::class_<SpeechLine> speechLine(m, "SpeechLine",
                                      "A line a character says (format 9): its tagged text, voice, audio file and "
                                      "timing (thespis.speech.insert makes one).");
    speechLine.def(py::init<>())
        .def_readwrite("name", &SpeechLine::name)
        .def_readwrite("start", &SpeechLine::start, "Where it starts, in ticks; None: not on the timeline (a script says it with voiceService.activateAction).")
        .def_readwrite("text", &SpeechLine::text, "Tagged text as written.")
        .def_readwrite("voice", &SpeechLine::voice, "The espeak-ng voice.")
        .def_readwrite("rate", &SpeechLine::rate, "Words a minute.")
        .def_readwrite("pitch", &SpeechLine::pitch)
        .def_readwrite("audio", &SpeechLine::audio, "The speech's sound file, relative to the scenario.")
        .def_property_readonly("words", [](const SpeechLine& l) {
            std::vector<std::tuple<std::string, double, double>> out;
            for (const auto& w : l.words)
                out.emplace_back(w.text, w.start, w.end);
            return out;
        }, "[(text, start, end)] in seconds from the line's start")
        .def_property_readonly("phonemes", [](const SpeechLine& l) {
            std::vector<std::tuple<std::string, double, double>> out;
            for (const auto& p : l.phonemes)
                out.emplace_back(p.phoneme, p.start, p.end);
            return out;
        }, "[(ARPAbet or 'SIL', start, end)] in seconds from the line's start")
        .def("__eq__", [](const SpeechLine& a, const SpeechLine& b) { return a == b; })
        .def("__repr__", [](const SpeechLine& l) { return "<thespis.SpeechLine '" + l.name + "': " + l.text + ">"; });
    defExtra(speechLine);

    py::class_<Character> character(m, "Character", "A character: its skeleton, clips and layers of actions.");
    character
        .def(py::init([](std::string name, std::string skeleton) {
                 Character c;
                 c.name = std::move(name);
                 c.skeleton = std::move(skeleton);
                 return c;
             }),
             "name"_a = "", "skeleton"_a = "hanim-loa1")
        .def_readwrite("name", &Character::name)
        .def_readwrite("skeleton", &Character::skeleton,
                       "'hanim-loa1', 'hanim-loa2', 'hanim-25', 'model' for its glTF model's own rig, or 'clip:NAME' "
                       "for a BVH clip's own skeleton.")
        .def_readwrite("position", &Character::position, "Where it stands, metres (x, y, z).")
        .def_readwrite("heading", &Character::heading, "Which way it faces: degrees about +Y (0 faces +Z).")
        .def("__eq__", [](const Character& a, const Character& b) { return a == b; })
        .def("__repr__", [](const Character& c) {
            return "<thespis.Character '" + c.name + "' " + std::to_string(c.clips.size()) + " clips, "
                   + std::to_string(c.layers.size()) + " layers>";
        });
    defExtra(character);
    character.def_readwrite("model", &Character::model,
                            "glTF file of the body, relative to the scenario; '' = the built-in humanoid.");
    character.def_readwrite("bake", &Character::bake,
                            "PRT transfer bake file, relative to the scenario; '' = unshadowed (DU) transfer.");
    character.def_readwrite("face_mapping", &Character::faceMapping,
                            "Face mapping table file (thespis.face.FaceMapping saved as JSON) its glTF model's face "
                            "follows, relative to the scenario; '' = the table recognised from the model's names "
                            "(format 8).");
    defList(character, "segment_tags", &Character::segmentTags,
            "Receiver / occluder and PI / PD tags of the model's segments (thespis.scene.SegmentTag, a copy).");
    defList(character, "clips", &Character::clips, "The character's clips (a copy).");
    defList(character, "layers", &Character::layers, "The character's layers (a copy).");
    defList(character, "gestures", &Character::gestures, "The character's gesture database (a copy).");
    defList(character, "speech", &Character::speech, "The lines the character says (format 9; a copy).");
    character.def_readwrite("bml_lexicon", &Character::bmlLexicon,
                            "Its BML gesture lexemes → gesture names ({'BEAT': 'agree', …}, format 12; a copy), which "
                            "BML's <gesture lexeme> is looked up in; None = the defaults "
                            "(thespis.bml.default_lexicon()).");
    character.def(
        "find_gesture",
        [](const Character& c, const std::string& name) -> std::optional<Gesture> {
            const Gesture* found = c.findGesture(name);
            return found ? std::optional<Gesture>(*found) : std::nullopt;
        },
        "name"_a, "A copy of the gesture called `name`, or None.");

    py::class_<NamedMask> namedMask(m, "NamedMask", "A joint mask shared by actions, by name.");
    namedMask.def(py::init([](std::string name, anim::JointMask mask) {
                 NamedMask named;
                 named.name = std::move(name);
                 named.mask = std::move(mask);
                 return named;
             }),
             "name"_a = "", "mask"_a = anim::JointMask())
        .def_readwrite("name", &NamedMask::name)
        .def_readwrite("mask", &NamedMask::mask)
        .def("__eq__", [](const NamedMask& a, const NamedMask& b) { return a == b; });
    defExtra(namedMask);

    py::class_<LightingSpec> lighting(m, "LightingSpec", "The scene's distant light: an HDR probe file and its layout.");
    lighting.def(py::init([](std::string probe, std::string layout) { return LightingSpec{std::move(probe), std::move(layout)}; }),
                 "probe"_a = "", "layout"_a = "latlong")
        .def_readwrite("probe", &LightingSpec::probe, "Probe file relative to the scenario; '' = the default light.")
        .def_readwrite("layout", &LightingSpec::layout, "'angular', 'latlong', 'mirrorball' or 'cross'.")
        .def_readwrite("rotation", &LightingSpec::rotation, "Degrees about the vertical axis.")
        .def_readwrite("intensity", &LightingSpec::intensity, "A multiplier of the probe's radiance.")
        .def("__eq__", [](const LightingSpec& a, const LightingSpec& b) { return a == b; });
    defExtra(lighting);

    py::class_<Marker> marker(m, "Marker", "A named point on the timeline (ticks): a cue actions snap to.");
    marker.def(py::init([](std::string name, core::Tick time) {
                 Marker mk;
                 mk.name = std::move(name);
                 mk.time = time;
                 return mk;
             }),
             "name"_a = "", "time"_a = core::Tick(0))
        .def_readwrite("name", &Marker::name)
        .def_readwrite("time", &Marker::time, "Time in ticks (thespis.TICKS_PER_SECOND per second).")
        .def("__eq__", [](const Marker& a, const Marker& b) { return a == b; })
        .def("__repr__", [](const Marker& mk) {
            return "<thespis.Marker '" + mk.name + "' at " + std::to_string(mk.time) + " ticks>";
        });
    defExtra(marker);

    py::class_<ScriptSpec> script(m, "Script", "A Python script kept in the scenario (run it with thespis-cli run --script NAME).");
    script.def(py::init([](std::string name, std::string source) { return ScriptSpec{std::move(name), std::move(source), nlohmann::json::object()}; }),
               "name"_a = "", "source"_a = "")
        .def_readwrite("name", &ScriptSpec::name)
        .def_readwrite("source", &ScriptSpec::source)
        .def("__eq__", [](const ScriptSpec& a, const ScriptSpec& b) { return a == b; })
        .def("__repr__", [](const ScriptSpec& s) { return "<thespis.Script '" + s.name + "'>"; });
    defExtra(script);

    py::class_<Scenario> scenario(m, "Scenario",
                                  "The scenario document (format 'thespis-scenario'): characters, masks and the "
                                  "timeline's duration in ticks. Plain data with value semantics: list fields are "
                                  "copies, so edit them and assign them back "
                                  "(`chars = s.characters; chars[0].name = 'Ada'; s.characters = chars`).");
    scenario.def(py::init([](std::string name) {
                     Scenario s;
                     s.name = std::move(name);
                     return s;
                 }),
                 "name"_a = "")
        .def_readwrite("name", &Scenario::name)
        .def_readwrite("duration", &Scenario::duration, "Timeline length in ticks (0: up to the last action's end).")
        .def_property(
            "duration_seconds", [](const Scenario& s) { return core::ticksToSeconds(s.duration); },
            [](Scenario& s, double seconds) { s.duration = core::secondsToTicks(seconds); })
        .def(
            "find_character",
            [](const Scenario& s, const std::string& name) -> std::optional<Character> {
                const Character* found = s.findCharacter(name);
                return found ? std::optional<Character>(*found) : std::nullopt;
            },
            "name"_a, "A copy of the character called `name`, or None.")
        .def(
            "find_mask",
            [](const Scenario& s, const std::string& name) -> std::optional<NamedMask> {
                const NamedMask* found = s.findMask(name);
                return found ? std::optional<NamedMask>(*found) : std::nullopt;
            },
            "name"_a, "A copy of the mask called `name`, or None.")
        .def("__eq__", [](const Scenario& a, const Scenario& b) { return a == b; })
        .def("__repr__", [](const Scenario& s) {
            return "<thespis.Scenario '" + s.name + "' " + std::to_string(s.characters.size()) + " characters>";
        });
    defExtra(scenario);
    defList(scenario, "characters", &Scenario::characters, "The characters (a copy).");
    defList(scenario, "masks", &Scenario::masks, "The named joint masks (a copy).");
    defList(scenario, "markers", &Scenario::markers, "The timeline markers (a copy).");
    defList(scenario, "scripts", &Scenario::scripts, "The scenario's Python scripts (a copy).");
    scenario.def_readwrite("lighting", &Scenario::lighting, "The light probe (a LightingSpec).");
    scenario.def_readwrite("posture_bases", &Scenario::postureBases,
                           "The .pca file (thespis-cli train-pca) the dependent-joint filter works in; '' = none.");
}

void bindImport(py::module_& m)
{
    py::class_<ClipFileReport>(m, "ClipFileReport", "What reading a motion file found.")
        .def_readonly("format", &ClipFileReport::format, "'bvh' or 'gltf'")
        .def_readonly("convention", &ClipFileReport::convention, "The joint naming found ('cmu', 'mixamo', …).")
        .def_readonly("unmapped", &ClipFileReport::unmapped, "File joints that kept their own name.")
        .def_readonly("turned_from", &ClipFileReport::turnedFrom, "How the body lay before it was stood up, or ''.")
        .def_readonly("calibration_frame", &ClipFileReport::calibrationFrame)
        .def_readonly("calibration_frame_dropped", &ClipFileReport::calibrationFrameDropped)
        .def_readonly("unit", &ClipFileReport::unit, "Metres per file unit as the file tells; 0 unknown.")
        .def_readonly("unit_name", &ClipFileReport::unitName)
        .def_readonly("animations", &ClipFileReport::animations, "glTF: every animation in the file.")
        .def_readonly("frame_count", &ClipFileReport::frameCount)
        .def_readonly("frame_rate", &ClipFileReport::frameRate)
        .def_readonly("warnings", &ClipFileReport::warnings);
    py::class_<ClipImport>(m, "ClipImport", "A motion file's clips as an import would add them to a character.")
        .def_property_readonly("path", [](const ClipImport& p) { return p.path; })
        .def_readonly("clips", &ClipImport::clips, "One ClipAsset per BVH file, one per animation of a glTF file.")
        .def_readonly("report", &ClipImport::report)
        .def_readonly("mapping", &ClipImport::mapping, "File joint → the name it plays as (correct it, pass it back).")
        .def_readonly("joints_moved", &ClipImport::jointsMoved, "The character's joints the file moves.")
        .def_readonly("unmoved", &ClipImport::unmoved, "The character's joints the file does not move.")
        .def_readonly("moving_nothing", &ClipImport::movingNothing,
                      "Joints without an H-Anim name whose motion reaches nothing of the character.")
        .def_readonly("problem", &ClipImport::problem, "Why it cannot go on the character; '' when it can.");
    m.def(
        "plan_clip_import",
        [](const std::filesystem::path& file, const std::filesystem::path& baseDir, const anim::Skeleton& skeleton,
           const std::map<std::string, std::string>& mapping) {
            return unwrap(withoutGil([&] { return planClipImport(file, baseDir, skeleton, mapping); }));
        },
        "file"_a, "base_dir"_a, "skeleton"_a, "mapping"_a = std::map<std::string, std::string>{},
        "Reads a motion file (BVH, glTF, GLB) to import it into a character with `skeleton` (the runtime's); clip "
        "paths are made relative to base_dir. Nothing is added: thespis.edit.add_clips adds what you keep.");
    m.def(
        "save_mapping",
        [](const std::filesystem::path& path, const std::map<std::string, std::string>& mapping) {
            unwrap(saveMapping(path, mapping));
        },
        "path"_a, "mapping"_a, "Writes a joint mapping file (thespis.load_mapping / the import dialog read it).");
}

void bindScenarioRuntime(py::module_& m)
{
    py::class_<CharacterRuntime>(m, "CharacterRuntime",
                                 "A character ready to play: skeleton, loaded clips and its nested schedules.")
        .def_readonly("name", &CharacterRuntime::name)
        .def_readonly("skeleton", &CharacterRuntime::skeleton)
        .def_readonly("clips", &CharacterRuntime::clips, "Clip name → KeyframeClip on the skeleton's layout.")
        .def_readonly("body", &CharacterRuntime::body, "Every body layer, nested in one schedule.")
        .def_readonly("face", &CharacterRuntime::face, "Every face layer (MPEG-4 FAPs), nested in one schedule.")
        .def_readonly("layers", &CharacterRuntime::layers, "One schedule per Layer, in document order.")
        .def_readonly("action_ids", &CharacterRuntime::actionIds, "Per layer, the schedule's id of each ActionSpec.")
        .def_readonly("warnings", &CharacterRuntime::warnings)
        .def_readonly("clip_reports", &CharacterRuntime::clipReports,
                      "Clip name → what reading its file found (thespis.ClipFileReport).")
        .def(
            "evaluate_body",
            [](const CharacterRuntime& c, double seconds) {
                std::vector<float> frame = c.skeleton.restFrame();
                c.evaluateBody(seconds, frame);
                return toArray<float>(frame);
            },
            "seconds"_a, "The body frame at `seconds`, placed where the character stands (NumPy floats).")
        .def("__repr__", [](const CharacterRuntime& c) {
            return "<thespis.CharacterRuntime '" + c.name + "' " + std::to_string(c.layers.size()) + " layers>";
        });

    py::class_<ScenarioRuntime>(m, "ScenarioRuntime", "Runnable schedules for every character of a scenario.")
        .def_readonly("characters", &ScenarioRuntime::characters)
        .def_property_readonly(
            "duration", [](const ScenarioRuntime& runtime) { return core::ticksToSeconds(runtime.duration); },
            "Seconds: the scenario's duration, or the latest end of a finite action.")
        .def("find_character", &ScenarioRuntime::findCharacter, "name"_a, py::return_value_policy::reference_internal);
}

} // namespace

void bindScenario(py::module_& m)
{
    m.attr("TICKS_PER_SECOND") = core::TicksPerSecond;
    m.def("ticks_to_seconds", &core::ticksToSeconds, "ticks"_a);
    m.def("seconds_to_ticks", &core::secondsToTicks, "seconds"_a, "Nearest whole tick.");
    m.def(
        "ticks_per_frame",
        [](int fps) {
            if (fps <= 0)
                throw py::value_error("frames_per_second must be positive, not " + std::to_string(fps) + ".");
            return core::ticksPerFrame(fps);
        },
        "frames_per_second"_a, "Ticks of one frame at a whole-number frame rate.");
    m.attr("SCENARIO_FORMAT") = std::string(FormatName);
    m.attr("SCENARIO_VERSION") = int(format::Current);
    m.attr("SCENARIO_EXTENSION") = std::string(FileExtension);

    bindDocument(m);
    bindScenarioRuntime(m);
    bindImport(m);
    bindPackages(m);

    m.def(
        "parse_scenario", [](const std::string& text) { return unwrap(withoutGil([&] { return parseScenario(text); })); },
        "text"_a,
        "Reads a scenario from JSON text. thespis.FormatError names the field of malformed input, or says when "
        "the text is from a newer Thespis.");
    m.def(
        "load_scenario",
        [](const std::filesystem::path& path) { return unwrap(withoutGil([&] { return loadScenario(path); })); },
        "path"_a, "Reads a .thespis file (FileNotFoundError, thespis.FormatError naming the field).");
    m.def("serialize_scenario", &serializeScenario, "scenario"_a, "The scenario as JSON text (current version).");
    m.def(
        "save_scenario",
        [](const std::filesystem::path& path, const Scenario& scenario) { unwrap(saveScenario(path, scenario)); },
        "path"_a, "scenario"_a, "Writes a .thespis file atomically (temporary file, then rename).");
    m.def(
        "build_runtime",
        [](const Scenario& scenario, const py::object& baseDir) {
            // A copy, so that other Python threads may touch the document while clips load.
            const Scenario snapshot = scenario;
            const Assets assets = assetsArgument(baseDir);
            return unwrap(withoutGil([&] { return buildRuntime(snapshot, assets); }));
        },
        "scenario"_a, "base_dir"_a = ".",
        "Loads every clip (files relative to base_dir: the scenario file's folder, or an open thespis.Package) and "
        "builds the schedules. Errors name the character, action and field.");
    m.def(
        "bake_motion",
        [](const Scenario& scenario, const std::string& character, const std::filesystem::path& out,
           const py::object& baseDir, double fps, double start, std::optional<double> end, const py::object& progress,
           bool animationOnly) {
            core::runtime::MotionBakeJob job;
            job.scenario = scenario;
            job.assets = assetsArgument(baseDir);
            job.character = character;
            job.output = out;
            job.fps = fps;
            job.start = start;
            job.end = end;
            job.animationOnly = animationOnly;
            runJob(job, progress);
            return job.frameCount;
        },
        "scenario"_a, "character"_a, "out"_a, py::kw_only(), "base_dir"_a = ".",
        "fps"_a = 30.0, "start"_a = 0.0, "end"_a = py::none(), "progress"_a = py::none(), "animation_only"_a = false,
        "Bakes a character's animation into a BVH file or a glTF 2.0 .glb (its model with the motion; with "
        "animation_only, its nodes and the motion alone), as `thespis-cli bake-motion` does (the same job): "
        "frames from start to end (default: the scenario's duration) at fps; returns the number of frames. "
        "Releases the GIL; progress(done, total); Ctrl-C stops it and nothing is written.");
    m.def(
        "validate_scenario",
        [](const Scenario& scenario, const py::object& baseDir) {
            const Scenario snapshot = scenario;
            const Assets assets = assetsArgument(baseDir);
            return withoutGil([&] { return validateScenario(snapshot, assets); });
        },
        "scenario"_a, "base_dir"_a = ".",
        "Every problem of the scenario as a list of thespis.Error; empty when it is valid.");
}

} // namespace thespis::python
