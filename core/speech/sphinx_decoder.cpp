#include "speech/sphinx_decoder.h"

#include <pocketsphinx.h>
#include <sphinxbase/err.h>
#include <sphinxbase/fsg_model.h>
#include <sphinxbase/glist.h>

#include <cassert>
#include <type_traits>

#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::speech {
namespace {

constexpr double kListeningWordInsertion = 0.1; // probability of one more word, see open()

constexpr const char* kMissingModel = "install Debian's pocketsphinx-en-us";

Result<void> checkExists(const std::filesystem::path& path, const std::string& what)
{
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        return makeError(ErrorCode::FileNotFound,
                         path.string() + ": pocketsphinx's " + what + " is missing; " + kMissingModel + ".");
    return {};
}

std::vector<std::string> splitWords(std::string_view text)
{
    std::vector<std::string> words;
    std::size_t at = 0;
    while (true) {
        at = text.find_first_not_of(" \t", at);
        if (at == std::string_view::npos)
            return words;
        const std::size_t end = std::min(text.find_first_of(" \t", at), text.size());
        words.emplace_back(text.substr(at, end - at));
        at = end;
    }
}

// pocketsphinx logs through one process-wide file, which -logfn would reopen (closing the one
// another decoder may be writing to) at every decoder made: instead it is off, once.
void silenceLog()
{
    static const bool silenced = (err_set_logfp(nullptr), true);
    (void)silenced;
}

} // namespace

SphinxModel SphinxModel::installed()
{
    const std::filesystem::path folder = "/usr/share/pocketsphinx/model/en-us";
    return {folder / "en-us", folder / "cmudict-en-us.dict", folder / "en-us.lm.bin"};
}

Result<std::map<std::string, std::vector<std::vector<std::string>>>>
readPronunciations(const std::filesystem::path& dictionary, const std::set<std::string, std::less<>>& words)
{
    if (auto exists = checkExists(dictionary, "pronunciation dictionary"); !exists)
        return exists.error();
    auto text = readTextFile(dictionary);
    if (!text)
        return text.error();
    std::map<std::string, std::vector<std::vector<std::string>>> found;
    std::string_view rest = *text;
    while (!rest.empty()) {
        const std::size_t newline = std::min(rest.find('\n'), rest.size());
        const std::string_view line = rest.substr(0, newline);
        rest.remove_prefix(std::min(newline + 1, rest.size()));
        const std::size_t space = line.find(' ');
        if (space == std::string_view::npos)
            continue;
        const std::string_view entry = line.substr(0, space);
        const std::string_view word = entry.substr(0, entry.find('('));
        if (const auto wanted = words.find(word); wanted != words.end())
            found[*wanted].push_back(splitWords(line.substr(space + 1)));
    }
    return found;
}

std::vector<std::array<float, 13>> sphinxCepstra(std::span<const std::int16_t> samples, int framesPerSecond)
{
    silenceLog();
    // The en-us model's filter bank (its feat.params).
    const std::string rate = std::to_string(framesPerSecond);
    cmd_ln_t* config = cmd_ln_init(nullptr, fe_get_args(), TRUE, "-samprate", "16000", "-frate", rate.c_str(),
                                   "-lowerf", "130", "-upperf", "6800", "-nfilt", "25", "-transform", "dct",
                                   "-lifter", "22", "-remove_silence", "no", nullptr);
    fe_t* fe = fe_init_auto_r(config); // owns the configuration
    assert(fe && fe_get_output_size(fe) == 13);
    int shift = 0, size = 0;
    fe_get_input_size(fe, &shift, &size);
    std::vector<std::array<float, 13>> cepstra;
    if (samples.size() >= std::size_t(size))
        cepstra.resize((samples.size() - std::size_t(size)) / std::size_t(shift) + 1);
    static_assert(std::is_same_v<mfcc_t, float>); // pocketsphinx built without fixed point
    std::vector<mfcc_t*> rows(cepstra.size());
    for (std::size_t i = 0; i < rows.size(); ++i)
        rows[i] = cepstra[i].data();
    const std::int16_t* next = samples.data();
    std::size_t left = samples.size();
    auto frames = std::int32_t(rows.size());
    fe_start_utt(fe);
    fe_process_frames(fe, &next, &left, rows.data(), &frames, nullptr);
    fe_free(fe);
    cepstra.resize(std::size_t(frames));
    return cepstra;
}

void SphinxDecoder::Free::operator()(ps_decoder_t* decoder) const
{
    ps_free(decoder);
}

Result<SphinxDecoder> SphinxDecoder::open(const SphinxModel& model, Mode mode)
{
    if (auto exists = checkExists(model.acousticModel, "acoustic model"); !exists)
        return exists.error();
    const std::string hmm = model.acousticModel.string(), dict = model.dictionary.string(),
                      lm = model.languageModel.string();
    if (mode == Mode::Recognise) {
        if (auto exists = checkExists(model.dictionary, "pronunciation dictionary"); !exists)
            return exists.error();
        if (auto exists = checkExists(model.languageModel, "language model"); !exists)
            return exists.error();
    }
    // Every frame is kept (-remove_silence no) so that frames are times. The pauses pocketsphinx
    // puts between a grammar's words by itself (-fsgusefiller) sometimes leave no path to the
    // grammar's end ("made a warm woollen"), so grammars name their pauses instead.
    silenceLog();
    cmd_ln_t* config = cmd_ln_init(nullptr, ps_args(), TRUE, "-hmm", hmm.c_str(), "-remove_silence", "no",
                                   "-fsgusefiller", mode == Mode::Listen ? "yes" : "no", nullptr);
    // Listening, a grammar's wildcard loops would otherwise fill pauses and noise with words
    // ("hello" heard as "hello are who"): each word costs more than pocketsphinx's default 0.65
    // (0.1: 52 of 66 of the demo bot's inputs spoken by espeak-ng heard exactly against 47; much
    // less leaves sentences without a path to the grammar's end).
    if (config && mode == Mode::Listen)
        cmd_ln_set_float_r(config, "-wip", kListeningWordInsertion);
    if (config && mode == Mode::Recognise) {
        cmd_ln_set_str_r(config, "-dict", dict.c_str());
        cmd_ln_set_str_r(config, "-lm", lm.c_str());
    }
    ps_decoder_t* decoder = config ? ps_init(config) : nullptr;
    cmd_ln_free_r(config); // the decoder keeps its own reference
    if (!decoder)
        return makeError(ErrorCode::CorruptData, hmm + ": pocketsphinx could not load its model; " + kMissingModel + ".");
    SphinxDecoder opened(decoder);
    if (mode == Mode::Recognise)
        opened.m_languageModelSearch = ps_get_search(decoder);
    return opened;
}

Result<void> SphinxDecoder::addWord(const std::string& name, const std::string& phones)
{
    if (ps_add_word(m_decoder.get(), name.c_str(), phones.c_str(), FALSE) < 0)
        return makeError(ErrorCode::InvalidArgument,
                         "pocketsphinx's model cannot say " + inQuotes(phones) + " (for " + inQuotes(name) + ").");
    return {};
}

Result<std::vector<SphinxSegment>> SphinxDecoder::decodeGrammar(std::string_view jsgf,
                                                                std::span<const std::int16_t> samples, bool wideBeams)
{
    setPruning(wideBeams ? 1e-80 : 1e-48, wideBeams ? 1e-60 : 7e-29, 30000);
    if (auto added = addGrammar("grammar", jsgf); !added)
        return added.error();
    return decode("grammar", samples);
}

Result<std::vector<SphinxSegment>> SphinxDecoder::recognise(std::span<const std::int16_t> samples)
{
    assert(!m_languageModelSearch.empty()); // opened to recognise
    return decode(m_languageModelSearch, samples);
}

void SphinxDecoder::setPruning(double beam, double wordBeam, int maxActiveHmms)
{
    // A search reads these from the configuration when it is made.
    cmd_ln_t* config = ps_get_config(m_decoder.get());
    cmd_ln_set_float_r(config, "-beam", beam);
    cmd_ln_set_float_r(config, "-pbeam", beam);
    cmd_ln_set_float_r(config, "-wbeam", wordBeam);
    cmd_ln_set_int_r(config, "-maxhmmpf", maxActiveHmms);
}

Result<void> SphinxDecoder::addGrammar(const std::string& name, std::string_view jsgf)
{
    const std::string grammar(jsgf);
    if (ps_set_jsgf_string(m_decoder.get(), name.c_str(), grammar.c_str()) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not compile a grammar.", grammar.substr(0, 4096));
    return {};
}

Result<void> SphinxDecoder::addWordGraph(const std::string& name, const WordGraph& graph)
{
    if (auto checked = checkWordGraph(graph); !checked)
        return checked;
    ps_decoder_t* ps = m_decoder.get();
    logmath_t* logmath = ps_get_logmath(ps);
    const float languageWeight = cmd_ln_float32_r(ps_get_config(ps), "-lw");
    fsg_model_t* fsg = fsg_model_init(name.c_str(), logmath, languageWeight, graph.states);
    fsg->start_state = graph.start;
    fsg->final_state = graph.end;
    std::vector<int> wordIds;
    wordIds.reserve(graph.words.size());
    for (const std::string& word : graph.words)
        wordIds.push_back(fsg_model_word_add(fsg, word.c_str()));
    for (const WordGraph::Arc& arc : graph.arcs) {
        // As pocketsphinx reads a grammar file's probabilities: scaled by the language weight.
        const auto logp = std::int32_t(logmath_log(logmath, arc.weight) * languageWeight);
        if (arc.word == WordGraph::kEmpty)
            fsg_model_null_trans_add(fsg, arc.from, arc.to, logp);
        else
            fsg_model_trans_add(fsg, arc.from, arc.to, logp, wordIds[std::size_t(arc.word)]);
    }
    // The search follows one empty arc at a time: it needs every chain of them as one arc.
    glist_free(fsg_model_null_trans_closure(fsg, nullptr));
    // The graph says every pronunciation it wants: pocketsphinx adding the others would walk
    // every arc for each word that has some.
    cmd_ln_t* config = ps_get_config(ps);
    const bool alternatives = cmd_ln_boolean_r(config, "-fsgusealtpron");
    cmd_ln_set_boolean_r(config, "-fsgusealtpron", FALSE);
    const int added = ps_set_fsg(ps, name.c_str(), fsg);
    cmd_ln_set_boolean_r(config, "-fsgusealtpron", alternatives ? TRUE : FALSE);
    fsg_model_free(fsg); // the search keeps its own reference
    if (added < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not take a grammar of " + std::to_string(graph.states)
                                                  + " states and " + std::to_string(graph.arcs.size()) + " arcs.");
    return {};
}

Result<void> SphinxDecoder::addPhoneLoop(const std::string& name)
{
    // Context-independent phones: a few dozen models instead of every triphone, and fast.
    cmd_ln_set_boolean_r(ps_get_config(m_decoder.get()), "-allphone_ci", TRUE);
    if (ps_set_allphone(m_decoder.get(), name.c_str(), nullptr) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not make its phone loop.");
    return {};
}

Result<void> SphinxDecoder::startUtterance(const std::string& search)
{
    ps_decoder_t* ps = m_decoder.get();
    if (ps_set_search(ps, search.c_str()) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx has no search " + inQuotes(search) + ".");
    if (ps_start_utt(ps) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not start an utterance.");
    return {};
}

Result<void> SphinxDecoder::feed(std::span<const std::int16_t> samples, bool wholeUtterance)
{
    if (ps_process_raw(m_decoder.get(), samples.data(), samples.size(), FALSE, wholeUtterance ? TRUE : FALSE) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not decode the audio.");
    return {};
}

Result<SphinxDecoding> SphinxDecoder::finishUtterance()
{
    ps_decoder_t* ps = m_decoder.get();
    if (ps_end_utt(ps) < 0)
        return makeError(ErrorCode::Internal, "pocketsphinx could not finish decoding the audio.");
    SphinxDecoding decoding;
    decoding.frames = ps_get_n_frames(ps);
    std::int32_t score = 0;
    if (!ps_get_hyp(ps, &score))
        return decoding;
    // Acoustic scores are logmath values shifted right by 10 bits (SENSCR_SHIFT in hmm.h).
    logmath_t* logmath = ps_get_logmath(ps);
    for (ps_seg_t* seg = ps_seg_iter(ps); seg; seg = ps_seg_next(seg)) {
        const char* word = ps_seg_word(seg);
        if (!word || std::string_view(word) == "(NULL)") // an empty transition of the grammar
            continue;
        SphinxSegment segment{word, 0, 0, 0};
        ps_seg_frames(seg, &segment.firstFrame, &segment.lastFrame);
        std::int32_t acoustic = 0, language = 0, backoff = 0;
        ps_seg_prob(seg, &acoustic, &language, &backoff);
        segment.acousticScore = logmath_log_to_ln(logmath, acoustic) * 1024.0;
        decoding.segments.push_back(std::move(segment));
    }
    return decoding;
}

Result<std::vector<SphinxSegment>> SphinxDecoder::decode(const std::string& search, std::span<const std::int16_t> samples)
{
    // One call with the whole utterance: pocketsphinx then normalises the cepstra over all of
    // it (batch CMN) instead of adapting from its initial estimate as it goes.
    if (auto started = startUtterance(search); !started)
        return started.error();
    if (auto fed = feed(samples, true); !fed)
        return fed.error();
    auto decoding = finishUtterance();
    if (!decoding)
        return decoding.error();
    return std::move(decoding->segments);
}

} // namespace thespis::core::speech
