#pragma once
// The voice service of the paper's scripts (§4.5: `voiceService.activateAction(Creon,
// "CreonSpeech.Cam01CreonP1", 1.0)`): a character says one of its speech lines now — its audio
// through the sound service (or, for a line that keeps none, its text spoken by its voice) and its
// visemes and face gestures live on the Stage (runtime/speech_performance.h) — or, for a name
// that is no speech line, plays that sound file as its voice. Every method may be called from a
// script's thread.

#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "runtime/sound.h"
#include "runtime/stage.h"
#include "util/error.h"

namespace thespis::core::runtime {

class VoiceService {
public:
    VoiceService(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound);

    /// `character` says `speech` from now at `volume`: its speech line of that name, else the
    /// sound file of that name. Returns the sound's activation id. Errors: no such character; a
    /// line whose audio cannot be read or whose text cannot be spoken; no line and no such file.
    Result<int> activateAction(const std::string& character, const std::string& speech, double volume = 1.0);
    /// What say() started: the sound's activation id and how long the line lasts.
    struct Said {
        int sound = 0;
        double seconds = 0;
    };
    /// `character` says `line` from now, as activateAction() says a line of its own (a
    /// conversation's answers are lines made on the spot). Errors as activateAction()'s.
    Result<Said> say(const std::string& character, const scenario::SpeechLine& line, double volume = 1.0);
    /// Stops the character's line (its sound and its face) now; false when it does not play.
    bool stop(const std::string& character, const std::string& speech);
    bool isPlaying(const std::string& character, const std::string& speech) const;
    /// Problems of the last activation that did not stop it (e.g. a gesture the character cannot
    /// play), one sentence each.
    std::vector<std::string> warnings() const;

    const std::shared_ptr<SoundService>& sound() const { return m_sound; }

private:
    std::shared_ptr<Stage> m_stage;
    std::shared_ptr<SoundService> m_sound;
    mutable std::mutex m_mutex;
    std::vector<std::string> m_warnings;
};

} // namespace thespis::core::runtime
