// Bindings of core/ar as the submodule thespis.ar (paper §7): boards and camera files, frames as
// NumPy images, poses, marker and picture trackers, the tracking session, and the calibrate and
// track jobs the CLI runs. Sources, the live capture, the video writer and the live light probe
// are bound in bind_ar_live.cpp.
//
// Frames: a VideoFrame owns its 8-bit BGR pixels (OpenCV's order, rows from the top) with its index
// and time. `VideoFrame(image)` copies a (height, width, 3) uint8 array in; `frame.image` is a
// view of the frame's own pixels (no copy; it keeps the frame alive). Every function that takes a
// frame also takes such an array (copied). Poses are Rodrigues vectors and metres, target → camera.
// Long calls (tracking a frame, detecting markers, the jobs) release the GIL; an object used from
// several threads serialises its calls on its own mutex, taken after the GIL is released.

#include <atomic>
#include <cmath>
#include <cstring>
#include <limits>
#include <mutex>
#include <optional>
#include <unistd.h>

#include "ar/board.h"
#include "ar/calibrate_job.h"
#include "ar/camera_file.h"
#include "ar/frame_source.h"
#include "ar/marker_tracker.h"
#include "ar/planar_tracker.h"
#include "ar/pose.h"
#include "ar/track_job.h"
#include "ar/tracking_session.h"
#include "ar/tracking_target.h"
#include "ar/video_frame.h"
#include <pybind11/operators.h>

#include "bind_ar.h"
#include "bind_common.h"
#include "errors.h"
#include "run_job.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace ar = core::ar;


ar::VideoFrame frameFromArray(const py::handle& image)
{
    const char* expected = "A frame is a thespis.ar.VideoFrame or a numpy.ndarray shaped (height, width, 3) of uint8 BGR.";
    if (!py::isinstance<py::buffer>(image))
        throw py::type_error(expected);
    const py::array any = py::array::ensure(image);
    if (!any)
        throw py::type_error(expected);
    if (any.ndim() != 3 || any.shape(2) != 3 || !py::isinstance<py::array_t<std::uint8_t>>(any)) {
        std::string shape;
        for (py::ssize_t d = 0; d < any.ndim(); ++d)
            shape += (d ? ", " : "") + std::to_string(any.shape(d));
        throw py::value_error("A frame must be a (height, width, 3) uint8 BGR array, not (" + shape + ") of " +
                              py::str(any.dtype()).cast<std::string>() + ".");
    }
    if (any.shape(0) < 1 || any.shape(1) < 1)
        throw py::value_error("A frame needs at least one pixel.");
    const auto pixels = py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>::ensure(any);
    ar::VideoFrame frame;
    frame.resize(int(any.shape(1)), int(any.shape(0)));
    std::memcpy(frame.bgr.data(), pixels.data(), frame.bgr.size());
    frame.index = 0;
    frame.captured = std::chrono::steady_clock::now();
    return frame;
}

const ar::VideoFrame& frameArgument(const py::handle& frame, ar::VideoFrame& storage)
{
    if (py::isinstance<ar::VideoFrame>(frame)) {
        const auto& given = frame.cast<const ar::VideoFrame&>();
        if (given.empty())
            throw py::value_error("The frame is empty (no pixels, or index −1).");
        return given;
    }
    storage = frameFromArray(frame);
    return storage;
}

ar::BoardSpec boardArgument(const py::handle& board)
{
    if (py::isinstance<py::str>(board))
        return unwrap(ar::parseBoard(board.cast<std::string>()));
    if (py::isinstance<ar::BoardSpec>(board))
        return board.cast<ar::BoardSpec>();
    throw py::type_error("A board is a thespis.ar.Board or its text (\"charuco:DICT_6X6_250:5x7:0.04:0.02\").");
}

ar::CameraIntrinsics cameraArgument(const py::handle& camera)
{
    if (py::isinstance<ar::CameraIntrinsics>(camera))
        return camera.cast<ar::CameraIntrinsics>();
    const auto path = camera.cast<std::filesystem::path>(); // str or os.PathLike; TypeError otherwise
    return unwrap(withoutGil([&] { return ar::readCameraFile(path); }));
}

namespace {

py::array_t<double> vector3(const std::array<double, 3>& v) { return toArray<double>(std::span<const double>(v)); }

// A tracker Python holds; sessions reach it through SharedTracker, so the Python object stays
// usable (estimate, markers) and one mutex serialises both.
struct TrackerHandle {
    std::unique_ptr<ar::Tracker> tracker;
    std::string description;
    std::mutex mutex;
};

class SharedTracker final : public ar::Tracker {
public:
    explicit SharedTracker(std::shared_ptr<TrackerHandle> handle) : m_handle(std::move(handle)) {}
    std::string description() const override { return m_handle->description; }
    ar::TrackerEstimate estimate(const ar::VideoFrame& frame) override
    {
        std::lock_guard lock(m_handle->mutex);
        return m_handle->tracker->estimate(frame);
    }
    void reset() override
    {
        std::lock_guard lock(m_handle->mutex);
        m_handle->tracker->reset();
    }
    ar::TargetGeometry geometry() const override
    {
        std::lock_guard lock(m_handle->mutex);
        return m_handle->tracker->geometry();
    }

private:
    std::shared_ptr<TrackerHandle> m_handle;
};

struct SessionHandle {
    SessionHandle(std::shared_ptr<TrackerHandle> t, const ar::PoseFilterSettings& settings, bool filter)
        : tracker(t), session(std::make_unique<SharedTracker>(std::move(t)), settings, filter)
    {
    }
    std::shared_ptr<TrackerHandle> tracker;
    ar::TrackingSession session;
    std::mutex mutex;
    std::int64_t next = 0; // the index given to the next frame passed as an array
};

struct TrackResult {
    std::vector<ar::TrackedFrame> frames;
    ar::TrackingSession::Statistics statistics;
    std::string tracker;
};

struct Calibration {
    ar::CameraIntrinsics camera;
    std::array<double, 4> deviations{};
    std::vector<ar::CalibrateJob::View> views;
};

// A camera given as intrinsics is written for TrackJob (which reads a file) and removed after.
class TemporaryCameraFile {
public:
    std::filesystem::path write(const ar::CameraIntrinsics& camera)
    {
        static std::atomic<int> counter{0};
        m_path = std::filesystem::temp_directory_path() /
                 ("thespis-camera-" + std::to_string(::getpid()) + "-" + std::to_string(counter++) + ".yml");
        unwrap(ar::writeCameraFile(m_path, camera));
        return m_path;
    }
    ~TemporaryCameraFile()
    {
        std::error_code ignored;
        if (!m_path.empty())
            std::filesystem::remove(m_path, ignored);
    }

private:
    std::filesystem::path m_path;
};

py::list markerList(const std::vector<ar::DetectedMarker>& markers)
{
    py::list out;
    for (const ar::DetectedMarker& marker : markers) {
        py::array_t<double> corners({4, 2});
        for (int c = 0; c < 4; ++c)
            for (int k = 0; k < 2; ++k)
                *corners.mutable_data(c, k) = marker.corners[std::size_t(c)][std::size_t(k)];
        out.append(py::make_tuple(marker.id, corners));
    }
    return out;
}

py::object poseOrNone(const ar::TrackedFrame& f) { return f.hasPose ? py::cast(f.pose) : py::none(); }

void bindBoardsAndCameras(py::module_& a)
{
    py::enum_<ar::BoardKind>(a, "BoardKind")
        .value("chessboard", ar::BoardKind::Chessboard)
        .value("aruco_grid", ar::BoardKind::ArucoGrid)
        .value("charuco", ar::BoardKind::Charuco);
    py::class_<ar::BoardSpec>(a, "Board",
                              "A calibration or tracking target, as its text says: chessboard:COLSxROWS:SQUARE, "
                              "aruco-grid:DICT:COLSxROWS:MARKER:GAP or charuco:DICT:COLSxROWS:SQUARE:MARKER[:inverted] "
                              "(metres). Functions that take a board also take its text.")
        .def(py::init([](const std::string& text) { return unwrap(ar::parseBoard(text)); }), "text"_a,
             "Parses a board's text (ValueError naming the wrong part).")
        .def_readwrite("kind", &ar::BoardSpec::kind)
        .def_readwrite("dictionary", &ar::BoardSpec::dictionary, "ArUco dictionary (DICT_6X6_250 …); '' for a chessboard.")
        .def_readwrite("columns", &ar::BoardSpec::columns)
        .def_readwrite("rows", &ar::BoardSpec::rows)
        .def_readwrite("square", &ar::BoardSpec::square, "Square side (m); an ArUco grid's marker side.")
        .def_readwrite("second", &ar::BoardSpec::second, "ChArUco: the marker side (m); ArUco grid: the gap (m).")
        .def_readwrite("inverted", &ar::BoardSpec::inverted, "A ChArUco board printed white on black.")
        .def_property_readonly("marker_count", [](const ar::BoardSpec& b) { return ar::boardMarkerCount(b); })
        .def(
            "chessboard_corners",
            [](const ar::BoardSpec& b) {
                const auto corners = ar::chessboardCorners(b);
                py::array_t<double> out({py::ssize_t(corners.size()), py::ssize_t(3)});
                for (std::size_t i = 0; i < corners.size(); ++i)
                    for (std::size_t k = 0; k < 3; ++k)
                        *out.mutable_data(py::ssize_t(i), py::ssize_t(k)) = corners[i][k];
                return out;
            },
            "A chessboard's inner corners in its plane (z = 0), row after row, metres: shape (N, 3).")
        .def(py::self == py::self)
        .def("__str__", &ar::formatBoard)
        .def("__repr__", [](const ar::BoardSpec& b) { return "thespis.ar.Board('" + ar::formatBoard(b) + "')"; });
    a.def("parse_board", [](const std::string& text) { return unwrap(ar::parseBoard(text)); }, "text"_a,
          "A board from its text; ValueError says which part is wrong.");
    a.def("format_board", [](const py::object& board) { return ar::formatBoard(boardArgument(board)); }, "board"_a,
          "The text parse_board reads back.");
    a.def("dictionary_size", [](const std::string& name) { return ar::arucoDictionarySize(name); }, "name"_a,
          "How many markers a predefined ArUco dictionary holds (0 for a name OpenCV does not have).");

    py::class_<ar::CameraIntrinsics>(a, "CameraIntrinsics",
                                     "A calibrated camera: image size, 3 × 3 matrix, distortion (OpenCV's order).")
        .def(py::init([](int width, int height, std::optional<std::array<double, 9>> matrix, std::optional<double> fx,
                         std::optional<double> fy, std::optional<double> cx, std::optional<double> cy,
                         std::vector<double> distortion, double reprojectionError) {
                 ar::CameraIntrinsics c;
                 c.width = width;
                 c.height = height;
                 if (matrix)
                     c.matrix = *matrix;
                 else if (fx)
                     c.matrix = {*fx, 0, cx.value_or(0.5 * width), 0, fy.value_or(*fx), cy.value_or(0.5 * height), 0, 0, 1};
                 c.distortion = std::move(distortion);
                 c.reprojectionError = reprojectionError;
                 return c;
             }),
             "width"_a = 0, "height"_a = 0, py::kw_only(), "matrix"_a = py::none(), "fx"_a = py::none(),
             "fy"_a = py::none(), "cx"_a = py::none(), "cy"_a = py::none(), "distortion"_a = std::vector<double>{},
             "reprojection_error"_a = -1.0,
             "matrix: 9 numbers row by row (or a 3 × 3 array); or fx (fy = fx, cx, cy the image's centre by default).")
        .def_readwrite("width", &ar::CameraIntrinsics::width)
        .def_readwrite("height", &ar::CameraIntrinsics::height)
        .def_property(
            "matrix",
            [](const ar::CameraIntrinsics& c) { return toArray<double>(std::span<const double>(c.matrix), {3, 3}); },
            [](ar::CameraIntrinsics& c, const py::array_t<double, py::array::c_style | py::array::forcecast>& m) {
                if (m.size() != 9)
                    throw py::value_error("A camera matrix has 3 × 3 numbers.");
                std::copy_n(m.data(), 9, c.matrix.begin());
            },
            "fx 0 cx / 0 fy cy / 0 0 1 as a 3 × 3 float64 array (a copy; assign to change it).")
        .def_property(
            "distortion", [](const ar::CameraIntrinsics& c) { return toArray<double>(std::span<const double>(c.distortion)); },
            [](ar::CameraIntrinsics& c, std::vector<double> d) { c.distortion = std::move(d); },
            "k1 k2 p1 p2 [k3 …] as a float64 array (a copy).")
        .def_readwrite("reprojection_error", &ar::CameraIntrinsics::reprojectionError, "RMS px; −1 when unknown.")
        .def_property_readonly("fx", &ar::CameraIntrinsics::fx)
        .def_property_readonly("fy", &ar::CameraIntrinsics::fy)
        .def_property_readonly("cx", &ar::CameraIntrinsics::cx)
        .def_property_readonly("cy", &ar::CameraIntrinsics::cy)
        .def(py::self == py::self)
        .def("__repr__", [](const ar::CameraIntrinsics& c) {
            return "<thespis.ar.CameraIntrinsics " + std::to_string(c.width) + "×" + std::to_string(c.height) +
                   " fx=" + std::to_string(c.fx()) + " fy=" + std::to_string(c.fy()) + ">";
        });
    a.def("read_camera_file",
          [](const std::filesystem::path& path) { return unwrap(withoutGil([&] { return ar::readCameraFile(path); })); }, "path"_a,
          "Reads OpenCV's camera YAML / XML / JSON (errors name the file and the field).");
    a.def("parse_camera_file",
          [](const std::string& text, const std::string& name) { return unwrap(ar::parseCameraFile(text, name)); },
          "text"_a, "name"_a = "camera file", "The same from text (`name` in messages).");
    a.def("write_camera_file",
          [](const std::filesystem::path& path, const ar::CameraIntrinsics& c) { unwrap(ar::writeCameraFile(path, c)); },
          "path"_a, "camera"_a, "Writes OpenCV's YAML, atomically.");
    a.def("format_camera_file", &ar::encodeCameraFile, "camera"_a, "The YAML write_camera_file writes.");
}

void bindFramesAndPoses(py::module_& a)
{
    py::class_<ar::VideoFrame>(a, "VideoFrame",
                               "One picture: 8-bit BGR (OpenCV's order), rows from the top, with its index and its "
                               "time (seconds on the source's clock). VideoFrame(image) copies the array in; `image` "
                               "is a view of the frame's pixels (no copy); numpy.asarray(frame) gives that view too.")
        .def(py::init([](const py::handle& image, std::int64_t index, double time) {
                 if (index < 0)
                     throw py::value_error("A frame's index is 0 or more.");
                 ar::VideoFrame frame = frameFromArray(image);
                 frame.index = index;
                 frame.time = time;
                 return frame;
             }),
             "image"_a, "index"_a = 0, "time"_a = 0.0)
        .def_property_readonly("image",
                               [](py::object self) {
                                   auto& f = self.cast<ar::VideoFrame&>();
                                   return py::array_t<std::uint8_t>({f.height, f.width, 3}, f.bgr.data(), self);
                               })
        .def(
            "__array__",
            [](py::object self, const py::object& dtype, const py::object& copy) {
                py::object view = self.attr("image");
                if (!dtype.is_none())
                    return view.attr("astype")(dtype);
                return !copy.is_none() && copy.cast<bool>() ? view.attr("copy")() : view;
            },
            "dtype"_a = py::none(), "copy"_a = py::none())
        .def_readonly("width", &ar::VideoFrame::width)
        .def_readonly("height", &ar::VideoFrame::height)
        .def_property(
            "index", [](const ar::VideoFrame& f) { return f.index; },
            [](ar::VideoFrame& f, std::int64_t index) {
                if (index < 0)
                    throw py::value_error("A frame's index is 0 or more.");
                f.index = index;
            })
        .def_readwrite("time", &ar::VideoFrame::time)
        .def("copy", [](const ar::VideoFrame& f) { return f; }, "A frame with its own copy of the pixels.")
        .def("__repr__", [](const ar::VideoFrame& f) {
            return "<thespis.ar.VideoFrame " + std::to_string(f.index) + " " + std::to_string(f.width) + "×" +
                   std::to_string(f.height) + " at " + std::to_string(f.time) + " s>";
        });
    a.def("read_picture", [](const std::filesystem::path& p) { return unwrap(withoutGil([&] { return ar::readPicture(p); })); },
          "path"_a, "A picture file as a frame (index 0, time 0); errors name the file.");
    a.def(
        "write_picture",
        [](const std::filesystem::path& path, const py::object& frame) {
            ar::VideoFrame storage;
            const ar::VideoFrame& f = frameArgument(frame, storage);
            unwrap(withoutGil([&] { return ar::writePicture(path, f); }));
        },
        "path"_a, "frame"_a, "Writes a frame (or a BGR array) as PNG, JPEG, … by the extension.");

    py::class_<ar::TargetPose>(a, "Pose", "Target → camera: `rvec` a Rodrigues vector (rad), `tvec` metres "
                                          "(x right, y down, z forward).")
        .def(py::init([](const std::array<double, 3>& rvec, const std::array<double, 3>& tvec) {
                 return ar::TargetPose{rvec, tvec};
             }),
             "rvec"_a = std::array<double, 3>{}, "tvec"_a = std::array<double, 3>{})
        .def_property_readonly("rvec", [](const ar::TargetPose& p) { return vector3(p.rotation); })
        .def_property_readonly("tvec", [](const ar::TargetPose& p) { return vector3(p.translation); })
        .def("to_camera", [](const ar::TargetPose& p, const std::array<double, 3>& point) { return vector3(ar::toCamera(p, point)); },
             "point"_a, "A point of the target (metres) in the camera's frame.")
        .def(py::self == py::self)
        .def("__repr__", [](const ar::TargetPose& p) {
            return py::str("Pose(rvec={}, tvec={})").format(py::cast(p.rotation), py::cast(p.translation)).cast<std::string>();
        });
    a.def("rotation_difference", &ar::rotationDifference, "a"_a, "b"_a, "The angle (rad) between two poses' rotations.");
    a.def("translation_difference", &ar::translationDifference, "a"_a, "b"_a, "The distance (m) between two poses' origins.");
}

void bindTracking(py::module_& a)
{
    py::class_<ar::TrackerEstimate>(a, "Estimate", "One frame's own estimate, before the temporal filter.")
        .def_readonly("found", &ar::TrackerEstimate::found)
        .def_readonly("pose", &ar::TrackerEstimate::pose)
        .def_readonly("features", &ar::TrackerEstimate::features, "Markers, ChArUco corners or matched points used.")
        .def_readonly("reprojection_error", &ar::TrackerEstimate::reprojectionError, "RMS px; −1 when not found.")
        .def_property_readonly(
            "blur", [](const ar::TrackerEstimate& e) { return py::make_tuple(e.blur.length, e.blur.angle); },
            "The frame's motion blur on the target's edges: (length px, direction rad from x towards y); "
            "(0, 0) sharp or not a marker board.")
        .def_readonly("ambiguity", &ar::TrackerEstimate::ambiguity,
                      "IPPE's worse pose's RMS error over the better one's (0: one pose); below 3 the tilt is unsure.")
        .def_property_readonly(
            "information",
            [](const ar::TrackerEstimate& e) { return toArray<double>(std::span<const double>(e.information), {6, 6}); },
            "The pose's information matrix over [translation (m), rotation (rad)], 6 × 6.");

    py::class_<TrackerHandle, std::shared_ptr<TrackerHandle>>(a, "Tracker", "Finds a board or a picture in frames (make_tracker).")
        .def_readonly("description", &TrackerHandle::description)
        .def(
            "estimate",
            [](TrackerHandle& h, const py::object& frame) {
                ar::VideoFrame storage;
                const ar::VideoFrame& f = frameArgument(frame, storage);
                py::gil_scoped_release release;
                std::lock_guard lock(h.mutex);
                return h.tracker->estimate(f);
            },
            "frame"_a, "The frame's own estimate (VideoFrame or BGR array). Releases the GIL.")
        .def("reset", [](TrackerHandle& h) {
            py::gil_scoped_release release;
            std::lock_guard lock(h.mutex);
            h.tracker->reset();
        })
        .def_property_readonly(
            "markers",
            [](TrackerHandle& h) {
                std::lock_guard lock(h.mutex);
                const auto* m = dynamic_cast<const ar::MarkerTracker*>(h.tracker.get());
                return m ? markerList(m->markers()) : py::list();
            },
            "The board's markers in the last frame: [(id, corners (4, 2))]; [] for a picture.")
        .def_property_readonly(
            "charuco_corners",
            [](TrackerHandle& h) -> py::object {
                std::lock_guard lock(h.mutex);
                const auto* m = dynamic_cast<const ar::MarkerTracker*>(h.tracker.get());
                if (!m)
                    return py::none();
                const auto& corners = m->charucoCorners();
                std::vector<int> ids;
                py::array_t<double> points({py::ssize_t(corners.size()), py::ssize_t(2)});
                for (std::size_t i = 0; i < corners.size(); ++i) {
                    ids.push_back(corners[i].first);
                    *points.mutable_data(py::ssize_t(i), 0) = corners[i].second[0];
                    *points.mutable_data(py::ssize_t(i), 1) = corners[i].second[1];
                }
                return py::make_tuple(toArray<int>(ids), points);
            },
            "(ids, pixels (N, 2)) of the last frame's ChArUco corners; None for a picture.")
        .def_property_readonly(
            "corners",
            [](TrackerHandle& h) -> py::object {
                std::lock_guard lock(h.mutex);
                const auto* p = dynamic_cast<const ar::PlanarTracker*>(h.tracker.get());
                if (!p)
                    return py::none();
                std::vector<double> xy;
                for (const ar::PixelPoint& corner : p->corners())
                    xy.insert(xy.end(), corner.begin(), corner.end());
                return toArray<double>(xy, {4, 2});
            },
            "A picture's corners in the last frame where it was found (4, 2); None for a board.")
        .def("__repr__", [](const TrackerHandle& h) { return "<thespis.ar.Tracker " + h.description + ">"; });
    a.def(
        "make_tracker",
        [](const py::object& camera, const py::object& board, const std::optional<std::filesystem::path>& picture,
           double width) {
            ar::TrackingTarget target;
            if (!board.is_none())
                target.board = boardArgument(board);
            if (picture) {
                target.picture = *picture;
                target.pictureWidth = width;
            }
            const ar::CameraIntrinsics intrinsics = cameraArgument(camera);
            auto handle = std::make_shared<TrackerHandle>();
            handle->tracker = unwrap(withoutGil([&] { return ar::makeTracker(target, intrinsics); }));
            handle->description = handle->tracker->description();
            return handle;
        },
        "camera"_a, py::kw_only(), "board"_a = py::none(), "picture"_a = py::none(), "width"_a = 0.0,
        "A tracker for a board (aruco-grid or charuco; Board or text) or a printed picture `width` metres wide; "
        "camera: CameraIntrinsics or a camera file.");
    a.def(
        "detect_markers",
        [](const py::object& image, const std::string& dictionary, bool wholePixels) {
            ar::VideoFrame storage;
            const ar::VideoFrame& f = frameArgument(image, storage);
            const auto corners = wholePixels ? ar::MarkerCorners::WholePixels : ar::MarkerCorners::SubPixel;
            return markerList(unwrap(withoutGil([&] { return ar::detectMarkers(f, dictionary, corners); })));
        },
        "image"_a, "dictionary"_a, "whole_pixels"_a = false,
        "The markers of a predefined dictionary in a frame: [(id, corners)], corners (4, 2) float64 pixels, "
        "top-left, top-right, bottom-right, bottom-left. whole_pixels: OpenCV's own corners, without refinement.");

    py::class_<ar::TrackedFrame>(a, "TrackedFrame", "One frame through a tracking session.")
        .def_readonly("frame", &ar::TrackedFrame::frame)
        .def_readonly("time", &ar::TrackedFrame::time)
        .def_readonly("tracked", &ar::TrackedFrame::tracked, "The target was found in this frame.")
        .def_readonly("has_pose", &ar::TrackedFrame::hasPose, "False when lost longer than the filter remembers.")
        .def_property_readonly("pose", &poseOrNone, "Filtered (predicted while briefly lost); None without a pose.")
        .def_property_readonly("rvec", [](const ar::TrackedFrame& f) {
            return f.hasPose ? py::object(vector3(f.pose.rotation)) : py::none();
        })
        .def_property_readonly("tvec", [](const ar::TrackedFrame& f) {
            return f.hasPose ? py::object(vector3(f.pose.translation)) : py::none();
        })
        .def_readonly("measured", &ar::TrackedFrame::measured)
        .def_property_readonly("event", [](const ar::TrackedFrame& f) { return std::string(ar::trackingEventName(f.event)); },
                               "'found', 'lost', 'recovered' or ''.")
        .def_readonly("latency", &ar::TrackedFrame::latency, "Seconds from the frame's capture to its pose.")
        .def("__repr__", [](const ar::TrackedFrame& f) {
            return "<thespis.ar.TrackedFrame " + std::to_string(f.frame) + (f.tracked ? " tracked" : " not tracked") + ">";
        });
    using Statistics = ar::TrackingSession::Statistics;
    py::class_<Statistics>(a, "TrackingStatistics")
        .def_readonly("frames", &Statistics::frames)
        .def_readonly("tracked", &Statistics::tracked)
        .def_readonly("lost", &Statistics::lost, "How many times the target was lost.")
        .def_readonly("mean_latency", &Statistics::meanLatency, "Seconds.")
        .def_readonly("max_latency", &Statistics::maxLatency, "Seconds.");

    const ar::PoseFilterSettings defaults;
    py::class_<SessionHandle>(a, "TrackingSession",
                              "A tracker over time: the temporal filter (a Kalman filter on SE(3)), found / lost / "
                              "recovered events and latency.")
        .def(py::init([](std::shared_ptr<TrackerHandle> tracker, bool filter, double linear, double angular,
                         double forgetAfter, double outlierDistance, int outliersBeforeRestart) {
                 ar::PoseFilterSettings settings{linear, angular, forgetAfter, outlierDistance, outliersBeforeRestart};
                 return std::make_unique<SessionHandle>(std::move(tracker), settings, filter);
             }),
             "tracker"_a, "filter"_a = true, py::kw_only(), "linear_acceleration"_a = defaults.linearAcceleration,
             "angular_acceleration"_a = defaults.angularAcceleration, "forget_after"_a = defaults.forgetAfter,
             "outlier_distance"_a = defaults.outlierDistance, "outliers_before_restart"_a = defaults.outliersBeforeRestart,
             "filter=False gives each frame's own pose. The tracker is shared, not copied.")
        .def(
            "process",
            [](SessionHandle& h, const py::object& frame, std::optional<double> time) {
                ar::VideoFrame storage;
                const ar::VideoFrame* f = &frameArgument(frame, storage);
                if (f != &storage && time) {
                    storage = *f;
                    f = &storage;
                } else if (f == &storage) {
                    if (!time)
                        throw py::value_error("A frame given as an array needs its time: process(image, time) (seconds).");
                    storage.index = h.next;
                }
                if (time)
                    storage.time = *time;
                h.next = f->index + 1;
                py::gil_scoped_release release;
                std::lock_guard lock(h.mutex);
                return h.session.process(*f);
            },
            "frame"_a, "time"_a = py::none(),
            "Tracks one frame (a VideoFrame, or a BGR array with its time in seconds, numbered in call order); "
            "times must increase. Releases the GIL.")
        .def("reset",
             [](SessionHandle& h) {
                 py::gil_scoped_release release;
                 std::lock_guard lock(h.mutex);
                 h.session.reset();
             },
             "Starts over: the tracker and the filter forget.")
        .def_readonly("tracker", &SessionHandle::tracker)
        .def_property_readonly("tracking", [](SessionHandle& h) { std::lock_guard lock(h.mutex); return h.session.tracking(); })
        .def_property_readonly("statistics", [](SessionHandle& h) { std::lock_guard lock(h.mutex); return h.session.statistics(); });
}

py::array trackArray(const TrackResult& r)
{
    const py::module_ np = py::module_::import("numpy");
    py::list fields;
    for (const char* name : {"frame:i8", "time:f8", "tracked:?", "rvec:f8", "tvec:f8", "event:U9", "latency:f8"}) {
        const std::string text(name);
        const auto colon = text.find(':');
        const std::string field = text.substr(0, colon), type = text.substr(colon + 1);
        fields.append(field == "rvec" || field == "tvec" ? py::make_tuple(field, type, 3) : py::make_tuple(field, type));
    }
    const auto n = py::ssize_t(r.frames.size());
    py::array out = np.attr("zeros")(n, np.attr("dtype")(fields));
    std::vector<std::int64_t> frame;
    std::vector<double> time, latency, rvec, tvec;
    std::vector<bool> tracked;
    py::list events;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (const ar::TrackedFrame& f : r.frames) {
        frame.push_back(f.frame);
        time.push_back(f.time);
        tracked.push_back(f.tracked);
        latency.push_back(f.latency);
        events.append(ar::trackingEventName(f.event));
        for (std::size_t k = 0; k < 3; ++k) {
            rvec.push_back(f.hasPose ? f.pose.rotation[k] : nan);
            tvec.push_back(f.hasPose ? f.pose.translation[k] : nan);
        }
    }
    out[py::str("frame")] = toArray<std::int64_t>(frame);
    out[py::str("time")] = toArray<double>(time);
    out[py::str("tracked")] = py::cast(tracked);
    out[py::str("rvec")] = toArray<double>(rvec, {n, 3});
    out[py::str("tvec")] = toArray<double>(tvec, {n, 3});
    out[py::str("event")] = events;
    out[py::str("latency")] = toArray<double>(latency);
    return out;
}

void bindJobs(py::module_& a)
{
    py::class_<TrackResult>(a, "TrackResult",
                            "What track() found: `frames` (TrackedFrame per frame, also by index and iteration), "
                            "`statistics`, the `tracker` description; to_numpy() as a structured array.")
        .def_readonly("frames", &TrackResult::frames)
        .def_readonly("statistics", &TrackResult::statistics)
        .def_readonly("tracker", &TrackResult::tracker)
        .def("__len__", [](const TrackResult& r) { return r.frames.size(); })
        .def("__getitem__",
             [](const TrackResult& r, py::ssize_t i) {
                 const auto n = py::ssize_t(r.frames.size());
                 if (i < -n || i >= n)
                     throw py::index_error("frame " + std::to_string(i) + " of " + std::to_string(n));
                 return r.frames[std::size_t(i < 0 ? i + n : i)];
             })
        .def("__iter__", [](const TrackResult& r) { return py::make_iterator(r.frames.begin(), r.frames.end()); },
             py::keep_alive<0, 1>())
        .def("to_numpy", &trackArray,
             "One row per frame: frame (int64), time, tracked (bool), rvec (3), tvec (3) (NaN without a pose), "
             "event (str), latency.")
        .def("csv", [](const TrackResult& r) { return ar::formatPosesCsv(r.frames); },
             "The CSV thespis-cli track writes (frame,tracked,rx,ry,rz,tx,ty,tz,blur_px,blur_deg,ambiguity).");
    a.def(
        "track",
        [](const std::optional<std::filesystem::path>& video, const std::optional<std::vector<std::filesystem::path>>& pictures,
           double fps, const py::object& camera, const py::object& board, const std::optional<std::filesystem::path>& target,
           double width, bool filter, const std::optional<std::filesystem::path>& out, const py::object& progress) {
            ar::TrackJob job;
            job.video = video.value_or(std::filesystem::path());
            job.pictures = pictures.value_or(std::vector<std::filesystem::path>{});
            job.picturesFps = fps;
            TemporaryCameraFile temporary;
            job.cameraFile = py::isinstance<ar::CameraIntrinsics>(camera)
                                 ? temporary.write(camera.cast<ar::CameraIntrinsics>())
                                 : camera.cast<std::filesystem::path>();
            if (!board.is_none())
                job.target.board = boardArgument(board);
            if (target) {
                job.target.picture = *target;
                job.target.pictureWidth = width;
            }
            job.filter = filter;
            job.output = out.value_or(std::filesystem::path());
            runJob(job, progress);
            return TrackResult{std::move(job.frames), job.statistics, std::move(job.trackerDescription)};
        },
        "video"_a = py::none(), "pictures"_a = py::none(), py::kw_only(), "fps"_a = 30.0, "camera"_a,
        "board"_a = py::none(), "target"_a = py::none(), "width"_a = 0.0, "filter"_a = true, "out"_a = py::none(),
        "progress"_a = py::none(),
        "thespis-cli track from Python (the same TrackJob): a video, or pictures played at fps, through a board "
        "(Board or text) or a printed picture `target` `width` metres wide; camera: CameraIntrinsics or a camera "
        "file; out: the CSV to write. Returns a TrackResult. Releases the GIL; progress(done, total) is called on "
        "this thread; Ctrl-C cancels (nothing is written).");

    using View = ar::CalibrateJob::View;
    py::class_<View>(a, "CalibrationView")
        .def_readonly("image", &View::image)
        .def_readonly("found", &View::found, "The view took part in the calibration.")
        .def_readonly("corners", &View::corners, "The board's corners found in it.")
        .def_readonly("error", &View::error, "RMS reprojection error (px); −1 when not used.")
        .def("__repr__", [](const View& v) {
            return "<thespis.ar.CalibrationView " + v.image.filename().string() +
                   (v.found ? " " + std::to_string(v.error) + " px>" : " unused>");
        });
    py::class_<Calibration>(a, "Calibration", "What calibrate() found.")
        .def_readonly("camera", &Calibration::camera)
        .def_readonly("views", &Calibration::views)
        .def_property_readonly("errors",
                               [](const Calibration& c) {
                                   std::vector<double> errors;
                                   for (const View& v : c.views)
                                       errors.push_back(v.found ? v.error : std::numeric_limits<double>::quiet_NaN());
                                   return toArray<double>(errors);
                               },
                               "Per-view RMS reprojection errors (px), NaN for views left out.")
        .def_property_readonly("rms", [](const Calibration& c) { return c.camera.reprojectionError; })
        .def_property_readonly("deviations",
                               [](const Calibration& c) { return toArray<double>(std::span<const double>(c.deviations)); },
                               "OpenCV's standard deviations of fx, fy, cx, cy (px).");
    a.def(
        "calibrate",
        [](const std::vector<std::filesystem::path>& images, const py::object& board, bool fixAspect,
           const std::optional<std::filesystem::path>& out, const py::object& progress) {
            ar::CalibrateJob job;
            job.images = images;
            job.board = boardArgument(board);
            job.fixAspectRatio = fixAspect;
            job.output = out.value_or(std::filesystem::path());
            runJob(job, progress);
            return Calibration{std::move(job.camera), job.deviations, std::move(job.views)};
        },
        "images"_a, "board"_a, "fix_aspect"_a = false, "out"_a = py::none(), "progress"_a = py::none(),
        "thespis-cli calibrate from Python: a chessboard or ChArUco board (Board or text) in every picture; "
        "fix_aspect: fx = fy; out: the camera file to write. Returns a Calibration. Releases the GIL; "
        "progress(done, total) on this thread; Ctrl-C cancels.");
}

} // namespace

void bindAr(py::module_& m)
{
    py::module_ a = m.def_submodule("ar", "Augmented reality (paper §7): boards, camera calibration, frames as NumPy "
                                          "BGR images, marker and picture tracking, live capture, the live light probe.");
    bindBoardsAndCameras(a);
    bindFramesAndPoses(a);
    bindTracking(a);
    bindJobs(a);
    bindArLive(a);
}

} // namespace thespis::python
