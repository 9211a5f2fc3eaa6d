#pragma once
// Private to the default humanoid: where its face's features sit on the neutral head (rest pose,
// metres; the character faces +z, its left is +x). Adult proportions: eyes at half the head's
// height, 64 mm apart; the mouth 50 mm wide, a third of the way from the nose to the chin.
// The modelling (humanoid_face.cpp), the rig (humanoid_face_rig.cpp) and the skin's painting
// (humanoid_face_texture.cpp) all read these.

#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/humanoid_parts.h"

namespace thespis::core::scene::humanoid::face {

// Eyes (the left one; the right mirrors x).
constexpr Vec3d kLeftEye{0.032, 1.681, 0.0725};
constexpr double kEyeballRadius = 0.012;
constexpr double kIrisAngle = 0.50;   ///< the iris's angular radius on the eyeball (radians)
constexpr double kPupilAngle = 0.17;
constexpr double kUpperLidRadius = 0.0132, kLowerLidRadius = 0.0128;
/// The lids' margins at the front, radians above and below the eye's axis (IRISD ≈ 9.8 mm).
constexpr double kUpperMargin = 0.33, kLowerMargin = 0.42;
/// The eye's corners, radians about the vertical from its axis (outer, inner).
constexpr double kOuterCorner = 1.12, kInnerCorner = 1.02;
/// How far the lids reach round the eyeball (radians): their far edges hide in the skin.
constexpr double kLidReach = 1.30, kLidTop = 1.25;

inline Vec3d eyeCentre(int eye) { return {eye * kLeftEye.x, kLeftEye.y, kLeftEye.z}; }
/// A point at `radius` from the eye's centre, `up` radians above its axis and `out` radians about
/// the vertical towards the face's side (eye: +1 left, −1 right).
inline Vec3d onEye(int eye, double radius, double up, double out)
{
    return eyeCentre(eye) + Vec3d{eye * std::cos(up) * std::sin(out), std::sin(up), std::cos(up) * std::cos(out)} * radius;
}

// Mouth: the line where the lips meet, its corners, the lips' outer borders.
constexpr double kMouthY = 1.6040;
constexpr double kMouthCorner = 0.0255; ///< |x| of the corners
/// Height of the mouth line at x (the corners a little lower, as at rest).
inline double mouthLineY(double x)
{
    const double t = std::min(1.0, std::abs(x) / kMouthCorner);
    return kMouthY - 0.0012 * t * t;
}
/// Heights of the upper and lower lips' outer borders above and below the mouth line at x
/// (the upper with a Cupid's bow).
inline double upperLipHeight(double x)
{
    const double t = std::min(1.0, std::abs(x) / kMouthCorner);
    const double bow = 0.0012 * std::exp(-std::pow((std::abs(x) - 0.004) / 0.0025, 2));
    return (0.0070 + bow) * std::sqrt(std::max(0.0, 1 - std::pow(t, 3.0))) ;
}
inline double lowerLipHeight(double x)
{
    const double t = std::min(1.0, std::abs(x) / kMouthCorner);
    return 0.0095 * std::sqrt(std::max(0.0, 1 - std::pow(t, 2.5)));
}
/// How deep the lips turn into the mouth (metres) and how many rows that takes.
constexpr double kLipRollDepth = 0.0065;
constexpr int kLipRollRows = 3;

// Inside the mouth.
constexpr double kTeethFront = 0.0895; ///< z of the incisors' front
constexpr double kUpperTeethTop = 1.6150, kLowerTeethBottom = 1.5950;
constexpr Vec3d kTongueCentre{0.0, 1.5935, 0.0615}, kTongueRadii{0.0200, 0.0075, 0.0235};
constexpr Vec3d kMouthCentre{0.0, 1.6010, 0.0700}, kMouthRadii{0.0255, 0.0165, 0.0240};

// The jaw turns about the line through both temporomandibular joints.
constexpr Vec3d kJawPivot{0.0, 1.6520, 0.0150};

// Brows (painted on the skin): their inner, middle and outer points (left side).
constexpr double kBrowInner = 0.011, kBrowMiddle = 0.033, kBrowOuter = 0.054;
inline double browY(double x)
{
    const double t = (std::abs(x) - kBrowInner) / (kBrowOuter - kBrowInner);
    return 1.6975 + 0.0035 * std::sin(std::numbers::pi * std::clamp(t, 0.0, 1.0) * 0.85) - 0.0015 * t;
}

} // namespace thespis::core::scene::humanoid::face
