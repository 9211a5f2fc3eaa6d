// libFuzzer target for the scenario reader (core/scenario/scenario_io.h).
//
// Any bytes: parseScenario must return a value or an error with a message, never crash, hang or
// throw. When it accepts the input, writing and reading again must give an equal Scenario and
// the same text (the writer's output is canonical), and building the runtime of a document
// whose clips are all inline must not crash either (BVH files are not opened: fuzzed names
// could point anywhere on disk).

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_scenario: %s\n%s\n", what, detail.c_str());
    std::abort();
}

bool allClipsInline(const thespis::core::scenario::Scenario& scenario)
{
    std::size_t floats = 0;
    for (const auto& character : scenario.characters)
        for (const auto& clip : character.clips) {
            if (!clip.file.empty())
                return false;
            floats += clip.frames.size();
        }
    // Keep each run fast: huge inline clips only test the allocator.
    return floats <= 100000;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace thespis::core::scenario;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto first = parseScenario(text);
    if (!first) {
        if (first.error().message.empty())
            failure("an error without a message", std::string(text));
        return 0;
    }

    const std::string written = serializeScenario(*first);
    auto second = parseScenario(written);
    if (!second)
        failure("the writer's output does not read back", describe(second.error()) + "\n" + written);
    if (!(*second == *first))
        failure("the scenario changed in a write/read round trip", written);
    if (serializeScenario(*second) != written)
        failure("writing is not stable", written);

    if (allClipsInline(*first)) {
        auto runtime = buildRuntime(*first, {});
        if (runtime) {
            // Evaluate each character once: building must leave schedules that can play.
            for (const auto& character : runtime->characters) {
                std::vector<float> frame(character.body->layout()->floatCount());
                character.body->evaluate(0.5, frame);
                std::vector<float> face(character.face->layout()->floatCount());
                character.face->evaluate(0.5, face);
            }
        } else if (runtime.error().message.empty()) {
            failure("a runtime error without a message", written);
        }
    }
    return 0;
}
