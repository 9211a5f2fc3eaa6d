// The JSGF reader and matcher (core/speech/jsgf.h) on pocketsphinx's own grammars and on
// broken text.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "speech/jsgf.h"
#include "test_support.h"

namespace speech = thespis::core::speech;
using thespis::core::ErrorCode;
using thespis::test::sharedData;

namespace {

std::vector<std::string> words(std::string_view text)
{
    std::istringstream in{std::string(text)};
    std::vector<std::string> out;
    for (std::string word; in >> word;)
        out.push_back(word);
    return out;
}

speech::JsgfSet readShared(const std::string& relative)
{
    auto set = speech::readJsgfFile(sharedData("speech/pocketsphinx/" + relative));
    EXPECT_TRUE(set) << relative << ": " << (set ? "" : describe(set.error()));
    return set ? *set : speech::JsgfSet{};
}

speech::JsgfSet readText(std::string_view text)
{
    auto grammar = speech::parseJsgf(text);
    EXPECT_TRUE(grammar) << (grammar ? "" : describe(grammar.error()));
    if (!grammar)
        return {};
    auto set = speech::resolveJsgf(*grammar, [](const std::string& name) -> thespis::core::Result<std::string> {
        return thespis::core::makeError(ErrorCode::FileNotFound, name + " is not here.");
    });
    EXPECT_TRUE(set) << (set ? "" : describe(set.error()));
    return set ? *set : speech::JsgfSet{};
}

// The message of the error reading `text`, which must fail as corrupt data.
std::string errorOf(std::string_view text)
{
    auto grammar = speech::parseJsgf(text);
    EXPECT_FALSE(grammar) << text;
    if (grammar)
        return {};
    EXPECT_EQ(grammar.error().code, ErrorCode::CorruptData) << grammar.error().message;
    return grammar.error().message;
}

constexpr const char* kHead = "#JSGF V1.0;\ngrammar g;\n";

} // namespace

TEST(Jsgf, ReadsGoforwardIntoRules)
{
    const speech::JsgfSet set = readShared("goforward.gram");
    ASSERT_EQ(set.grammars.size(), 1u);
    const speech::JsgfGrammar& g = set.grammars[0];
    EXPECT_EQ(g.name, "goforward");
    ASSERT_EQ(g.rules.size(), 4u);
    EXPECT_EQ(g.publicRules().size(), 2u);
    const speech::JsgfRule* move2 = g.findRule("move2");
    ASSERT_NE(move2, nullptr);
    EXPECT_EQ(move2->line, 11);
    // go <direction> <distance> [meter | meters]
    ASSERT_EQ(move2->expansion.kind, speech::JsgfExpansion::Kind::Sequence);
    ASSERT_EQ(move2->expansion.children.size(), 4u);
    EXPECT_EQ(move2->expansion.children[1].kind, speech::JsgfExpansion::Kind::RuleRef);
    EXPECT_EQ(move2->expansion.children[1].text, "direction");
    const auto& optional = move2->expansion.children[3];
    ASSERT_EQ(optional.kind, speech::JsgfExpansion::Kind::Optional);
    EXPECT_EQ(optional.children[0].kind, speech::JsgfExpansion::Kind::Alternatives);
    EXPECT_EQ(optional.children[0].children.size(), 2u);
}

TEST(Jsgf, AcceptsGoforwardSentencesAndNothingElse)
{
    const speech::JsgfSet set = readShared("goforward.gram");
    std::string transcript;
    ASSERT_TRUE(std::getline(std::ifstream(sharedData("speech/pocketsphinx/goforward.txt")), transcript));
    EXPECT_TRUE(set.accepts(words(transcript)));
    EXPECT_TRUE(set.accepts(words("go backward three")));
    EXPECT_TRUE(set.accepts(words("go backward three meter")));
    EXPECT_FALSE(set.accepts(words("go forward")));
    EXPECT_FALSE(set.accepts(words("go forward ten meters please")));
    EXPECT_FALSE(set.accepts(words("")));
    EXPECT_TRUE(set.accepts(words("forward"), "direction"));
}

TEST(Jsgf, AcceptsEveryCardsTranscription)
{
    const speech::JsgfSet set = readShared("cards/cards.gram");
    std::ifstream in(sharedData("speech/pocketsphinx/cards/cards.transcription"));
    int lines = 0;
    for (std::string line; std::getline(in, line); ++lines) {
        // "<s> ten of clubs  </s> (001)"
        std::vector<std::string> said = words(line);
        ASSERT_GE(said.size(), 3u);
        said.erase(said.end() - 2, said.end());
        said.erase(said.begin());
        EXPECT_TRUE(set.accepts(said)) << line;
    }
    EXPECT_EQ(lines, 5);
    EXPECT_FALSE(set.accepts(words("ten of")));
    EXPECT_FALSE(set.accepts(words("ace ace ace ace")));
}

TEST(Jsgf, ResolvesTheImportOfPoliteAndRecursion)
{
    const speech::JsgfSet set = readShared("grammars/test.gram");
    ASSERT_EQ(set.grammars.size(), 2u);
    EXPECT_EQ(set.grammars[1].name, "polite");
    ASSERT_EQ(set.grammars[0].imports.size(), 2u);
    EXPECT_EQ(set.grammars[0].imports[0].rule, "startPolite");
    // Right recursion, nested recursion through another rule, Kleene star, <NULL>, imports.
    EXPECT_TRUE(set.accepts(words("start and stop and start"), "rightRecursion"));
    EXPECT_FALSE(set.accepts(words("start and"), "rightRecursion"));
    EXPECT_TRUE(set.accepts(words("another"), "nestedRightRecursion"));
    EXPECT_TRUE(set.accepts(words("please oh mighty computer don't crash"), "kleene"));
    EXPECT_TRUE(set.accepts(words("don't crash"), "kleene"));
    EXPECT_TRUE(set.accepts(words("one and one two two three and three"), "nulltest"));
    EXPECT_TRUE(set.accepts(words("could you stop stop thank you"), "command"));
    EXPECT_TRUE(set.accepts(words("go go go")));
    EXPECT_FALSE(set.accepts(words("could you stop go")));
}

TEST(Jsgf, ReadsTheOtherPocketsphinxCases)
{
    const speech::JsgfSet reserved = readShared("grammars/public.gram");
    EXPECT_TRUE(reserved.accepts(words("grammar")));
    EXPECT_TRUE(reserved.accepts(words("import")));
    const speech::JsgfSet upper = readShared("grammars/right_recursion_53.gram");
    EXPECT_TRUE(upper.accepts(words("ONE HUNDRED METER EQUAL TO HOW MANY CENTIMETER")));
    EXPECT_TRUE(upper.accepts(words("WHAT IS YOUR NAME")));
    EXPECT_FALSE(upper.accepts(words("METER EQUAL TO METER")));
    const speech::JsgfSet polite = readShared("grammars/polite.gram");
    EXPECT_TRUE(polite.accepts(words("")));
    EXPECT_TRUE(polite.accepts(words("please thank you kindly"), "allPolite"));
    const std::vector<std::string> tokens = polite.tokens();
    EXPECT_NE(std::find(tokens.begin(), tokens.end(), "mighty"), tokens.end());
}

TEST(Jsgf, RejectsPocketsphinxsNegativeCases)
{
    for (const std::string name : {"invalid", "defective", "fuzzed"}) {
        SCOPED_TRACE(name);
        auto set = speech::readJsgfFile(sharedData("speech/pocketsphinx/grammars/negative/" + name + ".gram"));
        ASSERT_FALSE(set);
        EXPECT_EQ(set.error().code, ErrorCode::CorruptData);
        EXPECT_NE(set.error().message.find("line "), std::string::npos) << set.error().message;
        EXPECT_NE(set.error().message.find(name + ".gram"), std::string::npos) << set.error().message;
    }
    auto invalid = speech::readJsgfFile(sharedData("speech/pocketsphinx/grammars/negative/invalid.gram"));
    ASSERT_FALSE(invalid);
    EXPECT_NE(invalid.error().message.find("line 5, column 8"), std::string::npos) << invalid.error().message;
    auto defective = speech::readJsgfFile(sharedData("speech/pocketsphinx/grammars/negative/defective.gram"));
    ASSERT_FALSE(defective);
    EXPECT_NE(defective.error().message.find("imported twice"), std::string::npos) << defective.error().message;
}

TEST(Jsgf, AnImportThatCannotBeReadIsAnError)
{
    auto grammar = speech::parseJsgf(std::string(kHead) + "import <nowhere.rule>;\npublic <a> = <rule>;\n");
    ASSERT_TRUE(grammar) << grammar.error().message;
    auto set = speech::resolveJsgf(*grammar, [](const std::string&) -> thespis::core::Result<std::string> {
        return thespis::core::makeError(ErrorCode::FileNotFound, "missing");
    });
    ASSERT_FALSE(set);
    EXPECT_NE(set.error().message.find("line 3, column 8"), std::string::npos) << set.error().message;
    auto privateRule = speech::resolveJsgf(*grammar, [](const std::string&) -> thespis::core::Result<std::string> {
        return std::string("#JSGF V1.0; grammar nowhere; <rule> = x;");
    });
    ASSERT_FALSE(privateRule);
    EXPECT_NE(privateRule.error().message.find("no public rule rule"), std::string::npos) << privateRule.error().message;
}

TEST(Jsgf, NamesLineAndColumnOfSyntaxErrors)
{
    EXPECT_NE(errorOf(std::string(kHead) + "public <a> = hello there\n").find("line 4, column 1: expected ';'"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "public <a> = (hello | there;\n").find("line 3, column 28: expected ')'"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = x;\n<a> = y;\n").find("line 4, column 1: <a> is defined twice"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = <b>;\n").find("line 3, column 7: <b> is neither defined"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = /2/ x | y;\n").find("line 3, column 15: either every alternative"),
              std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = x**;\n").find("column 9: a second"), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = /x/ y;\n").find("column 7: a weight"), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = x {tag;\n").find("column 9: a tag"), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "/* never closed\n").find("line 3, column 1: a comment"), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = \xC3\xA9t\xC3;\n").find("line 3, column 9: the text is not UTF-8"),
              std::string::npos);
    EXPECT_NE(errorOf("#JSGF V2.0;\ngrammar g;\n").find("not V1.0"), std::string::npos);
    EXPECT_NE(errorOf("#JSGF V1.0;\n<a> = x;\n").find("line 2, column 1: expected \"grammar name;\""), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = ;\n").find("line 3, column 7: expected a word"), std::string::npos);
    EXPECT_NE(errorOf(std::string(kHead) + "<a> = <NULL;\n").find("column 7: a rule name"), std::string::npos);
    auto notJsgf = speech::parseJsgf("grammar g; <a> = x;");
    ASSERT_FALSE(notJsgf);
    EXPECT_EQ(notJsgf.error().code, ErrorCode::NotOurFormat);
}

TEST(Jsgf, WeightsTagsQuotesNullAndVoid)
{
    const speech::JsgfSet set = readText(std::string(kHead) + "// a line comment\n"
                                         "public <a> = /10/ hello {greet} | /0.5/ \"good day\" | /1/ <NULL> bye | /1e-3/ <VOID> never;\n");
    ASSERT_FALSE(set.grammars.empty());
    const speech::JsgfExpansion& top = set.grammars[0].rules[0].expansion;
    ASSERT_EQ(top.kind, speech::JsgfExpansion::Kind::Alternatives);
    EXPECT_EQ(top.weights, (std::vector<double>{10, 0.5, 1, 1e-3}));
    EXPECT_TRUE(set.accepts(words("hello")));
    EXPECT_TRUE(set.accepts(std::vector<std::string>{"good day"}));
    EXPECT_TRUE(set.accepts(words("bye")));
    EXPECT_FALSE(set.accepts(words("never")));
    EXPECT_EQ(top.children[0].tags, std::vector<std::string>{"greet"});
}

TEST(Jsgf, RecursionThatConsumesNothingFirstStillMatches)
{
    // Left recursion (which pocketsphinx cannot compile) still has its sentences: "y x x".
    const speech::JsgfSet set = readText(std::string(kHead) + "public <a> = <b> x | y;\n<b> = <a>;\n");
    EXPECT_TRUE(set.accepts(words("y")));
    EXPECT_TRUE(set.accepts(words("y x x")));
    EXPECT_FALSE(set.accepts(words("x")));
}
