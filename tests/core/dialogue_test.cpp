// core/dialogue: AIML 2.0 conformance element by element (small scripts written here, after the
// AIML 2.0 specification's examples), conversations with every real bot in the shared data
// (alice-1.6, free-aiml, program-y-ybot, rosie), and a saved conversation that continues.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>

#include "dialogue/bot.h"
#include "dialogue/conversation.h"
#include "dialogue/normalise.h"

namespace dialogue = thespis::core::dialogue;
using dialogue::Answer;
using dialogue::BotBuilder;
using dialogue::Conversation;

namespace {

const std::filesystem::path kData = std::filesystem::path(THESPIS_SHARED_DATA) / "dialogue";

std::string problemsOf(const std::vector<dialogue::LoadProblem>& problems)
{
    std::string text;
    for (const auto& problem : problems)
        text += dialogue::describe(problem) + "\n";
    return text;
}

// A bot of the given categories (wrapped in <aiml>), with optional data files added first.
std::shared_ptr<const dialogue::Bot> botOf(std::string_view categories, BotBuilder builder = {})
{
    builder.addAiml("<aiml version=\"2.0\">" + std::string(categories) + "</aiml>", "test.aiml");
    dialogue::LoadedBot loaded = std::move(builder).build();
    EXPECT_TRUE(loaded.problems.empty()) << problemsOf(loaded.problems);
    return loaded.bot;
}

std::string cat(std::string_view pattern, std::string_view templateXml)
{
    return "<category><pattern>" + std::string(pattern) + "</pattern><template>" + std::string(templateXml)
           + "</template></category>";
}

std::string say(Conversation& conversation, std::string_view input)
{
    const Answer answer = conversation.respond(input);
    EXPECT_TRUE(answer.problem.empty()) << input << ": " << answer.problem;
    return answer.text;
}

} // namespace

// --- Matching ----------------------------------------------------------------------------

TEST(DialogueMatch, WordsMatchInUpperCaseWithoutPunctuation)
{
    Conversation c(botOf(cat("HELLO THERE", "Hi!")));
    EXPECT_EQ(say(c, "hello, there"), "Hi!");
    EXPECT_EQ(say(c, "Hello there"), "Hi!");
    EXPECT_EQ(say(c, "goodbye"), "");
}

TEST(DialogueMatch, PriorityOrderOfWildcardsWordsAndSets)
{
    BotBuilder builder;
    builder.addSet("color", "[[\"red\"], [\"dark\", \"blue\"]]", "color.set");
    const std::string script = cat("I LIKE *", "star") + cat("I LIKE ^", "caret") + cat("I LIKE <set>color</set>", "set")
                               + cat("I LIKE RED", "word") + cat("I LIKE _", "underscore") + cat("I LIKE #", "hash")
                               + cat("I LIKE $RED", "dollar");
    Conversation c(botOf(script, std::move(builder)));
    EXPECT_EQ(say(c, "I like red"), "dollar");
    EXPECT_EQ(say(c, "I like green"), "hash");
    // Without $ and #, _ comes next; without _, the word, then the set, then ^ and *.
    Conversation d(botOf(cat("I LIKE *", "star") + cat("I LIKE ^", "caret") + cat("I LIKE RED", "word")
                         + cat("I LIKE _", "underscore")));
    EXPECT_EQ(say(d, "I like red"), "underscore");
    BotBuilder colors;
    colors.addSet("color", "red\ndark blue\n", "color.set");
    Conversation e(botOf(cat("I LIKE *", "star") + cat("I LIKE ^", "caret") + cat("I LIKE <set>color</set>", "set <star/>")
                             + cat("I LIKE RED", "word"),
                         std::move(colors)));
    EXPECT_EQ(say(e, "I like red"), "word");
    EXPECT_EQ(say(e, "I like dark blue"), "set dark blue");
    EXPECT_EQ(say(e, "I like green"), "caret");
    EXPECT_EQ(say(e, "I like"), "caret");
    Conversation f(botOf(cat("I LIKE *", "star")));
    EXPECT_EQ(say(f, "I like"), "");
    EXPECT_EQ(say(f, "I like it a lot"), "star");
}

TEST(DialogueMatch, ZeroOrMoreWildcardsMatchNothing)
{
    Conversation c(botOf(cat("# HELLO ^", "[<star/>|<star index=\"2\"/>]")));
    EXPECT_EQ(say(c, "hello"), "[|]");
    EXPECT_EQ(say(c, "well hello my friend"), "[well|my friend]");
}

TEST(DialogueMatch, BotPropertyAndNumberSetInPatterns)
{
    BotBuilder builder;
    builder.addProperties("[[\"name\", \"Rosie\"]]", "bot.properties");
    Conversation c(botOf(cat("<bot name=\"name\"/> *", "you called me: <star/>") + cat("ADD <set>number</set>", "<map name=\"successor\"><star/></map>"),
                         std::move(builder)));
    EXPECT_EQ(say(c, "Rosie come here"), "you called me: come here");
    EXPECT_EQ(say(c, "add 41"), "42");
    EXPECT_EQ(say(c, "add many"), "");
}

TEST(DialogueMatch, ThatAndTopicSelectCategories)
{
    const std::string script = cat("TELL ME A JOKE", "Knock knock.")
                               + "<category><pattern>WHO IS THERE</pattern><that>KNOCK KNOCK</that><template>Boo.<think><set name=\"topic\">jokes</set></think></template></category>"
                               + "<category><pattern>WHO IS THERE</pattern><template>Nobody.</template></category>"
                               + "<topic name=\"JOKES\"><category><pattern>*</pattern><template>Joke topic: <star/> (<thatstar/>)</template></category></topic>"
                               + "<category><pattern>*</pattern><that>* JOKE *</that><template>that: <thatstar index=\"2\"/></template></category>";
    Conversation c(botOf(script));
    EXPECT_EQ(say(c, "who is there"), "Nobody.");
    EXPECT_EQ(say(c, "tell me a joke"), "Knock knock.");
    EXPECT_EQ(say(c, "Who is there?"), "Boo.");
    EXPECT_EQ(say(c, "boo who"), "Joke topic: boo who (Boo)");
}

TEST(DialogueMatch, AnswerNamesTheCategoryAndItsPlace)
{
    Conversation c(botOf("\n" + cat("HELLO", "Hi") + "\n" + cat("HOW ARE YOU", "Fine")));
    const Answer answer = c.respond("Hello. How are you?");
    EXPECT_EQ(answer.text, "Hi Fine");
    ASSERT_EQ(answer.matched.size(), 2u);
    EXPECT_EQ(answer.matched[1].pattern, "HOW ARE YOU");
    EXPECT_EQ(answer.matched[1].that, "*");
    EXPECT_EQ(answer.matched[1].source.file, "test.aiml");
    EXPECT_EQ(answer.matched[1].source.line, 3);
    EXPECT_EQ(answer.matched[0].sentence, "HELLO");
}

// --- Template elements -------------------------------------------------------------------

TEST(DialogueTemplate, SraiSrAndStarsWithIndex)
{
    Conversation c(botOf(cat("HI", "Hello!") + cat("HEY *", "<sr/>") + cat("GREETINGS", "<srai>hi</srai>")
                         + cat("* AND *", "<star index=\"2\"/>+<star/>")));
    EXPECT_EQ(say(c, "greetings"), "Hello!");
    EXPECT_EQ(say(c, "hey hi"), "Hello!");
    EXPECT_EQ(say(c, "salt and pepper"), "pepper+salt");
}

TEST(DialogueTemplate, SetGetPredicatesAndLocalVars)
{
    Conversation c(botOf(cat("MY NAME IS *", "<think><set name=\"name\"><star/></set><set var=\"x\">local</set></think>Hi <get name=\"name\"/> <get var=\"x\"/>")
                         + cat("WHO AM I", "<get name=\"name\"/>/<get var=\"x\"/>") + cat("ELEMENT NAME", "<get><name>name</name></get>")));
    EXPECT_EQ(say(c, "my name is Ada"), "Hi Ada local");
    EXPECT_EQ(say(c, "who am I"), "Ada/unknown");
    EXPECT_EQ(say(c, "element name"), "Ada");
    EXPECT_EQ(c.state().predicates.at("name"), "Ada");
}

TEST(DialogueTemplate, BotThinkAndRandom)
{
    BotBuilder builder;
    builder.addProperties("name:Thespis\n", "bot.properties");
    Conversation c(botOf(cat("NAME", "<bot name=\"name\"/><think>hidden</think>") + cat("PICK", "<random><li>a</li><li>b</li><li>c</li></random>"),
                         std::move(builder)));
    EXPECT_EQ(say(c, "name"), "Thespis");
    std::set<std::string> picked;
    for (int i = 0; i < 60; ++i)
        picked.insert(say(c, "pick"));
    EXPECT_EQ(picked, (std::set<std::string>{"a", "b", "c"}));
}

TEST(DialogueTemplate, ConditionInAllThreeForms)
{
    const std::string script =
        cat("ONE", "<condition name=\"mood\" value=\"happy\">Yay</condition>")
        + cat("TWO", "<condition name=\"mood\"><li value=\"happy\">glad</li><li value=\"sad\">sorry</li><li>hm</li></condition>")
        + cat("THREE", "<condition><li name=\"mood\" value=\"sad\">sorry</li><li var=\"v\" value=\"*\">var</li><li>default</li></condition>")
        + cat("BOUND", "<condition name=\"mood\"><li value=\"*\">bound</li><li>unbound</li></condition>")
        + cat("SET *", "<think><set name=\"mood\"><star/></set></think>ok");
    Conversation c(botOf(script));
    EXPECT_EQ(say(c, "bound"), "unbound");
    EXPECT_EQ(say(c, "two"), "hm");
    EXPECT_EQ(say(c, "set happy"), "ok");
    EXPECT_EQ(say(c, "one"), "Yay");
    EXPECT_EQ(say(c, "two"), "glad");
    EXPECT_EQ(say(c, "bound"), "bound");
    EXPECT_EQ(say(c, "three"), "default");
    EXPECT_EQ(say(c, "set sad"), "ok");
    EXPECT_EQ(say(c, "one"), "");
    EXPECT_EQ(say(c, "three"), "sorry");
}

TEST(DialogueTemplate, ConditionLoopsAndLoopsAreCut)
{
    // The specification's counting loop: the li with <loop/> runs again until the value changes.
    const std::string count =
        "<think><set var=\"n\">0</set></think><condition var=\"n\"><li value=\"3\">done</li>"
        "<li><set var=\"n\"><map name=\"successor\"><get var=\"n\"/></map></set> <loop/></li></condition>";
    Conversation c(botOf(cat("COUNT", count) + cat("FOREVER", "<condition name=\"x\"><li>x<loop/></li></condition>")));
    EXPECT_EQ(say(c, "count"), "1 2 3 done");
    const Answer forever = c.respond("forever");
    EXPECT_EQ(forever.text, "");
    EXPECT_NE(forever.problem.find("looped 100 times"), std::string::npos) << forever.problem;
}

TEST(DialogueTemplate, SraiLoopIsCutWithAMessage)
{
    Conversation c(botOf(cat("WHAT IS *", "<srai><star/> IS WHAT</srai>") + cat("* IS WHAT", "<srai>WHAT IS <star/></srai>")
                         + cat("HELLO", "Hi")));
    const Answer answer = c.respond("what is what?");
    EXPECT_EQ(answer.text, "");
    EXPECT_NE(answer.problem.find("100 levels deep"), std::string::npos) << answer.problem;
    // The conversation goes on afterwards.
    EXPECT_EQ(say(c, "hello"), "Hi");
}

TEST(DialogueTemplate, MatchingThatWouldTakeAgesIsCut)
{
    // Ten wildcards before a word no input has: every way of splitting 60 words is tried.
    Conversation c(botOf(cat("* * * * * * * * * * NEVER", "x") + cat("HELLO", "Hi")));
    std::string input;
    for (int i = 0; i < 60; ++i)
        input += "word ";
    const Answer answer = c.respond(input);
    EXPECT_EQ(answer.text, "");
    EXPECT_NE(answer.problem.find("pattern nodes"), std::string::npos) << answer.problem;
    EXPECT_EQ(say(c, "hello"), "Hi");
}

TEST(DialogueTemplate, PersonGenderAndCase)
{
    BotBuilder builder;
    builder.addSubstitutions("person", "[[\" I \", \" you \"], [\" you \", \" I \"], [\" my \", \" your \"]]", "person.substitution");
    builder.addSubstitutions("person2", "[[\" I \", \" he or she \"]]", "person2.substitution");
    builder.addSubstitutions("gender", "[[\" he \", \" she \"], [\" she \", \" he \"]]", "gender.substitution");
    Conversation c(botOf(cat("SAY *", "<person/>|<person2><star/></person2>|<gender/>") + cat("CASE *", "<uppercase><star/></uppercase> <lowercase><star/></lowercase> <formal><star/></formal> <sentence><star/></sentence> <explode><star/></explode>"),
                         std::move(builder)));
    EXPECT_EQ(say(c, "say I like my cat and you"), "you like your cat and I|he or she like my cat and you|I like my cat and you");
    EXPECT_EQ(say(c, "say he told her she"), "he told her she|he told her she|she told her he");
    EXPECT_EQ(say(c, "case hello wORLD"), "HELLO WORLD hello world Hello World Hello wORLD h e l l o w O R L D");
}

TEST(DialogueTemplate, SubstitutionOfASpaceEnds)
{
    // Found by fuzz_bot_files: a rule of one space sharing its space with the next never moved on.
    const dialogue::Substitutions spaces(dialogue::Pairs{{" ", " _ "}});
    EXPECT_EQ(spaces.apply("a b"), "_ a _ b _");
}

TEST(DialogueTemplate, MapsFirstRestNormalize)
{
    BotBuilder builder;
    builder.addMap("capital", "[[\"France\", \"Paris\"], [\"New York\", \"Albany\"]]", "capital.map");
    builder.addSubstitutions("normal", "[[\" dont \", \" do not \"]]", "normal.substitution");
    builder.addSubstitutions("denormal", "[[\" do not \", \" dont \"]]", "denormal.substitution");
    builder.addProperties("[[\"default-map\", \"nowhere\"]]", "bot.properties");
    Conversation c(botOf(cat("CAPITAL OF *", "<map name=\"capital\"><star/></map>") + cat("WORDS *", "<first><star/></first>/<rest><star/></rest>")
                             + cat("I DO NOT *", "<normalize>dont</normalize>|<denormalize>do not</denormalize>")
                             + cat("PLURAL *", "<map><name>plural</name><star/></map>"),
                         std::move(builder)));
    EXPECT_EQ(say(c, "capital of new york"), "Albany");
    EXPECT_EQ(say(c, "capital of france"), "Paris");
    EXPECT_EQ(say(c, "capital of mars"), "nowhere");
    EXPECT_EQ(say(c, "words a b c"), "a/b c");
    EXPECT_EQ(say(c, "words a"), "a/NIL");
    EXPECT_EQ(say(c, "I dont know"), "do not|dont");
    EXPECT_EQ(say(c, "plural city"), "cities");
}

TEST(DialogueTemplate, DateAndInterval)
{
    Conversation c(botOf(cat("YEAR", "<date format=\"%Y\"/>") + cat("JYEAR", "<date jformat=\"yyyy\"/>")
                         + cat("DAYS", "<interval format=\"%B %d, %Y\"><style>days</style><from>January 1, 2020</from><to>March 1, 2020</to></interval>")
                         + cat("YEARS", "<interval jformat=\"MMMMMMMMM dd, yyyy\"><style>years</style><from>August 29, 2014</from><to>August 28, 2024</to></interval>")));
    const std::string year = say(c, "year");
    EXPECT_EQ(year.size(), 4u);
    EXPECT_GE(year, "2024");
    EXPECT_EQ(say(c, "jyear"), year);
    EXPECT_EQ(say(c, "days"), "60");
    EXPECT_EQ(say(c, "years"), "9");
}

TEST(DialogueTemplate, InputThatRequestResponseHistory)
{
    Conversation c(botOf(cat("A", "First. Second.") + cat("B", "<that index=\"1,2\"/>|<that/>|<input/>|<input index=\"2\"/>|<request/>|<response/>")));
    say(c, "a");
    // <input/> is the sentence being answered; <request/> and <response/> the previous exchange.
    EXPECT_EQ(say(c, "b!"), "First|Second|b|a|a|First. Second.");
}

TEST(DialogueTemplate, IdSizeVocabularyProgram)
{
    Conversation c(botOf(cat("INFO", "<id/> <size/> <vocabulary/>") + cat("PROGRAM", "<program/>")), "guest-7");
    EXPECT_EQ(say(c, "info"), "guest-7 2 2"); // categories; words INFO and PROGRAM
    EXPECT_NE(say(c, "program").find("Thespis"), std::string::npos);
}

TEST(DialogueTemplate, LearnedCategoriesStayInTheConversation)
{
    const std::string script = cat("WHEN I SAY * SAY *",
                                    "<learn><category><pattern><eval><uppercase><star/></uppercase></eval></pattern>"
                                    "<template><eval><star index=\"2\"/></eval></template></category></learn>OK")
                               + cat("PING", "pong");
    auto bot = botOf(script);
    Conversation c(bot), other(bot);
    EXPECT_EQ(say(c, "when I say ping say beep"), "OK");
    EXPECT_EQ(say(c, "ping"), "beep"); // the same pattern learned later wins
    EXPECT_EQ(say(c, "when I say marco say polo"), "OK");
    EXPECT_EQ(say(c, "marco"), "polo");
    ASSERT_EQ(c.learnedCategories().size(), 2u);
    EXPECT_EQ(c.learnedCategories()[1].pattern, "MARCO");
    EXPECT_EQ(say(other, "marco"), "");
    EXPECT_EQ(say(other, "ping"), "pong");
}

TEST(DialogueTemplate, SpeechMarkupAndUnknownElementsPassThrough)
{
    const std::string gesture = "<begin_gesture id=\"g1\" anim=\"wave\"/>Hello <star/>!<end_gesture id=\"g1\"/>";
    const std::string bml = "<bml id=\"b1\"><gesture id=\"x\" lexeme=\"BEAT\" start=\"0.5\"/><speech id=\"s\"><text>Hi</text></speech></bml>";
    Conversation c(botOf(cat("GREET *", gesture) + cat("BML", bml) + cat("HTML", "Look <a href=\"x.html?a=1&amp;b=2\">here</a> &amp; <oob><search>cats</search></oob>")));
    EXPECT_EQ(say(c, "greet Ada"), "<begin_gesture id=\"g1\" anim=\"wave\"/>Hello Ada!<end_gesture id=\"g1\"/>");
    EXPECT_EQ(say(c, "bml"), bml);
    EXPECT_EQ(say(c, "html"), "Look <a href=\"x.html?a=1&amp;b=2\">here</a> &amp; <oob><search>cats</search></oob>");
}

// --- Loading -----------------------------------------------------------------------------

TEST(DialogueLoad, MalformedFilesAreReportedWithLineAndTheRestLoads)
{
    BotBuilder builder;
    builder.addAiml("<aiml>\n" + cat("GOOD", "yes") + "\n<category><pattern>BAD</pattern>\n<template>oops</li></template></category></aiml>", "broken.aiml");
    builder.addAiml("<aiml>" + cat("OTHER", "fine") + "<category><template>no pattern</template></category></aiml>", "other.aiml");
    builder.addSet("things", "[[\"a\"],\n[\"b\", 3]]", "things.set");
    builder.addMap("pairs", "one:1\ntwo\n", "pairs.map");
    builder.addAiml("<aiml>" + cat("I SEE <set>unknown</set>", "x") + "</aiml>", "sets.aiml");
    dialogue::LoadedBot loaded = std::move(builder).build();
    const std::string problems = problemsOf(loaded.problems);
    EXPECT_NE(problems.find("broken.aiml:4:"), std::string::npos) << problems;
    EXPECT_NE(problems.find("mismatched tag"), std::string::npos) << problems;
    EXPECT_NE(problems.find("other.aiml:1:"), std::string::npos) << problems;
    EXPECT_NE(problems.find("things.set:2"), std::string::npos) << problems;
    EXPECT_NE(problems.find("pairs.map:2"), std::string::npos) << problems;
    EXPECT_NE(problems.find("sets.aiml:1: the pattern uses the set \"unknown\""), std::string::npos) << problems;
    EXPECT_EQ(loaded.problems.size(), 5u) << problems;
    Conversation c(loaded.bot);
    EXPECT_EQ(say(c, "good"), "yes");
    EXPECT_EQ(say(c, "other"), "fine");
    EXPECT_EQ(loaded.bot->sets().at("things").phrases, std::vector<std::string>{"a"});
    EXPECT_EQ(loaded.bot->maps().at("pairs").at("ONE"), "1");
}

TEST(DialogueLoad, MissingFolderIsAnError)
{
    const auto loaded = dialogue::loadBotFolder(kData / "no-such-bot");
    ASSERT_FALSE(loaded.ok());
    EXPECT_EQ(loaded.error().code, thespis::core::ErrorCode::FileNotFound);
}

// --- Real bots ---------------------------------------------------------------------------

namespace {

std::vector<std::filesystem::path> aimlFilesIn(const std::filesystem::path& folder)
{
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(folder))
        if (entry.path().extension() == ".aiml")
            files.push_back(entry.path());
    std::sort(files.begin(), files.end());
    EXPECT_FALSE(files.empty()) << folder;
    return files;
}

std::shared_ptr<const dialogue::Bot> rosie()
{
    static const dialogue::LoadedBot loaded = [] {
        auto result = dialogue::loadBotFolder(kData / "rosie");
        EXPECT_TRUE(result.ok()) << (result.ok() ? "" : result.error().message);
        return result.ok() ? std::move(result).value() : dialogue::LoadedBot{};
    }();
    return loaded.bot;
}

} // namespace

TEST(DialogueRosie, LoadsEveryCategoryAndDataFile)
{
    auto loaded = dialogue::loadBotFolder(kData / "rosie");
    ASSERT_TRUE(loaded.ok());
    const std::string problems = problemsOf(loaded->problems);
    // Two of Rosie's patterns use Pandorabots' "season" and "acronym" sets, which it does not ship.
    for (const auto& problem : loaded->problems)
        EXPECT_NE(problem.message.find("the pattern uses the set"), std::string::npos) << problems;
    EXPECT_EQ(loaded->problems.size(), 2u) << problems;
    const dialogue::Bot& bot = *loaded->bot;
    EXPECT_GT(bot.categories().size(), 12000u);
    EXPECT_EQ(bot.sets().size(), 42u);
    EXPECT_EQ(bot.maps().size(), 32u);
    EXPECT_EQ(bot.property("name"), "Rosie");
    EXPECT_EQ(bot.predicateDefaults().at("env"), "browser");
    EXPECT_GT(bot.substitutions("normal").size(), 100u);
    EXPECT_TRUE(bot.sets().at("month").matchKeys.contains("SEPTEMBER"));
    EXPECT_EQ(bot.maps().at("state2capital").at("WY"), "Cheyenne");
    // What the grammar generator reads: the categories as written, with their file and line.
    const auto hello = std::find_if(bot.categories().begin(), bot.categories().end(),
                                    [](const dialogue::Category& c) { return c.pattern == "HELLO"; });
    ASSERT_NE(hello, bot.categories().end());
    EXPECT_NE(hello->source.file.find("reductions1.aiml"), std::string::npos);
    EXPECT_EQ(hello->source.line, 5324);
    const auto withSet = std::find_if(bot.categories().begin(), bot.categories().end(),
                                      [](const dialogue::Category& c) { return c.pattern == "GENDERNAME <set>name</set>"; });
    ASSERT_NE(withSet, bot.categories().end());
    EXPECT_EQ(dialogue::patternTokens(withSet->pattern), (std::vector<std::string_view>{"GENDERNAME", "<set>name</set>"}));
}

TEST(DialogueRosie, AnswersHelloThroughItsReduction)
{
    Conversation c(rosie());
    const Answer answer = c.respond("Hello!");
    // reductions1.aiml: HELLO → <srai>HI</srai>; personality.aiml's HI answers at random, every
    // answer starting with "Hi".
    EXPECT_TRUE(answer.text.starts_with("Hi")) << answer.text;
    ASSERT_EQ(answer.matched.size(), 1u);
    EXPECT_EQ(answer.matched[0].pattern, "HELLO");
}

TEST(DialogueRosie, RemembersTheVisitorsName)
{
    Conversation c(rosie());
    // reductions1.aiml: MY NAME IS * → CALL ME *, which client_profile.aiml answers and sets "name".
    EXPECT_EQ(say(c, "My name is Ada."), "How are you doing, Ada.");
    EXPECT_EQ(c.state().predicates.at("name"), "Ada");
    // ("My name is Alice" would not do: reductions_update.aiml's "_ ALICE" outranks "MY NAME IS *".)
    EXPECT_EQ(say(c, "What is my name?"), "Ada.");
}

TEST(DialogueRosie, SetsAndMapsAnswerKnowledgeQuestions)
{
    Conversation c(rosie());
    // knowledge.aiml: WHAT IS THE CAPITAL OF <set>nation</set> → <map name="nation2capital">.
    const Answer answer = c.respond("What is the capital of France?");
    EXPECT_EQ(answer.text, "Paris.");
    ASSERT_EQ(answer.matched.size(), 1u);
    EXPECT_EQ(answer.matched[0].pattern, "WHAT IS THE CAPITAL OF <set>nation</set>");
    EXPECT_EQ(say(c, "knock knock"), "Who is there?"); // personality.aiml:1794
}

TEST(DialogueAlice, SraiReductionsAndBadAnswerLearning)
{
    const auto files = aimlFilesIn(kData / "alice-1.6");
    dialogue::LoadedBot loaded = dialogue::loadBotFiles(files);
    EXPECT_TRUE(loaded.problems.empty()) << problemsOf(loaded.problems);
    EXPECT_GT(loaded.bot->categories().size(), 300u);
    Conversation c(loaded.bot);
    // reductions-update.aiml: MY _ S NAME IS * → <srai>MY <star/> IS CALLED <star index="2"/></srai>.
    const Answer answer = c.respond("My dog's name is Rex");
    ASSERT_FALSE(answer.matched.empty());
    EXPECT_EQ(answer.matched[0].pattern, "MY _ S NAME IS *");
    // badanswer.aiml teaches a new answer through topics, <that>, <input>/<that>/<response>
    // history, condition on predicates and <learn> with <eval>.
    c.respond("What is your favorite color?");
    EXPECT_EQ(say(c, "Bad answer"), "Would you like to teach me a new answer to \"What is your favorite color\"?");
    EXPECT_EQ(say(c, "yes"), "OK, what should I have said?");
    EXPECT_TRUE(say(c, "Blue is nice").starts_with("\"Blue is nice...\"? Does this depend on me having just said"));
    EXPECT_EQ(say(c, "no"), "I'll try to remember to respond, \"Blue is nice\" when you say, \"What is your favorite color\"");
    const Answer learned = c.respond("What is your favorite color?");
    EXPECT_EQ(learned.text, "Blue is nice");
    ASSERT_EQ(learned.matched.size(), 1u);
    EXPECT_TRUE(learned.matched[0].learned);
    EXPECT_EQ(learned.matched[0].pattern, "WHAT IS YOUR FAVORITE COLOR");
}

TEST(DialogueFreeAiml, KnockKnockFollowsThatAndCopyMeFollowsTheTopic)
{
    BotBuilder builder;
    for (const auto& file : aimlFilesIn(kData / "free-aiml"))
        builder.addFile(file);
    // knockknock.aiml expects another file to start the joke ("put Knock knock into pickup.aiml").
    builder.addAiml("<aiml>" + cat("TELL ME A JOKE", "Knock knock.") + "</aiml>", "pickup.aiml");
    dialogue::LoadedBot loaded = std::move(builder).build();
    EXPECT_TRUE(loaded.problems.empty()) << problemsOf(loaded.problems);
    Conversation c(loaded.bot);
    EXPECT_EQ(say(c, "Tell me a joke"), "Knock knock.");
    EXPECT_EQ(say(c, "banana"), "You're supposed to say, \"Who's there\" now. Let's try it again. Knock Knock.");
    // free-aiml has no substitutions turning "who's" into "who is".
    const std::string name = say(c, "Who is there?");
    ASSERT_FALSE(name.empty());
    const Answer punchline = c.respond(name + " who?");
    ASSERT_EQ(punchline.matched.size(), 1u) << name;
    EXPECT_EQ(punchline.matched[0].that, dialogue::matchForm(name));
    EXPECT_FALSE(punchline.text.empty());
    // copyme.aiml: the topic COPYME repeats what is said until told twice to stop.
    EXPECT_EQ(say(c, "copy me"), "Ok I will copy everything you say.");
    EXPECT_EQ(say(c, "bananas are yellow"), "bananas are yellow");
    EXPECT_EQ(say(c, "stop it"), "No I am having fun.");
    EXPECT_EQ(say(c, "I am a parrot"), "I am a parrot");
    EXPECT_EQ(say(c, "stop it"), "Ok, I'll stop it now. Hope I didn't annoy you too much.");
    EXPECT_EQ(c.state().predicates.at("topic"), "");
}

TEST(DialogueYbot, ThatBasedReply)
{
    dialogue::LoadedBot loaded = dialogue::loadBotFiles(aimlFilesIn(kData / "program-y-ybot"));
    const std::string problems = problemsOf(loaded.problems);
    for (const auto& problem : loaded.problems) // y-bot's files refer to sets and maps of the whole y-bot
        EXPECT_NE(problem.message.find("the pattern uses the"), std::string::npos) << problems;
    Conversation c(loaded.bot);
    EXPECT_EQ(say(c, "ywhythattest"), "WHY");
    EXPECT_EQ(say(c, "because I can"), "Interesting explanation.");
    // defaults_topics_hello.aiml: "# HI #" (zero words on either side) → <srai>HELLO</srai>.
    const Answer hello = c.respond("hi");
    ASSERT_EQ(hello.matched.size(), 1u);
    EXPECT_EQ(hello.matched[0].pattern, "# HI #");
    EXPECT_FALSE(hello.text.empty());
}

// --- State -------------------------------------------------------------------------------

TEST(DialogueState, SavedConversationContinues)
{
    const std::string script = cat("MY NAME IS *", "<think><set name=\"name\"><star/></set></think>Hello <get name=\"name\"/>.")
                               + cat("WHAT IS MY NAME", "<get name=\"name\"/>") + cat("JOKE", "Knock knock.")
                               + "<category><pattern>WHO IS THERE</pattern><that>KNOCK KNOCK</that><template>Boo.</template></category>"
                               + cat("LEARN *", "<learn><category><pattern><eval><star/></eval></pattern><template>learned <eval><star/></eval></template></category></learn>")
                               + cat("RANDOM", "<random><li>1</li><li>2</li><li>3</li><li>4</li><li>5</li><li>6</li></random>");
    auto bot = botOf(script);
    Conversation original(bot, "visitor-1");
    say(original, "my name is Ada");
    say(original, "learn xyzzy");
    say(original, "joke");
    const std::string saved = original.saveJson();
    EXPECT_NE(saved.find("\"format\": \"thespis-conversation\""), std::string::npos);
    auto restored = Conversation::restore(bot, saved);
    ASSERT_TRUE(restored.ok()) << restored.error().message;
    EXPECT_EQ(restored->saveJson(), saved);
    EXPECT_EQ(say(*restored, "who is there"), "Boo.");
    EXPECT_EQ(say(*restored, "what is my name"), "Ada");
    EXPECT_EQ(say(*restored, "xyzzy"), "learned xyzzy");
    EXPECT_EQ(restored->learnedCategories().size(), 1u);
    // The random generator continues where it was: both sides now pick the same.
    say(original, "who is there");
    for (int i = 0; i < 5; ++i)
        EXPECT_EQ(say(*restored, "random"), say(original, "random"));
}

TEST(DialogueState, BadDocumentsAreRefused)
{
    auto bot = botOf(cat("HI", "Hello"));
    EXPECT_EQ(Conversation::restore(bot, "{\"format\": \"other\", \"version\": 1}").error().code, thespis::core::ErrorCode::NotOurFormat);
    EXPECT_EQ(Conversation::restore(bot, "{\"format\": \"thespis-conversation\", \"version\": 9}").error().code, thespis::core::ErrorCode::NewerVersion);
    const auto wrongType = Conversation::restore(bot, "{\"format\": \"thespis-conversation\", \"version\": 1, \"inputs\": 3}");
    ASSERT_FALSE(wrongType.ok());
    EXPECT_EQ(wrongType.error().code, thespis::core::ErrorCode::CorruptData);
    EXPECT_TRUE(wrongType.error().message.starts_with("inputs:")) << wrongType.error().message;
}
