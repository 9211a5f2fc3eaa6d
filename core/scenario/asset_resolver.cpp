#include "scenario/asset_resolver.h"

#include <chrono>

#include "util/file_io.h"

namespace thespis::core::scenario {

FolderResolver::FolderResolver(std::filesystem::path folder)
    : m_folder(folder.empty() ? std::filesystem::path(".") : std::move(folder))
{
}

std::filesystem::path FolderResolver::path(const std::string& name) const
{
    const std::filesystem::path relative(name);
    return relative.is_absolute() ? relative : m_folder / relative;
}

Result<std::string> FolderResolver::read(const std::string& name) const
{
    return readTextFile(path(name));
}

long long FolderResolver::stamp(const std::string& name) const
{
    std::error_code ec;
    const auto time = std::filesystem::last_write_time(path(name), ec);
    return ec ? 0 : static_cast<long long>(time.time_since_epoch().count());
}

std::string FolderResolver::nameOf(const std::filesystem::path& file) const
{
    const std::filesystem::path absolute = std::filesystem::absolute(file).lexically_normal();
    return absolute.lexically_relative(std::filesystem::absolute(m_folder).lexically_normal()).generic_string();
}

std::string FolderResolver::where(const std::string& name) const
{
    return path(name).lexically_normal().string();
}

std::string FolderResolver::describe() const
{
    return "the folder " + m_folder.string();
}

Assets::Assets(const std::filesystem::path& folder) : m_resolver(std::make_shared<FolderResolver>(folder)) {}

Assets::Assets(std::shared_ptr<const AssetResolver> resolver) : m_resolver(std::move(resolver)) {}

Assets Assets::besideFile(const std::filesystem::path& scenarioFile)
{
    return Assets(scenarioFile.parent_path());
}

} // namespace thespis::core::scenario
