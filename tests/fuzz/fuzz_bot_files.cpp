// libFuzzer target for the readers of a bot's data files (core/dialogue/bot_files.h and the
// substitutions of normalise.h).
//
// Any bytes as a set, a map/properties/substitution file: reading returns what it could with
// problems naming a line, never crashes, hangs or throws. Every phrase a set keeps matches as
// itself, and substitutions built from the pairs apply to any text without growing it beyond
// what the rules allow.

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "dialogue/bot_files.h"
#include "dialogue/normalise.h"

namespace dialogue = thespis::core::dialogue;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_bot_files: %s\n%s\n", what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    if (size > 64 * 1024)
        return 0;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    std::vector<dialogue::LoadProblem> problems;
    const dialogue::PhraseSet set = dialogue::readSet(text, "fuzz.set", problems);
    for (const std::string& phrase : set.phrases)
        if (!set.matchKeys.contains(dialogue::matchForm(phrase)))
            failure("a set's phrase does not match itself", phrase);
    const dialogue::Pairs pairs = dialogue::readPairs(text, "fuzz.map", problems);
    for (const dialogue::LoadProblem& problem : problems)
        if (problem.line < 0 || problem.message.empty())
            failure("a problem without line or message", problem.message);
    const dialogue::Substitutions substitutions(pairs);
    std::size_t longest = 1;
    for (const auto& [from, to] : pairs)
        longest = std::max(longest, to.size() + 1);
    const std::string applied = substitutions.apply(text);
    if (applied.size() > (text.size() + 2) * longest)
        failure("substitution output grew beyond its rules", applied);
    return 0;
}
