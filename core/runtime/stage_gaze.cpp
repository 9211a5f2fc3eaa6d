// The Stage's layers that turn a finished pose toward a target that may move every frame — a
// point, a joint of another character (between its eyes by default), or the camera (stage.h):
// per character, a motion::GazeController (eyes, head and body), then a pointing arm
// (motion/pointing.h) over it.

#include "anim/joint_transform.h"
#include "runtime/stage.h"

namespace thespis::core::runtime {

namespace {

using anim::jointTransform;
using anim::Quatd;
using anim::Vec3d;

Vec3d toDouble(const anim::Vec3& v) { return {v.x, v.y, v.z}; }
Quatd toDouble(const anim::Quat& q) { return {q.x, q.y, q.z, q.w}; }

Vec3d placed(const anim::Placement& placement, const Vec3d& p)
{
    return anim::rotate(toDouble(placement.rotation), p) + toDouble(placement.translation);
}

Vec3d unplaced(const anim::Placement& placement, const Vec3d& p)
{
    return anim::rotate(anim::conjugate(toDouble(placement.rotation)), p - toDouble(placement.translation));
}

// The index of the cue playing at `seconds` (the latest started that has not ended), or −1;
// `cues` are in start order.
template <class Cue>
int cuePlaying(std::span<const Cue> cues, double seconds)
{
    int now = -1;
    for (std::size_t k = 0; k < cues.size() && cues[k].start <= seconds; ++k)
        if (seconds < cues[k].end)
            now = int(k);
    return now;
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

Result<Stage::StageTarget> Stage::findTarget(const Performer& p, const GazeTarget& target, std::string_view verb) const
{
    const std::string& character = p.name;
    const std::string what = "\"" + character + "\" cannot " + std::string(verb) + " ";
    StageTarget found{target, -1, -1};
    if (target.kind != GazeTarget::Kind::Joint)
        return found;
    for (std::size_t i = 0; i < m_performers.size(); ++i)
        if (m_performers[i].name == target.character)
            found.character = int(i);
    if (found.character < 0)
        return makeError(ErrorCode::NotFound, what + "\"" + target.character + "\": there is no such character.");
    const Performer& other = m_performers[std::size_t(found.character)];
    if (!target.joint.empty()) {
        found.joint = other.skeleton.find(target.joint);
        if (found.joint < 0)
            return makeError(ErrorCode::NotFound, what + target.character + "'s \"" + target.joint + "\": " +
                                                      target.character + " has no such joint.");
    } else if (!other.gazeRig) {
        return makeError(ErrorCode::InvalidArgument,
                         what + target.character + "'s eyes: " + target.character + " has no head joint.");
    }
    return found;
}

Result<void> Stage::aim(Performer& p, const GazeTarget& target, const motion::GazeSettings& settings, double start,
                        bool authored)
{
    const std::string& character = p.name;
    if (!p.gazeRig)
        return makeError(ErrorCode::InvalidArgument,
                         "\"" + character + "\" cannot look at anything: its skeleton has no head joint (skullbase).");
    auto found = findTarget(p, target, "look at");
    if (!found)
        return found.error();
    if (p.gaze) {
        p.gaze->controller.setSettings(settings);
    } else {
        p.gaze.emplace(GazeSlot{motion::GazeController(*p.gazeRig, settings), {}, 0, {}, false});
    }
    p.gaze->target = *found;
    p.gaze->start = start;
    p.gaze->release.reset();
    p.gaze->authored = authored;
    return {};
}

void Stage::followAuthoredGaze(Performer& performer, std::span<const scenario::GazeCue> cues, double seconds)
{
    const int now = cuePlaying(cues, seconds);
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

std::optional<Vec3d> Stage::targetPosition(const StageTarget& target, const PoseSet& out) const
{
    switch (target.target.kind) {
    case GazeTarget::Kind::Point: return target.target.point;
    case GazeTarget::Kind::Camera: return m_camera;
    case GazeTarget::Kind::Joint: break;
    }
    const auto i = std::size_t(target.character);
    if (i >= out.characters.size())
        return std::nullopt;
    const Performer& other = m_performers[i];
    const CharacterPose& pose = out.characters[i];
    Vec3d position;
    Quatd orientation;
    if (target.joint >= 0) {
        jointTransform(other.skeleton, pose.body, target.joint, position, orientation);
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
        const std::optional<Vec3d> target = targetPosition(gaze.target, out);
        if (!target && !gaze.release)
            continue; // a camera not known yet
        CharacterPose& pose = out.characters[i];
        gaze.controller.apply(seconds, target ? unplaced(pose.placement, *target) : Vec3d{}, pose.body, pose.face);
        if (gaze.controller.finished())
            performer.gaze.reset();
    }
}

Result<void> Stage::point(const std::string& character, const GazeTarget& target, motion::PointingHand hand,
                          anim::Curve weight, Tick at, double seconds)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    Performer& p = **performer;
    auto arms = motion::pointingArms(p.skeleton, hand);
    if (!arms)
        return makeError(arms.error().code, "\"" + character + "\" cannot point: " + arms.error().message);
    auto found = findTarget(p, target, "point at");
    if (!found)
        return found.error();
    const double start = ticksToSeconds(at);
    const double end = start + std::max(seconds, 0.0);
    p.pointing = PointSlot{*found, std::move(arms).value(), std::move(weight), start, end, end, 0, false};
    return {};
}

void Stage::followAuthoredPointing(Performer& performer, std::span<const scenario::PointingCue> cues, double seconds)
{
    const int now = cuePlaying(cues, seconds);
    if (now == performer.authoredPointing)
        return;
    performer.authoredPointing = now;
    if (now < 0) {
        if (performer.pointing && performer.pointing->authored)
            performer.pointing.reset();
        return;
    }
    const scenario::PointingCue& cue = cues[std::size_t(now)];
    // The runtime checked the target and the arms on the scenario's rig; a target this stage
    // cannot find leaves the arm as it is.
    auto arms = motion::pointingArms(performer.skeleton, cue.hand);
    auto found = findTarget(performer, cue.target, "point at");
    if (arms && found)
        performer.pointing = PointSlot{*found, std::move(arms).value(), cue.weight, cue.start, cue.end, cue.end, 0, true};
}

Result<bool> Stage::stopPointing(const std::string& character, Tick at, double fadeSeconds)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    std::optional<PointSlot>& pointing = (*performer)->pointing;
    if (!pointing)
        return false;
    pointing->cutAt = std::min(pointing->end, ticksToSeconds(at));
    pointing->cutFade = std::max(fadeSeconds, 0.0);
    return true;
}

void Stage::applyPointing(double seconds, PoseSet& out)
{
    for (std::size_t i = 0; i < m_performers.size() && i < out.characters.size(); ++i) {
        Performer& performer = m_performers[i];
        if (i < m_runtime.characters.size())
            followAuthoredPointing(performer, m_runtime.characters[i].pointing, seconds);
        if (!performer.pointing || seconds < performer.pointing->start)
            continue;
        const PointSlot& pointing = *performer.pointing;
        if (seconds >= std::min(pointing.end, pointing.cutAt + pointing.cutFade)) {
            performer.pointing.reset();
            continue;
        }
        const std::optional<Vec3d> target = targetPosition(pointing.target, out);
        if (!target)
            continue; // a camera not known yet
        CharacterPose& pose = out.characters[i];
        double weight = pointing.weight.evaluate(seconds - pointing.start, pointing.end - pointing.start);
        if (seconds > pointing.cutAt)
            weight *= std::max(0.0, 1 - (seconds - pointing.cutAt) / std::max(pointing.cutFade, 1e-9));
        for (const motion::PointingArm& arm : pointing.arms)
            motion::aimArm(performer.skeleton, arm, pose.body, unplaced(pose.placement, *target), weight);
    }
}

} // namespace thespis::core::runtime
