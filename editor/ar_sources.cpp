#include "editor/ar_sources.h"

#include <QCollator>
#include <QDir>
#include <QFileInfo>

#include <algorithm>

#include "editor/qt_conversions.h"

namespace thespis::editor {

namespace {

constexpr int kTestPatternWidth = 640, kTestPatternHeight = 480;
constexpr double kTestPatternFps = 30;
constexpr std::int64_t kTestPatternFrames = 2 * 60 * 30;

} // namespace

QImage toQImage(const core::ar::VideoFrame& frame)
{
    if (frame.empty() || frame.width <= 0 || frame.height <= 0)
        return {};
    // The frame's buffer is reused by the next one: the picture gets its own copy.
    return QImage(frame.bgr.data(), frame.width, frame.height, qsizetype(frame.width) * 3, QImage::Format_BGR888).copy();
}

QStringList picturesIn(const QString& folder)
{
    const QDir dir(folder);
    QStringList names = dir.entryList({QStringLiteral("*.png"), QStringLiteral("*.jpg"), QStringLiteral("*.jpeg"),
                                       QStringLiteral("*.bmp"), QStringLiteral("*.tif"), QStringLiteral("*.tiff")},
                                      QDir::Files | QDir::Readable, QDir::NoSort);
    QCollator collator;
    collator.setNumericMode(true);
    std::sort(names.begin(), names.end(), [&](const QString& a, const QString& b) { return collator.compare(a, b) < 0; });
    QStringList paths;
    for (const QString& name : names)
        paths << dir.filePath(name);
    return paths;
}

core::ar::SyntheticScene testPatternScene(const core::ar::BoardSpec& board)
{
    core::ar::SyntheticScene scene;
    scene.board = board;
    scene.camera.width = kTestPatternWidth;
    scene.camera.height = kTestPatternHeight;
    scene.camera.matrix = {600, 0, 320, 0, 600, 240, 0, 0, 1};
    scene.camera.distortion = {0, 0, 0, 0, 0};
    scene.fps = kTestPatternFps;
    scene.frames = kTestPatternFrames;
    // Large boards are seen from further away, so that they stay in the picture.
    const double extent = std::max(board.columns, board.rows) * (board.square + board.second);
    const double scale = std::max(1.0, extent / 0.2);
    scene.nearest *= scale;
    scene.farthest *= scale;
    return scene;
}

core::ar::CameraRequest cameraRequest(const ArSource& source, QSize cameraFileSize)
{
    core::ar::CameraRequest request;
    request.index = source.camera;
    request.fps = source.fps;
    const QSize size = source.size.isEmpty() ? cameraFileSize : source.size;
    if (!size.isEmpty()) {
        request.width = size.width();
        request.height = size.height();
    }
    return request;
}

core::Result<std::unique_ptr<core::ar::FrameSource>> openArSource(const ArSource& source,
                                                                  const core::ar::BoardSpec& board, QSize cameraSize)
{
    using Kind = ArSource::Kind;
    switch (source.kind) {
    case Kind::VideoFile:
        return core::ar::openVideoFile(toFsPath(source.path));
    case Kind::ImageFolder: {
        std::vector<std::filesystem::path> pictures;
        for (const QString& picture : picturesIn(source.path))
            pictures.push_back(toFsPath(picture));
        if (pictures.empty())
            return core::makeError(core::ErrorCode::FileNotFound,
                                   QDir::toNativeSeparators(source.path).toStdString() + " holds no pictures");
        return core::ar::openImageSequence(std::move(pictures), source.fps);
    }
    case Kind::Camera:
        return core::ar::openCamera(cameraRequest(source, cameraSize));
    case Kind::TestPattern:
        break;
    }
    auto made = core::ar::SyntheticSource::create(testPatternScene(board));
    if (!made)
        return made.error();
    return std::unique_ptr<core::ar::FrameSource>(std::move(made).value());
}

core::Result<ArSourceInfo> probeArSource(const ArSource& source, const core::ar::BoardSpec& board)
{
    ArSourceInfo info;
    switch (source.kind) {
    case ArSource::Kind::Camera:
        return info;
    case ArSource::Kind::ImageFolder: {
        const QStringList pictures = picturesIn(source.path);
        if (pictures.isEmpty())
            return core::makeError(core::ErrorCode::FileNotFound,
                                   QDir::toNativeSeparators(source.path).toStdString() + " holds no pictures");
        auto first = core::ar::readPicture(toFsPath(pictures.front()));
        if (!first)
            return first.error();
        info.size = QSize(first->width, first->height);
        info.fps = source.fps;
        info.frames = pictures.size();
        return info;
    }
    case ArSource::Kind::VideoFile:
    case ArSource::Kind::TestPattern:
        break;
    }
    auto opened = openArSource(source, board, {});
    if (!opened)
        return opened.error();
    info.size = QSize((*opened)->width(), (*opened)->height());
    info.fps = (*opened)->fps();
    info.frames = (*opened)->frameCount();
    return info;
}

} // namespace thespis::editor
