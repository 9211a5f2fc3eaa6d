#include "scene/character.h"

#include <algorithm>
#include <cmath>

namespace thespis::core::scene {

Result<void> Skin::validate(std::size_t vertexCount, int jointCount) const
{
    auto broken = [](std::string message) { return makeError(ErrorCode::CorruptData, std::move(message)); };
    if (influences == 0)
        return joints.empty() && weights.empty() ? Result<void>{} : broken("A skin without influences has weights.");
    if (influences < 0 || influences > kMaxInfluences)
        return broken("A skin has " + std::to_string(influences) + " influences per vertex (1 to " +
                      std::to_string(kMaxInfluences) + " are allowed).");
    const std::size_t expected = vertexCount * std::size_t(influences);
    if (joints.size() != expected || weights.size() != expected)
        return broken("The skin has " + std::to_string(weights.size()) + " weights and " +
                      std::to_string(joints.size()) + " joint indices for " + std::to_string(vertexCount) +
                      " vertices × " + std::to_string(influences) + " influences.");
    for (std::size_t v = 0; v < vertexCount; ++v) {
        double sum = 0;
        for (std::size_t i = v * std::size_t(influences); i < (v + 1) * std::size_t(influences); ++i) {
            if (joints[i] >= jointCount)
                return broken("Vertex " + std::to_string(v) + " is weighted to joint " + std::to_string(joints[i]) +
                              " but the skeleton has " + std::to_string(jointCount) + " joints.");
            if (!std::isfinite(weights[i]) || weights[i] < 0)
                return broken("Vertex " + std::to_string(v) + " has a negative or non-finite skin weight.");
            sum += weights[i];
        }
        if (std::abs(sum - 1.0) > 1e-3)
            return broken("The skin weights of vertex " + std::to_string(v) + " sum to " + std::to_string(sum) +
                          " instead of 1.");
    }
    return {};
}

Result<void> Character::validate() const
{
    auto broken = [this](std::string message) {
        return makeError(ErrorCode::CorruptData, "Character \"" + name + "\": " + std::move(message));
    };
    if (skeleton.jointCount() == 0)
        return broken("it has no skeleton.");
    if (auto valid = mesh.validate(); !valid)
        return broken(valid.error().message);
    if (auto valid = skin.validate(mesh.vertexCount(), skeleton.jointCount()); !valid)
        return broken(valid.error().message);
    if (!texcoords.empty() && texcoords.size() != mesh.vertexCount())
        return broken("it has " + std::to_string(texcoords.size()) + " texture coordinates for " +
                      std::to_string(mesh.vertexCount()) + " vertices.");
    if (!segmentMaterials.empty() && segmentMaterials.size() != mesh.segments.size())
        return broken("it has " + std::to_string(segmentMaterials.size()) + " segment materials for " +
                      std::to_string(mesh.segments.size()) + " segments.");
    for (int material : segmentMaterials)
        if (material < -1 || material >= int(materials.size()))
            return broken("a segment uses material " + std::to_string(material) + ", which does not exist.");
    for (const Material& material : materials)
        if (material.baseColorTexture < -1 || material.baseColorTexture >= int(textures.size()))
            return broken("material \"" + material.name + "\" uses a texture that does not exist.");
    for (const TextureImage& texture : textures)
        if (texture.width <= 0 || texture.height <= 0 ||
            texture.rgba.size() != std::size_t(texture.width) * std::size_t(texture.height) * 4)
            return broken("texture \"" + texture.name + "\" has a size that does not match its pixels.");
    for (const Segment& segment : mesh.segments)
        if (!segment.joint.empty() && skeleton.find(segment.joint) < 0)
            return broken("segment \"" + segment.name + "\" follows joint \"" + segment.joint +
                          "\", which the skeleton does not have.");
    for (const auto& clip : clips)
        if (!clip || !(*clip->layout() == *skeleton.frameLayout()))
            return broken("a clip is not on the character's skeleton.");
    if (auto valid = validateFace(); !valid)
        return broken(valid.error().message);
    return {};
}

Result<void> Character::validateFace() const
{
    const auto broken = [](std::string message) { return makeError(ErrorCode::CorruptData, std::move(message)); };
    const std::size_t vertices = mesh.vertexCount();
    const auto ascendingInRange = [&](const std::vector<std::uint32_t>& list) {
        for (std::size_t i = 0; i < list.size(); ++i)
            if (list[i] >= vertices || (i > 0 && list[i] <= list[i - 1]))
                return false;
        return true;
    };
    const auto channelOk = [](int channel) { return channel >= 0 && channel < kFaceChannelCount; };
    for (const MorphTarget& target : face.targets)
        if (target.offsets.size() != target.vertices.size() || !ascendingInRange(target.vertices))
            return broken("face morph target \"" + target.name + "\" names vertices out of order or range.");
    for (const MorphDrive& drive : face.drives)
        if (drive.target < 0 || std::size_t(drive.target) >= face.targets.size() || !channelOk(drive.channel))
            return broken("a face drive names a target or channel that does not exist.");
    for (const RigidFacePart& part : face.parts) {
        if (part.weights.size() != part.vertices.size() || !ascendingInRange(part.vertices))
            return broken("face part \"" + part.name + "\" names vertices out of order or range.");
        bool channels = part.drop.channel < 0 || channelOk(part.drop.channel);
        for (const RigidFacePart::Turn& turn : part.turns)
            channels = channels && channelOk(turn.channel);
        for (const RigidFacePart::Shift& shift : part.shifts)
            channels = channels && channelOk(shift.channel);
        if (!channels)
            return broken("face part \"" + part.name + "\" is driven by a channel that does not exist.");
    }
    for (const FaceJointDrive& drive : face.joints)
        if (drive.joint < 0 || drive.joint >= skeleton.jointCount() || !channelOk(drive.channel))
            return broken("a face joint drive names a joint or channel that does not exist.");
    for (const auto& [upper, lower] : face.lipContacts)
        if (upper >= vertices || lower >= vertices)
            return broken("a lip contact names a vertex that does not exist.");
    for (const FeaturePoint& point : face.featurePoints)
        if (point.vertex >= vertices)
            return broken("face feature point " + point.name + " names a vertex that does not exist.");
    const auto fapsOk = [](const std::vector<FapValue>& values) {
        return std::all_of(values.begin(), values.end(), [](const FapValue& v) { return v.fap >= 3 && v.fap <= kFapCount; });
    };
    if (!std::all_of(face.visemes.begin(), face.visemes.end(), fapsOk) ||
        !std::all_of(face.expressions.begin(), face.expressions.end(), fapsOk))
        return broken("a viseme or expression names a FAP that is not a low-level one (3 … 68).");
    return {};
}

int Character::segmentJoint(std::size_t segment) const
{
    const int joint = skeleton.find(mesh.segments[segment].joint);
    return joint < 0 ? 0 : joint;
}

} // namespace thespis::core::scene
