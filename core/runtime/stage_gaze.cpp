// The Stage's gaze layer (stage.h): per character, a motion::GazeController that turns the pose
// every other layer made toward a target that may move every frame — a point, a joint of
// another character (between its eyes by default), or the camera.

#include <array>

#include "runtime/stage.h"

namespace thespis::core::runtime {

namespace {

using anim::Quatd;
using anim::Vec3d;

Vec3d toDouble(const anim::Vec3& v) { return {v.x, v.y, v.z}; }
Quatd toDouble(const anim::Quat& q) { return {q.x, q.y, q.z, q.w}; }

// A joint's position and orientation in a body frame (before placement), from its ancestors
// alone: no allocation.
void jointTransform(const anim::Skeleton& skeleton, std::span<const float> body, int joint, Vec3d& position,
                    Quatd& orientation)
{
    std::array<int, 128> chain{};
    std::size_t depth = 0;
    for (int j = joint; j >= 0 && depth < chain.size(); j = skeleton.joint(j).parent)
        chain[depth++] = j;
    position = {};
    orientation = {0, 0, 0, 1};
    while (depth-- > 0) {
        const int j = chain[depth];
        Vec3d offset = skeleton.joint(j).offset;
        if (const int element = skeleton.translationElement(j); element >= 0) {
            const std::size_t t = skeleton.frameLayout()->floatOffset(element);
            offset = {body[t], body[t + 1], body[t + 2]};
        }
        position = position + anim::rotate(orientation, offset);
        orientation = orientation * toDouble(anim::rotationAt(body, j));
    }
}

Vec3d placed(const anim::Placement& placement, const Vec3d& p)
{
    return anim::rotate(toDouble(placement.rotation), p) + toDouble(placement.translation);
}

Vec3d unplaced(const anim::Placement& placement, const Vec3d& p)
{
    return anim::rotate(anim::conjugate(toDouble(placement.rotation)), p - toDouble(placement.translation));
}

} // namespace

Result<void> Stage::gaze(const std::string& character, const GazeTarget& target, const motion::GazeSettings& settings,
                         Tick at)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    return aim(**performer, target, settings, ticksToSeconds(at), false);
}

Result<void> Stage::aim(Performer& p, const GazeTarget& target, const motion::GazeSettings& settings, double start,
                        bool authored)
{
    const std::string& character = p.name;
    if (!p.gazeRig)
        return makeError(ErrorCode::InvalidArgument,
                         "\"" + character + "\" cannot look at anything: its skeleton has no head joint (skullbase).");
    int targetCharacter = -1, targetJoint = -1;
    if (target.kind == GazeTarget::Kind::Joint) {
        for (std::size_t i = 0; i < m_performers.size(); ++i)
            if (m_performers[i].name == target.character)
                targetCharacter = int(i);
        if (targetCharacter < 0)
            return makeError(ErrorCode::NotFound, "\"" + character + "\" cannot look at \"" + target.character +
                                                      "\": there is no such character.");
        const Performer& other = m_performers[std::size_t(targetCharacter)];
        if (!target.joint.empty()) {
            targetJoint = other.skeleton.find(target.joint);
            if (targetJoint < 0)
                return makeError(ErrorCode::NotFound, "\"" + character + "\" cannot look at " + target.character +
                                                          "'s \"" + target.joint + "\": " + target.character +
                                                          " has no such joint.");
        } else if (!other.gazeRig) {
            return makeError(ErrorCode::InvalidArgument, "\"" + character + "\" cannot look " + target.character +
                                                             " in the eyes: " + target.character + " has no head joint.");
        }
    }
    if (p.gaze) {
        p.gaze->controller.setSettings(settings);
    } else {
        p.gaze.emplace(GazeSlot{motion::GazeController(*p.gazeRig, settings), {}, -1, -1, 0, {}, false});
    }
    p.gaze->target = target;
    p.gaze->targetCharacter = targetCharacter;
    p.gaze->targetJoint = targetJoint;
    p.gaze->start = start;
    p.gaze->release.reset();
    p.gaze->authored = authored;
    return {};
}

void Stage::followAuthoredGaze(Performer& performer, std::span<const scenario::GazeCue> cues, double seconds)
{
    // The cue playing now: the latest started that has not ended.
    int now = -1;
    for (std::size_t k = 0; k < cues.size() && cues[k].start <= seconds; ++k)
        if (seconds < cues[k].end)
            now = int(k);
    if (now == performer.authoredCue)
        return;
    performer.authoredCue = now;
    if (now >= 0) {
        const scenario::GazeCue& cue = cues[std::size_t(now)];
        // A target the scenario checked but this stage cannot find (a joint of a rig without
        // it) leaves the gaze as it is.
        if (aim(performer, cue.target, cue.settings, cue.start, true))
            performer.gaze->release = cue.end;
    } else if (performer.gaze && performer.gaze->authored) {
        performer.gaze->release = std::min(performer.gaze->release.value_or(seconds), seconds);
    }
}

Result<bool> Stage::stopGaze(const std::string& character, Tick at)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    if (!(*performer)->gaze)
        return false;
    (*performer)->gaze->release = ticksToSeconds(at);
    return true;
}

Result<std::optional<motion::GazeState>> Stage::gazeState(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    if (!(*performer)->gaze)
        return std::optional<motion::GazeState>{};
    motion::GazeState state = (*performer)->gaze->controller.state();
    // Let go, now or later by stopGaze(); a gaze action of the scenario lets go when it ends.
    state.released |= (*performer)->gaze->release.has_value() && !(*performer)->gaze->authored;
    return std::optional<motion::GazeState>(state);
}

void Stage::setCameraPosition(std::optional<anim::Vec3d> position)
{
    const std::lock_guard lock(m_mutex);
    m_camera = position;
}

std::optional<anim::Vec3d> Stage::cameraPosition() const
{
    const std::lock_guard lock(m_mutex);
    return m_camera;
}

std::optional<Vec3d> Stage::targetPosition(const GazeSlot& gaze, const PoseSet& out) const
{
    switch (gaze.target.kind) {
    case GazeTarget::Kind::Point: return gaze.target.point;
    case GazeTarget::Kind::Camera: return m_camera;
    case GazeTarget::Kind::Joint: break;
    }
    const auto i = std::size_t(gaze.targetCharacter);
    if (i >= out.characters.size())
        return std::nullopt;
    const Performer& other = m_performers[i];
    const CharacterPose& pose = out.characters[i];
    Vec3d position;
    Quatd orientation;
    if (gaze.targetJoint >= 0) {
        jointTransform(other.skeleton, pose.body, gaze.targetJoint, position, orientation);
    } else {
        const int head = other.gazeRig->path.back().joint;
        jointTransform(other.skeleton, pose.body, head, position, orientation);
        position = position + anim::rotate(orientation, other.gazeRig->eyes);
    }
    return placed(pose.placement, position);
}

void Stage::applyGazes(double seconds, PoseSet& out)
{
    for (std::size_t i = 0; i < m_performers.size() && i < out.characters.size(); ++i) {
        Performer& performer = m_performers[i];
        if (i < m_runtime.characters.size())
            followAuthoredGaze(performer, m_runtime.characters[i].gaze, seconds);
        if (!performer.gaze || seconds < performer.gaze->start)
            continue;
        GazeSlot& gaze = *performer.gaze;
        if (gaze.release && seconds >= *gaze.release)
            gaze.controller.release();
        const std::optional<Vec3d> target = targetPosition(gaze, out);
        if (!target && !gaze.release)
            continue; // a camera not known yet
        CharacterPose& pose = out.characters[i];
        gaze.controller.apply(seconds, target ? unplaced(pose.placement, *target) : Vec3d{}, pose.body, pose.face);
        if (gaze.controller.finished())
            performer.gaze.reset();
    }
}

} // namespace thespis::core::runtime
