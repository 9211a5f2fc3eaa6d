#pragma once
// The paper's interaction service (§5.3: "a dialogue manager that responds to the user according
// to a predefined script …", with speech recognition and synthesis): a character converses with
// the visitor on the Stage. What the visitor says — typed, or recognised against the grammar of
// what the bot can answer (speech/grammar_recogniser.h) — goes to the character's conversation
// (dialogue/conversation.h); the answer, tagged text or BML, is spoken with its face, gestures and
// gaze through the voice service and the BML realizer, live over whatever else the character
// plays (its idle motion, a script's actions), so a script may hand the character over at any
// moment and take it back without the motion stopping. While conversing the character looks at
// the visitor (the camera: in AR the tracked real one), as a listener while the visitor speaks —
// with a small nod — and as a speaker while it answers. Every method may be called from a
// script's thread.

#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "dialogue/bot.h"
#include "dialogue/conversation.h"
#include "motion/gaze_target.h"
#include "runtime/bml_performance.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "runtime/voice_service.h"
#include "speech/espeak_voice.h"
#include "speech/grammar_recogniser.h"
#include "util/error.h"

namespace thespis::core::runtime {

struct InteractionOptions {
    motion::GazeTarget visitor;                ///< whom the character talks to (default: the camera)
    /// How the character speaks; none: as its first speech line does (else espeak-ng's default).
    std::optional<speech::VoiceSettings> voice;
    bool speak = true;                         ///< false: answers are only returned (text mode)
};

/// One turn: what the visitor said and what the character answered.
struct Exchange {
    std::string heard;          ///< as typed or recognised; empty when not understood
    bool understood = true;     ///< false: the recogniser rejected it, the bot was told kNotUnderstood
    double confidence = 0;      ///< the recogniser's (0 for typed input)
    dialogue::Answer answer;    ///< text empty when nothing matched
    double start = 0, end = 0;  ///< seconds on the stage's time the answer is spoken (equal: silent)
    std::vector<std::string> warnings; ///< what of the answer could not play, one sentence each
};

class InteractionService {
public:
    InteractionService(std::shared_ptr<Stage> stage, std::shared_ptr<SoundService> sound);

    /// The bot in the scenario's files `names` (AIML files or bot folders as dialogue::loadBot
    /// reads them, named as the scenario names its assets: "dialogue/antigone/antigone.aiml").
    /// FileNotFound naming the first that is not there; what of them does not read is in its
    /// problems.
    Result<dialogue::LoadedBot> loadBot(std::span<const std::string> names) const;
    /// Hands `character` to a conversation with `bot` from now (a new one, or continuing `state`,
    /// saved by saveState()): it looks at the visitor and listens. Errors: no such character; a
    /// voice that does not validate; a state that does not read (naming its field).
    Result<void> converse(const std::string& character, std::shared_ptr<const dialogue::Bot> bot,
                          const InteractionOptions& options = {}, std::string_view state = {});
    /// Gives the character back to what else plays it: its gaze at the visitor lets go. False
    /// when it was not conversing.
    bool handBack(const std::string& character);
    bool conversing(const std::string& character) const;
    /// The bot `character` converses with; null when it does not.
    std::shared_ptr<const dialogue::Bot> bot(const std::string& character) const;

    /// The visitor started speaking: the character listens visibly (its eyes on the visitor as a
    /// listener's, a small nod).
    Result<void> visitorSpeaks(const std::string& character);
    /// The visitor typed `input`: the character answers it from now.
    Result<Exchange> hear(const std::string& character, std::string_view input);
    /// The visitor said something: what the recogniser heard, or, when it did not understand,
    /// dialogue::kNotUnderstood, is answered from now.
    Result<Exchange> hear(const std::string& character, const speech::Recognition& heard);

    /// The character's conversation state as JSON (dialogue::Conversation::saveJson()).
    Result<std::string> saveState(const std::string& character) const;
    /// The transcript so far, oldest first.
    Result<std::vector<Exchange>> transcript(const std::string& character) const;

private:
    struct Visit {
        dialogue::Conversation conversation;
        InteractionOptions options;
        speech::VoiceSettings voice;
        std::vector<Exchange> transcript;
        int answers = 0;
    };
    Result<Exchange> answer(const std::string& character, Exchange exchange, std::string_view input);
    Result<void> look(const std::string& character, const Visit& visit, bool talking, Tick at);
    Visit* find(const std::string& character);
    const Visit* find(const std::string& character) const;

    std::shared_ptr<Stage> m_stage;
    std::shared_ptr<SoundService> m_sound;
    VoiceService m_voice;
    BmlRealizer m_bml;
    mutable std::mutex m_mutex;
    std::map<std::string, Visit> m_visits; // by character
};

} // namespace thespis::core::runtime
