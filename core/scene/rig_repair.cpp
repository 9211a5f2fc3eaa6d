#include "scene/rig_repair.h"

#include <algorithm>
#include <cmath>

#include "anim/rig_orientation.h"

namespace thespis::core::scene {

namespace {

Vec3 toFloat(const Vec3d& v)
{
    return {float(v.x), float(v.y), float(v.z)};
}

Vec3d toDouble(const Vec3& v)
{
    return {v.x, v.y, v.z};
}

// Rebuilds every clip of the character on `skeleton` (same joint names, one joint moved to
// another parent): each frame's world transforms on the old skeleton, expressed as locals of the
// new one. `order[n]` is the old index of new joint n.
Result<void> reparentClips(Character& character, const anim::Skeleton& skeleton, const std::vector<int>& order)
{
    const anim::Skeleton& old = character.skeleton;
    std::vector<Vec3d> positions(std::size_t(old.jointCount()));
    std::vector<Quatd> orientations(positions.size());
    const anim::FrameLayout& layout = *skeleton.frameLayout();
    for (auto& clip : character.clips) {
        std::vector<float> frames(layout.floatCount() * std::size_t(clip->frameCount()));
        for (int f = 0; f < clip->frameCount(); ++f) {
            old.worldTransforms(clip->frame(f), positions, orientations);
            std::span<float> out(frames.data() + std::size_t(f) * layout.floatCount(), layout.floatCount());
            for (int j = 0; j < skeleton.jointCount(); ++j) {
                const auto o = std::size_t(order[std::size_t(j)]);
                const int parent = skeleton.joint(j).parent;
                const Quatd parentRotation = parent >= 0 ? orientations[std::size_t(order[std::size_t(parent)])] : Quatd{};
                const Quatd local = normalize(conjugate(parentRotation) * orientations[o]);
                anim::rotationAt(out, j) = anim::Quat{float(local.x), float(local.y), float(local.z), float(local.w)};
                if (const int element = skeleton.translationElement(j); element >= 0) {
                    const Vec3d parentPosition = parent >= 0 ? positions[std::size_t(order[std::size_t(parent)])] : Vec3d{};
                    const Vec3d offset = rotate(conjugate(parentRotation), positions[o] - parentPosition);
                    float* t = &out[layout.floatOffset(element)];
                    t[0] = float(offset.x), t[1] = float(offset.y), t[2] = float(offset.z);
                }
            }
        }
        auto rebuilt = anim::KeyframeClip::create(skeleton.frameLayout(), clip->frameRate(), std::move(frames), clip->name());
        if (!rebuilt)
            return rebuilt.error();
        clip = std::move(rebuilt).value();
    }
    return {};
}

} // namespace

std::string turnToFaceForward(Character& character)
{
    const anim::AxisTurn turn = anim::uprightTurn(character.skeleton);
    if (turn.isIdentity())
        return {};
    std::vector<anim::Joint> joints = character.skeleton.joints();
    anim::applyTurn(turn, joints);
    auto skeleton = anim::Skeleton::create(std::move(joints));
    if (!skeleton)
        return {};
    for (auto& clip : character.clips) {
        std::vector<float> frames = clip->data();
        anim::applyTurn(turn, *clip->layout(), frames);
        auto turned = anim::KeyframeClip::create(skeleton->frameLayout(), clip->frameRate(), std::move(frames), clip->name());
        if (!turned)
            return {};
        clip = std::move(turned).value();
    }
    character.skeleton = std::move(*skeleton);
    CharacterMesh& mesh = character.mesh;
    for (Vec3& p : mesh.positions)
        p = toFloat(turn.apply(toDouble(p)));
    for (Vec3& n : mesh.normals)
        n = toFloat(turn.apply(toDouble(n)));
    for (MorphTarget& target : character.face.targets)
        for (Vec3& offset : target.offsets)
            offset = toFloat(turn.apply(toDouble(offset)));
    const Quatd rotation = anim::turnRotation(turn);
    for (Segment& segment : mesh.segments) {
        segment.bindRotation = normalize(rotation * segment.bindRotation);
        segment.bindTranslation = turn.apply(segment.bindTranslation);
    }
    return turn.description;
}

std::vector<std::string> attachIkFeet(Character& character, std::string (*hanimName)(const std::string&))
{
    std::vector<std::string> moved;
    for (const char* side : {"l_", "r_"}) {
        const anim::Skeleton& skeleton = character.skeleton;
        const int knee = skeleton.find(std::string(side) + "knee");
        const std::string ankleName = std::string(side) + "talocrural";
        if (knee < 0 || skeleton.find(ankleName) >= 0)
            continue;
        int foot = -1;
        for (int j = 0; j < skeleton.jointCount(); ++j)
            if (hanimName(skeleton.joint(j).sourceName) == ankleName && skeleton.joint(j).parent != knee)
                foot = j;
        const std::vector<int> parents = skeleton.parents();
        if (foot < 0 || std::find(parents.begin(), parents.end(), foot) != parents.end())
            continue; // not a leaf: moving it would move a subtree nobody asked for

        // New order: every other joint as it was, the foot last (after its new parent).
        std::vector<int> order;
        for (int j = 0; j < skeleton.jointCount(); ++j)
            if (j != foot)
                order.push_back(j);
        order.push_back(foot);
        std::vector<int> newIndex(order.size());
        for (std::size_t n = 0; n < order.size(); ++n)
            newIndex[std::size_t(order[n])] = int(n);
        const std::vector<Vec3d> rest = skeleton.worldPositions(skeleton.restFrame());
        std::vector<anim::Joint> joints;
        for (int old : order) {
            anim::Joint joint = skeleton.joint(old);
            if (old == foot) {
                joint.name = ankleName;
                joint.parent = newIndex[std::size_t(knee)];
                joint.offset = rest[std::size_t(foot)] - rest[std::size_t(knee)];
                // An IK foot's distance to the knee may change in the rig's clips: keep it as a
                // translation when it does.
                joint.translates = !character.clips.empty();
            } else if (joint.parent >= 0) {
                joint.parent = newIndex[std::size_t(joint.parent)];
            }
            joints.push_back(std::move(joint));
        }
        auto reparented = anim::Skeleton::create(std::move(joints));
        if (!reparented || !reparentClips(character, *reparented, order))
            continue;
        const std::string oldName = skeleton.joint(foot).name;
        moved.push_back(skeleton.joint(foot).sourceName);
        for (std::uint16_t& joint : character.skin.joints)
            joint = std::uint16_t(newIndex[joint]);
        for (Segment& segment : character.mesh.segments) {
            if (segment.joint == oldName)
                segment.joint = ankleName;
            if (segment.name == oldName && !character.mesh.findSegment(ankleName))
                segment.name = ankleName;
        }
        character.skeleton = std::move(*reparented);
    }
    return moved;
}

} // namespace thespis::core::scene
