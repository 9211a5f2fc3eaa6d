#pragma once
// A camera looking at a board that moves as a hand-held one does, rendered with known poses: the
// ground truth the tracking tests and benchmarks measure against. It renders what makes real
// footage hard: sensor noise, motion blur over the exposure, a hand covering some markers, and a
// stretch where the board is hidden completely (lost, then found again).

#include <utility>

#include "ar/board.h"
#include "ar/camera_file.h"
#include "ar/frame_source.h"
#include "ar/pose.h"

namespace thespis::core::ar {

struct SyntheticScene {
    BoardSpec board;              ///< an aruco-grid, a charuco board or a chessboard
    CameraIntrinsics camera;      ///< its width, height and matrix (distortion is not rendered)
    double fps = 30;
    std::int64_t frames = 300;
    double nearest = 0.35, farthest = 0.6; ///< metres from the camera to the board's centre
    double noise = 2.0;           ///< sensor noise, standard deviation in grey levels
    double exposure = 0.5;        ///< of the frame time: the motion blur's length
    /// Frames [first, last) in which a hand covers part of the board (a third of its markers).
    std::pair<std::int64_t, std::int64_t> handOver{-1, -1};
    /// Frames [first, last) in which the board is covered completely.
    std::pair<std::int64_t, std::int64_t> hidden{-1, -1};
    unsigned seed = 1;
};

class SyntheticSource final : public FrameSource {
public:
    /// Errors: a scene that cannot be drawn (no frames, sizes not positive, a camera without
    /// focal lengths, distances out of order).
    static Result<std::unique_ptr<SyntheticSource>> create(const SyntheticScene& scene);
    ~SyntheticSource() override;

    std::string description() const override;
    Result<bool> read(VideoFrame& frame) override;
    double fps() const override;
    int width() const override;
    int height() const override;
    std::int64_t frameCount() const override;

    /// The board's true pose at a frame (board → camera, OpenCV's board frame).
    TargetPose truth(std::int64_t frame) const;
    /// Whether the board is visible enough to track at a frame (not hidden).
    bool visible(std::int64_t frame) const;
    const SyntheticScene& scene() const;

private:
    struct State;
    explicit SyntheticSource(std::unique_ptr<State> state);
    std::unique_ptr<State> m_state;
};

} // namespace thespis::core::ar
