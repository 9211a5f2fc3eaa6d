#pragma once
// Helpers of the tests on the studio window: finding a character by name, how much of a
// picture changed, a joint's rotation in a pose and the angle between two.

#include <QImage>
#include <QtGlobal>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <span>
#include <string>

#include "anim/quat.h"
#include "editor/document.h"
#include "scenario/scenario_runtime.h"

namespace thespis::test {

inline int characterIndex(const editor::Document& document, const std::string& name)
{
    const auto& characters = document.scenario().characters;
    for (std::size_t c = 0; c < characters.size(); ++c)
        if (characters[c].name == name)
            return int(c);
    return -1;
}

// How many pixels differ by more than a few levels over the channels.
inline int changedPixels(const QImage& a, const QImage& b)
{
    if (a.size() != b.size())
        return a.width() * a.height();
    int changed = 0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x) {
            const QRgb p = a.pixel(x, y), q = b.pixel(x, y);
            changed += std::abs(qRed(p) - qRed(q)) + std::abs(qGreen(p) - qGreen(q)) + std::abs(qBlue(p) - qBlue(q)) > 24;
        }
    return changed;
}

// The rotation of `joint` (x y z w) in a body frame of the character.
inline core::anim::Quat rotationOf(const core::scenario::CharacterRuntime& character, std::span<const float> frame,
                                   const std::string& joint)
{
    const auto& layout = *character.skeleton.frameLayout();
    const int element = layout.find(joint, core::anim::ElementKind::Rotation);
    if (element < 0)
        qFatal("no joint %s", joint.c_str());
    const std::size_t at = layout.floatOffset(element);
    return core::anim::Quat{frame[at], frame[at + 1], frame[at + 2], frame[at + 3]};
}

// The angle between two rotations in degrees. Lengths are divided out: near 1, acos turns a
// quaternion length one float ulp short of 1 into 0.05°.
inline double angleBetween(const core::anim::Quat& a, const core::anim::Quat& b)
{
    const auto dot = [](const core::anim::Quat& p, const core::anim::Quat& q) {
        return double(p.x) * q.x + double(p.y) * q.y + double(p.z) * q.z + double(p.w) * q.w;
    };
    const double cosine = std::abs(dot(a, b)) / std::sqrt(dot(a, a) * dot(b, b));
    return 2.0 * std::acos(std::min(1.0, cosine)) * 180.0 / std::numbers::pi;
}

} // namespace thespis::test
