#pragma once
// A dialogue's grammar source the size of a large AIML bot (Rosie: about 12 000 patterns over a
// few thousand words), made the same way every time from CMUdict's words, for the tests and
// the benchmark of core/dialogue/listening_grammar.h.

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>
#include <string>
#include <vector>

#include "dialogue/listening_grammar.h"

namespace thespis::test {

/// `vocabularySize` words of plain letters from `dictionary` (CMUdict) chosen by a seeded
/// generator; patterns of 1–6 items whose words are drawn with a Zipf-like bias (a few words
/// start many patterns, as "what", "do you" do in AIML); a quarter end in a one-or-more
/// wildcard, one in twenty starts with one, one in twenty has one after its first word, one in
/// thirty names one of three sets.
inline core::dialogue::GrammarSource largeGrammarSource(const std::string& dictionary, std::size_t patternCount,
                                                        std::size_t vocabularySize)
{
    using core::dialogue::PatternItem;
    std::vector<std::string> all;
    std::ifstream in(dictionary);
    for (std::string line; std::getline(in, line);) {
        const std::string word = line.substr(0, line.find(' '));
        if (word.size() >= 2 && std::all_of(word.begin(), word.end(), [](char c) { return c >= 'a' && c <= 'z'; }))
            all.push_back(word);
    }
    std::mt19937 random(20070101);
    std::shuffle(all.begin(), all.end(), random);
    all.resize(std::min(all.size(), vocabularySize));
    core::dialogue::GrammarSource source;
    source.vocabulary = all;
    if (all.empty())
        return source;
    const auto setWords = [&](std::size_t first, std::size_t count) {
        std::vector<std::vector<std::string>> phrases;
        for (std::size_t i = 0; i < count; ++i)
            phrases.push_back({all[(first + i) % all.size()]});
        phrases.push_back({all[first % all.size()], all[(first + 1) % all.size()]});
        return phrases;
    };
    source.sets["colour"] = setWords(100, 8);
    source.sets["city"] = setWords(200, 20);
    source.sets["name"] = setWords(300, 12);
    const std::vector<std::string> setNames = {"colour", "city", "name"};
    // Zipf-like: index = floor(n · u^3) favours the first words strongly.
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto zipfWord = [&] { return all[std::size_t(double(all.size()) * std::pow(unit(random), 3.0)) % all.size()]; };
    std::uniform_int_distribution<int> length(1, 6), percent(0, 99);
    for (std::size_t p = 0; p < patternCount; ++p) {
        std::vector<PatternItem> pattern;
        if (percent(random) < 5)
            pattern.push_back({PatternItem::Kind::OneOrMore, "", ""});
        const int words = length(random);
        const bool wildMiddle = words >= 2 && percent(random) < 5;
        for (int w = 0; w < words; ++w) {
            if (wildMiddle && w == 1)
                pattern.push_back({PatternItem::Kind::OneOrMore, "", ""});
            pattern.push_back({PatternItem::Kind::Word, zipfWord(), ""});
        }
        if (percent(random) < 3)
            pattern.push_back({PatternItem::Kind::SetOf, "", setNames[std::size_t(percent(random)) % setNames.size()]});
        if (percent(random) < 25)
            pattern.push_back({PatternItem::Kind::OneOrMore, "", ""});
        source.patterns.push_back(std::move(pattern));
    }
    return source;
}

/// The words a pattern's literal form says: each wildcard as `wildcardWords` (one or more), each set as its first phrase.
inline std::vector<std::string> literalForm(const core::dialogue::GrammarSource& source,
                                            const std::vector<core::dialogue::PatternItem>& pattern,
                                            const std::string& wildcardWords)
{
    using Kind = core::dialogue::PatternItem::Kind;
    std::vector<std::string> words;
    for (const auto& item : pattern) {
        if (item.kind == Kind::Word) {
            for (std::string& w : core::dialogue::speakableWords(item.word))
                words.push_back(std::move(w));
        } else if (item.kind == Kind::OneOrMore) {
            for (std::string& w : core::dialogue::speakableWords(wildcardWords))
                words.push_back(std::move(w));
        } else if (item.kind == Kind::SetOf) {
            for (const std::string& w : source.sets.at(item.set).front())
                for (std::string& said : core::dialogue::speakableWords(w))
                    words.push_back(std::move(said));
        }
    }
    return words;
}

} // namespace thespis::test
