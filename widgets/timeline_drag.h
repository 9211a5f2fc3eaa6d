#pragma once
// The timeline's gesture state: what a press started (a clip move, a trim, a fade, a scrub, a
// marker move or a rubber band) and what it has requested so far. TimelineView's mouse, key and
// drop handlers (timeline_drag.cpp) drive it. Also the pure rule that picks how many tracks a clip
// drag moves its clips up or down.

#include <QList>
#include <QPoint>
#include <QRect>
#include <QVector>

#include <span>
#include <vector>

#include "widgets/timeline_geometry.h"

namespace thespis::widgets {

enum class TimelineDragMode { None, Clip, TrimStart, TrimEnd, FadeIn, FadeOut, Scrub, Marker, RubberBand };

struct TimelineDrag {
    TimelineDragMode mode = TimelineDragMode::None;
    QPoint pressPos;
    bool active = false;  // moved past the threshold
    bool emitted = false; // something was requested during this drag
    bool locked = false;  // started on a locked track: the gesture only selects
    bool toggleOnRelease = false;     // Shift/Ctrl+press on a selected clip: deselect unless dragged
    bool selectOnlyOnRelease = false; // press on a selected clip: select only it unless dragged
    int clip = -1;                    // index into the clips
    int clipId = 0;
    int marker = -1;
    qint64 origStart = 0, origEnd = 0, origValue = 0; // origValue: fade length or marker time
    qint64 last = 0;                                   // last value requested
    QList<int> ids;                                    // moving clips
    QVector<TimelineClip> moving;                      // them as they were at the press
    int origTrack = -1;                                // the grabbed clip's track at the press
    int trackDelta = 0;                                // last track offset requested
    std::vector<qint64> edges;                         // their edges at the press
    qint64 minStart = 0;
    std::vector<char> baseSelection;                   // rubber band: selection kept (Shift/Ctrl)
    std::vector<char> pressSelection;                  // rubber band: selection before the press
    QRect band;
};

/// Whether every clip in `moving` lands, `offset` tracks further down, on an unlocked track of its
/// own group and kind. Offset 0 always fits.
bool trackOffsetFits(std::span<const TimelineTrack> tracks, std::span<const TimelineClip> moving, int offset);

/// The track offset of a clip drag grabbed on `origTrack` with the mouse at viewport y: towards the
/// track whose lane centre is nearest to y, the nearest offset (the nearer to 0 on a tie) at which
/// every clip of `moving` fits.
int clipDragTrackOffset(const TimelineGeometry& geometry, std::span<const TimelineClip> moving, int origTrack, int y);

} // namespace thespis::widgets
