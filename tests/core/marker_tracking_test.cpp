// core/ar's marker tracking (issue 16 §3): ArUco grids and ChArUco boards on synthetic footage
// with known poses (noise, motion blur, a hand over some markers, a stretch hidden) and on the
// real photos in ../shared/data/vision/aruco_real with OpenCV's own gold corners. The temporal
// filter must make the pose better than each frame's own estimate: ≤ 2 mm mean and ≤ 5 mm max
// translation error, ≤ 0.15° mean rotation error at 0.35–0.6 m, every frame tracked.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>

#include <nlohmann/json.hpp>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "ar/frame_source.h"
#include "ar/marker_tracker.h"
#include "ar/synthetic_source.h"
#include "ar/tracking_session.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using thespis::test::sharedData;

namespace {

constexpr double Degree = std::numbers::pi / 180;

// The camera of OpenCV's calibration sample (640 × 480), without distortion: the synthetic scene
// renders none.
CameraIntrinsics sampleCamera()
{
    CameraIntrinsics camera = *readCameraFile(sharedData("vision/calibration/left_intrinsics.yml"));
    camera.distortion.clear();
    return camera;
}

struct Errors {
    double meanTranslation = 0, maxTranslation = 0, meanRotation = 0, maxRotation = 0;
    int frames = 0;
    void add(const TargetPose& pose, const TargetPose& truth)
    {
        const double t = translationDifference(pose, truth), r = rotationDifference(pose, truth);
        meanTranslation += t, meanRotation += r, ++frames;
        maxTranslation = std::max(maxTranslation, t), maxRotation = std::max(maxRotation, r);
    }
    void finish() { meanTranslation /= frames, meanRotation /= frames; }
};

std::ostream& operator<<(std::ostream& out, const Errors& e)
{
    return out << "translation mean " << e.meanTranslation * 1000 << " mm, max " << e.maxTranslation * 1000
               << " mm; rotation mean " << e.meanRotation / Degree << "°, max " << e.maxRotation / Degree << "° over "
               << e.frames << " frames";
}

struct TrackingRun {
    Errors raw, filtered;
    std::int64_t frames = 0, tracked = 0, trackedWhileHidden = 0;
    std::vector<std::pair<std::int64_t, TrackingEvent>> events;
};

TrackingRun track(const SyntheticScene& scene)
{
    auto source = SyntheticSource::create(scene);
    EXPECT_TRUE(source) << source.error().message;
    auto tracker = MarkerTracker::create(scene.board, scene.camera);
    EXPECT_TRUE(tracker) << tracker.error().message;
    TrackingSession session(std::move(*tracker));
    TrackingRun run;
    VideoFrame frame;
    while (*(*source)->read(frame)) {
        const TrackedFrame tracked = session.process(frame);
        ++run.frames;
        if (tracked.event != TrackingEvent::None)
            run.events.emplace_back(frame.index, tracked.event);
        if (!(*source)->visible(frame.index)) {
            run.trackedWhileHidden += tracked.tracked ? 1 : 0;
            continue;
        }
        if (!tracked.tracked)
            continue;
        ++run.tracked;
        const TargetPose truth = (*source)->truth(frame.index);
        run.raw.add(tracked.measured.pose, truth);
        run.filtered.add(tracked.pose, truth);
    }
    run.raw.finish();
    run.filtered.finish();
    return run;
}

SyntheticScene gridScene()
{
    SyntheticScene scene;
    scene.board = *parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
    scene.camera = sampleCamera();
    scene.frames = 240;
    scene.noise = 3;
    scene.exposure = 0.5;
    scene.handOver = {90, 130};
    return scene;
}

} // namespace

TEST(MarkerTracking, TheFilteredGridPoseMeetsTheGoalOnNoisyBlurredFootage)
{
    const TrackingRun run = track(gridScene());
    std::cout << "raw:      " << run.raw << "\nfiltered: " << run.filtered << "\n";
    EXPECT_EQ(run.tracked, run.frames) << "every frame tracked, the hand's too";
    EXPECT_LE(run.filtered.meanTranslation, 0.002);
    EXPECT_LE(run.filtered.maxTranslation, 0.005);
    EXPECT_LE(run.filtered.meanRotation, 0.15 * Degree);
    // Better than each frame's own estimate, not only smoother.
    EXPECT_LT(run.filtered.meanTranslation, run.raw.meanTranslation);
    EXPECT_LT(run.filtered.meanRotation, run.raw.meanRotation);
}

TEST(MarkerTracking, AHiddenBoardIsLostThenRecovered)
{
    SyntheticScene scene = gridScene();
    scene.frames = 150;
    scene.handOver = {-1, -1};
    scene.hidden = {60, 90};
    const TrackingRun run = track(scene);
    EXPECT_EQ(run.trackedWhileHidden, 0);
    EXPECT_EQ(run.tracked, run.frames - 30) << "every visible frame tracked";
    ASSERT_EQ(run.events.size(), 3u);
    EXPECT_EQ(run.events[0], std::make_pair(std::int64_t(0), TrackingEvent::Found));
    EXPECT_EQ(run.events[1], std::make_pair(std::int64_t(60), TrackingEvent::Lost));
    EXPECT_EQ(run.events[2], std::make_pair(std::int64_t(90), TrackingEvent::Recovered));
    std::cout << "filtered after recovery included: " << run.filtered << "\n";
    EXPECT_LE(run.filtered.maxTranslation, 0.005);
}

TEST(MarkerTracking, AChArUcoBoardPrintedWhiteOnBlackIsTracked)
{
    SyntheticScene scene = gridScene();
    scene.board = *parseBoard("charuco:DICT_4X4_1000:5x7:0.03:0.022:inverted");
    scene.frames = 90;
    scene.handOver = {-1, -1};
    const TrackingRun run = track(scene);
    std::cout << "ChArUco raw: " << run.raw << "\nChArUco filtered: " << run.filtered << "\n";
    EXPECT_EQ(run.tracked, run.frames);
    EXPECT_LE(run.filtered.meanTranslation, 0.002);
    EXPECT_LE(run.filtered.meanRotation, 0.5 * Degree); // 24 corners on a 15 × 21 cm board, up to 0.6 m away
}

TEST(MarkerTracking, RealPhotosGiveOpenCVsGoldCorners)
{
    std::ifstream in(sharedData("vision/aruco_real/gold_detections.json"));
    const nlohmann::json gold = nlohmann::json::parse(in);
    int checked = 0;
    for (const nlohmann::json& image : gold["images"]) {
        const std::string dictionary = image["dictionary"];
        if (!dictionary.starts_with("DICT_") || !image.contains("markers"))
            continue; // a custom dictionary
        const auto frame = readPicture(sharedData("vision/aruco_real") / image["file"].get<std::string>());
        ASSERT_TRUE(frame) << frame.error().message;
        // The gold corners are OpenCV's whole-pixel ones: compared without the sub-pixel refinement.
        const auto markers = detectMarkers(*frame, dictionary, MarkerCorners::WholePixels);
        ASSERT_TRUE(markers) << markers.error().message;
        const auto refined = detectMarkers(*frame, dictionary);
        ASSERT_TRUE(refined) << refined.error().message;
        EXPECT_EQ(refined->size(), markers->size());
        for (const nlohmann::json& expected : image["markers"]) {
            const int id = expected["id"];
            const auto found = std::find_if(markers->begin(), markers->end(), [&](const auto& m) { return m.id == id; });
            ASSERT_NE(found, markers->end()) << image["file"] << " marker " << id;
            for (std::size_t c = 0; c < 4; ++c) {
                EXPECT_NEAR(found->corners[c][0], expected["corners_xy"][c][0].get<double>(), 1.0) << image["file"] << id;
                EXPECT_NEAR(found->corners[c][1], expected["corners_xy"][c][1].get<double>(), 1.0) << image["file"] << id;
            }
            ++checked;
        }
    }
    EXPECT_GE(checked, 20);
}

TEST(MarkerTracking, RealChArUcoViewsGiveAPoseThatFits)
{
    const auto camera = readCameraFile(sharedData("vision/aruco_real/tutorial_camera_charuco.yml"));
    ASSERT_TRUE(camera) << camera.error().message;
    const BoardSpec board = *parseBoard("charuco:DICT_6X6_250:5x7:0.04:0.02");
    for (const char* name : {"charuco_img_00.jpg", "charuco_img_01.jpg", "charuco_img_02.jpg", "charuco_img_03.jpg",
                             "chocclusion_original.jpg"}) {
        auto tracker = MarkerTracker::create(board, *camera);
        ASSERT_TRUE(tracker);
        const auto frame = readPicture(sharedData("vision/aruco_real") / name);
        ASSERT_TRUE(frame);
        const TrackerEstimate estimate = (*tracker)->estimate(*frame);
        ASSERT_TRUE(estimate.found) << name;
        std::cout << name << ": " << estimate.features << " corners, " << estimate.reprojectionError << " px, at "
                  << estimate.pose.translation[2] << " m\n";
        EXPECT_GE(estimate.features, 12) << name;
        EXPECT_LT(estimate.reprojectionError, 1.0) << name;
        EXPECT_GT(estimate.pose.translation[2], 0.1) << name;
        EXPECT_LT(estimate.pose.translation[2], 1.0) << name;
    }
}

TEST(MarkerTracking, BadBoardsAndCamerasAreRefused)
{
    EXPECT_FALSE(parseBoard("aruco-grid:DICT_9X9_50:4x3:0.04:0.01"));
    const auto tooMany = parseBoard("aruco-grid:DICT_4X4_50:8x8:0.04:0.01");
    ASSERT_FALSE(tooMany);
    EXPECT_NE(tooMany.error().message.find("64 markers but DICT_4X4_50 has only 50"), std::string::npos)
        << tooMany.error().message;
    const auto chessboard = MarkerTracker::create(*parseBoard("chessboard:9x6:0.025"), sampleCamera());
    ASSERT_FALSE(chessboard);
    EXPECT_NE(chessboard.error().message.find("calibration only"), std::string::npos);
    EXPECT_FALSE(MarkerTracker::create(*parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01"), CameraIntrinsics{}));
    EXPECT_FALSE(detectMarkers(VideoFrame{}, "DICT_NOPE"));
}
