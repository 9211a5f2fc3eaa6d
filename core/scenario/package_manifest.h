#pragma once
// A scenario package's manifest.json, the package's first entry: what wrote it, which entry is
// the scenario, and the size and SHA-256 of every other entry. A versioned document
// (util/json_document.h: "format": "thespis-package", "version"); a package of a newer version
// is refused as NewerVersion. Unknown fields survive a round trip.
//
//     {"format": "thespis-package", "version": 1, "writer": "Thespis Studio 0.9.0",
//      "scenario": "demo.thespis",
//      "entries": [{"name": "demo.thespis", "size": 5120, "sha256": "9f86…"}, …]}

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

#include "util/error.h"

namespace thespis::core::scenario {

inline constexpr std::string_view kPackageFormat = "thespis-package";
inline constexpr int kPackageVersion = 1;
inline constexpr std::string_view kManifestName = "manifest.json";

struct PackageEntry {
    std::string name;       ///< relative, '/'-separated (checkEntryName)
    std::uint64_t size = 0; ///< bytes, uncompressed
    std::string sha256;     ///< 64 lower-case hex digits
    bool operator==(const PackageEntry&) const = default;
};

struct PackageManifest {
    std::string writer;                 ///< the program and version that wrote the package
    std::string scenario;               ///< the entry holding the scenario
    std::vector<PackageEntry> entries;  ///< every entry but the manifest, in the package's order
    nlohmann::json extra = nlohmann::json::object();
    bool operator==(const PackageManifest&) const = default;

    const PackageEntry* find(std::string_view name) const;
};

/// Whether `name` may stand in a package: relative, '/'-separated, no empty, "." or ".."
/// components, no backslash, drive letter or control character, at most 512 bytes. The message
/// says what is wrong with it.
Result<void> checkEntryName(std::string_view name);

std::string serializeManifest(const PackageManifest& manifest);
/// Errors: NotOurFormat, NewerVersion, CorruptData naming the field ("entries[2].sha256: …").
Result<PackageManifest> parseManifest(std::string_view text);

} // namespace thespis::core::scenario
