// libFuzzer target for the BML reader and sync resolver (core/speech/bml.h).
//
// Any bytes: parseBml must return a block or an error with "line L, column C: …", never crash,
// hang or throw. A block it accepts writes back to BML that reads equal (up to line and column),
// and resolving it over a made-up timing either fails, naming a behaviour, or gives every
// behaviour finite points in order, each constrained point exactly where its reference says.

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <string_view>

#include "speech/bml.h"
#include "../core/made_up_timing.h"

namespace speech = thespis::core::speech;

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_bml: %s\n%s\n", what, detail.c_str());
    std::abort();
}

std::array<double, speech::kBmlPointCount> oneSecond(const speech::BmlBehavior&)
{
    return {0, 0.2, 0.3, 0.4, 0.5, 0.7, 1.0};
}

speech::BmlBlock withoutPlaces(speech::BmlBlock block)
{
    for (speech::BmlBehavior& b : block.behaviors)
        b.line = b.column = 0;
    return block;
}

void checkResolution(const speech::BmlBlock& block, const std::string& input)
{
    std::map<std::string, speech::SpeechTiming> timing;
    for (const speech::BmlBehavior& b : block.behaviors)
        if (b.kind == speech::BmlBehaviorKind::Speech)
            timing[b.id] = thespis::test::madeUpTiming(b.text, 0.1);
    auto resolved = speech::resolveBml(block, timing, &oneSecond);
    if (!resolved) {
        const std::string& message = resolved.error().message;
        const bool namesOne = std::any_of(block.behaviors.begin(), block.behaviors.end(), [&](const auto& b) {
            return message.rfind(b.id + " (line ", 0) == 0;
        });
        if (!namesOne)
            failure("a resolution error that does not name a behaviour", message + "\n" + input);
        return;
    }
    if (resolved->size() != block.behaviors.size())
        failure("not one set of times per behaviour", input);
    std::map<std::string, std::array<double, speech::kBmlPointCount>> at;
    for (std::size_t i = 0; i < resolved->size(); ++i) {
        const speech::BmlTimes& times = (*resolved)[i];
        if (times.behavior != block.behaviors[i].id)
            failure("times out of document order", input);
        for (int p = 0; p < speech::kBmlPointCount; ++p)
            if (!std::isfinite(times.at[p]) || (p > 0 && times.at[p] < times.at[p - 1]))
                failure("a behaviour's points not finite and in order", times.behavior + "\n" + input);
        at[times.behavior] = times.at;
    }
    for (const speech::BmlBehavior& b : block.behaviors)
        for (const auto& [point, ref] : b.sync) {
            const auto target = speech::bmlPointNamed(ref.point);
            if (!ref.behavior.empty() && !target)
                continue; // a speech's sync mark: its time is not among the results
            const double expected = ref.behavior.empty() ? ref.offset : at[ref.behavior][int(*target)] + ref.offset;
            if (at[b.id][int(point)] != expected)
                failure("a constrained point away from its reference", b.id + "\n" + input);
        }
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    const std::string input(reinterpret_cast<const char*>(data), size);
    auto first = speech::parseBml(input);
    if (!first) {
        const std::string& message = first.error().message;
        if (message.rfind("line ", 0) != 0 || message.find(", column ") == std::string::npos)
            failure("an error without its line and column", message);
        return 0;
    }
    const std::string written = speech::bmlString(*first);
    auto second = speech::parseBml(written);
    if (!second)
        failure("the writer's output does not read back", second.error().message + "\n" + written);
    if (!(withoutPlaces(*first) == withoutPlaces(*second)))
        failure("the block changed in a write/read round trip", input + "\n---\n" + written);
    checkResolution(*first, input);
    return 0;
}
