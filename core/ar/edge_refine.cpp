#include "ar/edge_refine.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>

#include <opencv2/imgproc.hpp>

namespace thespis::core::ar {

namespace {

// Profiles are sampled this finely (pixels) across a side.
constexpr float ProfileStep = 0.25f;
// A profile reaches this share of the black border's width to each side of the contour: far
// enough for both plateaus of a smeared edge, short of the marker's bits inside.
constexpr float BorderReach = 0.8f;
// A profile whose plateaus differ by less than this (grey levels) holds no edge worth placing.
constexpr float MinimumContrast = 20;
// The drop's centroid is taken between the points this share of the contrast in from each
// plateau, so the plateaus' noise does not weigh on it.
constexpr float PlateauMargin = 0.05f;
// The 10–90 % width of a sharp edge's ramp here: the sensor pixel's own area and the bilinear
// samples between pixels (measured on area-sampled renders).
constexpr double SharpRampWidth = 1.05;
// A smear of length L makes a 10–90 % ramp 0.8 L wide across an edge it runs across.
constexpr double RampShareOfSmear = 0.8;

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

// Where the piecewise-linear profile first crosses `level`, walking from sample `from` by `dir`
// (±1); −1 when it never does.
float crossing(const std::vector<float>& profile, float level, int from, int dir)
{
    const int n = int(profile.size());
    for (int k = from; k >= 0 && k < n && k + dir >= 0 && k + dir < n; k += dir) {
        const float here = profile[std::size_t(k)] - level, next = profile[std::size_t(k + dir)] - level;
        if (here == 0)
            return float(k);
        if ((here > 0) != (next > 0))
            return float(k) + float(dir) * here / (here - next);
    }
    return -1;
}

struct EdgePoint {
    float offset = 0; // samples from the profile's start
    float width = -1; // 10–90 % ramp width, samples; −1 unknown
};

// The edge in one profile (light first, dark last): the centroid of the drop between the
// plateaus, around the mid-level crossing nearest the profile's middle (the contour).
bool edgeInProfile(const std::vector<float>& profile, EdgePoint& edge)
{
    const int n = int(profile.size()), ends = std::max(2, n / 6);
    float light = 0, dark = 0;
    for (int k = 0; k < ends; ++k)
        light += profile[std::size_t(k)], dark += profile[std::size_t(n - 1 - k)];
    light /= float(ends), dark /= float(ends);
    const float contrast = light - dark;
    if (contrast < MinimumContrast)
        return false;
    const float half = 0.5f * (light + dark), middle = 0.5f * float(n - 1);
    float mid = -1;
    for (int k = 0; k + 1 < n; ++k) {
        const float here = profile[std::size_t(k)] - half, next = profile[std::size_t(k + 1)] - half;
        if ((here >= 0) != (next >= 0)) {
            const float at = float(k) + here / (here - next);
            if (mid < 0 || std::abs(at - middle) < std::abs(mid - middle))
                mid = at;
        }
    }
    if (mid < 0)
        return false;
    const int below = int(std::floor(mid));
    const float from = crossing(profile, light - PlateauMargin * contrast, below, -1);
    const float to = crossing(profile, dark + PlateauMargin * contrast, below + 1, +1);
    if (from < 0 || to < 0)
        return false;
    double mass = 0, moment = 0;
    for (int k = int(std::floor(from)); k < int(std::ceil(to)) && k + 1 < n; ++k) {
        const float lo = std::max(float(k), from), hi = std::min(float(k + 1), to);
        if (hi <= lo)
            continue;
        const double drop = double(profile[std::size_t(k)] - profile[std::size_t(k + 1)]) * double(hi - lo);
        mass += drop;
        moment += drop * 0.5 * double(lo + hi);
    }
    if (mass <= 0.5 * double(contrast)) // the drop is not one edge (a bit's edge, noise)
        return false;
    edge.offset = float(moment / mass);
    const float x10 = crossing(profile, light - 0.1f * contrast, below, -1);
    const float x90 = crossing(profile, dark + 0.1f * contrast, below + 1, +1);
    edge.width = x10 >= 0 && x90 >= 0 ? x90 - x10 : -1;
    return true;
}

} // namespace

bool refineMarkerEdges(const cv::Mat& grey, std::vector<cv::Point2f>& corners, int cells, std::vector<EdgeRamp>* ramps)
{
    if (corners.size() != 4 || cells < 3)
        return false;
    cv::Vec4f lines[4];
    EdgeRamp found[4];
    float narrowestBorder = 1e9f;
    std::vector<float> profile;
    std::vector<cv::Point2f> edge;
    for (int side = 0; side < 4; ++side) {
        const cv::Point2f a = corners[std::size_t(side)], b = corners[std::size_t((side + 1) % 4)];
        const cv::Point2f along = b - a;
        const float length = std::hypot(along.x, along.y);
        if (length < 8)
            return false;
        const cv::Point2f normal(-along.y / length, along.x / length); // into the marker
        // The border's width across this side comes from the adjacent sides, not from this one:
        // a marker seen at a slant is narrower one way than the other.
        const cv::Point2f before = corners[std::size_t((side + 3) % 4)], after = corners[std::size_t((side + 2) % 4)];
        const float across = 0.5f * std::abs((before - a).dot(normal) + (after - b).dot(normal));
        const float border = across / float(cells);
        narrowestBorder = std::min(narrowestBorder, border);
        const float reach = std::clamp(BorderReach * border, 1.5f, 12.0f);
        const int steps = int(reach / ProfileStep);
        profile.resize(std::size_t(2 * steps + 1));
        edge.clear();
        double widths = 0;
        int measured = 0;
        const int count = std::max(6, int(length / 2));
        for (int i = 0; i < count; ++i) {
            // The corners' ends of a side bend round them: profile its middle 76 %.
            const cv::Point2f centre = a + along * (0.12f + 0.76f * float(i) / float(count - 1));
            for (int k = -steps; k <= steps; ++k) {
                const float value = sample(grey, centre + normal * (float(k) * ProfileStep));
                if (value < 0)
                    return false; // at the picture's border
                profile[std::size_t(k + steps)] = value;
            }
            EdgePoint point;
            if (!edgeInProfile(profile, point))
                continue;
            edge.push_back(centre + normal * ((point.offset - float(steps)) * ProfileStep));
            if (point.width >= 0)
                widths += double(point.width * ProfileStep), ++measured;
        }
        if (int(edge.size()) < count / 2)
            return false;
        cv::fitLine(edge, lines[side], cv::DIST_L2, 0, 0.01, 0.01);
        found[side] = {normal, measured ? float(widths / measured) : 0.f, measured};
    }
    // A right edge moves a corner by the contour's bias, under a pixel or two even when smeared;
    // more than half the border means a profile took a bit's edge or something beside the marker.
    const float cap = std::max(1.5f, 0.5f * narrowestBorder);
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
        if (moved.dot(moved) > cap * cap)
            return false;
    }
    corners = refined;
    if (ramps)
        ramps->insert(ramps->end(), found, found + 4);
    return true;
}

MotionBlur estimateMotionBlur(const std::vector<EdgeRamp>& ramps)
{
    // Each ramp's excess over a sharp one, squared, is (0.8 L)² (n·d)²: fit L² and d by scanning
    // d over half a turn (a smear has no sign), L² in closed form for each.
    std::vector<std::pair<cv::Point2f, double>> excess;
    for (const EdgeRamp& ramp : ramps)
        if (ramp.profiles >= 3)
            excess.emplace_back(ramp.normal, (double(ramp.width) * ramp.width - SharpRampWidth * SharpRampWidth) /
                                                 (RampShareOfSmear * RampShareOfSmear));
    MotionBlur blur;
    if (excess.size() < 2)
        return blur;
    double bestResidual = 1e300, bestSquared = 0;
    constexpr int Directions = 180;
    for (int i = 0; i < Directions; ++i) {
        const double angle = std::numbers::pi * i / Directions;
        const double dx = std::cos(angle), dy = std::sin(angle);
        double yc = 0, cc = 0, yy = 0;
        for (const auto& [normal, y] : excess) {
            const double dot = normal.x * dx + normal.y * dy, c = dot * dot;
            yc += y * c, cc += c * c, yy += y * y;
        }
        const double squared = cc > 0 ? std::max(0.0, yc / cc) : 0;
        const double residual = yy - 2 * squared * yc + squared * squared * cc;
        if (residual < bestResidual)
            bestResidual = residual, bestSquared = squared, blur.angle = angle;
    }
    blur.length = std::sqrt(bestSquared);
    return blur;
}

} // namespace thespis::core::ar
