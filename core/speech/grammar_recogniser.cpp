#include "speech/grammar_recogniser.h"

#include <algorithm>
#include <functional>
#include <limits>
#include <map>
#include <set>

#include "runtime/sound.h"
#include "speech/espeak_voice.h"
#include "speech/resample.h"
#include "speech/jsgf.h"
#include "util/text.h"

namespace thespis::core::speech {
namespace {

const std::string kGrammarSearch = "grammar";
const std::string kPhoneLoopSearch = "phones";

// The grammar's tokens, after checking it as pocketsphinx will read it.
Result<std::vector<std::string>> grammarTokens(std::string_view jsgf)
{
    auto grammar = parseJsgf(jsgf);
    if (!grammar)
        return grammar.error();
    if (!grammar->imports.empty())
        return makeError(ErrorCode::InvalidArgument, "A grammar to listen for cannot import others (it imports <"
                                                         + grammar->imports.front().grammar + "." + grammar->imports.front().rule
                                                         + ">): pocketsphinx reads it as text alone.");
    if (grammar->publicRules().empty())
        return makeError(ErrorCode::InvalidArgument, "The grammar " + grammar->name + " has no public rule to listen for.");
    auto set = resolveJsgf(std::move(*grammar), {});
    if (!set)
        return set.error();
    return set->tokens();
}

// Gives every token its pronunciations: CMUdict's (looked up in lower case), or espeak-ng's,
// which are listed as "word: PHONES" for people to check. `count`: token → how many it has.
Result<std::vector<std::string>> addPronunciations(SphinxDecoder& decoder, const std::vector<std::string>& tokens,
                                                   const RecogniserOptions& options, std::map<std::string, std::size_t>& count)
{
    std::set<std::string, std::less<>> keys;
    for (const std::string& token : tokens)
        keys.insert(lowercase(token));
    auto dictionary = readPronunciations(options.model.dictionary, keys);
    if (!dictionary)
        return dictionary.error();
    std::vector<std::string> espeakPronounced;
    for (const std::string& token : tokens) {
        std::vector<std::vector<std::string>> pronunciations;
        if (const auto found = dictionary->find(lowercase(token)); found != dictionary->end()) {
            pronunciations = found->second;
        } else {
            auto phones = phonemesOf(token, options.espeakVoice);
            if (!phones)
                return phones.error();
            if (phones->empty())
                return makeError(ErrorCode::InvalidArgument, "The grammar's word " + inQuotes(token)
                                                                 + " is in no pronunciation dictionary, and espeak-ng cannot say it.");
            espeakPronounced.push_back(token + ": " + joined(*phones));
            pronunciations.push_back(std::move(*phones));
        }
        count[token] = pronunciations.size();
        for (std::size_t p = 0; p < pronunciations.size(); ++p) {
            const std::string name = p == 0 ? token : token + "(" + std::to_string(p + 1) + ")";
            if (auto added = decoder.addWord(name, joined(pronunciations[p])); !added)
                return added.error();
        }
    }
    return espeakPronounced;
}

// `graph` with an arc for each of its words' other pronunciations ("word(2)") beside the word's:
// pocketsphinx's own adding of them (-fsgusealtpron) walks every arc for every such word.
WordGraph withEveryPronunciation(const WordGraph& graph, const std::map<std::string, std::size_t>& count)
{
    WordGraph out = graph;
    std::vector<std::vector<int>> others(graph.words.size());
    for (std::size_t w = 0; w < graph.words.size(); ++w) {
        const auto found = count.find(graph.words[w]);
        for (std::size_t p = 2; found != count.end() && p <= found->second; ++p) {
            others[w].push_back(int(out.words.size()));
            out.words.push_back(graph.words[w] + "(" + std::to_string(p) + ")");
        }
    }
    for (const WordGraph::Arc& arc : graph.arcs)
        if (arc.word != WordGraph::kEmpty)
            for (const int other : others[std::size_t(arc.word)])
                out.arcs.push_back({arc.from, arc.to, other, arc.weight});
    return out;
}

// The acoustic score of frames [first, last] in `decoding`; a segment partly inside counts in
// proportion (the phone loop's segments do not end where the grammar's words do).
double scoreWithin(const SphinxDecoding& decoding, int first, int last)
{
    double total = 0;
    for (const SphinxSegment& segment : decoding.segments) {
        const int overlap = std::min(last, segment.lastFrame) - std::max(first, segment.firstFrame) + 1;
        if (overlap > 0)
            total += segment.acousticScore * overlap / (segment.lastFrame - segment.firstFrame + 1);
    }
    return total;
}

} // namespace

Result<std::vector<std::int16_t>> readRecording(const std::filesystem::path& path)
{
    auto sound = runtime::loadSound(path);
    if (!sound)
        return sound.error();
    return dithered16(resampled((*sound)->samples, (*sound)->rate, kSphinxRate));
}

Result<GrammarRecogniser> GrammarRecogniser::open(std::string_view jsgf, const RecogniserOptions& options)
{
    auto tokens = grammarTokens(jsgf);
    if (!tokens)
        return tokens.error();
    return open(std::move(*tokens), options,
                [&](SphinxDecoder& decoder, const Pronunciations&) { return decoder.addGrammar(kGrammarSearch, jsgf); });
}

Result<GrammarRecogniser> GrammarRecogniser::open(const WordGraph& graph, const RecogniserOptions& options)
{
    if (auto checked = checkWordGraph(graph); !checked)
        return checked.error();
    std::vector<std::string> tokens = graph.words;
    std::sort(tokens.begin(), tokens.end());
    tokens.erase(std::unique(tokens.begin(), tokens.end()), tokens.end());
    return open(std::move(tokens), options, [&](SphinxDecoder& decoder, const Pronunciations& count) {
        return decoder.addWordGraph(kGrammarSearch, withEveryPronunciation(graph, count));
    });
}

Result<GrammarRecogniser> GrammarRecogniser::open(std::vector<std::string> tokens, const RecogniserOptions& options,
                                                  const std::function<Result<void>(SphinxDecoder&, const Pronunciations&)>& addGrammar)
{
    auto grammar = SphinxDecoder::open(options.model, SphinxDecoder::Mode::Listen);
    if (!grammar)
        return grammar.error();
    Pronunciations count;
    auto espeakPronounced = addPronunciations(*grammar, tokens, options, count);
    if (!espeakPronounced)
        return espeakPronounced.error();
    grammar->setPruning(options.beam, options.wordBeam, options.maxActiveHmms);
    if (auto compiled = addGrammar(*grammar, count); !compiled)
        return compiled.error();
    auto phoneLoop = SphinxDecoder::open(options.model, SphinxDecoder::Mode::Listen);
    if (!phoneLoop)
        return phoneLoop.error();
    phoneLoop->setPruning(options.beam, options.wordBeam, options.maxActiveHmms);
    if (auto made = phoneLoop->addPhoneLoop(kPhoneLoopSearch); !made)
        return made.error();
    GrammarRecogniser recogniser(std::move(*grammar), std::move(*phoneLoop));
    recogniser.m_options = options;
    recogniser.m_words = std::move(tokens);
    recogniser.m_espeakPronounced = std::move(*espeakPronounced);
    return recogniser;
}

Result<Recognition> GrammarRecogniser::recognise(std::span<const std::int16_t> samples)
{
    if (auto started = start(); !started)
        return started.error();
    if (auto fed = feedBoth(samples, true); !fed)
        return fed.error();
    return finish();
}

Result<void> GrammarRecogniser::start()
{
    m_listening = false;
    if (auto started = m_grammar.startUtterance(kGrammarSearch); !started)
        return started;
    if (auto started = m_phoneLoop.startUtterance(kPhoneLoopSearch); !started)
        return started;
    m_listening = true;
    return {};
}

Result<void> GrammarRecogniser::feed(std::span<const std::int16_t> samples)
{
    return feedBoth(samples, false);
}

Result<void> GrammarRecogniser::feedBoth(std::span<const std::int16_t> samples, bool wholeUtterance)
{
    if (!m_listening)
        return makeError(ErrorCode::InvalidArgument, "The recogniser was given sound before start().");
    if (auto fed = m_grammar.feed(samples, wholeUtterance); !fed)
        return fed;
    return m_phoneLoop.feed(samples, wholeUtterance);
}

Result<Recognition> GrammarRecogniser::finish()
{
    if (!m_listening)
        return makeError(ErrorCode::InvalidArgument, "The recogniser was finished before start().");
    m_listening = false;
    auto heard = m_grammar.finishUtterance();
    if (!heard)
        return heard.error();
    auto phones = m_phoneLoop.finishUtterance();
    if (!phones)
        return phones.error();
    Recognition recognition;
    recognition.frames = heard->frames;
    int first = -1, last = -1; // the frames from the first word to the last: the speech
    for (const SphinxSegment& segment : heard->segments) {
        const std::string word = segment.word.substr(0, segment.word.find('(')); // "word(2)": its second pronunciation
        if (!std::binary_search(m_words.begin(), m_words.end(), word))
            continue; // a pause or a noise
        recognition.words.push_back({word, segment.firstFrame * kSphinxFrame, (segment.lastFrame + 1) * kSphinxFrame});
        recognition.text += (recognition.text.empty() ? "" : " ") + word;
        first = first < 0 ? segment.firstFrame : first;
        last = segment.lastFrame;
    }
    if (recognition.words.empty()) {
        recognition.confidence = -std::numeric_limits<double>::infinity();
        return recognition;
    }
    // Over the speech only: the pauses around it score alike on both paths and would water
    // the difference down by how long the microphone was open.
    recognition.confidence = (scoreWithin(*heard, first, last) - scoreWithin(*phones, first, last)) / (last - first + 1);
    recognition.verdict = recognition.confidence >= m_options.rejectBelow ? Recognition::Verdict::Understood
                                                                          : Recognition::Verdict::NotUnderstood;
    return recognition;
}

} // namespace thespis::core::speech
