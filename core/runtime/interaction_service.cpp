#include "runtime/interaction_service.h"

#include <filesystem>

#include "dialogue/bot_grammar.h"
#include "scenario/scenario_runtime.h"
#include "speech/bml.h"
#include "speech/speak_job.h"

namespace thespis::core::runtime {
namespace {

// A listener's small nod, a moment after the visitor starts (BML, so that it plays as a <head>
// of the realizer does).
constexpr std::string_view kListeningNod =
    R"(<bml id="listening" composition="merge"><head id="nod" lexeme="NOD" amount="0.3" start="0.4"/></bml>)";

Error notConversing(const std::string& character)
{
    return makeError(ErrorCode::InvalidArgument,
                     "\"" + character + "\" is not conversing: hand it to a conversation first (converse).");
}

// "file:line" of the category that answered last, for messages.
std::string answeredAt(const dialogue::Answer& answer)
{
    if (answer.matched.empty())
        return "(none)";
    const dialogue::SourcePlace& place = answer.matched.back().source;
    return place.file + ":" + std::to_string(place.line);
}

} // namespace

InteractionService::InteractionService(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound)
    : m_stage(stage), m_sound(sound), m_voice(stage, sound), m_bml(stage, sound)
{
}

Result<dialogue::LoadedBot> InteractionService::loadBot(std::span<const std::string> names) const
{
    std::vector<std::filesystem::path> paths;
    for (const std::string& name : names)
        paths.push_back(m_sound->assets().path(name));
    return dialogue::loadBot(paths);
}

Result<void> InteractionService::converse(const std::string& character, std::shared_ptr<const dialogue::Bot> bot,
                                          const InteractionOptions& options, std::string_view state)
{
    if (m_stage->findCharacter(character) < 0)
        return makeError(ErrorCode::NotFound, "There is no character \"" + character + "\" to converse.");
    speech::VoiceSettings voice;
    if (options.voice)
        voice = *options.voice;
    else if (const scenario::ScenarioRuntime runtime = m_stage->runtimeCopy();
             runtime.findCharacter(character) && !runtime.findCharacter(character)->speech.empty()) {
        const scenario::SpeechLine& line = runtime.findCharacter(character)->speech.front();
        voice.voice = line.voice;
        voice.wordsPerMinute = line.rate;
        voice.pitch = line.pitch;
    }
    if (auto valid = voice.validate(); !valid)
        return valid.error();
    auto conversation = state.empty() ? Result<dialogue::Conversation>(dialogue::Conversation(bot, character))
                                      : dialogue::Conversation::restore(bot, state);
    if (!conversation)
        return conversation.error();
    const std::lock_guard lock(m_mutex);
    m_visits.insert_or_assign(character, Visit{std::move(conversation).value(), options, voice, {}, 0});
    return look(character, m_visits.at(character), false, m_sound->now());
}

bool InteractionService::handBack(const std::string& character)
{
    const std::lock_guard lock(m_mutex);
    if (m_visits.erase(character) == 0)
        return false;
    (void)m_stage->stopGaze(character, m_sound->now());
    return true;
}

bool InteractionService::conversing(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    return find(character) != nullptr;
}

std::shared_ptr<const dialogue::Bot> InteractionService::bot(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    const Visit* visit = find(character);
    return visit ? visit->conversation.sharedBot() : nullptr;
}

Result<void> InteractionService::visitorSpeaks(const std::string& character)
{
    const std::lock_guard lock(m_mutex);
    const Visit* visit = find(character);
    if (!visit)
        return notConversing(character);
    const Tick now = m_sound->now();
    if (auto looked = look(character, *visit, false, now); !looked)
        return looked;
    auto nod = speech::parseBml(kListeningNod);
    if (!nod)
        return nod.error();
    auto played = m_bml.perform(character, *nod, {}, now);
    if (!played)
        return played.error();
    return {};
}

Result<Exchange> InteractionService::hear(const std::string& character, std::string_view input)
{
    Exchange exchange;
    exchange.heard = std::string(input);
    return answer(character, std::move(exchange), input);
}

Result<Exchange> InteractionService::hear(const std::string& character, const speech::Recognition& heard)
{
    Exchange exchange;
    exchange.understood = heard.understood();
    exchange.confidence = heard.confidence;
    if (exchange.understood)
        exchange.heard = heard.text;
    const std::string input = exchange.understood ? heard.text : std::string(dialogue::kNotUnderstood);
    return answer(character, std::move(exchange), input);
}

Result<Exchange> InteractionService::answer(const std::string& character, Exchange exchange, std::string_view input)
{
    const std::lock_guard lock(m_mutex);
    Visit* visit = find(character);
    if (!visit)
        return notConversing(character);
    exchange.answer = visit->conversation.respond(input);
    const Tick now = m_sound->now();
    exchange.start = exchange.end = ticksToSeconds(now);
    const std::string& text = exchange.answer.text;
    if (!text.empty() && visit->options.speak) {
        if (auto looked = look(character, *visit, true, now); !looked)
            return looked.error();
        const std::string name = "answer " + std::to_string(++visit->answers);
        if (speech::isBml(text)) {
            auto block = speech::parseBml(text);
            if (!block)
                return makeError(block.error().code, "The answer of the category at " + answeredAt(exchange.answer) +
                                                         " is not BML that plays: " + block.error().message);
            BmlOptions options;
            options.voice = visit->voice;
            auto played = m_bml.perform(character, *block, options, now);
            if (!played)
                return played.error();
            exchange.end = played->end;
            exchange.warnings = played->warnings;
        } else {
            scenario::SpeechLine line;
            line.name = name;
            line.text = text;
            line.voice = visit->voice.voice;
            line.rate = visit->voice.wordsPerMinute;
            line.pitch = visit->voice.pitch;
            auto spoken = m_voice.say(character, line);
            if (!spoken)
                return spoken.error();
            exchange.end = exchange.start + spoken->seconds;
            exchange.warnings = m_voice.warnings();
        }
    }
    visit->transcript.push_back(exchange);
    return exchange;
}

Result<void> InteractionService::look(const std::string& character, const Visit& visit, bool talking, Tick at)
{
    motion::GazeSettings settings;
    settings.talking = talking;
    settings.influence = motion::GazeInfluence::Head;
    return m_stage->gaze(character, visit.options.visitor, settings, at);
}

Result<std::string> InteractionService::saveState(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    const Visit* visit = find(character);
    if (!visit)
        return notConversing(character);
    return visit->conversation.saveJson();
}

Result<std::vector<Exchange>> InteractionService::transcript(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    const Visit* visit = find(character);
    if (!visit)
        return notConversing(character);
    return visit->transcript;
}

InteractionService::Visit* InteractionService::find(const std::string& character)
{
    const auto found = m_visits.find(character);
    return found == m_visits.end() ? nullptr : &found->second;
}

const InteractionService::Visit* InteractionService::find(const std::string& character) const
{
    const auto found = m_visits.find(character);
    return found == m_visits.end() ? nullptr : &found->second;
}

} // namespace thespis::core::runtime
