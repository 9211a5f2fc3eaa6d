// Scenario packages (issue 17 §1): the built-in demo and a scenario of real third-party files
// (../shared/data: the CesiumMan glTF, a CMU BVH clip, a Poly Haven probe) exported through
// ExportPackageJob, opened and imported into a fresh folder: every file byte-identical, the
// scenario valid there and playing the same poses. Packages made to be refused (a path out of
// the package, an absolute path, a symbolic link, an entry the manifest does not list or lists
// with another digest, a newer format, no manifest first, an entry over the size limit, a zip
// bomb) are refused with a message naming the entry. A cancelled export writes nothing.

#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <map>
#include <memory>
#include <stop_token>

#include <zip.h>

#include "scenario/package.h"
#include "scenario/package_export_job.h"
#include "scenario/package_resolver.h"
#include "scenario/scenario_io.h"
#include "scenario/scenario_runtime.h"
#include "test_support.h"
#include "util/file_io.h"
#include "util/sha256.h"

using namespace thespis::core;
using namespace thespis::core::scenario;
namespace fs = std::filesystem;

namespace {

fs::path freshFolder(const std::string& name)
{
    const fs::path folder = thespis::test::artifact("package_test") / name;
    fs::remove_all(folder);
    fs::create_directories(folder);
    return folder;
}

std::string bytesOf(const fs::path& file)
{
    auto text = readTextFile(file);
    EXPECT_TRUE(text) << file;
    return text ? *text : std::string();
}

Result<void> exportPackage(const Scenario& scenario, const Assets& assets, const fs::path& output, ExportPackageJob* result = nullptr,
                           std::stop_token stop = {})
{
    ExportPackageJob job;
    job.scenario = scenario;
    job.assets = assets;
    job.scenarioEntry = "play.thespis";
    job.output = output;
    if (auto valid = job.validate(); !valid)
        return valid.error();
    JobContext context(stop);
    auto ran = job.run(context);
    if (result)
        *result = std::move(job);
    return ran;
}

/// Every character's body and face frames at a few times.
std::vector<std::vector<float>> poses(const Scenario& scenario, const Assets& assets)
{
    auto runtime = buildRuntime(scenario, assets);
    EXPECT_TRUE(runtime) << (runtime ? "" : runtime.error().message);
    std::vector<std::vector<float>> frames;
    if (!runtime)
        return frames;
    for (const CharacterRuntime& character : runtime->characters)
        for (const double t : {0.0, 0.7, 2.3, 5.1}) {
            std::vector<float> body(character.body->layout()->floatCount());
            character.body->evaluate(t, body);
            frames.push_back(std::move(body));
        }
    return frames;
}

/// Exports, opens and imports `scenario`, checking what a user would: the files byte-identical,
/// the scenario valid in the new folder and playing the same poses.
void roundTrip(const Scenario& scenario, const Assets& assets, const std::string& name)
{
    const fs::path package = freshFolder(name) / (name + ".thespkg");
    ExportPackageJob job;
    ASSERT_TRUE(exportPackage(scenario, assets, package, &job)) << name;
    EXPECT_GT(job.packageBytes, 0u);
    auto opened = Package::open(package);
    ASSERT_TRUE(opened) << opened.error().message;
    const Package& p = **opened;
    EXPECT_EQ(p.manifest(), job.manifest);
    EXPECT_EQ(p.manifest().scenario, "play.thespis");
    for (const PackageFile& file : job.plan.files) {
        auto inside = p.read(file.name);
        ASSERT_TRUE(inside) << inside.error().message;
        EXPECT_EQ(*inside, bytesOf(file.source)) << file.name;
    }

    const fs::path folder = freshFolder(name + "_imported");
    auto imported = p.extractTo(folder);
    ASSERT_TRUE(imported) << imported.error().message;
    for (const PackageFile& file : job.plan.files)
        EXPECT_EQ(bytesOf(folder / file.name), bytesOf(file.source)) << file.name;
    auto reloaded = loadScenario(*imported);
    ASSERT_TRUE(reloaded) << reloaded.error().message;
    EXPECT_EQ(*reloaded, job.plan.scenario);
    const Assets importedAssets = Assets::besideFile(*imported);
    EXPECT_TRUE(validateScenario(*reloaded, importedAssets).empty());
    EXPECT_EQ(poses(*reloaded, importedAssets), poses(scenario, assets)) << name;
    // Importing again into the same folder finds the same files: nothing to refuse.
    EXPECT_TRUE(p.extractTo(folder));

    // Played straight from the package, without importing it: the same poses.
    auto played = openPackage(package);
    ASSERT_TRUE(played) << played.error().message;
    EXPECT_EQ(played->scenario, job.plan.scenario);
    EXPECT_TRUE(validateScenario(played->scenario, played->assets).empty());
    EXPECT_EQ(poses(played->scenario, played->assets), poses(scenario, assets)) << name;
}

// ---- Packages made to be refused ----------------------------------------------------------------

struct RawEntry {
    std::string name;
    std::string bytes;
    bool symlink = false;
};

/// A zip with these entries in this order, written by libzip as a tool other than ours might.
void writeZip(const fs::path& file, const std::vector<RawEntry>& entries)
{
    fs::remove(file);
    int error = 0;
    zip_t* archive = zip_open(file.c_str(), ZIP_CREATE | ZIP_TRUNCATE, &error);
    ASSERT_NE(archive, nullptr);
    for (const RawEntry& entry : entries) {
        zip_source_t* source = zip_source_buffer(archive, entry.bytes.data(), entry.bytes.size(), 0);
        const zip_int64_t index = zip_file_add(archive, entry.name.c_str(), source, ZIP_FL_ENC_UTF_8);
        ASSERT_GE(index, 0) << entry.name;
        if (entry.symlink)
            zip_file_set_external_attributes(archive, zip_uint64_t(index), 0, ZIP_OPSYS_UNIX, (S_IFLNK | 0777) << 16);
    }
    ASSERT_EQ(zip_close(archive), 0);
}

/// A manifest for these entries (the first is the scenario), as the exporter would write it.
std::string manifestFor(const std::vector<RawEntry>& entries)
{
    PackageManifest manifest;
    manifest.writer = "a test";
    manifest.scenario = entries.front().name;
    for (const RawEntry& entry : entries)
        manifest.entries.push_back({entry.name, entry.bytes.size(), sha256Hex(entry.bytes)});
    return serializeManifest(manifest);
}

std::string emptyScenarioText()
{
    Scenario empty;
    empty.name = "empty";
    return serializeScenario(empty);
}

std::string refusal(const fs::path& file, const PackageLimits& limits = {})
{
    auto opened = Package::open(file, limits);
    EXPECT_FALSE(opened) << file << " was opened";
    return opened ? std::string() : opened.error().message;
}

} // namespace

TEST(Package, TheDemoTravelsWhole)
{
    const fs::path demo = thespis::test::resources("demo.thespis");
    auto scenario = loadScenario(demo);
    ASSERT_TRUE(scenario) << scenario.error().message;
    ExportPackageJob job;
    ASSERT_TRUE(exportPackage(*scenario, Assets::besideFile(demo), freshFolder("plan") / "demo.thespkg", &job));
    std::vector<std::string> names;
    for (const PackageFile& file : job.plan.files)
        names.push_back(file.name);
    // Both characters' idle clips name one database: it goes in once. The paper's script names
    // Antigone's bot, which she takes questions with after the act.
    EXPECT_EQ(names, (std::vector<std::string>{"motion/cmu_standing.idle", "motion/cmu_postures.pca",
                                               "dialogue/antigone/antigone.aiml"}));
    roundTrip(*scenario, Assets::besideFile(demo), "demo");
}

TEST(Package, ClipsAndMotionDatabasesPlayFromTheZipItself)
{
    // The demo's idle motion database and posture bases, and a CMU clip, are read from the zip:
    // nothing of them is written anywhere to play the package.
    const fs::path demo = thespis::test::resources("demo.thespis");
    auto scenario = loadScenario(demo);
    ASSERT_TRUE(scenario);
    ClipAsset walk;
    walk.name = "walk";
    walk.file = thespis::test::sharedData("mocap/cmu/02_01.bvh").string();
    scenario->characters[0].clips.push_back(walk);
    const fs::path package = freshFolder("from_zip") / "demo.thespkg";
    ASSERT_TRUE(exportPackage(*scenario, Assets::besideFile(demo), package));
    auto opened = openPackage(package);
    ASSERT_TRUE(opened) << opened.error().message;
    const auto& resolver = dynamic_cast<const PackageResolver&>(opened->assets.resolver());
    fs::remove_all(resolver.fileFolder());
    auto runtime = buildRuntime(opened->scenario, opened->assets);
    ASSERT_TRUE(runtime) << runtime.error().message;
    EXPECT_TRUE(runtime->characters[0].clips.contains("walk"));
    EXPECT_FALSE(fs::exists(resolver.fileFolder())) << "files were written to play the package";
    // A file the package does not hold is named with the package.
    auto missing = opened->assets.read("motion/none.bvh");
    ASSERT_FALSE(missing);
    EXPECT_EQ(missing.error().code, ErrorCode::FileNotFound);
    EXPECT_NE(missing.error().message.find("not in the package"), std::string::npos);
    // A model is a file for its reader: written once into the package's own folder, checked.
    EXPECT_EQ(opened->assets.path("motion/cmu_postures.pca"), resolver.fileFolder() / "motion/cmu_postures.pca");
    EXPECT_EQ(bytesOf(resolver.fileFolder() / "motion/cmu_postures.pca"), bytesOf(demo.parent_path() / "motion/cmu_postures.pca"));
}

TEST(Package, RealFilesFromElsewhereMoveIntoTheAssetsFolder)
{
    // A scenario whose files live outside its folder, named by absolute paths as a user's
    // imports can be: a glTF character, a CMU clip on it, a light probe.
    Scenario s;
    s.name = "outside";
    Character c;
    c.name = "Cesium";
    c.model = thespis::test::sharedData("characters/CesiumMan/CesiumMan.glb").string();
    c.skeleton = "model";
    ClipAsset clip;
    clip.name = "walk";
    clip.file = thespis::test::sharedData("mocap/cmu/02_01.bvh").string();
    c.clips.push_back(clip);
    Layer layer;
    layer.name = "body";
    ActionSpec action;
    action.name = "walk";
    action.clip = "walk";
    action.placement = Placement::Character;
    layer.actions.push_back(action);
    c.layers.push_back(layer);
    s.characters.push_back(c);
    s.lighting.probe = thespis::test::sharedData("probes/polyhaven_1k/venice_sunset_1k.hdr").string();
    const fs::path folder = freshFolder("outside_source");
    ExportPackageJob job;
    ASSERT_TRUE(exportPackage(s, Assets(folder), freshFolder("outside_plan") / "p.thespkg", &job));
    EXPECT_EQ(job.plan.scenario.characters[0].model, "assets/CesiumMan.glb");
    EXPECT_EQ(job.plan.scenario.characters[0].clips[0].file, "assets/02_01.bvh");
    EXPECT_EQ(job.plan.scenario.lighting.probe, "assets/venice_sunset_1k.hdr");
    roundTrip(s, Assets(folder), "outside");
}

TEST(Package, AMissingFileIsNamedWithItsField)
{
    Scenario s;
    Character c;
    c.name = "Creon";
    ClipAsset clip;
    clip.name = "wave";
    clip.file = "motion/nowhere.bvh";
    c.clips.push_back(clip);
    s.characters.push_back(c);
    const fs::path output = freshFolder("missing") / "m.thespkg";
    auto exported = exportPackage(s, Assets(freshFolder("missing_source")), output);
    ASSERT_FALSE(exported);
    EXPECT_EQ(exported.error().code, ErrorCode::NotFound);
    EXPECT_NE(exported.error().message.find("characters[Creon].clips[wave].file names motion/nowhere.bvh"), std::string::npos)
        << exported.error().message;
    EXPECT_FALSE(fs::exists(output));
}

TEST(Package, ACancelledExportLeavesTheOldPackage)
{
    const fs::path demo = thespis::test::resources("demo.thespis");
    auto scenario = loadScenario(demo);
    ASSERT_TRUE(scenario);
    const fs::path output = freshFolder("cancel") / "demo.thespkg";
    ASSERT_TRUE(writeFileAtomically(output, "the old package"));
    std::stop_source stop;
    stop.request_stop();
    auto exported = exportPackage(*scenario, Assets::besideFile(demo), output, nullptr, stop.get_token());
    ASSERT_FALSE(exported);
    EXPECT_EQ(exported.error().code, ErrorCode::Cancelled);
    EXPECT_EQ(bytesOf(output), "the old package");
    for (const auto& entry : fs::directory_iterator(output.parent_path()))
        EXPECT_EQ(entry.path().filename(), "demo.thespkg") << "left behind: " << entry.path();
}

TEST(Package, UnsafeOrDamagedPackagesAreRefusedNamingTheEntry)
{
    const fs::path folder = freshFolder("refused");
    const RawEntry scenarioEntry{"play.thespis", emptyScenarioText()};
    const RawEntry clip{"motion/a.bvh", "HIERARCHY\n"};
    const auto package = [&](const std::string& name, std::vector<RawEntry> entries, std::vector<RawEntry> unlisted = {}) {
        const fs::path file = folder / (name + ".thespkg");
        std::vector<RawEntry> all{{"manifest.json", manifestFor(entries)}};
        all.insert(all.end(), entries.begin(), entries.end());
        all.insert(all.end(), unlisted.begin(), unlisted.end());
        writeZip(file, all);
        return file;
    };
    const auto expectRefused = [&](const fs::path& file, const std::string& words, const PackageLimits& limits = {}) {
        const std::string message = refusal(file, limits);
        EXPECT_NE(message.find(words), std::string::npos) << file.filename() << ": " << message;
    };

    // The well-formed one opens.
    EXPECT_TRUE(Package::open(package("good", {scenarioEntry, clip})));

    expectRefused(package("climbs", {scenarioEntry}, {{"../evil.sh", "rm -rf ~"}}), "\"../evil.sh\" climbs out of the package");
    expectRefused(package("absolute", {scenarioEntry}, {{"/etc/profile.d/evil.sh", "x"}}), "\"/etc/profile.d/evil.sh\" is an absolute path");
    expectRefused(package("link", {scenarioEntry, {"motion/a.bvh", "/etc/passwd", true}}), "\"motion/a.bvh\" is a symbolic link");
    expectRefused(package("unlisted", {scenarioEntry}, {clip}), "\"motion/a.bvh\" is not listed in the manifest");

    // The manifest's digest for an entry that was changed afterwards.
    {
        const fs::path file = folder / "changed.thespkg";
        writeZip(file, {{"manifest.json", manifestFor({scenarioEntry, clip})}, scenarioEntry, {"motion/a.bvh", "HIERARCHX\n"}});
        expectRefused(file, "\"motion/a.bvh\" does not match its SHA-256");
    }
    // Listed but missing.
    {
        const fs::path file = folder / "missing.thespkg";
        writeZip(file, {{"manifest.json", manifestFor({scenarioEntry, clip})}, scenarioEntry});
        expectRefused(file, "\"motion/a.bvh\" is listed in the manifest but missing");
    }
    // A newer format.
    {
        std::string manifest = manifestFor({scenarioEntry});
        manifest.replace(manifest.find("\"version\": 1"), 12, "\"version\": 7");
        const fs::path file = folder / "newer.thespkg";
        writeZip(file, {{"manifest.json", manifest}, scenarioEntry});
        auto opened = Package::open(file);
        ASSERT_FALSE(opened);
        EXPECT_EQ(opened.error().code, ErrorCode::NewerVersion) << opened.error().message;
    }
    // No manifest first: not a package.
    {
        const fs::path file = folder / "plain.zip";
        writeZip(file, {scenarioEntry, {"manifest.json", manifestFor({scenarioEntry})}});
        auto opened = Package::open(file);
        ASSERT_FALSE(opened);
        EXPECT_EQ(opened.error().code, ErrorCode::NotOurFormat);
        EXPECT_NE(opened.error().message.find("does not begin with manifest.json"), std::string::npos) << opened.error().message;
    }
    // Not a zip at all.
    {
        const fs::path file = folder / "text.thespkg";
        ASSERT_TRUE(writeFileAtomically(file, "just text"));
        auto opened = Package::open(file);
        ASSERT_FALSE(opened);
        EXPECT_EQ(opened.error().code, ErrorCode::NotOurFormat) << opened.error().message;
    }
    // Over the size limit, and a zip bomb: a megabyte of zeros deflates to about a kilobyte.
    const RawEntry zeros{"motion/zeros.bvh", std::string(1 << 20, '\0')};
    const fs::path bomb = package("bomb", {scenarioEntry, zeros});
    PackageLimits small;
    small.maxEntryBytes = 512 * 1024;
    expectRefused(bomb, "\"motion/zeros.bvh\" is 1048576 bytes, over the limit of 524288", small);
    expectRefused(bomb, "\"motion/zeros.bvh\" expands");
    PackageLimits lenient;
    lenient.maxCompressionRatio = 2000;
    EXPECT_TRUE(Package::open(bomb, lenient));
}

TEST(Package, TheManifestRoundTripsAndNamesABadField)
{
    PackageManifest manifest;
    manifest.writer = "Thespis 1";
    manifest.scenario = "a.thespis";
    manifest.entries = {{"a.thespis", 10, std::string(64, 'a')}, {"motion/b.bvh", 3, std::string(64, '0')}};
    manifest.extra["comment"] = "kept";
    auto read = parseManifest(serializeManifest(manifest));
    ASSERT_TRUE(read) << read.error().message;
    EXPECT_EQ(*read, manifest);

    const auto error = [](std::string text) {
        auto parsed = parseManifest(text);
        return parsed ? std::string("accepted") : parsed.error().message;
    };
    const std::string head = R"({"format": "thespis-package", "version": 1, "writer": "w", "scenario": "a.thespis", "entries": )";
    const std::string digest(64, 'f');
    EXPECT_NE(error(head + R"([{"name": "a.thespis", "size": 1, "sha256": "xyz"}]})").find("entries[0].sha256"), std::string::npos);
    EXPECT_NE(error(head + R"([{"name": "a.thespis", "size": -1, "sha256": ")" + digest + "\"}]}").find("entries[0].size"),
              std::string::npos);
    EXPECT_NE(error(head + R"([{"name": "../a.thespis", "size": 1, "sha256": ")" + digest + "\"}]}").find("entries[0].name"),
              std::string::npos);
    EXPECT_NE(error(head + R"([{"name": "b", "size": 1, "sha256": ")" + digest + "\"}]}").find("scenario: \"a.thespis\" is not among"),
              std::string::npos);
    EXPECT_NE(error(R"({"format": "thespis-scenario", "version": 1})").find("package manifest"), std::string::npos);
}
