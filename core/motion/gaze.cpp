#include "motion/gaze.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string_view>

#include "anim/quat4.h"
#include "motion/blink_synthesizer.h"
#include "scene/fap.h"

namespace thespis::core::motion {

namespace {

using anim::Quatd;
using anim::Vec3d;

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kDegrees = 180 / std::numbers::pi; // in a radian
constexpr double kFapAngleUnit = 1e-5; // radians (MPEG-4's AU)
constexpr double kLongestStep = 0.25;  // seconds: a longer step (or one back) settles at once
constexpr double kNewShift = 5;        // degrees a goal moves before the parts count it a new shift
constexpr double kEyeJump = 2;         // degrees the eyes' goal moves in one step to be jumped to
constexpr double kOnGoal = 0.05;       // degrees: close enough to stop
constexpr double kShifting = 1;        // degrees from its goal a part is still shifting (not just following)
constexpr double kShrunkEyeRange = 0.75; // of the eyes' range left at the head's top speed
// Of the eyes' range a shift is planned with: turning the body moves the eyes as well as turning
// them (a near target is then seen at a steeper angle than planned), and the rest of the range is
// what lets them still reach it instead of stopping short at their limit.
constexpr double kEyesPlannedRange = 0.85;

constexpr std::array<std::string_view, 3> kBack = {"vl5", "vl3", "vl1"};
constexpr std::array<std::string_view, 3> kChest = {"vt10", "vt6", "vt1"};
constexpr std::array<std::string_view, 3> kNeck = {"vc4", "vc2", "skullbase"};

// The controller runs per character per frame (goal: 0.5 µs), and libm's correctly rounded
// atan2, sin and cos would take half of that: these polynomials are exact to 1e-5 rad (atan2,
// below the eyeball FAPs' unit) and 1e-9 (sine and cosine of a half turn up to 90°).
double atan2Fast(double y, double x)
{
    const double ax = std::abs(x), ay = std::abs(y), big = std::max(ax, ay);
    if (big == 0)
        return 0;
    const double a = std::min(ax, ay) / big, a2 = a * a;
    double r = ((-0.0464964749 * a2 + 0.15931422) * a2 - 0.327622764) * a2 * a + a;
    if (ay > ax)
        r = std::numbers::pi / 2 - r;
    if (x < 0)
        r = std::numbers::pi - r;
    return y < 0 ? -r : r;
}

// sin and cos of |x| ≤ π/2 by their Taylor series (beyond it, libm's), multiplying by the
// terms' reciprocals: a division by a constant stays a division without -ffast-math.
void sinCos(double x, double& sine, double& cosine)
{
    if (std::abs(x) > std::numbers::pi / 2) {
        sine = std::sin(x);
        cosine = std::cos(x);
        return;
    }
    const double x2 = x * x;
    sine = x * (1 - x2 * (1. / 6) * (1 - x2 * (1. / 20) * (1 - x2 * (1. / 42) * (1 - x2 * (1. / 72) * (1 - x2 * (1. / 110))))));
    cosine = 1 - x2 * 0.5 * (1 - x2 * (1. / 12) * (1 - x2 * (1. / 30) * (1 - x2 * (1. / 56) * (1 - x2 * (1. / 90) * (1 - x2 * (1. / 132))))));
}

// Turns about the up (y) and across (x) axes, as anim/quat4.h's quaternions.
anim::simd::F4 heading(double degrees)
{
    double sine = 0, cosine = 1;
    sinCos(degrees * kDegree / 2, sine, cosine);
    return anim::simd::F4{0, float(sine), 0, float(cosine)};
}

anim::simd::F4 pitch(double degrees)
{
    double sine = 0, cosine = 1;
    sinCos(degrees * kDegree / 2, sine, cosine);
    return anim::simd::F4{float(sine), 0, 0, float(cosine)};
}

// |(a, b)|: std::hypot guards against overflow no angle here needs, at many times the cost.
double norm(double a, double b) { return std::sqrt(a * a + b * b); }

// Heading (+ left) and pitch (+ down) of a direction in a frame that faces +z with +y up.
void anglesOf(const Vec3d& d, double& headingDegrees, double& pitchDegrees)
{
    headingDegrees = atan2Fast(d.x, d.z) * kDegrees;
    pitchDegrees = atan2Fast(-d.y, norm(d.x, d.z)) * kDegrees;
}

// The parts' goals on one axis for a shift of `total` degrees (see the header): the neck takes
// its alignment share and what the eyes cannot reach, the chest and back the rest in proportion
// to their ranges.
void shareShift(double total, double eyes, const std::array<double, kGazeBodyParts>& range,
                const std::array<bool, kGazeBodyParts>& active, double alignment,
                std::array<double, kGazeBodyParts>& goal)
{
    const double size = std::abs(total), sign = total < 0 ? -1 : 1;
    const auto back = std::size_t(GazePart::Back), chest = std::size_t(GazePart::Chest), neck = std::size_t(GazePart::Neck);
    goal = {0, 0, 0};
    goal[neck] = active[neck] ? std::min(range[neck], std::max(alignment * size, size - eyes)) : 0;
    const double rest = size - eyes - goal[neck];
    const double chestRange = active[chest] ? range[chest] : 0, backRange = active[back] ? range[back] : 0;
    if (rest > 0 && chestRange + backRange > 0) {
        goal[chest] = std::min(chestRange, rest * chestRange / (chestRange + backRange));
        goal[back] = std::min(backRange, rest - goal[chest]);
        goal[chest] = std::min(chestRange, rest - goal[back]);
    }
    for (double& g : goal)
        g *= sign;
}

} // namespace

const GazePartLimits& GazeSettings::limits(GazePart part) const
{
    switch (part) {
    case GazePart::Back: return back;
    case GazePart::Chest: return chest;
    case GazePart::Neck: return neck;
    case GazePart::Eyes: break;
    }
    return eyes;
}

Result<GazeRig> GazeRig::create(const anim::Skeleton& skeleton, std::optional<Vec3d> eyesAtRest)
{
    const int head = skeleton.find("skullbase");
    if (head < 0)
        return makeError(ErrorCode::InvalidArgument,
                         "The character cannot look at anything: its skeleton has no head joint (skullbase).");
    std::vector<int> chain;
    for (int j = head; j >= 0; j = skeleton.joint(j).parent)
        chain.push_back(j);
    std::reverse(chain.begin(), chain.end());

    GazeRig rig;
    const auto partOf = [](std::string_view name) {
        for (std::size_t i = 0; i < kBack.size(); ++i) {
            if (name == kBack[i])
                return 0;
            if (name == kChest[i])
                return 1;
            if (name == kNeck[i])
                return 2;
        }
        return -1;
    };
    std::array<int, kGazeBodyParts> count{};
    for (const int j : chain)
        if (const int part = partOf(skeleton.joint(j).name); part >= 0)
            ++count[std::size_t(part)];
    std::vector<Vec3d> rest(chain.size());
    for (std::size_t i = 0; i < chain.size(); ++i) {
        GazeRig::Link link;
        link.joint = chain[i];
        link.offset = skeleton.joint(chain[i]).offset;
        if (const int element = skeleton.translationElement(chain[i]); element >= 0)
            link.translation = int(skeleton.frameLayout()->floatOffset(element));
        link.part = partOf(skeleton.joint(chain[i]).name);
        if (link.part >= 0) {
            const auto p = std::size_t(link.part);
            link.share = 1.0 / double(count[p]);
            rig.hasPart[p] = true;
        }
        rest[i] = (i == 0 ? Vec3d{} : rest[i - 1]) + link.offset;
        rig.path.push_back(link);
    }
    const Vec3d headAtRest = rest.back();
    if (!eyesAtRest) {
        const int left = skeleton.find("l_eyeball_joint"), right = skeleton.find("r_eyeball_joint");
        if (left >= 0 && right >= 0) {
            const auto positions = skeleton.worldPositions(skeleton.restFrame());
            eyesAtRest = (positions[std::size_t(left)] + positions[std::size_t(right)]) * 0.5;
        } else {
            // An adult's eyes sit about 8 cm above and in front of the skull base (at 1.6 m).
            const double scale = std::max(headAtRest.y, 0.5) / 1.6;
            eyesAtRest = headAtRest + Vec3d{0, 0.08, 0.08} * scale;
        }
    }
    // Rest orientations are the identity: the head's frame at rest is the skeleton's.
    rig.eyes = *eyesAtRest - headAtRest;
    return rig;
}

GazeController::GazeController(GazeRig rig, GazeSettings settings)
    : m_rig(std::move(rig)), m_settings(settings), m_saccades(settings.seed),
      m_stretches(m_rig.path.size() + 1), m_orientations(m_rig.path.size())
{
    for (const GazeRig::Link& link : m_rig.path)
        m_offsets.push_back(anim::quat4::vector(link.offset));
}

void GazeController::setSettings(const GazeSettings& settings)
{
    if (settings.seed != m_settings.seed)
        m_saccades = SaccadeGenerator(settings.seed);
    m_settings = settings;
    m_saccades.setTalking(settings.talking);
    m_released = m_finished = m_state.released = false;
}

void GazeController::release()
{
    m_released = true;
    m_state.released = true;
}

bool GazeController::finished() const { return m_finished; }

void GazeController::moveParts(double t, double dt, bool settle, const std::array<double, kGazeBodyParts>& headingGoal,
                               const std::array<double, kGazeBodyParts>& pitchGoal)
{
    bool newShift = false;
    for (std::size_t p = 0; p < kGazeBodyParts; ++p)
        newShift |= norm(headingGoal[p] - m_shiftHeading[p], pitchGoal[p] - m_shiftPitch[p]) > kNewShift;
    if (newShift) {
        m_shiftStart = t;
        m_shiftHeading = headingGoal;
        m_shiftPitch = pitchGoal;
    }
    m_state.shifting = false;
    m_onGoals = true;
    for (std::size_t p = 0; p < kGazeBodyParts; ++p) {
        const GazePartLimits& limits = m_settings.limits(GazePart(p));
        double& h = m_state.heading[p];
        double& v = m_state.pitch[p];
        double& speed = m_state.speed[p];
        const double dh = headingGoal[p] - h, dv = pitchGoal[p] - v, distance = norm(dh, dv);
        if (settle || distance <= kOnGoal) {
            h = headingGoal[p];
            v = pitchGoal[p];
            speed = 0;
            continue;
        }
        m_state.shifting |= distance > kShifting;
        m_onGoals = false;
        // A part at rest waits for its latency; one already moving goes on toward the new goal.
        if (speed == 0 && t - m_shiftStart < limits.latency)
            continue;
        // Speed up, but never faster than lets it stop on the goal: no overshoot.
        const double a = std::max(limits.acceleration, 1e-6);
        speed = std::min({limits.maxSpeed, speed + a * dt, std::sqrt(2 * a * distance)});
        const double step = std::min(speed * dt, distance);
        h += dh * step / distance;
        v += dv * step / distance;
        if (step == distance)
            speed = 0;
    }
}

bool GazeController::moveEyes(double t, bool settle, double goalHeading, double goalPitch)
{
    // Where the eyes were shown, and whether the goal jumped (a new target) or drifts (the head
    // coming round, a moving target): a jump is a saccade, a drift is followed.
    const double shown = m_eyeJump.duration > 0 ? minimumJerk((t - m_eyeJump.start) / m_eyeJump.duration) : 1;
    const double wasHeading = m_goalHeading + (m_eyeJump.fromHeading) * (1 - shown);
    const double wasPitch = m_goalPitch + (m_eyeJump.fromPitch) * (1 - shown);
    // How far the goal moved as seen: a change of heading counts less the higher or lower it looks.
    double sine = 0, cosine = 1;
    sinCos(0.5 * (goalPitch + m_goalPitch) * kDegree, sine, cosine);
    const double moved = norm((goalHeading - m_goalHeading) * cosine, goalPitch - m_goalPitch);
    // A jump under way goes on to the goal, wherever it moves; a new one would start from rest.
    if (!settle && moved > kEyeJump && shown >= 1) {
        m_eyeJump = Saccade{t, 0, wasHeading - goalHeading, wasPitch - goalPitch, 0, 0};
        m_eyeJump.duration = saccadeDuration(m_eyeJump.amplitude());
        if (m_eyeJump.amplitude() > m_settings.blinkAbove)
            m_blinkStart = t;
        m_fixating = false;
    } else if (settle) {
        m_eyeJump = Saccade{t, 0, 0, 0, 0, 0};
        m_blinkStart.reset();
    } else {
        // Followed: what is left of the jump stays as it was relative to the goal.
    }
    m_goalHeading = goalHeading;
    m_goalPitch = goalPitch;
    const double done = m_eyeJump.duration > 0 ? minimumJerk((t - m_eyeJump.start) / m_eyeJump.duration) : 1;
    m_state.eyeHeading = goalHeading + m_eyeJump.fromHeading * (1 - done);
    m_state.eyePitch = goalPitch + m_eyeJump.fromPitch * (1 - done);
    const bool jumping = done < 1;

    // Fixating (the shift over), the eyes make their small saccades around the target.
    if (!m_settings.saccades || m_released || jumping || m_state.shifting) {
        m_fixating = false;
        return jumping;
    }
    if (!m_fixating) {
        m_fixating = true;
        m_saccades.restart(t, m_settings.talking);
    }
    double h = 0, v = 0;
    m_saccades.offset(t, h, v);
    m_state.eyeHeading += h;
    m_state.eyePitch += v;
    return false;
}

void GazeController::apply(double t, const Vec3d& target, std::span<float> body, std::span<float> face)
{
    if (m_finished)
        return;
    const double dt = m_last ? t - *m_last : 0;
    const bool settle = dt < 0 || dt > kLongestStep;
    m_last = t;

    // The chain as the other layers posed it: orientations, and positions up to the base.
    const auto& s = m_settings;
    std::array<bool, kGazeBodyParts> active = m_rig.hasPart;
    active[std::size_t(GazePart::Back)] &= s.influence >= GazeInfluence::Waist;
    active[std::size_t(GazePart::Chest)] &= s.influence >= GazeInfluence::Shoulder;
    active[std::size_t(GazePart::Neck)] &= s.influence >= GazeInfluence::Head;
    const std::size_t links = m_rig.path.size();
    std::size_t baseLink = links - 1; // what the lowest turning part stands on: angles are measured in its frame
    for (std::size_t i = 0; i < links; ++i)
        if (m_rig.path[i].part >= 0 && active[std::size_t(m_rig.path[i].part)]) {
            baseLink = i > 0 ? i - 1 : 0;
            break;
        }
    // Up to the base in the body's frame; above it in the base's (m_orientations[i]: link i's
    // orientation in the base's frame, which the turns below need). Above the base, the head's
    // position is summed per stretch between turning joints (m_stretches[s]: the links after the
    // s-th turning joint), for the turns rotate each stretch as one: the turned head is then
    // Σ turn_s · stretch_s, without walking the chain again. In float SIMD (anim/quat4.h): the
    // frames are float, and the chain is most of a frame's work.
    using namespace anim::quat4;
    F4 basePosition{}, headInBase{}, base = identity(), inBase = identity();
    std::fill(m_stretches.begin(), m_stretches.end(), F4{});
    std::size_t stretch = 0;
    for (std::size_t i = 0; i < links; ++i) {
        const GazeRig::Link& link = m_rig.path[i];
        const F4 local = load(anim::rotationAt(std::span<const float>(body), link.joint));
        const F4 offset = link.translation >= 0 ? F4{body[std::size_t(link.translation)],
                                                     body[std::size_t(link.translation) + 1],
                                                     body[std::size_t(link.translation) + 2], 0}
                                                : m_offsets[i];
        if (i <= baseLink) {
            basePosition += rotate(base, offset);
            base = multiply(base, local);
        } else {
            const F4 step = rotate(inBase, offset);
            headInBase += step;
            m_stretches[stretch] += step;
            inBase = multiply(inBase, local);
            stretch += link.part >= 0 ? 1 : 0;
        }
        m_orientations[i] = inBase;
    }
    const Vec3d targetInBase = toVec3d(rotate(conjugate(base), vector(target) - basePosition));
    const Quatd headOrientation = toQuatd(inBase);

    std::array<double, kGazeBodyParts> headingGoal{}, pitchGoal{};
    if (!m_released) {
        double totalHeading = 0, totalPitch = 0;
        anglesOf(targetInBase - (toVec3d(headInBase) + anim::rotate(headOrientation, m_rig.eyes)), totalHeading, totalPitch);
        totalHeading += s.offsetHeading;
        totalPitch += s.offsetPitch;
        shareShift(totalHeading, s.eyes.heading * kEyesPlannedRange, {s.back.heading, s.chest.heading, s.neck.heading}, active,
                   s.headAlignment, headingGoal);
        shareShift(totalPitch, s.eyes.pitch * kEyesPlannedRange, {s.back.pitch, s.chest.pitch, s.neck.pitch}, active, s.headAlignment,
                   pitchGoal);
    }
    moveParts(t, settle ? 0 : dt, settle, headingGoal, pitchGoal);

    // Turn the chain. A turning joint's turn so far, in the base's frame, is the heading of the
    // parts below and of this joint's share of its part about the base's up, then their pitch:
    // the head's is the whole shift as shareShift() measured it. Each joint's share is the same
    // step; headings (and pitches) about one axis add up by multiplying, so that one sine and
    // cosine a part will do. Every link turns with the last turning joint at or below it, so only
    // the turning joints' local rotations change.
    int part = -1;
    F4 headingStep = identity(), pitchStep = identity(), headingSoFar = identity(), pitchSoFar = identity();
    F4 turn = identity(); // of the last turning joint so far
    F4 turnedHead = m_stretches[0];
    stretch = 0;
    for (std::size_t i = baseLink + 1; i < links; ++i) {
        const GazeRig::Link& link = m_rig.path[i];
        if (link.part < 0)
            continue;
        if (link.part != part) {
            part = link.part;
            const auto p = std::size_t(part);
            headingStep = heading(link.share * m_state.heading[p]);
            pitchStep = pitch(link.share * m_state.pitch[p]);
        }
        const F4 parent = multiply(turn, m_orientations[i - 1]); // the link below, turned
        headingSoFar = multiply(headingSoFar, headingStep);
        pitchSoFar = multiply(pitchSoFar, pitchStep);
        turn = multiply(headingSoFar, pitchSoFar);
        anim::rotationAt(body, link.joint) = toQuat(multiply(conjugate(parent), multiply(turn, m_orientations[i]))); // unit times unit
        turnedHead += rotate(turn, m_stretches[++stretch]);
    }

    // The eyes: toward the target from where the turned head holds them.
    const Quatd head = toQuatd(turn) * headOrientation;
    const Vec3d turnedEyes = toVec3d(turnedHead) + anim::rotate(head, m_rig.eyes);
    const auto fap = [&face](int number) -> float& { return face[std::size_t(scene::fapChannel(number))]; };
    double eyeHeading = 0, eyePitch = 0;
    if (m_released) {
        // Back to the eyes the face has.
        eyeHeading = 0.5 * (fap(23) + fap(24)) * (kFapAngleUnit * kDegrees);
        eyePitch = 0.5 * (fap(25) + fap(26)) * (kFapAngleUnit * kDegrees);
    } else {
        anglesOf(anim::rotate(anim::conjugate(head), targetInBase - turnedEyes), eyeHeading, eyePitch);
        eyeHeading += s.offsetHeading;
        eyePitch += s.offsetPitch;
        const auto neck = std::size_t(GazePart::Neck);
        const double shrink = 1 - (1 - kShrunkEyeRange) * std::min(1.0, m_state.speed[neck] / std::max(s.neck.maxSpeed, 1e-6));
        eyeHeading = std::clamp(eyeHeading, -s.eyes.heading * shrink, s.eyes.heading * shrink);
        eyePitch = std::clamp(eyePitch, -s.eyes.pitch * shrink, s.eyes.pitch * shrink);
    }
    const bool jumping = moveEyes(t, settle, eyeHeading, eyePitch);
    m_state.shifting |= jumping; // the eyes on their way to the goal are part of the shift
    m_state.eyeHeading = std::clamp(m_state.eyeHeading, -s.eyes.heading, s.eyes.heading);
    m_state.eyePitch = std::clamp(m_state.eyePitch, -s.eyes.pitch, s.eyes.pitch);
    fap(23) = fap(24) = float(m_state.eyeHeading * (kDegree / kFapAngleUnit));
    fap(25) = fap(26) = float(m_state.eyePitch * (kDegree / kFapAngleUnit));
    if (m_blinkStart)
        closeLids(face, blinkClosure(t - *m_blinkStart));

    m_finished = m_released && m_onGoals && !jumping;
}

} // namespace thespis::core::motion
