#include "ar/planar_tracker.h"

#include <opencv2/calib3d.hpp>
#include <opencv2/features2d.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <optional>
#include <sstream>

#include "ar/frame_source.h"
#include "ar/opencv_bridge.h"
#include "ar/pose_fit.h"
#include "util/file_io.h"

namespace thespis::core::ar {

namespace {

constexpr float RatioTest = 0.8f;            // Lowe's: the best match must clearly beat the second best
constexpr double DetectionThreshold = 2.0;   // MAGSAC++'s largest inlier distance, pixels, for features
constexpr double TrackingThreshold = 2.0;    // RANSAC inlier distance, pixels, for followed points
constexpr int MinimumDetectionInliers = 20;  // chance matches in clutter or noise stay well below this
constexpr int MinimumTrackedPoints = 15;     // below it one bad point moves the pose: detect again
constexpr int MaximumTrackedPoints = 400;    // plenty for the pose; KLT's cost grows with the count
constexpr int ReplenishBelow = MaximumTrackedPoints / 2; // fewer followed points: add fresh corners
constexpr double CornerQuality = 0.01;       // Shi–Tomasi: corners at least 1 % as strong as the best
constexpr double CornerSpacing = 8;          // pixels between followed points, to spread them out
constexpr double TargetInset = 0.03;         // corners this far (of the size) inside the picture's edge
constexpr double DriftLimit = 1.0;           // pixels a followed point may lie off the refitted homography
constexpr double ForwardBackwardLimit = 1.0; // pixels a point may miss its start when tracked back
constexpr int KltLevels = 3;                 // 15 px window × 2³: follows ~50 px of motion per frame
const cv::Size KltWindow(15, 15); // 21 × 21 drifted more under the perspective change of a turning view
const cv::TermCriteria KltStop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
// OpenCV's default of 5 iterations leaves pixels of error at a wide lens's corners.
const cv::TermCriteria UndistortStop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 20, 1e-4);
constexpr int MaximumReferenceSide = 1280;   // larger pictures are described on a smaller copy
constexpr double MinimumTargetArea = 400;    // pixels²: smaller than 20 × 20 is too small to trust

// A picture imread could not read: missing, or not a picture.
Error pictureNotRead(const std::filesystem::path& path)
{
    std::error_code ignored;
    if (!std::filesystem::exists(path, ignored))
        return makeError(ErrorCode::FileNotFound, path.string() + ": no such picture.");
    return makeError(ErrorCode::NotOurFormat, path.string() + ": not a picture OpenCV can read.");
}

// Reads a picture as grey, without OpenCV's warning for a missing file (the error says it).
cv::Mat readGrey(const std::filesystem::path& path)
{
    std::error_code ignored;
    return std::filesystem::exists(path, ignored) ? cv::imread(path.string(), cv::IMREAD_GRAYSCALE) : cv::Mat();
}

std::string tooFewFeatures(const std::filesystem::path& path, int found)
{
    return path.string() + ": " + std::to_string(found) + " features found, while a target picture needs at least " +
           std::to_string(PlanarTracker::MinimumReferenceFeatures) +
           ". Choose a picture with more texture (print, text, photographs), not plain areas.";
}

// The picture's corners (outer edges of its corner pixels), top-left first, clockwise on screen.
std::array<cv::Point2d, 4> pictureCorners(cv::Size size)
{
    const double right = size.width - 0.5, bottom = size.height - 0.5;
    return {cv::Point2d(-0.5, -0.5), cv::Point2d(right, -0.5), cv::Point2d(right, bottom), cv::Point2d(-0.5, bottom)};
}

// A homography that folds, mirrors or throws the picture past the horizon, or makes it tiny, is
// a wrong fit (RANSAC on too few or degenerate points), not a view of the target.
bool plausible(const cv::Matx33d& h, cv::Size picture, cv::Size frame)
{
    std::array<cv::Point2d, 4> seen{};
    const auto corners = pictureCorners(picture);
    for (std::size_t i = 0; i < 4; ++i) {
        const cv::Vec3d p = h * cv::Vec3d(corners[i].x, corners[i].y, 1.0);
        if (!(p[2] > 0) || !std::isfinite(p[0]) || !std::isfinite(p[1]))
            return false;
        seen[i] = cv::Point2d(p[0] / p[2], p[1] / p[2]);
    }
    double area = 0;
    for (std::size_t i = 0; i < 4; ++i) {
        const cv::Point2d a = seen[i], b = seen[(i + 1) % 4], c = seen[(i + 2) % 4];
        if ((b - a).cross(c - b) <= 0) // turns the other way: folded or mirrored
            return false;
        area += a.cross(b) / 2;
    }
    return area >= MinimumTargetArea && area <= 25.0 * frame.area();
}

bool hasDistortion(const CameraIntrinsics& camera)
{
    return std::any_of(camera.distortion.begin(), camera.distortion.end(), [](double k) { return k != 0; });
}

// Where an ideal pinhole camera would see the points (pixels): homographies hold only there, so
// with a distorting lens they are fitted on these.
void toPinhole(const CameraIntrinsics& camera, const std::vector<cv::Point2f>& points, std::vector<cv::Point2f>& out)
{
    const cv::Mat matrix = cameraMat(camera);
    cv::undistortPoints(points, out, matrix, distortionMat(camera), cv::noArray(), matrix, UndistortStop);
}

// Detects a reference picture in frames. AKAZE rather than ORB: its nonlinear scale space keeps
// features repeatable under the strong viewpoint changes of a hand-held camera (graf1 → graf3), and
// its binary descriptors still match quickly by Hamming distance.
class ReferenceDetector {
public:
    // Describes the picture once; returns how many features it has.
    int describe(const cv::Mat& grey)
    {
        pictureSize = grey.size();
        const double shrink = std::min(1.0, double(MaximumReferenceSide) / std::max(grey.cols, grey.rows));
        cv::Mat described = grey;
        if (shrink < 1.0)
            cv::resize(grey, described, cv::Size(), shrink, shrink, cv::INTER_AREA);
        std::vector<cv::KeyPoint> keypoints;
        m_akaze->detectAndCompute(described, cv::noArray(), keypoints, m_referenceDescriptors);
        m_referencePoints.clear();
        for (const cv::KeyPoint& k : keypoints) // back to the full picture's pixels
            m_referencePoints.emplace_back(float((k.pt.x + 0.5) / shrink - 0.5), float((k.pt.y + 0.5) / shrink - 0.5));
        return int(m_referencePoints.size());
    }

    // Finds the picture in `grey`: fills the homography (to the pinhole view when `camera`
    // distorts) and the inlier correspondences (frame pixels as seen; at most `limit`, spread over
    // all of them). Counts are left for messages even when it fails.
    bool detect(const cv::Mat& grey, const CameraIntrinsics* camera, int limit, cv::Matx33d& homography,
                std::vector<cv::Point2f>& referenceInliers, std::vector<cv::Point2f>& frameInliers)
    {
        matches = inliers = 0;
        m_akaze->detectAndCompute(grey, cv::noArray(), m_frameKeypoints, m_frameDescriptors);
        if (m_frameDescriptors.rows < 2 || m_referenceDescriptors.rows < 2)
            return false;
        m_knn.clear(); // knnMatch appends to what is there
        m_matcher.knnMatch(m_frameDescriptors, m_referenceDescriptors, m_knn, 2);
        m_matchedReference.clear();
        m_matchedFrame.clear();
        for (const auto& best : m_knn) {
            if (best.size() < 2 || best[0].distance >= RatioTest * best[1].distance)
                continue;
            m_matchedReference.push_back(m_referencePoints[std::size_t(best[0].trainIdx)]);
            m_matchedFrame.push_back(m_frameKeypoints[std::size_t(best[0].queryIdx)].pt);
        }
        matches = int(m_matchedFrame.size());
        if (matches < MinimumDetectionInliers)
            return false;
        const bool distorted = camera && hasDistortion(*camera);
        if (distorted)
            toPinhole(*camera, m_matchedFrame, m_matchedPinhole);
        // MAGSAC++ (OpenCV's USAC) rather than plain RANSAC: on graf1 → graf3 it stays within 0.7 px
        // of the true homography at every threshold and ratio tried, where RANSAC's error varies
        // from 0.4 to 1.6 px with them.
        const cv::Mat h = cv::findHomography(m_matchedReference, distorted ? m_matchedPinhole : m_matchedFrame,
                                            cv::USAC_MAGSAC, DetectionThreshold, m_inlierMask, 2000, 0.995);
        if (h.empty())
            return false;
        inliers = cv::countNonZero(m_inlierMask);
        homography = cv::Matx33d(h);
        if (inliers < MinimumDetectionInliers || !plausible(homography, pictureSize, grey.size()))
            return false;
        // Keep every inlier when there are few; else an even spread of `limit` of them.
        referenceInliers.clear();
        frameInliers.clear();
        const double step = std::max(1.0, double(inliers) / limit);
        double next = 0;
        for (int i = 0, k = 0; i < matches; ++i) {
            if (!m_inlierMask.at<unsigned char>(i))
                continue;
            if (k++ >= next) {
                referenceInliers.push_back(m_matchedReference[std::size_t(i)]);
                frameInliers.push_back(m_matchedFrame[std::size_t(i)]);
                next += step;
            }
        }
        return true;
    }

    cv::Size pictureSize;
    int matches = 0, inliers = 0;

private:
    cv::Ptr<cv::AKAZE> m_akaze = cv::AKAZE::create();
    cv::BFMatcher m_matcher{cv::NORM_HAMMING};
    std::vector<cv::Point2f> m_referencePoints;
    cv::Mat m_referenceDescriptors;
    // Per-detection buffers, kept to reuse their memory.
    std::vector<cv::KeyPoint> m_frameKeypoints;
    cv::Mat m_frameDescriptors;
    std::vector<std::vector<cv::DMatch>> m_knn;
    std::vector<cv::Point2f> m_matchedReference, m_matchedFrame, m_matchedPinhole;
    cv::Mat m_inlierMask;
};

Homography toArray(const cv::Matx33d& h)
{
    Homography out{};
    for (int i = 0; i < 9; ++i)
        out[std::size_t(i)] = h.val[i];
    return out;
}

// 1-based line of `offset` in `text`.
int lineOf(const std::string& text, std::size_t offset)
{
    return 1 + int(std::count(text.begin(), text.begin() + std::ptrdiff_t(std::min(offset, text.size())), '\n'));
}

// Where an entry starts in OpenCV's XML (<name), YAML (name:) or JSON ("name").
std::size_t entryOffset(const std::string& text, const std::string& field)
{
    if (field.empty())
        return std::string::npos;
    for (const std::string& form : {"<" + field, field + ":", "\"" + field + "\""})
        if (const std::size_t at = text.find(form); at != std::string::npos)
            return at;
    return std::string::npos;
}

Result<Homography> parseStorageHomography(const std::string& text, const std::string& name)
{
    try {
        cv::FileStorage file(text, cv::FileStorage::READ | cv::FileStorage::MEMORY);
        if (!file.isOpened())
            return makeError(ErrorCode::NotOurFormat, name + ": not a homography file OpenCV can read.");
        const cv::FileNode node = file.getFirstTopLevelNode();
        const std::string field = node.empty() ? std::string() : node.name();
        std::string where = name;
        if (const std::size_t at = entryOffset(text, field); at != std::string::npos)
            where.append(":").append(std::to_string(lineOf(text, at)));
        where.append(": ");
        if (node.empty() || !node.isMap())
            return makeError(ErrorCode::CorruptData, where + "expected a 3 × 3 matrix as the file's first entry.");
        cv::Mat matrix;
        node >> matrix;
        if (matrix.rows != 3 || matrix.cols != 3 || matrix.channels() != 1)
            return makeError(ErrorCode::CorruptData, where + field + ": expected a 3 × 3 matrix, found " +
                                                         std::to_string(matrix.rows) + " × " +
                                                         std::to_string(matrix.cols) + ".");
        matrix.convertTo(matrix, CV_64F);
        if (!cv::checkRange(matrix))
            return makeError(ErrorCode::CorruptData, where + field + ": expected finite numbers.");
        return toArray(cv::Matx33d(matrix));
    } catch (const cv::Exception& e) {
        // OpenCV's parser names the line in its message.
        return makeError(ErrorCode::CorruptData, name + ": not a homography file OpenCV can read.", e.msg);
    }
}

Result<Homography> parsePlainHomography(const std::string& text, const std::string& name)
{
    Homography h{};
    std::istringstream lines(text);
    std::string line;
    int row = 0, lineNumber = 0;
    while (std::getline(lines, line)) {
        ++lineNumber;
        std::istringstream words(line);
        std::string word;
        int column = 0;
        while (words >> word) {
            const std::string where = name + ":" + std::to_string(lineNumber) + ": ";
            if (row >= 3)
                return makeError(ErrorCode::CorruptData, where + "'" + word + "' after the matrix's three rows.");
            char* end = nullptr;
            const double value = std::strtod(word.c_str(), &end);
            if (end != word.c_str() + word.size() || !std::isfinite(value))
                return makeError(ErrorCode::CorruptData, where + "'" + word + "' is not a number.");
            if (column >= 3)
                return makeError(ErrorCode::CorruptData, where + "expected 3 numbers on the line, found more.");
            h[std::size_t(row * 3 + column++)] = value;
        }
        if (column == 0)
            continue; // blank lines
        if (column != 3)
            return makeError(ErrorCode::CorruptData, name + ":" + std::to_string(lineNumber) +
                                                         ": expected 3 numbers on the line, found " +
                                                         std::to_string(column) + ".");
        ++row;
    }
    if (row != 3)
        return makeError(ErrorCode::CorruptData, name + ":" + std::to_string(lineNumber) +
                                                     ": expected 3 rows of 3 numbers, found " + std::to_string(row) +
                                                     (row == 1 ? " row." : " rows."));
    return h;
}

} // namespace

// ---- PlanarTracker --------------------------------------------------------------------------

struct PlanarTracker::State {
    ReferenceDetector detector;
    CameraIntrinsics camera; // cameraMat / distortionMat view it
    bool distorted = false;  // the camera's lens distorts: homographies are fitted on pinhole points
    double metresPerPixel = 0;
    std::array<cv::Point3d, 4> targetCorners{}; // metres

    // What is followed between frames: reference pixels and where they were last seen.
    std::vector<cv::Point2f> trackedReference, trackedFrame;
    bool tracking = false;
    int framesSinceDetection = 0;
    cv::Size frameSize;
    std::optional<TargetPose> lastPose;

    // Per-frame buffers, kept to reuse their memory.
    cv::Mat grey;
    std::vector<cv::Mat> pyramid, previousPyramid;
    std::vector<cv::Point2f> nextPoints, backPoints;
    std::vector<unsigned char> status, backStatus;
    std::vector<float> flowErrors;
    cv::Mat inlierMask;
    std::vector<cv::Point3f> objectPoints;
    cv::Mat seedMask;
    std::vector<cv::Point2f> corners, cornerPinhole, cornerReference, pinholePoints;
    std::vector<cv::Point2d> insetQuad;
    std::array<cv::Point3d, 4> insetCorners{}; // metres
    cv::Matx33d homography;

    void buildPyramid()
    {
        // No reuse of `grey` inside the pyramid: it is overwritten by the next frame.
        cv::buildOpticalFlowPyramid(grey, pyramid, KltWindow, KltLevels, true, cv::BORDER_REFLECT_101,
                                    cv::BORDER_CONSTANT, false);
    }

    // Follows the points from the previous frame; false when too few survive or the fit degenerates.
    bool track()
    {
        cv::calcOpticalFlowPyrLK(previousPyramid, pyramid, trackedFrame, nextPoints, status, flowErrors, KltWindow,
                                 KltLevels, KltStop);
        cv::calcOpticalFlowPyrLK(pyramid, previousPyramid, nextPoints, backPoints, backStatus, flowErrors, KltWindow,
                                 KltLevels, KltStop);
        const cv::Rect2f inside(0, 0, float(frameSize.width), float(frameSize.height));
        std::size_t kept = 0;
        for (std::size_t i = 0; i < trackedFrame.size(); ++i) {
            // Tracked forward then back, a well-followed point returns where it started.
            if (!status[i] || !backStatus[i] || cv::norm(backPoints[i] - trackedFrame[i]) > ForwardBackwardLimit ||
                !inside.contains(nextPoints[i]))
                continue;
            trackedReference[kept] = trackedReference[i];
            trackedFrame[kept++] = nextPoints[i];
        }
        trackedReference.resize(kept);
        trackedFrame.resize(kept);
        if (int(kept) < MinimumTrackedPoints)
            return false;
        if (distorted)
            toPinhole(camera, trackedFrame, pinholePoints);
        const cv::Mat h = cv::findHomography(trackedReference, distorted ? pinholePoints : trackedFrame, cv::RANSAC,
                                             TrackingThreshold, inlierMask);
        if (h.empty() || cv::countNonZero(inlierMask) < MinimumTrackedPoints)
            return false;
        homography = cv::Matx33d(h);
        if (!plausible(homography, detector.pictureSize, frameSize))
            return false;
        // Points that have slid off where the homography puts them (KLT's drift) are dropped too.
        const std::vector<cv::Point2f>& seen = distorted ? pinholePoints : trackedFrame;
        kept = 0;
        for (std::size_t i = 0; i < trackedFrame.size(); ++i) {
            const cv::Vec3d p = homography * cv::Vec3d(trackedReference[i].x, trackedReference[i].y, 1.0);
            const double dx = p[0] / p[2] - seen[i].x, dy = p[1] / p[2] - seen[i].y;
            if (inlierMask.at<unsigned char>(int(i)) && dx * dx + dy * dy <= DriftLimit * DriftLimit) {
                trackedReference[kept] = trackedReference[i];
                trackedFrame[kept++] = trackedFrame[i];
            }
        }
        trackedReference.resize(kept);
        trackedFrame.resize(kept);
        return int(kept) >= MinimumTrackedPoints;
    }

    // Points to follow: Shi–Tomasi corners of this frame on the picture (a little inside its edge,
    // where the background does not move with it), their reference pixels from the homography.
    // Not AKAZE's matches themselves: those are blob centres, which KLT loses fast (on a synthetic
    // sweep 238 of them fell to 24 in 19 frames). `replace`: drop the current points (after a
    // detection); otherwise add corners away from them.
    void seedCorners(bool replace, const TargetPose& pose)
    {
        if (replace) {
            trackedReference.clear();
            trackedFrame.clear();
        }
        const int wanted = MaximumTrackedPoints - int(trackedFrame.size());
        if (wanted <= 0)
            return;
        seedMask.create(frameSize, CV_8U);
        seedMask.setTo(0);
        cv::projectPoints(insetCorners, rvec(pose), tvec(pose), cameraMat(camera), distortionMat(camera), insetQuad);
        std::array<cv::Point, 4> quad;
        for (std::size_t i = 0; i < 4; ++i)
            quad[i] = cv::Point(cvRound(insetQuad[i].x), cvRound(insetQuad[i].y));
        cv::fillConvexPoly(seedMask, quad.data(), 4, cv::Scalar(255));
        for (const cv::Point2f& p : trackedFrame)
            cv::circle(seedMask, p, int(CornerSpacing), cv::Scalar(0), cv::FILLED);
        cv::goodFeaturesToTrack(grey, corners, wanted, CornerQuality, CornerSpacing, seedMask);
        if (corners.empty())
            return;
        if (distorted)
            toPinhole(camera, corners, cornerPinhole);
        cv::perspectiveTransform(distorted ? cornerPinhole : corners, cornerReference, cv::Matx33d(homography.inv()));
        trackedFrame.insert(trackedFrame.end(), corners.begin(), corners.end());
        trackedReference.insert(trackedReference.end(), cornerReference.begin(), cornerReference.end());
    }

    // The pose from the followed correspondences, the points mapped to metres on the plane
    // (fitPlanarPose: IPPE, the last pose choosing between its two when they fit alike, then
    // Levenberg–Marquardt).
    bool solvePose(TrackerEstimate& estimate)
    {
        objectPoints.clear();
        for (const cv::Point2f& p : trackedReference)
            objectPoints.emplace_back(float((p.x + 0.5) * metresPerPixel), float((p.y + 0.5) * metresPerPixel), 0.f);
        auto fitted = fitPlanarPose(objectPoints, trackedFrame, camera, lastPose);
        if (!fitted)
            return false;
        estimate = *fitted;
        lastPose = estimate.pose;
        return true;
    }

    void lose()
    {
        tracking = false;
        lastPose.reset();
        trackedReference.clear();
        trackedFrame.clear();
    }
};

PlanarTracker::PlanarTracker(std::unique_ptr<State> state, std::string name, double width, double height,
                             int pictureWidth, int pictureHeight, int referenceFeatures)
    : m_state(std::move(state)), m_name(std::move(name)), m_width(width), m_height(height),
      m_pictureWidth(pictureWidth), m_pictureHeight(pictureHeight), m_referenceFeatures(referenceFeatures)
{
}

PlanarTracker::~PlanarTracker() = default;

Result<std::unique_ptr<PlanarTracker>> PlanarTracker::create(const std::filesystem::path& picture, double widthMetres,
                                                             const CameraIntrinsics& camera)
{
    if (!(widthMetres > 0) || !std::isfinite(widthMetres))
        return makeError(ErrorCode::InvalidArgument, "The printed width of " + picture.filename().string() +
                                                         " must be a positive number of metres, not " +
                                                         std::to_string(widthMetres) + ".");
    const cv::Mat grey = readGrey(picture);
    if (grey.empty())
        return pictureNotRead(picture);
    auto state = std::make_unique<State>();
    const int features = state->detector.describe(grey);
    if (features < MinimumReferenceFeatures)
        return makeError(ErrorCode::InvalidArgument, tooFewFeatures(picture, features));
    state->camera = camera;
    state->distorted = hasDistortion(camera);
    state->metresPerPixel = widthMetres / grey.cols;
    const double height = widthMetres * grey.rows / grey.cols;
    state->targetCorners = {cv::Point3d(0, 0, 0), cv::Point3d(widthMetres, 0, 0), cv::Point3d(widthMetres, height, 0),
                            cv::Point3d(0, height, 0)};
    const double insetX = TargetInset * widthMetres, insetY = TargetInset * height;
    state->insetCorners = {cv::Point3d(insetX, insetY, 0), cv::Point3d(widthMetres - insetX, insetY, 0),
                           cv::Point3d(widthMetres - insetX, height - insetY, 0), cv::Point3d(insetX, height - insetY, 0)};
    char width[32];
    std::snprintf(width, sizeof width, "%.2f", widthMetres);
    return std::unique_ptr<PlanarTracker>(new PlanarTracker(std::move(state),
                                                            picture.filename().string() + ", " + width + " m wide",
                                                            widthMetres, height, grey.cols, grey.rows, features));
}

std::string PlanarTracker::description() const
{
    return m_name;
}

void PlanarTracker::reset()
{
    m_state->lose();
    m_state->frameSize = {};
    m_lastWasDetection = false;
    m_detections = m_trackedFrames = 0;
}

TrackerEstimate PlanarTracker::estimate(const VideoFrame& frame)
{
    m_lastWasDetection = false;
    if (frame.empty()) {
        m_state->lose();
        return {};
    }
    try {
        return estimateFrame(frame);
    } catch (const cv::Exception&) {
        // Degenerate points OpenCV refuses (all on one line, say): this frame shows no target.
        m_state->lose();
        m_lastWasDetection = false;
        return {};
    }
}

TrackerEstimate PlanarTracker::estimateFrame(const VideoFrame& frame)
{
    State& s = *m_state;
    TrackerEstimate estimate;
    cv::cvtColor(bgrMat(frame), s.grey, cv::COLOR_BGR2GRAY);
    if (s.grey.size() != s.frameSize) { // a new source: nothing to follow from
        s.lose();
        s.frameSize = s.grey.size();
    }
    // Follow the points while that works; detect when they are lost and, to stop drift, every
    // RedetectionInterval frames, but keep following if that scheduled detection fails.
    const bool canTrack = s.tracking, due = s.framesSinceDetection >= RedetectionInterval;
    if (canTrack)
        s.buildPyramid();
    bool tracked = canTrack && !due && s.track();
    bool detected = false;
    if (!tracked) {
        detected = s.detector.detect(s.grey, &s.camera, MaximumTrackedPoints, s.homography, s.trackedReference,
                                     s.trackedFrame);
        if (!detected && canTrack && due)
            tracked = s.track();
        if (!detected && !tracked)
            s.lastPose.reset(); // a lost target may come back any way round
    }
    if ((!tracked && !detected) || !s.solvePose(estimate)) {
        s.lose();
        return estimate;
    }
    m_lastWasDetection = detected;
    if (detected || int(s.trackedFrame.size()) < ReplenishBelow)
        s.seedCorners(detected, estimate.pose);
    if (detected) {
        ++m_detections;
        s.framesSinceDetection = 0;
    } else {
        ++m_trackedFrames;
        ++s.framesSinceDetection;
    }
    if (!canTrack)
        s.buildPyramid();
    std::swap(s.pyramid, s.previousPyramid); // this frame is where the next one is tracked from
    s.tracking = true;

    m_homography = toArray(s.homography);
    std::array<cv::Point2d, 4> corners{};
    cv::projectPoints(s.targetCorners, rvec(estimate.pose), tvec(estimate.pose), cameraMat(s.camera),
                      distortionMat(s.camera), corners);
    for (std::size_t i = 0; i < 4; ++i)
        m_corners[i] = {corners[i].x, corners[i].y};
    return estimate;
}

// ---- Without a camera -----------------------------------------------------------------------

Result<PlanarMatch> findPlanarMatch(const std::filesystem::path& reference, const std::filesystem::path& scene)
try {
    const cv::Mat referenceGrey = readGrey(reference);
    if (referenceGrey.empty())
        return pictureNotRead(reference);
    const cv::Mat sceneGrey = readGrey(scene);
    if (sceneGrey.empty())
        return pictureNotRead(scene);
    ReferenceDetector detector;
    const int features = detector.describe(referenceGrey);
    if (features < PlanarTracker::MinimumReferenceFeatures)
        return makeError(ErrorCode::InvalidArgument, tooFewFeatures(reference, features));
    cv::Matx33d h;
    std::vector<cv::Point2f> referenceInliers, sceneInliers;
    if (!detector.detect(sceneGrey, nullptr, std::numeric_limits<int>::max(), h, referenceInliers, sceneInliers))
        return makeError(ErrorCode::NotFound,
                         reference.filename().string() + " was not found in " + scene.string() + ": " +
                             std::to_string(detector.matches) + " features matched, " +
                             std::to_string(detector.inliers) + " of them agree on where (at least " +
                             std::to_string(MinimumDetectionInliers) + " needed, on a picture that does not fold).");
    PlanarMatch match;
    match.homography = toArray(h);
    match.matches = detector.matches;
    match.inliers = detector.inliers;
    return match;
} catch (const cv::Exception& e) {
    return makeError(ErrorCode::Internal, "Finding " + reference.filename().string() + " in " + scene.string() +
                                              " failed inside OpenCV.", e.msg);
}

Result<Homography> findPlanarHomography(const std::filesystem::path& reference, const std::filesystem::path& scene)
{
    auto match = findPlanarMatch(reference, scene);
    if (!match)
        return match.error();
    return match->homography;
}

Result<Homography> readHomographyFile(const std::filesystem::path& path)
{
    const auto text = readTextFile(path);
    if (!text)
        return text.error();
    const std::size_t start = text->find_first_not_of(" \t\r\n");
    if (start == std::string::npos)
        return makeError(ErrorCode::CorruptData, path.string() + ":1: empty; expected a 3 × 3 matrix.");
    const char first = (*text)[start];
    if (first == '<' || first == '%' || first == '{') // OpenCV's XML, YAML or JSON storage
        return parseStorageHomography(*text, path.string());
    return parsePlainHomography(*text, path.string());
}

PixelPoint applyHomography(const Homography& h, const PixelPoint& p)
{
    const double w = h[6] * p[0] + h[7] * p[1] + h[8];
    return {(h[0] * p[0] + h[1] * p[1] + h[2]) / w, (h[3] * p[0] + h[4] * p[1] + h[5]) / w};
}

// ---- Drawing the target ---------------------------------------------------------------------

void renderPlanarTarget(const VideoFrame& picture, double widthMetres, const CameraIntrinsics& camera,
                        const TargetPose& pose, VideoFrame& frame, std::uint8_t background)
{
    if (frame.width <= 0 || frame.height <= 0)
        frame.resize(camera.width, camera.height);
    cv::Mat out = bgrMat(frame);
    const cv::Scalar grey = cv::Scalar::all(background);
    if (picture.empty() || !(widthMetres > 0) || out.empty()) {
        out.setTo(grey);
        return;
    }
    const double heightMetres = widthMetres * picture.height / picture.width;
    // The plane (X, Y, 1) to the camera's normalised rays: [r1 r2 t].
    cv::Matx33d r;
    cv::Rodrigues(rvec(pose), r);
    const cv::Vec3d t = tvec(pose);
    const cv::Matx33d plane(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
    const cv::Matx33d k(camera.matrix.data());

    // How large the picture appears (about; distortion aside): shrink it first, smoothing as it
    // goes, so that remap's bilinear sampling does not alias.
    const cv::Mat source = bgrMat(picture);
    double area = 0;
    bool inFront = true;
    std::array<cv::Point2d, 4> seen{};
    const std::array<cv::Vec3d, 4> corners{cv::Vec3d(0, 0, 1), cv::Vec3d(widthMetres, 0, 1),
                                           cv::Vec3d(widthMetres, heightMetres, 1), cv::Vec3d(0, heightMetres, 1)};
    for (std::size_t i = 0; i < 4; ++i) {
        const cv::Vec3d p = k * (plane * corners[i]);
        inFront = inFront && p[2] > 0;
        seen[i] = cv::Point2d(p[0] / p[2], p[1] / p[2]);
    }
    for (std::size_t i = 0; i < 4; ++i)
        area += seen[i].cross(seen[(i + 1) % 4]) / 2;
    const double scale = inFront ? std::sqrt(std::abs(area) / (double(picture.width) * picture.height)) : 1.0;
    cv::Mat shrunk = source;
    if (scale < 0.75)
        cv::resize(source, shrunk,
                   cv::Size(std::max(2, int(std::lround(picture.width * scale))),
                            std::max(2, int(std::lround(picture.height * scale)))),
                   0, 0, cv::INTER_AREA);
    const double pixelsPerMetreX = shrunk.cols / widthMetres, pixelsPerMetreY = shrunk.rows / heightMetres;

    // Each frame pixel's ray, undistorted, meets the plane at (X, Y); the picture pixel there.
    cv::Mat mapX(out.size(), CV_32F), mapY(out.size(), CV_32F);
    const cv::Mat distortion = distortionMat(camera);
    const bool distorted = hasDistortion(camera);
    std::vector<cv::Point2f> pixels, rays;
    if (distorted) {
        pixels.reserve(out.total());
        for (int y = 0; y < out.rows; ++y)
            for (int x = 0; x < out.cols; ++x)
                pixels.emplace_back(float(x), float(y));
        cv::undistortPoints(pixels, rays, cameraMat(camera), distortion, cv::noArray(), cv::noArray(), UndistortStop);
    }
    const cv::Matx33d fromRay = plane.inv(), fromPixel = fromRay * k.inv();
    for (int y = 0; y < out.rows; ++y) {
        float* u = mapX.ptr<float>(y);
        float* v = mapY.ptr<float>(y);
        for (int x = 0; x < out.cols; ++x) {
            cv::Vec3d q;
            if (distorted) {
                const cv::Point2f& ray = rays[std::size_t(y) * std::size_t(out.cols) + std::size_t(x)];
                q = fromRay * cv::Vec3d(ray.x, ray.y, 1);
            } else {
                q = fromPixel * cv::Vec3d(x, y, 1);
            }
            if (!(q[2] > 0)) { // the ray meets the plane behind the camera
                u[x] = v[x] = -10.f;
                continue;
            }
            u[x] = float(q[0] / q[2] * pixelsPerMetreX - 0.5);
            v[x] = float(q[1] / q[2] * pixelsPerMetreY - 0.5);
        }
    }
    cv::remap(shrunk, out, mapX, mapY, cv::INTER_LINEAR, cv::BORDER_CONSTANT, grey);
}

Result<VideoFrame> warpTargetIntoFrame(const std::filesystem::path& reference, double widthMetres,
                                       const CameraIntrinsics& camera, const TargetPose& pose, int frameWidth,
                                       int frameHeight)
{
    if (!(widthMetres > 0) || !std::isfinite(widthMetres))
        return makeError(ErrorCode::InvalidArgument, "The printed width of " + reference.filename().string() +
                                                         " must be a positive number of metres, not " +
                                                         std::to_string(widthMetres) + ".");
    if (frameWidth <= 0 || frameHeight <= 0)
        return makeError(ErrorCode::InvalidArgument, "A frame needs a positive size, not " +
                                                         std::to_string(frameWidth) + " × " +
                                                         std::to_string(frameHeight) + " pixels.");
    auto picture = readPicture(reference);
    if (!picture)
        return picture.error();
    VideoFrame frame;
    frame.resize(frameWidth, frameHeight);
    frame.index = 0;
    renderPlanarTarget(*picture, widthMetres, camera, pose, frame);
    return frame;
}

} // namespace thespis::core::ar
