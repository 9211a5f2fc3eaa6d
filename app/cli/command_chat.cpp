// thespis-cli chat: the visitor talks to a bot (paper §5.3, issue 34). Lines typed on standard
// input, one per line, or a recording recognised against the grammar of what the bot can answer,
// go to an AIML conversation (core/dialogue); each answer is printed on a line of its own (an
// empty line when nothing matches). With a scenario and --character the answers are also spoken
// by that character through the interaction service (runtime/interaction_service.h), exactly as in
// the studio and in scripts: speech, face, gestures and gaze on its Stage; --out keeps the voice.

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "commands.h"
#include "exit_codes.h"
#include "dialogue/bot.h"
#include "dialogue/bot_grammar.h"
#include "runtime/clock.h"
#include "runtime/interaction_service.h"
#include "runtime/sound.h"
#include "scenario/scenario_io.h"
#include "speech/grammar_recogniser.h"
#include "speech/speak_job.h"
#include "util/file_io.h"

namespace thespis::cli {
namespace {

constexpr double kPause = 0.5; // seconds between an answer and the visitor's next line

} // namespace

CommandSpec chatSpec()
{
    CommandSpec spec;
    spec.name = "chat";
    spec.summary = "Talk to an AIML bot by typing or from a recording; a scenario's character may speak the answers.";
    spec.positionals = {"SCENARIO"};
    spec.lastOptional = true;
    spec.options = {
        {"aiml", "PATH", "an AIML file, or a bot folder (Rosie's lib/ layout: aiml, sets, maps, substitutions, system)", true, true},
        {"character", "NAME", "who answers (with SCENARIO)"},
        {"wav", "IN.wav", "recognise this recording instead of reading lines from standard input"},
        {"no-speech", "", "print the answers only; do not speak them"},
        {"state", "FILE.json", "the conversation's state: read if it exists, written at the end (predicates survive runs)"},
        {"out", "FILE.wav", "the character's voice answering (with SCENARIO)"},
        {"quiet", "", "no problems of the bot's files and no summary on standard error"},
    };
    spec.description =
        "Each line of standard input is one thing the visitor says; each answer is one line of\n"
        "standard output (its words, the speech and gesture tags taken out), empty when the bot has\n"
        "no answer. With --wav the recording is recognised first with pocketsphinx against a JSGF\n"
        "grammar made from the bot's patterns; what was heard is printed on its own line as\n"
        "\"heard: TEXT (confidence C)\", or \"heard: nothing understood (confidence C)\", in which\n"
        "case the bot is told XNOTUNDERSTOOD. Problems in the bot's files are reported with file and\n"
        "line on standard error and the rest loads.\n"
        "Example: printf 'hello\\nwho is creon\\n' | thespis-cli chat --aiml resources/dialogue/antigone --no-speech\n"
        "         thespis-cli chat demo.thespis --character Antigone --aiml resources/dialogue/antigone --wav q.wav --out a.wav\n"
        "Exit status: 0 done, 2 bad command line, 3 a file cannot be read (the bot has no category, the\n"
        "recording, the state, the scenario or its character), 4 a file could not be written.";
    return spec;
}

int runChat(const CommandSpec& spec, const ParsedArguments& arguments)
{
    namespace dialogue = core::dialogue;
    const bool quiet = arguments.has("quiet");
    const bool withScenario = !arguments.positionals.empty();
    const auto character = arguments.value("character");
    if (withScenario != character.has_value())
        return usageError(spec, withScenario ? "give --character: who answers" : "--character needs SCENARIO");
    if (arguments.has("out") && (!withScenario || arguments.has("no-speech")))
        return usageError(spec, "--out needs SCENARIO and speech");

    std::vector<std::filesystem::path> paths;
    for (const std::string& path : arguments.all("aiml"))
        paths.emplace_back(path);
    auto loaded = dialogue::loadBot(paths);
    if (!loaded) {
        printError(spec.name, loaded.error());
        return ExitInvalidInput;
    }
    if (!quiet)
        for (const dialogue::LoadProblem& problem : loaded->problems)
            std::fprintf(stderr, "%s: warning: %s\n", spec.name.c_str(), dialogue::describe(problem).c_str());
    std::string state;
    const auto statePath = arguments.value("state");
    if (statePath && std::filesystem::exists(*statePath)) {
        auto read = core::readTextFile(*statePath);
        if (!read) {
            printError(spec.name, read.error());
            return ExitInvalidInput;
        }
        state = std::move(*read);
    }

    // Who answers: the scenario's character through the interaction service, else the bot alone.
    std::shared_ptr<core::runtime::ManualClock> clock;
    std::shared_ptr<core::runtime::SoundService> sound;
    std::unique_ptr<core::runtime::InteractionService> service;
    std::optional<dialogue::Conversation> conversation;
    if (withScenario) {
        auto document = openScenarioReporting(spec.name, arguments.positionals[0]);
        if (!document)
            return ExitInvalidInput;
        auto runtime = core::scenario::buildRuntime(document->scenario, document->assets);
        if (!runtime) {
            printError(spec.name, runtime.error());
            return ExitInvalidInput;
        }
        auto stage = std::make_shared<core::runtime::Stage>(std::move(runtime).value());
        clock = std::make_shared<core::runtime::ManualClock>();
        sound = std::make_shared<core::runtime::SoundService>(document->assets, clock);
        service = std::make_unique<core::runtime::InteractionService>(stage, sound);
        core::runtime::InteractionOptions options;
        options.speak = !arguments.has("no-speech");
        if (auto conversing = service->converse(*character, loaded->bot, options, state); !conversing) {
            printError(spec.name, conversing.error());
            return ExitInvalidInput;
        }
    } else {
        auto restored = state.empty() ? core::Result<dialogue::Conversation>(dialogue::Conversation(loaded->bot))
                                      : dialogue::Conversation::restore(loaded->bot, state);
        if (!restored) {
            printError(spec.name, restored.error());
            return ExitInvalidInput;
        }
        conversation.emplace(std::move(restored).value());
    }

    // One thing the visitor said, answered and printed.
    double spokenUntil = 0;
    const auto answer = [&](const std::string& input, const core::speech::Recognition* heard) -> int {
        dialogue::Answer said;
        if (service) {
            auto exchange = heard ? service->hear(*character, *heard) : service->hear(*character, input);
            if (!exchange) {
                printError(spec.name, exchange.error());
                return ExitInvalidInput;
            }
            for (const std::string& warning : exchange->warnings)
                std::fprintf(stderr, "%s: warning: %s\n", spec.name.c_str(), warning.c_str());
            said = exchange->answer;
            spokenUntil = exchange->end;
            clock->setTime(core::secondsToTicks(exchange->end + kPause));
        } else {
            said = conversation->respond(heard && !heard->understood() ? dialogue::kNotUnderstood : std::string_view(input));
        }
        if (!said.problem.empty())
            std::fprintf(stderr, "%s: warning: %s\n", spec.name.c_str(), said.problem.c_str());
        std::printf("%s\n", core::speech::spokenWords(said.text).c_str());
        std::fflush(stdout);
        return ExitOk;
    };

    int status = ExitOk;
    if (const auto wav = arguments.value("wav")) {
        auto samples = core::speech::readRecording(*wav);
        if (!samples) {
            printError(spec.name, samples.error());
            return ExitInvalidInput;
        }
        auto recogniser = dialogue::listenFor(*loaded->bot);
        if (!recogniser) {
            printError(spec.name, recogniser.error());
            return ExitInvalidInput;
        }
        auto heard = recogniser->recognise(*samples);
        if (!heard) {
            printError(spec.name, heard.error());
            return ExitInvalidInput;
        }
        if (heard->understood())
            std::printf("heard: %s (confidence %.2f)\n", heard->text.c_str(), heard->confidence);
        else
            std::printf("heard: nothing understood (confidence %.2f; nearest: \"%s\")\n", heard->confidence,
                        heard->text.c_str());
        status = answer(heard->text, &*heard);
    } else {
        for (std::string line; status == ExitOk && std::getline(std::cin, line);)
            status = answer(line, nullptr);
    }
    if (status != ExitOk)
        return status;

    if (statePath) {
        auto saved = service ? service->saveState(*character) : core::Result<std::string>(conversation->saveJson());
        if (auto written = saved ? core::writeFileAtomically(*statePath, *saved) : core::Result<void>(saved.error()); !written) {
            printError(spec.name, written.error());
            return ExitFailure;
        }
    }
    if (const auto out = arguments.value("out")) {
        if (auto written = sound->writeWav(*out, 0, core::secondsToTicks(spokenUntil)); !written) {
            printError(spec.name, written.error());
            return ExitFailure;
        }
    }
    return ExitOk;
}

} // namespace thespis::cli
