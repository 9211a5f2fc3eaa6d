#pragma once
// pocketsphinx 5prealpha (Debian libpocketsphinx-dev) with its en-us model (pocketsphinx-en-us):
// decodes 16 kHz speech against a JSGF grammar — forced alignment when the grammar is one
// sentence — or, for recognition, against the en-us language model. Owns one decoder.
//
// Every frame of the audio is decoded (pocketsphinx's own silence removal is off), so frame n
// starts n·10 ms after the audio does. Digital silence (synthesised pauses) must come dithered:
// a frame of zeros has no log energy. pocketsphinx's own dither is off, for its random
// generator is one for the whole process, shared by decoders working at once. pocketsphinx's
// log is off. A decoder is used by one thread at a time; several may work at once.

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "speech/word_graph.h"
#include "util/error.h"

struct ps_decoder_s; // pocketsphinx.h

namespace thespis::core::speech {

inline constexpr int kSphinxRate = 16000;       ///< samples per second pocketsphinx hears
inline constexpr double kSphinxFrame = 0.010;   ///< seconds from one frame to the next

/// Where the model's files are.
struct SphinxModel {
    std::filesystem::path acousticModel;  ///< folder: mdef, means, …
    std::filesystem::path dictionary;     ///< CMUdict: "word(2) P H O N E S", lower-case words
    std::filesystem::path languageModel;  ///< for recognition
    /// The model Debian's pocketsphinx-en-us installs.
    static SphinxModel installed();
};

/// word → its pronunciations in `dictionary` (ARPAbet), in the file's order ("word", "word(2)",
/// …), for the words asked for (lower case) that it has. Errors: the file cannot be read.
Result<std::map<std::string, std::vector<std::vector<std::string>>>>
readPronunciations(const std::filesystem::path& dictionary, const std::set<std::string, std::less<>>& words);

/// pocketsphinx's cepstra (the model's 13 MFCCs: 25.6 ms windows) of `samples` (kSphinxRate),
/// one every 1/`framesPerSecond` s: frame n's window starts at n/`framesPerSecond` s.
std::vector<std::array<float, 13>> sphinxCepstra(std::span<const std::int16_t> samples, int framesPerSecond);
inline constexpr double kSphinxWindow = 0.0256; ///< seconds of sound in one frame

/// One word of a decoding: as the grammar or dictionary names it ("w3(2)", "<sil>", "[NOISE]").
struct SphinxSegment {
    std::string word;
    int firstFrame = 0, lastFrame = 0; ///< inclusive
    double acousticScore = 0;          ///< log-likelihood of its frames under the model (natural log)
};

/// What one utterance decoded to: its words in time order (empty when no path reached the
/// search's end) and how many frames were heard.
struct SphinxDecoding {
    std::vector<SphinxSegment> segments;
    int frames = 0;
};

class SphinxDecoder {
public:
    /// Align: only the words added (and the model's noise words); Recognise: the model's
    /// dictionary and language model (slower to open: about a second); Listen: only the words
    /// added, and a grammar's words may have pauses and the model's noises between and around
    /// them (pocketsphinx's -fsgusefiller), as people's speech has.
    enum class Mode { Align, Recognise, Listen };
    /// Errors: the model's files are missing (naming them and the package) or do not load.
    static Result<SphinxDecoder> open(const SphinxModel& model, Mode mode);

    /// Adds `name` pronounced `phones` (ARPAbet, separated by spaces); "name(2)" adds a second
    /// pronunciation. Error: a phone the model lacks.
    Result<void> addWord(const std::string& name, const std::string& phones);

    /// Decodes `samples` (kSphinxRate) as the one sentence of the JSGF grammar `jsgf`, with
    /// pocketsphinx's default beams or (`wideBeams`) beams that keep far more paths, for what the
    /// default loses. Pauses come only where the grammar has words for them (pronounced "SIL").
    /// The words in time order; empty when no path reaches the grammar's end. Error: the grammar
    /// does not compile.
    Result<std::vector<SphinxSegment>> decodeGrammar(std::string_view jsgf, std::span<const std::int16_t> samples,
                                                     bool wideBeams);
    /// Recognises `samples` with the language model (Recognise mode only): the words in time order.
    Result<std::vector<SphinxSegment>> recognise(std::span<const std::int16_t> samples);

    /// Pruning for the searches added from now on: the beams (pocketsphinx's -beam and -pbeam,
    /// -wbeam: relative to the best path, smaller keeps more) and how many HMMs a frame may keep
    /// active before the beams narrow (-maxhmmpf).
    void setPruning(double beam, double wordBeam, int maxActiveHmms);
    /// Compiles the JSGF grammar `jsgf` (its first public rule, as pocketsphinx takes it) as the
    /// search `name`, with the current beams. Error: it does not compile (a word not added, …).
    Result<void> addGrammar(const std::string& name, std::string_view jsgf);
    /// The same for a grammar given as a graph of words (every word added), which has an arc for
    /// each pronunciation it listens for ("word(2)": only where the graph says it). Errors: the
    /// graph is not one (an arc off its states, a weight outside (0, 1]), pocketsphinx does not
    /// take it.
    Result<void> addWordGraph(const std::string& name, const WordGraph& graph);
    /// Adds the search `name` that hears any sequence of the model's context-independent phones:
    /// the best the model can say of any sound, to compare a grammar's path with.
    Result<void> addPhoneLoop(const std::string& name);

    /// An utterance decoded as it comes (a microphone): startUtterance, feed as often as samples
    /// arrive (kSphinxRate), finishUtterance. `wholeUtterance` when one feed holds all of it:
    /// the cepstra are then normalised over all of it. Error: no search `search`.
    Result<void> startUtterance(const std::string& search);
    Result<void> feed(std::span<const std::int16_t> samples, bool wholeUtterance = false);
    Result<SphinxDecoding> finishUtterance();

private:
    struct Free { void operator()(::ps_decoder_s* decoder) const; };
    explicit SphinxDecoder(::ps_decoder_s* decoder) : m_decoder(decoder) {}
    Result<std::vector<SphinxSegment>> decode(const std::string& search, std::span<const std::int16_t> samples);

    std::unique_ptr<::ps_decoder_s, Free> m_decoder;
    std::string m_languageModelSearch; ///< the search opened with the language model (Recognise)
};

} // namespace thespis::core::speech
