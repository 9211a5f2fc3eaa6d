#include "ar/marker_tracker.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "ar/aruco_board.h"
#include "ar/charuco_corners.h"
#include "ar/edge_refine.h"
#include "ar/marker_synthesis.h"
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
// Smears longer than this (pixels) bias the edges of the markers' borders (edge_refine.h); the
// markers' patterns are fitted to the picture instead (marker_synthesis.h). Sharp frames' edges
// are found to 0.03 px already, and show about a pixel of "smear" (the pixels' own area).
constexpr double SynthesisSmear = 2.0;
// A frame where the detector finds no marker of a grid seen in the last frame is most likely
// smeared over the markers' cells: their patterns are fitted where they were, starting from the
// last frame's smear, then from this one (pixels). At least half the markers must fit.
constexpr double LongSmearGuess = 12.0;

cv::Ptr<cv::aruco::DetectorParameters> detectorParameters()
{
    cv::Ptr<cv::aruco::DetectorParameters> parameters = cv::aruco::DetectorParameters::create();
    parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_SUBPIX;
    return parameters;
}

// A marker's width in cells: its bits and the black border round them.
int markerCells(const cv::aruco::Dictionary& dictionary, const cv::aruco::DetectorParameters& parameters)
{
    return dictionary.markerSize + 2 * parameters.markerBorderBits;
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
    const cv::Ptr<cv::aruco::Dictionary> markerDictionary = cv::aruco::getPredefinedDictionary(id);
    cv::aruco::detectMarkers(grey, markerDictionary, corners, ids, parameters);
    if (precision == MarkerCorners::SubPixel)
        for (std::vector<cv::Point2f>& marker : corners)
            refineMarkerEdges(grey, marker, markerCells(*markerDictionary, *parameters));
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
    std::vector<EdgeRamp> ramps;
    std::vector<MarkerPattern> patterns; // a grid's markers as printed, by id
    float whiteMargin = 0;               // cells of paper known round each of a grid's markers

    std::vector<cv::Point3f> outline; // the board's extent in its plane, for the search region
    std::vector<cv::Point2f> projectedOutline;
    std::optional<TargetPose> lastPose;
    MotionBlur lastBlur;
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

    // Each marker's pattern fitted to the picture, smeared; the frame's smear is then what the
    // markers' fits agree on (the mean of their smears' outer products, which have no sign).
    // Detected markers whose fit fails keep their corners; predicted ones are dropped.
    MotionBlur alignPatterns(const MotionBlur& estimated, CornerStart cornerStart = CornerStart::Detected)
    {
        double xx = 0, xy = 0, yy = 0;
        int fitted = 0;
        MotionBlur start = estimated;
        std::size_t kept = 0;
        for (std::size_t m = 0; m < corners.size(); ++m) {
            MotionBlur own;
            const bool aligned = ids[m] >= 0 && std::size_t(ids[m]) < patterns.size() &&
                                 alignMarkerPattern(grey, corners[m], patterns[std::size_t(ids[m])], whiteMargin, start,
                                                    fitted ? SmearDirection::Known : SmearDirection::Search, &own,
                                                    cornerStart);
            if (aligned || cornerStart == CornerStart::Detected) {
                std::swap(corners[kept], corners[m]);
                std::swap(ids[kept], ids[m]);
                ++kept;
            }
            if (!aligned)
                continue;
            start = own; // the next markers start from this one's smear
            const double x = own.length * std::cos(own.angle), y = own.length * std::sin(own.angle);
            xx += x * x, xy += x * y, yy += y * y, ++fitted;
        }
        corners.resize(kept);
        ids.resize(kept);
        if (fitted == 0)
            return estimated;
        xx /= fitted, xy /= fitted, yy /= fitted;
        MotionBlur blur;
        blur.modelled = fitted == int(corners.size());
        blur.length = std::sqrt(0.5 * (xx + yy) + std::hypot(0.5 * (xx - yy), xy));
        blur.angle = 0.5 * std::atan2(2 * xy, xx - yy);
        if (blur.angle < 0)
            blur.angle += CV_PI;
        return blur;
    }

    // A grid the detector cannot see in a smear longer than its cells is looked for where the
    // last frame saw it: its markers drawn there, smeared, and fitted to the picture. Only
    // markers whose fit holds are kept; fewer than half the board's leave the frame missed.
    MotionBlur placeFromLastPose()
    {
        if (charuco || !lastPose || framesSinceSeen > 0)
            return {};
        std::vector<cv::Point2f> projected;
        for (const double guess : {lastBlur.length, LongSmearGuess}) {
            if (guess <= SynthesisSmear)
                continue;
            corners.clear();
            ids.clear();
            for (std::size_t m = 0; m < board->ids.size(); ++m) {
                cv::projectPoints(board->objPoints[m], rvec(*lastPose), tvec(*lastPose), cameraMat(camera),
                                  distortionMat(camera), projected);
                corners.push_back(projected);
                ids.push_back(board->ids[m]);
            }
            MotionBlur blur = alignPatterns({guess, lastBlur.angle}, CornerStart::Predicted);
            if (2 * ids.size() >= board->ids.size()) {
                blur.modelled = false; // fitted from a guess: trusted along the smear as edges are
                return blur;
            }
        }
        corners.clear();
        ids.clear();
        return {};
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
    else // the edges place a grid's corners (edge_refine.h); cv::cornerSubPix would only cost time
        state->parameters->cornerRefinementMethod = cv::aruco::CORNER_REFINE_NONE;
    state->board = state->charuco ? cv::Ptr<cv::aruco::Board>(state->charuco) : arucoBoard(board);
    if (!state->charuco) {
        // Half the gap between markers is known to be white round each (the other half may be
        // smeared over by the neighbour).
        const int cells = markerCells(*state->board->dictionary, *state->parameters);
        state->whiteMargin = float(0.5 * board.second / board.square * cells);
        for (const int id : state->board->ids) {
            if (std::size_t(id) >= state->patterns.size())
                state->patterns.resize(std::size_t(id) + 1);
            cv::Mat drawn;
            state->board->dictionary->drawMarker(id, cells, drawn, state->parameters->markerBorderBits);
            MarkerPattern& pattern = state->patterns[std::size_t(id)];
            pattern.cells = cells;
            pattern.white.assign(drawn.begin<std::uint8_t>(), drawn.end<std::uint8_t>());
            for (std::uint8_t& cell : pattern.white)
                cell = cell > 127;
        }
    }
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
    // A grid's corners are its markers' corners, placed by their edges; a ChArUco board's come
    // from its chessboard, and its markers' edges only say how blurred the frame is.
    s.ramps.clear();
    const int cells = markerCells(*s.board->dictionary, *s.parameters);
    for (std::vector<cv::Point2f>& marker : s.corners) {
        if (s.charuco) {
            std::vector<cv::Point2f> copy = marker;
            refineMarkerEdges(s.grey, copy, cells, &s.ramps);
        } else {
            refineMarkerEdges(s.grey, marker, cells, &s.ramps);
        }
    }
    MotionBlur blur = estimateMotionBlur(s.ramps);
    if (!s.charuco && blur.length > SynthesisSmear)
        blur = s.alignPatterns(blur);
    if (s.ids.empty())
        blur = s.placeFromLastPose();
    s.lastBlur = blur;
    toDetected(s.corners, s.ids, s.markers);
    s.correspondences();
    const std::optional<TargetPose> previous =
        s.framesSinceSeen <= RememberPoseFrames ? s.lastPose : std::optional<TargetPose>();
    std::optional<TrackerEstimate> fit = fitPlanarPose(s.objectPoints, s.imagePoints, s.camera, previous, blur);
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
    m_state->lastBlur = {};
    m_state->framesSinceSeen = 0;
}

const std::vector<DetectedMarker>& MarkerTracker::markers() const { return m_state->markers; }

const std::vector<std::pair<int, std::array<float, 2>>>& MarkerTracker::charucoCorners() const
{
    return m_state->charucoCorners;
}

} // namespace thespis::core::ar
