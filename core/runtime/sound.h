#pragma once
// The voice and sound service (paper §4.5: `voiceService.activateAction(Creon, "CreonSpeech…",
// 1.0)`, `sndService.sndmpPlayMedia(…)`): sound files — WAV, OGG, FLAC, read with libsndfile —
// started at the clock's time, so speech plays in sync with the stage. Headless, mix() renders
// what plays over any span of time (the CLI writes it to a WAV next to the frames); the studio
// plays the same activations. Sounds are named by their file, relative to the scenario's
// folder. Every method locks, so a script thread may start sounds while another mixes.

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <span>
#include <string>
#include <vector>

#include "runtime/clock.h"
#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "speech/speech_timing.h"
#include "speech/tagged_text.h"
#include "util/error.h"
#include "util/tick.h"

namespace thespis::core::runtime {

/// A sound file's samples, mixed down to mono.
struct SoundClip {
    int rate = 0;
    std::vector<float> samples;
    double duration() const { return rate > 0 ? double(samples.size()) / rate : 0.0; }
};

/// Reads a sound file (WAV, OGG Vorbis, FLAC, …). Errors name the file and what is wrong.
Result<std::shared_ptr<const SoundClip>> loadSound(const std::filesystem::path& path);

/// Writes mono samples (−1 … 1, clamped) as a 16-bit PCM WAV, atomically.
Result<void> writeWav(const std::filesystem::path& path, int rate, std::span<const float> samples);

/// The name a speech line's sound plays under ("Creon: line").
std::string speechSoundName(const std::string& character, const std::string& line);

class SoundService {
public:
    /// Sounds are assets of `assets` (a scenario's); mix() renders at `mixRate` samples per second.
    SoundService(scenario::Assets assets, std::shared_ptr<Clock> clock, int mixRate = 48000);

    /// Starts the sound now at `volume` (1: as recorded), for `owner` (a character's name, or
    /// empty); returns its activation id. Errors: the file cannot be read.
    Result<int> play(const std::string& sound, double volume = 1.0, const std::string& owner = {});
    /// Starts the sound at `start` on the clock's time instead of now.
    Result<int> playAt(const std::string& sound, Tick start, double volume = 1.0, const std::string& owner = {});
    /// Starts samples made in memory (speech just synthesised) at `start`, named `sound` for
    /// stop() and isPlaying(); returns its activation id.
    int playClip(const std::string& sound, std::shared_ptr<const SoundClip> clip, Tick start, double volume = 1.0,
                 const std::string& owner = {});
    /// The sound file's samples (read once, then kept). Errors name the file.
    Result<std::shared_ptr<const SoundClip>> load(const std::string& sound);
    /// Where its sounds (and the scenario's other files a script names) are found.
    const scenario::Assets& assets() const { return m_assets; }
    /// The clock's time: what "now" is for play().
    Tick now() const { return m_clock->now(); }
    /// A speech line's audio and timing: its sound file with the timing it keeps, else its text
    /// spoken by its voice (espeak-ng says it the same way every time; kept, so that saying it
    /// again costs nothing). Errors name the file, the tags or the voice.
    struct SpokenLine {
        std::shared_ptr<const SoundClip> clip;
        speech::SpeechTiming timing; ///< words located in `text`
        speech::TaggedText text;     ///< the line's tagged text, read
    };
    Result<SpokenLine> lineAudio(const scenario::SpeechLine& line);
    /// Starts the audio of every speech line of the scenario's characters that is on the
    /// timeline at the line's start (format 9), as speechSoundName(character, line); returns what
    /// could not be played, one sentence naming the field each.
    std::vector<std::string> playSpeech(const scenario::Scenario& scenario);
    /// Forgets every activation (the sounds read stay kept): a scenario's sounds start over.
    void clear();
    /// Stops every activation of the sound now (false: none plays).
    bool stop(const std::string& sound);
    bool isPlaying(const std::string& sound) const;
    /// Length of the sound in seconds (loads it). Errors: unreadable.
    Result<double> length(const std::string& sound);

    int mixRate() const { return m_rate; }
    /// Mixes what plays from `from` on into `out` (out.size() samples at mixRate()), clamped
    /// to −1…1. No allocation.
    void mix(Tick from, std::span<float> out) const;
    /// Writes the mix of [from, to) as a 16-bit mono WAV, atomically.
    Result<void> writeWav(const std::filesystem::path& path, Tick from, Tick to) const;

    struct Activation {
        std::string sound, owner;
        std::shared_ptr<const SoundClip> clip;
        Tick start = 0, end = 0; // end: natural end, or when stopped
        float volume = 1;
    };
    std::vector<Activation> activations() const;
    std::size_t activationCount() const;

private:
    Result<std::shared_ptr<const SoundClip>> clip(const std::string& sound);

    mutable std::mutex m_mutex;
    scenario::Assets m_assets;
    std::shared_ptr<Clock> m_clock;
    int m_rate;
    std::map<std::string, std::shared_ptr<const SoundClip>> m_clips;
    std::vector<Activation> m_activations;
    std::map<std::string, std::pair<std::shared_ptr<const SoundClip>, speech::SpeechTiming>> m_spoken; // by voice and text
};

} // namespace thespis::core::runtime
