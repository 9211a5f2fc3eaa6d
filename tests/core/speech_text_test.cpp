// Tagged text (core/speech/tagged_text.h) and viseme sets (core/speech/viseme_set.h).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "speech/phonemes.h"
#include "speech/tagged_text.h"
#include "speech/viseme_set.h"

namespace speech = thespis::core::speech;
using thespis::core::ErrorCode;

namespace {

std::string parseError(std::string_view text)
{
    auto parsed = speech::parseTaggedText(text);
    EXPECT_FALSE(parsed.ok()) << text;
    if (parsed.ok())
        return {};
    EXPECT_EQ(parsed.error().code, ErrorCode::CorruptData);
    return parsed.error().message;
}

std::string spanText(const speech::TaggedText& t, const speech::TaggedGesture& g)
{
    return t.text.substr(g.begin, g.end - g.begin);
}

} // namespace

TEST(TaggedText, ThePapersExample)
{
    auto t = speech::parseTaggedText(
        R"(Are you <begin_gesture id="g1" anim="raise_eyebrows"/>really sure about that?<end_gesture id="g1"/>)");
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_EQ(t->text, "Are you really sure about that?");
    ASSERT_EQ(t->gestures.size(), 1u);
    EXPECT_EQ(t->gestures[0].id, "g1");
    EXPECT_EQ(t->gestures[0].animation, "raise_eyebrows");
    EXPECT_EQ(spanText(*t, t->gestures[0]), "really sure about that?");
    EXPECT_EQ(t->gestures[0].line, 1);
    EXPECT_EQ(t->gestures[0].column, 9);
}

TEST(TaggedText, NestedAndOverlappingGestures)
{
    auto t = speech::parseTaggedText("<begin_gesture id='a' anim='nod'/>One <begin_gesture id='b' anim='smile'/>two"
                                     "<end_gesture id='a'/> three<end_gesture id='b'/> four");
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_EQ(t->text, "One two three four");
    ASSERT_EQ(t->gestures.size(), 2u);
    EXPECT_EQ(spanText(*t, t->gestures[0]), "One two");
    EXPECT_EQ(spanText(*t, t->gestures[1]), "two three");
}

TEST(TaggedText, TextCharactersAndEntities)
{
    auto t = speech::parseTaggedText("1 < 2 &amp; 3 &gt; 2 & so on");
    ASSERT_TRUE(t.ok()) << t.error().message;
    EXPECT_EQ(t->text, "1 < 2 & 3 > 2 & so on");
}

TEST(TaggedText, ErrorsSayLineAndColumn)
{
    EXPECT_EQ(parseError("Hello\n  <begin_gesture anim=\"nod\"/>there"),
              "line 2, column 3: <begin_gesture> needs a id attribute.");
    EXPECT_NE(parseError("Hi <wave/>").find("line 1, column 4: unknown tag <wave>"), std::string::npos);
    EXPECT_NE(parseError("Hi <end_gesture id=\"x\"/>").find("has no <begin_gesture>"), std::string::npos);
    EXPECT_NE(parseError("Hi\n\n <begin_gesture id=\"g\" anim=\"nod\"/>there").find("line 3, column 2: the gesture \"g\" is never ended"),
              std::string::npos);
    EXPECT_NE(parseError("<begin_gesture id=\"g\" anim=\"a\"/>x<end_gesture id=\"g\"/><begin_gesture id=\"g\" anim=\"b\"/>")
                  .find("used twice"),
              std::string::npos);
    EXPECT_NE(parseError("Hé <wave/>").find("line 1, column 4:"), std::string::npos); // characters, not bytes
    EXPECT_NE(parseError("x <begin_gesture id=\"g\" anim=\"a\">y").find("must end with \"/>\""), std::string::npos);
    EXPECT_NE(parseError("x <begin_gesture id=\"g\" anim=\"a\"").find("not closed"), std::string::npos);
    EXPECT_NE(parseError("x <begin_gesture id=\"g\" anim=\"a\" speed=\"2\"/>").find("no attribute speed"), std::string::npos);
}

TEST(TaggedText, WritesBackWhatItRead)
{
    const std::string source = R"(<begin_gesture id="a" anim="nod"/>One <begin_gesture id="b" anim="sm&quot;ile"/>two<end_gesture id="a"/> 1 &lt; 2<end_gesture id="b"/>)";
    auto t = speech::parseTaggedText(source);
    ASSERT_TRUE(t.ok()) << t.error().message;
    const std::string written = speech::taggedTextString(*t);
    auto again = speech::parseTaggedText(written);
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_EQ(*again, *t);
}

TEST(VisemeSets, BuiltInSetsAreValidAndCoverEveryPhoneme)
{
    for (const speech::VisemeSet* set : {&speech::mpeg4Visemes(), &speech::oculusVisemes(), &speech::sapiVisemes()}) {
        ASSERT_TRUE(set->validate().ok()) << set->name << ": " << set->validate().error().message;
        for (std::string_view p : speech::arpabetPhonemes())
            EXPECT_NE(set->visemesOf(p).front(), 0) << set->name << " " << p;
        EXPECT_EQ(set->visemesOf("SIL"), std::vector<int>{0});
    }
    EXPECT_EQ(speech::mpeg4Visemes().visemes.size(), 15u);
    EXPECT_EQ(speech::oculusVisemes().visemes.size(), 15u);
    EXPECT_EQ(speech::sapiVisemes().visemes.size(), 22u);
    EXPECT_EQ(speech::mpeg4Viseme("m"), 1);
    EXPECT_EQ(speech::mpeg4Viseme("AA1"), 10);
    EXPECT_EQ(speech::oculusVisemes().find(speech::oculusVisemes().visemesOf("F").front())->name, "FF");
}

// Microsoft's own phoneme → viseme table (../shared/data/speech, CC BY 4.0) against ours.
TEST(VisemeSets, SapiMatchesMicrosoftsTable)
{
    std::ifstream in(THESPIS_SHARED_DATA "/speech/azure_en-US_sapi_ipa_viseme.csv");
    ASSERT_TRUE(in) << "missing ../shared/data/speech";
    std::string line;
    std::getline(in, line); // header
    int checked = 0;
    while (std::getline(in, line)) {
        std::stringstream row(line);
        std::string sapi, ipa, ids;
        std::getline(row, sapi, ',');
        std::getline(row, ipa, ',');
        std::getline(row, ids, ',');
        if (sapi == "er r")
            sapi = "er"; // the r-coloured vowel is one ARPAbet phoneme
        if (sapi.find(' ') != std::string::npos || sapi == "ax")
            continue; // sequences ("ih r") and the schwa ARPAbet writes as AH
        std::vector<int> expected;
        std::stringstream list(ids);
        for (std::string id; std::getline(list, id, ';');)
            expected.push_back(std::stoi(id));
        EXPECT_EQ(speech::sapiVisemes().visemesOf(sapi == "h" ? "HH" : sapi), expected) << sapi;
        ++checked;
    }
    EXPECT_GE(checked, 39);
}

TEST(VisemeSets, RoundTripAndErrorsNameTheField)
{
    speech::VisemeSet set = speech::mpeg4Visemes();
    set.visemes[1].alpha = 7.5;
    set.phonemes["HH"] = {10};
    auto read = speech::parseVisemeSet(speech::serializeVisemeSet(set));
    ASSERT_TRUE(read.ok()) << read.error().message;
    EXPECT_EQ(*read, set);

    std::string text = speech::serializeVisemeSet(set);
    const std::string bad = text.replace(text.find("7.5"), 3, "-1.0");
    auto refused = speech::parseVisemeSet(bad);
    ASSERT_FALSE(refused.ok());
    EXPECT_NE(refused.error().message.find("visemes[1].alpha"), std::string::npos) << refused.error().message;

    auto unknownPhoneme = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":1,"visemes":[{"id":0,"name":"sil"}],"phonemes":{"QQ":[0]}})");
    ASSERT_FALSE(unknownPhoneme.ok());
    EXPECT_NE(unknownPhoneme.error().message.find("phonemes.QQ"), std::string::npos);
    auto unknownViseme = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":1,"visemes":[{"id":0,"name":"sil"}],"phonemes":{"P":[3]}})");
    ASSERT_FALSE(unknownViseme.ok());
    EXPECT_NE(unknownViseme.error().message.find("phonemes.P[0]"), std::string::npos);
    auto newer = speech::parseVisemeSet(R"({"format":"thespis-visemes","version":99,"visemes":[],"phonemes":{}})");
    ASSERT_FALSE(newer.ok());
    EXPECT_EQ(newer.error().code, ErrorCode::NewerVersion);
}
