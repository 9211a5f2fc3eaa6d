#include "scenario/open_scenario.h"

#include "scenario/package_resolver.h"
#include "scenario/scenario_io.h"

namespace thespis::core::scenario {

bool isPackagePath(const std::filesystem::path& path)
{
    return path.extension() == kPackageExtension;
}

Result<OpenedScenario> openScenario(const std::filesystem::path& path)
{
    if (isPackagePath(path)) {
        const std::filesystem::path file = std::filesystem::absolute(path);
        auto opened = openPackage(file, {}, file.parent_path());
        if (!opened)
            return opened.error();
        return OpenedScenario{std::move(opened->scenario), std::move(opened->assets), std::move(opened->package)};
    }
    auto scenario = loadScenario(path);
    if (!scenario)
        return scenario.error();
    return OpenedScenario{std::move(scenario).value(), Assets::besideFile(path), nullptr};
}

} // namespace thespis::core::scenario
