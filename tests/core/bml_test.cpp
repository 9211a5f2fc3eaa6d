// BML 1.0 blocks (core/speech/bml.h): reading them as agents write them, the errors a block's
// author sees, writing them back, and turning their sync references into times.
#include <gtest/gtest.h>

#include <cmath>

#include "made_up_timing.h"
#include "speech/bml.h"

namespace speech = thespis::core::speech;
using speech::BmlBehaviorKind;
using speech::BmlPoint;
using speech::BmlSyncRef;
using thespis::core::ErrorCode;
using thespis::test::madeUpTiming;

namespace {

speech::BmlBlock parsed(std::string_view xml)
{
    auto block = speech::parseBml(xml);
    EXPECT_TRUE(block.ok()) << (block.ok() ? "" : block.error().message) << "\n" << xml;
    return block.ok() ? std::move(block).value() : speech::BmlBlock{};
}

std::string parseError(std::string_view xml)
{
    auto block = speech::parseBml(xml);
    EXPECT_FALSE(block.ok()) << xml;
    if (block.ok())
        return {};
    EXPECT_EQ(block.error().code, ErrorCode::CorruptData);
    return block.error().message;
}

// A block of the given behaviours, as the lines of a <bml> element.
std::string inBlock(std::string_view behaviours)
{
    return "<bml xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\" id=\"bml1\">\n" + std::string(behaviours)
           + "\n</bml>";
}

std::string syncRefError(std::string_view text)
{
    auto ref = speech::parseBmlSyncRef(text);
    EXPECT_FALSE(ref.ok()) << text;
    if (ref.ok())
        return {};
    EXPECT_EQ(ref.error().code, ErrorCode::InvalidArgument);
    return ref.error().message;
}

// Every gesture, head and gaze takes a second, its stroke 0.4 s in.
std::array<double, speech::kBmlPointCount> oneSecond(const speech::BmlBehavior&)
{
    return {0, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0};
}

struct Resolved {
    std::map<std::string, std::array<double, speech::kBmlPointCount>> at;
    std::string error;
};

Resolved resolve(const std::string& xml, const std::map<std::string, speech::SpeechTiming>& timing = {})
{
    const speech::BmlBlock block = parsed(xml);
    auto times = speech::resolveBml(block, timing, &oneSecond);
    Resolved out;
    if (!times.ok()) {
        EXPECT_EQ(times.error().code, ErrorCode::InvalidArgument);
        out.error = times.error().message;
        return out;
    }
    EXPECT_EQ(times->size(), block.behaviors.size());
    for (const speech::BmlTimes& t : *times)
        out.at[t.behavior] = t.at;
    return out;
}

double at(const Resolved& r, const std::string& behaviour, BmlPoint point)
{
    EXPECT_TRUE(r.error.empty()) << r.error;
    const auto it = r.at.find(behaviour);
    return it == r.at.end() ? NAN : it->second[std::size_t(point)];
}

} // namespace

TEST(BmlReader, TheHeadersExample)
{
    const speech::BmlBlock b = parsed(R"(<bml id="bml1" composition="merge">
  <speech id="s1"><text>Hello <sync id="t1"/>there, how are you?</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <head id="h1" lexeme="NOD" start="g1:stroke + 0.3" repetition="2"/>
  <gaze id="z1" target="camera" influence="HEAD" start="s1:start"/>
</bml>)");
    EXPECT_EQ(b.id, "bml1");
    EXPECT_EQ(b.character, "");
    EXPECT_EQ(b.composition, speech::BmlComposition::Merge);
    ASSERT_EQ(b.behaviors.size(), 4u);

    const speech::BmlBehavior& s1 = b.behaviors[0];
    EXPECT_EQ(s1.kind, BmlBehaviorKind::Speech);
    EXPECT_EQ(s1.id, "s1");
    EXPECT_EQ(s1.text, "Hello there, how are you?");
    ASSERT_EQ(s1.syncMarks.size(), 1u);
    EXPECT_EQ(s1.syncMarks[0].first, "t1");
    EXPECT_EQ(s1.text.substr(s1.syncMarks[0].second), "there, how are you?");
    EXPECT_TRUE(s1.sync.empty());
    EXPECT_EQ(s1.line, 2);
    EXPECT_EQ(s1.column, 3);

    const speech::BmlBehavior& g1 = b.behaviors[1];
    EXPECT_EQ(g1.kind, BmlBehaviorKind::Gesture);
    EXPECT_EQ(g1.lexeme, "BEAT");
    EXPECT_FALSE(g1.byName);
    EXPECT_EQ(g1.sync, (std::map<BmlPoint, BmlSyncRef>{{BmlPoint::Stroke, {"s1", "t1", 0}}}));
    EXPECT_EQ(g1.line, 3);

    const speech::BmlBehavior& h1 = b.behaviors[2];
    EXPECT_EQ(h1.kind, BmlBehaviorKind::Head);
    EXPECT_EQ(h1.lexeme, "NOD");
    EXPECT_EQ(h1.repetition, 2);
    EXPECT_EQ(h1.amount, 1);
    EXPECT_EQ(h1.sync, (std::map<BmlPoint, BmlSyncRef>{{BmlPoint::Start, {"g1", "stroke", 0.3}}}));

    const speech::BmlBehavior& z1 = b.behaviors[3];
    EXPECT_EQ(z1.kind, BmlBehaviorKind::Gaze);
    EXPECT_EQ(z1.target, "camera");
    EXPECT_EQ(z1.influence, "HEAD");
    EXPECT_EQ(z1.sync, (std::map<BmlPoint, BmlSyncRef>{{BmlPoint::Start, {"s1", "start", 0}}}));
    EXPECT_EQ(z1.line, 5);
    EXPECT_EQ(z1.column, 3);
}

// As a dialogue manager sends it: an XML declaration, the namespace, a character, extension
// attributes and elements in other namespaces, a <description> the realizer may use or ignore.
TEST(BmlReader, ReadsBlocksAsAgentsWriteThem)
{
    const speech::BmlBlock b = parsed(R"(<?xml version="1.0" encoding="UTF-8"?>
<!-- turn 12 of the scene -->
<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" xmlns:ext="http://example.org/ext"
     id="turn12" characterId="Creon" composition="APPEND" ext:priority="high">
  <speech id="line1" ext:voice="deep">
    <text>
      Is this   <sync id="w1"/>your
      answer,&#160;Antigone?  <sync id="w2"/>
    </text>
    <description priority="2" type="application/ssml+xml">
      <speak xmlns="http://www.w3.org/2001/10/synthesis">Is this <emphasis>your</emphasis> answer?</speak>
    </description>
  </speech>
  <gesture id="beat1" lexeme="BEAT" ext:hand="right" start="line1:w1" stroke="line1:w1+0.2"/>
  <ext:gesture id="ext1" lexeme="WAVE"/>
</bml>)");
    EXPECT_EQ(b.id, "turn12");
    EXPECT_EQ(b.character, "Creon");
    EXPECT_EQ(b.composition, speech::BmlComposition::Append);
    ASSERT_EQ(b.behaviors.size(), 3u);
    const speech::BmlBehavior& line = b.behaviors[0];
    EXPECT_EQ(line.text, "Is this your answer,\u00a0Antigone?");
    ASSERT_EQ(line.syncMarks.size(), 2u);
    EXPECT_EQ(line.text.substr(line.syncMarks[0].second), "your answer,\u00a0Antigone?");
    EXPECT_EQ(line.syncMarks[1].second, line.text.size()); // after the last word
    EXPECT_EQ(b.behaviors[1].sync.at(BmlPoint::Stroke), (BmlSyncRef{"line1", "w1", 0.2}));
    // An element in another namespace is known by its local name.
    EXPECT_EQ(b.behaviors[2].kind, BmlBehaviorKind::Gesture);
    EXPECT_EQ(b.behaviors[2].lexeme, "WAVE");

    const speech::BmlBlock prefixed = parsed(R"(<b:bml xmlns:b="http://www.bml-initiative.org/bml/bml-1.0" id="x">
  <b:head id="h" lexeme="SHAKE"/></b:bml>)");
    ASSERT_EQ(prefixed.behaviors.size(), 1u);
    EXPECT_EQ(prefixed.behaviors[0].kind, BmlBehaviorKind::Head);
}

TEST(BmlReader, ReadsEveryBehaviourAndAttribute)
{
    const speech::BmlBlock b = parsed(inBlock(R"(
  <speech id="s1" start="0.5"><text>One</text></speech>
  <gesture id="g1" name="shrug_big" start="1" ready="1.1" strokeStart="1.2" stroke="1.3" strokeEnd="1.4" relax="1.5" end="1.6"/>
  <faceLexeme id="f1" lexeme="RAISE_BROWS" amount="0.25"/>
  <head id="h1" lexeme="TILT" amount="0.5" repetition="3"/>
  <gaze id="z1" target="Antigone:HumanoidRoot" influence="WAIST" offsetAngle="-15.5" offsetDirection="UPLEFT"/>
  <pointing id="p1" target="1 0.5 2" mode="LEFT_HAND"/>
  <wait id="w1" duration="2.5"/>)"));
    ASSERT_EQ(b.behaviors.size(), 7u);
    const auto& [s1, g1, f1, h1, z1, p1, w1] =
        std::tie(b.behaviors[0], b.behaviors[1], b.behaviors[2], b.behaviors[3], b.behaviors[4], b.behaviors[5],
                 b.behaviors[6]);
    EXPECT_EQ(s1.sync.at(BmlPoint::Start), (BmlSyncRef{"", "", 0.5}));
    EXPECT_EQ(g1.kind, BmlBehaviorKind::Gesture);
    EXPECT_TRUE(g1.byName);
    EXPECT_EQ(g1.lexeme, "shrug_big");
    ASSERT_EQ(g1.sync.size(), 7u);
    for (int p = 0; p < speech::kBmlPointCount; ++p)
        EXPECT_DOUBLE_EQ(g1.sync.at(BmlPoint(p)).offset, 1 + 0.1 * p) << speech::bmlPointName(BmlPoint(p));
    EXPECT_EQ(f1.kind, BmlBehaviorKind::FaceLexeme);
    EXPECT_EQ(f1.lexeme, "RAISE_BROWS");
    EXPECT_EQ(f1.amount, 0.25);
    EXPECT_EQ(h1.kind, BmlBehaviorKind::Head);
    EXPECT_EQ(h1.lexeme, "TILT");
    EXPECT_EQ(h1.amount, 0.5);
    EXPECT_EQ(h1.repetition, 3);
    EXPECT_EQ(z1.kind, BmlBehaviorKind::Gaze);
    EXPECT_EQ(z1.target, "Antigone:HumanoidRoot");
    EXPECT_EQ(z1.influence, "WAIST");
    EXPECT_EQ(z1.offsetAngle, -15.5);
    EXPECT_EQ(z1.offsetDirection, "UPLEFT");
    EXPECT_EQ(p1.kind, BmlBehaviorKind::Pointing);
    EXPECT_EQ(p1.target, "1 0.5 2");
    EXPECT_EQ(p1.mode, "LEFT_HAND");
    EXPECT_EQ(w1.kind, BmlBehaviorKind::Wait);
    EXPECT_EQ(w1.duration, 2.5);

    const std::vector<std::string_view> kinds{"speech", "gesture", "faceLexeme", "head", "gaze", "pointing", "wait"};
    for (std::size_t k = 0; k < kinds.size(); ++k)
        EXPECT_EQ(speech::bmlKindName(b.behaviors[k].kind), kinds[k]);
    for (int p = 0; p < speech::kBmlPointCount; ++p)
        EXPECT_EQ(speech::bmlPointNamed(speech::bmlPointName(BmlPoint(p))), BmlPoint(p));
    EXPECT_EQ(speech::bmlPointName(BmlPoint::StrokeStart), "strokeStart");
    EXPECT_FALSE(speech::bmlPointNamed("Stroke"));
    EXPECT_EQ(parsed("<bml id='b' composition='Replace'/>").composition, speech::BmlComposition::Replace);
}

TEST(BmlReader, SpeechTextAndWhereItsMarksStand)
{
    const auto marksOf = [](std::string_view text) {
        const speech::BmlBlock b = parsed(inBlock("<speech id='s'><text>" + std::string(text) + "</text></speech>"));
        std::vector<std::string> out;
        if (b.behaviors.empty())
            return out;
        const speech::BmlBehavior& s = b.behaviors[0];
        out.push_back(s.text);
        for (const auto& [id, offset] : s.syncMarks)
            out.push_back(id + "@" + std::to_string(offset));
        return out;
    };
    using Marks = std::vector<std::string>;
    EXPECT_EQ(marksOf("  <sync id='a'/> Hello  <sync id='b'/> <sync id='c'/>\n\tthere<sync id='d'/>  "),
              (Marks{"Hello there", "a@0", "b@6", "c@6", "d@11"}));
    EXPECT_EQ(marksOf("Hello<sync id='a'/> there"), (Marks{"Hello there", "a@5"}));
    EXPECT_EQ(marksOf("1 &lt; 2 &amp;&amp; <![CDATA[x > y]]>"), (Marks{"1 < 2 && x > y"}));
    EXPECT_EQ(marksOf(""), (Marks{""}));
    EXPECT_EQ(marksOf("<sync id='only'/>"), (Marks{"", "only@0"}));
}

TEST(BmlSyncRef, ReadsEveryForm)
{
    const auto read = [](std::string_view text) {
        auto ref = speech::parseBmlSyncRef(text);
        EXPECT_TRUE(ref.ok()) << text << ": " << (ref.ok() ? "" : ref.error().message);
        return ref.ok() ? *ref : BmlSyncRef{"?", "?", -1};
    };
    EXPECT_EQ(read("s1:t1"), (BmlSyncRef{"s1", "t1", 0}));
    EXPECT_EQ(read("g1:stroke + 0.3"), (BmlSyncRef{"g1", "stroke", 0.3}));
    EXPECT_EQ(read("g1:stroke+0.3"), (BmlSyncRef{"g1", "stroke", 0.3}));
    EXPECT_EQ(read("g1:stroke - 0.5"), (BmlSyncRef{"g1", "stroke", -0.5}));
    EXPECT_EQ(read("  g1:stroke-.5 "), (BmlSyncRef{"g1", "stroke", -0.5}));
    EXPECT_EQ(read("bml1:s1:start"), (BmlSyncRef{"s1", "start", 0}));
    EXPECT_EQ(read("bml1:s1:start - 2e-1"), (BmlSyncRef{"s1", "start", -0.2}));
    EXPECT_EQ(read("nod-2:end+1"), (BmlSyncRef{"nod-2", "end", 1})); // a "-" inside an id
    EXPECT_EQ(read("1.5"), (BmlSyncRef{"", "", 1.5}));
    EXPECT_EQ(read(" 0 "), (BmlSyncRef{"", "", 0}));

    EXPECT_EQ(speech::bmlSyncRefString({"g1", "stroke", 0.3}), "g1:stroke + 0.3");
    EXPECT_EQ(speech::bmlSyncRefString({"g1", "stroke", -0.5}), "g1:stroke - 0.5");
    EXPECT_EQ(speech::bmlSyncRefString({"s1", "t1", 0}), "s1:t1");
    EXPECT_EQ(speech::bmlSyncRefString({"", "", 1.5}), "1.5");
    for (const BmlSyncRef& ref :
         {BmlSyncRef{"a", "b", 0.1 + 0.2}, BmlSyncRef{"a", "b", -1e-7}, BmlSyncRef{"", "", 1e300}})
        EXPECT_EQ(read(speech::bmlSyncRefString(ref)), ref) << speech::bmlSyncRefString(ref);
}

TEST(BmlSyncRef, RefusesWhatDoesNotRead)
{
    EXPECT_EQ(syncRefError("s1"),
              "\"s1\" is not a sync reference: it is neither a number of seconds nor a reference such as "
              "\"s1:start + 0.5\".");
    for (std::string_view text : {"", "inf", "nan", "1e999", "1,5", "+1.5 s"})
        EXPECT_NE(syncRefError(text).find("neither a number of seconds"), std::string::npos) << text;
    for (std::string_view text : {"g1:stroke + x", "g1:stroke +- 1", "g1:stroke * 2", "g1:stroke + inf", "g1:stroke 1",
                                  "g1:stroke + 0.3 + 0.1"})
        EXPECT_NE(syncRefError(text).find("where \"+ seconds\" or \"- seconds\" was expected"), std::string::npos)
            << text;
    EXPECT_NE(syncRefError("a:b:c:d").find("more than three parts"), std::string::npos);
    for (std::string_view text : {"s1:", ":t1", "g 1:stroke", "::t1", " :start"})
        EXPECT_NE(syncRefError(text).find("an empty id or a space in one"), std::string::npos) << text;
}

TEST(BmlReader, ErrorsSayLineAndColumn)
{
    EXPECT_EQ(parseError("<bml id=\"b\">\n  <gesture id=\"g\" lexeme=\"BEAT\">\n</bml>"),
              "line 3, column 3: the XML is malformed: mismatched tag.");
    EXPECT_EQ(parseError(inBlock("  <gesture id=\"g1\" lexeme=\"BEAT\"/>\n    <dance id=\"d1\"/>")),
              "line 3, column 5: unknown element <dance> in <bml>: expected speech, gesture, faceLexeme, head, gaze, "
              "pointing or wait.");
    EXPECT_EQ(parseError(inBlock("  <head lexeme=\"NOD\"/>")), "line 2, column 3: <head> needs an id.");
    EXPECT_EQ(parseError(inBlock("<head id=\"x\" lexeme=\"NOD\"/>\n<gaze id=\"x\" target=\"camera\"/>")),
              "line 3, column 1: the id \"x\" is used twice in the block.");
    EXPECT_EQ(parseError(inBlock("<faceLexeme id=\"f1\" lexeme=\"SMILE\" amount=\"abc\"/>")),
              "line 2, column 1: the amount of <faceLexeme> \"f1\" must be a number from 0 to 1, not \"abc\".");
    EXPECT_EQ(parseError(inBlock("<head id=\"h1\" lexeme=\"NOD\" repetition=\"-1\"/>")),
              "line 2, column 1: the repetition of <head> \"h1\" must be a whole number from 1 to 1000000, not "
              "\"-1\".");
    EXPECT_NE(parseError(inBlock("<head id=\"h1\" lexeme=\"NOD\" repetition=\"2.5\"/>")).find("must be a whole number"),
              std::string::npos);
    EXPECT_NE(parseError(inBlock("<head id=\"h1\" lexeme=\"NOD\" amount=\"1.5\"/>")).find("from 0 to 1"),
              std::string::npos);
    EXPECT_NE(parseError(inBlock("<gaze id=\"z\" target=\"c\" offsetAngle=\"left\"/>")).find("offsetAngle"),
              std::string::npos);
    EXPECT_NE(parseError(inBlock("<wait id=\"w\" duration=\"-1\"/>")).find("duration of <wait> \"w\""),
              std::string::npos);
    EXPECT_EQ(parseError(inBlock("<speech id=\"s1\"><sync id=\"t1\"/><text>Hi</text></speech>")),
              "line 2, column 17: <sync> must be inside the speech's <text>.");
    EXPECT_EQ(parseError(inBlock("<gesture id=\"g1\" lexeme=\"BEAT\" stroke=\"s1:t1 +\"/>")),
              "line 2, column 1: the stroke \"s1:t1 +\" of <gesture> \"g1\" is not a sync reference: after \"s1:t1\" "
              "comes \"+\" where \"+ seconds\" or \"- seconds\" was expected.");
    EXPECT_EQ(parseError(inBlock("<gesture id=\"g1\" lexeme=\"BEAT\" start=\"bml2:s1:start\"/>")),
              "line 2, column 1: the start of <gesture> \"g1\" refers to the block \"bml2\": only this block, "
              "\"bml1\", can be referred to.");
    // Columns count characters, not bytes.
    EXPECT_NE(parseError("<bml id=\"é\"><nod/></bml>").find("line 1, column 13: unknown element <nod>"),
              std::string::npos);
}

TEST(BmlReader, RefusesWhatIsNotABlock)
{
    EXPECT_EQ(parseError(""), "line 1, column 1: the XML is malformed: no element found.");
    EXPECT_EQ(parseError("<speech id='s'/>"),
              "line 1, column 1: the root element is <speech>, not <bml>: this is not a BML block.");
    EXPECT_EQ(parseError("<bml/>"), "line 1, column 1: <bml> needs an id.");
    EXPECT_NE(parseError("<bml id='a b'/>").find("nothing can refer to it"), std::string::npos);
    EXPECT_NE(parseError("<bml id='b' composition='mix'/>").find("the composition \"mix\" is not MERGE"),
              std::string::npos);
    EXPECT_NE(parseError("<!DOCTYPE bml [<!ENTITY a 'aaaa'>]><bml id='b'/>").find(": BML has no DOCTYPE"),
              std::string::npos);
    EXPECT_NE(parseError("<bml id='b'>&undefined;</bml>").find("undefined entity"), std::string::npos);
    EXPECT_NE(parseError("<bml id='b'/><bml id='c'/>").find("junk after document element"), std::string::npos);
    EXPECT_NE(parseError(std::string(100, '<')).find("line 1, column 2: the XML is malformed"), std::string::npos);
}

TEST(BmlReader, RefusesMisplacedContent)
{
    const auto error = [](std::string_view behaviours) { return parseError(inBlock(behaviours)); };
    EXPECT_EQ(error("<speech id=\"s1\">\n   Hello<text>Hi</text></speech>"),
              "line 3, column 4: text outside a speech's <text>, in <speech>.");
    EXPECT_EQ(error("<speech id=\"s1\"/>"), "line 2, column 1: <speech> \"s1\" needs a <text>.");
    EXPECT_NE(error("<speech id=\"s1\"><text>a</text><text>b</text></speech>").find("has a second <text>"),
              std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text>a<sync/></text></speech>").find("<sync> needs an id"), std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text>a<sync id=\"x\">b</sync></text></speech>").find("<sync> must be empty"),
              std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text>a<sync id=\"x\"/><sync id=\"x\"/></text></speech>").find("used twice"),
              std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text><sync id=\"end\"/></text></speech>").find("standard sync point"),
              std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text><sync id=\"t-1\"/></text></speech>").find("nothing can refer to it"),
              std::string::npos);
    EXPECT_NE(error("<speech id=\"s1\"><text><b>a</b></text></speech>").find("unknown element <b> in <text>"),
              std::string::npos);
    EXPECT_NE(error("<gesture id=\"g\" lexeme=\"BEAT\"><speech id=\"s\"/></gesture>")
                  .find("unknown element <speech> in <gesture>"),
              std::string::npos);
    EXPECT_NE(error("<gesture id=\"g\"/>").find("<gesture> \"g\" needs a lexeme"), std::string::npos);
    EXPECT_NE(error("<gesture id=\"g\" lexeme=\"A\" name=\"B\"/>").find("both a lexeme and a name"), std::string::npos);
    EXPECT_NE(error("<gaze id=\"z\"/>").find("needs a target"), std::string::npos);
    EXPECT_NE(error("<pointing id=\"p\" mode=\"LEFT_HAND\"/>").find("needs a target"), std::string::npos);
    EXPECT_NE(error("<faceLexeme id=\"f\"/>").find("needs a lexeme"), std::string::npos);
    EXPECT_NE(error("hello").find("text outside a speech's <text>, in <bml>"), std::string::npos);
    std::string deep = "<speech id='s'><text>a</text><description>";
    for (int i = 0; i < 40; ++i)
        deep += "<x>";
    EXPECT_NE(error(deep).find("nested more than 32 deep"), std::string::npos);
}

TEST(BmlReader, WritesBackWhatItRead)
{
    const std::string source = R"(<bml id="b&amp;1" characterId="Cr&quot;eon" composition="replace">
  <speech id="s1" start="2.5"><text><sync id="a"/>Tom &amp; Jerry <sync id="b"/>&lt;run&gt;<sync id="c"/></text></speech>
  <gesture id="g1" name="wave&#10;big" stroke="s1:b + 0.1" end="s1:end - 1e-3"/>
  <faceLexeme id="f1" lexeme="SMILE" amount="0.3" start="b&amp;1:s1:start"/>
  <head id="h1" lexeme="NOD" repetition="4" amount="0"/>
  <gaze id="z1" target="x y z" influence="EYES" offsetAngle="10" offsetDirection="DOWN" relax="h1:end"/>
  <pointing id="p1" target="camera" mode="BOTH_HANDS"/>
  <wait id="w1" duration="0.75" start="-0.25"/>
  <head id="h2" lexeme="SHAKE"/>
</bml>)";
    const speech::BmlBlock read = parsed(source);
    const std::string written = speech::bmlString(read);
    speech::BmlBlock again = parsed(written);
    speech::BmlBlock expected = read;
    for (speech::BmlBlock* b : {&again, &expected})
        for (speech::BmlBehavior& behaviour : b->behaviors)
            behaviour.line = behaviour.column = 0;
    EXPECT_EQ(again, expected) << written;
    EXPECT_EQ(read.behaviors[1].lexeme, "wave\nbig");
    EXPECT_NE(written.find("xmlns=\"http://www.bml-initiative.org/bml/bml-1.0\""), std::string::npos);
    EXPECT_NE(written.find("<text><sync id=\"a\"/>Tom &amp; Jerry <sync id=\"b\"/>&lt;run&gt;<sync id=\"c\"/></text>"),
              std::string::npos)
        << written;
    EXPECT_NE(written.find("<head id=\"h2\" lexeme=\"SHAKE\"/>"), std::string::npos) << written;
}

TEST(BmlResolve, UnconstrainedBehavioursStartWithTheBlock)
{
    const Resolved r = resolve(inBlock("<gesture id='g1' lexeme='BEAT'/><wait id='w1' duration='2'/>"));
    EXPECT_EQ(r.at.at("g1"), (std::array<double, 7>{0, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0}));
    EXPECT_EQ(r.at.at("w1"), (std::array<double, 7>{0, 0, 0, 0, 2, 2, 2}));
}

TEST(BmlResolve, OnePinShiftsTheBehaviour)
{
    const Resolved r = resolve(inBlock("<gesture id='g1' lexeme='BEAT' stroke='2'/>"));
    const std::array<double, 7> expected{1.6, 1.8, 1.9, 2.0, 2.1, 2.3, 2.6};
    for (int p = 0; p < 7; ++p)
        EXPECT_NEAR(at(r, "g1", BmlPoint(p)), expected[std::size_t(p)], 1e-12) << p;
}

TEST(BmlResolve, TwoPinsStretchBetweenAndShiftBeyond)
{
    const Resolved r = resolve(inBlock("<gesture id='g1' lexeme='BEAT' start='1' end='3'/>"
                                       "<head id='h1' lexeme='NOD' ready='1' strokeEnd='1.6'/>"));
    const std::array<double, 7> g1{1, 1.4, 1.6, 1.8, 2.0, 2.4, 3.0};
    const std::array<double, 7> h1{0.8, 1, 1.2, 1.4, 1.6, 1.8, 2.1};
    for (int p = 0; p < 7; ++p) {
        EXPECT_NEAR(at(r, "g1", BmlPoint(p)), g1[std::size_t(p)], 1e-12) << p;
        EXPECT_NEAR(at(r, "h1", BmlPoint(p)), h1[std::size_t(p)], 1e-12) << p;
    }
}

TEST(BmlResolve, SyncMarksFallOnTheirWords)
{
    // Words of 0.25 s: "Hello" from 0, "there," 0.25, "how" 0.5, "are" 0.75, "you?" 1 to 1.25; audio 1.5 s.
    const std::string xml = inBlock(R"(
  <speech id="s1"><text><sync id="t0"/>Hello <sync id="t1"/>there, how<sync id="t2"/> are you?<sync id="t4"/></text></speech>
  <gesture id="g0" lexeme="BEAT" stroke="s1:t0"/>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <gesture id="g2" lexeme="BEAT" stroke="s1:t2"/>
  <gesture id="g4" lexeme="BEAT" stroke="s1:t4"/>
  <gaze id="z1" target="camera" start="s1:start" end="s1:end"/>)");
    speech::SpeechTiming timing = madeUpTiming("Hello there, how are you?", 0.25);
    timing.duration = 1.5;
    const Resolved r = resolve(xml, {{"s1", timing}});
    EXPECT_EQ(at(r, "g0", BmlPoint::Stroke), 0);
    EXPECT_EQ(at(r, "g1", BmlPoint::Stroke), 0.25);
    EXPECT_EQ(at(r, "g2", BmlPoint::Stroke), 0.75); // "are": the word after the mark
    EXPECT_EQ(at(r, "g4", BmlPoint::Stroke), 1.25); // no word after: the end of the last
    EXPECT_EQ(r.at.at("s1"), (std::array<double, 7>{0, 0, 0, 0, 1.5, 1.5, 1.5}));
    EXPECT_EQ(at(r, "z1", BmlPoint::Start), 0);
    EXPECT_EQ(at(r, "z1", BmlPoint::End), 1.5);
}

TEST(BmlResolve, ASpeechShiftsAndStretchesWithItsMarks)
{
    const std::string text = "<text>One two <sync id='t2'/>three four</text>";
    const std::map<std::string, speech::SpeechTiming> timing{{"s1", madeUpTiming("One two three four", 0.5)}};
    const Resolved shifted =
        resolve(inBlock("<speech id='s1' start='1'>" + text + "</speech><head id='h1' lexeme='NOD' stroke='s1:t2'/>"),
                timing);
    EXPECT_EQ(at(shifted, "h1", BmlPoint::Stroke), 2);
    EXPECT_EQ(at(shifted, "s1", BmlPoint::End), 3);
    const Resolved stretched = resolve(
        inBlock("<speech id='s1' start='1' end='5'>" + text + "</speech><head id='h1' lexeme='NOD' stroke='s1:t2'/>"),
        timing);
    EXPECT_EQ(at(stretched, "h1", BmlPoint::Stroke), 3);
    EXPECT_EQ(at(stretched, "s1", BmlPoint::StrokeEnd), 5);
}

TEST(BmlResolve, ChainsOffsetsAndForwardReferences)
{
    const Resolved r = resolve(inBlock(R"(
  <gaze id="z1" target="camera" ready="h1:end"/>
  <speech id="s1" start="1.5"><text>Look <sync id="t1"/>here</text></speech>
  <gesture id="g1" lexeme="POINT" stroke="s1:t1 + 0.3"/>
  <head id="h1" lexeme="NOD" start="bml1:g1:stroke - 0.5"/>)"),
                               {{"s1", madeUpTiming("Look here", 0.4)}});
    EXPECT_NEAR(at(r, "g1", BmlPoint::Stroke), 1.5 + 0.4 + 0.3, 1e-12);
    EXPECT_NEAR(at(r, "h1", BmlPoint::Start), 2.2 - 0.5, 1e-12);
    EXPECT_NEAR(at(r, "z1", BmlPoint::Ready), 1.7 + 1.0, 1e-12);
    EXPECT_NEAR(at(r, "z1", BmlPoint::Start), 2.7 - 0.2, 1e-12);
    // A behaviour may refer to its own points when the chain ends elsewhere.
    const Resolved self = resolve(inBlock("<gesture id='g1' lexeme='BEAT' start='1' stroke='g1:start + 0.8'/>"));
    EXPECT_NEAR(at(self, "g1", BmlPoint::Stroke), 1.8, 1e-12);
    EXPECT_NEAR(at(self, "g1", BmlPoint::Ready), 1.4, 1e-12);
}

TEST(BmlResolve, EqualNaturalOffsetsBetweenPinsSpreadEvenly)
{
    // A speech's ready and strokeStart fall with its start: pinned apart, they share the span.
    const Resolved r = resolve(inBlock("<speech id='s1' start='0' stroke='3'><text>Hi</text></speech>"),
                               {{"s1", madeUpTiming("Hi", 1)}});
    EXPECT_EQ(r.at.at("s1"), (std::array<double, 7>{0, 1, 2, 3, 4, 4, 4}));
}

TEST(BmlResolve, NamesWhatDoesNotExist)
{
    const std::string speech = "<speech id='s1'><text>Hi <sync id='t1'/>you</text></speech>";
    const Resolved noBehaviour = resolve(inBlock(speech + "\n  <gesture id='g1' lexeme='BEAT' stroke='s2:t9'/>"),
                                         {{"s1", madeUpTiming("Hi you", 1)}});
    EXPECT_EQ(noBehaviour.error, "g1 (line 3, column 3): stroke refers to \"s2:t9\", which does not exist: the block "
                                 "has no behaviour \"s2\".");
    const Resolved noPoint = resolve(inBlock(speech + "<gesture id='g1' lexeme='BEAT' start='0' stroke='s1:t9'/>"),
                                     {{"s1", madeUpTiming("Hi you", 1)}});
    EXPECT_NE(noPoint.error.find("g1 (line 2, column "), std::string::npos) << noPoint.error;
    EXPECT_NE(noPoint.error.find(
                  "stroke refers to \"s1:t9\", which does not exist: <speech> \"s1\" has no sync point \"t9\""),
              std::string::npos)
        << noPoint.error;
    const Resolved noMark = resolve(inBlock("<head id='h1' lexeme='NOD'/><gaze id='z' target='c' end='h1:t1'/>"));
    EXPECT_NE(noMark.error.find("<head> \"h1\" has no sync point \"t1\""), std::string::npos) << noMark.error;
    const Resolved noTiming = resolve(inBlock(speech));
    EXPECT_EQ(noTiming.error, "s1 (line 2, column 1): no word timing was given for this speech.");
}

TEST(BmlResolve, NamesACycle)
{
    EXPECT_EQ(resolve(inBlock("<wait id='w' duration='1'/>\n<gesture id='g1' lexeme='BEAT' start='h1:end'/>\n"
                              "<head id='h1' lexeme='NOD' end='g1:start'/>"))
                  .error,
              "g1 (line 3, column 1): its sync references form a cycle: g1:start → h1:end → g1:start.");
    // h1's end follows from its start, which waits for g1; z1 waits behind the cycle, which is
    // named from its first point in the document.
    EXPECT_EQ(resolve(inBlock("<gaze id='z1' target='c' start='g1:end'/>\n<head id='h1' lexeme='NOD' "
                              "start='g1:start + 1'/><gesture id='g1' lexeme='BEAT' start='h1:end'/>"))
                  .error,
              "h1 (line 3, column 1): its sync references form a cycle: h1:start → g1:start → h1:end → h1:start.");
    EXPECT_NE(resolve(inBlock("<gesture id='g1' lexeme='BEAT' stroke='g1:start'/>"))
                  .error.find("g1:stroke → g1:start → g1:stroke"),
              std::string::npos);
}

TEST(BmlResolve, RefusesPinsOutOfOrder)
{
    EXPECT_EQ(resolve(inBlock("<gesture id='g1' lexeme='BEAT' start='2' end='w1:end'/><wait id='w1' duration='1.5'/>"))
                  .error,
              "g1 (line 2, column 1): its end (\"w1:end\", at 1.5 s) would come before its start (\"2\", at 2 s).");
    // Equal times keep the order.
    EXPECT_EQ(at(resolve(inBlock("<gesture id='g1' lexeme='BEAT' start='2' stroke='2'/>")), "g1", BmlPoint::Ready), 2);
}

TEST(BmlResolve, RefusesTimesItCannotPlace)
{
    EXPECT_NE(resolve(inBlock("<wait id='w1' start='1e308' duration='1'/><wait id='w2' start='w1:end + 1e308'/>"))
                  .error.find("w2 (line 2, column "),
              std::string::npos);
    const speech::BmlBlock block = parsed(inBlock("<gesture id='g1' lexeme='BEAT'/>"));
    const auto backwards = [](const speech::BmlBehavior&) { return std::array<double, 7>{0, 1, 0.5, 1, 1, 1, 1}; };
    auto times = speech::resolveBml(block, {}, backwards);
    ASSERT_FALSE(times.ok());
    EXPECT_EQ(times.error().message, "g1 (line 2, column 1): its natural timing is not finite and in order.");
    // Without a natural timing, a gesture takes no time.
    auto instant = speech::resolveBml(block, {}, {});
    ASSERT_TRUE(instant.ok());
    EXPECT_EQ((*instant)[0].at, (std::array<double, 7>{}));
}
