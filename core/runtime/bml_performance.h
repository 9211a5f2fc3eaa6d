#pragma once
// A BML realizer on the Stage (issue 33): a <bml> block's behaviours played for one character —
// its speeches spoken by espeak-ng with their lips (runtime/speech_performance.h), gestures of
// the character's gesticon fitted between their start and end points, faceLexemes on the face
// (speech/face_lexemes.h), head nods, shakes and tilts (motion/head_gesture.h) and gaze
// (Stage::gaze) — at the times the planner (speech/bml_plan.h) finds from the speeches' TTS timing. Blocks
// compose as BML says: merge plays alongside what plays, append after the character's last block
// ends, replace stops that first. The studio, scripts, the command line and the dialogue all
// realise BML through here.

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "motion/gaze.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "speech/bml.h"
#include "speech/bml_plan.h"
#include "speech/espeak_voice.h"
#include "util/error.h"
#include "util/tick.h"

namespace thespis::core::runtime {

struct BmlOptions {
    speech::VoiceSettings voice;
    /// The gesture lexemes' table; nullopt: the character's own on the stage (Stage::bmlLexicon).
    std::optional<speech::BmlLexicon> lexicon;
    motion::GazeSettings gaze; ///< what a <gaze> does beyond its target, influence and offset
    /// Speeches already spoken, by behaviour id (the others are synthesised with `voice`).
    std::shared_ptr<const std::map<std::string, speech::Utterance>> spoken;
};

/// When something of a block happens: its start and end ("bml1:start", "bml1:end") and each
/// behaviour's sync points ("g1:stroke", "s1:t1"), in seconds on the stage's time.
struct BmlEvent {
    double time = 0;
    std::string name;
};

struct BmlPerformance {
    std::string block;
    double start = 0, end = 0;                 ///< seconds on the stage's time
    std::vector<speech::BmlTimes> times;       ///< each behaviour's points, on the stage's time
    std::vector<BmlEvent> events;              ///< sorted by time
    std::vector<std::string> warnings;         ///< what could not play, one sentence each
};

class BmlRealizer {
public:
    /// `sound` (may be null) plays the speeches' audio, named speechSoundName(character, "BLOCK:ID").
    BmlRealizer(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound);

    /// Plays `block` for `character` from `at` (append: from the end of its last block, when later).
    /// Errors: no such character; a speech espeak-ng cannot say; a constraint resolveBml() refuses;
    /// a gesture lexeme, faceLexeme or head lexeme the character cannot play, or a gaze target
    /// that does not exist — each named with the behaviour's line and column.
    Result<BmlPerformance> perform(const std::string& character, const speech::BmlBlock& block,
                                   const BmlOptions& options, Tick at);

    /// The events of `block` played for `character` as they now stand, in time order: a block a
    /// later one replaced keeps those up to the replacement and ends there ("bml1:end" then).
    /// Empty for a block not played (or played long ago: the last kRememberedBlocks are kept).
    std::vector<BmlEvent> events(const std::string& character, const std::string& block) const;

    /// For a script's own loop: each event of any block that `now` (seconds on the stage's time)
    /// has reached and no earlier call took, in time order, with its character.
    std::vector<std::pair<std::string, BmlEvent>> takeEvents(double now);

    static constexpr std::size_t kRememberedBlocks = 64;

private:
    struct Played {
        double end = 0;
        std::vector<std::pair<Track, std::string>> actions; // to stop on replace
        std::vector<std::string> sounds;
        bool gaze = false, pointing = false;
    };
    // What a block's events are now, and how many of them takeEvents() gave.
    struct Feedback {
        std::string character, block;
        std::vector<BmlEvent> events;
        std::size_t taken = 0;
    };
    void cutOff(const std::string& character, double at);
    void remember(const std::string& character, const BmlPerformance& performance);

    std::shared_ptr<Stage> m_stage;
    std::shared_ptr<SoundService> m_sound;
    mutable std::mutex m_mutex;
    std::map<std::string, Played> m_played; // by character
    std::vector<Feedback> m_feedback;       // oldest first
};

} // namespace thespis::core::runtime
