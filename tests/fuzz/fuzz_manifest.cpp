// libFuzzer target for the package manifest reader (core/scenario/package_manifest.h).
//
// Any bytes: parseManifest must return a value or an error with a message, never crash, hang or
// throw. When it accepts the input, writing and reading again must give an equal manifest and
// the same text, and every entry name it accepted must pass checkEntryName.

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

#include "scenario/package_manifest.h"

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_manifest: %s\n%s\n", what, detail.c_str());
    std::abort();
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace thespis::core::scenario;
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    auto first = parseManifest(text);
    if (!first) {
        if (first.error().message.empty())
            failure("an error without a message", std::string(text));
        return 0;
    }
    for (const PackageEntry& entry : first->entries)
        if (!checkEntryName(entry.name))
            failure("an entry name that checkEntryName refuses was accepted", entry.name);
    const std::string written = serializeManifest(*first);
    auto second = parseManifest(written);
    if (!second)
        failure("the writer's output does not read back", written);
    if (!(*second == *first))
        failure("the manifest changed in a write/read round trip", written);
    if (serializeManifest(*second) != written)
        failure("writing is not stable", written);
    return 0;
}
