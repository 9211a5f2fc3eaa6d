#pragma once
// Private to thespis.ar's bindings (bind_ar.cpp, bind_ar_live.cpp): how their arguments become
// core values. Defined in bind_ar.cpp.

#include "ar/board.h"
#include "ar/camera_file.h"
#include "ar/video_frame.h"
#include "bind_common.h"

namespace thespis::python {

/// A (height, width, 3) uint8 BGR array copied into a frame.
core::ar::VideoFrame frameFromArray(const py::handle& image);
/// A VideoFrame as it is, or an array copied into `storage`.
const core::ar::VideoFrame& frameArgument(const py::handle& frame, core::ar::VideoFrame& storage);
/// A Board or its text.
core::ar::BoardSpec boardArgument(const py::handle& board);
/// CameraIntrinsics or a camera file's path.
core::ar::CameraIntrinsics cameraArgument(const py::handle& camera);
/// The live half of thespis.ar (bind_ar_live.cpp).
void bindArLive(py::module_& a);

} // namespace thespis::python
