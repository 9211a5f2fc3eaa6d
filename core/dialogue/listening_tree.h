#pragma once
// The listening grammar's patterns as trees of steps, as listening_grammar.cpp collects them:
// written there as JSGF for people and the grammar inspector, and here as the word graph the
// recogniser listens with (listening_graph.cpp).

#include <map>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "speech/word_graph.h"

namespace thespis::core::dialogue::listening {

// One step of a pattern. A wildcard is a step only where it begins a pattern, a set only where
// it ends one: the others are said by where the tree holding the pattern leads (see Forest).
enum class Step { Word, Set, Any, MaybeAny };
using Key = std::pair<Step, std::string>; ///< the word, or the set's rule name

struct Node {
    std::map<Key, std::unique_ptr<Node>> children;
    bool end = false; ///< a pattern (or its part) ends here
};

// Patterns, or what follows a split in them, as trees by what comes after them: nothing, a
// wildcard that ends them (<any>, [<any>]), an inner wildcard (<few>, [<few>]) and then what
// follows an inner wildcard in any pattern (the tails), or a set inside them and then what
// follows that set inside any pattern. Splitting patterns there lets one copy of a word loop or
// of a set serve them all: a copy per continuation made Rosie's grammar (22 673 names in her
// set of names alone) hundreds of thousands of arcs and minutes to open. The price: after an
// inner wildcard or set the recogniser accepts the rest of any pattern that has one there.
struct Forest {
    Node plain, thenAny, thenMaybeAny, thenFew, thenMaybeFew;
    std::map<std::string, Node> thenSet; ///< set rule → the patterns' beginnings before it
};

struct Trees {
    Forest utterance; ///< the patterns up to their first split
    Forest tails;     ///< what follows an inner wildcard, up to the next split
    std::map<std::string, Forest> setTails; ///< set rule → what follows it inside patterns
    std::vector<std::string> anyWords, fewWords;               ///< the words of the two loops
    std::map<std::string, std::vector<std::string>> setPhrases; ///< rule name → phrases ("new york")
    float wildcardWordWeight = 1;                              ///< probability of each word a wildcard hears
};

/// The language of `trees` as a small word graph: patterns that end alike share their endings
/// as they share their beginnings, and each word loop or set is one copy for all the steps that
/// lead through it to the same place.
speech::WordGraph wordGraphOf(const Trees& trees);

} // namespace thespis::core::dialogue::listening
