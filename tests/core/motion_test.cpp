// core/motion: posture vectors, the posture PCA and its files, on real motion capture (CMU).

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "anim/hanim.h"
#include "motion/exp_map.h"
#include "motion/idle_builder.h"
#include "motion/posture_bases.h"
#include "scenario/posture_clip.h"
#include "motion_test_support.h"

using namespace thespis::core;
using namespace thespis::core::motion;
using thespis::core::scenario::PostureClip;
using thespis::core::anim::Quatd;
using thespis::core::anim::Vec3d;

namespace {

PostureClip cmu(const std::string& name, double rate = 0)
{
    return thespis::test::cmuPostureClip(name, rate);
}

std::vector<float> concat(std::initializer_list<std::vector<float>> parts)
{
    std::vector<float> all;
    for (const auto& part : parts)
        all.insert(all.end(), part.begin(), part.end());
    return all;
}

PostureBases basesOf(const std::vector<float>& whole)
{
    return {*PostureBasis::train(PostureSet::WholeBody, whole), *PostureBasis::train(PostureSet::UpperBody, upperBodyOf(whole))};
}

} // namespace

TEST(ExpMap, RoundTripsNearZeroAndNearPi)
{
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (double angle : {0.0, 1e-9, 1e-6, 1e-3, 0.5, 2.0, std::numbers::pi - 1e-3, std::numbers::pi - 1e-7,
                         std::numbers::pi}) {
        for (int i = 0; i < 20; ++i) {
            Vec3d axis{unit(random), unit(random), unit(random)};
            axis = axis * (1.0 / std::sqrt(anim::dot(axis, axis)));
            const Quatd q = Quatd::fromAxisAngle(axis, angle);
            const Vec3d v = logMap(q);
            EXPECT_NEAR(std::sqrt(anim::dot(v, v)), angle, 1e-9) << angle;
            EXPECT_NEAR(anim::angleBetween(expMap(v), q), 0.0, 1e-7) << angle;
            EXPECT_NEAR(anim::angleBetween(expMap(logMap(anim::negate(q))), q), 0.0, 1e-7) << "sign, " << angle;
        }
    }
}

TEST(Posture, UpperBodyRoundTripsRealFrames)
{
    const PostureClip clip = cmu("141_16"); // a wave: large arm rotations
    const PostureMap map = *PostureMap::create(postureSkeleton(), PostureSet::UpperBody);
    ASSERT_EQ(map.layout().size(), 45);
    std::vector<float> frame(postureSkeleton().frameLayout()->floatCount()), back, posture(45);
    for (int f = 0; f < clip.frameCount(); f += 7) {
        clip.frames->evaluate(f / clip.frameRate(), frame);
        map.toPosture(frame, posture);
        back = postureSkeleton().restFrame();
        map.toFrame(posture, back);
        for (const std::string& joint : map.layout().joints) {
            const int element = postureSkeleton().find(joint);
            EXPECT_LT(anim::angleBetween(anim::rotationAt(std::span<const float>(frame), element),
                                         anim::rotationAt(std::span<const float>(back), element)),
                      1e-5f)
                << joint << " at frame " << f;
        }
    }
}

TEST(Posture, WholeBodyStandsBetweenItsFeetFacingZ)
{
    // 140_06 wanders 4.6 m about the room, turning: its postures are all measured from the feet.
    const PostureClip clip = cmu("140_06");
    const PostureMap map = *PostureMap::create(postureSkeleton(), PostureSet::WholeBody);
    ASSERT_EQ(map.layout().size(), 78);
    const auto postures = clip.postures(PostureSet::WholeBody, 2, 2);
    const int left = postureSkeleton().find("l_talocrural"), right = postureSkeleton().find("r_talocrural");
    for (std::size_t f = 0; f < postures.size() / 78; ++f) {
        std::vector<float> frame = postureSkeleton().restFrame();
        map.toFrame(std::span<const float>(postures).subspan(f * 78, 78), frame);
        const auto world = postureSkeleton().worldPositions(frame);
        EXPECT_NEAR((world[left].x + world[right].x) / 2, 0.0, 1e-4) << f;
        EXPECT_NEAR((world[left].z + world[right].z) / 2, 0.0, 1e-4) << f;
        EXPECT_NEAR(world[left].z - world[right].z, 0.0, 1e-4) << "facing +Z, " << f;
        EXPECT_GT(world[left].x - world[right].x, 0.1) << "the left foot on +X, " << f;
    }
}

TEST(Posture, SkeletonWithoutTheJointsIsNamed)
{
    auto map = PostureMap::create(anim::hanim::skeleton(anim::hanim::Level::Loa1), PostureSet::UpperBody);
    ASSERT_FALSE(map);
    EXPECT_NE(map.error().message.find("vt6"), std::string::npos) << map.error().message;
}

TEST(Pca, ReconstructionErrorFallsWithEveryPcOnAHeldBackClip)
{
    const auto training = concat({cmu("140_07").postures(PostureSet::WholeBody, 30, 2),
                                  cmu("113_21").postures(PostureSet::WholeBody, 30, 2),
                                  cmu("02_01").postures(PostureSet::WholeBody, 30),
                                  cmu("141_16").postures(PostureSet::WholeBody, 30, 1),
                                  cmu("05_06").postures(PostureSet::WholeBody, 30)});
    const PostureBasis basis = *PostureBasis::train(PostureSet::WholeBody, training);
    const auto held = cmu("111_28").postures(PostureSet::WholeBody, 30, 2);
    std::vector<float> pcs(78), back(78);
    double previous = std::numeric_limits<double>::max();
    for (int k = 1; k <= 78; ++k) {
        double error = 0;
        for (std::size_t f = 0; f < held.size() / 78; ++f) {
            const std::span<const float> posture(held.data() + f * 78, 78);
            basis.project(posture, pcs);
            basis.reconstruct(std::span<const float>(pcs).first(std::size_t(k)), back);
            for (int i = 0; i < 78; ++i)
                error += (back[std::size_t(i)] - posture[std::size_t(i)]) * (back[std::size_t(i)] - posture[std::size_t(i)]);
        }
        EXPECT_LE(error, previous * (1 + 1e-6)) << k << " PCs";
        previous = error;
        if (k == 78) {
            EXPECT_LT(error / double(held.size()), 1e-9) << "all PCs give the posture back";
        }
    }
    EXPECT_GT(basis.explainedVariance(10), 0.8);
}

TEST(Pca, DistanceWithAllPcsIsTheCovarianceWeightedDistance)
{
    const auto data = concat({cmu("113_21").postures(PostureSet::WholeBody, 30, 2),
                              cmu("141_16").postures(PostureSet::WholeBody, 30, 1)});
    const PostureBasis basis = *PostureBasis::train(PostureSet::WholeBody, data);
    // The data's covariance, straight from the postures.
    const std::size_t n = data.size() / 78;
    std::vector<double> mean(78, 0.0), covariance(78 * 78, 0.0);
    for (std::size_t f = 0; f < n; ++f)
        for (int i = 0; i < 78; ++i)
            mean[std::size_t(i)] += data[f * 78 + std::size_t(i)] / double(n);
    for (std::size_t f = 0; f < n; ++f)
        for (std::size_t i = 0; i < 78; ++i)
            for (std::size_t j = 0; j < 78; ++j)
                covariance[i * 78 + j] += (data[f * 78 + i] - mean[i]) * (data[f * 78 + j] - mean[j]) / double(n - 1);
    std::vector<float> p(78), q(78);
    for (std::size_t a : {std::size_t(3), std::size_t(100)}) {
        const std::size_t b = n - 1 - a;
        basis.project(std::span<const float>(data).subspan(a * 78, 78), p);
        basis.project(std::span<const float>(data).subspan(b * 78, 78), q);
        double expected = 0;
        for (std::size_t i = 0; i < 78; ++i)
            for (std::size_t j = 0; j < 78; ++j)
                expected += (data[a * 78 + i] - data[b * 78 + i]) * covariance[i * 78 + j] * (data[a * 78 + j] - data[b * 78 + j]);
        EXPECT_NEAR(basis.distance(p, q, 78), std::sqrt(expected), 1e-3 * std::sqrt(expected));
        EXPECT_LE(basis.distance(p, q, 5), basis.distance(p, q, 78));
    }
}

TEST(Pca, TooFewFramesSaysSo)
{
    const auto few = cmu("113_21").postures(PostureSet::WholeBody, 1, 2); // 1 fps: 10 frames
    auto basis = PostureBasis::train(PostureSet::WholeBody, few);
    ASSERT_FALSE(basis);
    EXPECT_NE(basis.error().message.find("Too few postures"), std::string::npos) << basis.error().message;
}

TEST(PostureBasesFile, RoundTripsAndRefusesDamage)
{
    const PostureBases bases = basesOf(cmu("113_21").postures(PostureSet::WholeBody, 30, 2));
    const std::string bytes = encodePostureBases(bases);
    auto back = parsePostureBases(bytes, "bases.pca");
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(encodePostureBases(*back), bytes);
    EXPECT_EQ(back->whole.mean(), bases.whole.mean());

    std::string newer = bytes;
    newer[8] = 2;
    EXPECT_EQ(parsePostureBases(newer, "bases.pca").error().code, ErrorCode::NewerVersion);
    EXPECT_EQ(parsePostureBases("THSPPRT" + bytes.substr(7), "bases.pca").error().code, ErrorCode::NotOurFormat);
    std::string flipped = bytes;
    flipped[bytes.size() / 2] ^= 0x10;
    auto damaged = parsePostureBases(flipped, "bases.pca");
    ASSERT_FALSE(damaged);
    EXPECT_EQ(damaged.error().code, ErrorCode::CorruptData);
    for (std::size_t length = 0; length < bytes.size(); length += 997) {
        auto truncated = parsePostureBases(bytes.substr(0, length), "bases.pca");
        ASSERT_FALSE(truncated) << length;
        EXPECT_NE(truncated.error().message.find("bases.pca"), std::string::npos);
    }
    // A basis for another skeleton: its dimension is not the set's.
    std::string other = bytes;
    other[8 + 4 + 4 + 1 + 8] = 60;
    auto foreign = parsePostureBases(other, "bases.pca");
    ASSERT_FALSE(foreign);
    EXPECT_NE(foreign.error().message.find("another skeleton"), std::string::npos) << foreign.error().message;
}
