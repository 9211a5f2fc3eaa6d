#pragma once
// The Conversation dock's long work as jobs (util/job.h) that editor::JobRunner runs off the GUI
// thread: loading a bot, opening the recogniser that listens for what it can answer, and one
// turn of the conversation (a recording or the microphone's samples recognised, then answered by
// the interaction service; or a typed line answered). Each is a thin wrapper around the core
// calls that thespis-cli chat and thespis.dialogue make — loadBot, makeListeningGrammar,
// listenFor, GrammarRecogniser::recognise, InteractionService::hear — so the studio runs the same
// pipeline. No Qt here.
//
// Cancelling: the core calls take no stop token (loading Rosie ~0.4 s; opening a recogniser on a
// Rosie-sized grammar ~10 s; recognising a few seconds of speech), so a job stops between them:
// a turn cancelled before its answer tells the bot nothing.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "dialogue/bot.h"
#include "dialogue/listening_grammar.h"
#include "runtime/interaction_service.h"
#include "speech/grammar_recogniser.h"
#include "util/job.h"

namespace thespis::editor {

/// Reads a bot (folders as loadBotFolder reads them, files by their extension) and makes the
/// grammar its recogniser will listen with, for the grammar inspector.
struct LoadBotJob final : core::Job {
    std::vector<std::filesystem::path> paths;
    /// A bot loaded already (one a script handed over): only its grammar is made.
    std::shared_ptr<const core::dialogue::Bot> given;

    // After run():
    core::dialogue::LoadedBot loaded;
    /// The listening grammar; empty with `grammarError` set when the bot has nothing to listen for.
    std::optional<core::dialogue::ListeningGrammar> grammar;
    std::string grammarError;
    double loadSeconds = 0, grammarSeconds = 0;

    std::string title() const override;
    core::Result<void> validate() const override;
    core::Result<void> run(core::JobContext& context) override;
};

/// Opens the recogniser for `bot` (dialogue::listenFor): pocketsphinx with the bot's grammar.
struct ListenJob final : core::Job {
    std::shared_ptr<const core::dialogue::Bot> bot;

    // After run():
    std::shared_ptr<core::speech::GrammarRecogniser> recogniser;
    double seconds = 0;

    std::string title() const override;
    core::Result<void> validate() const override;
    core::Result<void> run(core::JobContext& context) override;
};

/// One turn: what the visitor said — typed `text`, `samples` (16 kHz mono, from the microphone)
/// or the recording at `recording` — answered by `character` through `service`. Speech is
/// recognised with `recogniser` first; what it rejects is answered as not understood.
struct TurnJob final : core::Job {
    std::shared_ptr<core::runtime::InteractionService> service;
    std::string character;
    std::optional<std::string> text;
    std::vector<std::int16_t> samples;
    std::filesystem::path recording;
    std::shared_ptr<core::speech::GrammarRecogniser> recogniser;

    // After run() (also after a cancel that came once the answer was given):
    std::optional<core::speech::Recognition> heard;
    std::optional<core::runtime::Exchange> exchange;
    double recogniseSeconds = 0, answerSeconds = 0;

    std::string title() const override;
    core::Result<void> validate() const override;
    core::Result<void> run(core::JobContext& context) override;
};

} // namespace thespis::editor
