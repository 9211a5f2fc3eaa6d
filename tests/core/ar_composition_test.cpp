// The virtual human over tracked video (issue 16 §4): the world registered on the target (a point
// of the world lands on the pixel the real camera sees it at), the character standing on the
// target at the size the scenario says, phantom occluders hiding what is behind them, the shadow
// catcher darkening the real ground at the feet, the real ChArUco photos with a character
// standing on the board, and the character's face moving over the video. Pictures are left in test-artifacts/ar/ for people to look at.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "ar/frame_source.h"
#include "ar/marker_tracker.h"
#include "render/ar_compositor.h"
#include "render/ar_view.h"
#include "test_support.h"

using namespace thespis::core;
using namespace thespis::core::ar;
using namespace thespis::core::render;
using thespis::test::artifact;
using thespis::test::sharedData;

namespace {

CameraIntrinsics camera640()
{
    CameraIntrinsics camera;
    camera.width = 640;
    camera.height = 480;
    camera.matrix = {600, 0, 322.5, 0, 610, 236.25, 0, 0, 1};
    return camera;
}

// A camera 60 cm from a board lying like a table top, looking down at it at 50°: the board's
// printed side faces +z (an ArUco grid's, whose y runs up the print and away from the camera).
TargetPose tableTopPose()
{
    const double tilt = (180 - 50) * std::numbers::pi / 180; // about the camera's x
    return {{tilt, 0, 0}, {-0.1, 0.05, 0.6}};
}

TargetGeometry gridGeometry() { return {{0.095, 0.07, 0}, {0.19, 0.14}, 1}; }

scenario::Scenario oneCharacter(double scale)
{
    scenario::Scenario s;
    scenario::Character hero;
    hero.name = "Hero";
    hero.skeleton = "hanim-25";
    s.characters.push_back(hero);
    s.ar.scale = scale;
    return s;
}

std::array<double, 2> pixelOf(const CameraIntrinsics& camera, const TargetPose& pose, const std::array<double, 3>& target)
{
    const std::array<double, 3> c = toCamera(pose, target);
    return {camera.fx() * c[0] / c[2] + camera.cx(), camera.fy() * c[1] / c[2] + camera.cy()};
}

std::filesystem::path picture(const std::string& name)
{
    const std::filesystem::path folder = artifact("ar");
    std::filesystem::create_directories(folder);
    return folder / name;
}

VideoFrame greyFrame(const CameraIntrinsics& camera)
{
    VideoFrame frame;
    frame.resize(camera.width, camera.height);
    std::fill(frame.bgr.begin(), frame.bgr.end(), std::uint8_t(150));
    frame.index = 0;
    return frame;
}

struct Coverage {
    int top = 1 << 30, bottom = -1, left = 1 << 30, right = -1, pixels = 0;
};

// Where the layer is opaque (a character, not a shadow: alpha above `threshold`).
Coverage coverage(const RgbaImage& layer, int threshold = 200)
{
    Coverage c;
    for (int y = 0; y < layer.height; ++y)
        for (int x = 0; x < layer.width; ++x)
            if (layer.pixel(x, y)[3] > threshold) {
                c.top = std::min(c.top, y), c.bottom = std::max(c.bottom, y);
                c.left = std::min(c.left, x), c.right = std::max(c.right, x);
                ++c.pixels;
            }
    return c;
}

std::unique_ptr<ArCompositor> compositor(const scenario::Scenario& s, const CameraIntrinsics& camera,
                                         const TargetGeometry& target)
{
    auto made = ArCompositor::create(s, scenario::Assets(), camera, target);
    if (!made) {
        ADD_FAILURE() << describe(made.error());
        return nullptr;
    }
    return std::move(made).value();
}

} // namespace

TEST(ArView, AWorldPointLandsWhereTheCameraSeesIt)
{
    const CameraIntrinsics camera = camera640();
    scenario::ArSpec placement;
    placement.offset = {0.02, -0.01};
    placement.heading = 30;
    placement.scale = 0.1;
    const CameraView view = arCameraView(camera, tableTopPose(), gridGeometry(), placement);
    for (const anim::Vec3d world : {anim::Vec3d{0, 0, 0}, anim::Vec3d{0, 1.8, 0}, anim::Vec3d{0.3, 0.5, -0.2}}) {
        const std::array<double, 2> expected = pixelOf(camera, tableTopPose(), worldToTarget(world, gridGeometry(), placement));
        const anim::Vec3 point{float(world.x), float(world.y), float(world.z)};
        const PixelRect seen = projectToPixels(std::span(&point, 1), view, camera.width, camera.height);
        // projectToPixels counts from the picture's edge, OpenCV from the first pixel's centre.
        EXPECT_NEAR(seen.left - 0.5, expected[0], 1e-3);
        EXPECT_NEAR(seen.top - 0.5, expected[1], 1e-3);
    }
    // Up in the world is the board's printed side's normal: a point above the origin is nearer
    // the camera (which looks down on the board).
    const auto origin = toCamera(tableTopPose(), worldToTarget({0, 0, 0}, gridGeometry(), placement));
    const auto above = toCamera(tableTopPose(), worldToTarget({0, 1, 0}, gridGeometry(), placement));
    EXPECT_LT(above[2], origin[2]);
    EXPECT_NEAR(std::hypot(above[0] - origin[0], above[1] - origin[1], above[2] - origin[2]), 0.1, 1e-9);
}

TEST(ArComposition, TheCharacterStandsOnTheTargetAtItsScale)
{
    const CameraIntrinsics camera = camera640();
    auto ar = compositor(oneCharacter(0.1), camera, gridGeometry());
    if (!ar)
        FAIL() << "no compositor (the failure above says why)";
    VideoFrame frame = greyFrame(camera);
    ASSERT_TRUE(ar->compose(frame, tableTopPose()));
    (void)writePicture(picture("standing.png"), frame);
    const Coverage body = coverage(ar->layer());
    ASSERT_GT(body.pixels, 500);
    // The feet on the world's origin, the head at the character's height: where they project.
    const Bounds bounds = ar->scene().scene().characterBounds();
    // The soles span the ground from heel to toe: the lowest pixel is one of theirs.
    const auto heels = pixelOf(camera, tableTopPose(), worldToTarget({0, 0, bounds.min.z}, gridGeometry(), ar->placement()));
    const auto toes = pixelOf(camera, tableTopPose(), worldToTarget({0, 0, bounds.max.z}, gridGeometry(), ar->placement()));
    const auto head = pixelOf(camera, tableTopPose(), worldToTarget({0, bounds.max.y, 0}, gridGeometry(), ar->placement()));
    std::cout << "soles between rows " << heels[1] << " and " << toes[1] << ", lowest pixel " << body.bottom
              << "; head at " << head[1] << ", top " << body.top << "\n";
    EXPECT_GE(body.bottom, std::min(heels[1], toes[1]) - 3);
    EXPECT_LE(body.bottom, std::max(heels[1], toes[1]) + 3);
    EXPECT_NEAR(body.top, head[1], 6);
    EXPECT_NEAR((body.left + body.right) / 2.0, heels[0], 12);
    // The video is left as it was where no character is.
    EXPECT_EQ(frame.bgr[0], 150);
}

TEST(ArComposition, APhantomBoxHidesTheLegsBehindIt)
{
    const CameraIntrinsics camera = camera640();
    scenario::Scenario s = oneCharacter(0.1);
    s.ar.shadowCatcher = false;
    auto open = compositor(s, camera, gridGeometry());
    if (!open)
        FAIL() << "no compositor (the failure above says why)";
    VideoFrame frame = greyFrame(camera);
    ASSERT_TRUE(open->compose(frame, tableTopPose()));
    const Coverage whole = coverage(open->layer());
    // A real box 0.8 m tall (8 cm at this scale) between the camera and the character's legs.
    const auto near = toCamera(tableTopPose(), worldToTarget({0, 0, 1}, gridGeometry(), s.ar));
    const auto far = toCamera(tableTopPose(), worldToTarget({0, 0, -1}, gridGeometry(), s.ar));
    const double towardsCamera = near[2] < far[2] ? 1 : -1; // the world's z towards the camera?
    s.ar.occluders.push_back({"box", scenario::PhantomOccluder::Shape::Box, {0, 0, 0.5 * towardsCamera},
                              {1.2, 0.8, 0.3}, 0, ""});
    ASSERT_TRUE(open->setPlacement(s.ar));
    VideoFrame hidden = greyFrame(camera);
    ASSERT_TRUE(open->compose(hidden, tableTopPose()));
    (void)writePicture(picture("phantom_box.png"), hidden);
    const Coverage partly = coverage(open->layer());
    std::cout << "character pixels: " << whole.pixels << " without the box, " << partly.pixels << " with it\n";
    EXPECT_LT(partly.bottom, whole.bottom - (whole.bottom - whole.top) / 4) << "the legs are hidden";
    EXPECT_LT(partly.pixels, whole.pixels * 0.9);
    EXPECT_GT(partly.pixels, whole.pixels * 0.5) << "the upper body is not";
    EXPECT_EQ(partly.top, whole.top) << "the head shows above the box";
    // Where the box hides the character, the video shows: the box itself is never drawn.
    for (std::size_t i = 0; i < hidden.bgr.size(); i += 3)
        if (open->layer().rgba[i / 3 * 4 + 3] == 0) {
            ASSERT_EQ(hidden.bgr[i], 150);
        }
}

TEST(ArComposition, AGltfPhantomHidesWhatIsBehindIt)
{
    // CesiumMan (glTF, 1.5 m tall in its own units) stands for a real person between the camera
    // and the character.
    const CameraIntrinsics camera = camera640();
    scenario::Scenario s = oneCharacter(0.1);
    s.ar.shadowCatcher = false;
    auto ar = ArCompositor::create(s, scenario::Assets(sharedData("characters/CesiumMan")), camera, gridGeometry());
    ASSERT_TRUE(ar) << describe(ar.error());
    VideoFrame frame = greyFrame(camera);
    ASSERT_TRUE((*ar)->compose(frame, tableTopPose()));
    const Coverage whole = coverage((*ar)->layer());
    const auto near = toCamera(tableTopPose(), worldToTarget({0, 0, 1}, gridGeometry(), s.ar));
    const auto far = toCamera(tableTopPose(), worldToTarget({0, 0, -1}, gridGeometry(), s.ar));
    s.ar.occluders.push_back({"passer-by", scenario::PhantomOccluder::Shape::Model, {0, 0, near[2] < far[2] ? 0.6 : -0.6},
                              {1, 1, 1}, 0, "CesiumMan.glb"});
    ASSERT_TRUE((*ar)->setPlacement(s.ar));
    frame = greyFrame(camera);
    ASSERT_TRUE((*ar)->compose(frame, tableTopPose()));
    (void)writePicture(picture("phantom_model.png"), frame);
    const Coverage hidden = coverage((*ar)->layer());
    std::cout << "character pixels: " << whole.pixels << " in the open, " << hidden.pixels << " behind the model\n";
    EXPECT_LT(hidden.pixels, whole.pixels * 0.8);
    // A model that cannot be read is named.
    s.ar.occluders.back().model = "missing.glb";
    const auto refused = (*ar)->setPlacement(s.ar);
    ASSERT_FALSE(refused);
    EXPECT_NE(refused.error().message.find("passer-by (missing.glb)"), std::string::npos) << refused.error().message;
}

TEST(ArComposition, TheShadowCatcherDarkensTheGroundAtTheFeet)
{
    const CameraIntrinsics camera = camera640();
    auto ar = compositor(oneCharacter(0.1), camera, gridGeometry());
    if (!ar)
        FAIL() << "no compositor (the failure above says why)";
    VideoFrame frame = greyFrame(camera);
    ASSERT_TRUE(ar->compose(frame, tableTopPose()));
    EXPECT_GT(ar->shadowSpheres(), 8);
    // Ground beside the feet (a third of a metre to the side) is darker than ground far away.
    const auto beside = pixelOf(camera, tableTopPose(), worldToTarget({0.3, 0, 0}, gridGeometry(), ar->placement()));
    const auto far = pixelOf(camera, tableTopPose(), worldToTarget({3, 0, 0}, gridGeometry(), ar->placement()));
    const auto grey = [&](const std::array<double, 2>& p) {
        return int(frame.bgr[(std::size_t(std::lround(p[1])) * std::size_t(frame.width) + std::size_t(std::lround(p[0]))) * 3]);
    };
    std::cout << "ground beside the feet " << grey(beside) << ", far away " << grey(far) << "\n";
    EXPECT_LT(grey(beside), 140);
    EXPECT_GE(grey(far), 148);
}

TEST(ArComposition, ACharacterStandsOnTheRealChArUcoBoard)
{
    const auto camera = readCameraFile(sharedData("vision/aruco_real/tutorial_camera_charuco.yml"));
    ASSERT_TRUE(camera);
    auto tracker = MarkerTracker::create(*parseBoard("charuco:DICT_6X6_250:5x7:0.04:0.02"), *camera);
    ASSERT_TRUE(tracker);
    auto frame = readPicture(sharedData("vision/aruco_real/charuco_img_01.jpg"));
    ASSERT_TRUE(frame);
    const TrackerEstimate seen = (*tracker)->estimate(*frame);
    ASSERT_TRUE(seen.found);
    auto ar = compositor(oneCharacter(0.08), *camera, (*tracker)->geometry());
    if (!ar)
        FAIL() << "no compositor (the failure above says why)";
    ASSERT_TRUE(ar->compose(*frame, seen.pose));
    (void)writePicture(picture("charuco_board.png"), *frame);
    const Coverage body = coverage(ar->layer());
    ASSERT_GT(body.pixels, 300);
    // Its feet stand at the board's centre, as the photo shows the board.
    const auto centre = pixelOf(*camera, seen.pose, (*tracker)->geometry().centre);
    const auto feetOnBoard = pixelOf(*camera, seen.pose, worldToTarget({0, 0, 0}, (*tracker)->geometry(), ar->placement()));
    EXPECT_NEAR(feetOnBoard[0], centre[0], 1e-6);
    EXPECT_GE(centre[0], body.left - 2);
    EXPECT_LE(centre[0], body.right + 2);
    EXPECT_GE(centre[1], body.top - 2);
    EXPECT_LE(centre[1], body.bottom + 2);
}

// Faces move in AR too (issue 31 §4): a face layer opening the jaw in surprise changes the
// composed picture on the head, and nowhere else, against the same frame with the layer muted.
TEST(ArComposition, TheFaceMovesOverTheVideo)
{
    const CameraIntrinsics camera = camera640();
    scenario::Scenario s = oneCharacter(0.3);
    scenario::ClipAsset surprise;
    surprise.name = "surprise";
    surprise.frameRate = 1;
    surprise.scalars = {"open_jaw", "expression6"};
    surprise.frames = {600, 1, 600, 1};
    scenario::Layer face;
    face.name = "face";
    face.kind = scenario::LayerKind::Face;
    face.actions.push_back({});
    face.actions.back().name = "surprise";
    face.actions.back().clip = "surprise";
    s.characters[0].clips.push_back(surprise);
    s.characters[0].layers.push_back(face);
    // The camera 0.5 m above the board and 1 m in front of the character (which faces the
    // board's −y), looking along +y a little down: the body about 290 pixels tall.
    const TargetPose front{{std::numbers::pi / 2 + 0.15, 0, 0}, {-0.095, 0.355, 0.994}};
    VideoFrame frames[2] = {greyFrame(camera), greyFrame(camera)};
    RgbaImage layers[2];
    for (int muted = 0; muted < 2; ++muted) {
        s.characters[0].layers[0].mute = muted == 1;
        auto ar = compositor(s, camera, gridGeometry());
        if (!ar)
            FAIL() << "no compositor (the failure above says why)";
        ar->scene().playAt(secondsToTicks(0.5));
        ASSERT_TRUE(ar->compose(frames[muted], front));
        layers[muted] = ar->layer();
    }
    (void)writePicture(picture("face_surprised.png"), frames[0]);
    (void)writePicture(picture("face_muted.png"), frames[1]);
    const Coverage body = coverage(layers[1]);
    ASSERT_GT(body.pixels, 2000) << "the character is in view";
    int changed = 0, belowHead = 0;
    const int neck = body.top + (body.bottom - body.top) / 7; // a head is about a seventh of a body
    for (int y = 0; y < camera.height; ++y)
        for (int x = 0; x < camera.width; ++x) {
            const std::size_t i = 3 * (std::size_t(y) * std::size_t(camera.width) + std::size_t(x));
            int d = 0;
            for (int c = 0; c < 3; ++c)
                d = std::max(d, std::abs(int(frames[0].bgr[i + std::size_t(c)]) - int(frames[1].bgr[i + std::size_t(c)])));
            if (d > 24) {
                ++changed;
                belowHead += y > neck;
            }
        }
    std::cout << changed << " pixels changed, " << belowHead << " below the head (rows " << body.top << "–" << neck << ")\n";
    EXPECT_GT(changed, 30) << "the open jaw shows";
    EXPECT_EQ(belowHead, 0) << "only the face changes";
}
