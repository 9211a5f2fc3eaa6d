#include "ar/marker_tracker.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "ar/aruco_board.h"
#include "ar/charuco_corners.h"
#include "ar/opencv_bridge.h"
#include "ar/pose_fit.h"

namespace thespis::core::ar {

namespace {

// After this many frames without the board, the last pose no longer says which of IPPE's two
// poses is the real one.
constexpr int RememberPoseFrames = 15;
// ChArUco corners are interpolated from the markers around them; fewer than this many markers
// give corners too loosely placed.
constexpr int CharucoMinimumMarkers = 2;
// The search region around the board's last place reaches this much farther (pixels) than a
// quarter of its size, for a small board moving fast.
constexpr int SearchMarginPixels = 24;

cv::Ptr<cv::aruco::DetectorParameters> detectorParameters()
{
    cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
    parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
    return parameters;
}

// The grey level at a sub-pixel position (bilinear), or −1 outside the picture.
float sample(const cv::Mat& grey, cv::Point2f p)
{
    const int x = int(std::floor(p.x)), y = int(std::floor(p.y));
    if (x < 0 || y < 0 || x + 1 >= grey.cols || y + 1 >= grey.rows)
        return -1;
    const float fx = p.x - float(x), fy = p.y - float(y);
    const std::uint8_t* row = grey.ptr<std::uint8_t>(y);
    const std::uint8_t* next = grey.ptr<std::uint8_t>(y + 1);
    return (1 - fy) * ((1 - fx) * row[x] + fx * row[x + 1]) + fy * ((1 - fx) * next[x] + fx * next[x + 1]);
}

// A marker's corner is where two straight edges of a black square meet: an L, not the saddle
// cv::cornerSubPix is made for, which it places a few tenths of a pixel off, always the same way
// for a given view (so no temporal filter can average it out). Each side's edge is found instead
// at many points along it (the steepest grey-level step across the side, to a fraction of a
// pixel), a line fitted through them, and the corners are where the lines cross.
bool refineAlongEdges(const cv::Mat& grey, std::vector<cv::Point2f>& corners)
{
    cv::Vec4f lines[4];
    for (int side = 0; side < 4; ++side) {
        const cv::Point2f a = corners[std::size_t(side)], b = corners[std::size_t((side + 1) % 4)];
        const cv::Point2f along = b - a;
        const float length = std::hypot(along.x, along.y);
        if (length < 8)
            return false;
        const cv::Point2f normal(-along.y / length, along.x / length);
        // Search no farther than a quarter of a marker bit, so the bits inside are not taken.
        const float reach = std::clamp(length / 24, 1.0f, 4.0f), step = 0.25f;
        const int steps = int(reach / step);
        std::vector<cv::Point2f> edge;
        const int count = std::max(6, int(length / 2));
        for (int i = 0; i < count; ++i) {
            const cv::Point2f centre = a + along * (0.12f + 0.76f * float(i) / float(count - 1));
            float best = 0, bestOffset = 0;
            float before = sample(grey, centre - normal * float(steps + 1) * step);
            float here = sample(grey, centre - normal * float(steps) * step);
            float gradients[64];
            int n = 0;
            for (int k = -steps; k <= steps && n < 64; ++k, ++n) {
                const float after = sample(grey, centre + normal * float(k + 1) * step);
                if (before < 0 || after < 0)
                    return false;
                gradients[n] = std::abs(after - before);
                before = here;
                here = after;
            }
            int peak = -1;
            for (int k = 1; k + 1 < n; ++k)
                if (gradients[k] > best && gradients[k] >= gradients[k - 1] && gradients[k] >= gradients[k + 1])
                    best = gradients[k], peak = k;
            if (peak < 0 || best < 8)
                continue;
            const float curvature = gradients[peak - 1] - 2 * gradients[peak] + gradients[peak + 1];
            bestOffset = curvature < 0 ? 0.5f * (gradients[peak - 1] - gradients[peak + 1]) / curvature : 0;
            edge.push_back(centre + normal * ((float(peak - steps) + bestOffset) * step));
        }
        if (int(edge.size()) < count / 2)
            return false;
        cv::fitLine(edge, lines[side], cv::DIST_L2, 0, 0.01, 0.01);
    }
    std::vector<cv::Point2f> refined(4);
    for (int corner = 0; corner < 4; ++corner) {
        // Corner c joins side c − 1 (ending at it) and side c (starting from it).
        const cv::Vec4f& p = lines[(corner + 3) % 4];
        const cv::Vec4f& q = lines[corner];
        const float denominator = p[0] * q[1] - p[1] * q[0];
        if (std::abs(denominator) < 1e-3f)
            return false;
        const float t = ((q[2] - p[2]) * q[1] - (q[3] - p[3]) * q[0]) / denominator;
        refined[std::size_t(corner)] = {p[2] + t * p[0], p[3] + t * p[1]};
        const cv::Point2f moved = refined[std::size_t(corner)] - corners[std::size_t(corner)];
        if (moved.dot(moved) > 4) // more than 2 px: a bad edge, keep what the detector found
            return false;
    }
    corners = refined;
    return true;
}

void toDetected(const std::vector<std::vector<cv::Point2f>>& corners, const std::vector<int>& ids,
                std::vector<DetectedMarker>& out)
{
    out.resize(ids.size());
    for (std::size_t m = 0; m < ids.size(); ++m) {
        out[m].id = ids[m];
        for (int c = 0; c < 4; ++c)
            out[m].corners[std::size_t(c)] = {corners[m][std::size_t(c)].x, corners[m][std::size_t(c)].y};
    }
}

} // namespace

Result<std::vector<DetectedMarker>> detectMarkers(const VideoFrame& frame, std::string_view dictionary,
                                                  MarkerCorners precision)
{
    const int id = arucoDictionaryId(dictionary);
    if (id < 0)
        return makeError(ErrorCode::InvalidArgument,
                         std::string(dictionary).append(" is not an ArUco dictionary (DICT_4X4_50, DICT_6X6_250, …)"));
    cv::Mat grey;
    cv::cvtColor(bgrMat(frame), grey, cv::COLOR_BGR2GRAY);
    std::vector<std::vector<cv::Point2f>> corners;
    std::vector<int> ids;
    cv::Ptr<cv::aruco::DetectorParameters> parameters = detectorParameters();
    if (precision == MarkerCorners::WholePixels)
        parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
    cv::aruco::detectMarkers(grey, cv::aruco::getPredefinedDictionary(id), corners, ids, parameters);
    if (precision == MarkerCorners::SubPixel)
        for (std::vector<cv::Point2f>& marker : corners)
            refineAlongEdges(grey, marker);
    std::vector<DetectedMarker> markers;
    toDetected(corners, ids, markers);
    return markers;
}

struct MarkerTracker::State {
    BoardSpec spec;
    CameraIntrinsics camera;
    cv::Ptr<cv::aruco::Board> board;
    cv::Ptr<cv::aruco::CharucoBoard> charuco; // the same board, when it is one
    cv::Ptr<cv::aruco::DetectorParameters> parameters = detectorParameters();

    // Reused from frame to frame.
    cv::Mat grey;
    std::vector<std::vector<cv::Point2f>> corners, rejected;
    std::vector<int> ids, cornerIds;
    std::vector<cv::Point2f> charucoPixels;
    std::vector<cv::Point3f> objectPoints;
    std::vector<cv::Point2f> imagePoints;

    std::vector<cv::Point3f> outline; // the board's extent in its plane, for the search region
    std::vector<cv::Point2f> projectedOutline;
    std::optional<TargetPose> lastPose;
    int framesSinceSeen = 0;
    std::vector<DetectedMarker> markers;
    std::vector<std::pair<int, std::array<float, 2>>> charucoCorners;

    // Where to look for the board: around where it was in the last frame, when it was seen there
    // (the detector's cost grows with the pixels it thresholds); else the whole frame.
    cv::Rect searchRegion()
    {
        const cv::Rect whole(0, 0, grey.cols, grey.rows);
        if (!lastPose || framesSinceSeen > 0)
            return whole;
        cv::projectPoints(outline, rvec(*lastPose), tvec(*lastPose), cameraMat(camera), distortionMat(camera),
                          projectedOutline);
        const cv::Rect seen = cv::boundingRect(projectedOutline);
        // Room for the board to move between frames: a quarter of its size each way, and more.
        const int marginX = seen.width / 4 + SearchMarginPixels, marginY = seen.height / 4 + SearchMarginPixels;
        const cv::Rect region = cv::Rect(seen.x - marginX, seen.y - marginY, seen.width + 2 * marginX,
                                         seen.height + 2 * marginY) & whole;
        return region.area() > whole.area() * 7 / 10 || region.empty() ? whole : region;
    }

    void detect(const cv::Rect& region)
    {
        cv::aruco::detectMarkers(grey(region), board->dictionary, corners, ids, parameters, rejected);
        const cv::Point2f offset(float(region.x), float(region.y));
        for (auto* found : {&corners, &rejected})
            for (std::vector<cv::Point2f>& marker : *found)
                for (cv::Point2f& corner : marker)
                    corner += offset;
    }

    // The board's points and where they are seen, from the markers found in `grey`.
    void correspondences()
    {
        objectPoints.clear();
        imagePoints.clear();
        charucoCorners.clear();
        if (!charuco) {
            if (!ids.empty())
                cv::aruco::getBoardObjectAndImagePoints(board, corners, ids, objectPoints, imagePoints);
            return;
        }
        if (int(ids.size()) < CharucoMinimumMarkers)
            return;
        cv::aruco::interpolateCornersCharuco(corners, ids, grey, charuco, charucoPixels, cornerIds, cameraMat(camera),
                                             distortionMat(camera), CharucoMinimumMarkers);
        if (cornerIds.size() < 4 || cv::aruco::testCharucoCornersCollinear(charuco, cornerIds))
            return;
        refineCharucoCorners(grey, charucoPixels, corners, spec);
        for (std::size_t i = 0; i < cornerIds.size(); ++i) {
            objectPoints.push_back(charuco->chessboardCorners[std::size_t(cornerIds[i])]);
            imagePoints.push_back(charucoPixels[i]);
            charucoCorners.push_back({cornerIds[i], {charucoPixels[i].x, charucoPixels[i].y}});
        }
    }
};

MarkerTracker::MarkerTracker(std::unique_ptr<State> state) : m_state(std::move(state)) {}
MarkerTracker::~MarkerTracker() = default;

Result<std::unique_ptr<MarkerTracker>> MarkerTracker::create(const BoardSpec& board, const CameraIntrinsics& camera)
{
    if (board.kind == BoardKind::Chessboard)
        return makeError(ErrorCode::InvalidArgument,
                         "A chessboard is for calibration only (its pose is ambiguous under a half turn); track an "
                         "aruco-grid or a charuco board");
    if (camera.fx() <= 0 || camera.fy() <= 0)
        return makeError(ErrorCode::InvalidArgument, "The camera's focal lengths must be positive");
    auto state = std::make_unique<State>();
    state->spec = board;
    state->camera = camera;
    if (board.kind == BoardKind::Charuco)
        state->charuco = charucoBoard(board);
    else // the edges place a grid's corners (refineAlongEdges); cv::cornerSubPix would only cost time
        state->parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
    state->board = state->charuco ? cv::Ptr<cv::aruco::Board>(state->charuco) : arucoBoard(board);
    float minX = 1e9f, minY = 1e9f, maxX = -1e9f, maxY = -1e9f;
    for (const auto& marker : state->board->objPoints)
        for (const cv::Point3f& corner : marker) {
            minX = std::min(minX, corner.x), maxX = std::max(maxX, corner.x);
            minY = std::min(minY, corner.y), maxY = std::max(maxY, corner.y);
        }
    if (state->charuco) // the squares reach beyond the markers
        minX = minY = 0, maxX = float(board.columns * board.square), maxY = float(board.rows * board.square);
    state->outline = {{minX, minY, 0}, {maxX, minY, 0}, {maxX, maxY, 0}, {minX, maxY, 0}};
    return std::unique_ptr<MarkerTracker>(new MarkerTracker(std::move(state)));
}

std::string MarkerTracker::description() const
{
    const BoardSpec& board = m_state->spec;
    return (board.kind == BoardKind::Charuco ? "ChArUco board " : "ArUco grid ") + std::to_string(board.columns) +
           " × " + std::to_string(board.rows) + " of " + board.dictionary;
}

TrackerEstimate MarkerTracker::estimate(const VideoFrame& frame)
{
    State& s = *m_state;
    cv::cvtColor(bgrMat(frame), s.grey, cv::COLOR_BGR2GRAY);
    if (s.spec.inverted)
        cv::bitwise_not(s.grey, s.grey);
    const cv::Rect region = s.searchRegion();
    s.detect(region);
    if (s.ids.empty() && region.area() < s.grey.cols * s.grey.rows)
        s.detect(cv::Rect(0, 0, s.grey.cols, s.grey.rows)); // it moved farther than expected
    // Markers the first pass missed are looked for again against the board's layout; a grid
    // whose every marker was found needs no second look (a ChArUco board's corners still gain
    // from the refined markers).
    if (!s.ids.empty() && (s.charuco || s.ids.size() < s.board->ids.size()))
        cv::aruco::refineDetectedMarkers(s.grey, s.board, s.corners, s.ids, s.rejected, cameraMat(s.camera),
                                         distortionMat(s.camera), 10.f, 3.f, true, cv::noArray(), s.parameters);
    if (!s.charuco)
        for (std::vector<cv::Point2f>& marker : s.corners)
            refineAlongEdges(s.grey, marker);
    toDetected(s.corners, s.ids, s.markers);
    s.correspondences();
    const std::optional<TargetPose> previous =
        s.framesSinceSeen <= RememberPoseFrames ? s.lastPose : std::optional<TargetPose>();
    std::optional<TrackerEstimate> fit = fitPlanarPose(s.objectPoints, s.imagePoints, s.camera, previous);
    if (!fit) {
        ++s.framesSinceSeen;
        return {};
    }
    fit->features = s.charuco ? int(s.charucoCorners.size()) : int(s.ids.size());
    s.lastPose = fit->pose;
    s.framesSinceSeen = 0;
    return *fit;
}

TargetGeometry MarkerTracker::geometry() const
{
    const std::vector<cv::Point3f>& outline = m_state->outline; // min x, min y … max x, max y
    TargetGeometry geometry;
    geometry.centre = {0.5 * (outline[0].x + outline[2].x), 0.5 * (outline[0].y + outline[2].y), 0};
    geometry.size = {double(outline[2].x - outline[0].x), double(outline[2].y - outline[0].y)};
    // A marker's corners go clockwise on the printed side: with its bottom-left below its
    // top-left, y runs up the print and the printed side faces +z.
    const std::vector<cv::Point3f>& marker = m_state->board->objPoints.front();
    geometry.faceNormal = marker[3].y < marker[0].y ? 1 : -1;
    return geometry;
}

void MarkerTracker::reset()
{
    m_state->lastPose.reset();
    m_state->framesSinceSeen = 0;
}

const std::vector<DetectedMarker>& MarkerTracker::markers() const { return m_state->markers; }

const std::vector<std::pair<int, std::array<float, 2>>>& MarkerTracker::charucoCorners() const
{
    return m_state->charucoCorners;
}

} // namespace thespis::core::ar
