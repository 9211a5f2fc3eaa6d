#include "scenario/clip_import.h"

#include <algorithm>

#include "anim/retarget.h"
#include "util/file_io.h"
#include "util/text.h"

namespace thespis::core::scenario {

bool isMotionFile(const std::filesystem::path& path)
{
    const std::string extension = lowercase(path.extension().string());
    return extension == ".bvh" || extension == ".gltf" || extension == ".glb";
}

Result<ClipImport> planClipImport(const std::filesystem::path& file, const Assets& assets,
                                  const anim::Skeleton& skeleton, const std::map<std::string, std::string>& mapping)
{
    if (!isMotionFile(file))
        return makeError(ErrorCode::NotOurFormat, file.filename().string()
                                                      + " is not a motion file Thespis reads (BVH, glTF or GLB).");
    ClipAsset asset;
    asset.name = file.stem().string();
    asset.file = assets.nameOf(file);
    if (asset.file.empty())
        asset.file = std::filesystem::absolute(file).lexically_normal().generic_string();
    asset.mapping = mapping;
    auto read = readClipFile(asset, assets);
    if (!read)
        return read.error();

    ClipImport plan;
    plan.path = file;
    plan.report = read->report;
    for (const anim::Joint& joint : read->skeleton.joints())
        plan.mapping[joint.sourceName.empty() ? joint.name : joint.sourceName] = joint.name;
    if (read->report.format == "gltf") {
        for (const std::string& animation : read->report.animations) {
            ClipAsset clip = asset;
            clip.name = animation;
            clip.animation = animation;
            plan.clips.push_back(std::move(clip));
        }
    } else {
        plan.clips.push_back(asset);
    }
    plan.jointsMoved = anim::FrameRetarget(read->skeleton, skeleton).mappedJointCount();
    plan.movingNothing = unmappedJointsMovingNothing(*read, skeleton);
    for (const anim::Joint& joint : skeleton.joints())
        if (read->skeleton.find(joint.name) < 0)
            plan.unmoved.push_back(joint.name);
    if (plan.jointsMoved == 0)
        plan.problem = file.filename().string() + " moves none of the character's joints: its joints ("
                       + std::to_string(read->skeleton.jointCount()) + ") have no name the character's skeleton has. "
                       + "Correct the joint mapping, or import it into a character with another skeleton.";
    return plan;
}

Result<void> saveMapping(const std::filesystem::path& path, const std::map<std::string, std::string>& mapping)
{
    std::string text = "# Thespis joint mapping: file joint name, then the H-Anim name it plays as.\n";
    for (const auto& [joint, name] : mapping)
        if (!name.empty() && joint != name)
            text += joint + "  " + name + "\n";
    return writeFileAtomically(path, text);
}

} // namespace thespis::core::scenario
