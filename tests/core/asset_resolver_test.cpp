// The asset resolver (scenario/asset_resolver.h): a folder resolver finds a scenario's files by
// the relative names it records, passes absolute names through, names imports relative to its
// folder, and tells when a file changed; the demo scenario builds through it.

#include <gtest/gtest.h>

#include <filesystem>
#include <thread>

#include "scenario/asset_resolver.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "test_support.h"
#include "util/file_io.h"

namespace {

using namespace thespis::core;
using scenario::Assets;
namespace fs = std::filesystem;

fs::path freshFolder()
{
    const fs::path folder = thespis::test::artifact("assets");
    fs::remove_all(folder);
    fs::create_directories(folder / "clips");
    return folder;
}

} // namespace

TEST(FolderResolver, FindsReadsAndNamesFilesOfItsFolder)
{
    const fs::path folder = freshFolder();
    ASSERT_TRUE(writeFileAtomically(folder / "clips" / "wave.bvh", "HIERARCHY").ok());
    const Assets assets(folder);
    EXPECT_EQ(assets.path("clips/wave.bvh"), folder / "clips/wave.bvh");
    const auto bytes = assets.read("clips/wave.bvh");
    ASSERT_TRUE(bytes.ok());
    EXPECT_EQ(*bytes, "HIERARCHY");
    EXPECT_EQ(assets.nameOf(folder / "clips" / "wave.bvh"), "clips/wave.bvh");
    EXPECT_EQ(assets.nameOf(folder / "clips" / ".." / "x.wav"), "x.wav");
    EXPECT_EQ(assets.path((folder / "elsewhere.bvh").string()), folder / "elsewhere.bvh"); // absolute: as it is
    EXPECT_NE(assets.describe().find(folder.string()), std::string::npos);

    const auto missing = assets.read("clips/none.bvh");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
    EXPECT_EQ(assets.stamp("clips/none.bvh"), 0);

    const long long before = assets.stamp("clips/wave.bvh");
    EXPECT_NE(before, 0);
    fs::last_write_time(folder / "clips" / "wave.bvh", fs::last_write_time(folder / "clips" / "wave.bvh") + std::chrono::seconds(2));
    EXPECT_NE(assets.stamp("clips/wave.bvh"), before);
}

TEST(FolderResolver, AScenarioBuildsFromTheFolderItsNamesAreRelativeTo)
{
    // A CMU clip and a glTF model, named relative to the shared data folder.
    scenario::Scenario s;
    scenario::Character c;
    c.name = "Robot";
    c.model = "characters/RobotExpressive/RobotExpressive.glb";
    c.skeleton = "model";
    scenario::ClipAsset clip;
    clip.name = "walk";
    clip.file = "mocap/cmu/02_01.bvh";
    c.clips.push_back(clip);
    scenario::Layer layer;
    layer.name = "body";
    scenario::ActionSpec action;
    action.name = "walk";
    action.clip = "walk";
    layer.actions.push_back(action);
    c.layers.push_back(layer);
    s.characters.push_back(c);

    auto runtime = scenario::buildRuntime(s, Assets(thespis::test::sharedData()));
    ASSERT_TRUE(runtime.ok()) << runtime.error().message;
    EXPECT_GT(runtime->duration, TicksPerSecond);
    EXPECT_TRUE(scenario::validateScenario(s, Assets(thespis::test::sharedData())).empty());

    // From another folder the same names find nothing, and the errors name what was looked for.
    const auto problems = scenario::validateScenario(s, Assets(freshFolder()));
    ASSERT_FALSE(problems.empty());
    std::string all;
    for (const Error& problem : problems)
        all += problem.message + " " + problem.detail + "\n";
    EXPECT_NE(all.find("02_01.bvh"), std::string::npos) << all;
    EXPECT_NE(all.find("RobotExpressive.glb"), std::string::npos) << all;
}
