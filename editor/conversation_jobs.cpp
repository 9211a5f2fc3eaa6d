#include "editor/conversation_jobs.h"

#include <chrono>

#include "dialogue/bot_grammar.h"

namespace thespis::editor {
namespace {

double secondsSince(std::chrono::steady_clock::time_point start)
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

} // namespace

std::string LoadBotJob::title() const { return "Loading the bot"; }

core::Result<void> LoadBotJob::validate() const
{
    if (paths.empty() && !given)
        return core::makeError(core::ErrorCode::InvalidArgument, "Choose a bot folder or AIML files to load.");
    return {};
}

core::Result<void> LoadBotJob::run(core::JobContext& context)
{
    auto start = std::chrono::steady_clock::now();
    if (given) {
        loaded.bot = given;
    } else {
        context.beginStage("Reading the bot's files");
        auto read = core::dialogue::loadBot(paths);
        if (!read)
            return read.error();
        loaded = std::move(read).value();
    }
    loadSeconds = secondsSince(start);
    if (context.stopRequested())
        return core::cancelledError(title());

    context.beginStage("Making the listening grammar");
    start = std::chrono::steady_clock::now();
    auto made = core::dialogue::makeListeningGrammar(core::dialogue::grammarSourceOf(*loaded.bot));
    grammarSeconds = secondsSince(start);
    if (made)
        grammar = std::move(made).value();
    else
        grammarError = made.error().message;
    if (context.stopRequested())
        return core::cancelledError(title());
    return {};
}

std::string ListenJob::title() const { return "Opening the recogniser"; }

core::Result<void> ListenJob::validate() const
{
    if (!bot)
        return core::makeError(core::ErrorCode::InvalidArgument, "Load a bot first: the recogniser listens for what it can answer.");
    return {};
}

core::Result<void> ListenJob::run(core::JobContext& context)
{
    context.beginStage("Opening the recogniser (pocketsphinx)");
    const auto start = std::chrono::steady_clock::now();
    auto opened = core::dialogue::listenFor(*bot);
    seconds = secondsSince(start);
    if (!opened)
        return opened.error();
    if (context.stopRequested())
        return core::cancelledError(title());
    recogniser = std::make_shared<core::speech::GrammarRecogniser>(std::move(opened).value());
    return {};
}

std::string TurnJob::title() const { return text ? "Answering" : "Hearing the visitor"; }

core::Result<void> TurnJob::validate() const
{
    if (!service || character.empty())
        return core::makeError(core::ErrorCode::InvalidArgument, "Choose the character who converses.");
    if (!text && samples.empty() && recording.empty())
        return core::makeError(core::ErrorCode::InvalidArgument, "Nothing was heard: the recording is empty.");
    if (!text && !recogniser)
        return core::makeError(core::ErrorCode::InvalidArgument,
                               "The recogniser is not open yet: wait until the bot's grammar is ready, or type.");
    return {};
}

core::Result<void> TurnJob::run(core::JobContext& context)
{
    if (!text) {
        if (!recording.empty()) {
            context.beginStage("Reading the recording");
            auto read = core::speech::readRecording(recording);
            if (!read)
                return read.error();
            samples = std::move(read).value();
        }
        if (context.stopRequested())
            return core::cancelledError(title());
        context.beginStage("Recognising");
        const auto start = std::chrono::steady_clock::now();
        auto recognised = recogniser->recognise(samples);
        recogniseSeconds = secondsSince(start);
        if (!recognised)
            return recognised.error();
        heard = std::move(recognised).value();
        // Stopped now, the bot is told nothing.
        if (context.stopRequested())
            return core::cancelledError(title());
    }
    context.beginStage("Answering");
    const auto start = std::chrono::steady_clock::now();
    auto answered = heard ? service->hear(character, *heard) : service->hear(character, *text);
    answerSeconds = secondsSince(start);
    if (!answered)
        return answered.error();
    exchange = std::move(answered).value();
    return {};
}

} // namespace thespis::editor
