// libFuzzer target for the JSGF reader and matcher (core/speech/jsgf.h).
//
// Any bytes: parseJsgf returns a grammar or an error; an error of a grammar that has its header
// names "JSGF line L, column C", never crashes, hangs or throws. A grammar it reads resolves
// (its imports answered with the grammar itself) or fails naming a line, and the matcher answers
// for a few word sequences made of its own tokens without crashing.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "speech/jsgf.h"

namespace speech = thespis::core::speech;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_jsgf: %s\n%s\n", what, detail.c_str());
    std::abort();
}

bool namesPlace(const std::string& message)
{
    return message.find("line ") != std::string::npos && message.find(", column ") != std::string::npos;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    auto grammar = speech::parseJsgf(input);
    if (!grammar) {
        if (grammar.error().code != thespis::core::ErrorCode::NotOurFormat && !namesPlace(grammar.error().message))
            failure("an error without its line and column", grammar.error().message);
        return 0;
    }
    const std::string name = grammar->name;
    auto set = speech::resolveJsgf(std::move(*grammar), [&](const std::string&) -> thespis::core::Result<std::string> {
        return input; // every import reads this grammar again (under its own name)
    });
    if (!set) {
        if (!namesPlace(set.error().message))
            failure("an import error without its line and column", set.error().message);
        return 0;
    }
    if (set->grammars.empty() || set->grammars[0].name != name)
        failure("the set does not start with the grammar read", input);
    const std::vector<std::string> tokens = set->tokens();
    std::vector<std::string> words;
    (void)set->accepts(words);
    for (std::size_t i = 0; i < tokens.size() && i < 6; ++i) {
        words.push_back(tokens[i]);
        (void)set->accepts(words);
        (void)set->accepts(std::vector<std::string>{tokens[i], tokens[i]});
    }
    return 0;
}
