#pragma once
// A small scenario built in code for the editor tests: two H-Anim LOA 1 characters with inline
// clips, so the tests depend on no file. Ada raises her right arm twice (0.5 s and 2 s), Ben
// bows once (1 s); the timeline is 4 s long.

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "scenario/scenario.h"

namespace thespis::test {

// A clip rotating one joint about `axis` from 0 to `angle` radians and back, over `seconds`.
inline core::scenario::ClipAsset swingClip(const std::string& name, const std::string& joint,
                                           core::anim::Vec3 axis, float angle, double seconds)
{
    core::scenario::ClipAsset clip;
    clip.name = name;
    clip.frameRate = 30;
    clip.joints = {joint};
    const int frames = int(std::lround(seconds * clip.frameRate)) + 1;
    for (int f = 0; f < frames; ++f) {
        const float u = float(f) / float(frames - 1);
        const float a = angle * std::sin(std::numbers::pi_v<float> * u); // up and back down
        clip.frames.insert(clip.frames.end(), {axis.x * std::sin(a / 2), axis.y * std::sin(a / 2),
                                               axis.z * std::sin(a / 2), std::cos(a / 2)});
    }
    return clip;
}

inline core::scenario::ActionSpec action(const std::string& name, const std::string& clip, double start,
                                         core::anim::Curve weight)
{
    core::scenario::ActionSpec spec;
    spec.name = name;
    spec.clip = clip;
    spec.start = core::secondsToTicks(start);
    spec.weight = std::move(weight);
    return spec;
}

inline core::scenario::Scenario makeFixtureScenario()
{
    using namespace core::scenario;
    Scenario scenario;
    scenario.name = "Fixture";
    scenario.duration = core::secondsToTicks(4.0);

    Character ada;
    ada.name = "Ada";
    ada.skeleton = "hanim-loa1";
    ada.clips.push_back(swingClip("raise_arm", "r_shoulder", {0, 0, 1}, -1.4f, 1.0));
    Layer adaBase;
    adaBase.name = "base";
    adaBase.actions.push_back(action("raise", "raise_arm", 0.5, core::anim::Curve::cubicFade(0.2, 0.2)));
    adaBase.actions.push_back(action("raise_again", "raise_arm", 2.0, core::anim::Curve::linearFade(0.1, 0.3)));
    ada.layers.push_back(adaBase);

    Character ben;
    ben.name = "Ben";
    ben.skeleton = "hanim-loa1";
    ben.clips.push_back(swingClip("bend", "vl5", {1, 0, 0}, 0.8f, 1.5));
    Layer benBase;
    benBase.name = "base";
    benBase.actions.push_back(action("bow", "bend", 1.0, core::anim::Curve::linearAdsr(0.3, 0.2, 0.8, 0.4)));
    ben.layers.push_back(benBase);

    scenario.characters = {ada, ben};
    return scenario;
}

} // namespace thespis::test
