// thespis.dialogue: conversation (paper §5.3) — AIML bots loaded from folders and files, one
// conversation per visitor (answers with the category that gave them, state saved as JSON), the
// recogniser that listens for what a bot can answer, and the interaction service that lets a
// character of the stage converse (scripts get it as `interactionService`).

#include "bind_common.h"
#include "errors.h"

#include "dialogue/bot_grammar.h"
#include "dialogue/conversation.h"
#include "runtime/animation_service.h"
#include "runtime/interaction_service.h"
#include "speech/speak_job.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace dialogue = core::dialogue;
namespace runtime = core::runtime;
namespace speech = core::speech;

namespace {

/// A loaded bot and what its files had wrong.
struct PyBot {
    std::shared_ptr<const dialogue::Bot> bot;
    std::vector<std::string> problems;
};

PyBot pyBot(dialogue::LoadedBot loaded)
{
    PyBot bot{std::move(loaded.bot), {}};
    for (const dialogue::LoadProblem& problem : loaded.problems)
        bot.problems.push_back(dialogue::describe(problem));
    return bot;
}

py::dict answerDict(const dialogue::Answer& answer)
{
    py::list matched;
    for (const dialogue::MatchedCategory& m : answer.matched)
        matched.append(py::dict("sentence"_a = m.sentence, "pattern"_a = m.pattern, "that"_a = m.that,
                                "topic"_a = m.topic, "file"_a = m.source.file, "line"_a = m.source.line,
                                "learned"_a = m.learned));
    return py::dict("text"_a = answer.text, "words"_a = speech::spokenWords(answer.text), "matched"_a = matched,
                    "problem"_a = answer.problem);
}

py::dict recognitionDict(const speech::Recognition& heard)
{
    py::list words;
    for (const speech::HeardWord& w : heard.words)
        words.append(py::make_tuple(w.word, w.start, w.end));
    return py::dict("understood"_a = heard.understood(), "text"_a = heard.text, "confidence"_a = heard.confidence,
                    "words"_a = words);
}

py::dict exchangeDict(const runtime::Exchange& e)
{
    return py::dict("heard"_a = e.heard, "understood"_a = e.understood, "confidence"_a = e.confidence,
                    "answer"_a = answerDict(e.answer), "start"_a = e.start, "end"_a = e.end, "warnings"_a = e.warnings);
}

} // namespace

void bindDialogue(py::module_& m)
{
    py::module_ d = m.def_submodule(
        "dialogue", "Conversation: AIML bots, one conversation per visitor, listening for what a bot can answer, and "
                    "the interaction service that lets a character converse on the stage.");
    d.attr("NOT_UNDERSTOOD") = std::string(dialogue::kNotUnderstood);

    py::class_<PyBot>(d, "Bot", "An AIML bot: its categories, sets, maps, substitutions and properties.")
        .def_property_readonly("problems", [](const PyBot& b) { return b.problems; },
                               "What its files had wrong (\"file:line:column: message\"); the rest loaded.")
        .def("__len__", [](const PyBot& b) { return b.bot->categories().size(); }, "Its categories.")
        .def("property", [](const PyBot& b, const std::string& name) { return b.bot->property(name); }, "name"_a)
        .def(
            "grammar",
            [](const PyBot& b) {
                auto grammar = unwrap(dialogue::makeListeningGrammar(dialogue::grammarSourceOf(*b.bot)));
                return py::dict("jsgf"_a = grammar.jsgf, "words"_a = grammar.words, "notes"_a = grammar.notes,
                                "patterns_used"_a = grammar.patternsUsed, "patterns_skipped"_a = grammar.patternsSkipped,
                                "graph_states"_a = grammar.graph.states, "graph_word_arcs"_a = grammar.graph.wordArcs());
            },
            "What the recogniser listens for (what the bot can answer) as JSGF, and the size of the word graph it "
            "listens with (the same language).");
    d.def(
        "load",
        [](const std::vector<std::filesystem::path>& paths) { return pyBot(unwrap(dialogue::loadBot(paths))); },
        "paths"_a,
        "Loads a bot from folders (Rosie's layout: aiml, sets, maps, substitutions, system) and AIML files. Raises "
        "thespis.FileNotFoundError for a path that does not exist; problems inside files are in Bot.problems.");

    py::class_<dialogue::Conversation>(d, "Conversation", "One visitor's conversation with a bot.")
        .def(py::init([](const PyBot& bot, const std::string& id) { return dialogue::Conversation(bot.bot, id); }),
             "bot"_a, "id"_a = "visitor")
        .def("respond", [](dialogue::Conversation& c, const std::string& input) { return answerDict(c.respond(input)); },
             "input"_a,
             "The answer: text (with its speech and gesture tags), words (what is said), matched (the categories, with "
             "file and line) and problem (why it was cut short, or \"\").")
        .def("save", &dialogue::Conversation::saveJson, "The state as JSON (predicates, history, learned categories).")
        .def_static(
            "restore",
            [](const PyBot& bot, const std::string& json) { return unwrap(dialogue::Conversation::restore(bot.bot, json)); },
            "bot"_a, "json"_a, "A conversation continuing from save()'s JSON. Raises thespis.FormatError naming the field.")
        .def_property_readonly("predicates", [](const dialogue::Conversation& c) { return c.state().predicates; });

    py::class_<speech::GrammarRecogniser>(d, "Recogniser", "pocketsphinx listening for what a bot can answer.")
        .def(py::init([](const PyBot& bot) { return unwrap(dialogue::listenFor(*bot.bot)); }), "bot"_a)
        .def(
            "recognise_file",
            [](speech::GrammarRecogniser& r, const std::filesystem::path& path) {
                auto samples = unwrap(speech::readRecording(path));
                py::gil_scoped_release release;
                auto heard = unwrap(r.recognise(samples));
                py::gil_scoped_acquire acquire;
                return recognitionDict(heard);
            },
            "path"_a,
            "Recognises a recording (WAV, FLAC, … at any rate): understood, text, confidence (log per frame against a free "
            "phone loop) and words [(word, start, end)].");

    py::class_<runtime::InteractionService, std::shared_ptr<runtime::InteractionService>>(
        d, "InteractionService",
        "The paper's interaction service: a character of the stage converses with the visitor — answers spoken with "
        "face, gestures and gaze, over whatever else it plays.")
        .def(py::init([](const std::shared_ptr<runtime::AnimationService>& service,
                         const std::shared_ptr<runtime::SoundService>& sound) {
                 return std::make_shared<runtime::InteractionService>(service->sharedStage(), sound);
             }),
             "service"_a, "sound"_a)
        .def(
            "load_bot",
            [](const runtime::InteractionService& s, const py::args& names) {
                std::vector<std::string> list;
                for (const py::handle& name : names)
                    list.push_back(py::str(name));
                return pyBot(unwrap(s.loadBot(list)));
            },
            "Loads a bot from the scenario's files (AIML files or bot folders, named as the scenario names its "
            "assets: \"dialogue/antigone/antigone.aiml\"), as thespis.dialogue.load does from paths.")
        .def(
            "converse",
            [](runtime::InteractionService& s, const std::string& character, const PyBot& bot, const py::object& visitor,
               bool speak, const std::string& state) {
                runtime::InteractionOptions options;
                options.visitor = gazeTarget(visitor);
                options.speak = speak;
                unwrap(s.converse(character, bot.bot, options, state));
            },
            "character"_a, "bot"_a, "visitor"_a = "camera", "speak"_a = true, "state"_a = "",
            "Hands the character to a conversation with `bot` from now: it looks at `visitor` (\"camera\", a character, "
            "(x, y, z)) and listens. `state`: save_state()'s JSON to continue from.")
        .def("hand_back", &runtime::InteractionService::handBack, "character"_a,
             "Gives the character back to the script; False when it was not conversing.")
        .def("conversing", &runtime::InteractionService::conversing, "character"_a)
        .def("visitor_speaks", [](runtime::InteractionService& s, const std::string& c) { unwrap(s.visitorSpeaks(c)); },
             "character"_a, "The visitor started speaking: the character listens visibly (its eyes, a small nod).")
        .def(
            "hear",
            [](runtime::InteractionService& s, const std::string& character, const std::string& text) {
                return exchangeDict(unwrap(s.hear(character, text)));
            },
            "character"_a, "text"_a,
            "The visitor typed `text`: the character answers from now. Returns heard, understood, confidence, answer "
            "(as Conversation.respond's), start and end (seconds on the stage) and warnings.")
        .def(
            "hear_file",
            [](runtime::InteractionService& s, const std::string& character, speech::GrammarRecogniser& recogniser,
               const std::filesystem::path& path) {
                auto samples = unwrap(speech::readRecording(path));
                auto heard = [&] {
                    py::gil_scoped_release release;
                    return unwrap(recogniser.recognise(samples));
                }();
                return exchangeDict(unwrap(s.hear(character, heard)));
            },
            "character"_a, "recogniser"_a, "path"_a,
            "The visitor said what the recording holds: recognised with `recogniser`, then answered (not understood: "
            "the bot's NOT_UNDERSTOOD category answers).")
        .def("save_state", [](const runtime::InteractionService& s, const std::string& c) { return unwrap(s.saveState(c)); },
             "character"_a)
        .def(
            "transcript",
            [](const runtime::InteractionService& s, const std::string& character) {
                py::list lines;
                for (const runtime::Exchange& e : unwrap(s.transcript(character)))
                    lines.append(exchangeDict(e));
                return lines;
            },
            "character"_a, "Every exchange of this visit, oldest first.");
}

} // namespace thespis::python
