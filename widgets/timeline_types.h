#pragma once
// The values a TimelineView shows (tracks, clips, captions, markers) and names (edges, track flags): plain
// data that the editor fills and that the timeline's geometry, snapping and painting read.

#include <QMetaType>
#include <QString>
#include <QVector>

#include <limits>

namespace thespis::widgets {

enum class TimelineEdge { Start, End };
enum class TimelineTrackFlag { Mute, Solo, Lock };

/// The end of an open-ended clip (TimelineView::OpenEnd).
inline constexpr qint64 TimelineOpenEnd = std::numeric_limits<qint64>::max();

/// One row of the timeline.
struct TimelineTrack {
    QString name;  ///< "Body", "Face", …
    QString group; ///< the character's name; consecutive tracks of one group share a group header row
    bool muted = false, solo = false, locked = false;
    /// Clips are dragged only between tracks of the same group and the same kind ("body", "face").
    QString kind;
};

/// One action on a track, in ticks.
struct TimelineClip {
    int id = 0;      ///< stable id chosen by the caller
    int track = 0;   ///< index into the tracks; clips on a track that does not exist are not drawn
    QString name;
    qint64 start = 0, end = 0;      ///< end == TimelineView::OpenEnd for open-ended actions
    qint64 fadeIn = 0, fadeOut = 0; ///< lengths in ticks
    QVector<float> weight;          ///< weight samples evenly over [start, end] (thumbnail), 0..1+, may be empty
};

/// Words under a track's clips (what a speech line says while its visemes play), in ticks.
struct TimelineCaption {
    int track = 0;
    QString text;
    qint64 start = 0, end = 0;
};

struct TimelineMarker {
    QString name;
    qint64 time = 0;
};

} // namespace thespis::widgets

Q_DECLARE_METATYPE(thespis::widgets::TimelineEdge)
Q_DECLARE_METATYPE(thespis::widgets::TimelineTrackFlag)
Q_DECLARE_METATYPE(thespis::widgets::TimelineTrack)
Q_DECLARE_METATYPE(thespis::widgets::TimelineClip)
Q_DECLARE_METATYPE(thespis::widgets::TimelineMarker)
Q_DECLARE_METATYPE(thespis::widgets::TimelineCaption)
