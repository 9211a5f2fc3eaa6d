#pragma once
// What the character listens for (paper §5.3): a JSGF grammar made from what the dialogue can
// answer, so that the recogniser hears only sentences the bot has a reply for.
//
// The source is neutral (no AIML here): each pattern's literal form, the sets patterns name, and
// the words a wildcard may stand for. The grammar has one public rule, <utterance> (pocketsphinx
// listens for a grammar's first public rule only), whose patterns share their common beginnings
// (a tree: "what is" is written once for every pattern that starts so), because pocketsphinx
// copies a rule's arcs at every reference and a flat list of ten thousand patterns each with its
// own wildcard loop does not fit. Wildcards are <any> = <word> [<any>] (one loop, written so
// that pocketsphinx copies the word list once per wildcard); the wildcards that end patterns
// share one copy ("(what is | tell me about) <any>"), those that start them share the tree's
// first branch. The loop has at most `maxWildcardWords` words: the vocabulary's words that the
// patterns and sets use most, then the vocabulary's order. Every other wildcard costs a copy of
// its loop, so those inside patterns are <few>: the first `maxInnerWildcardWords` of them.
//
// The recogniser listens with the same language as a word graph (speech/word_graph.h) in which
// patterns share their endings as well as their beginnings, and each wildcard's loop and each
// set is one copy for all the patterns that go on alike after it: pocketsphinx's own
// compilation of the JSGF copies every reference and makes millions of arcs of a large bot.
//
// Words are made speakable: lower case ASCII; numbers spelled ("42" → "forty two"); accented
// Latin letters without their accents ("café" → "cafe"); punctuation splits words (apostrophes
// between letters stay: "don't"); anything else is dropped. Each token changed or dropped is
// reported once; a pattern left with nothing to say is skipped and reported.

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "speech/word_graph.h"
#include "util/error.h"

namespace thespis::core::dialogue {

struct PatternItem {
    enum class Kind { Word, OneOrMore, ZeroOrMore, SetOf };
    Kind kind = Kind::Word;
    std::string word; ///< Word: the word as written (made speakable here)
    std::string set;  ///< SetOf: the set's name (a key of GrammarSource::sets)
};

struct GrammarSource {
    std::vector<std::vector<PatternItem>> patterns;                     ///< each pattern's literal form
    std::map<std::string, std::vector<std::vector<std::string>>> sets; ///< set name → its phrases (words)
    std::vector<std::string> vocabulary;                               ///< words a wildcard may stand for
};

struct ListeningOptions {
    std::string grammarName = "listening";
    /// Words in the wildcard loop; more make the grammar slower to compile and to decode.
    std::size_t maxWildcardWords = 2000;
    /// Words in the loop of wildcards inside patterns (each is a copy of it in pocketsphinx).
    std::size_t maxInnerWildcardWords = 50;
    /// Probability of each word a wildcard hears, against 1 for a pattern's own words: below 1
    /// the recogniser prefers a pattern's words to a wildcard's when both fit the sound.
    float wildcardWordWeight = 0.01f;
};

struct ListeningGrammar {
    std::string jsgf;                       ///< JSGF V1.0, public rule <utterance>: for people
    /// The same language as a word graph: what the recogniser listens with (JSGF this large
    /// takes pocketsphinx minutes and gigabytes to compile).
    speech::WordGraph graph;
    std::vector<std::string> words;         ///< every word it uses, sorted
    std::vector<std::string> wildcardWords; ///< the words of <any>, most used first
    std::size_t wildcardWordsLeftOut = 0;   ///< vocabulary words the cap left out
    std::vector<std::string> innerWildcardWords; ///< the words of <few> (wildcards inside patterns)
    std::size_t patternsUsed = 0, patternsSkipped = 0;
    std::vector<std::string> notes;         ///< for people: tokens spelled or dropped, patterns skipped
};

/// The grammar for `source`. Error (InvalidArgument): no pattern has anything to say.
Result<ListeningGrammar> makeListeningGrammar(const GrammarSource& source, const ListeningOptions& options = {});

/// `token` as words a recogniser can hear (see above); what was dropped is appended to
/// `dropped` when given.
std::vector<std::string> speakableWords(std::string_view token, std::string* dropped = nullptr);

} // namespace thespis::core::dialogue
