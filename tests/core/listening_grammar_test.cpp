// The grammar the character listens for, made from what the dialogue can answer
// (core/dialogue/listening_grammar.h), read back with the JSGF reader and compiled by pocketsphinx.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <iostream>

#include "dialogue/listening_grammar.h"
#include "listening_source.h"
#include "speech/jsgf.h"
#include "speech/sphinx_decoder.h"
#include "test_support.h"
#include "util/text.h"

namespace dialogue = thespis::core::dialogue;
namespace speech = thespis::core::speech;
using Kind = dialogue::PatternItem::Kind;
using thespis::core::ErrorCode;

namespace {

dialogue::PatternItem word(const std::string& w) { return {Kind::Word, w, ""}; }
dialogue::PatternItem star() { return {Kind::OneOrMore, "", ""}; }
dialogue::PatternItem maybeStar() { return {Kind::ZeroOrMore, "", ""}; }
dialogue::PatternItem set(const std::string& name) { return {Kind::SetOf, "", name}; }

std::vector<std::string> words(const std::string& text)
{
    std::vector<std::string> out;
    std::istringstream in(text);
    for (std::string w; in >> w;)
        out.push_back(w);
    return out;
}

speech::JsgfSet readBack(const dialogue::ListeningGrammar& grammar)
{
    auto parsed = speech::parseJsgf(grammar.jsgf);
    EXPECT_TRUE(parsed) << (parsed ? "" : describe(parsed.error())) << "\n" << grammar.jsgf;
    if (!parsed)
        return {};
    auto set = speech::resolveJsgf(std::move(*parsed), {});
    EXPECT_TRUE(set) << (set ? "" : describe(set.error()));
    return set ? *set : speech::JsgfSet{};
}

dialogue::GrammarSource smallSource()
{
    dialogue::GrammarSource source;
    source.patterns = {
        {word("what"), word("is"), word("your"), word("name")},
        {word("what"), word("is"), star()},
        {word("what"), word("is"), word("your"), word("favourite"), set("thing")},
        {word("my"), word("name"), word("is"), star()},
        {word("hello")},
        {word("hello"), word("there")},
        {maybeStar(), word("thank"), word("you"), maybeStar()},
        {star(), word("is"), word("nice")},
        {word("is"), star(), word("here")},
    };
    source.sets["thing"] = {{"colour"}, {"ice", "cream"}};
    source.vocabulary = {"anna", "bob", "the", "weather", "nice", "colour"};
    return source;
}

} // namespace

TEST(ListeningGrammar, AcceptsEveryPatternsLiteralFormAndLittleElse)
{
    const dialogue::GrammarSource source = smallSource();
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    EXPECT_EQ(grammar->patternsUsed, source.patterns.size());
    EXPECT_EQ(grammar->patternsSkipped, 0u);
    const speech::JsgfSet set = readBack(*grammar);
    const speech::WordGraph& graph = grammar->graph;
    // The JSGF text and the word graph the recogniser listens with say the same language.
    const auto accepts = [&](const std::vector<std::string>& sentence) {
        const bool inJsgf = set.accepts(sentence);
        EXPECT_EQ(graph.accepts(sentence), inJsgf) << thespis::core::joined(sentence);
        return inJsgf;
    };
    for (const auto& pattern : source.patterns) {
        EXPECT_TRUE(accepts(thespis::test::literalForm(source, pattern, "bob"))) << grammar->jsgf;
        EXPECT_TRUE(accepts(thespis::test::literalForm(source, pattern, "the weather")));
    }
    EXPECT_TRUE(accepts(words("what is your favourite ice cream")));
    EXPECT_TRUE(accepts(words("what is your favourite colour")));
    EXPECT_TRUE(accepts(words("thank you")));
    EXPECT_TRUE(accepts(words("bob thank you anna")));
    EXPECT_TRUE(accepts(words("bob anna thank you")));
    EXPECT_FALSE(accepts(words("what is")));
    EXPECT_FALSE(accepts(words("what is your favourite ice")));
    EXPECT_FALSE(accepts(words("hello bob")));
    EXPECT_FALSE(accepts(words("what is zebra")));
    EXPECT_FALSE(accepts(words("is nice")));
    EXPECT_FALSE(accepts(words("thank")));
    EXPECT_FALSE(accepts(words("hello there there")));
    EXPECT_TRUE(accepts(words("is anna bob here")));
    EXPECT_TRUE(accepts(words("anna bob is nice")));
    // Patterns that end alike share their ending: "what is your name" and "my name is bob" end
    // in one state; the graph has far fewer states than the patterns have words.
    EXPECT_LT(graph.states, 40);
    EXPECT_NE(grammar->jsgf.find("is <few> <tails>"), std::string::npos) << grammar->jsgf;
    EXPECT_NE(grammar->jsgf.find("<tails> =\n    here;"), std::string::npos) << grammar->jsgf;
    // One public rule; shared beginnings, and one loop for the wildcards that end patterns.
    EXPECT_EQ(set.grammars[0].publicRules().size(), 1u);
    EXPECT_NE(grammar->jsgf.find("| what is your (favourite <set_thing> | name)\n"), std::string::npos) << grammar->jsgf;
    EXPECT_NE(grammar->jsgf.find("| (my name is | what is) <any>\n"), std::string::npos) << grammar->jsgf;
    EXPECT_EQ(grammar->words, (std::vector<std::string>{"anna", "bob", "colour", "cream", "favourite", "hello", "here", "ice",
                                                        "is", "my", "name", "nice", "thank", "the", "there", "weather",
                                                        "what", "you", "your"}));
}

TEST(ListeningGrammar, InnerWildcardsShareOneWordLoopAndWhatFollowsThem)
{
    dialogue::GrammarSource source;
    source.patterns = {{word("is"), star(), word("here")},
                       {word("where"), star(), word("go"), star(), word("now")},
                       {word("tell"), maybeStar(), word("me")}};
    source.vocabulary = {"bob", "anna"};
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    const speech::JsgfSet set = readBack(*grammar);
    const speech::WordGraphWalker graph(grammar->graph);
    for (const char* sentence : {"is bob here", "where anna go bob now", "where bob anna go bob now", "tell me", "tell anna me",
                                 "is bob go anna now", "where bob here"}) {
        EXPECT_TRUE(set.accepts(words(sentence))) << sentence << "\n" << grammar->jsgf;
        EXPECT_TRUE(graph.accepts(words(sentence))) << sentence;
    }
    for (const char* sentence : {"is here", "where go now", "where bob go now", "tell", "is bob", "bob here"}) {
        EXPECT_FALSE(set.accepts(words(sentence))) << sentence << "\n" << grammar->jsgf;
        EXPECT_FALSE(graph.accepts(words(sentence))) << sentence;
    }
    // One copy of the inner wildcards' loop for the three patterns: each of its words is one arc.
    const auto arcsSaying = [&](const std::string& w) {
        const auto id = std::find(grammar->graph.words.begin(), grammar->graph.words.end(), w) - grammar->graph.words.begin();
        return std::count_if(grammar->graph.arcs.begin(), grammar->graph.arcs.end(), [&](const auto& arc) { return arc.word == id; });
    };
    EXPECT_EQ(arcsSaying("bob"), 1);
    EXPECT_EQ(arcsSaying("anna"), 1);
}

TEST(ListeningGrammar, MakesTokensSpeakableAndSaysWhatChanged)
{
    EXPECT_EQ(dialogue::speakableWords("42"), words("forty two"));
    EXPECT_EQ(dialogue::speakableWords("2001"), words("two thousand one"));
    EXPECT_EQ(dialogue::speakableWords("310"), words("three hundred ten"));
    EXPECT_EQ(dialogue::speakableWords("007"), words("zero zero seven"));
    EXPECT_EQ(dialogue::speakableWords("R2D2"), words("r two d two"));
    EXPECT_EQ(dialogue::speakableWords("Café"), words("cafe"));
    EXPECT_EQ(dialogue::speakableWords("x-ray"), words("x ray"));
    EXPECT_EQ(dialogue::speakableWords("don't"), words("don't"));
    EXPECT_EQ(dialogue::speakableWords("don\xE2\x80\x99t"), words("don't"));
    EXPECT_EQ(dialogue::speakableWords("'quoted'"), words("quoted"));
    std::string dropped;
    EXPECT_TRUE(dialogue::speakableWords("\xE2\x82\xAC", &dropped).empty()); // €
    EXPECT_EQ(dropped, "\xE2\x82\xAC");

    dialogue::GrammarSource source;
    source.patterns = {{word("I"), word("am"), word("42")}, {word("\xE2\x82\xAC")}, {word("HELLO"), word("Zoë!")}};
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    EXPECT_EQ(grammar->patternsUsed, 2u);
    EXPECT_EQ(grammar->patternsSkipped, 1u);
    std::string notes;
    for (const std::string& note : grammar->notes)
        notes += note + "\n";
    EXPECT_NE(notes.find("\"42\" is listened for as \"forty two\""), std::string::npos) << notes;
    EXPECT_NE(notes.find("\"Zoë!\" is listened for as \"zoe\" (\"!\" left out)"), std::string::npos) << notes;
    EXPECT_NE(notes.find("Pattern 2 is left out"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("HELLO"), std::string::npos) << notes; // case alone is no change
    const speech::JsgfSet set = readBack(*grammar);
    EXPECT_TRUE(set.accepts(words("i am forty two")));
    EXPECT_TRUE(set.accepts(words("hello zoe")));
}

TEST(ListeningGrammar, CapsTheWildcardLoopToTheMostUsedWords)
{
    dialogue::GrammarSource source;
    source.patterns = {{word("say"), star()}, {word("apple"), word("pie")}, {word("pie")}, {word("cherry"), word("pie")}};
    source.vocabulary = {"zebra", "apple", "pie", "cherry", "yak"};
    auto grammar = dialogue::makeListeningGrammar(source, {.grammarName = "capped", .maxWildcardWords = 3});
    ASSERT_TRUE(grammar) << describe(grammar.error());
    EXPECT_EQ(grammar->wildcardWords, words("pie apple cherry"));
    EXPECT_EQ(grammar->wildcardWordsLeftOut, 2u);
    const speech::JsgfSet set = readBack(*grammar);
    EXPECT_TRUE(set.accepts(words("say apple pie")));
    EXPECT_FALSE(set.accepts(words("say zebra")));
}

TEST(ListeningGrammar, PatternsWithNothingCertainToSayAreLeftOut)
{
    dialogue::GrammarSource source;
    source.patterns = {{star()}, {maybeStar()}, {word("hi"), set("nowhere")}};
    auto none = dialogue::makeListeningGrammar(source);
    ASSERT_FALSE(none);
    EXPECT_EQ(none.error().code, ErrorCode::InvalidArgument);
    source.patterns.push_back({word("hi")});
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    EXPECT_EQ(grammar->patternsSkipped, 3u);
    EXPECT_EQ(grammar->patternsUsed, 1u);
    auto badName = dialogue::makeListeningGrammar(source, {.grammarName = "two words"});
    ASSERT_FALSE(badName);
    EXPECT_EQ(badName.error().code, ErrorCode::InvalidArgument);
    for (const float weight : {0.0f, -0.5f, 1.5f}) {
        auto badWeight = dialogue::makeListeningGrammar(source, {.wildcardWordWeight = weight});
        ASSERT_FALSE(badWeight) << weight;
        EXPECT_NE(badWeight.error().message.find("weight"), std::string::npos) << badWeight.error().message;
    }
}

TEST(ListeningGrammar, ARosieSizedSourceIsAcceptedWholeAndPocketsphinxTakesItsGraph)
{
    const speech::SphinxModel model = speech::SphinxModel::installed();
    const dialogue::GrammarSource source = thespis::test::largeGrammarSource(model.dictionary.string(), 12000, 3000);
    ASSERT_EQ(source.patterns.size(), 12000u);
    ASSERT_EQ(source.vocabulary.size(), 3000u);
    using Clock = std::chrono::steady_clock;
    const auto began = Clock::now();
    auto grammar = dialogue::makeListeningGrammar(source);
    ASSERT_TRUE(grammar) << describe(grammar.error());
    const auto generated = Clock::now();
    EXPECT_EQ(grammar->patternsUsed, 12000u);
    const speech::JsgfSet set = readBack(*grammar);
    ASSERT_FALSE(set.grammars.empty());
    const std::string& someWord = grammar->innerWildcardWords.back(); // in both loops
    const speech::WordGraphWalker graph(grammar->graph);
    for (const auto& pattern : source.patterns) {
        const std::vector<std::string> sentence = thespis::test::literalForm(source, pattern, someWord);
        ASSERT_TRUE(set.accepts(sentence));
        ASSERT_TRUE(graph.accepts(sentence)) << thespis::core::joined(sentence);
    }
    const auto checked = Clock::now();

    auto decoder = speech::SphinxDecoder::open(model, speech::SphinxDecoder::Mode::Listen);
    ASSERT_TRUE(decoder) << describe(decoder.error());
    std::set<std::string, std::less<>> wanted(grammar->words.begin(), grammar->words.end());
    auto pronunciations = speech::readPronunciations(model.dictionary, wanted);
    ASSERT_TRUE(pronunciations) << describe(pronunciations.error());
    for (const auto& [w, phones] : *pronunciations)
        ASSERT_TRUE(decoder->addWord(w, thespis::core::joined(phones.front())));
    const auto added = Clock::now();
    auto compiled = decoder->addWordGraph("rosie", grammar->graph);
    ASSERT_TRUE(compiled) << describe(compiled.error());
    const auto done = Clock::now();
    const auto ms = [](auto a, auto b) { return std::chrono::duration<double, std::milli>(b - a).count(); };
    std::cout << "12000 patterns, 3000 words: JSGF " << grammar->jsgf.size() / 1024 << " KiB and a graph of "
              << grammar->graph.states << " states, " << grammar->graph.wordArcs() << " word arcs made in "
              << ms(began, generated) << " ms; every literal form accepted in " << ms(generated, checked)
              << " ms; words added in " << ms(checked, added) << " ms; pocketsphinx took the graph in " << ms(added, done)
              << " ms\n";
}
