// The live light probe (live_probe.h): finding the mirror ball, unwrapping it into a mirror-ball
// probe image, projecting and smoothing its light.

#include "ar/live_probe.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <sstream>
#include <vector>

#include <opencv2/imgproc.hpp>

#include "ar/opencv_bridge.h"
#include "lighting/probe_projection_job.h"

namespace thespis::core::ar {

namespace {

constexpr int kClippedLevel = 250;      // 8-bit values at or above this were clipped by the camera
constexpr int kMaxSamplesPerAxis = 16;  // per probe pixel, when a large ball is reduced
constexpr int kEncodeSteps = 4096;      // resolution of the linear → sRGB table for the picture
constexpr double kPi = 3.14159265358979323846;
constexpr double kRimStepFraction = 0.4; // of a ray's strongest step, for a step to count as the rim
constexpr double kMinRimContrast = 8;    // grey levels over 2 px: a fainter rim is not trusted
constexpr double kMaxRimScatter = 2.0;   // px: rim points further from the fitted circle are left out
// A rim runs along its circle: the grey gradient at its points is radial. Measured as the mean
// |cosine| between gradient and radius over the rim points: 0.993 or more on the real and the
// synthetic balls, 0.961 at most on the circles a marker board's squares and corners suggest
// (whose edges cross the circle at all angles: a checkerboard has an edge near any circle).
constexpr double kMinRimAlignment = 0.98;
constexpr double kRimPullPixels = 1.0;   // see unwrap()
constexpr std::size_t kMaxCandidates = 8; // Hough circles checked against the rim, strongest first
constexpr double kEdgeThreshold = 100;    // Canny's upper threshold in the circle search (grey levels)

std::string number(double value)
{
    std::ostringstream text;
    text.precision(6);
    text << value;
    return text.str();
}

double decodeSrgb(double encoded)
{
    return encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
}
std::uint8_t encodeSrgb(double linear)
{
    const double c = std::clamp(linear, 0.0, 1.0);
    const double s = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1.0 / 2.4) - 0.055;
    return std::uint8_t(std::lround(s * 255.0));
}

double luminance(const float* rgb) { return 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]; }

/// Solves the 3 × 3 system a·x = b (row-major) by Cramer's rule; false when singular.
bool solve3(const std::array<double, 9>& a, const std::array<double, 3>& b, std::array<double, 3>& x)
{
    const auto det = [](double a0, double a1, double a2, double b0, double b1, double b2, double c0, double c1, double c2) {
        return a0 * (b1 * c2 - b2 * c1) - a1 * (b0 * c2 - b2 * c0) + a2 * (b0 * c1 - b1 * c0);
    };
    const double d = det(a[0], a[1], a[2], a[3], a[4], a[5], a[6], a[7], a[8]);
    if (!(std::abs(d) > 1e-300))
        return false;
    x[0] = det(b[0], a[1], a[2], b[1], a[4], a[5], b[2], a[7], a[8]) / d;
    x[1] = det(a[0], b[0], a[2], a[3], b[1], a[5], a[6], b[2], a[8]) / d;
    x[2] = det(a[0], a[1], b[0], a[3], a[4], b[1], a[6], a[7], b[2]) / d;
    return std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]);
}

/// An edge point found on one ray, in frame pixels (probe.h's convention), with its contrast and
/// the grey gradient there.
struct EdgePoint {
    double x = 0, y = 0, strength = 0, gradientX = 0, gradientY = 0, residual = 0;
    bool used = true;
};

/// How well the used points' edges run along `circle`: the mean |cosine| between the grey
/// gradient and the radius, 1 when every edge is tangent to the circle.
double rimAlignment(const std::vector<EdgePoint>& points, const BallCircle& circle)
{
    double sum = 0;
    int count = 0;
    for (const EdgePoint& p : points) {
        const double dx = p.x - circle.centerX, dy = p.y - circle.centerY;
        const double norms = std::hypot(p.gradientX, p.gradientY) * std::hypot(dx, dy);
        if (!p.used || !(norms > 0))
            continue;
        sum += std::abs(p.gradientX * dx + p.gradientY * dy) / norms;
        ++count;
    }
    return count > 0 ? sum / count : 0.0;
}

/// The circle through the used points nearest in the geometric sense: an algebraic (Kåsa) fit
/// to start, then Gauss–Newton on Σ(|p − c| − r)², which the algebraic fit's bias does not have.
bool fitCircle(std::vector<EdgePoint>& points, BallCircle& circle)
{
    // Relative to the current centre, for conditioning.
    const double ox = circle.centerX, oy = circle.centerY;
    std::array<double, 9> a{};
    std::array<double, 3> b{}, x{};
    int count = 0;
    for (const EdgePoint& p : points) {
        if (!p.used)
            continue;
        const double px = p.x - ox, py = p.y - oy, q = px * px + py * py;
        const double row[3] = {px, py, 1.0};
        for (int i = 0; i < 3; ++i) {
            for (int j = 0; j < 3; ++j)
                a[size_t(i * 3 + j)] += row[i] * row[j];
            b[size_t(i)] -= row[i] * q;
        }
        ++count;
    }
    if (count < 8 || !solve3(a, b, x))
        return false;
    double cx = -0.5 * x[0], cy = -0.5 * x[1];
    double r = std::sqrt(std::max(0.0, cx * cx + cy * cy - x[2]));
    for (int iteration = 0; iteration < 10; ++iteration) {
        a = {};
        b = {};
        for (const EdgePoint& p : points) {
            if (!p.used)
                continue;
            const double dx = p.x - ox - cx, dy = p.y - oy - cy, d = std::hypot(dx, dy);
            if (!(d > 1e-9))
                continue;
            const double j[3] = {-dx / d, -dy / d, -1.0}; // ∂(d − r)/∂(cx, cy, r)
            const double e = d - r;
            for (int i = 0; i < 3; ++i) {
                for (int k = 0; k < 3; ++k)
                    a[size_t(i * 3 + k)] += j[i] * j[k];
                b[size_t(i)] -= j[i] * e;
            }
        }
        if (!solve3(a, b, x))
            return false;
        cx += x[0];
        cy += x[1];
        r += x[2];
        if (std::abs(x[0]) + std::abs(x[1]) + std::abs(x[2]) < 1e-6)
            break;
    }
    if (!(r > 0) || !std::isfinite(cx) || !std::isfinite(cy))
        return false;
    circle = {ox + cx, oy + cy, r};
    for (EdgePoint& p : points)
        p.residual = std::hypot(p.x - circle.centerX, p.y - circle.centerY) - r;
    return true;
}

} // namespace

// ---- Settings ---------------------------------------------------------------------------------

Result<void> validateLiveProbeSettings(const LiveProbeSettings& s)
{
    const auto refuse = [](const std::string& what) { return makeError(ErrorCode::InvalidArgument, what); };
    if (s.order < 1 || s.order > lighting::kMaxShOrder)
        return refuse("The live probe's SH order must be 1 to " + std::to_string(lighting::kMaxShOrder) + "; got "
                      + std::to_string(s.order) + ".");
    if (s.probeSize < 16 || s.probeSize > 1024)
        return refuse("The live probe's probeSize must be 16 to 1024 px; got " + std::to_string(s.probeSize) + ".");
    if (s.searchSize < 64 || s.searchSize > 8192)
        return refuse("The live probe's searchSize must be 64 to 8192 px; got " + std::to_string(s.searchSize) + ".");
    if (s.updateEvery < 1)
        return refuse("The live probe's updateEvery must be at least 1 frame; got " + std::to_string(s.updateEvery) + ".");
    if (!(s.smoothingSeconds >= 0) || !std::isfinite(s.smoothingSeconds))
        return refuse("The live probe's smoothingSeconds must be 0 or more; got " + number(s.smoothingSeconds) + ".");
    if (!(s.exposureSmoothingSeconds >= 0) || !std::isfinite(s.exposureSmoothingSeconds))
        return refuse("The live probe's exposureSmoothingSeconds must be 0 or more; got " + number(s.exposureSmoothingSeconds) + ".");
    if (!(s.exposure > 0) || !std::isfinite(s.exposure))
        return refuse("The live probe's exposure must be positive; got " + number(s.exposure) + ".");
    if (!(s.targetLuminance > 0) || !std::isfinite(s.targetLuminance))
        return refuse("The live probe's targetLuminance must be positive; got " + number(s.targetLuminance) + ".");
    if (!(s.clippedGain >= 1) || !std::isfinite(s.clippedGain))
        return refuse("The live probe's clippedGain must be 1 or more (a clipped pixel is at least as bright as it shows); got "
                      + number(s.clippedGain) + ".");
    if (!(s.minRadius >= 0) || !(s.maxRadius >= 0) || !std::isfinite(s.minRadius) || !std::isfinite(s.maxRadius))
        return refuse("The live probe's radius range must be 0 (automatic) or positive; got " + number(s.minRadius) + " to "
                      + number(s.maxRadius) + " px.");
    if (s.minRadius > 0 && s.maxRadius > 0 && !(s.minRadius < s.maxRadius))
        return refuse("The live probe's minRadius (" + number(s.minRadius) + " px) must be below its maxRadius ("
                      + number(s.maxRadius) + " px).");
    if (s.location == BallLocation::Given) {
        const BallCircle& c = s.givenCircle;
        if (!std::isfinite(c.centerX) || !std::isfinite(c.centerY) || !(c.radius >= 2) || !std::isfinite(c.radius))
            return refuse("The ball's circle must have a finite centre and a radius of at least 2 px; got centre ("
                          + number(c.centerX) + ", " + number(c.centerY) + "), radius " + number(c.radius) + " px.");
    }
    return {};
}

Result<void> checkBallCircle(const BallCircle& c, int frameWidth, int frameHeight)
{
    // Checked every processed frame: the message is only made when there is something to say.
    const auto circle = [&] {
        return "The ball's circle (centre " + number(c.centerX) + ", " + number(c.centerY) + ", radius " + number(c.radius) + " px)";
    };
    if (!std::isfinite(c.centerX) || !std::isfinite(c.centerY) || !(c.radius > 0) || !std::isfinite(c.radius))
        return makeError(ErrorCode::InvalidArgument, circle() + " is not a circle.");
    const char* side = c.centerX - c.radius < 0          ? "left"
                       : c.centerX + c.radius > frameWidth  ? "right"
                       : c.centerY - c.radius < 0          ? "top"
                       : c.centerY + c.radius > frameHeight ? "bottom"
                                                            : nullptr;
    if (side)
        return makeError(ErrorCode::InvalidArgument, circle() + " crosses the " + side + " edge of the "
                                                         + std::to_string(frameWidth) + "×" + std::to_string(frameHeight)
                                                         + " frame; the whole ball must be in view.");
    return {};
}

// ---- State ------------------------------------------------------------------------------------

struct LiveProbe::State {
    LiveProbeSettings settings;
    bool fromBall = true;
    std::optional<lighting::ProbeProjector> projector;
    lighting::ProbeLayout layout = lighting::ProbeLayout::MirrorBall;

    lighting::ShRgb light;
    BallSighting ball;
    double exposure = 1.0;
    double clippedFraction = 0;
    lighting::HdrImage image;       // the unwrapped ball, linear, before the exposure
    lighting::PreviewImage picture; // image as the camera saw it (sRGB), alpha 0 off the disc

    std::int64_t framesSeen = 0;
    bool started = false; // the smoothing has a previous light and time
    double lastTime = 0;

    std::array<float, 256> linearOf{};                // 8-bit sRGB → linear
    std::array<std::uint8_t, kEncodeSteps + 1> srgbOf{}; // linear [0, 1] → 8-bit sRGB

    // Circle search buffers, kept so that frames of one size allocate nothing once running.
    cv::Mat grey, reduced, blurred;
    std::vector<cv::Vec3f> circles;
    std::vector<EdgePoint> edges;
    std::vector<double> strengths;

    BallSighting findBall(const VideoFrame& frame);
    bool refine(BallCircle& circle, double window);
    double unwrap(const VideoFrame& frame, const BallCircle& circle);
    void drawPicture();
};

BallSighting LiveProbe::State::findBall(const VideoFrame& frame)
{
    const int shortSide = std::min(frame.width, frame.height);
    const double minRadius = settings.minRadius > 0 ? settings.minRadius : 0.04 * shortSide;
    const double maxRadius = settings.maxRadius > 0 ? settings.maxRadius : 0.5 * shortSide;
    BallSighting sighting;
    cv::cvtColor(bgrMat(frame), grey, cv::COLOR_BGR2GRAY);
    // Where the ball was last time is looked at first: its rim confirmed there spares the search,
    // which costs tens of milliseconds on a busy picture.
    if (ball.found) {
        BallCircle circle = ball.circle;
        if (refine(circle, std::clamp(4.0 + 0.03 * circle.radius, 4.0, 60.0)) && checkBallCircle(circle, frame.width, frame.height)) {
            sighting.found = true;
            sighting.circle = circle;
            return sighting;
        }
    }
    // The search runs on a reduced copy: a Hough transform's cost grows with the pixels and the
    // radii, and the refinement below gets the precision back on the full frame.
    const double scale = std::min(1.0, double(settings.searchSize) / std::max(frame.width, frame.height));
    const cv::Size reducedSize(std::max(1, int(std::lround(frame.width * scale))),
                               std::max(1, int(std::lround(frame.height * scale))));
    if (scale < 1.0)
        cv::resize(grey, reduced, reducedSize, 0, 0, cv::INTER_AREA);
    else
        grey.copyTo(reduced);
    const double sx = double(reducedSize.width) / frame.width, sy = double(reducedSize.height) / frame.height;
    // Blur so that the texture the ball reflects does not outvote its rim.
    cv::GaussianBlur(reduced, blurred, cv::Size(0, 0), 1.5);
    const int minReduced = std::max(2, int(std::floor(minRadius * scale)));
    const int maxReduced = std::max(minReduced + 1, int(std::ceil(maxRadius * scale)));
    // Votes a ball's rim gets: half its circumference at the smallest radius, at least 20. Fewer
    // let a textured picture through as hundreds of candidates, each costing a pass over its
    // edges (a painting took 3 s at a quarter, 0.4 s at half).
    const double votes = std::max(20.0, 0.5 * 2 * kPi * minReduced);
    circles.clear(); // HoughCircles leaves its output as it was when it finds nothing
    try {
        cv::HoughCircles(blurred, circles, cv::HOUGH_GRADIENT, 1.0, std::max(8, minReduced), kEdgeThreshold, votes, minReduced, maxReduced);
    } catch (const cv::Exception& error) {
        sighting.reason = "The search for the ball failed in frame " + std::to_string(frame.index) + ": " + error.what();
        return sighting;
    }
    // Strongest first (OpenCV sorts by votes): the first the rim confirms and the frame holds.
    if (circles.size() > kMaxCandidates)
        circles.resize(kMaxCandidates);
    for (const cv::Vec3f& found : circles) {
        // HoughCircles gives pixel-centre coordinates (a pixel's centre at integers).
        BallCircle circle{(found[0] + 0.5) / sx, (found[1] + 0.5) / sy, found[2] / scale};
        if (circle.radius < minRadius - 2.0 / scale || circle.radius > maxRadius + 2.0 / scale)
            continue;
        // The reduced frame knows the rim to a reduced pixel or two; search that far, and more
        // for large balls (the Hough radius is the least precise part).
        if (!refine(circle, std::clamp(3.0 / scale + 0.03 * circle.radius, 4.0, 60.0)))
            continue; // the rim does not confirm it: a round shape in the picture, not the ball
        if (auto inside = checkBallCircle(circle, frame.width, frame.height); !inside) {
            sighting.reason = inside.error().message;
            continue;
        }
        sighting.found = true;
        sighting.circle = circle;
        sighting.reason.clear();
        return sighting;
    }
    if (sighting.reason.empty())
        sighting.reason = "No circle between " + number(std::round(minRadius)) + " and " + number(std::round(maxRadius))
                          + " px was found in frame " + std::to_string(frame.index) + ".";
    return sighting;
}

bool LiveProbe::State::refine(BallCircle& circle, double window)
{
    // Along rays from the centre, the rim is the outermost clear step of the grey profile within
    // ±window of the rough radius; the circle is fitted to those points, leaving out rays whose
    // step was weak (the ball mirrors something as bright as what is beside it) or far off. The
    // circle stands only if a third of the rays agree on a rim of some contrast that runs along
    // the circle.
    constexpr double step = 0.5;
    constexpr int maxSamples = 256;
    window = std::min(window, 0.5 * (maxSamples - 5) * step);
    const int samples = int(2 * window / step) + 1;
    const int rays = std::clamp(int(2 * kPi * circle.radius / 3), 32, 720);
    const int width = grey.cols, height = grey.rows;
    const auto greyAt = [&](double x, double y) { // bilinear, pixel centres at integers
        const int x0 = int(x), y0 = int(y);
        const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
        const double tx = x - x0, ty = y - y0;
        const std::uint8_t* row0 = grey.ptr<std::uint8_t>(y0);
        const std::uint8_t* row1 = grey.ptr<std::uint8_t>(y1);
        return (1 - ty) * ((1 - tx) * row0[x0] + tx * row0[x1]) + ty * ((1 - tx) * row1[x0] + tx * row1[x1]);
    };
    edges.clear();
    std::array<double, maxSamples> profile{};
    for (int k = 0; k < rays; ++k) {
        const double angle = 2 * kPi * (k + 0.5) / rays, c = std::cos(angle), s = std::sin(angle);
        bool inside = true;
        for (int i = 0; i < samples && inside; ++i) {
            const double r = circle.radius - window + i * step;
            const double x = circle.centerX + r * c - 0.5, y = circle.centerY + r * s - 0.5;
            inside = x >= 0 && y >= 0 && x <= width - 1 && y <= height - 1;
            if (inside)
                profile[size_t(i)] = greyAt(x, y);
        }
        if (!inside || samples < 7)
            continue;
        // Steps over ±1 px (two samples either side). The rim is the outermost clear step, not
        // the strongest: the ball's outer ring mirrors what is right behind it, so the true rim
        // is often fainter than the reflections just inside it.
        const auto stepAt = [&](int i) { return std::abs(profile[size_t(i + 2)] - profile[size_t(i - 2)]); };
        double strongest = 0;
        for (int i = 2; i + 2 < samples; ++i)
            strongest = std::max(strongest, stepAt(i));
        int best = -1;
        for (int i = samples - 4; i >= 3 && best < 0; --i)
            if (stepAt(i) >= kRimStepFraction * strongest && stepAt(i) >= stepAt(i - 1) && stepAt(i) >= stepAt(i + 1))
                best = i;
        const double bestStep = best >= 0 ? stepAt(best) : 0.0;
        if (best < 3 || best + 3 >= samples)
            continue;
        const double before = stepAt(best - 1), after = stepAt(best + 1);
        const double curvature = before - 2 * bestStep + after;
        const double offset = curvature < 0 ? std::clamp(0.5 * (before - after) / curvature, -0.5, 0.5) : 0.0;
        const double r = circle.radius - window + (best + offset) * step;
        const double x = circle.centerX + r * c - 0.5, y = circle.centerY + r * s - 0.5;
        const double left = greyAt(std::max(0.0, x - 1), y), right = greyAt(std::min(width - 1.0, x + 1), y);
        const double up = greyAt(x, std::max(0.0, y - 1)), down = greyAt(x, std::min(height - 1.0, y + 1));
        edges.push_back({x + 0.5, y + 0.5, bestStep, right - left, down - up, 0, true});
    }
    if (edges.size() < 16)
        return false;
    strengths.clear();
    for (const EdgePoint& e : edges)
        strengths.push_back(e.strength);
    std::nth_element(strengths.begin(), strengths.begin() + strengths.size() / 2, strengths.end());
    const double medianStrength = strengths[strengths.size() / 2];
    for (EdgePoint& e : edges)
        e.used = e.strength >= 0.5 * medianStrength;
    BallCircle fitted = circle;
    for (int round = 0; round < 3; ++round) {
        if (!fitCircle(edges, fitted))
            return false;
        strengths.clear();
        for (const EdgePoint& e : edges)
            if (e.used)
                strengths.push_back(std::abs(e.residual));
        std::nth_element(strengths.begin(), strengths.begin() + strengths.size() / 2, strengths.end());
        const double limit = std::clamp(3.0 * 1.4826 * strengths[strengths.size() / 2], 0.5, kMaxRimScatter);
        for (EdgePoint& e : edges)
            e.used = e.used && std::abs(e.residual) <= limit;
    }
    if (!fitCircle(edges, fitted))
        return false;
    // A circle is confirmed when most rays agree on a clear rim and the fit stayed in the band.
    strengths.clear();
    for (const EdgePoint& e : edges)
        if (e.used)
            strengths.push_back(e.strength);
    if (strengths.size() < size_t(rays) / 3)
        return false;
    std::nth_element(strengths.begin(), strengths.begin() + strengths.size() / 2, strengths.end());
    if (strengths[strengths.size() / 2] < kMinRimContrast || rimAlignment(edges, fitted) < kMinRimAlignment || std::abs(fitted.radius - circle.radius) > window
        || std::hypot(fitted.centerX - circle.centerX, fitted.centerY - circle.centerY) > window)
        return false;
    circle = fitted;
    return true;
}

double LiveProbe::State::unwrap(const VideoFrame& frame, const BallCircle& circle)
{
    // Each probe pixel averages a grid of m × m bilinear samples of the decoded frame, m the
    // frame pixels a probe pixel spans: a box filter when the ball is large, plain bilinear when
    // it is small. Samples off the disc are left out, so the rim does not mix in the background.
    const int size = settings.probeSize;
    image.width = image.height = size;
    image.rgb.resize(size_t(size) * size_t(size) * 3);
    const int m = std::clamp(int(std::ceil(2 * circle.radius / size)), 1, kMaxSamplesPerAxis);
    const int width = frame.width, height = frame.height;
    const std::uint8_t* bgr = frame.bgr.data();
    const float gain = float(settings.clippedGain);
    // The frame's outermost pixel of the ball is partly background: samples there are pulled in
    // by kRimPullPixels (measured: the synthetic ball's SH error drops from 0.5 % to 0.1 %).
    const double rimLimit = std::max(0.0, 1.0 - kRimPullPixels / circle.radius);
    double luminanceSum = 0, clippedWeight = 0;
    long discPixels = 0, samplesTaken = 0;
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            double sum[3] = {0, 0, 0};
            int count = 0;
            for (int b = 0; b < m; ++b) {
                const double v = 1.0 - 2.0 * (j + (b + 0.5) / m) / size;
                for (int a = 0; a < m; ++a) {
                    const double u = -1.0 + 2.0 * (i + (a + 0.5) / m) / size;
                    const double rho2 = u * u + v * v;
                    if (rho2 > 1.0)
                        continue;
                    const double pull = rho2 > rimLimit * rimLimit ? rimLimit / std::sqrt(rho2) : 1.0;
                    // Pixel-centre coordinates of the frame point the disc point (u, v) shows.
                    const double x = std::clamp(circle.centerX + pull * u * circle.radius - 0.5, 0.0, double(width - 1));
                    const double y = std::clamp(circle.centerY - pull * v * circle.radius - 0.5, 0.0, double(height - 1));
                    const int x0 = int(x), y0 = int(y);
                    const int x1 = std::min(x0 + 1, width - 1), y1 = std::min(y0 + 1, height - 1);
                    const double tx = x - x0, ty = y - y0;
                    const int xs[4] = {x0, x1, x0, x1}, ys[4] = {y0, y0, y1, y1};
                    const double weights[4] = {(1 - tx) * (1 - ty), tx * (1 - ty), (1 - tx) * ty, tx * ty};
                    for (int corner = 0; corner < 4; ++corner) {
                        const std::uint8_t* p = bgr + 3 * (size_t(ys[corner]) * size_t(width) + size_t(xs[corner]));
                        double w = weights[corner];
                        if (std::max({p[0], p[1], p[2]}) >= kClippedLevel) {
                            clippedWeight += w;
                            w *= gain;
                        }
                        sum[0] += w * linearOf[p[2]];
                        sum[1] += w * linearOf[p[1]];
                        sum[2] += w * linearOf[p[0]];
                    }
                    ++count;
                }
            }
            float* out = image.rgb.data() + 3 * (size_t(j) * size_t(size) + size_t(i));
            for (int c = 0; c < 3; ++c)
                out[c] = count ? float(sum[c] / count) : 0.0f;
            samplesTaken += count;
            // The mirror ball's solid angle per image area is the same everywhere (4 on the unit
            // disc), so the plain mean over the disc is the mean radiance over the sphere.
            const double centreU = -1.0 + 2.0 * (i + 0.5) / size, centreV = 1.0 - 2.0 * (j + 0.5) / size;
            if (centreU * centreU + centreV * centreV <= 1.0) {
                luminanceSum += luminance(out);
                ++discPixels;
            }
        }
    clippedFraction = samplesTaken ? clippedWeight / double(samplesTaken) : 0.0;
    return discPixels ? luminanceSum / double(discPixels) : 0.0;
}

void LiveProbe::State::drawPicture()
{
    const int size = image.width;
    picture.width = picture.height = size;
    picture.rgba.resize(size_t(size) * size_t(size) * 4);
    for (int j = 0; j < size; ++j)
        for (int i = 0; i < size; ++i) {
            const size_t p = size_t(j) * size_t(size) + size_t(i);
            const float* in = image.rgb.data() + 3 * p;
            std::uint8_t* out = picture.rgba.data() + 4 * p;
            for (int c = 0; c < 3; ++c)
                out[c] = srgbOf[size_t(std::lround(std::clamp(in[c], 0.0f, 1.0f) * kEncodeSteps))];
            const double u = -1.0 + 2.0 * (i + 0.5) / size, v = 1.0 - 2.0 * (j + 0.5) / size;
            out[3] = u * u + v * v <= 1.0 ? 255 : 0;
        }
}

// ---- LiveProbe --------------------------------------------------------------------------------

LiveProbe::LiveProbe(std::unique_ptr<State> state) : m_state(std::move(state)) {}
LiveProbe::LiveProbe(LiveProbe&&) noexcept = default;
LiveProbe& LiveProbe::operator=(LiveProbe&&) noexcept = default;
LiveProbe::~LiveProbe() = default;

Result<LiveProbe> LiveProbe::create(const LiveProbeSettings& settings)
{
    if (auto valid = validateLiveProbeSettings(settings); !valid)
        return valid.error();
    auto projector = lighting::ProbeProjector::create(lighting::ProbeLayout::MirrorBall, settings.probeSize, settings.probeSize,
                                                      settings.order);
    if (!projector)
        return projector.error();
    auto state = std::make_unique<State>();
    state->settings = settings;
    state->projector = std::move(*projector);
    state->exposure = settings.exposure;
    for (int v = 0; v < 256; ++v)
        state->linearOf[size_t(v)] = float(decodeSrgb(v / 255.0));
    for (int k = 0; k <= kEncodeSteps; ++k)
        state->srgbOf[size_t(k)] = encodeSrgb(double(k) / kEncodeSteps);
    return LiveProbe(std::move(state));
}

Result<LiveProbe> LiveProbe::fromFile(const std::filesystem::path& path, lighting::ProbeLayout layout, int order)
{
    // The same job the scenario's probe goes through, so a file lights the AR scene exactly as
    // it lights the studio's.
    lighting::ProbeProjectionJob job;
    job.path = path;
    job.layout = layout;
    job.order = order;
    if (auto valid = job.validate(); !valid)
        return valid.error();
    JobContext context;
    if (auto ran = job.run(context); !ran)
        return ran.error();
    auto state = std::make_unique<State>();
    state->settings.order = order;
    state->fromBall = false;
    state->layout = layout;
    state->light = job.light;
    state->ball.reason = "The light comes from the probe file " + path.filename().string() + ", not from a ball.";
    state->picture = lighting::previewProbe(*job.probe, 256, 0, 1, lighting::previewExposure(*job.probe));
    state->image = job.probe->image();
    return LiveProbe(std::move(state));
}

bool LiveProbe::update(const VideoFrame& frame)
{
    State& s = *m_state;
    if (!s.fromBall || frame.empty())
        return false;
    const bool due = s.framesSeen % s.settings.updateEvery == 0;
    ++s.framesSeen;
    if (!due)
        return false;

    if (s.settings.location == BallLocation::Given) {
        if (auto inside = checkBallCircle(s.settings.givenCircle, frame.width, frame.height); !inside) {
            s.ball = {false, {}, inside.error().message};
            return false;
        }
        s.ball = {true, s.settings.givenCircle, {}};
    } else {
        s.ball = s.findBall(frame);
        if (!s.ball.found)
            return false;
    }

    const double meanLuminance = s.unwrap(frame, s.ball.circle);
    s.drawPicture();
    auto projected = s.projector->project(s.image, {}, 1); // one thread: the AR loop has its own
    if (!projected) {
        s.ball.reason = projected.error().message;
        return false;
    }

    // Time since the last processed frame; none, or not forward, starts the smoothing again.
    const double elapsed = frame.time - s.lastTime;
    const bool restart = !s.started || !(elapsed > 0);
    const auto blend = [&](double seconds) { return restart || seconds <= 0 ? 1.0 : 1.0 - std::exp(-elapsed / seconds); };
    if (s.settings.exposureMode == ProbeExposure::Fixed)
        s.exposure = s.settings.exposure;
    else if (meanLuminance > 1e-6) {
        // Smoothed in the logarithm: the eye and the camera's own exposure steps are ratios.
        const double target = std::log(s.settings.targetLuminance / meanLuminance);
        const double current = std::log(s.exposure);
        s.exposure = std::exp(current + blend(s.settings.exposureSmoothingSeconds) * (target - current));
    }
    const double alpha = blend(s.settings.smoothingSeconds);
    const int n = lighting::shCoefficientCount(s.settings.order);
    s.light.order = s.settings.order;
    for (int c = 0; c < 3; ++c)
        for (int i = 0; i < n; ++i) {
            double& value = s.light.channel[size_t(c)][size_t(i)];
            const double measured = s.exposure * projected->channel[size_t(c)][size_t(i)];
            value = restart ? measured : value + alpha * (measured - value);
        }
    s.lastTime = frame.time;
    s.started = true;
    return true;
}

void LiveProbe::reset()
{
    State& s = *m_state;
    if (!s.fromBall)
        return;
    s.light = {};
    s.ball = {};
    s.framesSeen = 0;
    s.started = false;
    s.exposure = s.settings.exposure;
    s.clippedFraction = 0;
}

bool LiveProbe::fromBall() const { return m_state->fromBall; }
const LiveProbeSettings& LiveProbe::settings() const { return m_state->settings; }
const lighting::ShRgb& LiveProbe::light() const { return m_state->light; }
const BallSighting& LiveProbe::ball() const { return m_state->ball; }
double LiveProbe::exposure() const { return m_state->exposure; }
double LiveProbe::clippedFraction() const { return m_state->clippedFraction; }
const lighting::HdrImage& LiveProbe::probeImage() const { return m_state->image; }
lighting::ProbeLayout LiveProbe::probeLayout() const { return m_state->layout; }
const lighting::PreviewImage& LiveProbe::picture() const { return m_state->picture; }

Result<lighting::LightProbe> LiveProbe::probe() const
{
    if (m_state->image.rgb.empty())
        return makeError(ErrorCode::InvalidArgument, "The live probe has no picture yet: no ball has been seen.");
    lighting::HdrImage exposed = m_state->image;
    if (m_state->fromBall)
        for (float& value : exposed.rgb)
            value *= float(m_state->exposure);
    return lighting::LightProbe::fromImage(std::move(exposed), m_state->layout);
}

} // namespace thespis::core::ar
