#pragma once
// Where a scenario's files are found. A scenario names its assets (clips, models, probes, bakes,
// sounds) by relative names; every reader asks an AssetResolver for them instead of joining a
// base folder itself. FolderResolver serves a scenario file's folder; PackageResolver
// (package_resolver.h) a scenario package. Readers that parse bytes ask for read(), which a
// package serves straight from the zip; readers that need a file (a glTF model, a probe, a
// sound) ask for path(). `Assets` is the cheap, shared handle readers take: a folder path
// converts to it, so "the scenario's folder" stays as easy to say as before.

#include <filesystem>
#include <memory>
#include <string>

#include "util/error.h"

namespace thespis::core::scenario {

class AssetResolver {
public:
    virtual ~AssetResolver() = default;
    /// A file a reader can open for the asset `name` (absolute names are taken as they are). A
    /// missing file is the reader's to report, with what it was reading.
    virtual std::filesystem::path path(const std::string& name) const = 0;
    /// The asset's bytes (FileNotFound naming it when there is none).
    virtual Result<std::string> read(const std::string& name) const = 0;
    /// A number that changes when the asset changes (for caches); 0 when it cannot be told.
    virtual long long stamp(const std::string& name) const = 0;
    /// The name under which this resolver finds `file` (an import's relative name).
    virtual std::string nameOf(const std::filesystem::path& file) const = 0;
    /// Where the asset is, for messages and cache keys, without making it a file.
    virtual std::string where(const std::string& name) const = 0;
    /// Where the assets come from, for messages ("the folder /home/me/play").
    virtual std::string describe() const = 0;
};

/// Assets in a folder (the scenario file's), named relative to it.
class FolderResolver final : public AssetResolver {
public:
    explicit FolderResolver(std::filesystem::path folder);
    const std::filesystem::path& folder() const { return m_folder; }

    std::filesystem::path path(const std::string& name) const override;
    Result<std::string> read(const std::string& name) const override;
    long long stamp(const std::string& name) const override;
    std::string nameOf(const std::filesystem::path& file) const override;
    std::string where(const std::string& name) const override;
    std::string describe() const override;

private:
    std::filesystem::path m_folder;
};

class Assets {
public:
    /// The assets of a folder ("" is the current one).
    Assets(const std::filesystem::path& folder);
    /// The current folder's.
    Assets() : Assets(std::filesystem::path(".")) {}
    Assets(const char* folder) : Assets(std::filesystem::path(folder)) {}
    Assets(const std::string& folder) : Assets(std::filesystem::path(folder)) {}
    explicit Assets(std::shared_ptr<const AssetResolver> resolver);
    /// The assets of the scenario file at `scenarioFile`: its folder.
    static Assets besideFile(const std::filesystem::path& scenarioFile);

    std::filesystem::path path(const std::string& name) const { return m_resolver->path(name); }
    Result<std::string> read(const std::string& name) const { return m_resolver->read(name); }
    long long stamp(const std::string& name) const { return m_resolver->stamp(name); }
    std::string nameOf(const std::filesystem::path& file) const { return m_resolver->nameOf(file); }
    std::string where(const std::string& name) const { return m_resolver->where(name); }
    std::string describe() const { return m_resolver->describe(); }
    const AssetResolver& resolver() const { return *m_resolver; }

private:
    std::shared_ptr<const AssetResolver> m_resolver;
};

} // namespace thespis::core::scenario
