#pragma once
// Where the AR preview's video comes from, as the studio lets people choose it: a video file, a
// folder of pictures played as a sequence, a camera, or the test pattern (a synthetic board moving
// as if hand-held, seen by a camera known exactly: it needs no calibration and no printout).
// ArSource is the choice as a value (the panel keeps one, the calibration dialog opens another
// reader of the same); openArSource() makes the core reader, probeArSource() says what it gives
// before anything plays (its size, to refuse a calibration for another size up front).

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>

#include <memory>

#include "ar/board.h"
#include "ar/frame_source.h"
#include "ar/synthetic_source.h"
#include "util/error.h"

namespace thespis::editor {

struct ArSource {
    enum class Kind { TestPattern, VideoFile, ImageFolder, Camera };
    Kind kind = Kind::TestPattern;
    QString path;     ///< the video file or the picture folder
    int camera = 0;   ///< /dev/video<camera>
    QSize size;       ///< asked of a camera; empty: the camera file's
    double fps = 30;  ///< the picture folder's frame rate, or the one asked of a camera
};

/// What a source gives, known before it plays.
struct ArSourceInfo {
    QSize size;          ///< empty for a camera (known once it runs)
    double fps = 0;      ///< 0 when unknown
    qint64 frames = -1;  ///< −1 for a camera
};

/// A copy of a BGR frame as a picture for a widget (a null image for an empty frame).
QImage toQImage(const core::ar::VideoFrame& frame);

/// The pictures (PNG, JPEG, BMP, TIFF) of `folder` in natural order (view2 before view10).
QStringList picturesIn(const QString& folder);

/// The test pattern: `board` seen by a 640 × 480 camera, hand-held for two minutes.
core::ar::SyntheticScene testPatternScene(const core::ar::BoardSpec& board);

/// What a camera source asks of its camera: the source's size, else `cameraFileSize`, else
/// 640 × 480, and the source's frame rate (the camera may give others).
core::ar::CameraRequest cameraRequest(const ArSource& source, QSize cameraFileSize);

/// Opens the source. `board` is what the test pattern shows; a camera is opened with
/// cameraRequest(source, cameraSize).
core::Result<std::unique_ptr<core::ar::FrameSource>> openArSource(const ArSource& source,
                                                                  const core::ar::BoardSpec& board, QSize cameraSize);

/// Opens the source briefly to read what it gives (a camera is left alone). Errors: the reader's
/// (a missing file, one that is not a video, a folder without pictures).
core::Result<ArSourceInfo> probeArSource(const ArSource& source, const core::ar::BoardSpec& board);

} // namespace thespis::editor
