#include "ar/marker_synthesis.h"

#include <algorithm>
#include <array>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace thespis::core::ar {

namespace {

// A pixel crossed by an edge is sampled at 16 points, a rank-1 lattice that puts one in each row
// and each column of a 16 × 16 grid: an edge along x or y gets 16 steps of coverage, not 4.
constexpr int AreaSamples = 16;
constexpr int LatticeStep = 5;
constexpr int MaximumIterations = 12;
// Stop when no corner moves more than this (pixels).
constexpr double Converged = 0.01;
// The smear's derivative is taken over this step (pixels) of its vector.
constexpr double SmearStep = 0.25;
// A fit whose RMS residual exceeds this share of the marker's contrast is not this marker (a
// hand over it, a reflection): its corners are not used.
constexpr double MaximumResidual = 0.15;
// The fitted smear may grow this much over the estimate before the drawn patch runs short.
constexpr double SmearGrowth = 1.5;
constexpr double MinimumContrast = 20;
constexpr int DirectionSteps = 12;

// The smear as the taps of a correlation: each pixel's weight is the share of the centred segment
// `s` inside it (an exact box splat, continuous in `s`, so the smear can be differentiated).
struct Tap {
    int dx, dy;
    float weight;
};

std::vector<Tap> smearTaps(cv::Point2d s)
{
    const int radius = int(std::ceil(0.5 * std::max(std::abs(s.x), std::abs(s.y)) + 0.5));
    std::vector<Tap> taps;
    double total = 0;
    for (int y = -radius; y <= radius; ++y)
        for (int x = -radius; x <= radius; ++x) {
            double t0 = 0, t1 = 1; // Liang–Barsky clip of −s/2 + t s to the pixel
            const double from[2] = {-0.5 * s.x, -0.5 * s.y}, step[2] = {s.x, s.y}, centre[2] = {double(x), double(y)};
            for (int axis = 0; axis < 2 && t0 < t1; ++axis) {
                const double lo = centre[axis] - 0.5, hi = centre[axis] + 0.5;
                if (std::abs(step[axis]) < 1e-9) {
                    if (from[axis] < lo || from[axis] >= hi)
                        t1 = t0;
                    continue;
                }
                double a = (lo - from[axis]) / step[axis], b = (hi - from[axis]) / step[axis];
                if (a > b)
                    std::swap(a, b);
                t0 = std::max(t0, a), t1 = std::min(t1, b);
            }
            if (t1 > t0)
                taps.push_back({x, y, float(t1 - t0)}), total += t1 - t0;
        }
    for (Tap& tap : taps)
        tap.weight = float(tap.weight / total);
    return taps;
}

struct Model {
    cv::Matx33d homography; // marker cells → picture
    cv::Point2d smear;
    double dark = 0, contrast = 0;
};

class PatternFit {
public:
    PatternFit(const cv::Mat& grey, const MarkerPattern& pattern) : m_grey(grey), m_pattern(pattern) {}

    // The pixels fitted: inside the picture and inside the marker with its margin of white, far
    // enough in that what their area and the smear reach is all known. False when too few are.
    bool choosePixels(const cv::Matx33d& homography, float margin, cv::Point2d smear)
    {
        const double lo = -margin, hi = m_pattern.cells + margin;
        std::array<cv::Point2d, 4> quad;
        const double square[4][2] = {{lo, lo}, {hi, lo}, {hi, hi}, {lo, hi}};
        cv::Point2d centre(0, 0);
        for (int i = 0; i < 4; ++i) {
            const cv::Vec3d p = homography * cv::Vec3d(square[i][0], square[i][1], 1);
            if (p[2] <= 0)
                return false;
            quad[std::size_t(i)] = {p[0] / p[2], p[1] / p[2]};
            centre += 0.25 * quad[std::size_t(i)];
        }
        cv::Rect box = cv::boundingRect(std::vector<cv::Point2f>(quad.begin(), quad.end()));
        const cv::Rect picture(1, 1, m_grey.cols - 2, m_grey.rows - 2);
        const double reachAllowed = SmearGrowth * 0.5 * std::hypot(smear.x, smear.y);
        m_pixels.clear();
        int expected = 0;
        for (int y = box.y; y < box.y + box.height; ++y)
            for (int x = box.x; x < box.x + box.width; ++x) {
                bool inside = true;
                for (int e = 0; e < 4 && inside; ++e) {
                    const cv::Point2d a = quad[std::size_t(e)], b = quad[std::size_t((e + 1) % 4)];
                    cv::Point2d n(a.y - b.y, b.x - a.x);
                    n /= std::hypot(n.x, n.y);
                    if (n.dot(centre - a) < 0)
                        n = -n;
                    const double reach = 0.5 * (std::abs(n.x) + std::abs(n.y)) + reachAllowed + 0.5;
                    inside = n.dot(cv::Point2d(x, y) - a) >= reach;
                }
                if (!inside)
                    continue;
                ++expected;
                if (picture.contains({x, y}))
                    m_pixels.push_back({x, y});
            }
        if (m_pixels.empty() || m_pixels.size() < std::size_t(expected) * 9 / 10)
            return false;
        m_data = cv::boundingRect(m_pixels);
        m_radius = int(std::ceil(reachAllowed + 0.5));
        const int pad = m_radius + 1; // the kernel's reach, and one more for the gradient
        m_draw = cv::Rect(m_data.x - pad, m_data.y - pad, m_data.width + 2 * pad, m_data.height + 2 * pad);
        return true;
    }

    // Draws the model's pattern (each pixel's white share) and smears it into `blurred`; the sum
    // of squared residuals over the fitted pixels at the model's grey levels.
    double draw(const Model& model, cv::Mat& blurred)
    {
        drawCoverage(model.homography.inv());
        blurred = smeared(model.smear);
        return blurred.empty() ? HUGE_VAL : squaredResidual(model, blurred);
    }

    // The smear's direction as the edges' ramps give it is unsure (a square marker shows only
    // two edge directions): the model is smeared every 15° at `length`, and the best one kept,
    // with its grey levels.
    void chooseDirection(Model& model, cv::Mat& blurred, double length) const
    {
        double best = HUGE_VAL;
        for (int step = 0; step < DirectionSteps; ++step) {
            const double angle = CV_PI * step / DirectionSteps;
            Model trial = model;
            trial.smear = {length * std::cos(angle), length * std::sin(angle)};
            cv::Mat trialBlurred = smeared(trial.smear);
            if (trialBlurred.empty())
                continue;
            fitLevels(trial, trialBlurred);
            const double cost = squaredResidual(trial, trialBlurred);
            if (cost < best)
                best = cost, model = trial, blurred = trialBlurred;
        }
    }

    // The drawn pattern smeared, over the fitted pixels and one more round them (for the
    // gradient); empty when the smear reaches beyond what was drawn.
    cv::Mat smeared(cv::Point2d smear) const
    {
        const std::vector<Tap> taps = smearTaps(smear);
        cv::Mat out = cv::Mat::zeros(m_draw.size(), CV_32F);
        for (const Tap& tap : taps)
            if (std::max(std::abs(tap.dx), std::abs(tap.dy)) > m_radius)
                return {};
        const int x0 = m_data.x - 1 - m_draw.x, y0 = m_data.y - 1 - m_draw.y;
        for (int y = y0; y < y0 + m_data.height + 2; ++y) {
            float* row = out.ptr<float>(y);
            for (const Tap& tap : taps) {
                const float* source = m_coverage.ptr<float>(y + tap.dy) + tap.dx;
                for (int x = x0; x < x0 + m_data.width + 2; ++x)
                    row[x] += tap.weight * source[x];
            }
        }
        return out;
    }

    double squaredResidual(const Model& model, const cv::Mat& blurred) const
    {
        double sum = 0;
        for (const cv::Point& p : m_pixels) {
            const double r = m_grey.at<std::uint8_t>(p) - model.dark - model.contrast * at(blurred, p);
            sum += r * r;
        }
        return sum;
    }

    // The grey levels that fit best for the drawn pattern (linear least squares).
    void fitLevels(Model& model, const cv::Mat& blurred) const
    {
        double n = 0, sb = 0, sbb = 0, si = 0, sbi = 0;
        for (const cv::Point& p : m_pixels) {
            const double b = at(blurred, p), i = m_grey.at<std::uint8_t>(p);
            n += 1, sb += b, sbb += b * b, si += i, sbi += b * i;
        }
        const double det = n * sbb - sb * sb;
        if (det <= 0)
            return;
        model.contrast = (n * sbi - sb * si) / det;
        model.dark = (si - model.contrast * sb) / n;
    }

    float at(const cv::Mat& drawn, cv::Point p) const { return drawn.at<float>(p.y - m_draw.y, p.x - m_draw.x); }
    const std::vector<cv::Point>& pixels() const { return m_pixels; }
    cv::Point origin() const { return m_draw.tl(); }
    const cv::Mat& grey() const { return m_grey; }

private:
    // Each pixel's share of white: a pixel whose four corners fall on cells of one shade is that
    // shade; one an edge crosses is sampled at AreaSamples points.
    void drawCoverage(const cv::Matx33d& toMarker)
    {
        const int w = m_draw.width, h = m_draw.height, cells = m_pattern.cells;
        const auto shade = [&](double x, double y) -> float {
            const double z = toMarker(2, 0) * x + toMarker(2, 1) * y + toMarker(2, 2);
            const double u = (toMarker(0, 0) * x + toMarker(0, 1) * y + toMarker(0, 2)) / z;
            const double v = (toMarker(1, 0) * x + toMarker(1, 1) * y + toMarker(1, 2)) / z;
            if (u >= 0 && v >= 0 && u < cells && v < cells)
                return m_pattern.white[std::size_t(int(v) * cells + int(u))];
            return 1.f; // the paper round the marker
        };
        m_corners.resize(std::size_t((w + 1) * (h + 1)));
        for (int j = 0; j <= h; ++j)
            for (int i = 0; i <= w; ++i)
                m_corners[std::size_t(j * (w + 1) + i)] = shade(m_draw.x + i - 0.5, m_draw.y + j - 0.5);
        m_coverage.create(h, w, CV_32F);
        for (int j = 0; j < h; ++j) {
            float* row = m_coverage.ptr<float>(j);
            const float* top = &m_corners[std::size_t(j * (w + 1))];
            const float* bottom = top + (w + 1);
            for (int i = 0; i < w; ++i) {
                if (top[i] == top[i + 1] && top[i] == bottom[i] && top[i] == bottom[i + 1]) {
                    row[i] = top[i];
                    continue;
                }
                float sum = 0;
                for (int k = 0; k < AreaSamples; ++k)
                    sum += shade(m_draw.x + i - 0.5 + (k + 0.5) / AreaSamples,
                                 m_draw.y + j - 0.5 + ((k * LatticeStep) % AreaSamples + 0.5) / AreaSamples);
                row[i] = sum / AreaSamples;
            }
        }
    }

    const cv::Mat& m_grey;
    const MarkerPattern& m_pattern;
    std::vector<cv::Point> m_pixels;
    cv::Rect m_data, m_draw;
    int m_radius = 1;
    std::vector<float> m_corners;
    cv::Mat m_coverage;
};

// The four corners of the marker (cells → picture).
std::array<cv::Point2d, 4> cornersOf(const cv::Matx33d& homography, int cells)
{
    std::array<cv::Point2d, 4> out;
    const double square[4][2] = {{0, 0}, {double(cells), 0}, {double(cells), double(cells)}, {0, double(cells)}};
    for (int i = 0; i < 4; ++i) {
        const cv::Vec3d p = homography * cv::Vec3d(square[i][0], square[i][1], 1);
        out[std::size_t(i)] = {p[0] / p[2], p[1] / p[2]};
    }
    return out;
}

double largestMove(const std::array<cv::Point2d, 4>& a, const std::array<cv::Point2d, 4>& b)
{
    double most = 0;
    for (std::size_t i = 0; i < 4; ++i)
        most = std::max(most, std::hypot(a[i].x - b[i].x, a[i].y - b[i].y));
    return most;
}

} // namespace

bool alignMarkerPattern(const cv::Mat& grey, std::vector<cv::Point2f>& corners, const MarkerPattern& pattern,
                        float margin, const MotionBlur& blur, SmearDirection direction, MotionBlur* fitted,
                        CornerStart cornerStart)
{
    if (corners.size() != 4 || pattern.cells < 3 || pattern.white.size() != std::size_t(pattern.cells * pattern.cells))
        return false;
    const float cells = float(pattern.cells);
    const std::vector<cv::Point2f> square = {{0, 0}, {cells, 0}, {cells, cells}, {0, cells}};
    Model model;
    model.homography = cv::Matx33d(cv::getPerspectiveTransform(square, corners));
    model.smear = {blur.length * std::cos(blur.angle), blur.length * std::sin(blur.angle)};
    PatternFit fit(grey, pattern);
    if (!fit.choosePixels(model.homography, margin, model.smear))
        return false;
    // The homography is perturbed in the picture about the marker's middle, scaled to its size,
    // so that the eight parameters are of one magnitude.
    const std::array<cv::Point2d, 4> start = cornersOf(model.homography, pattern.cells);
    cv::Point2d middle(0, 0);
    double size = 1;
    for (const cv::Point2d& c : start)
        middle += 0.25 * c;
    for (const cv::Point2d& c : start)
        size = std::max(size, std::hypot(c.x - middle.x, c.y - middle.y));
    const cv::Matx33d normalise(1 / size, 0, -middle.x / size, 0, 1 / size, -middle.y / size, 0, 0, 1);
    const cv::Matx33d denormalise = normalise.inv();

    cv::Mat blurred, jacobian, residuals;
    fit.draw(model, blurred);
    if (direction == SmearDirection::Search)
        fit.chooseDirection(model, blurred, blur.length);
    else
        fit.fitLevels(model, blurred);
    double cost = fit.squaredResidual(model, blurred);
    constexpr int Parameters = 12; // homography 8, dark, contrast, smear 2
    double damping = 1e-4;
    bool converged = false;
    int steps = 0;
    for (int iteration = 0; iteration < MaximumIterations && !converged; ++iteration) {
        // The model's gradient in the picture stands for its derivative under a small warp (the
        // smear is nearly the same kernel after it); the smear's own by a finite step.
        const cv::Mat alongX = fit.smeared(model.smear + cv::Point2d(SmearStep, 0));
        const cv::Mat alongY = fit.smeared(model.smear + cv::Point2d(0, SmearStep));
        if (alongX.empty() || alongY.empty())
            return false; // the smear outgrew the patch drawn for it
        // One row of the Jacobian per pixel, then JᵀJ and Jᵀr in one product each.
        jacobian.create(int(fit.pixels().size()), Parameters, CV_64F);
        residuals.create(int(fit.pixels().size()), 1, CV_64F);
        const double k = -model.contrast * size;
        const std::size_t stride = blurred.step1();
        for (std::size_t i = 0; i < fit.pixels().size(); ++i) {
            const cv::Point p = fit.pixels()[i];
            const float* row = blurred.ptr<float>(p.y - fit.origin().y) + (p.x - fit.origin().x);
            const double b = row[0], gx = 0.5 * (row[1] - row[-1]);
            const double gy = 0.5 * (row[stride] - row[-std::ptrdiff_t(stride)]);
            const double x = (p.x - middle.x) / size, y = (p.y - middle.y) / size;
            const double wx = k * gx, wy = k * gy, radial = wx * x + wy * y;
            double* j = jacobian.ptr<double>(int(i));
            j[0] = wx * x, j[1] = wx * y, j[2] = wx, j[3] = wy * x, j[4] = wy * y, j[5] = wy;
            j[6] = -radial * x, j[7] = -radial * y, j[8] = 1, j[9] = b;
            j[10] = model.contrast * (fit.at(alongX, p) - b) / SmearStep;
            j[11] = model.contrast * (fit.at(alongY, p) - b) / SmearStep;
            residuals.at<double>(int(i)) = grey.at<std::uint8_t>(p) - model.dark - model.contrast * b;
        }
        cv::Mat normalMat, gradientMat;
        cv::mulTransposed(jacobian, normalMat, true);
        cv::gemm(jacobian, residuals, 1, cv::noArray(), 0, gradientMat, cv::GEMM_1_T);
        cv::Matx<double, Parameters, Parameters> normal(normalMat);
        const cv::Vec<double, Parameters> gradient(gradientMat);
        // A smear's slant within one row or column of pixels changes no pixel: a pixel's worth of
        // weight keeps the smear where it is along such flat directions.
        for (int i = 10; i < Parameters; ++i)
            normal(i, i) += model.contrast * model.contrast;
        // Levenberg–Marquardt: a step that does not lower the residual is retried shorter.
        bool improved = false;
        for (int attempt = 0; attempt < 6 && !improved; ++attempt) {
            cv::Matx<double, Parameters, Parameters> damped = normal;
            for (int i = 0; i < Parameters; ++i)
                damped(i, i) *= 1 + damping;
            cv::Vec<double, Parameters> step;
            if (!cv::solve(damped, gradient, step, cv::DECOMP_CHOLESKY))
                return false;
            const cv::Matx33d warp(1 + step[0], step[1], step[2], step[3], 1 + step[4], step[5], step[6], step[7], 1);
            Model next = model;
            next.homography = denormalise * warp * normalise * model.homography;
            next.dark += step[8], next.contrast += step[9];
            next.smear += cv::Point2d(step[10], step[11]);
            cv::Mat nextBlurred;
            const double nextCost = fit.draw(next, nextBlurred);
            if (nextCost < cost) {
                converged = largestMove(cornersOf(model.homography, pattern.cells),
                                        cornersOf(next.homography, pattern.cells)) < Converged;
                model = next, cost = nextCost, blurred = nextBlurred;
                damping = std::max(1e-6, damping / 4);
                improved = true;
                ++steps;
            } else {
                damping *= 8;
            }
        }
        if (!improved)
            converged = true; // nothing lowers the residual: at its minimum within the pixels' steps
    }
    const std::array<cv::Point2d, 4> end = cornersOf(model.homography, pattern.cells);
    double border = 1e9;
    for (std::size_t i = 0; i < 4; ++i)
        border = std::min(border, std::hypot(start[i].x - start[(i + 1) % 4].x, start[i].y - start[(i + 1) % 4].y) /
                                      pattern.cells);
    const double rms = std::sqrt(cost / double(fit.pixels().size()));
    // The corners may move as far as the smear reaches: a small marker's thresholded contour, where
    // they start, can be half the smear out (3 px for a 9-pixel smear over 5-pixel cells, issue 29).
    const double reach = std::max({1.5, 0.5 * border, 0.5 * std::hypot(model.smear.x, model.smear.y)});
    if (model.contrast < MinimumContrast || rms > MaximumResidual * model.contrast || largestMove(start, end) > reach ||
        (cornerStart == CornerStart::Predicted && steps == 0))
        return false;
    for (std::size_t i = 0; i < 4; ++i)
        corners[i] = cv::Point2f(float(end[i].x), float(end[i].y));
    if (fitted) {
        double angle = std::atan2(model.smear.y, model.smear.x);
        if (angle < 0)
            angle += CV_PI;
        if (angle >= CV_PI)
            angle -= CV_PI;
        *fitted = {std::hypot(model.smear.x, model.smear.y), angle};
    }
    return true;
}

} // namespace thespis::core::ar
