// core/ar's marker tracking on footage it did not render (issue 29): an ArUco grid drawn, warped
// and averaged down by OpenCV as a sensor integrates light (sensor_footage.h), with noise and box
// smears of several lengths and directions. Scored against the poses that made it and against
// OpenCV's own per-frame pose (cv::aruco::estimatePoseBoard on its sub-pixel corners) on the same
// frames. The figures are the issue's: rotation ≤ 0.10° mean over all frames and better than
// OpenCV's, translation ≤ 1 mm mean and ≤ 3 mm max, the filter never worse than each frame alone
// on the sharp frames; smeared frames within a bound of the sharp ones (see the sweep).

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <numbers>
#include <optional>

#include <opencv2/aruco.hpp>
#include <opencv2/calib3d.hpp>

#include "ar/board.h"
#include "ar/marker_tracker.h"
#include "ar/tracking_session.h"
#include "sensor_footage.h"

using namespace thespis::core::ar;
using thespis::test::SensorFootage;
using thespis::test::SensorFootageSettings;

namespace {

constexpr double Degree = std::numbers::pi / 180;

// Errors split between sharp and smeared frames.
struct Score {
    double rotation[2] = {}, translation[2] = {}, maxTranslation = 0, maxRotation[2] = {};
    int frames[2] = {}, missed = 0;
    void add(const TargetPose& pose, const TargetPose& truth, bool smeared)
    {
        const double r = rotationDifference(pose, truth), t = translationDifference(pose, truth);
        rotation[smeared] += r, translation[smeared] += t, ++frames[smeared];
        maxTranslation = std::max(maxTranslation, t);
        maxRotation[smeared] = std::max(maxRotation[smeared], r);
    }
    int all() const { return frames[0] + frames[1]; }
    double meanRotation() const { return (rotation[0] + rotation[1]) / all(); }
    double meanTranslation() const { return (translation[0] + translation[1]) / all(); }
    double sharpRotation() const { return frames[0] ? rotation[0] / frames[0] : 0; }
    double smearedRotation() const { return frames[1] ? rotation[1] / frames[1] : 0; }
};

std::ostream& operator<<(std::ostream& out, const Score& s)
{
    return out << "translation mean " << s.meanTranslation() * 1000 << " / max " << s.maxTranslation * 1000
               << " mm; rotation mean " << s.meanRotation() / Degree << "°, sharp " << s.sharpRotation() / Degree
               << "° / smeared " << s.smearedRotation() / Degree << "° (" << s.frames[0] << " + " << s.frames[1]
               << " frames, " << s.missed << " missed)";
}

struct FootageRun {
    Score filtered, raw, opencv;
    double milliseconds[2] = {}; // tracking time, sharp and smeared frames (for the log only)
    std::vector<double> smearedLengths, smearedAngles, sharpLengths;
};

// OpenCV's own pose of the frame: its detector with sub-pixel corners (the better of its
// refinements on this footage), then estimatePoseBoard.
std::optional<TargetPose> opencvPose(const cv::Mat& grey, const SensorFootage& footage)
{
    cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
    parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<int> ids;
    cv::aruco::detectMarkers(grey, footage.board->dictionary, corners, ids, parameters);
    cv::Vec3d rotation, translation;
    const cv::Ptr<cv::aruco::Board> board = footage.board;
    if (ids.empty() ||
        cv::aruco::estimatePoseBoard(corners, ids, board, footage.cameraMatrix(), cv::noArray(), rotation, translation) == 0)
        return std::nullopt;
    return TargetPose{{rotation[0], rotation[1], rotation[2]}, {translation[0], translation[1], translation[2]}};
}

// The first `frames` frames of the footage (all when 0).
FootageRun track(const SensorFootageSettings& settings, int frames = 0)
{
    SensorFootage footage(settings);
    auto tracker = MarkerTracker::create(*parseBoard(SensorFootage::BoardSpec), footage.camera());
    EXPECT_TRUE(tracker);
    TrackingSession session(std::move(*tracker));
    FootageRun run;
    for (int i = 0; i < (frames > 0 ? frames : footage.frames()); ++i) {
        const SensorFootage::Frame frame = footage.render(i);
        const VideoFrame video = SensorFootage::videoFrame(frame.grey, i);
        const auto start = std::chrono::steady_clock::now();
        const TrackedFrame tracked = session.process(video);
        run.milliseconds[frame.smeared] +=
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
        if (tracked.tracked) {
            run.filtered.add(tracked.pose, frame.truth, frame.smeared);
            run.raw.add(tracked.measured.pose, frame.truth, frame.smeared);
            if (frame.smeared) {
                run.smearedLengths.push_back(tracked.measured.blur.length);
                run.smearedAngles.push_back(tracked.measured.blur.angle);
            } else {
                run.sharpLengths.push_back(tracked.measured.blur.length);
            }
        } else {
            ++run.filtered.missed, ++run.raw.missed;
        }
        if (const std::optional<TargetPose> pose = opencvPose(frame.grey, footage))
            run.opencv.add(*pose, frame.truth, frame.smeared);
        else
            ++run.opencv.missed;
    }
    return run;
}

double median(std::vector<double> values)
{
    if (values.empty())
        return 0;
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

// The angle between two smear directions, which have no sign (radians, 0 … π/2).
double directionDifference(double a, double b)
{
    const double d = std::fmod(std::abs(a - b), std::numbers::pi);
    return std::min(d, std::numbers::pi - d);
}

} // namespace

// The issue's footage: 640 × 480, fx 600, 0.35–0.6 m, ±45° yaw, 0–40° pitch, noise σ 3, a
// 7-pixel horizontal smear on 2 frames in 10 (fewer frames than the issue's 300, over the same
// path, so the test stays short).
TEST(MarkerFootage, TheIssuesFootageMeetsItsFigures)
{
    SensorFootageSettings settings;
    settings.frames = 120;
    const FootageRun run = track(settings);
    std::cout << "filtered: " << run.filtered << "\nraw:      " << run.raw << "\nOpenCV:   " << run.opencv
              << "\ntracking: " << run.milliseconds[0] / run.filtered.frames[0] << " ms a sharp frame, "
              << run.milliseconds[1] / run.filtered.frames[1] << " ms a smeared one\n";
    EXPECT_EQ(run.filtered.missed, 0);
    EXPECT_EQ(run.opencv.missed, 0);
    EXPECT_LE(run.filtered.meanRotation(), 0.10 * Degree);
    EXPECT_LT(run.filtered.meanRotation(), run.opencv.meanRotation());
    EXPECT_LT(run.raw.meanRotation(), run.opencv.meanRotation());
    EXPECT_LE(run.filtered.meanTranslation(), 0.001);
    EXPECT_LE(run.filtered.maxTranslation, 0.003);
    EXPECT_LE(run.raw.maxTranslation, 0.003);
    // Smeared frames: better than OpenCV's on the same frames, and within 2× our sharp ones.
    // Fitting each marker's pattern, smeared, to the picture (core/ar/marker_synthesis.h) brings
    // them from 13× to about 1.1×; the edges alone leave a smear longer than the border biased
    // outward.
    EXPECT_LT(run.filtered.smearedRotation(), run.opencv.smearedRotation());
    EXPECT_LT(run.raw.smearedRotation(), run.opencv.smearedRotation());
    EXPECT_LE(run.filtered.smearedRotation(), 2 * run.filtered.sharpRotation());
    EXPECT_LE(run.raw.smearedRotation(), 2 * run.raw.sharpRotation());
    // The filter never makes the sharp frames worse than they are alone, nor the smeared ones
    // (which it used to trust too little once they were as good as the sharp ones).
    EXPECT_LE(run.filtered.sharpRotation(), run.raw.sharpRotation());
    EXPECT_LE(run.filtered.maxRotation[0], run.raw.maxRotation[0] * 1.1);
    EXPECT_LE(run.filtered.smearedRotation(), run.raw.smearedRotation() * 1.05);
}

// The issue's harder footage: a larger camera, an 11-pixel smear along 30°, the board farther and
// more oblique (yaw up to ±60° with pitch up to 40°; it stays over 60 pixels across), the first
// 120 frames of the issue's 300. The issue saw runs of frames 15–43 mm off here and the filter
// spreading a smeared frame's error into the sharp ones after it. Where the smear is longer than
// the markers' cells OpenCV's detector finds no marker at all; the tracker then fits the markers'
// patterns where the last frame saw them (marker_tracker.cpp), which keeps most of those frames.
TEST(MarkerFootage, FartherAndMoreObliqueWithALongerSmear)
{
    SensorFootageSettings settings;
    settings.width = 1280, settings.height = 720, settings.fx = 1000;
    settings.smear = 11, settings.smearAngle = 30;
    settings.nearest = 0.7, settings.farthest = 1.4;
    settings.yaw = 60;
    settings.seed = 5;
    const FootageRun run = track(settings, 120);
    std::cout << "filtered: " << run.filtered << "\nraw:      " << run.raw << "\nOpenCV:   " << run.opencv << "\n";
    EXPECT_EQ(run.filtered.frames[0], 96) << "every sharp frame is tracked";
    EXPECT_GE(run.filtered.frames[1], 12) << "most smeared frames are tracked";
    EXPECT_GT(run.filtered.frames[1], run.opencv.frames[1] + 8);
    EXPECT_LE(run.filtered.maxTranslation, 0.005);
    EXPECT_LE(run.filtered.meanTranslation(), 0.001);
    EXPECT_LT(run.filtered.meanRotation(), run.opencv.meanRotation() / 5);
    EXPECT_LT(run.filtered.smearedRotation(), run.raw.smearedRotation());
    // The filter does not carry the smeared frames' error into the sharp ones: they stay as good
    // as alone (within 5 %: 2–3 % worse here, as without the smeared frames at all).
    EXPECT_LE(run.filtered.sharpRotation(), 1.05 * run.raw.sharpRotation());
    EXPECT_LE(run.filtered.maxRotation[0], run.raw.maxRotation[0] * 1.1);
}

// Smears of 0, 5, 7 and 9 pixels along 0°, 45° and 90°, on every other frame: each frame's own
// pose (no filter to hide behind) against OpenCV's, and the blur the tracker reports.
TEST(MarkerFootage, SmearsOfEveryLengthAndDirection)
{
    for (const double length : {0.0, 5.0, 7.0, 9.0})
        for (const double angle : {0.0, 45.0, 90.0}) {
            if (length == 0 && angle > 0)
                continue;
            SensorFootageSettings settings;
            settings.frames = 30;
            settings.smear = length;
            settings.smearAngle = angle;
            settings.smearEvery = 2;
            settings.smearPhases = {1};
            settings.seed = 3;
            const FootageRun run = track(settings);
            SCOPED_TRACE(::testing::Message() << "smear " << length << " px at " << angle << "°");
            std::cout << "smear " << length << " px at " << angle << "°: raw " << run.raw << "\n    OpenCV "
                      << run.opencv << "\n    blur reported: sharp " << median(run.sharpLengths) << " px, smeared "
                      << median(run.smearedLengths) << " px at " << median(run.smearedAngles) / Degree << "°\n";
            EXPECT_EQ(run.raw.missed, 0);
            // OpenCV's own reaches 6 and 28 mm at 9 pixels here.
            EXPECT_LE(run.raw.maxTranslation, 0.003);
            EXPECT_LT(run.raw.maxTranslation, run.opencv.maxTranslation);
            EXPECT_LT(run.raw.meanRotation(), run.opencv.meanRotation());
            EXPECT_LE(run.raw.sharpRotation(), 0.03 * Degree);
            EXPECT_LT(median(run.sharpLengths), 2.0);
            if (length == 0)
                continue;
            EXPECT_LT(run.raw.smearedRotation(), run.opencv.smearedRotation());
            // Each smeared frame alone is within 2× the sharp ones up to 7 pixels (1.6× at most,
            // at 7 px along 90°; the edges alone gave 10×, 26× and 17× at 45°, 0° and 90°), and
            // within 4× at 9 pixels, which is wider than the nearer markers' borders (3×).
            EXPECT_LE(run.raw.smearedRotation(), (length <= 7 ? 2 : 4) * run.raw.sharpRotation());
            // The fitted smear, not the edges' ramps alone (which cannot tell a square marker's
            // +45° from −45°, and are off by 20–30° along x with the board turned about its
            // vertical): its length and direction.
            EXPECT_NEAR(median(run.smearedLengths), length, 0.05 * length);
            std::vector<double> off;
            for (const double a : run.smearedAngles)
                off.push_back(directionDifference(a, angle * Degree));
            EXPECT_LT(median(off), 3 * Degree);
        }
}
