// libFuzzer target for opening a scenario package (core/scenario/package.h): any bytes as a
// .thespkg file. Package::open must refuse or accept with a message, never crash or hang; an
// accepted package must hand out every entry it lists with the manifest's size, and its scenario
// must parse or be refused with a message. Small limits keep each run fast (an input that
// expands to gigabytes is refused by them, as a user's would be by the defaults).

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "scenario/package.h"

namespace {

[[noreturn]] void failure(const char* what, const std::string& detail)
{
    std::fprintf(stderr, "fuzz_package: %s\n%s\n", what, detail.c_str());
    std::abort();
}

const std::filesystem::path& inputFile()
{
    static const std::filesystem::path file =
        std::filesystem::temp_directory_path() / ("fuzz_package_" + std::to_string(getpid()) + ".thespkg");
    return file;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
    using namespace thespis::core::scenario;
    {
        std::ofstream out(inputFile(), std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
    }
    PackageLimits limits;
    limits.maxEntryBytes = 1 << 20;
    limits.maxTotalBytes = 4 << 20;
    limits.maxEntries = 64;
    auto package = Package::open(inputFile(), limits);
    if (!package) {
        if (package.error().message.empty())
            failure("a refusal without a message", inputFile().string());
        return 0;
    }
    for (const PackageEntry& entry : (*package)->manifest().entries) {
        auto bytes = (*package)->read(entry.name);
        if (!bytes)
            failure("an entry of an accepted package cannot be read", entry.name + ": " + bytes.error().message);
        if (bytes->size() != entry.size)
            failure("an entry is not the manifest's size", entry.name);
    }
    if (auto scenario = (*package)->scenario(); !scenario && scenario.error().message.empty())
        failure("a scenario refused without a message", (*package)->manifest().scenario);
    return 0;
}
