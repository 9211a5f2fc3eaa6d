// Bindings of core/speech as the submodule thespis.speech: tagged text, espeak-ng's voices and
// speech (the SpeakJob: audio, word and phoneme timing, viseme and gesture cues), viseme sets,
// the coarticulation dominance function, and Insert into a scenario (one undoable Edit).

#include <optional>
#include <string>
#include <vector>

#include "bind_common.h"
#include "edit/bml_edits.h"
#include "edit/speech_edits.h"
#include "errors.h"
#include "run_job.h"
#include "runtime/speech_performance.h"
#include "speech/espeak_voice.h"
#include "speech/lip_sync.h"
#include "speech/speak_job.h"
#include "speech/tagged_text.h"
#include "speech/viseme_set.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace speech = core::speech;

namespace {

py::list wordsOf(const speech::SpeechTiming& timing)
{
    py::list words;
    for (const speech::WordTiming& w : timing.words)
        words.append(py::make_tuple(w.text, w.start, w.end));
    return words;
}

py::list phonemesOf(const speech::SpeechTiming& timing)
{
    py::list phonemes;
    for (const speech::PhonemeTiming& p : timing.phonemes)
        phonemes.append(py::make_tuple(p.phoneme, p.start, p.end, p.word));
    return phonemes;
}

// The index of the character who speaks; ValueError naming it when there is none.
int speakerIndex(const core::scenario::Scenario& scenario, const std::string& character)
{
    const core::scenario::Character* who = scenario.findCharacter(character);
    if (!who)
        throw py::value_error("The scenario has no character '" + character + "'.");
    return int(who - scenario.characters.data());
}

} // namespace

void bindSpeech(py::module_& m)
{
    py::module_ s = m.def_submodule(
        "speech", "Speech (paper §5): tagged text, espeak-ng voices and speech with phoneme timing, visemes with the "
                  "coarticulation dominance curve, and speech inserted into a scenario.");

    // The same function as thespis.dominance, where speech users look for it.
    s.attr("dominance") = m.attr("dominance");

    s.def(
        "parse_tagged_text",
        [](const std::string& text) {
            const speech::TaggedText tagged = unwrap(speech::parseTaggedText(text));
            py::list gestures;
            for (const speech::TaggedGesture& g : tagged.gestures)
                gestures.append(py::dict("id"_a = g.id, "anim"_a = g.animation, "begin"_a = g.begin, "end"_a = g.end,
                                         "line"_a = g.line, "column"_a = g.column));
            return py::make_tuple(tagged.text, gestures);
        },
        "text"_a,
        "Reads tagged text (<begin_gesture id=.. anim=../> ... <end_gesture id=../>): (the text spoken, [gestures as "
        "dicts with id, anim, begin and end byte offsets into it, line, column]). FormatError names the line and column.");

    s.def(
        "voices",
        []() {
            py::list out;
            for (const speech::VoiceInfo& v : unwrap(speech::listVoices()))
                out.append(py::dict("name"_a = v.name, "identifier"_a = v.identifier, "language"_a = v.language,
                                    "gender"_a = v.gender));
            return out;
        },
        "The voices espeak-ng has installed (name, identifier, language, gender: 0 unknown, 1 male, 2 female).");

    s.def(
        "phonemes_of", [](const std::string& word, const std::string& voice) { return unwrap(speech::phonemesOf(word, voice)); },
        "word"_a, "voice"_a = "en-us", "The ARPAbet phonemes espeak-ng says for a word.");
    s.def("mpeg4_viseme", &speech::mpeg4Viseme, "phoneme"_a, "The MPEG-4 viseme (1 ... 14, 0 for a pause) of an ARPAbet phoneme.");

    py::class_<speech::Viseme>(s, "Viseme", "A mouth shape of a viseme set and how it blends into its neighbours.")
        .def_readwrite("id", &speech::Viseme::id)
        .def_readwrite("name", &speech::Viseme::name)
        .def_readwrite("alpha", &speech::Viseme::alpha, "dominance: larger keeps the shape to its own phoneme")
        .def_readwrite("weight", &speech::Viseme::weight, "how far the shape is reached (0 ... 1)")
        .def_readwrite("spread", &speech::Viseme::spread, "reach past the phoneme, a fraction of its length each side")
        .def_readwrite("mpeg4", &speech::Viseme::mpeg4,
                       "the MPEG-4 viseme (1 ... 14) it shows as on the face; 0: the mouth at rest")
        .def("__repr__", [](const speech::Viseme& v) { return "Viseme(" + std::to_string(v.id) + ", '" + v.name + "')"; });

    py::class_<speech::VisemeSet>(s, "VisemeSet", "Visemes and which ARPAbet phonemes show each one (data: edit, load, save).")
        .def_static("builtin", [](const std::string& name) {
            const speech::VisemeSet* set = speech::builtInVisemeSet(name);
            if (!set)
                throw py::value_error("There is no built-in viseme set '" + name + "': mpeg4, oculus or sapi.");
            return *set;
        }, "name"_a, "'mpeg4' (the face's 14), 'oculus' (15) or 'sapi' (21).")
        .def_static("load", [](const std::filesystem::path& path) { return unwrap(speech::loadVisemeSet(path)); }, "path"_a)
        .def_static("parse", [](const std::string& text) { return unwrap(speech::parseVisemeSet(text)); }, "text"_a)
        .def("save", [](const speech::VisemeSet& set, const std::filesystem::path& path) { unwrap(speech::saveVisemeSet(path, set)); }, "path"_a)
        .def("serialize", &speech::serializeVisemeSet)
        .def("validate", [](const speech::VisemeSet& set) { unwrap(set.validate()); },
             "Raises ValueError naming the field that breaks a rule.")
        .def_readwrite("name", &speech::VisemeSet::name)
        .def_readwrite("visemes", &speech::VisemeSet::visemes)
        .def_readwrite("phonemes", &speech::VisemeSet::phonemes, "ARPAbet phoneme -> viseme ids")
        .def("visemes_of", &speech::VisemeSet::visemesOf, "phoneme"_a)
        .def("__eq__", [](const speech::VisemeSet& a, const speech::VisemeSet& b) { return a == b; });

    // The speak job's results, kept whole so that insert() gets exactly what was heard.
    py::class_<speech::SpeakJob, std::shared_ptr<speech::SpeakJob>>(
        s, "Speech", "Speech made by thespis.speech.speak(): audio, timing, viseme and gesture cues.")
        .def_property_readonly("text", [](const speech::SpeakJob& j) { return j.text; }, "the tagged text or BML")
        .def_property_readonly("bml_block", [](const speech::SpeakJob& j) {
            return j.bml ? py::object(py::str(j.bml->id)) : py::object(py::none());
        },
                               "the BML block's id when the text was BML (its speeches are in bml_speeches), else None")
        .def_property_readonly("bml_speeches", [](const speech::SpeakJob& j) {
            py::dict out;
            for (const auto& [id, u] : j.bmlSpeech)
                out[py::str(id)] = wordsOf(u.timing);
            return out;
        }, "BML: each speech's words [(text, start, end)] by its id")
        .def_property_readonly("spoken_text", [](const speech::SpeakJob& j) { return j.tagged.text; })
        .def_property_readonly("rate", [](const speech::SpeakJob& j) { return j.utterance.rate; })
        .def_property_readonly("samples", [](const speech::SpeakJob& j) { return toArray<float>(j.utterance.samples); },
                               "the audio, float32 in -1 ... 1")
        .def_property_readonly("duration", [](const speech::SpeakJob& j) { return j.utterance.duration(); })
        .def_property_readonly("words", [](const speech::SpeakJob& j) { return wordsOf(j.utterance.timing); },
                               "[(text, start, end)] in seconds")
        .def_property_readonly("phonemes", [](const speech::SpeakJob& j) { return phonemesOf(j.utterance.timing); },
                               "[(ARPAbet or 'SIL', start, end, word index or -1)]")
        .def_property_readonly("visemes", [](const speech::SpeakJob& j) {
            py::list out;
            for (const speech::VisemeCue& c : j.visemeCues)
                out.append(py::dict("viseme"_a = c.viseme, "mpeg4"_a = c.mpeg4, "name"_a = c.name, "phoneme"_a = c.phoneme, "start"_a = c.start,
                                    "duration"_a = c.duration, "centre"_a = c.centre, "alpha"_a = c.weight.envelope().alpha,
                                    "weight"_a = c.weight.envelope().peak));
            return out;
        }, "one dict per viseme action: viseme id, the MPEG-4 viseme it shows as, name, phoneme, start, duration, "
           "centre, alpha, weight")
        .def_property_readonly("gestures", [](const speech::SpeakJob& j) {
            py::list out;
            for (const speech::GestureCue& c : j.gestureCues)
                out.append(py::dict("id"_a = c.id, "anim"_a = c.animation, "start"_a = c.start, "end"_a = c.end));
            return out;
        }, "one dict per tagged gesture: id, anim, start and end (seconds, from its words)");

    s.def(
        "speak",
        [](const std::string& text, const std::string& voice, int rate, int pitch, int volume, const speech::VisemeSet* visemes,
           const std::optional<std::filesystem::path>& wav, const py::object& progress) {
            auto job = std::make_shared<speech::SpeakJob>();
            job->text = text;
            job->voice = {voice, rate, pitch, volume};
            if (visemes)
                job->visemes = *visemes;
            job->wavOutput = wav.value_or(std::filesystem::path());
            runJob(*job, progress);
            return job;
        },
        "text"_a, "voice"_a = "en-us", "rate"_a = 175, "pitch"_a = 50, "volume"_a = 100, "visemes"_a = nullptr,
        "wav"_a = py::none(), "progress"_a = py::none(),
        "Speaks tagged text with espeak-ng, sentence by sentence (a core job: progress(done, total) per sentence, "
        "Ctrl-C cancels), into a Speech; writes it as a 16-bit WAV when `wav` is given.");

    s.def(
        "insert",
        [](const core::scenario::Scenario& scenario, const std::string& character, const speech::SpeakJob& spoken,
           double at, const std::string& audio, const core::scenario::ScenarioRuntime* runtime) {
            auto line = core::edit::speechLine(spoken.text, spoken.voice, spoken.utterance.timing, audio,
                                               core::secondsToTicks(at));
            if (!spoken.gestureBml.empty() && !runtime)
                throw py::value_error("The speech has tagged gestures: give the scenario's runtime "
                                      "(thespis.build_runtime) for their lengths.");
            return unwrap(core::edit::insertSpeech(scenario, speakerIndex(scenario, character), std::move(line),
                                                   spoken.visemeCues, spoken.gestureBml, runtime))
                .edit;
        },
        "scenario"_a, "character"_a, "speech"_a, "at"_a = 0.0, "audio"_a = "", "runtime"_a = nullptr,
        "The Edit that puts the speech on the character from `at` seconds as the studio's Insert does: the line "
        "(text, voice, timing, `audio` file relative to the scenario), viseme actions on its 'Speech' face layer, "
        "tagged gestures over their words, timed by the BML planner on the gesticon of `runtime` (the scenario's, "
        "needed when the text has gestures). One undo step: apply(scenario), inverse().");

    s.def(
        "insert_bml",
        [](const core::scenario::Scenario& scenario, const core::scenario::ScenarioRuntime& runtime,
           const std::string& character, const speech::SpeakJob& spoken, double at,
           std::optional<std::map<std::string, std::string>> lexicon) {
            if (!spoken.bml)
                throw py::value_error("This speech was tagged text, not BML: use insert().");
            core::edit::BmlInsertOptions options;
            options.voice = spoken.voice;
            options.visemes = spoken.visemes;
            if (lexicon) { // rows over the character's own
                const int who = speakerIndex(scenario, character);
                options.lexicon = speech::BmlLexicon::of(scenario.characters[std::size_t(who)].bmlLexicon);
                for (const auto& [lexeme, entry] : *lexicon)
                    options.lexicon->set(lexeme, entry);
            }
            return unwrap(core::edit::insertBml(scenario, runtime, speakerIndex(scenario, character), *spoken.bml,
                                                spoken.bmlSpeech, options, core::secondsToTicks(at)))
                .edit;
        },
        "scenario"_a, "runtime"_a, "character"_a, "speech"_a, "at"_a = 0.0, "lexicon"_a = py::none(),
        "The Edit that puts a BML block spoken by speak() on the character from `at` seconds as the studio's "
        "Insert does: speeches with their visemes, gestures on 'Gestures', head gestures on 'Head', faceLexemes on "
        "'Face lexemes', gaze on the 'Gaze' gaze layer. `runtime` is the scenario's (the gestures' lengths). "
        "Gesture lexemes are looked up in the character's BML lexicon (Character.bml_lexicon), with the rows of "
        "`lexicon` ({lexeme: gesture}) over it when given.");

    py::class_<speech::LipSyncJob, std::shared_ptr<speech::LipSyncJob>>(
        s, "Alignment", "A recording lip-synced by thespis.speech.align(): its words and phonemes in time.")
        .def_property_readonly("audio", [](const speech::LipSyncJob& j) { return j.audio; })
        .def_property_readonly("transcript", [](const speech::LipSyncJob& j) { return j.result.transcript; },
                               "as given, or as recognised")
        .def_property_readonly("words", [](const speech::LipSyncJob& j) { return wordsOf(j.result.timing); },
                               "[(text, start, end)] in seconds")
        .def_property_readonly("phonemes", [](const speech::LipSyncJob& j) { return phonemesOf(j.result.timing); },
                               "[(ARPAbet or 'SIL', start, end, word index or -1)]")
        .def_property_readonly("warnings", [](const speech::LipSyncJob& j) { return j.result.warnings; });

    s.def(
        "align",
        [](const std::filesystem::path& audio, const std::string& transcript, const py::object& progress) {
            auto job = std::make_shared<speech::LipSyncJob>();
            job->audio = audio;
            job->transcript = transcript;
            runJob(*job, progress);
            return job;
        },
        "audio"_a, "transcript"_a = "", "progress"_a = py::none(),
        "Lip sync of a recording (WAV, FLAC, OGG; any rate): word and phoneme times by forced alignment of its "
        "transcript with pocketsphinx (empty: the words are recognised first). A core job: Ctrl-C cancels.");

    s.def(
        "insert",
        [](const core::scenario::Scenario& scenario, const std::string& character, const speech::LipSyncJob& aligned,
           double at, const std::string& audio) {
            const speech::SpeechTiming& timing = aligned.result.timing;
            auto line = core::edit::speechLine(aligned.result.transcript, {}, timing,
                                               audio.empty() ? aligned.audio.string() : audio, core::secondsToTicks(at));
            return unwrap(core::edit::insertSpeech(scenario, speakerIndex(scenario, character), std::move(line),
                                                   speech::visemeCues(timing)))
                .edit;
        },
        "scenario"_a, "character"_a, "alignment"_a, "at"_a = 0.0, "audio"_a = "",
        "As insert() for speech, for a lip-synced recording: its file (or `audio`, relative to the scenario) is the "
        "line's audio.");

    s.def(
        "perform",
        [](core::runtime::Stage& stage, const std::string& character, const speech::SpeakJob& spoken, double at,
           const std::string& name) {
            auto performed = unwrap(core::runtime::performSpeech(stage, character, name, spoken.visemeCues,
                                                                 spoken.gestureBml, core::secondsToTicks(at)));
            return py::dict("action"_a = performed.action, "visemes"_a = performed.visemes,
                            "gestures"_a = performed.gestures, "unknown_gestures"_a = performed.unknownGestures);
        },
        "stage"_a, "character"_a, "speech"_a, "at"_a = 0.0, "name"_a = "line",
        "Plays the speech's visemes and gestures live on the stage from `at` seconds (the studio's Preview), as the "
        "face action 'speech NAME'; the audio is the caller's (speech.samples at speech.rate).");
}

} // namespace thespis::python
