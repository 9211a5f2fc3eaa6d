// core/ar's live light probe (issue 16 §5). A chrome ball rendered into a 640 × 480 frame from a
// known light (probe.h's mirror-ball mapping, 4 × 4 samples a pixel, sRGB 8-bit with 1 level of
// sensor noise, radius 150.4 px at a sub-pixel centre) is found automatically and projected at
// order 6. Measured against the light's SH projected directly (a 1024 × 512 lat-long through the
// same projector): circle within 0.12 px (centre) and 0.06 px (radius); relative RMS over the
// 3 × 36 coefficients 0.09 % for a band-limited light and 0.34 % for a sky with a sun lobe; the
// dominant direction within 0.06° and 0.14°. The tests assert about twice that. The light
// follows a sudden change by 1 − 1/e after one time constant. The real chrome-ball photos of
// ../shared/data/vision/mirrorball (reduced to 1024 / 1000 px) are found within 2.0 px (centre)
// and 3.5 px (radius) of their hand-tuned crops, which are not ground truth: the balls' lower
// rims meet a dark stand. A ball that moves is followed. No ball is found in marker-board footage
// or in the other real photos of ../shared/data/vision. Frames without a ball, circles outside
// the frame and bad settings are said so.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <numbers>
#include <random>

#include "allocation_counter.h"
#include "ar/frame_source.h"
#include "ar/live_probe.h"
#include "ar/synthetic_source.h"
#include "lighting/probe.h"
#include "lighting/probe_projection_job.h"
#include "render/shading.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using lighting::ShRgb;
using lighting::Vec3d;

namespace {

using Rgb = std::array<double, 3>;
using Environment = std::function<Rgb(const Vec3d&)>;

Vec3d normalized(Vec3d v)
{
    const double n = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
    return {v.x / n, v.y / n, v.z / n};
}
double dot(const Vec3d& a, const Vec3d& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

/// A smooth light of bands 0–2 only (so its order-6 SH is exact), brighter above and to one side.
Rgb bandLimitedLight(const Vec3d& d)
{
    const double base = 0.30 + 0.16 * d.y + 0.07 * d.x - 0.05 * d.z + 0.04 * (3 * d.y * d.y - 1) + 0.05 * d.x * d.z;
    return {base * 1.05 + 0.02 * d.x, base, base * 0.9 + 0.03 * d.y};
}

const Vec3d kSun = normalized({0.45, 0.7, -0.55});

/// A sky over a darker ground and a warm sun lobe, all below 1 so the 8-bit frame does not clip.
Rgb sunnySky(const Vec3d& d)
{
    const Rgb zenith{0.12, 0.2, 0.42}, horizon{0.35, 0.38, 0.42}, ground{0.08, 0.07, 0.06};
    Rgb light{};
    for (int c = 0; c < 3; ++c)
        light[size_t(c)] = d.y > 0 ? horizon[size_t(c)] + (zenith[size_t(c)] - horizon[size_t(c)]) * d.y : ground[size_t(c)];
    const double lobe = 0.5 * std::pow(std::max(0.0, dot(d, kSun)), 12);
    const Rgb warm{1.0, 0.85, 0.65};
    for (int c = 0; c < 3; ++c)
        light[size_t(c)] += lobe * warm[size_t(c)];
    return light;
}

std::uint8_t toSrgb8(double linear, double noise)
{
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::clamp(std::lround(s * 255.0 + noise), 0L, 255L));
}

/// What a camera sees of a chrome ball of the given circle lit by `light`, on a plain background:
/// each pixel averages 4 × 4 samples in linear light, then sRGB 8-bit with Gaussian noise.
VideoFrame mirrorBallFrame(int width, int height, const BallCircle& ball, const Environment& light, double background = 0.06,
                           double noise = 1.0, unsigned seed = 1)
{
    VideoFrame frame;
    frame.resize(width, height);
    frame.index = 0;
    std::mt19937 random(seed);
    std::normal_distribution<double> sensor(0.0, noise);
    constexpr int kSamples = 4;
    constexpr int kLayoutSize = 2000; // any size: the mirror-ball mapping is scale-free
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Rgb sum{};
            if (std::hypot(x + 0.5 - ball.centerX, y + 0.5 - ball.centerY) > ball.radius + 1)
                sum = {background, background, background};
            else
                for (int b = 0; b < kSamples; ++b)
                    for (int a = 0; a < kSamples; ++a) {
                        const double u = (x + (a + 0.5) / kSamples - ball.centerX) / ball.radius;
                        const double v = (ball.centerY - (y + (b + 0.5) / kSamples)) / ball.radius;
                        Vec3d d;
                        // The layout's pixel coordinates of the disc point (u, v).
                        const double px = 0.5 * kLayoutSize * (1 + u) - 0.5, py = 0.5 * kLayoutSize * (1 - v) - 0.5;
                        const bool onBall = u * u + v * v <= 1.0
                                            && lighting::directionOfPixel(lighting::ProbeLayout::MirrorBall, kLayoutSize,
                                                                          kLayoutSize, px, py, d);
                        const Rgb value = onBall ? light(d) : Rgb{background, background, background};
                        for (int c = 0; c < 3; ++c)
                            sum[size_t(c)] += value[size_t(c)] / (kSamples * kSamples);
                    }
            std::uint8_t* p = frame.bgr.data() + 3 * (size_t(y) * size_t(width) + size_t(x));
            for (int c = 0; c < 3; ++c)
                p[2 - c] = toSrgb8(sum[size_t(c)], noise > 0 ? sensor(random) : 0.0);
        }
    return frame;
}

/// The light's SH the direct way: a 1024 × 512 lat-long sampled at pixel centres, projected by
/// the same projector (its fit gives a band-limited light's coefficients back to rounding).
ShRgb referenceLight(const Environment& light, int order)
{
    lighting::HdrImage image;
    image.width = 1024;
    image.height = 512;
    image.rgb.resize(size_t(image.width) * size_t(image.height) * 3);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            Vec3d d;
            lighting::directionOfPixel(lighting::ProbeLayout::LatLong, image.width, image.height, x, y, d);
            const Rgb value = light(d);
            for (int c = 0; c < 3; ++c)
                image.rgb[3 * (size_t(y) * size_t(image.width) + size_t(x)) + size_t(c)] = float(value[size_t(c)]);
        }
    auto projector = lighting::ProbeProjector::create(lighting::ProbeLayout::LatLong, image.width, image.height, order);
    EXPECT_TRUE(projector) << projector.error().message;
    auto projected = projector->project(image);
    EXPECT_TRUE(projected) << projected.error().message;
    return *projected;
}

/// √(Σ (a − b)²) / √(Σ b²) over every coefficient of the three channels.
double relativeRms(const ShRgb& a, const ShRgb& b)
{
    double difference = 0, norm = 0;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < b.order * b.order; ++i) {
            difference += std::pow(a[c][size_t(i)] - b[c][size_t(i)], 2);
            norm += std::pow(b[c][size_t(i)], 2);
        }
    return std::sqrt(difference / norm);
}

double degreesBetween(const Vec3d& a, const Vec3d& b)
{
    return std::acos(std::clamp(dot(normalized(a), normalized(b)), -1.0, 1.0)) * 180 / std::numbers::pi;
}

void printDirection(const char* what, const Vec3d& d)
{
    std::printf("%s: dominant light towards (%.3f, %.3f, %.3f)\n", what, d.x, d.y, d.z);
}

const BallCircle kBall{331.3, 228.7, 150.4}; // sub-pixel on purpose

} // namespace

TEST(LiveProbe, RecoversABandLimitedLightFromASyntheticMirrorBall)
{
    const VideoFrame frame = mirrorBallFrame(640, 480, kBall, bandLimitedLight);
    ASSERT_TRUE(writePicture(thespis::test::artifact("live_probe_band_limited.png"), frame));
    auto probe = LiveProbe::create();
    ASSERT_TRUE(probe) << probe.error().message;
    ASSERT_TRUE(probe->update(frame)) << probe->ball().reason;
    const BallCircle found = probe->ball().circle;
    std::printf("circle: found (%.3f, %.3f) r %.3f, true (%.3f, %.3f) r %.3f\n", found.centerX, found.centerY, found.radius,
                kBall.centerX, kBall.centerY, kBall.radius);
    EXPECT_LT(std::hypot(found.centerX - kBall.centerX, found.centerY - kBall.centerY), 0.25);
    EXPECT_NEAR(found.radius, kBall.radius, 0.15);

    const ShRgb truth = referenceLight(bandLimitedLight, 6);
    const ShRgb& light = probe->light();
    ASSERT_EQ(light.order, 6);
    const double error = relativeRms(light, truth);
    const double angle = degreesBetween(render::dominantLight(light).direction, render::dominantLight(truth).direction);
    std::printf("band-limited light: relative RMS %.4f over 3 × 36 coefficients, dominant direction off by %.2f°\n", error, angle);
    EXPECT_LT(error, 0.002);
    EXPECT_LT(angle, 0.15);
    EXPECT_EQ(probe->clippedFraction(), 0.0);
    EXPECT_EQ(probe->picture().width, 128);
    const auto captured = probe->probe();
    ASSERT_TRUE(captured) << captured.error().message;
    EXPECT_EQ(captured->layout(), lighting::ProbeLayout::MirrorBall);
    EXPECT_EQ(captured->image().width, 128);
}

TEST(LiveProbe, FollowsTheBallAsTheCameraMoves)
{
    // A small move is confirmed where the ball was; a jump further than the rim search reaches
    // makes the probe search the whole frame again. Both land on the true circle.
    LiveProbeSettings settings;
    settings.updateEvery = 1;
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe);
    const BallCircle path[] = {kBall, {kBall.centerX + 2.6, kBall.centerY - 1.9, kBall.radius + 1.2},
                               {kBall.centerX - 90.4, kBall.centerY + 40.2, kBall.radius - 30.3}};
    for (int i = 0; i < 3; ++i) {
        VideoFrame frame = mirrorBallFrame(640, 480, path[i], bandLimitedLight, 0.06, 1.0, unsigned(i + 1));
        frame.index = i;
        frame.time = i / 30.0;
        ASSERT_TRUE(probe->update(frame)) << "frame " << i << ": " << probe->ball().reason;
        const BallCircle found = probe->ball().circle;
        EXPECT_LT(std::hypot(found.centerX - path[i].centerX, found.centerY - path[i].centerY), 0.25) << "frame " << i;
        EXPECT_NEAR(found.radius, path[i].radius, 0.15) << "frame " << i;
    }
}

TEST(LiveProbe, RecoversASunnySkyAndItsSunDirection)
{
    const VideoFrame frame = mirrorBallFrame(640, 480, kBall, sunnySky, 0.06, 1.0, 2);
    ASSERT_TRUE(writePicture(thespis::test::artifact("live_probe_sunny.png"), frame));
    auto probe = LiveProbe::create();
    ASSERT_TRUE(probe);
    ASSERT_TRUE(probe->update(frame)) << probe->ball().reason;
    EXPECT_LT(std::hypot(probe->ball().circle.centerX - kBall.centerX, probe->ball().circle.centerY - kBall.centerY), 0.25);
    EXPECT_NEAR(probe->ball().circle.radius, kBall.radius, 0.15);
    const ShRgb truth = referenceLight(sunnySky, 6);
    const double error = relativeRms(probe->light(), truth);
    const Vec3d direction = render::dominantLight(probe->light()).direction;
    const double angle = degreesBetween(direction, render::dominantLight(truth).direction);
    std::printf("sunny sky: relative RMS %.4f, dominant direction off by %.2f° (%.2f° from the sun itself)\n", error, angle,
                degreesBetween(direction, kSun));
    EXPECT_LT(error, 0.006);
    EXPECT_LT(angle, 0.3);
}

TEST(LiveProbe, SmoothsASuddenChangeOverItsTimeConstant)
{
    const auto dim = [](const Vec3d&) { return Rgb{0.2, 0.2, 0.2}; };
    const auto bright = [](const Vec3d&) { return Rgb{0.6, 0.6, 0.6}; };
    VideoFrame before = mirrorBallFrame(320, 240, {160, 120, 80}, dim, 0.06, 0.0);
    VideoFrame after = mirrorBallFrame(320, 240, {160, 120, 80}, bright, 0.06, 0.0);
    LiveProbeSettings settings;
    settings.location = BallLocation::Given;
    settings.givenCircle = {160, 120, 80};
    settings.updateEvery = 3;
    settings.smoothingSeconds = 0.5;
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe) << probe.error().message;
    constexpr double fps = 30;
    // The dim light until frame 30, then the bright one; every third frame is processed.
    const auto dc = [&] { return probe->light()[1][0]; };
    double dimDc = 0, brightDc = 0;
    for (int i = 0; i < 30; ++i) {
        before.index = i;
        before.time = i / fps;
        EXPECT_EQ(probe->update(before), i % 3 == 0) << "frame " << i;
    }
    dimDc = dc();
    // The last dim frame processed was 27 (0.9 s); the light changed after it.
    std::vector<double> fraction;
    for (int i = 30; i < 30 + 150; ++i) {
        after.index = i;
        after.time = i / fps;
        probe->update(after);
        fraction.push_back(dc());
    }
    brightDc = dc();
    const auto reached = [&](int frameIndex) { return (fraction[size_t(frameIndex - 30)] - dimDc) / (brightDc - dimDc); };
    // 150 frames = 10 time constants: settled on what the bright frame gives at once.
    auto fresh = LiveProbe::create(settings);
    ASSERT_TRUE(fresh && fresh->update(after));
    EXPECT_NEAR(brightDc, fresh->light()[1][0], 1e-4 * brightDc);
    EXPECT_LT(reached(30), 0.2);              // not at once: 1 − e^(−0.1 / 0.5)
    EXPECT_NEAR(reached(30), 1 - std::exp(-0.2), 0.01);
    // One time constant after the last dim frame (27 + 15 = frame 42): 1 − 1/e.
    std::printf("after one time constant: %.3f of the change (1 − 1/e = %.3f)\n", reached(42), 1 - std::exp(-1.0));
    EXPECT_NEAR(reached(42), 1 - std::exp(-1.0), 0.01);
}

TEST(LiveProbe, AutomaticExposureBringsTheBallToItsTarget)
{
    LiveProbeSettings settings;
    settings.exposureMode = ProbeExposure::Automatic;
    settings.targetLuminance = 0.5;
    settings.exposureSmoothingSeconds = 1.0;
    settings.updateEvery = 1;
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe);
    VideoFrame frame = mirrorBallFrame(320, 240, {150, 125, 70}, bandLimitedLight, 0.06, 0.0);
    ASSERT_TRUE(probe->update(frame));
    // Mean radiance over the sphere is L₀₀·Y₀₀, Y₀₀ = 1/√(4π).
    const auto meanLuminance = [&] {
        const ShRgb& l = probe->light();
        return (0.2126 * l[0][0] + 0.7152 * l[1][0] + 0.0722 * l[2][0]) / std::sqrt(4 * std::numbers::pi);
    };
    EXPECT_NEAR(meanLuminance(), 0.5, 0.01);
    // The camera's picture gets darker at once: the exposure follows over its own time constant.
    const auto darker = [](const Vec3d& d) {
        Rgb value = bandLimitedLight(d);
        for (double& v : value)
            v *= 0.5;
        return value;
    };
    VideoFrame dark = mirrorBallFrame(320, 240, {150, 125, 70}, darker, 0.06, 0.0);
    const double exposureBefore = probe->exposure();
    dark.index = 1;
    dark.time = 0.1;
    ASSERT_TRUE(probe->update(dark));
    EXPECT_GT(probe->exposure(), exposureBefore);
    EXPECT_LT(probe->exposure(), 1.2 * exposureBefore);
    for (int i = 2; i < 150; ++i) {
        dark.index = i;
        dark.time = 0.1 * i;
        probe->update(dark);
    }
    EXPECT_NEAR(probe->exposure() / exposureBefore, 2.0, 0.05);
    EXPECT_NEAR(meanLuminance(), 0.5, 0.01);
}

TEST(LiveProbe, ClippedHighlightsAreCountedAndTakenAsBrighter)
{
    const auto burnt = [](const Vec3d& d) { // a sun far too bright for the camera
        Rgb value = sunnySky(d);
        if (dot(d, kSun) > 0.95)
            value = {4.0, 4.0, 4.0};
        return value;
    };
    const VideoFrame frame = mirrorBallFrame(320, 240, {160, 120, 90}, burnt, 0.06, 0.0);
    LiveProbeSettings settings;
    settings.location = BallLocation::Given;
    settings.givenCircle = {160, 120, 90};
    auto plain = LiveProbe::create(settings);
    settings.clippedGain = 4.0;
    auto boosted = LiveProbe::create(settings);
    ASSERT_TRUE(plain && boosted);
    ASSERT_TRUE(plain->update(frame) && boosted->update(frame));
    std::printf("clipped: %.4f of the ball\n", plain->clippedFraction());
    EXPECT_GT(plain->clippedFraction(), 0.005);
    EXPECT_LT(plain->clippedFraction(), 0.05);
    EXPECT_GT(boosted->light()[0][0], 1.1 * plain->light()[0][0]);
}

TEST(LiveProbe, FindsTheBallInTheRealPhotos)
{
    struct Photo {
        const char* file;
        int top, bottom, left, right; // mirrorball_params.json's hand-tuned crop
    };
    for (const Photo& photo : {Photo{"room.jpg", 71, 62, 62, 74}, Photo{"tisch.jpg", 84, 150, 116, 118}}) {
        SCOPED_TRACE(photo.file);
        auto picture = readPicture(thespis::test::sharedData("vision/mirrorball") / photo.file);
        ASSERT_TRUE(picture) << picture.error().message;
        // Reduced 4 × 4 → 1 (box) for speed: 4096² → 1024², 4000² → 1000².
        constexpr int k = 4;
        VideoFrame frame;
        frame.resize(picture->width / k, picture->height / k);
        frame.index = 0;
        for (int y = 0; y < frame.height; ++y)
            for (int x = 0; x < frame.width; ++x)
                for (int c = 0; c < 3; ++c) {
                    int sum = 0;
                    for (int b = 0; b < k; ++b)
                        for (int a = 0; a < k; ++a)
                            sum += picture->bgr[3 * (size_t(y * k + b) * size_t(picture->width) + size_t(x * k + a))
                                                + size_t(c)];
                    frame.bgr[3 * (size_t(y) * size_t(frame.width) + size_t(x)) + size_t(c)] =
                        std::uint8_t((sum + k * k / 2) / (k * k));
                }
        // The crop's square, in the reduced frame: its centre, and half its mean side.
        const double cropWidth = picture->width - photo.left - photo.right, cropHeight = picture->height - photo.top - photo.bottom;
        const BallCircle crop{(photo.left + 0.5 * cropWidth) / k, (photo.top + 0.5 * cropHeight) / k,
                              0.25 * (cropWidth + cropHeight) / k};
        auto probe = LiveProbe::create();
        ASSERT_TRUE(probe);
        ASSERT_TRUE(probe->update(frame)) << probe->ball().reason;
        const BallCircle found = probe->ball().circle;
        std::printf("%s: found (%.2f, %.2f) r %.2f, crop (%.2f, %.2f) r %.2f (px of %d)\n", photo.file, found.centerX, found.centerY,
                    found.radius, crop.centerX, crop.centerY, crop.radius, frame.width);
        EXPECT_LT(std::hypot(found.centerX - crop.centerX, found.centerY - crop.centerY), 3.0);
        EXPECT_NEAR(found.radius, crop.radius, 0.01 * crop.radius);
        const ShRgb& light = probe->light();
        for (int c = 0; c < 3; ++c) {
            EXPECT_GT(light[c][0], 0.0);
            for (double value : light[c])
                EXPECT_TRUE(std::isfinite(value));
        }
        printDirection(photo.file, render::dominantLight(light).direction);
        std::printf("%s: clipped %.4f of the ball\n", photo.file, probe->clippedFraction());
        const lighting::PreviewImage& shown = probe->picture();
        VideoFrame unwrapped;
        unwrapped.resize(shown.width, shown.height);
        unwrapped.index = 0;
        for (size_t p = 0; p < size_t(shown.width) * size_t(shown.height); ++p)
            for (int c = 0; c < 3; ++c)
                unwrapped.bgr[3 * p + size_t(2 - c)] = shown.rgba[4 * p + size_t(c)];
        EXPECT_TRUE(writePicture(thespis::test::artifact(std::string("live_probe_") + photo.file + ".png"), unwrapped));
    }
}

TEST(LiveProbe, AFrameWithoutABallKeepsTheLight)
{
    LiveProbeSettings settings;
    settings.updateEvery = 1;
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe);
    EXPECT_FALSE(probe->hasLight());
    VideoFrame frame = mirrorBallFrame(640, 480, kBall, bandLimitedLight);
    ASSERT_TRUE(probe->update(frame));
    const ShRgb before = probe->light();
    // A plain wall with a dark doorway: edges, but no circle.
    VideoFrame empty;
    empty.resize(640, 480);
    empty.index = 5;
    empty.time = 5 / 30.0;
    for (int y = 0; y < 480; ++y)
        for (int x = 0; x < 640; ++x)
            for (int c = 0; c < 3; ++c)
                empty.bgr[3 * (size_t(y) * 640 + size_t(x)) + size_t(c)] =
                    (x > 200 && x < 320 && y > 150) ? 30 : std::uint8_t(120 + x / 10);
    EXPECT_FALSE(probe->update(empty));
    EXPECT_FALSE(probe->ball().found);
    EXPECT_NE(probe->ball().reason.find("No circle between 19 and 240 px"), std::string::npos) << probe->ball().reason;
    ASSERT_EQ(probe->light().order, before.order);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 36; ++i)
            EXPECT_EQ(probe->light()[c][size_t(i)], before[c][size_t(i)]);
}

TEST(LiveProbe, AGivenCircleOutsideTheFrameIsRefused)
{
    LiveProbeSettings settings;
    settings.location = BallLocation::Given;
    settings.givenCircle = {600, 240, 100};
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe);
    const VideoFrame frame = mirrorBallFrame(640, 480, kBall, bandLimitedLight);
    EXPECT_FALSE(probe->update(frame));
    EXPECT_FALSE(probe->ball().found);
    EXPECT_FALSE(probe->hasLight());
    const std::string& reason = probe->ball().reason;
    for (const char* part : {"600", "240", "100", "right", "640×480"})
        EXPECT_NE(reason.find(part), std::string::npos) << part << " in: " << reason;
    EXPECT_FALSE(checkBallCircle({50, 60, 70}, 640, 480));
    EXPECT_TRUE(checkBallCircle({70, 70, 70}, 640, 480));
}

TEST(LiveProbe, RefusesBadSettings)
{
    const auto refused = [](const LiveProbeSettings& settings, const char* named) {
        auto probe = LiveProbe::create(settings);
        ASSERT_FALSE(probe) << named;
        EXPECT_NE(probe.error().message.find(named), std::string::npos) << probe.error().message;
    };
    LiveProbeSettings s;
    s.order = 0;
    refused(s, "order");
    s = {};
    s.updateEvery = 0;
    refused(s, "updateEvery");
    s = {};
    s.smoothingSeconds = -1;
    refused(s, "smoothingSeconds");
    s = {};
    s.exposure = 0;
    refused(s, "exposure");
    s = {};
    s.clippedGain = 0.5;
    refused(s, "clippedGain");
    s = {};
    s.minRadius = 50;
    s.maxRadius = 20;
    refused(s, "minRadius (50 px)");
    s = {};
    s.location = BallLocation::Given;
    s.givenCircle = {100, 100, 0};
    refused(s, "radius 0 px");
    s = {};
    s.probeSize = 8;
    refused(s, "probeSize");
}

TEST(LiveProbe, AProbeFileLightsAsTheScenarioProbeDoes)
{
    lighting::HdrImage image;
    image.width = 256;
    image.height = 128;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            Vec3d d;
            lighting::directionOfPixel(lighting::ProbeLayout::LatLong, image.width, image.height, x, y, d);
            for (double v : sunnySky(d))
                image.rgb.push_back(float(v));
        }
    const auto path = thespis::test::artifact("live_probe_sky.hdr");
    ASSERT_TRUE(lighting::writeRadianceHdr(path, image));
    auto probe = LiveProbe::fromFile(path, lighting::ProbeLayout::LatLong, 5);
    ASSERT_TRUE(probe) << probe.error().message;
    EXPECT_FALSE(probe->fromBall());
    const auto direct = lighting::projectProbeFile(path, lighting::ProbeLayout::LatLong, 5);
    ASSERT_TRUE(direct);
    ASSERT_EQ(probe->light().order, 5);
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < 25; ++i)
            EXPECT_EQ(probe->light()[c][size_t(i)], (*direct)[c][size_t(i)]);
    EXPECT_FALSE(probe->update(mirrorBallFrame(320, 240, {160, 120, 80}, bandLimitedLight)));
    EXPECT_NE(probe->ball().reason.find("live_probe_sky.hdr"), std::string::npos);
    EXPECT_EQ(probe->picture().width, 256);
    EXPECT_TRUE(probe->probe());
    EXPECT_FALSE(LiveProbe::fromFile(thespis::test::artifact("no_such_probe.hdr"), lighting::ProbeLayout::LatLong));
}

TEST(LiveProbe, AllocatesOnlyInTheProjectorOnceRunning)
{
    LiveProbeSettings settings;
    settings.location = BallLocation::Given;
    settings.givenCircle = kBall;
    settings.updateEvery = 1;
    auto probe = LiveProbe::create(settings);
    ASSERT_TRUE(probe);
    VideoFrame frame = mirrorBallFrame(640, 480, kBall, bandLimitedLight, 0.06, 0.0);
    ASSERT_TRUE(probe->update(frame));
    frame.index = 1;
    frame.time = 1 / 30.0;
    const long before = thespis::test::allocationCount();
    ASSERT_TRUE(probe->update(frame));
    const long allocations = thespis::test::allocationCount() - before;
    std::printf("allocations in a steady-state update with a given circle: %ld\n", allocations);
    // ProbeProjector::project's per-call partial sums; nothing of the live probe's own.
    EXPECT_LE(allocations, 1);
}

TEST(LiveProbe, FindsNoBallWhereThereIsNone)
{
    // The studio's test pattern (a marker board moved by hand, with noise, blur and a hand over
    // it) and OpenCV's real photos of boards, markers and scenes: their squares and corners
    // suggest circles to a Hough search (before the rim had to run along its circle, 13 of these
    // 29 photos and nearly every board frame had a "ball"); the rim check turns each one down.
    // Also checked once over 1500 frames of five boards and two seeds: none.
    LiveProbeSettings settings;
    settings.updateEvery = 1;
    int looked = 0;
    const auto expectNoBall = [&](const VideoFrame& frame, const std::string& what) {
        auto probe = LiveProbe::create(settings);
        ASSERT_TRUE(probe);
        ++looked;
        EXPECT_FALSE(probe->update(frame)) << what << ": a ball at (" << probe->ball().circle.centerX << ", "
                                           << probe->ball().circle.centerY << "), radius " << probe->ball().circle.radius;
    };
    for (const char* spec : {"aruco-grid:DICT_4X4_50:4x3:0.04:0.01", "charuco:DICT_4X4_1000:5x7:0.03:0.022"}) {
        SyntheticScene scene;
        scene.board = parseBoard(spec).value();
        scene.camera.width = 640;
        scene.camera.height = 480;
        scene.camera.matrix = {600, 0, 320, 0, 600, 240, 0, 0, 1};
        scene.frames = 90;
        scene.handOver = {30, 60};
        auto source = SyntheticSource::create(scene);
        ASSERT_TRUE(source);
        VideoFrame frame;
        while (source.value()->read(frame).value())
            if (frame.index % 3 == 0)
                expectNoBall(frame, std::string(spec) + " frame " + std::to_string(frame.index));
    }
    for (const char* folder : {"vision/aruco", "vision/aruco_real", "vision/calibration", "vision/features"})
        for (const auto& entry : std::filesystem::directory_iterator(thespis::test::sharedData(folder))) {
            const std::string extension = entry.path().extension().string();
            if (extension != ".jpg" && extension != ".png")
                continue;
            auto picture = readPicture(entry.path());
            ASSERT_TRUE(picture) << picture.error().message;
            expectNoBall(*picture, entry.path().string());
        }
    EXPECT_EQ(looked, 60 + 29);
}
