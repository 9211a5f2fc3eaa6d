#include "motion/head_gesture.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <string>

#include "util/text.h"

namespace thespis::core::motion {

namespace {

constexpr double kDegree = std::numbers::pi / 180;
constexpr double kNodDegrees = 15, kShakeDegrees = 20, kTiltDegrees = 12;
constexpr double kNodSeconds = 0.5, kShakeSeconds = 0.7, kTiltSeconds = 1.2;

// 0 → 1 → 0 over [0, 1] with zero slope at both ends.
double swell(double u) { return 0.5 - 0.5 * std::cos(2 * std::numbers::pi * std::clamp(u, 0.0, 1.0)); }
// 0 → 1 over [0, 1], smooth.
double smoothstep(double u)
{
    u = std::clamp(u, 0.0, 1.0);
    return u * u * (3 - 2 * u);
}

} // namespace

std::optional<HeadLexeme> headLexemeNamed(std::string_view name)
{
    const std::string upper = uppercase(name);
    if (upper == "NOD")
        return HeadLexeme::Nod;
    if (upper == "SHAKE")
        return HeadLexeme::Shake;
    if (upper == "TILT")
        return HeadLexeme::Tilt;
    return std::nullopt;
}

double naturalHeadGestureSeconds(const HeadGestureOptions& options)
{
    const double each = options.lexeme == HeadLexeme::Nod     ? kNodSeconds
                        : options.lexeme == HeadLexeme::Shake ? kShakeSeconds
                                                              : kTiltSeconds;
    return each * std::max(1, options.repetition);
}

Result<std::shared_ptr<HeadGesture>> HeadGesture::create(const anim::Skeleton& skeleton, const HeadGestureOptions& options)
{
    if (options.repetition < 1)
        return makeError(ErrorCode::InvalidArgument,
                         "A head gesture repeats at least once, not " + std::to_string(options.repetition) + " times.");
    if (!(options.amount >= 0 && options.amount <= 2))
        return makeError(ErrorCode::InvalidArgument,
                         "A head gesture's amount is 0 to 2, not " + std::to_string(options.amount) + ".");
    std::shared_ptr<HeadGesture> self(new HeadGesture);
    for (const char* name : {"vc4", "skullbase"})
        if (const int joint = skeleton.find(name); joint >= 0)
            self->m_joints[self->m_jointCount++] = joint;
    if (self->m_jointCount == 0)
        return makeError(ErrorCode::InvalidArgument, "The character cannot nod or shake its head: its skeleton has "
                                                     "no neck (vc4) or head (skullbase) joint.");
    self->m_layout = skeleton.frameLayout();
    self->m_options = options;
    self->m_duration = options.duration > 0 ? options.duration : naturalHeadGestureSeconds(options);
    return self;
}

void HeadGesture::angles(double t, double& heading, double& pitch, double& roll) const
{
    heading = pitch = roll = 0;
    const double u = std::clamp(t / m_duration, 0.0, 1.0), a = m_options.amount;
    const double cycles = m_options.repetition;
    switch (m_options.lexeme) {
    case HeadLexeme::Nod: pitch = a * kNodDegrees * swell(u * cycles - std::floor(u * cycles)); break;
    case HeadLexeme::Shake:
        heading = a * kShakeDegrees * std::sin(2 * std::numbers::pi * cycles * u) * std::sin(std::numbers::pi * u);
        break;
    case HeadLexeme::Tilt: roll = a * kTiltDegrees * smoothstep(u / 0.25) * smoothstep((1 - u) / 0.25); break;
    }
}

void HeadGesture::evaluate(double t, std::span<float> out) const
{
    std::fill(out.begin(), out.end(), 0.0f);
    for (int r = 0; r < m_layout->rotationCount(); ++r)
        out[4 * std::size_t(r) + 3] = 1.0f;
    double heading = 0, pitch = 0, roll = 0;
    angles(t, heading, pitch, roll);
    // Each joint takes its share; heading about +y, pitch about +x, roll about +z (H-Anim axes).
    const double share = kDegree / (2 * m_jointCount);
    const double h = heading * share, p = pitch * share, r = roll * share;
    const anim::Quatd turn = anim::Quatd{0, std::sin(h), 0, std::cos(h)} * anim::Quatd{std::sin(p), 0, 0, std::cos(p)} *
                             anim::Quatd{0, 0, std::sin(r), std::cos(r)};
    for (int j = 0; j < m_jointCount; ++j)
        anim::rotationAt(out, m_joints[j]) = {float(turn.x), float(turn.y), float(turn.z), float(turn.w)};
}

} // namespace thespis::core::motion
