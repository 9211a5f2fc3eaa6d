#pragma once
// Speech recognition restricted to a JSGF grammar (paper §5.3: the recogniser listens only for
// what the dialogue can answer), with rejection of what the grammar does not cover.
//
// Owns two pocketsphinx decoders fed the same samples: one follows the grammar, the other a
// free loop of the model's phones. pocketsphinx 5prealpha's posterior for a grammar's
// hypothesis is always 1, so the confidence is the difference of their acoustic
// log-likelihoods per frame: near 0 when the grammar's words explain the sound about as well
// as any phones do, far below 0 when the sound was something else, forced onto the grammar.
//
// The grammar's words are pronounced as pocketsphinx's dictionary (CMUdict) has them, matched
// without case; words it lacks are pronounced by espeak-ng (its phonemes mapped to ARPAbet) and
// listed. Grammars that import others are not taken (pocketsphinx cannot read them from text).

#include <cstdint>
#include <filesystem>
#include <functional>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "speech/sphinx_decoder.h"
#include "util/error.h"

namespace thespis::core::speech {

struct RecogniserOptions {
    SphinxModel model = SphinxModel::installed();
    std::string espeakVoice = "en-us"; ///< pronounces the words the dictionary lacks
    /// Confidence (natural log per frame) below which an utterance is not understood. Measured
    /// on pocketsphinx's real recordings: their own grammars −0.35 … +0.18, another's −3.2 … −3.1
    /// (or no path at all). espeak-ng's voices score about 1.5 lower even in the grammar: tune
    /// this on the microphone and voices the character will hear.
    double rejectBelow = -1.5;
    /// Pruning (SphinxDecoder::setPruning): the beams are pocketsphinx's defaults; the HMMs a
    /// frame keeps before they narrow are far fewer (its default 30 000), for grammars of
    /// thousands of sentences must be decoded faster than they are spoken. Measured
    /// (thespis-bench Recognition/*): Rosie's whole grammar decodes at 0.6–0.8 of real time
    /// against 2.5–3.2 with 30 000, a synthetic 12 000-pattern grammar at 0.64–0.75 against
    /// 1.16–1.24, hearing as many of its sentences exactly (17 of 40 against 18; 11 of 24
    /// both); the demo bot's inputs are heard as before (61 of 66).
    double beam = 1e-48, wordBeam = 7e-29;
    int maxActiveHmms = 1000;
};

struct HeardWord {
    std::string word;       ///< as the grammar spells it
    double start = 0, end = 0; ///< seconds from the utterance's first sample
};

struct Recognition {
    enum class Verdict {
        Understood,    ///< a sentence of the grammar, heard with enough confidence
        NotUnderstood, ///< nothing of the grammar fits (no path, no words, or confidence too low)
    };
    Verdict verdict = Verdict::NotUnderstood;
    std::string text;             ///< the grammar's sentence that fits best ("" when none does)
    std::vector<HeardWord> words; ///< its words in time order; pauses and noises left out
    double confidence = 0;        ///< grammar minus phone loop, natural log per frame (≤ about 0)
    int frames = 0;               ///< 10 ms frames heard

    bool understood() const { return verdict == Verdict::Understood; }
};

/// A recording (WAV, FLAC, OGG at any rate) as the samples recognise() takes. Errors name the file.
Result<std::vector<std::int16_t>> readRecording(const std::filesystem::path& path);

class GrammarRecogniser {
public:
    /// Opens the model and compiles `jsgf`. Errors: the model missing (naming Debian's
    /// pocketsphinx-en-us), the grammar unreadable (line and column) or importing others, a
    /// word neither the dictionary nor espeak-ng can pronounce, pocketsphinx failing to compile it.
    static Result<GrammarRecogniser> open(std::string_view jsgf, const RecogniserOptions& options = {});
    /// The same for a grammar given as a graph of words (word_graph.h): for grammars too large
    /// for pocketsphinx to compile from JSGF. Errors as above, and a graph that is not one.
    static Result<GrammarRecogniser> open(const WordGraph& graph, const RecogniserOptions& options = {});

    /// Words of the grammar the dictionary lacks, pronounced by espeak-ng: "word: AA B …".
    const std::vector<std::string>& espeakPronounced() const { return m_espeakPronounced; }

    /// One whole utterance (kSphinxRate, mono).
    Result<Recognition> recognise(std::span<const std::int16_t> samples);

    /// A live stream: start, feed blocks as they come, finish for the result.
    Result<void> start();
    Result<void> feed(std::span<const std::int16_t> samples);
    Result<Recognition> finish();

private:
    GrammarRecogniser(SphinxDecoder grammar, SphinxDecoder phoneLoop) : m_grammar(std::move(grammar)), m_phoneLoop(std::move(phoneLoop)) {}
    using Pronunciations = std::map<std::string, std::size_t>; ///< token → how many it has
    static Result<GrammarRecogniser> open(std::vector<std::string> tokens, const RecogniserOptions& options,
                                          const std::function<Result<void>(SphinxDecoder&, const Pronunciations&)>& addGrammar);
    Result<void> feedBoth(std::span<const std::int16_t> samples, bool wholeUtterance);

    SphinxDecoder m_grammar, m_phoneLoop;
    RecogniserOptions m_options;
    std::vector<std::string> m_words; ///< the grammar's tokens, sorted
    std::vector<std::string> m_espeakPronounced;
    bool m_listening = false;
};

} // namespace thespis::core::speech
