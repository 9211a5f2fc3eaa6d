#include "scenario/clip_file.h"

#include <algorithm>
#include <cmath>

#include "anim/body_measure.h"
#include "anim/bvh.h"
#include "anim/hanim.h"
#include "scene/foot_soles.h"
#include "scene/gltf_character.h"
#include "util/text.h"

namespace thespis::core::scenario {

namespace {

// CMU's unit: (1/0.45)·2.54 cm (mocap.cs.cmu.edu's FAQ).
constexpr double kCmuUnit = 0.0254 / 0.45;

// A BVH file's unit: CMU's by its conventions, else from the legs (a human's are 0.7 to 1 m).
void guessUnit(const std::string& convention, const anim::Skeleton& skeleton, ClipFileReport& report)
{
    if (convention == "cmu" || convention == "cmu-3dsmax") {
        report.unit = kCmuUnit;
        report.unitName = "CMU units (0.0564 m)";
        return;
    }
    const double legs = anim::measureBody(skeleton).legLength;
    struct Unit {
        double metres;
        const char* name;
    };
    for (const Unit& unit : {Unit{1.0, "metres"}, Unit{0.1, "decimetres"}, Unit{0.01, "centimetres"},
                             Unit{0.0254, "inches"}, Unit{0.001, "millimetres"}})
        if (const double metres = legs * unit.metres; metres > 0.55 && metres < 1.25) {
            report.unit = unit.metres;
            report.unitName = unit.name;
            return;
        }
}

Result<ClipFile> readBvh(const ClipAsset& asset, const Assets& assets)
{
    anim::bvh::ImportOptions options;
    if (asset.frameRateOverride > 0)
        options.frameRate = asset.frameRateOverride;
    if (!asset.mapping.empty())
        options.mapping = anim::bvh::JointMapping(asset.mapping.begin(), asset.mapping.end());
    options.dropCalibrationFrame = !asset.keepCalibrationFrame;
    // Parsed from the resolver's bytes: a package serves them straight from its zip.
    const std::filesystem::path where(assets.where(asset.file));
    auto text = assets.read(asset.file);
    if (!text)
        return text.error();
    auto imported = anim::bvh::parseFile(*text, where, options);
    if (!imported)
        return imported.error();
    ClipFile file;
    file.report.format = "bvh";
    file.report.convention = imported->report.convention;
    file.report.unmapped = imported->report.unmapped;
    file.report.turnedFrom = imported->report.turnedFrom;
    file.report.calibrationFrame = imported->report.calibrationFrame;
    file.report.calibrationFrameDropped = imported->report.calibrationFrame && options.dropCalibrationFrame;
    file.report.frameCount = imported->clip->frameCount();
    file.report.frameRate = imported->clip->frameRate();
    guessUnit(imported->report.convention, imported->skeleton, file.report);
    file.clip = std::move(imported->clip);
    file.skeleton = std::move(imported->skeleton);
    return file;
}

Result<ClipFile> readGltf(const ClipAsset& asset, const std::filesystem::path& path)
{
    scene::GltfCharacterOptions options;
    options.loadTextures = false;
    options.jointMapping = asset.mapping;
    if (asset.frameRateOverride > 0)
        options.clipFrameRate = asset.frameRateOverride;
    auto character = scene::loadGltfCharacter(path, options);
    if (!character)
        return character.error();
    ClipFile file;
    file.report.format = "gltf";
    file.report.convention = asset.mapping.empty() ? "automatic" : "user";
    file.report.unit = 1.0;
    file.report.unitName = "metres";
    file.report.warnings = character->warnings;
    for (const anim::Joint& joint : character->skeleton.joints())
        if (!anim::hanim::isJointName(joint.name))
            file.report.unmapped.push_back(joint.sourceName);
    for (const auto& clip : character->clips)
        file.report.animations.push_back(clip->name());
    const std::string name = path.filename().string();
    if (character->clips.empty())
        return makeError(ErrorCode::InvalidArgument, name + " has no animations.");
    auto chosen = character->clips.begin();
    if (!asset.animation.empty()) {
        chosen = std::find_if(character->clips.begin(), character->clips.end(),
                              [&](const auto& clip) { return clip->name() == asset.animation; });
        if (chosen == character->clips.end()) {
            std::string names;
            for (const std::string& animation : file.report.animations)
                names += (names.empty() ? "" : ", ") + animation;
            return makeError(ErrorCode::InvalidArgument,
                             name + " has no animation named " + inQuotes(asset.animation) + " (it has " + names + ").");
        }
    }
    file.clip = *chosen;
    file.report.frameCount = file.clip->frameCount();
    file.report.frameRate = file.clip->frameRate();
    file.skeleton = std::move(character->skeleton);
    return file;
}

bool isGltf(const std::filesystem::path& path)
{
    const std::string extension = lowercase(path.extension().string());
    return extension == ".gltf" || extension == ".glb";
}

} // namespace

std::vector<std::string> unmappedJointsMovingNothing(const ClipFile& file, const anim::Skeleton& target)
{
    const auto& joints = file.skeleton.joints();
    std::vector<char> reaches(joints.size(), 0);
    for (std::size_t j = joints.size(); j-- > 0;) { // children come after their parents
        reaches[j] = reaches[j] || target.find(joints[j].name) >= 0;
        if (joints[j].parent >= 0)
            reaches[std::size_t(joints[j].parent)] |= reaches[j];
    }
    std::vector<std::string> lost;
    for (std::size_t j = 0; j < joints.size(); ++j) {
        const std::string& fileName = joints[j].sourceName.empty() ? joints[j].name : joints[j].sourceName;
        if (!reaches[j] && std::find(file.report.unmapped.begin(), file.report.unmapped.end(), fileName) != file.report.unmapped.end())
            lost.push_back(fileName);
    }
    return lost;
}

Result<ClipFile> readClipFile(const ClipAsset& asset, const Assets& assets)
{
    const std::filesystem::path name(asset.file);
    if (isGltf(name))
        return readGltf(asset, assets.path(asset.file));
    if (!asset.animation.empty())
        return makeError(ErrorCode::InvalidArgument, "animation: only a glTF file holds named animations, and "
                                                         + name.filename().string() + " is read as BVH.");
    return readBvh(asset, assets);
}

Result<ModelRig> readModelRig(const std::filesystem::path& path)
{
    auto character = scene::loadGltfCharacter(path, {.loadTextures = false});
    if (!character)
        return character.error();
    ModelRig rig;
    rig.soles = scene::footSoles(*character);
    rig.skeleton = std::move(character->skeleton);
    return rig;
}

// ---- the cache ---------------------------------------------------------------------------------

struct AssetCache::Entry {
    long long stamp = 0; ///< the resolver's (AssetResolver::stamp) when it was read
    std::shared_ptr<const ClipFile> clip;
    std::shared_ptr<const ModelRig> rig;
    std::shared_ptr<const motion::IdleDatabase> idle;
    std::shared_ptr<const motion::PostureBases> bases;
};

namespace {

// The file and every option that changes what is read.
std::string keyOf(const ClipAsset& asset, const Assets& assets)
{
    std::string key = "clip\n" + assets.where(asset.file) + "\n" + asset.animation + "\n"
                      + std::to_string(asset.frameRateOverride) + "\n" + (asset.keepCalibrationFrame ? "keep" : "drop");
    for (const auto& [joint, name] : asset.mapping)
        key += "\n" + joint + "=" + name;
    return key;
}

long long modifiedTime(const std::filesystem::path& path)
{
    std::error_code error;
    const auto time = std::filesystem::last_write_time(path, error);
    return error ? 0 : static_cast<long long>(time.time_since_epoch().count());
}

} // namespace

AssetCache::AssetCache() = default;
AssetCache::~AssetCache() = default;

bool AssetCache::holds(const ClipAsset& asset, const Assets& assets) const
{
    const auto it = m_entries.find(keyOf(asset, assets));
    return it != m_entries.end() && it->second->stamp == assets.stamp(asset.file);
}

Result<std::shared_ptr<const ClipFile>> AssetCache::clipFile(const ClipAsset& asset, const Assets& assets)
{
    const std::string key = keyOf(asset, assets);
    const long long stamp = assets.stamp(asset.file);
    if (const auto it = m_entries.find(key); it != m_entries.end() && it->second->stamp == stamp)
        return it->second->clip;
    auto read = readClipFile(asset, assets);
    if (!read) {
        m_entries.erase(key);
        return read.error();
    }
    auto entry = std::make_unique<Entry>();
    entry->stamp = stamp;
    entry->clip = std::make_shared<const ClipFile>(std::move(read).value());
    auto clip = entry->clip;
    m_entries[key] = std::move(entry);
    return clip;
}

Result<std::shared_ptr<const ModelRig>> AssetCache::modelRig(const std::filesystem::path& path)
{
    const std::string key = "rig\n" + path.lexically_normal().string();
    const long long stamp = modifiedTime(path);
    if (const auto it = m_entries.find(key); it != m_entries.end() && it->second->stamp == stamp)
        return it->second->rig;
    auto read = readModelRig(path);
    if (!read) {
        m_entries.erase(key);
        return read.error();
    }
    auto entry = std::make_unique<Entry>();
    entry->stamp = stamp;
    entry->rig = std::make_shared<const ModelRig>(std::move(read).value());
    auto rig = entry->rig;
    m_entries[key] = std::move(entry);
    return rig;
}

template <class T, class Parse>
Result<std::shared_ptr<const T>> AssetCache::motionFile(const std::string& kind, const std::string& name,
                                                        const Assets& assets, Parse parse,
                                                        std::shared_ptr<const T> Entry::*slot)
{
    const std::string key = kind + "\n" + assets.where(name);
    const long long stamp = assets.stamp(name);
    if (const auto it = m_entries.find(key); it != m_entries.end() && it->second->stamp == stamp)
        return (*it->second).*slot;
    m_entries.erase(key);
    auto bytes = assets.read(name);
    if (!bytes)
        return bytes.error();
    auto parsed = parse(*bytes, std::filesystem::path(assets.where(name)));
    if (!parsed)
        return parsed.error();
    auto entry = std::make_unique<Entry>();
    entry->stamp = stamp;
    (*entry).*slot = std::make_shared<const T>(std::move(parsed).value());
    auto value = (*entry).*slot;
    m_entries[key] = std::move(entry);
    return value;
}

Result<std::shared_ptr<const motion::IdleDatabase>> AssetCache::idleDatabase(const std::string& name,
                                                                              const Assets& assets)
{
    return motionFile("idle", name, assets, motion::parseIdleDatabase, &Entry::idle);
}

Result<std::shared_ptr<const motion::PostureBases>> AssetCache::postureBases(const std::string& name,
                                                                              const Assets& assets)
{
    return motionFile("bases", name, assets, motion::parsePostureBases, &Entry::bases);
}

Result<AssetCache::ClipPtr> AssetCache::retargeted(const std::string& key, const std::function<Result<ClipPtr>()>& make)
{
    if (const auto it = m_retargeted.find(key); it != m_retargeted.end())
        return it->second;
    auto made = make();
    if (!made)
        return made.error();
    constexpr std::size_t kKept = 64;
    if (m_retargetedOrder.size() >= kKept) {
        m_retargeted.erase(m_retargetedOrder.front());
        m_retargetedOrder.erase(m_retargetedOrder.begin());
    }
    m_retargeted[key] = *made;
    m_retargetedOrder.push_back(key);
    return made;
}

void AssetCache::clear()
{
    m_entries.clear();
    m_retargeted.clear();
    m_retargetedOrder.clear();
}

} // namespace thespis::core::scenario
