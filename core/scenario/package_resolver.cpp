// A scenario package's assets (package_resolver.h).

#include "scenario/package_resolver.h"

#include "util/file_io.h"
#include "util/sha256.h"

namespace thespis::core::scenario {

namespace {

namespace fs = std::filesystem;

/// A name the package holds, as the manifest spells it ("./a/../b.bvh" is "b.bvh").
std::string entryName(const std::string& name)
{
    return fs::path(name).lexically_normal().generic_string();
}

} // namespace

PackageResolver::PackageResolver(std::shared_ptr<const Package> package, fs::path beside) : m_package(std::move(package))
{
    if (!beside.empty())
        m_beside.emplace(std::move(beside));
    // The digest of the manifest names this package's contents exactly.
    const std::string digest = sha256Hex(serializeManifest(m_package->manifest())).substr(0, 24);
    std::error_code error;
    m_folder = fs::temp_directory_path(error) / "thespis-packages" / digest;
}

fs::path PackageResolver::path(const std::string& name) const
{
    const std::string entry = entryName(name);
    const fs::path file = m_folder / fs::path(entry);
    const PackageEntry* listed = m_package->manifest().find(entry);
    if (!listed)
        return m_beside ? m_beside->path(name) : file; // else the reader reports the missing file
    std::lock_guard lock(m_mutex);
    if (m_written.contains(entry))
        return file;
    // A file left by an earlier run is used when it is still what the manifest says.
    if (auto existing = readTextFile(file); existing && existing->size() == listed->size && sha256Hex(*existing) == listed->sha256) {
        m_written.insert(entry);
        return file;
    }
    auto bytes = m_package->read(entry);
    std::error_code error;
    fs::create_directories(file.parent_path(), error);
    if (bytes && !error && writeFileAtomically(file, *bytes))
        m_written.insert(entry);
    return file; // when it could not be written, the reader reports it missing
}

Result<std::string> PackageResolver::read(const std::string& name) const
{
    if (m_beside && !m_package->manifest().find(entryName(name)))
        return m_beside->read(name);
    auto bytes = m_package->read(entryName(name));
    if (!bytes && bytes.error().code == ErrorCode::NotFound)
        return makeError(ErrorCode::FileNotFound, "The file " + name + " is not in the package " + m_package->file().string() + ".");
    return bytes;
}

long long PackageResolver::stamp(const std::string& name) const
{
    // A package does not change while it is open.
    if (m_package->manifest().find(entryName(name)))
        return 1;
    return m_beside ? m_beside->stamp(name) : 0;
}

std::string PackageResolver::nameOf(const fs::path& file) const
{
    if (m_beside)
        return m_beside->nameOf(file);
    return fs::absolute(file).lexically_normal().lexically_relative(m_folder).generic_string();
}

std::string PackageResolver::where(const std::string& name) const
{
    if (m_beside && !m_package->manifest().find(entryName(name)))
        return m_beside->where(name);
    return (m_package->file() / fs::path(entryName(name))).string();
}

std::string PackageResolver::describe() const
{
    return "the package " + m_package->file().string();
}

Result<OpenedPackage> openPackage(const fs::path& file, const PackageLimits& limits, const fs::path& beside)
{
    auto package = Package::open(file, limits);
    if (!package)
        return package.error();
    std::shared_ptr<const Package> shared = std::move(package).value();
    auto scenario = shared->scenario();
    if (!scenario)
        return scenario.error();
    Assets assets(std::make_shared<PackageResolver>(shared, beside));
    return OpenedPackage{shared, std::move(assets), std::move(scenario).value()};
}

} // namespace thespis::core::scenario
