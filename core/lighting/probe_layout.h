#pragma once
// Private to lighting's probe code (probe.cpp, probe_projector.cpp): what the layouts' pixel
// geometry and the projector's solid angles both need of a layout.

#include <numbers>

#include "lighting/probe.h"

namespace thespis::core::lighting {

inline constexpr double kPi = std::numbers::pi;

/// One cube face in the cross: its cell, and direction = centre + a·aAxis + b·bAxis for the face
/// coordinates a (image right) and b (image down) in [−1, 1].
struct CrossFace {
    int cellX, cellY;
    Vec3d centre, aAxis, bAxis;
};

/// The cube face at cell (cellX, cellY) of the vertical cross, or null for an empty cell.
const CrossFace* crossFaceAt(int cellX, int cellY);

/// InvalidArgument, for the user, when an image of width × height cannot hold `layout`.
Result<void> checkSize(ProbeLayout layout, int width, int height);

} // namespace thespis::core::lighting
