// thespis.bml: BML 1.0 blocks read (speech/bml.h) and realised on the Stage for a character
// (runtime/bml_performance.h), with the block's start, end and sync points called back to Python
// as the clock reaches them.

#include "bind_common.h"
#include "errors.h"

#include "runtime/animation_service.h"
#include "runtime/bml_performance.h"
#include "speech/bml.h"
#include "speech/face_lexemes.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace speech = core::speech;
namespace runtime = core::runtime;

namespace {

py::dict behaviorDict(const speech::BmlBehavior& b)
{
    py::dict sync;
    for (const auto& [point, ref] : b.sync)
        sync[py::str(std::string(speech::bmlPointName(point)))] = speech::bmlSyncRefString(ref);
    py::list marks;
    for (const auto& [id, offset] : b.syncMarks)
        marks.append(py::make_tuple(id, offset));
    return py::dict("kind"_a = std::string(speech::bmlKindName(b.kind)), "id"_a = b.id, "line"_a = b.line,
                    "column"_a = b.column, "sync"_a = sync, "text"_a = b.text, "sync_marks"_a = marks,
                    "lexeme"_a = b.lexeme, "by_name"_a = b.byName, "amount"_a = b.amount,
                    "repetition"_a = b.repetition, "target"_a = b.target, "influence"_a = b.influence,
                    "offset_angle"_a = b.offsetAngle, "offset_direction"_a = b.offsetDirection, "mode"_a = b.mode,
                    "duration"_a = b.duration);
}

py::dict blockDict(const speech::BmlBlock& block)
{
    py::list behaviors;
    for (const speech::BmlBehavior& b : block.behaviors)
        behaviors.append(behaviorDict(b));
    const char* composition = block.composition == speech::BmlComposition::Merge    ? "merge"
                              : block.composition == speech::BmlComposition::Append ? "append"
                                                                                    : "replace";
    return py::dict("id"_a = block.id, "character"_a = block.character, "composition"_a = composition,
                    "behaviors"_a = behaviors);
}

/// Plays BML through a service's stage at its clock's time.
class Realizer {
public:
    Realizer(std::shared_ptr<runtime::AnimationService> service, std::shared_ptr<runtime::SoundService> sound)
        : m_service(std::move(service)), m_realizer(m_service->sharedStage(), std::move(sound))
    {
    }
    runtime::AnimationService& service() { return *m_service; }
    runtime::BmlRealizer& realizer() { return m_realizer; }

private:
    std::shared_ptr<runtime::AnimationService> m_service;
    runtime::BmlRealizer m_realizer;
};

} // namespace

void bindBml(py::module_& m)
{
    py::module_ b = m.def_submodule(
        "bml", "BML 1.0 (the subset real agents use): blocks of speech, gesture, faceLexeme, head, gaze, pointing and "
               "wait behaviours with sync references, read and realised on the Stage.");
    b.def("parse", [](const std::string& xml) { return blockDict(unwrap(speech::parseBml(xml))); }, "xml"_a,
          "Reads one <bml> block into a dict (id, character, composition, behaviors). Raises thespis.FormatError "
          "with \"line L, column C\".");
    b.def("normalize", [](const std::string& xml) { return speech::bmlString(unwrap(speech::parseBml(xml))); },
          "xml"_a, "The block as the realizer reads it, written back as BML.");
    b.def("face_lexemes", &speech::faceLexemeNames, "The faceLexemes the face shows (RAISE_BROWS, …).");
    b.def("default_lexicon", [] { return core::speech::BmlLexicon::defaults().gestures; },
          "Gesture lexemes → gesticon entries of a character that keeps no BML lexicon of its own "
          "(Character.bml_lexicon is None).");

    py::class_<Realizer>(b, "Realizer", "Realises BML blocks for the characters of an animation service's stage.")
        .def(py::init<std::shared_ptr<runtime::AnimationService>, std::shared_ptr<runtime::SoundService>>(),
             "service"_a, "sound"_a = nullptr, "`sound` (a SoundService) plays the speeches' audio when given.")
        .def(
            "perform",
            [](Realizer& r, const std::string& character, const std::string& xml, const std::string& voice, int rate,
               int pitch, std::optional<double> at, std::optional<std::map<std::string, std::string>> lexicon,
               bool saccades, const py::object& onEvent) {
                const speech::BmlBlock block = unwrap(speech::parseBml(xml));
                runtime::BmlOptions options;
                options.voice = {.voice = voice, .wordsPerMinute = rate, .pitch = pitch};
                if (lexicon) { // rows over the character's own
                    options.lexicon = unwrap(r.service().sharedStage()->bmlLexicon(character));
                    for (const auto& [lexeme, entry] : *lexicon)
                        options.lexicon->set(lexeme, entry);
                }
                options.gaze.saccades = saccades;
                const core::Tick start = at ? core::secondsToTicks(*at) : r.service().now();
                runtime::BmlPerformance performed = [&] {
                    py::gil_scoped_release release;
                    return unwrap(r.realizer().perform(character, block, options, start));
                }();
                py::list events;
                for (const runtime::BmlEvent& e : performed.events)
                    events.append(py::make_tuple(e.time, e.name));
                // Each event as the clock reaches it, as the block then stands: a block another
                // thread replaces meanwhile ends where it was cut off.
                const auto eventAt = [&](std::size_t i) {
                    const auto now = r.realizer().events(character, block.id);
                    return i < now.size() ? std::optional(now[i]) : std::nullopt;
                };
                for (std::size_t next = 0; !onEvent.is_none(); ++next) {
                    std::optional<runtime::BmlEvent> e = eventAt(next);
                    while (e) {
                        core::Result<bool> reached = false;
                        {
                            py::gil_scoped_release release;
                            reached = r.service().waitUntil(core::secondsToTicks(e->time), std::chrono::milliseconds(50));
                        }
                        const bool due = unwrap(std::move(reached));
                        const auto still = eventAt(next);
                        if (due && still && still->time == e->time && still->name == e->name)
                            break;
                        e = still;
                        if (PyErr_CheckSignals() != 0)
                            throw py::error_already_set();
                    }
                    if (!e)
                        break;
                    onEvent(e->name, e->time);
                }
                return py::dict("block"_a = performed.block, "start"_a = performed.start, "end"_a = performed.end,
                                "events"_a = events, "warnings"_a = performed.warnings);
            },
            "character"_a, "xml"_a, "voice"_a = "en-us", "rate"_a = 175, "pitch"_a = 50, "at"_a = py::none(),
            "lexicon"_a = py::none(), "saccades"_a = true, "on_event"_a = py::none(),
            "Plays the block for `character` from `at` (default: now) and returns its start, end and events "
            "(`lexicon`: {lexeme: gesture} rows over the character's own BML lexicon, Character.bml_lexicon) "
            "[(seconds, \"g1:stroke\"), …]. With `on_event`, waits through the block calling on_event(name, seconds) "
            "as the clock reaches each (\"bml1:start\", \"s1:t1\", …, \"bml1:end\"); without, returns at once — "
            "poll() then gives the events as the clock reaches them.")
        .def(
            "events",
            [](Realizer& r, const std::string& character, const std::string& block) {
                py::list out;
                for (const runtime::BmlEvent& e : r.realizer().events(character, block))
                    out.append(py::make_tuple(e.time, e.name));
                return out;
            },
            "character"_a, "block"_a,
            "The block's events as they now stand [(seconds, name), …]: one a later block replaced ends where it "
            "was cut off.")
        .def(
            "poll",
            [](Realizer& r) {
                py::list out;
                for (const auto& [character, e] : r.realizer().takeEvents(core::ticksToSeconds(r.service().now())))
                    out.append(py::make_tuple(e.time, e.name, character));
                return out;
            },
            "Without waiting: the events of every block the clock has reached since the last poll, in time order "
            "[(seconds, name, character), …] — for a script with its own loop.");
}

} // namespace thespis::python
