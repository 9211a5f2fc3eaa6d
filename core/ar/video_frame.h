#pragma once
// One picture from a camera, a video or a synthetic source, as every stage of the AR loop passes
// it on: 8-bit BGR (OpenCV's order), rows from the top, with when it was taken. Frames are values;
// the capture thread swaps them rather than copying, so their buffers are reused (no allocation
// per frame once the loop runs).

#include <chrono>
#include <cstdint>
#include <vector>

namespace thespis::core::ar {

struct VideoFrame {
    int width = 0, height = 0;
    std::vector<std::uint8_t> bgr;  ///< width × height × 3 bytes
    std::int64_t index = -1;        ///< 0, 1, … in the source's order; −1: no frame
    double time = 0;                ///< seconds on the source's own clock (a video's timestamp)
    std::chrono::steady_clock::time_point captured; ///< when it reached us, for latency

    bool empty() const { return index < 0 || bgr.empty(); }
    /// Sizes the buffer for width × height (keeping its memory when it is large enough).
    void resize(int newWidth, int newHeight)
    {
        width = newWidth;
        height = newHeight;
        bgr.resize(std::size_t(newWidth) * std::size_t(newHeight) * 3);
    }
};

} // namespace thespis::core::ar
