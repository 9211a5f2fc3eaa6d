#pragma once
// Opening a scenario package (package_export_job.h writes them): the zip is checked before
// anything in it is used, and every refusal names the entry.
//   - manifest.json comes first and parses (a newer version is NewerVersion);
//   - every entry's name is relative and stays inside (no absolute path, '..', backslash or
//     drive), none is a symbolic link, none appears twice;
//   - every entry is in the manifest and every manifest entry in the zip;
//   - no entry is larger than the limit, nor compressed more than the ratio allows (a zip bomb
//     expands kilobytes into gigabytes), nor are all of them together;
//   - every entry's size and SHA-256 are the manifest's (CorruptData naming it).
// Reading an entry checks its digest again. Scripts inside come with the scenario; whether they
// run is the caller's decision (the studio asks the user to trust the package first).

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "scenario/package_manifest.h"
#include "scenario/scenario.h"
#include "util/error.h"

namespace thespis::core::scenario {

inline constexpr std::string_view kPackageExtension = ".thespkg";

struct PackageLimits {
    std::uint64_t maxEntryBytes = std::uint64_t(2) << 30;  ///< one entry, uncompressed
    std::uint64_t maxTotalBytes = std::uint64_t(8) << 30;  ///< all entries, uncompressed
    double maxCompressionRatio = 200; ///< uncompressed / compressed, for entries above 64 KiB
    std::uint64_t maxEntries = 100000;
};

class Package {
public:
    /// Opens and checks the package (see above). Errors: FileNotFound, NotOurFormat (not a zip, or
    /// no manifest first), NewerVersion, CorruptData naming the entry and what is wrong with it.
    static Result<std::unique_ptr<Package>> open(const std::filesystem::path& file, const PackageLimits& limits = {});
    ~Package();
    Package(const Package&) = delete;
    Package& operator=(const Package&) = delete;

    const std::filesystem::path& file() const;
    const PackageManifest& manifest() const;
    /// An entry's bytes, checked against the manifest. Errors: NotFound listing nothing more than
    /// the name, CorruptData when it no longer matches.
    Result<std::string> read(const std::string& name) const;
    /// The package's scenario document.
    Result<Scenario> scenario() const;
    /// Writes every entry under `folder` (created if missing), each file atomically, and returns
    /// the scenario's path there. Refuses to replace a file that is already there and differs.
    /// Without `withScenario`, the scenario's own entry is left out (its caller writes it).
    Result<std::filesystem::path> extractTo(const std::filesystem::path& folder, bool withScenario = true) const;

private:
    struct State;
    explicit Package(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

} // namespace thespis::core::scenario
