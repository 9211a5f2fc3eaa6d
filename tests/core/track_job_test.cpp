// core/ar's TrackJob, the path `thespis-cli track`, Python and the studio take: synthetic footage
// with known poses written as an H.264 video (so compression is in the way, as with a real
// camera), tracked frame by frame, the CSV read back and compared with the truth; the real
// ChArUco photos as a picture sequence; and the inputs a user gets wrong.

#include <gtest/gtest.h>

#include <fstream>
#include <numbers>
#include <sstream>

#include "ar/frame_source.h"
#include "ar/synthetic_source.h"
#include "ar/track_job.h"
#include "ar/video_writer.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using thespis::test::artifact;
using thespis::test::sharedData;

namespace {

struct CsvRow {
    std::int64_t frame = -1;
    bool tracked = false;
    TargetPose pose;
};

std::vector<CsvRow> readCsv(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "frame,tracked,rx,ry,rz,tx,ty,tz,blur_px,blur_deg,ambiguity");
    std::vector<CsvRow> rows;
    while (std::getline(in, line)) {
        CsvRow row;
        std::replace(line.begin(), line.end(), ',', ' ');
        std::istringstream fields(line);
        int tracked = 0;
        fields >> row.frame >> tracked;
        row.tracked = tracked == 1;
        if (row.tracked)
            fields >> row.pose.rotation[0] >> row.pose.rotation[1] >> row.pose.rotation[2] >> row.pose.translation[0] >>
                row.pose.translation[1] >> row.pose.translation[2];
        rows.push_back(row);
    }
    return rows;
}

} // namespace

TEST(TrackJob, ASyntheticVideoTracksToItsTruthThroughCompression)
{
    SyntheticScene scene;
    scene.board = *parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
    scene.camera = *readCameraFile(sharedData("vision/calibration/left_intrinsics.yml"));
    scene.camera.distortion.clear();
    scene.frames = 90;
    scene.hidden = {40, 55};
    auto source = SyntheticSource::create(scene);
    ASSERT_TRUE(source) << source.error().message;
    const std::filesystem::path video = artifact("track_job/board.mp4");
    std::filesystem::create_directories(video.parent_path());
    {
        auto writer = VideoWriter::create(video, scene.camera.width, scene.camera.height, scene.fps);
        ASSERT_TRUE(writer) << writer.error().message;
        VideoFrame frame;
        while (*(*source)->read(frame))
            ASSERT_TRUE((*writer)->write(frame));
        ASSERT_TRUE((*writer)->finish());
    }
    const std::filesystem::path camera = artifact("track_job/camera.yml");
    ASSERT_TRUE(writeCameraFile(camera, scene.camera));

    TrackJob job;
    job.video = video;
    job.cameraFile = camera;
    job.target.board = scene.board;
    job.output = artifact("track_job/poses.csv");
    ASSERT_TRUE(job.validate());
    JobContext context;
    const auto ran = job.run(context);
    ASSERT_TRUE(ran) << ran.error().message;

    const std::vector<CsvRow> rows = readCsv(job.output);
    ASSERT_EQ(rows.size(), 90u);
    double meanTranslation = 0, meanRotation = 0;
    int tracked = 0;
    for (const CsvRow& row : rows) {
        const bool visible = (*source)->visible(row.frame);
        EXPECT_EQ(row.tracked, visible) << "frame " << row.frame;
        if (!row.tracked || !visible)
            continue;
        const TargetPose truth = (*source)->truth(row.frame);
        meanTranslation += translationDifference(row.pose, truth);
        meanRotation += rotationDifference(row.pose, truth);
        ++tracked;
    }
    meanTranslation /= tracked, meanRotation /= tracked;
    std::cout << "through H.264: " << meanTranslation * 1000 << " mm, " << meanRotation * 180 / std::numbers::pi
              << "° mean over " << tracked << " frames\n";
    EXPECT_EQ(tracked, 75);
    EXPECT_LE(meanTranslation, 0.002);
    EXPECT_LE(meanRotation, 0.3 * std::numbers::pi / 180);
    EXPECT_EQ(job.statistics.lost, 1);
}

TEST(TrackJob, TheRealChArUcoPhotosTrackAsAPictureSequence)
{
    TrackJob job;
    for (int i = 0; i < 4; ++i)
        job.pictures.push_back(sharedData("vision/aruco_real") / ("charuco_img_0" + std::to_string(i) + ".jpg"));
    job.picturesFps = 1;
    job.cameraFile = sharedData("vision/aruco_real/tutorial_camera_charuco.yml");
    job.target.board = *parseBoard("charuco:DICT_6X6_250:5x7:0.04:0.02");
    JobContext context;
    const auto ran = job.run(context);
    ASSERT_TRUE(ran) << ran.error().message;
    ASSERT_EQ(job.frames.size(), 4u);
    for (const TrackedFrame& frame : job.frames) {
        EXPECT_TRUE(frame.tracked);
        EXPECT_EQ(frame.measured.features, 24) << "every inner corner of the 5 × 7 board";
        // The tutorial's photos were taken 35–41 cm from the board.
        EXPECT_GT(frame.pose.translation[2], 0.33);
        EXPECT_LT(frame.pose.translation[2], 0.43);
    }
}

TEST(TrackJob, WrongInputsAreNamed)
{
    TrackJob job;
    job.video = sharedData("vision/video/cockatoo.mp4");
    job.cameraFile = sharedData("vision/aruco_real/tutorial_camera_charuco.yml");
    EXPECT_FALSE(job.validate()) << "no target";
    job.target.board = *parseBoard("charuco:DICT_6X6_250:5x7:0.04:0.02");
    ASSERT_TRUE(job.validate());
    JobContext context;
    auto ran = job.run(context);
    ASSERT_FALSE(ran);
    EXPECT_NE(ran.error().message.find("is for 640 × 480 pictures but cockatoo.mp4 is"), std::string::npos)
        << ran.error().message;

    job.cameraFile = "/nowhere/camera.yml";
    ran = job.run(context);
    ASSERT_FALSE(ran);
    EXPECT_NE(ran.error().message.find("/nowhere/camera.yml"), std::string::npos) << ran.error().message;

    TrackJob picture = job;
    picture.target = {};
    picture.target.picture = sharedData("vision/features/graf1.png");
    EXPECT_FALSE(picture.validate()) << "a picture without its width";

    std::stop_source stop;
    stop.request_stop();
    JobContext cancelled(stop.get_token());
    job.cameraFile = sharedData("vision/aruco_real/tutorial_camera_charuco.yml");
    job.video.clear();
    job.pictures = {sharedData("vision/aruco_real/charuco_img_00.jpg")};
    job.output = artifact("track_job/cancelled.csv");
    ran = job.run(cancelled);
    ASSERT_FALSE(ran);
    EXPECT_EQ(ran.error().code, ErrorCode::Cancelled);
    EXPECT_FALSE(std::filesystem::exists(job.output));
}
