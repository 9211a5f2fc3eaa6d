// libFuzzer target for the AIML reader and the interpreter (core/dialogue).
//
// Any bytes as an AIML file: reading must report problems (never crash, hang or throw), and a bot
// built from what was read must answer a few inputs — with text, nothing, or a problem saying why
// it was cut — and its conversation must save and restore to the same state. Bytes after a NUL
// are said to the bot too (the AIML is what comes before), so the fuzzer steers the matching.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "dialogue/bot.h"
#include "dialogue/conversation.h"

namespace dialogue = thespis::core::dialogue;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_aiml: %s\n%s\n", what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > 64 * 1024)
        return 0;
    const std::string_view all(reinterpret_cast<const char*>(data), size);
    const std::size_t nul = std::min(all.find('\0'), all.size());
    const std::string_view text = all.substr(0, nul), said = all.substr(std::min(nul + 1, all.size()));
    dialogue::BotBuilder builder;
    builder.addProperties("[[\"name\", \"Fuzzy\"], [\"default-get\", \"unknown\"]]", "fuzz.properties");
    builder.addSet("color", "[[\"red\"], [\"dark\", \"blue\"]]", "color.set");
    builder.addMap("capital", "[[\"France\", \"Paris\"]]", "capital.map");
    builder.addSubstitutions("person", "[[\" I \", \" you \"], [\" you \", \" I \"]]", "person.substitution");
    builder.addAiml(text, "fuzz.aiml");
    dialogue::LoadedBot loaded = std::move(builder).build();
    for (const dialogue::LoadProblem& problem : loaded.problems)
        if (problem.message.empty() || problem.file.empty())
            failure("a problem without a message or file", dialogue::describe(problem));

    // Small limits keep each input fast; they are the same checks as the defaults.
    dialogue::Conversation conversation(loaded.bot, "fuzz");
    conversation.setLimits(dialogue::ConversationLimits{20, 200, 20, 20000, 100000});
    for (std::string_view input : {said, std::string_view("hello"), std::string_view("I like dark blue. What is * red?")}) {
        const dialogue::Answer answer = conversation.respond(input);
        if (!answer.problem.empty() && answer.problem.find("cut") == std::string::npos)
            failure("a problem that does not say the answer was cut", answer.problem);
    }
    const std::string saved = conversation.saveJson();
    auto restored = dialogue::Conversation::restore(loaded.bot, saved);
    if (!restored)
        failure("a saved conversation does not restore", restored.error().message + "\n" + saved);
    if (restored->saveJson() != saved)
        failure("a restored conversation saves differently", saved + "\n----\n" + restored->saveJson());
    return 0;
}
