#pragma once
// Speaking tagged text as a job (paper §5.1): the text is read, spoken sentence by sentence —
// so that a player can start the first sentence while the rest is being synthesised — and
// planned into visemes and gesture cues; or a BML block is read and each of its speeches spoken.
// The CLI, Python and the studio run it the same way.

#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "speech/bml.h"
#include "speech/espeak_voice.h"
#include "speech/speech_plan.h"
#include "speech/tagged_bml.h"
#include "speech/tagged_text.h"
#include "util/job.h"

namespace thespis::core::speech {

/// The sentences of `text`: byte ranges [begin, end) that end after ".", "!" or "?" (with any
/// closing quotes or brackets) followed by white space, or at the end. White space between them
/// belongs to no sentence.
std::vector<std::pair<std::size_t, std::size_t>> sentenceRanges(std::string_view text);

/// True when `text` is a BML block (it starts with "<bml" or an XML declaration, after white
/// space) rather than tagged text.
bool isBml(std::string_view text);

/// The words `text` says, for a transcript: tagged text without its tags, a BML block's speeches
/// in order; the text as it is when it reads as neither.
std::string spokenWords(std::string_view text);

struct SpeakJob final : Job {
    static constexpr const char* SpeakingStage = "Speaking";

    std::string text;              ///< tagged text (plain text is tagged text without tags), or a BML block
    VoiceSettings voice;
    VisemeSet visemes = mpeg4Visemes();
    std::filesystem::path wavOutput; ///< optional: the speech as a 16-bit WAV, written at the end
    /// Called on the job's thread as each sentence is ready, with the speech so far (a player
    /// may start it while the next sentence is synthesised).
    std::function<void(const Utterance& soFar)> sentenceReady;

    // After run():
    TaggedText tagged;
    Utterance utterance;           ///< the whole speech; timing offsets into tagged.text
    std::vector<VisemeCue> visemeCues;
    std::vector<GestureCue> gestureCues; ///< the words each tagged gesture spans
    TaggedBml gestureBml;          ///< the tagged gestures as BML, for the planner
    /// BML: the block, and each of its speeches said, by behaviour id (the fields above stay empty).
    std::optional<BmlBlock> bml;
    std::map<std::string, Utterance> bmlSpeech;

    std::string title() const override;
    /// The text reads as tagged text (line and column otherwise) and has something to say; the
    /// voice settings are in range; the WAV's folder exists.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;

private:
    Result<void> runBml(JobContext& context);
};

} // namespace thespis::core::speech
