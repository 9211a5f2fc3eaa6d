#pragma once
// Footage of an ArUco grid as a camera's sensor sees it, made from OpenCV's primitives only, so
// that the tracker is not tested against renders it shares code with (issue 29): the board drawn
// by cv::aruco::GridBoard::draw, warped by cv::warpPerspective into a 4× finer frame and averaged
// down 4 × 4 (cv::INTER_AREA, as a pixel integrates light), a box smear by cv::filter2D on some
// frames, Gaussian noise, then 8 bits. Pixel centres sit at integer coordinates, OpenCV's rule,
// in every image. A point-sampled warp would alias the thin marker borders by up to half a pixel.
// Ported from the study's generator (/work/exp29/src/gen.cpp): the same poses, frame by frame,
// for the same settings and seed.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include <opencv2/aruco.hpp>
#include <opencv2/imgproc.hpp>

#include "ar/camera_file.h"
#include "ar/pose.h"
#include "ar/video_frame.h"

namespace thespis::test {

struct SensorFootageSettings {
    int frames = 300;
    int width = 640, height = 480;
    double fx = 600;          ///< = fy; the principal point is the picture's centre; no distortion
    double smear = 7;         ///< pixels; 0: none
    double smearAngle = 0;    ///< degrees from the picture's x towards its y
    int smearEvery = 10;      ///< frames i with i % smearEvery in smearPhases are smeared
    std::vector<int> smearPhases{3, 8};
    double nearest = 0.35, farthest = 0.6; ///< metres from the camera to the board's centre
    double yaw = 45, pitch = 40;           ///< degrees, at most
    double noise = 3;                      ///< grey levels, σ
    int seed = 1;
};

class SensorFootage {
public:
    // The board: DICT_4X4_50, 4 × 3 markers of 4 cm, 1 cm apart (thespis board
    // "aruco-grid:DICT_4X4_50:4x3:0.04:0.01"), in OpenCV 4.6's frame: x right, y down the print.
    static constexpr const char* BoardSpec = "aruco-grid:DICT_4X4_50:4x3:0.04:0.01";

    struct Frame {
        cv::Mat grey;               ///< 8 bits
        core::ar::TargetPose truth; ///< board → camera
        bool smeared = false;
    };

    explicit SensorFootage(SensorFootageSettings settings) : m_settings(std::move(settings)), m_rng(uint64(m_settings.seed))
    {
        board = cv::aruco::GridBoard::create(4, 3, 0.04f, 0.01f,
                                             cv::aruco::getPredefinedDictionary(cv::aruco::DICT_4X4_50));
        // Drawn at 12 000 px/m with a 1 cm white margin: a marker's 6 cells are then 80 print
        // pixels each. At 10 000 px/m (66⅔ each) drawMarker rounds the inner cells' edges to whole
        // print pixels, up to 33 µm off: a misprinted board, which the fit of the whole pattern
        // (marker_synthesis.h) reads as a pose error of 0.01° on smeared frames. draw() puts board
        // point (X, Y) at pixel corner coordinates (margin + X s, margin + Y s): pixel centres half
        // a pixel less.
        cv::Mat drawn;
        board->draw(cv::Size(int(BoardWidth * Scale + 2 * Margin), int(BoardHeight * Scale + 2 * Margin)), drawn,
                    int(Margin), 1);
        drawn.convertTo(m_print, CV_32F, (Paper - Ink) / 255.0, Ink);
        if (m_settings.smear > 0)
            m_kernel = smearKernel(m_settings.smear, m_settings.smearAngle);
    }

    core::ar::CameraIntrinsics camera() const
    {
        core::ar::CameraIntrinsics c;
        c.width = m_settings.width;
        c.height = m_settings.height;
        const double cx = (m_settings.width - 1) / 2.0, cy = (m_settings.height - 1) / 2.0;
        c.matrix = {m_settings.fx, 0, cx, 0, m_settings.fx, cy, 0, 0, 1};
        return c;
    }
    cv::Matx33d cameraMatrix() const
    {
        const auto& m = camera().matrix;
        return cv::Matx33d(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7], m[8]);
    }
    int frames() const { return m_settings.frames; }

    /// Frame `i`; frames must be asked for in order (the noise is drawn frame after frame).
    Frame render(int i)
    {
        const SensorFootageSettings& s = m_settings;
        const double deg = CV_PI / 180, u = double(i) / std::max(1, s.frames - 1);
        const double d = 0.5 * (s.nearest + s.farthest) + 0.5 * (s.farthest - s.nearest) * std::sin(2 * CV_PI * 1.3 * u + 0.4);
        const double yaw = s.yaw * std::sin(2 * CV_PI * u) * deg;
        const double pitch = s.pitch * (0.5 - 0.5 * std::cos(2 * CV_PI * 1.7 * u)) * deg;
        const double roll = 8 * std::sin(2 * CV_PI * 0.8 * u + 1.0) * deg;
        const cv::Matx33d ry(std::cos(yaw), 0, std::sin(yaw), 0, 1, 0, -std::sin(yaw), 0, std::cos(yaw));
        const cv::Matx33d rx(1, 0, 0, 0, std::cos(pitch), -std::sin(pitch), 0, std::sin(pitch), std::cos(pitch));
        const cv::Matx33d rz(std::cos(roll), -std::sin(roll), 0, std::sin(roll), std::cos(roll), 0, 0, 0, 1);
        const cv::Matx33d r = rz * rx * ry;
        const cv::Vec3d centre(0.025 * std::sin(2 * CV_PI * 1.1 * u), 0.02 * std::sin(2 * CV_PI * 0.7 * u + 0.5), d);
        const cv::Vec3d t = centre - r * cv::Vec3d(BoardWidth / 2, BoardHeight / 2, 0);
        Frame frame;
        frame.smeared = s.smear > 0 && std::find(s.smearPhases.begin(), s.smearPhases.end(), i % s.smearEvery) !=
                                           s.smearPhases.end();
        // Board (X, Y, 1) → the fine frame's pixel index: a low-res pixel centre x is the fine
        // index 4x + 1.5 (pixel i covers [i − ½, i + ½), fine pixel 4i + k has its centre at
        // i − ½ + (k + ½) / 4).
        const cv::Matx33d printToBoard = cv::Matx33d(Scale, 0, Margin - 0.5, 0, Scale, Margin - 0.5, 0, 0, 1).inv();
        const cv::Matx33d lowToFine(4, 0, 1.5, 0, 4, 1.5, 0, 0, 1);
        const cv::Matx33d plane(r(0, 0), r(0, 1), t[0], r(1, 0), r(1, 1), t[1], r(2, 0), r(2, 1), t[2]);
        const cv::Matx33d homography = lowToFine * cameraMatrix() * plane * printToBoard;
        cv::warpPerspective(m_print, m_fine, cv::Mat(homography), cv::Size(4 * s.width, 4 * s.height), cv::INTER_LINEAR,
                            cv::BORDER_CONSTANT, cv::Scalar(Background));
        cv::resize(m_fine, m_low, cv::Size(s.width, s.height), 0, 0, cv::INTER_AREA);
        if (frame.smeared)
            cv::filter2D(m_low, m_low, -1, m_kernel, cv::Point(-1, -1), 0, cv::BORDER_REPLICATE);
        m_noise.create(m_low.size(), CV_32F);
        m_rng.fill(m_noise, cv::RNG::NORMAL, 0, s.noise);
        m_low += m_noise;
        m_low.convertTo(frame.grey, CV_8U); // rounds and saturates
        cv::Vec3d rotation;
        cv::Rodrigues(r, rotation);
        frame.truth = {{rotation[0], rotation[1], rotation[2]}, {t[0], t[1], t[2]}};
        return frame;
    }

    /// The grey frame as the tracker takes it (BGR), at 30 frames a second.
    static core::ar::VideoFrame videoFrame(const cv::Mat& grey, int index)
    {
        core::ar::VideoFrame frame;
        frame.resize(grey.cols, grey.rows);
        cv::Mat bgr(grey.rows, grey.cols, CV_8UC3, frame.bgr.data());
        cv::cvtColor(grey, bgr, cv::COLOR_GRAY2BGR);
        frame.index = index;
        frame.time = index / 30.0;
        frame.captured = std::chrono::steady_clock::now();
        return frame;
    }

    cv::Ptr<cv::aruco::GridBoard> board;

private:
    static constexpr double Scale = 12000, Margin = 120, BoardWidth = 0.19, BoardHeight = 0.14;
    static constexpr double Ink = 25, Paper = 230, Background = 110;

    // A box `length` pixels long along `degrees`, symmetric about the pixel, drawn 8× finer so any
    // direction works, normalised.
    static cv::Mat smearKernel(double length, double degrees)
    {
        const int n = int(std::ceil(length)) | 1;
        cv::Mat fine = cv::Mat::zeros(n * 8, n * 8, CV_32F), kernel;
        const double c = (n * 8 - 1) / 2.0, dx = std::cos(degrees * CV_PI / 180), dy = std::sin(degrees * CV_PI / 180);
        for (int j = 0; j <= 4000; ++j) {
            const double along = (j / 4000.0 - 0.5) * length * 8;
            const int x = int(std::lround(c + along * dx)), y = int(std::lround(c + along * dy));
            if (x >= 0 && y >= 0 && x < n * 8 && y < n * 8)
                fine.at<float>(y, x) += 1;
        }
        cv::resize(fine, kernel, cv::Size(n, n), 0, 0, cv::INTER_AREA);
        return kernel / cv::sum(kernel)[0];
    }

    SensorFootageSettings m_settings;
    cv::RNG m_rng;
    cv::Mat m_print, m_kernel, m_fine, m_low, m_noise;
};

} // namespace thespis::test
