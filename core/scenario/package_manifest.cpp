// A scenario package's manifest (package_manifest.h).

#include "scenario/package_manifest.h"

#include <set>

#include "scenario/scenario_object_reader.h"
#include "util/json_document.h"

namespace thespis::core::scenario {

namespace {

constexpr std::size_t kMaxNameBytes = 512;

bool isHexDigest(const std::string& text)
{
    if (text.size() != 64)
        return false;
    for (const char c : text)
        if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f')))
            return false;
    return true;
}

} // namespace

const PackageEntry* PackageManifest::find(std::string_view name) const
{
    for (const PackageEntry& entry : entries)
        if (entry.name == name)
            return &entry;
    return nullptr;
}

Result<void> checkEntryName(std::string_view name)
{
    const auto refuse = [&](const std::string& why) {
        return makeError(ErrorCode::CorruptData, "The entry " + json_document::quote(name) + " " + why + ".");
    };
    if (name.empty())
        return refuse("has no name");
    if (name.size() > kMaxNameBytes)
        return refuse("has a name longer than " + std::to_string(kMaxNameBytes) + " bytes");
    if (name.front() == '/')
        return refuse("is an absolute path: a package holds only relative names");
    if (name.size() >= 2 && name[1] == ':')
        return refuse("names a drive: a package holds only relative names");
    for (const char c : name) {
        if (c == '\\')
            return refuse("has a backslash: a package separates folders with '/'");
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f)
            return refuse("has a control character in its name");
    }
    std::size_t start = 0;
    while (start <= name.size()) {
        const std::size_t end = std::min(name.find('/', start), name.size());
        const std::string_view part = name.substr(start, end - start);
        if (part == "..")
            return refuse("climbs out of the package with '..'");
        if (part.empty() || part == ".")
            return refuse("has an empty or '.' folder in its name");
        start = end + 1;
    }
    return {};
}

std::string serializeManifest(const PackageManifest& manifest)
{
    nlohmann::ordered_json document;
    document["format"] = kPackageFormat;
    document["version"] = kPackageVersion;
    document["writer"] = manifest.writer;
    document["scenario"] = manifest.scenario;
    nlohmann::ordered_json entries = nlohmann::ordered_json::array();
    for (const PackageEntry& entry : manifest.entries)
        entries.push_back({{"name", entry.name}, {"size", entry.size}, {"sha256", entry.sha256}});
    document["entries"] = std::move(entries);
    for (const auto& [key, value] : manifest.extra.items())
        document[key] = value;
    return document.dump(2) + "\n";
}

Result<PackageManifest> parseManifest(std::string_view text)
{
    using detail::ObjectReader;
    static constexpr json_document::Kind kManifest{"package manifest", kPackageFormat, 1, kPackageVersion};
    auto parsed = json_document::parseVersioned(text, kManifest);
    if (!parsed)
        return parsed.error();
    try {
        ObjectReader reader(parsed->document, "", "");
        (void)reader.find("format");
        (void)reader.find("version");
        PackageManifest manifest;
        manifest.writer = reader.string("writer", true);
        manifest.scenario = reader.name("scenario");
        const nlohmann::json& entries = reader.array("entries", true);
        std::set<std::string> seen;
        for (std::size_t i = 0; i < entries.size(); ++i) {
            ObjectReader entryReader(entries[i], json_document::indexed("entries", i), "");
            PackageEntry entry;
            entry.name = entryReader.name();
            if (auto allowed = checkEntryName(entry.name); !allowed) {
                std::string why = allowed.error().message;
                why.pop_back(); // its full stop: the reader's message ends with one
                json_document::fail(entryReader.fieldPath("name"), why);
            }
            if (entry.name == kManifestName)
                json_document::fail(entryReader.fieldPath("name"), "the manifest does not list itself");
            if (!seen.insert(entry.name).second)
                json_document::fail(entryReader.fieldPath("name"), json_document::quote(entry.name) + " is listed twice");
            entry.size = std::uint64_t(entryReader.integer("size", true, 0, 0, std::int64_t(1) << 50));
            entry.sha256 = entryReader.string("sha256", true);
            if (!isHexDigest(entry.sha256))
                json_document::fail(entryReader.fieldPath("sha256"),
                                    "expected 64 lower-case hex digits, found " + json_document::quote(entry.sha256));
            manifest.entries.push_back(std::move(entry));
        }
        if (!manifest.find(manifest.scenario))
            json_document::fail("scenario", json_document::quote(manifest.scenario) + " is not among the entries");
        manifest.extra = reader.extra();
        return manifest;
    } catch (const json_document::FieldError& e) {
        return makeError(ErrorCode::CorruptData,
                         "The package manifest is not valid: " + (e.path.empty() ? "" : e.path + ": ") + e.message + ".");
    }
}

} // namespace thespis::core::scenario
