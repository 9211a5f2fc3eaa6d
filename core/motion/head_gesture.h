#pragma once
// BML's head lexemes (NOD, SHAKE, TILT) as motion: an open-and-shut additive action on the neck
// (vc4) and head (skullbase), which share the turn, over whatever the body does. A nod dips the
// head and brings it back, once per repetition; a shake turns it left and right with a smooth
// swell and fade; a tilt leans it to the side, holds and comes back. `amount` scales the
// largest angle (1: 15° nod, 20° shake, 12° tilt).

#include <memory>
#include <optional>
#include <string_view>

#include "anim/blendable.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::motion {

enum class HeadLexeme { Nod, Shake, Tilt };
/// NOD, SHAKE, TILT in any case; nullopt for others.
std::optional<HeadLexeme> headLexemeNamed(std::string_view name);

struct HeadGestureOptions {
    HeadLexeme lexeme = HeadLexeme::Nod;
    int repetition = 1;
    double amount = 1;
    /// Seconds; 0: its natural length (0.5 s a nod, 0.7 s a shake, 1.2 s a tilt, per repetition).
    double duration = 0;
};
double naturalHeadGestureSeconds(const HeadGestureOptions& options);

class HeadGesture final : public anim::BlendableObject {
public:
    /// Errors: a skeleton with neither vc4 nor skullbase; repetition below 1; amount outside 0 … 2.
    static Result<std::shared_ptr<HeadGesture>> create(const anim::Skeleton& skeleton, const HeadGestureOptions& options);

    const anim::FrameLayoutPtr& layout() const override { return m_layout; }
    anim::TimeDomain domain() const override { return {0.0, m_duration}; }
    /// Identity everywhere but the neck and head (an additive frame): their share of the turn at t.
    void evaluate(double t, std::span<float> out) const override;
    /// The head's turn at t in degrees: (heading + left, pitch + down, roll + to its right).
    void angles(double t, double& heading, double& pitch, double& roll) const;

private:
    HeadGesture() = default;

    anim::FrameLayoutPtr m_layout;
    HeadGestureOptions m_options;
    double m_duration = 0;
    int m_joints[2] = {-1, -1};
    int m_jointCount = 0;
};

} // namespace thespis::core::motion
