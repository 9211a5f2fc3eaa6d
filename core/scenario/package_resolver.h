#pragma once
// The assets of an open scenario package (package.h): a scenario plays straight from its
// package, with no import. read() serves an entry's bytes from the zip, checked against the
// manifest (clips, idle motion databases, posture bases). path() is for the readers that need a
// file (a glTF model, a probe, a sound): the entry is written once, checked, into a folder of the
// package's own under the system's temporary folder, named by the manifest's digest so that two
// packages never share one and the same package is not written twice. A resolver may also look
// beside the package for names it does not hold (the studio, for files a user adds to a package
// it opened); a package alone is self-contained.

#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

#include "scenario/asset_resolver.h"
#include "scenario/package.h"

namespace thespis::core::scenario {

class PackageResolver final : public AssetResolver {
public:
    /// `beside`: where names the package does not hold are found (empty: nowhere).
    explicit PackageResolver(std::shared_ptr<const Package> package, std::filesystem::path beside = {});

    const Package& package() const { return *m_package; }
    /// Where path() puts the entries it is asked for.
    const std::filesystem::path& fileFolder() const { return m_folder; }

    std::filesystem::path path(const std::string& name) const override;
    Result<std::string> read(const std::string& name) const override;
    long long stamp(const std::string& name) const override;
    std::string nameOf(const std::filesystem::path& file) const override;
    std::string where(const std::string& name) const override;
    std::string describe() const override;

private:
    std::shared_ptr<const Package> m_package;
    std::filesystem::path m_folder;
    std::optional<FolderResolver> m_beside;
    mutable std::mutex m_mutex;
    mutable std::set<std::string> m_written; // entries path() has put in m_folder
};

/// The assets and the scenario of the package at `file`, opened and checked (Package::open).
struct OpenedPackage {
    std::shared_ptr<const Package> package;
    Assets assets;
    Scenario scenario;
};
Result<OpenedPackage> openPackage(const std::filesystem::path& file, const PackageLimits& limits = {},
                                  const std::filesystem::path& beside = {});

} // namespace thespis::core::scenario
