#pragma once
// Synthetic clips and comparisons for the engine tests.

#include <cmath>
#include <memory>
#include <vector>

#include "anim/keyframe_clip.h"
#include "anim/quat.h"

namespace thespis::test {

using namespace thespis::core::anim;

/// A clip on `layout` whose rotation r turns about a fixed axis by angle(r, t) = phase + speed·t,
/// sampled at `rate` for `seconds`; translations move linearly; scalars ramp.
inline std::shared_ptr<KeyframeClip> makeTurningClip(FrameLayoutPtr layout, double seconds, double rate,
                                                     float speed, float phase = 0.0f)
{
    const int frames = int(std::lround(seconds * rate)) + 1;
    std::vector<float> data;
    for (int f = 0; f < frames; ++f) {
        const float t = float(f / rate);
        for (int r = 0; r < layout->rotationCount(); ++r) {
            const Vec3 axis = r % 3 == 0 ? Vec3{1, 0, 0} : r % 3 == 1 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
            const Quat q = Quat::fromAxisAngle(axis, phase + speed * t * (1.0f + 0.1f * float(r)));
            data.insert(data.end(), {q.x, q.y, q.z, q.w});
        }
        for (int i = 0; i < layout->translationCount(); ++i)
            data.insert(data.end(), {t * speed, 1.0f, -t});
        for (int i = 0; i < layout->scalarCount(); ++i)
            data.push_back(phase + t);
    }
    return std::move(KeyframeClip::create(layout, rate, std::move(data), "turning")).value();
}

inline std::shared_ptr<const FrameLayout> makeLayout(int rotations, bool translation = true, int scalars = 0)
{
    std::vector<std::string> names, translations, scalarNames;
    for (int i = 0; i < rotations; ++i)
        names.push_back("joint" + std::to_string(i));
    if (translation)
        translations.push_back("joint0");
    for (int i = 0; i < scalars; ++i)
        scalarNames.push_back("s" + std::to_string(i));
    return FrameLayout::create(names, translations, scalarNames);
}

/// Angle between two rotations in radians, sign-independent.
inline double angle(const Quat& a, const Quat& b)
{
    return angleBetween(Quatd{a.x, a.y, a.z, a.w}, Quatd{b.x, b.y, b.z, b.w});
}

} // namespace thespis::test
