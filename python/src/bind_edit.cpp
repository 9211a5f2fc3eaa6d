// Bindings of the studio's undoable scenario edits (core/edit: scenario_edit.h, document_edits.h)
// as `thespis.edit`. Each function looks at a Scenario and returns the Edit that makes a change,
// or raises (ValueError, with the core message) when the change cannot be made; Edit.apply()
// changes the Python Scenario in place and Edit.inverse() takes it back. Paths are small value
// classes that also load from tuples: (character, layer, action), (character, layer),
// (character, index).

#include <optional>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "bind_common.h"
#include "edit/content_edits.h"
#include "edit/document_edits.h"
#include "edit/lexicon_edits.h"
#include "edit/gaze_edits.h"
#include "edit/scenario_edit.h"
#include "errors.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace edit = core::edit;
namespace anim = core::anim;
using core::Tick;
using core::scenario::ActionSpec;
using core::scenario::Character;
using core::scenario::Gesture;
using core::scenario::Marker;
using core::scenario::Scenario;
using core::scenario::ScenarioRuntime;

namespace {

// "(0, 1, 2)" for repr of paths and edits.
std::string joined(std::initializer_list<int> values)
{
    std::string text = "(";
    for (int value : values) {
        if (text.size() > 1)
            text += ", ";
        text += std::to_string(value);
    }
    return text + ")";
}

// A path class: fields, ==, hashing, repr, and loading from a tuple of `N` ints.
template <class Path, std::size_t N>
py::class_<Path> bindPath(py::module_& e, const char* name, const char* doc)
{
    py::class_<Path> cls(e, name, doc);
    cls.def(py::init([name](const py::tuple& t) {
                if (t.size() != N)
                    throw py::type_error(std::string(name) + " needs " + std::to_string(N) + " integers, not "
                                         + std::to_string(t.size()) + ".");
                std::vector<int> v;
                for (const py::handle item : t)
                    v.push_back(item.cast<int>());
                Path p;
                if constexpr (N == 3)
                    p = Path{v[0], v[1], v[2]};
                else
                    p = Path{v[0], v[1]};
                return p;
            }),
            "values"_a)
        .def("__eq__", [](const Path& a, const Path& b) { return a == b; })
        .def("__lt__", [](const Path& a, const Path& b) { return a < b; });
    py::implicitly_convertible<py::tuple, Path>();
    return cls;
}

std::string describeEdit(const edit::Edit& e)
{
    const std::size_t count = e.changes().size();
    std::string text = "<thespis.edit.Edit " + std::to_string(count) + (count == 1 ? " change" : " changes");
    std::string kinds;
    for (const edit::Change& change : e.changes()) {
        const std::string kind = std::visit(
            [](const auto& c) -> std::string {
                using C = std::decay_t<decltype(c)>;
                if constexpr (std::is_same_v<C, edit::SegmentTagsChange>)
                    return "segment tags";
                else if constexpr (std::is_same_v<C, edit::CharacterBakeChange>)
                    return "bake";
                else if constexpr (std::is_same_v<C, edit::LightingChange>)
                    return "lighting";
                else if constexpr (std::is_same_v<C, edit::ScriptsChange>)
                    return "scripts";
                else if constexpr (std::is_same_v<C, edit::ArChange>)
                    return "ar";
                else if constexpr (std::is_same_v<C, edit::BmlLexiconChange>)
                    return "bml lexicon";
                else {
                    std::string element = std::is_same_v<C, edit::ActionChange>    ? "action"
                                          : std::is_same_v<C, edit::LayerChange>   ? "layer"
                                          : std::is_same_v<C, edit::MaskChange>    ? "mask"
                                          : std::is_same_v<C, edit::MarkerChange>  ? "marker"
                                          : std::is_same_v<C, edit::GestureChange> ? "gesture"
                                          : std::is_same_v<C, edit::CharacterChange> ? "character"
                                                                                   : "clip";
                    return (!c.before ? "+" : !c.after ? "-" : "") + element;
                }
            },
            change);
        kinds += (kinds.empty() ? ": " : ", ") + kind;
    }
    return text + kinds + ">";
}

} // namespace

void bindEdit(py::module_& m)
{
    py::module_ e = m.def_submodule(
        "edit",
        "The studio's undoable scenario edits. Each function looks at a Scenario and returns the Edit that makes "
        "a change (ValueError with the reason when it cannot be made); Edit.apply(scenario) changes the scenario "
        "in place and Edit.inverse() is the edit that takes it back. Paths accept tuples: "
        "(character, layer, action), (character, layer), (character, index). Times are ticks.");

    bindPath<edit::LayerPath, 2>(e, "LayerPath", "A layer: (character, layer) indices.")
        .def(py::init([](int character, int layer) { return edit::LayerPath{character, layer}; }), "character"_a,
             "layer"_a)
        .def_readwrite("character", &edit::LayerPath::character)
        .def_readwrite("layer", &edit::LayerPath::layer)
        .def("__hash__", [](const edit::LayerPath& p) { return py::hash(py::make_tuple(p.character, p.layer)); })
        .def("__repr__",
             [](const edit::LayerPath& p) { return "LayerPath" + joined({p.character, p.layer}); });

    bindPath<edit::ActionPath, 3>(e, "ActionPath", "An action: (character, layer, action) indices.")
        .def(py::init([](int character, int layer, int action) { return edit::ActionPath{character, layer, action}; }),
             "character"_a, "layer"_a, "action"_a)
        .def_readwrite("character", &edit::ActionPath::character)
        .def_readwrite("layer", &edit::ActionPath::layer)
        .def_readwrite("action", &edit::ActionPath::action)
        .def_property_readonly("layer_path", &edit::ActionPath::layerPath)
        .def("__hash__",
             [](const edit::ActionPath& p) { return py::hash(py::make_tuple(p.character, p.layer, p.action)); })
        .def("__repr__",
             [](const edit::ActionPath& p) { return "ActionPath" + joined({p.character, p.layer, p.action}); });

    bindPath<edit::CharacterItemPath, 2>(e, "CharacterItemPath",
                                         "An element of a character's list (gestures, clips): (character, index).")
        .def(py::init([](int character, int index) { return edit::CharacterItemPath{character, index}; }),
             "character"_a, "index"_a)
        .def_readwrite("character", &edit::CharacterItemPath::character)
        .def_readwrite("index", &edit::CharacterItemPath::index)
        .def("__hash__",
             [](const edit::CharacterItemPath& p) { return py::hash(py::make_tuple(p.character, p.index)); })
        .def("__repr__", [](const edit::CharacterItemPath& p) {
            return "CharacterItemPath" + joined({p.character, p.index});
        });

    py::enum_<edit::LayerFlag>(e, "LayerFlag", "A layer's switch: mute, solo or lock.")
        .value("mute", edit::LayerFlag::Mute)
        .value("solo", edit::LayerFlag::Solo)
        .value("lock", edit::LayerFlag::Lock);
    py::enum_<edit::Edge>(e, "Edge", "Which edge of an action trim_action moves.")
        .value("start", edit::Edge::Start)
        .value("end", edit::Edge::End);

    py::class_<edit::ActionSpan>(e, "ActionSpan", "Where an action plays on its layer (from action_span()).")
        .def_readonly("start", &edit::ActionSpan::start, "Ticks.")
        .def_readonly("end", &edit::ActionSpan::end, "start + duration (ticks); meaningless when open_ended.")
        .def_readonly("open_ended", &edit::ActionSpan::openEnded, "Plays until cut off (a loop forever).")
        .def_readonly("source", &edit::ActionSpan::source,
                      "The domain (seconds) of the action's clip with its modifiers.")
        .def_readonly("untrimmed", &edit::ActionSpan::untrimmed,
                      "The domain under the outermost trim (how far trimming can reach).")
        .def("__repr__", [](const edit::ActionSpan& s) {
            return "<thespis.edit.ActionSpan " + std::to_string(s.start) + ".."
                   + (s.openEnded ? std::string("open") : std::to_string(s.end)) + " ticks>";
        });

    py::class_<edit::Edit>(e, "Edit",
                           "A reversible change to a scenario: a list of changes, each inserting, removing or "
                           "replacing one element (action, layer, mask, marker, gesture, clip) or a character's "
                           "segment tags or bake. len() is the number of changes.")
        .def(py::init<>(), "An empty edit (changes nothing).")
        .def(
            "apply", [](const edit::Edit& self, Scenario& scenario) { unwrap(self.apply(scenario)); }, "scenario"_a,
            "Changes `scenario` in place. Raises ValueError when the edit does not fit it (made for another state "
            "of the document); the scenario is then left exactly as it was.")
        .def("inverse", &edit::Edit::inverse,
             "The edit that takes the document back: changes in reverse order, before and after swapped.")
        .def("changes_nothing", &edit::Edit::changesNothing,
             "True when applying it changes nothing (every change replaces a value by an equal one).")
        .def(
            "append", [](edit::Edit& self, const edit::Edit& other) { self.append(other); }, "other"_a,
            "Appends every change of `other` (they run after this edit's changes).")
        .def("__len__", [](const edit::Edit& self) { return self.changes().size(); })
        .def("__eq__", [](const edit::Edit& a, const edit::Edit& b) { return a == b; })
        .def("__repr__", &describeEdit);

    e.def(
        "action_span",
        [](const Scenario& scenario, const ScenarioRuntime& runtime, const edit::ActionPath& action) {
            return edit::actionSpan(scenario, runtime, action);
        },
        "scenario"_a, "runtime"_a, "action"_a,
        "Where the action plays, from `runtime` (thespis.build_runtime of the same scenario); None when the "
        "path leads nowhere or the runtime does not match.");

    // ---- Actions
    e.def(
        "action_from_clip",
        [](const Scenario& scenario, const edit::LayerPath& layer, const std::string& clip, Tick start) {
            return unwrap(edit::actionFromClip(scenario, layer, clip, start));
        },
        "scenario"_a, "layer"_a, "clip"_a, "start"_a,
        "A new ActionSpec playing `clip` of the layer's character from `start`, faded in and out over 0.3 s, "
        "named after the clip and unique in the layer (not added: see insert_actions).");
    e.def(
        "insert_actions",
        [](const Scenario& scenario, const edit::LayerPath& layer, std::vector<ActionSpec> actions) {
            return unwrap(edit::insertActions(scenario, layer, std::move(actions)));
        },
        "scenario"_a, "layer"_a, "actions"_a,
        "Adds actions at the end of a layer (names made unique in the layer: 'wave', 'wave 2', ...).");
    e.def(
        "move_actions",
        [](const Scenario& scenario, const std::vector<edit::ActionPath>& actions, Tick delta, int layerDelta) {
            return unwrap(edit::moveActions(scenario, actions, delta, layerDelta));
        },
        "scenario"_a, "actions"_a, "delta_ticks"_a, "layer_delta"_a = 0,
        "Moves actions in time by `delta_ticks` (the earliest stops at 0) and, with `layer_delta`, to the layer "
        "that many places further down (up when negative) in their character, added at its end (renamed "
        "'wave 2' on a name clash). Refused when an action is missing or listed twice, a layer is locked, a "
        "target layer is outside the character or of another kind (face vs body).");
    e.def(
        "moved_action_paths",
        [](const Scenario& scenario, const std::vector<edit::ActionPath>& actions, int layerDelta) {
            return edit::movedActionPaths(scenario, actions, layerDelta);
        },
        "scenario"_a, "actions"_a, "layer_delta"_a = 0,
        "Where move_actions(scenario, actions, _, layer_delta) puts each action (same order); empty when the "
        "move is refused.");
    e.def(
        "trim_action",
        [](const Scenario& scenario, const edit::ActionPath& action, const edit::ActionSpan& span, edit::Edge edge,
           Tick time, Tick minimumLength) {
            return unwrap(edit::trimAction(scenario, action, span, edge, time, minimumLength));
        },
        "scenario"_a, "action"_a, "span"_a, "edge"_a, "time"_a, "minimum_length"_a = Tick(1),
        "Moves one edge of the action to `time` (ticks) keeping its motion in place (NLE trim, through its "
        "outermost trim modifier, added when missing). `span` from action_span(). The action keeps at least "
        "`minimum_length` ticks and stays within its clip.");
    e.def(
        "set_action_fades",
        [](const Scenario& scenario, const edit::ActionPath& action, std::optional<double> fadeIn,
           std::optional<double> fadeOut) { return unwrap(edit::setActionFades(scenario, action, fadeIn, fadeOut)); },
        "scenario"_a, "action"_a, "fade_in"_a = py::none(), "fade_out"_a = py::none(),
        "Sets the fade-in and / or fade-out (seconds; None keeps it) of the action's weight curve. Keyframed "
        "weights have no fades.");
    e.def(
        "set_action_curves",
        [](const Scenario& scenario, const edit::ActionPath& action, std::optional<anim::Curve> weight,
           std::optional<anim::Curve> scale) {
            return unwrap(edit::setActionCurves(scenario, action, std::move(weight), std::move(scale)));
        },
        "scenario"_a, "action"_a, "weight"_a = py::none(), "scale"_a = py::none(),
        "Replaces the action's weight and / or scale curve (validated; None keeps it).");
    e.def(
        "replace_action",
        [](const Scenario& scenario, const edit::ActionPath& action, ActionSpec spec) {
            return unwrap(edit::replaceAction(scenario, action, std::move(spec)));
        },
        "scenario"_a, "action"_a, "spec"_a,
        "Replaces the whole action (name, clip, mask, mode, ...); the clip and mask must exist.");
    e.def(
        "split_action",
        [](const Scenario& scenario, const edit::ActionPath& action, const edit::ActionSpan& span, Tick time) {
            return unwrap(edit::splitAction(scenario, action, span, time));
        },
        "scenario"_a, "action"_a, "span"_a, "time"_a,
        "Cuts the action in two at `time` (ticks, strictly inside it; `span` from action_span()). The first part "
        "keeps the fade-in, the second the fade-out.");
    e.def(
        "remove_actions",
        [](const Scenario& scenario, const std::vector<edit::ActionPath>& actions, const ScenarioRuntime* rippleWith) {
            return unwrap(edit::removeActions(scenario, actions, rippleWith));
        },
        "scenario"_a, "actions"_a, "ripple_with"_a = py::none(),
        "Removes actions. With `ripple_with` (thespis.build_runtime of the same scenario), later actions of each "
        "layer move earlier to close the gaps.");

    // ---- Layers and markers
    e.def(
        "set_layer_flag",
        [](const Scenario& scenario, const edit::LayerPath& layer, edit::LayerFlag flag, bool on) {
            return unwrap(edit::setLayerFlag(scenario, layer, flag, on));
        },
        "scenario"_a, "layer"_a, "flag"_a, "on"_a = true, "Turns a layer's mute, solo or lock on or off.");
    e.def(
        "add_marker", [](const Scenario& scenario, Marker marker) { return unwrap(edit::addMarker(scenario, std::move(marker))); },
        "scenario"_a, "marker"_a, "Adds a marker (thespis.Marker), keeping markers ordered by time.");
    e.def(
        "move_marker",
        [](const Scenario& scenario, int index, Tick time) { return unwrap(edit::moveMarker(scenario, index, time)); },
        "scenario"_a, "index"_a, "time"_a, "Moves marker `index` to `time` (ticks, not before 0).");
    e.def(
        "remove_marker", [](const Scenario& scenario, int index) { return unwrap(edit::removeMarker(scenario, index)); },
        "scenario"_a, "index"_a, "Removes marker `index`.");

    // ---- Masks
    e.def(
        "add_mask",
        [](const Scenario& scenario, std::string name, anim::JointMask mask) {
            return unwrap(edit::addMask(scenario, std::move(name), std::move(mask)));
        },
        "scenario"_a, "name"_a, "mask"_a, "Adds a named mask (the name must be new).");
    e.def(
        "set_mask",
        [](const Scenario& scenario, int index, anim::JointMask mask) {
            return unwrap(edit::setMask(scenario, index, std::move(mask)));
        },
        "scenario"_a, "index"_a, "mask"_a, "Replaces the weights of mask `index` (every weight in [0, 1]).");
    e.def(
        "set_mask_weights",
        [](const Scenario& scenario, int index, const std::vector<std::string>& joints, float weight) {
            return unwrap(edit::setMaskWeights(scenario, index, joints, weight));
        },
        "scenario"_a, "index"_a, "joints"_a, "weight"_a,
        "Sets the weight of some joints of mask `index`, leaving the others as they are.");
    e.def(
        "rename_mask",
        [](const Scenario& scenario, int index, const std::string& name) {
            return unwrap(edit::renameMask(scenario, index, name));
        },
        "scenario"_a, "index"_a, "name"_a,
        "Renames mask `index` and every action and gesture that uses it (the name must be new).");
    e.def(
        "remove_mask", [](const Scenario& scenario, int index) { return unwrap(edit::removeMask(scenario, index)); },
        "scenario"_a, "index"_a, "Removes a mask no action or gesture uses (the error names those that do).");

    // ---- Gesticon, segments, bakes
    e.def(
        "add_gesture",
        [](const Scenario& scenario, int character, Gesture gesture) {
            return unwrap(edit::addGesture(scenario, character, std::move(gesture)));
        },
        "scenario"_a, "character"_a, "gesture"_a,
        "Adds a gesture to a character's gesticon (a unique name, a clip of the character, a mask of the scenario).");
    e.def(
        "replace_gesture",
        [](const Scenario& scenario, const edit::CharacterItemPath& gesture, Gesture value) {
            return unwrap(edit::replaceGesture(scenario, gesture, std::move(value)));
        },
        "scenario"_a, "gesture"_a, "value"_a, "Replaces a gesture (validated as add_gesture).");
    e.def(
        "remove_gesture",
        [](const Scenario& scenario, const edit::CharacterItemPath& gesture) {
            return unwrap(edit::removeGesture(scenario, gesture));
        },
        "scenario"_a, "gesture"_a, "Removes a gesture.");
    e.def(
        "set_segment_tags",
        [](const Scenario& scenario, int character, std::vector<core::scene::SegmentTag> tags) {
            return unwrap(edit::setSegmentTags(scenario, character, std::move(tags)));
        },
        "scenario"_a, "character"_a, "tags"_a,
        "Sets the receiver / occluder tags (thespis.scene.SegmentTag) of a character's segments.");
    e.def(
        "set_character_bake",
        [](const Scenario& scenario, int character, std::string path) {
            return unwrap(edit::setCharacterBake(scenario, character, std::move(path)));
        },
        "scenario"_a, "character"_a, "path"_a,
        "Sets a character's bake file (relative to the scenario's folder; '' = no bake, unshadowed transfer).");

    // ---- BML lexicons (lexicon_edits.h)
    e.def("bml_lexicon_rows", [](const Scenario& scenario, int character) {
            if (character < 0 || std::size_t(character) >= scenario.characters.size())
                throw py::index_error("There is no character " + std::to_string(character) + ".");
            return edit::bmlLexiconRows(scenario.characters[std::size_t(character)]);
        },
        "scenario"_a, "character"_a,
        "The rows of a character's BML lexicon (lexeme → gesture): its own, else the defaults whose gestures it has.");
    e.def(
        "set_bml_lexicon",
        [](const Scenario& scenario, int character, std::optional<std::map<std::string, std::string>> rows) {
            return unwrap(edit::setBmlLexicon(scenario, character, std::move(rows)));
        },
        "scenario"_a, "character"_a, "rows"_a,
        "Sets a character's whole BML lexicon ({lexeme: gesture}; lexemes kept in upper case); None = back to "
        "the defaults. Each row must name a gesture of the character.");
    e.def(
        "set_bml_lexeme",
        [](const Scenario& scenario, int character, const std::string& lexeme, std::optional<std::string> gesture) {
            return unwrap(edit::setBmlLexeme(scenario, character, lexeme, std::move(gesture)));
        },
        "scenario"_a, "character"_a, "lexeme"_a, "gesture"_a,
        "Sets the row of `lexeme` of a character's BML lexicon to `gesture`, or removes it (None).");
    e.def(
        "rename_bml_lexeme",
        [](const Scenario& scenario, int character, const std::string& lexeme, const std::string& to) {
            return unwrap(edit::renameBmlLexeme(scenario, character, lexeme, to));
        },
        "scenario"_a, "character"_a, "lexeme"_a, "to"_a, "Gives a row of a character's BML lexicon another lexeme.");

    // ---- Characters, layers, clips and the light (content_edits.h)
    e.def("new_character", &edit::newCharacter, "name"_a, "model"_a = "", "skeleton"_a = "hanim-25",
          "A Character on the built-in humanoid (model '', skeleton an H-Anim level) or a glTF model (skeleton "
          "'model' plays on its own rig), with a body and a face layer (not added: see add_character).");
    e.def(
        "add_character",
        [](const Scenario& scenario, Character character) {
            return unwrap(edit::addCharacter(scenario, std::move(character)));
        },
        "scenario"_a, "character"_a, "Adds a character at the end (its name made unique).");
    e.def(
        "remove_character", [](const Scenario& scenario, int character) { return unwrap(edit::removeCharacter(scenario, character)); },
        "scenario"_a, "character"_a, "Removes a character.");
    e.def(
        "rename_character",
        [](const Scenario& scenario, int character, const std::string& name) {
            return unwrap(edit::renameCharacter(scenario, character, name));
        },
        "scenario"_a, "character"_a, "name"_a, "Renames a character (a new, non-empty name).");
    e.def(
        "duplicate_character",
        [](const Scenario& scenario, int character) { return unwrap(edit::duplicateCharacter(scenario, character)); },
        "scenario"_a, "character"_a, "A copy named 'Name 2', a metre to the original's right.");
    e.def(
        "set_character_body",
        [](const Scenario& scenario, int character, const std::string& model, const std::string& skeleton) {
            return unwrap(edit::setCharacterBody(scenario, character, model, skeleton));
        },
        "scenario"_a, "character"_a, "model"_a, "skeleton"_a,
        "Another body: a glTF model ('' = the built-in humanoid) and the skeleton its motion plays on. A new model "
        "drops the old one's segment tags and bake.");
    e.def(
        "set_character_placement",
        [](const Scenario& scenario, int character, anim::Vec3 position, double heading) {
            return unwrap(edit::setCharacterPlacement(scenario, character, position, heading));
        },
        "scenario"_a, "character"_a, "position"_a, "heading"_a,
        "Where the character stands (metres) and which way it faces (degrees about +Y).");
    e.def(
        "set_character_face_mapping",
        [](const Scenario& scenario, int character, const std::string& path) {
            return unwrap(edit::setCharacterFaceMapping(scenario, character, path));
        },
        "scenario"_a, "character"_a, "path"_a,
        "Sets the face mapping table file a glTF character's face follows (relative to the scenario's folder; '' = "
        "the table recognised from the model's names). Refused for the built-in humanoid.");
    e.def(
        "add_gaze",
        [](const Scenario& scenario, int character, const core::scenario::GazeSpec& gaze, core::Tick start,
           double seconds) { return unwrap(edit::addGaze(scenario, character, gaze, start, seconds)); },
        "scenario"_a, "character"_a, "gaze"_a, "start"_a, "seconds"_a = 2.0,
        "Adds a gaze action (a GazeSpec: what the character looks at) from `start` (ticks) for `seconds` seconds "
        "on the character's 'Gaze' gaze layer, added when it has none.");
    e.def(
        "add_layer",
        [](const Scenario& scenario, int character, const std::string& name, core::scenario::LayerKind kind) {
            return unwrap(edit::addLayer(scenario, character, name, kind));
        },
        "scenario"_a, "character"_a, "name"_a, "kind"_a = core::scenario::LayerKind::Body,
        "Adds a layer at the end of the character's (its name made unique).");
    e.def(
        "remove_layer", [](const Scenario& scenario, const edit::LayerPath& layer) { return unwrap(edit::removeLayer(scenario, layer)); },
        "scenario"_a, "layer"_a, "Removes a layer (not a locked one).");
    e.def(
        "rename_layer",
        [](const Scenario& scenario, const edit::LayerPath& layer, const std::string& name) {
            return unwrap(edit::renameLayer(scenario, layer, name));
        },
        "scenario"_a, "layer"_a, "name"_a, "Renames a layer (unique in its character).");
    e.def(
        "move_layer",
        [](const Scenario& scenario, const edit::LayerPath& layer, int delta) { return unwrap(edit::moveLayer(scenario, layer, delta)); },
        "scenario"_a, "layer"_a, "delta"_a, "Moves a layer `delta` places down (up when negative).");
    e.def(
        "add_clips",
        [](const Scenario& scenario, int character, std::vector<core::scenario::ClipAsset> clips) {
            return unwrap(edit::addClips(scenario, character, std::move(clips)));
        },
        "scenario"_a, "character"_a, "clips"_a,
        "Adds clips to a character (names made unique): ClipImport.clips from thespis.plan_clip_import.");
    e.def(
        "add_idle_action",
        [](const Scenario& scenario, const edit::LayerPath& layer, const std::string& database, Tick start) {
            return unwrap(edit::addIdleAction(scenario, layer, database, start));
        },
        "scenario"_a, "layer"_a, "database"_a, "start"_a = Tick(0),
        "An open-ended action of idle motion from `database` (an .idle file) on a body layer: the character's idle "
        "clip on it, else a new clip 'idle' added in the same edit (what dropping Idle from the studio's clip library "
        "does).");
    e.def(
        "replace_clip",
        [](const Scenario& scenario, const edit::CharacterItemPath& clip, core::scenario::ClipAsset value) {
            return unwrap(edit::replaceClip(scenario, clip, std::move(value)));
        },
        "scenario"_a, "clip"_a, "value"_a,
        "Replaces a clip (options, joint mapping); a new name is followed by the actions and gestures using it.");
    e.def(
        "remove_clip",
        [](const Scenario& scenario, const edit::CharacterItemPath& clip) { return unwrap(edit::removeClip(scenario, clip)); },
        "scenario"_a, "clip"_a, "Removes a clip no action, gesture or skeleton uses.");
    e.def(
        "set_lighting",
        [](const Scenario& scenario, core::scenario::LightingSpec lighting) {
            return unwrap(edit::setLighting(scenario, std::move(lighting)));
        },
        "scenario"_a, "lighting"_a,
        "Another light (thespis.LightingSpec: probe file and layout, rotation in degrees, intensity; probe '' = the "
        "default sky).");
    e.def(
        "set_script",
        [](const Scenario& scenario, const std::string& name, const std::string& source) {
            return unwrap(edit::setScript(scenario, name, source));
        },
        "scenario"_a, "name"_a, "source"_a, "Adds the script, or replaces the source of the one of that name.");
    e.def(
        "remove_script",
        [](const Scenario& scenario, const std::string& name) { return unwrap(edit::removeScript(scenario, name)); },
        "scenario"_a, "name"_a, "Removes the script of that name (KeyError when there is none).");
}

} // namespace thespis::python
