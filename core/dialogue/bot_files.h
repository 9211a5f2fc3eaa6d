#pragma once
// Readers of a bot's data files besides AIML (Rosie's and Pandorabots' layout): sets, maps,
// substitutions and properties. Each is either JSON-ish, `[["a","b"], ...]` (what Rosie ships),
// or one entry a line: a set's phrase, `key:value` for maps and properties, `"from","to"` or
// `from:to` for substitutions. Bad entries are reported with their line and skipped.

#include <map>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "dialogue/aiml.h"

namespace thespis::core::dialogue {

/// A set of phrases a pattern's <set>name</set> matches.
struct PhraseSet {
    std::vector<std::string> phrases;          ///< as the file wrote them (words joined by a space)
    std::unordered_set<std::string> matchKeys; ///< the phrases as input is matched: upper case, no punctuation
    int longestWords = 0;                      ///< the most words in one phrase
    void add(std::string phrase);
};

/// A map's pairs; keys in match form (upper case) so <map> finds "new york" under "NEW YORK".
using PhraseMap = std::map<std::string, std::string>;

/// Pairs in file order (substitutions are tried in that order).
using Pairs = std::vector<std::pair<std::string, std::string>>;

PhraseSet readSet(std::string_view text, const std::string& file, std::vector<LoadProblem>& problems);
/// The pairs of a map, properties or substitution file, in file order.
Pairs readPairs(std::string_view text, const std::string& file, std::vector<LoadProblem>& problems);

} // namespace thespis::core::dialogue
