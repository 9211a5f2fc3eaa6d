#include "ar/synthetic_source.h"

#include <cmath>
#include <numbers>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "ar/aruco_board.h"
#include "ar/opencv_bridge.h"

namespace thespis::core::ar {

namespace {

// The printed board's resolution: fine enough that drawing it to whole pixels moves nothing by
// more than a few hundredths of a millimetre.
constexpr double CanvasPixelsPerMetre = 8000;
// Frames are drawn this many times larger, then averaged down: edges as a lens and sensor see them.
constexpr int Supersampling = 3;

cv::Matx33d rotationX(double a) { return {1, 0, 0, 0, std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a)}; }
cv::Matx33d rotationY(double a) { return {std::cos(a), 0, std::sin(a), 0, 1, 0, -std::sin(a), 0, std::cos(a)}; }
cv::Matx33d rotationZ(double a) { return {std::cos(a), -std::sin(a), 0, std::sin(a), std::cos(a), 0, 0, 0, 1}; }

double degrees(double d) { return d * std::numbers::pi / 180; }

} // namespace

struct SyntheticSource::State {
    SyntheticScene scene;
    cv::Mat canvas;             // the printed board
    cv::Matx33d canvasToBoard;
    cv::Vec3d boardCentre;      // in the board's plane
    cv::Point2d boardSize;      // metres
    cv::Matx33d facing;         // turns the printed side towards the camera
    cv::Mat background;         // grey, frame sized
    cv::RNG random;
    std::int64_t next = 0;
    // Reused per frame.
    cv::Mat large, grey, noise, kernel;

    cv::Point2d project(const TargetPose& pose, const cv::Vec3d& boardPoint) const
    {
        const std::array<double, 3> p = toCamera(pose, {boardPoint[0], boardPoint[1], boardPoint[2]});
        const CameraIntrinsics& c = scene.camera;
        return {c.fx() * p[0] / p[2] + c.cx(), c.fy() * p[1] / p[2] + c.cy()};
    }

    TargetPose poseAt(double t) const
    {
        const double tau = 2 * std::numbers::pi;
        const double middle = 0.5 * (scene.nearest + scene.farthest), swing = 0.5 * (scene.farthest - scene.nearest);
        const double distance = middle + swing * std::sin(tau * t / 7.3);
        // The board wanders about the middle of the view and turns as a hand turns it.
        const cv::Vec3d centre(distance * 0.08 * std::sin(tau * t / 5.1), distance * 0.06 * std::sin(tau * t / 6.7 + 1),
                               distance);
        const cv::Matx33d r = facing * rotationZ(degrees(15) * std::sin(tau * t / 8.1 + 1)) *
                              rotationY(degrees(25) * std::sin(tau * t / 5.7 + 0.5)) *
                              rotationX(degrees(25) * std::sin(tau * t / 4.3));
        const cv::Vec3d translation = centre - r * boardCentre;
        cv::Vec3d rotation;
        cv::Rodrigues(r, rotation);
        return targetPose(rotation, translation);
    }

    bool within(std::int64_t frame, const std::pair<std::int64_t, std::int64_t>& range) const
    {
        return frame >= range.first && frame < range.second;
    }

    void render(std::int64_t index, VideoFrame& frame)
    {
        const CameraIntrinsics& camera = scene.camera;
        const double time = double(index) / scene.fps;
        const TargetPose pose = poseAt(time);
        cv::Matx33d r;
        cv::Rodrigues(rvec(pose), r);
        const cv::Vec3d t = tvec(pose);
        const cv::Matx33d planeToImage =
            cv::Matx33d(camera.matrix.data()) * cv::Matx33d(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
        // A large pixel's centre j is the small picture's (j + ½) / s − ½.
        const double s = Supersampling, shift = 0.5 * (s - 1);
        const cv::Matx33d toLarge(s, 0, shift, 0, s, shift, 0, 0, 1);
        cv::resize(background, large, cv::Size(), s, s, cv::INTER_NEAREST);
        cv::warpPerspective(canvas, large, toLarge * planeToImage * canvasToBoard, large.size(), cv::INTER_LINEAR,
                            cv::BORDER_TRANSPARENT);
        cv::resize(large, grey, background.size(), 0, 0, cv::INTER_AREA);

        const double pixelsPerMetre = camera.fx() / t[2];
        if (within(index, scene.handOver)) {
            // A hand over the board's left third.
            const cv::Point2d at = project(pose, boardCentre - cv::Vec3d(boardSize.x / 3, 0, 0));
            const double radius = 0.22 * boardSize.x * pixelsPerMetre;
            cv::ellipse(grey, at, cv::Size2d(radius, 1.6 * radius), 20, 0, 360, cv::Scalar(95), cv::FILLED, cv::LINE_AA);
        }
        if (within(index, scene.hidden)) {
            const cv::Point2d at = project(pose, boardCentre);
            const double radius = 0.9 * std::max(boardSize.x, boardSize.y) * pixelsPerMetre;
            cv::ellipse(grey, at, cv::Size2d(radius, radius), 0, 0, 360, cv::Scalar(95), cv::FILLED, cv::LINE_AA);
        }
        // Motion blur: the picture smeared along the board's motion during the exposure.
        const double exposure = scene.exposure / scene.fps;
        const cv::Point2d smear = project(poseAt(time + exposure / 2), boardCentre) -
                                  project(poseAt(time - exposure / 2), boardCentre);
        const double length = std::hypot(smear.x, smear.y);
        if (length > 0.5) {
            const int side = 2 * int(std::ceil(length / 2)) + 1;
            kernel = cv::Mat::zeros(side, side, CV_32F);
            // The kernel's anchor is its middle pixel: the smear is centred there, so nothing shifts.
            const cv::Point2d middle(side / 2, side / 2), half = smear * 0.5;
            const auto fixedPoint = [](const cv::Point2d& p) { return cv::Point(cvRound(p.x * 16), cvRound(p.y * 16)); };
            cv::line(kernel, fixedPoint(middle - half), fixedPoint(middle + half), cv::Scalar(1), 1, cv::LINE_AA, 4);
            kernel /= cv::sum(kernel)[0];
            cv::filter2D(grey, grey, -1, kernel);
        }
        if (scene.noise > 0) {
            grey.convertTo(noise, CV_16S);
            cv::Mat added(noise.size(), CV_16S);
            random.fill(added, cv::RNG::NORMAL, 0, scene.noise);
            noise += added;
            noise.convertTo(grey, CV_8U);
        }
        frame.resize(camera.width, camera.height);
        cv::Mat target = bgrMat(frame);
        cv::cvtColor(grey, target, cv::COLOR_GRAY2BGR);
        frame.index = index;
        frame.time = time;
        frame.captured = std::chrono::steady_clock::now();
    }
};

SyntheticSource::SyntheticSource(std::unique_ptr<State> state) : m_state(std::move(state)) {}
SyntheticSource::~SyntheticSource() = default;

Result<std::unique_ptr<SyntheticSource>> SyntheticSource::create(const SyntheticScene& scene)
{
    const CameraIntrinsics& camera = scene.camera;
    if (camera.width <= 0 || camera.height <= 0 || camera.fx() <= 0 || camera.fy() <= 0)
        return makeError(ErrorCode::InvalidArgument, "A synthetic scene needs a camera with a size and focal lengths");
    if (scene.frames <= 0 || !(scene.fps > 0))
        return makeError(ErrorCode::InvalidArgument, "A synthetic scene needs frames and a positive frame rate");
    if (!(scene.nearest > 0) || !(scene.farthest >= scene.nearest))
        return makeError(ErrorCode::InvalidArgument, "A synthetic scene's distances must be positive and in order");
    if (scene.board.columns <= 0 || scene.board.rows <= 0 || !(scene.board.square > 0))
        return makeError(ErrorCode::InvalidArgument, "A synthetic scene needs a board");
    auto state = std::make_unique<State>();
    state->scene = scene;
    state->random = cv::RNG(scene.seed);
    state->canvas = drawBoard(scene.board, CanvasPixelsPerMetre, state->canvasToBoard);
    const cv::Vec3d topLeft = state->canvasToBoard * cv::Vec3d(0, 0, 1);
    const cv::Vec3d bottomRight = state->canvasToBoard * cv::Vec3d(state->canvas.cols, state->canvas.rows, 1);
    state->boardCentre = cv::Vec3d(0.5 * (topLeft[0] + bottomRight[0]), 0.5 * (topLeft[1] + bottomRight[1]), 0);
    state->boardSize = {std::abs(bottomRight[0] - topLeft[0]), std::abs(bottomRight[1] - topLeft[1])};
    // The printed side faces the camera: along −z of the board's frame when its y runs up the
    // print (OpenCV 4.6's ArUco grid), along +z when y runs down.
    bool yUp = false;
    if (scene.board.kind != BoardKind::Chessboard) {
        const cv::Ptr<cv::aruco::Board> board = arucoBoard(scene.board);
        yUp = board->objPoints[0][3].y < board->objPoints[0][0].y; // bottom-left below top-left
    }
    state->facing = yUp ? cv::Matx33d(1, 0, 0, 0, -1, 0, 0, 0, -1) : cv::Matx33d::eye();
    // A background with some structure (blotches of grey), as a room behind a board has.
    cv::Mat coarse(9, 12, CV_8UC1);
    state->random.fill(coarse, cv::RNG::UNIFORM, 70, 190);
    cv::resize(coarse, state->background, cv::Size(camera.width, camera.height), 0, 0, cv::INTER_CUBIC);
    return std::unique_ptr<SyntheticSource>(new SyntheticSource(std::move(state)));
}

std::string SyntheticSource::description() const { return "synthetic " + formatBoard(m_state->scene.board); }

Result<bool> SyntheticSource::read(VideoFrame& frame)
{
    if (m_state->next >= m_state->scene.frames)
        return false;
    m_state->render(m_state->next++, frame);
    return true;
}

double SyntheticSource::fps() const { return m_state->scene.fps; }
int SyntheticSource::width() const { return m_state->scene.camera.width; }
int SyntheticSource::height() const { return m_state->scene.camera.height; }
std::int64_t SyntheticSource::frameCount() const { return m_state->scene.frames; }
const SyntheticScene& SyntheticSource::scene() const { return m_state->scene; }

TargetPose SyntheticSource::truth(std::int64_t frame) const { return m_state->poseAt(double(frame) / m_state->scene.fps); }

bool SyntheticSource::visible(std::int64_t frame) const { return !m_state->within(frame, m_state->scene.hidden); }

} // namespace thespis::core::ar
