// core/ar's camera calibration (paper §7.2) on the real chessboard views in
// ../shared/data/vision/calibration (OpenCV's left01–14 sample, 9 × 6 inner corners, 25 mm
// squares): they calibrate to the intrinsics OpenCV's own sample found (left_intrinsics.yml,
// fx = fy fixed); the camera file reads back what was written; board specs and bad files are
// refused with the field or part named.

#include <gtest/gtest.h>

#include <filesystem>

#include "ar/board.h"
#include "ar/calibrate_job.h"
#include "ar/camera_file.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;

namespace {

const std::filesystem::path kViews = std::filesystem::path(THESPIS_SHARED_DATA) / "vision" / "calibration";

std::vector<std::filesystem::path> sampleViews()
{
    std::vector<std::filesystem::path> views;
    for (const auto& entry : std::filesystem::directory_iterator(kViews))
        if (entry.path().extension() == ".jpg")
            views.push_back(entry.path());
    std::sort(views.begin(), views.end());
    return views;
}

} // namespace

TEST(Calibration, TheChessboardViewsGiveOpenCVsIntrinsics)
{
    const auto gold = readCameraFile(kViews / "left_intrinsics.yml");
    ASSERT_TRUE(gold) << gold.error().message;
    CalibrateJob job;
    job.images = sampleViews();
    ASSERT_EQ(job.images.size(), 13u);
    job.board = *parseBoard("chessboard:9x6:0.025");
    job.fixAspectRatio = true; // as the sample did (flags: 2)
    const std::filesystem::path out = std::filesystem::path(THESPIS_TEST_ARTIFACTS) / "calibration" / "left.yml";
    std::filesystem::create_directories(out.parent_path());
    job.output = out;
    ASSERT_TRUE(job.validate().ok());
    JobContext context;
    const auto ran = job.run(context);
    ASSERT_TRUE(ran) << ran.error().message;
    for (const CalibrateJob::View& view : job.views)
        EXPECT_TRUE(view.found) << view.image;
    EXPECT_EQ(job.camera.width, 640);
    EXPECT_EQ(job.camera.height, 480);
    EXPECT_NEAR(job.camera.fx(), gold->fx(), 0.005 * gold->fx());
    EXPECT_DOUBLE_EQ(job.camera.fx(), job.camera.fy());
    EXPECT_NEAR(job.camera.cx(), gold->cx(), 1.0);
    EXPECT_NEAR(job.camera.cy(), gold->cy(), 1.0);
    for (std::size_t k = 0; k < 5; ++k)
        EXPECT_NEAR(job.camera.distortion[k], gold->distortion[k], 0.02) << "k" << k;
    EXPECT_NEAR(job.camera.reprojectionError, gold->reprojectionError, 0.05);
    // The written file reads back as what was found.
    const auto back = readCameraFile(out);
    ASSERT_TRUE(back) << back.error().message;
    EXPECT_EQ(*back, job.camera);
}

TEST(Calibration, TooFewViewsOrTheWrongBoardAreSaidSo)
{
    CalibrateJob job;
    job.images = sampleViews();
    job.board = *parseBoard("chessboard:10x7:0.025"); // more corners than the board has
    JobContext context;
    const auto ran = job.run(context);
    ASSERT_FALSE(ran);
    EXPECT_NE(ran.error().message.find("inner corners counted right"), std::string::npos) << ran.error().message;
    job.images.resize(2);
    EXPECT_FALSE(job.validate());
    job.images = sampleViews();
    job.output = "camera.txt";
    EXPECT_FALSE(job.validate());
}

TEST(CameraFile, MissingAndMalformedFieldsAreNamed)
{
    const std::string good = encodeCameraFile(*readCameraFile(kViews / "left_intrinsics.yml"));
    ASSERT_TRUE(parseCameraFile(good, "good.yml"));
    const auto without = [&](const std::string& field) {
        std::string text = good;
        const std::size_t at = text.find(field + ":");
        text.replace(at, field.size(), "x_" + field);
        return parseCameraFile(text, "bad.yml");
    };
    for (const std::string field : {"image_width", "image_height", "camera_matrix", "distortion_coefficients"}) {
        const auto read = without(field);
        ASSERT_FALSE(read) << field;
        EXPECT_NE(read.error().message.find("bad.yml: " + field + ": this field is required"), std::string::npos)
            << read.error().message;
    }
    const auto notYaml = parseCameraFile("camera_matrix: [1, 2", "broken.yml");
    ASSERT_FALSE(notYaml);
    EXPECT_NE(notYaml.error().message.find("broken.yml"), std::string::npos) << notYaml.error().message;
    EXPECT_FALSE(readCameraFile(kViews / "no_such_camera.yml"));
}

TEST(Board, SpecsParseBackAndWrongPartsAreNamed)
{
    for (const char* text : {"chessboard:9x6:0.025", "aruco-grid:DICT_4X4_50:4x3:0.04:0.01",
                             "charuco:DICT_4X4_1000:4x5:0.054:0.0405:inverted", "charuco:DICT_6X6_250:5x7:0.04:0.02"}) {
        const auto board = parseBoard(text);
        ASSERT_TRUE(board) << text << ": " << board.error().message;
        EXPECT_EQ(*parseBoard(formatBoard(*board)), *board) << text;
    }
    const auto grid = *parseBoard("aruco-grid:DICT_4X4_50:4x3:0.04:0.01");
    EXPECT_EQ(grid.kind, BoardKind::ArucoGrid);
    EXPECT_EQ(grid.columns, 4);
    EXPECT_EQ(grid.rows, 3);
    EXPECT_DOUBLE_EQ(grid.second, 0.01);
    const std::pair<const char*, const char*> bad[] = {
        {"checkers:9x6:0.025", "unknown kind"},
        {"chessboard:9by6:0.025", "\"9by6\" is not COLUMNSxROWS"},
        {"chessboard:9x6:-1", "\"-1\" is not a positive length"},
        {"chessboard:9x6", "expected chessboard:"},
        {"aruco-grid:4X4:4x3:0.04:0.01", "not an ArUco dictionary"},
        {"charuco:DICT_4X4_50:4x5:0.03:0.04", "markers must be smaller"},
        {"chessboard:1x6:0.025", "at least 2 × 2"},
    };
    for (const auto& [text, why] : bad) {
        const auto board = parseBoard(text);
        ASSERT_FALSE(board) << text;
        EXPECT_NE(board.error().message.find(why), std::string::npos) << board.error().message;
    }
}
