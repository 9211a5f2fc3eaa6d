#include "runtime/sound.h"

#include <algorithm>
#include <cmath>

#include <sndfile.h>

#include "runtime/speech_performance.h"
#include "speech/espeak_voice.h"
#include "util/file_io.h"

namespace thespis::core::runtime {

Result<std::shared_ptr<const SoundClip>> loadSound(const std::filesystem::path& path)
{
    SF_INFO info{};
    SNDFILE* file = sf_open(path.string().c_str(), SFM_READ, &info);
    if (!file) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec))
            return makeError(ErrorCode::FileNotFound, path.string() + ": no such sound file.");
        return makeError(ErrorCode::NotOurFormat, path.string() + ": not a sound file libsndfile reads (" +
                                                      std::string(sf_strerror(nullptr)) + ").");
    }
    const auto close = [file] { sf_close(file); };
    if (info.channels < 1 || info.samplerate < 1 || info.frames < 0 || info.frames > (sf_count_t(1) << 31)) {
        close();
        return makeError(ErrorCode::CorruptData, path.string() + ": the sound's header is not valid.");
    }
    std::vector<float> interleaved(std::size_t(info.frames) * std::size_t(info.channels));
    const sf_count_t read = sf_readf_float(file, interleaved.data(), info.frames);
    close();
    auto clip = std::make_shared<SoundClip>();
    clip->rate = info.samplerate;
    clip->samples.resize(std::size_t(std::max<sf_count_t>(read, 0)));
    for (std::size_t f = 0; f < clip->samples.size(); ++f) {
        float sum = 0;
        for (int c = 0; c < info.channels; ++c)
            sum += interleaved[f * std::size_t(info.channels) + std::size_t(c)];
        clip->samples[f] = sum / float(info.channels);
    }
    return std::shared_ptr<const SoundClip>(std::move(clip));
}

SoundService::SoundService(scenario::Assets assets, std::shared_ptr<Clock> clock, int mixRate)
    : m_assets(std::move(assets)), m_clock(std::move(clock)), m_rate(std::max(mixRate, 1))
{
}

Result<std::shared_ptr<const SoundClip>> SoundService::clip(const std::string& sound)
{
    if (auto found = m_clips.find(sound); found != m_clips.end())
        return found->second;
    auto loaded = loadSound(m_assets.path(sound));
    if (!loaded)
        return loaded.error();
    m_clips[sound] = *loaded;
    return *loaded;
}

Result<int> SoundService::play(const std::string& sound, double volume, const std::string& owner)
{
    return playAt(sound, m_clock->now(), volume, owner);
}

Result<int> SoundService::playAt(const std::string& sound, Tick now, double volume, const std::string& owner)
{
    const std::lock_guard lock(m_mutex);
    auto loaded = clip(sound);
    if (!loaded)
        return loaded.error();
    m_activations.push_back(Activation{sound, owner, *loaded, now, now + secondsToTicks((*loaded)->duration()),
                                       float(std::max(volume, 0.0))});
    return int(m_activations.size()) - 1;
}

int SoundService::playClip(const std::string& sound, std::shared_ptr<const SoundClip> clip, Tick start, double volume,
                           const std::string& owner)
{
    const std::lock_guard lock(m_mutex);
    const Tick end = start + secondsToTicks(clip->duration());
    m_activations.push_back(Activation{sound, owner, std::move(clip), start, end, float(std::max(volume, 0.0))});
    return int(m_activations.size()) - 1;
}

Result<std::shared_ptr<const SoundClip>> SoundService::load(const std::string& sound)
{
    const std::lock_guard lock(m_mutex);
    return clip(sound);
}

std::string speechSoundName(const std::string& character, const std::string& line) { return character + ": " + line; }

Result<SoundService::SpokenLine> SoundService::lineAudio(const scenario::SpeechLine& line)
{
    auto tagged = speech::parseTaggedText(line.text);
    if (!tagged)
        return makeError(tagged.error().code, "text: " + tagged.error().message);
    if (!line.audio.empty()) {
        auto loaded = load(line.audio);
        if (!loaded)
            return makeError(loaded.error().code, "audio: " + loaded.error().message);
        speech::SpeechTiming timing = timingOf(line, tagged->text);
        return SpokenLine{std::move(loaded).value(), std::move(timing), std::move(tagged).value()};
    }
    const std::string key = "\x01speech\x01" + line.voice + "\x01" + std::to_string(line.rate) + "\x01"
                            + std::to_string(line.pitch) + "\x01" + tagged->text;
    {
        const std::lock_guard lock(m_mutex);
        if (auto found = m_spoken.find(key); found != m_spoken.end())
            return SpokenLine{found->second.first, found->second.second, std::move(tagged).value()};
    }
    auto spoken = speech::speak(tagged->text, {.voice = line.voice, .wordsPerMinute = line.rate, .pitch = line.pitch});
    if (!spoken)
        return makeError(spoken.error().code, "voice: " + spoken.error().message);
    auto clip = std::make_shared<const SoundClip>(SoundClip{spoken->rate, std::move(spoken->samples)});
    const std::lock_guard lock(m_mutex);
    m_spoken[key] = {clip, spoken->timing};
    return SpokenLine{std::move(clip), std::move(spoken->timing), std::move(tagged).value()};
}

std::vector<std::string> SoundService::playSpeech(const scenario::Scenario& scenario)
{
    std::vector<std::string> problems;
    for (std::size_t c = 0; c < scenario.characters.size(); ++c) {
        const scenario::Character& character = scenario.characters[c];
        for (std::size_t l = 0; l < character.speech.size(); ++l) {
            const scenario::SpeechLine& line = character.speech[l];
            if (!line.start)
                continue;
            auto audio = lineAudio(line);
            if (!audio) {
                problems.push_back("characters[" + std::to_string(c) + "].speech[" + std::to_string(l) + "]."
                                   + audio.error().message);
                continue;
            }
            playClip(speechSoundName(character.name, line.name), audio->clip, *line.start, 1.0, character.name);
        }
    }
    return problems;
}

void SoundService::clear()
{
    const std::lock_guard lock(m_mutex);
    m_activations.clear();
}

bool SoundService::stop(const std::string& sound)
{
    const Tick now = m_clock->now();
    const std::lock_guard lock(m_mutex);
    bool stopped = false;
    for (Activation& a : m_activations)
        if (a.sound == sound && a.start <= now && now < a.end) {
            a.end = now;
            stopped = true;
        }
    return stopped;
}

bool SoundService::isPlaying(const std::string& sound) const
{
    const Tick now = m_clock->now();
    const std::lock_guard lock(m_mutex);
    return std::any_of(m_activations.begin(), m_activations.end(),
                       [&](const Activation& a) { return a.sound == sound && a.start <= now && now < a.end; });
}

Result<double> SoundService::length(const std::string& sound)
{
    const std::lock_guard lock(m_mutex);
    auto loaded = clip(sound);
    if (!loaded)
        return loaded.error();
    return (*loaded)->duration();
}

void SoundService::mix(Tick from, std::span<float> out) const
{
    const std::lock_guard lock(m_mutex);
    std::fill(out.begin(), out.end(), 0.0f);
    const double start = ticksToSeconds(from);
    for (const Activation& a : m_activations) {
        // Output sample i is at time start + i / rate; the sound's own sample position there,
        // linearly interpolated (the sound's rate may differ from the mix's).
        const double offset = start - ticksToSeconds(a.start);
        const double end = ticksToSeconds(a.end - a.start);
        const std::size_t count = a.clip->samples.size();
        for (std::size_t i = 0; i < out.size(); ++i) {
            const double t = offset + double(i) / m_rate;
            if (t < 0 || t >= end)
                continue;
            const double position = t * a.clip->rate;
            const auto k = std::size_t(position);
            if (k + 1 >= count) {
                if (k < count)
                    out[i] += a.volume * a.clip->samples[k];
                continue;
            }
            const float u = float(position - double(k));
            out[i] += a.volume * ((1 - u) * a.clip->samples[k] + u * a.clip->samples[k + 1]);
        }
    }
    for (float& s : out)
        s = std::clamp(s, -1.0f, 1.0f);
}

Result<void> writeWav(const std::filesystem::path& path, int rate, std::span<const float> samples)
{
    // A 16-bit PCM RIFF WAV, written whole through the project's atomic writer.
    std::string bytes;
    const auto put = [&](std::uint32_t value, int size) {
        for (int b = 0; b < size; ++b)
            bytes.push_back(char((value >> (8 * b)) & 0xff));
    };
    const std::uint32_t dataBytes = std::uint32_t(samples.size() * 2);
    bytes += "RIFF";
    put(36 + dataBytes, 4);
    bytes += "WAVEfmt ";
    put(16, 4);
    put(1, 2); // PCM
    put(1, 2); // mono
    put(std::uint32_t(rate), 4);
    put(std::uint32_t(rate) * 2, 4);
    put(2, 2);
    put(16, 2);
    bytes += "data";
    put(dataBytes, 4);
    for (const float s : samples)
        put(std::uint32_t(std::uint16_t(std::int16_t(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f)))), 2);
    return writeFileAtomically(path, bytes);
}

Result<void> SoundService::writeWav(const std::filesystem::path& path, Tick from, Tick to) const
{
    const auto frames = std::size_t(std::max<Tick>(0, (to - from)) * m_rate / TicksPerSecond);
    std::vector<float> samples(frames);
    mix(from, samples);
    return runtime::writeWav(path, m_rate, samples);
}

std::size_t SoundService::activationCount() const
{
    const std::lock_guard lock(m_mutex);
    return m_activations.size();
}

std::vector<SoundService::Activation> SoundService::activations() const
{
    const std::lock_guard lock(m_mutex);
    return m_activations;
}

} // namespace thespis::core::runtime
