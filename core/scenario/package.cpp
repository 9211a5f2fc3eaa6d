// Opening and checking a scenario package (package.h).

#include "scenario/package.h"

#include <sys/stat.h>

#include <map>
#include <mutex>
#include <set>

#include "scenario/package_zip.h"
#include "scenario/scenario_io.h"
#include "util/file_io.h"
#include "util/json_document.h"
#include "util/sha256.h"

namespace thespis::core::scenario {

namespace {

namespace fs = std::filesystem;
using json_document::quote;

constexpr std::uint64_t kRatioFloorBytes = 64 * 1024; // smaller entries may compress as they like
constexpr std::size_t kReadChunk = 1 << 16;

struct ZipFileClose {
    void operator()(zip_file_t* file) const { zip_fclose(file); }
};

} // namespace

struct Package::State {
    fs::path file;
    detail::ZipArchive archive;
    PackageManifest manifest;
    std::map<std::string, zip_uint64_t> indexOf; // entry name → its index in the zip
    mutable std::mutex mutex;                    // a zip_t reads one entry at a time

    Error corrupt(const std::string& entry, const std::string& what) const
    {
        return makeError(ErrorCode::CorruptData, "The package " + file.string() + " is refused: its entry " + quote(entry)
                                                     + " " + what + ".");
    }

    /// The entry's bytes as the zip holds them (libzip checks its CRC), at most `size` of them.
    Result<std::string> readIndex(zip_uint64_t index, const std::string& name, std::uint64_t size) const
    {
        std::unique_ptr<zip_file_t, ZipFileClose> entry(zip_fopen_index(archive.get(), index, 0));
        if (!entry)
            return corrupt(name, std::string("cannot be read: ") + zip_error_strerror(zip_get_error(archive.get())));
        std::string bytes;
        bytes.resize(size);
        std::uint64_t got = 0;
        while (got < size) {
            const zip_int64_t n = zip_fread(entry.get(), bytes.data() + got, std::min<std::uint64_t>(kReadChunk, size - got));
            if (n < 0)
                return corrupt(name, std::string("cannot be read: ") + zip_error_strerror(zip_file_get_error(entry.get())));
            if (n == 0)
                break;
            got += std::uint64_t(n);
        }
        char extra = 0;
        if (got != size || zip_fread(entry.get(), &extra, 1) != 0)
            return corrupt(name, "is not the size its header says");
        return bytes;
    }

    Result<std::string> readChecked(const PackageEntry& entry) const
    {
        auto bytes = readIndex(indexOf.at(entry.name), entry.name, entry.size);
        if (!bytes)
            return bytes.error();
        if (sha256Hex(*bytes) != entry.sha256)
            return corrupt(entry.name, "does not match its SHA-256 in the manifest (changed or damaged since it was written)");
        return bytes;
    }
};

Package::Package(std::unique_ptr<State> state) : m_state(std::move(state)) {}
Package::~Package() = default;

Result<std::unique_ptr<Package>> Package::open(const fs::path& file, const PackageLimits& limits)
{
    auto state = std::make_unique<State>();
    state->file = file;
    std::error_code exists;
    if (!fs::is_regular_file(file, exists))
        return makeError(ErrorCode::FileNotFound, "The package " + file.string() + " does not exist or is not a file.");
    int openError = 0;
    state->archive.reset(zip_open(file.c_str(), ZIP_RDONLY, &openError));
    if (!state->archive) {
        const std::string why = detail::zipOpenError(openError);
        return makeError(openError == ZIP_ER_OPEN || openError == ZIP_ER_READ ? ErrorCode::FileNotFound : ErrorCode::NotOurFormat,
                         "The package " + file.string() + " cannot be opened as a zip: " + why + ".");
    }
    zip_t* archive = state->archive.get();
    const zip_int64_t count = zip_get_num_entries(archive, 0);
    if (count <= 0 || std::uint64_t(count) > limits.maxEntries + 1)
        return makeError(count <= 0 ? ErrorCode::NotOurFormat : ErrorCode::CorruptData,
                         "The package " + file.string() + " holds " + std::to_string(count) + " entries; a package holds "
                             + "its manifest and at most " + std::to_string(limits.maxEntries) + " more.");

    // The zip's own directory: names, links, sizes and ratios, before anything is read.
    std::uint64_t total = 0;
    for (zip_uint64_t i = 0; i < zip_uint64_t(count); ++i) {
        zip_stat_t stat;
        zip_stat_init(&stat);
        if (zip_stat_index(archive, i, 0, &stat) != 0 || !(stat.valid & ZIP_STAT_NAME) || !(stat.valid & ZIP_STAT_SIZE))
            return makeError(ErrorCode::CorruptData, "The package " + file.string() + " is refused: entry "
                                                         + std::to_string(i) + " cannot be read from its directory.");
        const std::string name = stat.name;
        if (auto allowed = checkEntryName(name); !allowed)
            return makeError(ErrorCode::CorruptData, "The package " + file.string() + " is refused: " + allowed.error().message);
        if (!state->indexOf.emplace(name, i).second)
            return state->corrupt(name, "appears twice");
        zip_uint8_t system = 0;
        zip_uint32_t attributes = 0;
        if (zip_file_get_external_attributes(archive, i, 0, &system, &attributes) == 0 && system == ZIP_OPSYS_UNIX
            && ((attributes >> 16) & S_IFMT) == S_IFLNK)
            return state->corrupt(name, "is a symbolic link; a package holds only files");
        if (stat.size > limits.maxEntryBytes)
            return state->corrupt(name, "is " + std::to_string(stat.size) + " bytes, over the limit of "
                                            + std::to_string(limits.maxEntryBytes));
        if ((stat.valid & ZIP_STAT_COMP_SIZE) && stat.size > kRatioFloorBytes
            && double(stat.size) > limits.maxCompressionRatio * double(std::max<zip_uint64_t>(1, stat.comp_size)))
            return state->corrupt(name, "expands " + std::to_string(stat.comp_size) + " bytes into " + std::to_string(stat.size)
                                            + ", more than " + std::to_string(int(limits.maxCompressionRatio))
                                            + " times (a zip bomb?)");
        total += stat.size;
        if (total > limits.maxTotalBytes)
            return makeError(ErrorCode::CorruptData, "The package " + file.string() + " is refused: its entries expand to more than "
                                                         + std::to_string(limits.maxTotalBytes) + " bytes.");
    }

    // The manifest, first.
    zip_stat_t first;
    zip_stat_init(&first);
    zip_stat_index(archive, 0, 0, &first);
    if (std::string_view(first.name) != kManifestName)
        return makeError(ErrorCode::NotOurFormat, "The package " + file.string() + " does not begin with " + std::string(kManifestName)
                                                      + " (its first entry is " + quote(first.name) + "): it is not a Thespis package.");
    auto manifestText = state->readIndex(0, std::string(kManifestName), first.size);
    if (!manifestText)
        return manifestText.error();
    auto manifest = parseManifest(*manifestText);
    if (!manifest) {
        Error error = manifest.error();
        error.message = "The package " + file.string() + ": " + error.message;
        return error;
    }
    state->manifest = std::move(manifest).value();

    // The manifest and the zip list the same entries, and each entry is what the manifest says.
    for (const auto& [name, index] : state->indexOf)
        if (name != kManifestName && !state->manifest.find(name))
            return state->corrupt(name, "is not listed in the manifest");
    for (const PackageEntry& entry : state->manifest.entries) {
        const auto found = state->indexOf.find(entry.name);
        if (found == state->indexOf.end())
            return state->corrupt(entry.name, "is listed in the manifest but missing from the package");
        zip_stat_t stat;
        zip_stat_init(&stat);
        zip_stat_index(archive, found->second, 0, &stat);
        if (stat.size != entry.size)
            return state->corrupt(entry.name, "is " + std::to_string(stat.size) + " bytes, but the manifest says "
                                                  + std::to_string(entry.size));
        if (auto checked = state->readChecked(entry); !checked)
            return checked.error();
    }
    return std::unique_ptr<Package>(new Package(std::move(state)));
}

const fs::path& Package::file() const { return m_state->file; }
const PackageManifest& Package::manifest() const { return m_state->manifest; }

Result<std::string> Package::read(const std::string& name) const
{
    const PackageEntry* entry = m_state->manifest.find(name);
    if (!entry)
        return makeError(ErrorCode::NotFound, "The package " + m_state->file.string() + " has no entry " + quote(name) + ".");
    std::lock_guard lock(m_state->mutex);
    return m_state->readChecked(*entry);
}

Result<Scenario> Package::scenario() const
{
    auto text = read(m_state->manifest.scenario);
    if (!text)
        return text.error();
    auto scenario = parseScenario(*text);
    if (!scenario) {
        Error error = scenario.error();
        error.message = "The package's scenario " + m_state->manifest.scenario + ": " + error.message;
        return error;
    }
    return scenario;
}

Result<fs::path> Package::extractTo(const fs::path& folder, bool withScenario) const
{
    std::error_code error;
    fs::create_directories(folder, error);
    if (error)
        return makeError(ErrorCode::IoError, "Cannot create the folder " + folder.string() + ": " + error.message() + ".");
    // Everything is read and compared before anything is written: a refusal leaves the folder as it was.
    std::vector<std::pair<fs::path, std::string>> files;
    for (const PackageEntry& entry : m_state->manifest.entries) {
        if (!withScenario && entry.name == m_state->manifest.scenario)
            continue;
        auto bytes = read(entry.name);
        if (!bytes)
            return bytes.error();
        const fs::path target = folder / fs::path(entry.name);
        if (fs::exists(target, error)) {
            auto existing = readTextFile(target);
            if (existing && *existing == *bytes)
                continue;
            return makeError(ErrorCode::InvalidArgument, target.string() + " is already there and differs from the package's "
                                                             + entry.name + "; import into an empty folder.");
        }
        files.emplace_back(target, std::move(bytes).value());
    }
    for (const auto& [target, bytes] : files) {
        fs::create_directories(target.parent_path(), error);
        if (auto written = writeFileAtomically(target, bytes); !written)
            return written.error();
    }
    return folder / fs::path(m_state->manifest.scenario);
}

} // namespace thespis::core::scenario
