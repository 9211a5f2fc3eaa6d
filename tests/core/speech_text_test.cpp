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

// Every set shows on the built-in face as MPEG-4 visemes: Oculus is MPEG-4's 14 renamed, and the
// SAPI 21 show a phoneme as MPEG-4 does for most phonemes (34 of 39: SAPI groups "th" and "n"
// with d/t, "uh" with e, and begins "ch" and "jh" as d/t) — the lips close on p/b/m and open on
// "aa" in every set.
TEST(VisemeSets, EverySetShowsOnTheFaceAsMpeg4Visemes)
{
    for (const speech::Viseme& v : speech::mpeg4Visemes().visemes)
        EXPECT_EQ(v.mpeg4, v.id) << v.name;
    for (const speech::Viseme& v : speech::oculusVisemes().visemes)
        EXPECT_EQ(v.mpeg4, v.id) << v.name;
    for (const speech::VisemeSet* set : {&speech::oculusVisemes(), &speech::sapiVisemes()}) {
        int same = 0, all = 0;
        for (std::string_view p : speech::arpabetPhonemes()) {
            const int shown = set->find(set->visemesOf(p).front())->mpeg4;
            ++all;
            same += shown == speech::mpeg4Viseme(p);
        }
        EXPECT_GE(same, all * 85 / 100) << set->name << ": " << same << " of " << all;
        for (std::string_view p : {"P", "B", "M"})
            EXPECT_EQ(set->find(set->visemesOf(p).front())->mpeg4, 1) << set->name << " " << p;
        EXPECT_EQ(set->find(set->visemesOf("AA").front())->mpeg4, 10) << set->name;
    }
}

// Version 1 had no "mpeg4": a copy of a built-in set shows as that set does, another set's
// visemes as the MPEG-4 viseme of their id (what version 1 did), above 14 at rest.
TEST(VisemeSets, AVersionOneSetIsUpgraded)
{
    auto sapi = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":1,"name":"sapi","visemes":[{"id":0,"name":"sil"},)"
        R"({"id":21,"name":"p_b_m","alpha":2.5},{"id":1,"name":"ae_ax_ah"}],"phonemes":{"P":[21],"AE":[1]}})");
    ASSERT_TRUE(sapi.ok()) << sapi.error().message;
    EXPECT_EQ(sapi->find(21)->mpeg4, 1);
    EXPECT_EQ(sapi->find(21)->alpha, 2.5);
    EXPECT_EQ(sapi->find(1)->mpeg4, 10);
    auto mine = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":1,"name":"mine","visemes":[{"id":0,"name":"sil"},)"
        R"({"id":3,"name":"teeth"},{"id":20,"name":"odd"}],"phonemes":{"TH":[3],"K":[20]}})");
    ASSERT_TRUE(mine.ok()) << mine.error().message;
    EXPECT_EQ(mine->find(3)->mpeg4, 3);
    EXPECT_EQ(mine->find(20)->mpeg4, 0);
    // Written again, it is version 2 and reads back the same.
    const std::string written = speech::serializeVisemeSet(*mine);
    EXPECT_NE(written.find("\"version\": 2"), std::string::npos) << written;
    auto again = speech::parseVisemeSet(written);
    ASSERT_TRUE(again.ok()) << again.error().message;
    EXPECT_EQ(*again, *mine);
    // Version 2 must say it.
    auto unsaid = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":2,"visemes":[{"id":0,"name":"sil"}],"phonemes":{}})");
    ASSERT_FALSE(unsaid.ok());
    EXPECT_NE(unsaid.error().message.find("visemes[0].mpeg4"), std::string::npos) << unsaid.error().message;
    auto beyond = speech::parseVisemeSet(
        R"({"format":"thespis-visemes","version":2,"visemes":[{"id":0,"name":"sil","mpeg4":15}],"phonemes":{}})");
    ASSERT_FALSE(beyond.ok());
    EXPECT_NE(beyond.error().message.find("visemes[0].mpeg4"), std::string::npos) << beyond.error().message;
    // A set edited in memory is checked with the viseme's name in the field.
    speech::VisemeSet edited = speech::sapiVisemes();
    edited.visemes.back().mpeg4 = 15;
    ASSERT_FALSE(edited.validate().ok());
    EXPECT_NE(edited.validate().error().message.find("visemes[21] (p_b_m).mpeg4"), std::string::npos)
        << edited.validate().error().message;
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
