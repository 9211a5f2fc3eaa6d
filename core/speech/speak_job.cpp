#include "speech/speak_job.h"

#include <cctype>

#include "runtime/sound.h"
#include "speech/bml_plan.h"

namespace thespis::core::speech {
namespace {

bool isSpace(char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; }

} // namespace

std::vector<std::pair<std::size_t, std::size_t>> sentenceRanges(std::string_view text)
{
    std::vector<std::pair<std::size_t, std::size_t>> ranges;
    std::size_t begin = 0;
    auto close = [&](std::size_t end) {
        while (begin < end && isSpace(text[begin]))
            ++begin;
        if (begin < end)
            ranges.emplace_back(begin, end);
        begin = end;
    };
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] != '.' && text[i] != '!' && text[i] != '?')
            continue;
        std::size_t end = i + 1;
        while (end < text.size() && (text[end] == '.' || text[end] == '!' || text[end] == '?' || text[end] == '"'
                                     || text[end] == '\'' || text[end] == ')'))
            ++end;
        if (end == text.size() || isSpace(text[end]))
            close(end);
        i = end - 1;
    }
    close(text.size());
    return ranges;
}

std::string SpeakJob::title() const
{
    return "Speaking";
}

bool isBml(std::string_view text)
{
    std::size_t at = 0;
    while (at < text.size() && isSpace(text[at]))
        ++at;
    text.remove_prefix(at);
    return text.starts_with("<bml") || text.starts_with("<?xml");
}

std::string spokenWords(std::string_view text)
{
    if (isBml(text)) {
        auto block = parseBml(text);
        if (!block)
            return std::string(text);
        std::string words;
        for (const BmlBehavior& behavior : block->behaviors)
            if (behavior.kind == BmlBehaviorKind::Speech)
                words += (words.empty() ? "" : " ") + behavior.text;
        return words;
    }
    auto tagged = parseTaggedText(text);
    return tagged ? std::move(tagged->text) : std::string(text);
}

Result<void> SpeakJob::validate() const
{
    if (isBml(text)) {
        auto block = parseBml(text);
        if (!block)
            return makeError(ErrorCode::InvalidArgument, "The text is not valid BML: " + block.error().message);
        if (block->behaviors.empty())
            return makeError(ErrorCode::InvalidArgument, "The BML block \"" + block->id + "\" has no behaviour.");
        if (!wavOutput.empty())
            return makeError(ErrorCode::InvalidArgument,
                             "A BML block's speeches are not written as one WAV: leave the WAV out.");
        return voice.validate();
    }
    auto parsed = parseTaggedText(text);
    if (!parsed)
        return makeError(ErrorCode::InvalidArgument, "The text is not valid tagged text: " + parsed.error().message);
    if (sentenceRanges(parsed->text).empty())
        return makeError(ErrorCode::InvalidArgument, "There is no text to speak.");
    if (auto valid = voice.validate(); !valid)
        return valid;
    if (auto valid = visemes.validate(); !valid)
        return valid;
    if (!wavOutput.empty()) {
        const std::filesystem::path folder = wavOutput.parent_path();
        if (!folder.empty() && !std::filesystem::is_directory(folder))
            return makeError(ErrorCode::InvalidArgument, "The folder of " + wavOutput.string() + " does not exist.");
    }
    return {};
}

Result<void> SpeakJob::runBml(JobContext& context)
{
    bml = parseBml(text).value();
    bmlSpeech.clear();
    std::size_t speeches = 0;
    for (const BmlBehavior& b : bml->behaviors)
        speeches += b.kind == BmlBehaviorKind::Speech;
    context.beginStage(SpeakingStage, speeches);
    for (const BmlBehavior& b : bml->behaviors) {
        if (b.kind != BmlBehaviorKind::Speech)
            continue;
        auto spoken = speak(b.text, voice, {}, context.stopToken());
        if (!spoken) {
            if (spoken.error().code == ErrorCode::Cancelled)
                return cancelledError(title());
            return bmlBehaviorError(spoken.error().code, b, spoken.error().message);
        }
        bmlSpeech[b.id] = std::move(spoken).value();
        context.setDone(bmlSpeech.size());
    }
    return {};
}

Result<void> SpeakJob::run(JobContext& context)
{
    if (auto valid = validate(); !valid)
        return valid;
    tagged = {};
    utterance = {};
    visemeCues.clear();
    gestureCues.clear();
    gestureBml = {};
    bml.reset();
    if (isBml(text))
        return runBml(context);
    tagged = parseTaggedText(text).value();
    const auto sentences = sentenceRanges(tagged.text);
    context.beginStage(SpeakingStage, sentences.size());
    utterance = {};
    for (std::size_t s = 0; s < sentences.size(); ++s) {
        const auto [begin, end] = sentences[s];
        auto spoken = speak(std::string_view(tagged.text).substr(begin, end - begin), voice, {}, context.stopToken());
        if (!spoken)
            return spoken.error().code == ErrorCode::Cancelled ? cancelledError(title()) : spoken.error();
        const double offset = utterance.duration();
        utterance.timing.append(spoken->timing, offset, begin);
        utterance.samples.insert(utterance.samples.end(), spoken->samples.begin(), spoken->samples.end());
        if (sentenceReady)
            sentenceReady(utterance);
        context.setDone(s + 1);
    }
    utterance.timing.duration = utterance.duration();
    visemeCues = speech::visemeCues(utterance.timing, visemes);
    gestureCues = speech::gestureCues(tagged, utterance.timing);
    gestureBml = taggedBml(tagged, utterance.timing);
    if (context.stopRequested())
        return cancelledError(title());
    if (!wavOutput.empty())
        if (auto written = runtime::writeWav(wavOutput, utterance.rate, utterance.samples); !written)
            return written;
    return {};
}

void SpeakJob::discardOutput()
{
    if (!wavOutput.empty()) {
        std::error_code ignored;
        std::filesystem::remove(wavOutput, ignored);
    }
}

} // namespace thespis::core::speech
