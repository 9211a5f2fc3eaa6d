#pragma once
// The CMU clips of ../shared/data/mocap/cmu as postures, for the motion tests.

#include <gtest/gtest.h>

#include <string>

#include "scenario/posture_clip.h"
#include "test_support.h"

namespace thespis::test {

/// mocap/cmu/NAME.bvh on the posture skeleton; `rate` replaces the header's frame rate when > 0.
inline core::scenario::PostureClip cmuPostureClip(const std::string& name, double rate = 0)
{
    core::scenario::ClipAsset asset;
    asset.name = name;
    asset.file = name + ".bvh";
    asset.frameRateOverride = rate;
    auto clip = core::scenario::readPostureClip(asset, sharedData("mocap/cmu"));
    EXPECT_TRUE(clip) << (clip ? "" : clip.error().message);
    return clip ? *clip : core::scenario::PostureClip{};
}

} // namespace thespis::test
