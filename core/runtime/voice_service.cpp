#include "runtime/voice_service.h"

#include "runtime/speech_performance.h"

namespace thespis::core::runtime {
namespace {

std::optional<scenario::SpeechLine> findLine(const Stage& stage, const std::string& character, const std::string& name)
{
    const scenario::ScenarioRuntime runtime = stage.runtimeCopy();
    if (const scenario::CharacterRuntime* who = runtime.findCharacter(character))
        for (const scenario::SpeechLine& line : who->speech)
            if (line.name == name)
                return line;
    return std::nullopt;
}

} // namespace

VoiceService::VoiceService(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound)
    : m_stage(std::move(stage)), m_sound(std::move(sound))
{
}

Result<int> VoiceService::activateAction(const std::string& character, const std::string& speech, double volume)
{
    if (m_stage->findCharacter(character) < 0)
        return makeError(ErrorCode::NotFound, "There is no character \"" + character + "\" to speak.");
    const std::optional<scenario::SpeechLine> line = findLine(*m_stage, character, speech);
    if (!line) // the paper's scripts name recorded sound files
        return m_sound->play(speech, volume, character);

    auto said = say(character, *line, volume);
    if (!said)
        return said.error();
    return said->sound;
}

Result<VoiceService::Said> VoiceService::say(const std::string& character, const scenario::SpeechLine& line,
                                             double volume)
{
    const Tick now = m_sound->now();
    const std::string where = character + "'s line \"" + line.name + "\"";
    auto spoken = m_sound->lineAudio(line);
    if (!spoken)
        return makeError(spoken.error().code, where + ", " + spoken.error().message);
    auto performed = performSpeech(*m_stage, character, line.name, speech::visemeCues(spoken->timing),
                                   speech::taggedBml(spoken->text, spoken->timing), now);
    if (!performed)
        return makeError(performed.error().code, where + ": " + performed.error().message);
    {
        const std::lock_guard lock(m_mutex);
        m_warnings.clear();
        for (const std::string& gesture : performed->unknownGestures)
            m_warnings.push_back(where + ": " + character + " cannot play the gesture \"" + gesture + "\".");
    }
    const int sound = m_sound->playClip(speechSoundName(character, line.name), spoken->clip, now, volume, character);
    return Said{sound, spoken->clip->duration()};
}

bool VoiceService::stop(const std::string& character, const std::string& speech)
{
    const bool sound = m_sound->stop(speechSoundName(character, speech)) || m_sound->stop(speech);
    const auto face = m_stage->cutOffAction(character, Track::Face, "speech " + speech, m_sound->now(), 0.1);
    return sound || (face && *face);
}

bool VoiceService::isPlaying(const std::string& character, const std::string& speech) const
{
    return m_sound->isPlaying(speechSoundName(character, speech)) || m_sound->isPlaying(speech);
}

std::vector<std::string> VoiceService::warnings() const
{
    const std::lock_guard lock(m_mutex);
    return m_warnings;
}

} // namespace thespis::core::runtime
