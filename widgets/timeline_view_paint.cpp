// TimelineView's painting: lanes with the grid and the shaded time past the end, the clips (fade
// ramps, weight thumbnail, name, fade handles), overlays (drop and move ghosts, snap line, rubber
// band, playhead), the track header column and the ruler; and the colours taken from the palette.

#include "widgets/timeline_view.h"
#include "widgets/color_mix.h"

#include <QLinearGradient>
#include <QPainter>
#include <QSet>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {

using M = TimelineMetrics;

constexpr int kMinSmoothClipWidth = 80; // narrower clips: fade ramps unshaded, lines aliased
constexpr int kOpenFadeWidth = 90;      // an open-ended clip fades out over this many pixels

const char* flagLetter(TimelineTrackFlag flag)
{
    switch (flag) {
    case TimelineTrackFlag::Mute: return "M";
    case TimelineTrackFlag::Solo: return "S";
    case TimelineTrackFlag::Lock: return "L";
    }
    return "";
}

// A bar with 1-pixel chamfered corners from solid fills only (no overlap, so that translucent
// brushes blend once): reads like a small corner radius at a fraction of a path's cost.
void fillBar(QPainter& painter, const QRect& r, const QBrush& fill, const QBrush& border, int b)
{
    const int x = r.left(), y = r.top(), w = r.width(), h = r.height();
    if (w <= 2 * b + 1 || h <= 2 * b + 1) {
        painter.fillRect(r, border);
        return;
    }
    painter.fillRect(QRect(x + 1, y, w - 2, b), border);         // top
    painter.fillRect(QRect(x + 1, y + h - b, w - 2, b), border); // bottom
    painter.fillRect(QRect(x, y + 1, b, h - 2), border);         // left (overlaps the top by one pixel at b = 2)
    painter.fillRect(QRect(x + w - b, y + 1, b, h - 2), border); // right
    painter.fillRect(QRect(x + b, y + b, w - 2 * b, h - 2 * b), fill);
}

// An open-ended clip's bar: no right border, and from `fadeStart` on the fill and the border fade
// out (`fillFade`, `borderFade`). Only that last stretch is drawn with the gradients: a gradient
// costs a colour-table lookup per pixel, and open clips (idle motion) reach the lanes' edge.
void fillOpenBar(QPainter& painter, const QRect& r, const QColor& fill, const QColor& border, int b, int fadeStart,
                 const QBrush& fillFade, const QBrush& borderFade)
{
    const int x = r.left(), y = r.top(), right = r.left() + r.width(), h = r.height();
    if (h <= 2 * b + 1) {
        painter.fillRect(r, borderFade);
        return;
    }
    const int solidEnd = std::clamp(fadeStart, x + b, right);
    painter.fillRect(QRect(x, y + 1, b, h - 2), border); // left
    for (const int top : {y, y + h - b}) {               // top and bottom
        painter.fillRect(QRect(x + 1, top, solidEnd - x - 1, b), border);
        painter.fillRect(QRect(solidEnd, top, right - solidEnd, b), borderFade);
    }
    painter.fillRect(QRect(x + b, y + b, solidEnd - x - b, h - 2 * b), fill);
    painter.fillRect(QRect(solidEnd, y + b, right - solidEnd, h - 2 * b), fillFade);
}

} // namespace

void TimelineView::updateColors()
{
    const QPalette& pal = palette();
    const QColor window = pal.color(QPalette::Window);
    const QColor windowText = pal.color(QPalette::WindowText);
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const QColor highlight = pal.color(QPalette::Highlight);
    const QColor shadow = pal.color(QPalette::Shadow);
    Colors& c = m_colors;
    c.dark = window.lightnessF() < 0.5;
    c.lane = base;
    c.laneAlt = mix(base, text, 0.035);
    c.group = mix(window, windowText, c.dark ? 0.10 : 0.08);
    c.header = window;
    c.headerText = windowText;
    c.headerDim = mix(windowText, window, 0.55);
    c.separator = mix(window, shadow, c.dark ? 0.5 : 0.2);
    c.ruler = mix(window, windowText, 0.05);
    c.rulerText = mix(windowText, window, 0.2);
    c.rulerTick = mix(windowText, window, 0.55);
    c.gridMajor = mix(base, text, 0.10);
    c.gridMinor = mix(base, text, 0.05);
    c.outside = mix(base, shadow, c.dark ? 0.35 : 0.07);

    // Clips: the highlight's hue, calmed down; selected ones closer to the highlight itself.
    const float hue = std::max(0.0f, highlight.hslHueF());
    const float saturation = highlight.hslSaturationF();
    c.clip = QColor::fromHslF(hue, saturation * 0.32f, c.dark ? 0.35f : 0.80f);
    c.clipBorder = c.dark ? c.clip.darker(160) : c.clip.darker(130);
    c.clipSelected = QColor::fromHslF(hue, saturation * 0.70f, c.dark ? 0.45f : 0.68f);
    c.clipSelectedBorder = c.dark ? QColor::fromHslF(hue, 0.9f, 0.78f) : QColor::fromHslF(hue, 0.9f, 0.30f);
    c.clipText = text;
    c.clipSelectedText = c.dark ? QColor(0xff, 0xff, 0xff) : QColor(0x0b, 0x0d, 0x10);
    c.fadeShade = c.dark ? QColor(0, 0, 0, 90) : QColor(0, 0, 0, 40);
    c.fadeLine = withAlpha(text, 160);
    c.weightLine = withAlpha(text, 150);
    c.weightFill = withAlpha(text, 28);
    c.handle = c.dark ? QColor(0xf2, 0xf2, 0xf2) : QColor(0xff, 0xff, 0xff);
    c.playhead = QColor(0xe5, 0x48, 0x4d);
    c.marker = QColor(0xf0, 0xa8, 0x30);
    c.markerText = QColor(0x26, 0x1c, 0x08);
    c.snap = c.dark ? QColor(0xff, 0xd8, 0x4d) : QColor(0xc0, 0x7a, 0x00);
    c.band = withAlpha(highlight, 50);
    c.bandBorder = highlight;
    c.flagOff = mix(window, windowText, c.dark ? 0.10 : 0.07);
    c.flagOffText = mix(windowText, window, 0.45);
    c.mute = QColor(0xe0, 0x7b, 0x39);
    c.solo = QColor(0xe6, 0xc2, 0x29);
    c.lock = QColor(0x6f, 0xa0, 0xd8);
    c.flagOnText = QColor(0x1a, 0x1a, 0x1a);
    m_fadePen = QPen(c.fadeLine, 1.0);
    m_fadePen.setCosmetic(true);
    m_weightPen = QPen(c.weightLine, 1.0);
    m_weightPen.setCosmetic(true);
    c.lockedHatch = QBrush(mix(base, text, c.dark ? 0.13 : 0.12), Qt::BDiagPattern);
    viewport()->update();
}

void TimelineView::paintEvent(QPaintEvent*)
{
    QPainter painter(viewport());
    const TimelineGeometry g = geometry();
    painter.setClipRect(g.lanesRect());
    paintLanes(painter, g);
    paintClips(painter, g);
    paintCaptions(painter, g);
    paintOverlays(painter, g);
    painter.setClipping(false);
    paintHeader(painter, g);
    paintRuler(painter, g);
}

void TimelineView::paintLanes(QPainter& painter, const TimelineGeometry& g)
{
    const QRect lanes = g.lanesRect();
    const Colors& c = m_colors;
    painter.fillRect(lanes, c.outside);
    const int right = lanes.right() + 1;
    for (const TimelineRow& row : m_rows.rows) {
        const int y = g.rowY(row);
        if (y > lanes.bottom())
            break;
        const int height = row.height();
        if (y + height <= lanes.top())
            continue;
        const QRect r(lanes.left(), y, lanes.width(), height);
        if (row.track < 0) {
            painter.fillRect(r, c.group);
        } else {
            painter.fillRect(r, row.track % 2 ? c.laneAlt : c.lane);
            if (m_tracks[row.track].locked)
                painter.fillRect(r, c.lockedHatch);
            if (trackDimmed(row.track))
                painter.fillRect(r, withAlpha(c.outside, 120));
        }
        painter.setPen(c.separator);
        painter.drawLine(lanes.left(), y + height - 1, right, y + height - 1);
    }

    // Time past the scenario's end is shaded.
    if (m_duration > 0) {
        const int endX = g.xForTime(m_duration);
        if (endX < right) {
            const int bottom = std::min(lanes.bottom(), RulerHeight + m_rows.contentHeight() - g.scroll.y());
            const QRect after(std::max(endX, lanes.left()), lanes.top(), right - std::max(endX, lanes.left()),
                              bottom - lanes.top() + 1);
            painter.fillRect(after, withAlpha(c.outside, 150));
        }
    }

    // Vertical grid at the ruler's major steps.
    const Steps steps = rulerSteps();
    const qint64 firstFrame = std::max<qint64>(0, floorDiv(floorDiv(g.timeForX(lanes.left()) * m_time.frameRate, m_time.ticksPerSecond), steps.major));
    m_lines.clear();
    for (qint64 k = firstFrame;; ++k) {
        const int x = g.xForTime(m_time.frameTime(k * steps.major));
        if (x > right)
            break;
        m_lines.emplace_back(x, lanes.top(), x, lanes.bottom());
    }
    painter.setPen(c.gridMajor);
    painter.drawLines(m_lines.data(), int(m_lines.size()));

    // Markers: a thin line through the lanes.
    painter.setPen(QPen(withAlpha(c.marker, 110), 1, Qt::DashLine));
    for (const TimelineMarker& marker : m_markers) {
        const int x = g.xForTime(marker.time);
        if (x >= lanes.left() && x <= right)
            painter.drawLine(x, lanes.top(), x, lanes.bottom());
    }
}

void TimelineView::paintClips(QPainter& painter, const TimelineGeometry& g)
{
    const QRect lanes = g.lanesRect();
    if (m_clips.isEmpty() || m_tracks.isEmpty())
        return;
    // Cull in ticks first (no pixel math for clips outside the visible time range).
    const qint64 visibleStart = g.timeForX(lanes.left() - 2);
    const qint64 visibleEnd = g.timeForX(lanes.right() + 2);
    const int laneRight = lanes.right() + 1;
    // Unselected clips first, so that selected outlines are never covered.
    for (int pass = 0; pass < 2; ++pass) {
        for (int i = 0; i < int(m_clips.size()); ++i) {
            const TimelineClip& c = m_clips[i];
            if (bool(m_selected[std::size_t(i)]) != (pass == 1) || c.track < 0 || c.track >= int(m_tracks.size()))
                continue;
            if (c.start > visibleEnd || (c.end != TimelineOpenEnd && c.end < visibleStart))
                continue;
            const int y = g.trackY(c.track);
            if (y + TrackHeight <= lanes.top() || y > lanes.bottom())
                continue;
            const int x0 = g.xForTime(c.start);
            const int x1 = c.end == TimelineOpenEnd ? laneRight : std::max(x0 + 1, g.xForTime(c.end));
            const QRect r(x0, y + M::ClipInset, x1 - x0, TrackHeight - 2 * M::ClipInset);
            paintClip(painter, g, i, r, trackDimmed(c.track), m_tracks[c.track].locked, laneRight);
        }
    }
}

void TimelineView::paintCaptions(QPainter& painter, const TimelineGeometry& g)
{
    const QRect lanes = g.lanesRect();
    const int height = m_smallMetrics.height() + 2;
    painter.setFont(m_smallFont);
    for (const TimelineCaption& caption : m_captions) {
        if (caption.track < 0 || caption.track >= int(m_tracks.size()))
            continue;
        const int x0 = g.xForTime(caption.start), x1 = std::max(x0 + 1, g.xForTime(caption.end));
        const int y = g.trackY(caption.track) + TrackHeight - height - 1;
        if (x1 < lanes.left() || x0 > lanes.right() || y + height <= lanes.top() || y > lanes.bottom())
            continue;
        const QRect r(x0, y, x1 - x0, height);
        painter.fillRect(r, withAlpha(m_colors.header, 215));
        painter.setPen(m_colors.clipBorder);
        painter.drawRect(r.adjusted(0, 0, -1, -1));
        painter.setPen(m_colors.headerText);
        painter.drawText(r.adjusted(2, 0, -1, 0), Qt::AlignLeft | Qt::AlignVCenter,
                         m_smallMetrics.elidedText(caption.text, Qt::ElideRight, r.width() - 3));
    }
}

void TimelineView::paintClip(QPainter& painter, const TimelineGeometry& g, int index, const QRect& r, bool dimmed,
                             bool locked, int laneRight)
{
    // Solid fills and aliased shapes wherever they look the same: antialiased paths cost ten
    // times as much, and a thousand clips must paint in a few milliseconds. Only the thin lines
    // (fade ramps, weight curve) are antialiased, with cosmetic pens (the rasterizer's fast path).
    const Colors& c = m_colors;
    const TimelineClip& clip = m_clips[index];
    const bool selected = m_selected[std::size_t(index)];
    const bool open = clip.end == TimelineOpenEnd;
    const QColor& fill = selected ? c.clipSelected : c.clip;
    if (dimmed)
        painter.setOpacity(0.45);
    if (r.width() < 5) {
        // Zoomed far out: a bar is all that can be seen.
        painter.fillRect(r, selected ? c.clipSelectedBorder : fill);
        if (dimmed)
            painter.setOpacity(1.0);
        return;
    }
    const int borderWidth = selected ? 2 : 1;
    const QColor& borderColor = selected ? c.clipSelectedBorder : c.clipBorder;
    if (open) {
        // Open-ended: no right border; fill and border fade out towards the view's edge.
        QLinearGradient fillFade(laneRight - kOpenFadeWidth, 0, laneRight, 0);
        fillFade.setColorAt(0, fill);
        fillFade.setColorAt(1, withAlpha(fill, 0));
        QLinearGradient borderFade(laneRight - kOpenFadeWidth, 0, laneRight, 0);
        borderFade.setColorAt(0, borderColor);
        borderFade.setColorAt(1, withAlpha(borderColor, 0));
        fillOpenBar(painter, r.adjusted(0, 0, 4, 0), fill, borderColor, borderWidth, laneRight - kOpenFadeWidth,
                    QBrush(fillFade), QBrush(borderFade));
    } else {
        fillBar(painter, r, fill, borderColor, borderWidth);
    }

    const int top = r.top() + borderWidth, bottom = r.bottom() - borderWidth + 1;
    const int left = r.left() + borderWidth, right = r.left() + r.width() - borderWidth;
    if (r.width() >= 10) {
        // Narrow clips (zoomed out, hundreds in view) keep the ramps but not their shading, and
        // draw their lines aliased: at that size neither is visible, and switching smoothing on
        // and off per clip costs more than the drawing itself.
        const bool smooth = r.width() >= kMinSmoothClipWidth;
        // Fades: the part above the ramp is shaded, the ramp itself a line.
        if (smooth && clip.fadeIn > 0) {
            const int xf = std::clamp(g.xForTime(clip.start + clip.fadeIn), left, right);
            const QPoint shade[] = {{left, top}, {xf, top}, {left, bottom}};
            painter.setPen(Qt::NoPen);
            painter.setBrush(c.fadeShade);
            painter.drawConvexPolygon(shade, 3);
        }
        if (smooth && !open && clip.fadeOut > 0) {
            const int xf = std::clamp(g.xForTime(clip.end - clip.fadeOut), left, right);
            const QPoint shade[] = {{right, top}, {xf, top}, {right, bottom}};
            painter.setPen(Qt::NoPen);
            painter.setBrush(c.fadeShade);
            painter.drawConvexPolygon(shade, 3);
        }
        if (smooth)
            painter.setRenderHint(QPainter::Antialiasing, true);
        if (clip.fadeIn > 0) {
            painter.setPen(m_fadePen);
            painter.drawLine(QPointF(left, bottom), QPointF(std::clamp(g.xForTime(clip.start + clip.fadeIn), left, right), top));
        }
        if (!open && clip.fadeOut > 0) {
            painter.setPen(m_fadePen);
            painter.drawLine(QPointF(right, bottom), QPointF(std::clamp(g.xForTime(clip.end - clip.fadeOut), left, right), top));
        }

        // Weight thumbnail in the lower part: one point per sample, or per two pixels (four on a
        // narrow clip) when the samples are denser than that (keeping each bucket's peak),
        // visible columns only.
        const QVector<float>& weight = clip.weight;
        const qsizetype n = weight.size();
        const double barLeft = r.left() + 0.5;
        const double barRight = open ? laneRight : r.left() + r.width() - 0.5;
        if (n >= 2 && r.width() >= 16) {
            const double span = barRight - barLeft;
            const double baseY = bottom - 2.5;
            const double amplitude = (r.height() - 4) * 0.45;
            const double visibleLeft = std::max<double>(barLeft, HeaderWidth - 2);
            const double visibleRight = std::min<double>(barRight, laneRight + 2);
            auto yFor = [&](float w) { return baseY - std::clamp(double(w), 0.0, 1.3) * amplitude; };
            m_points.clear();
            const double bucket = smooth ? 2.0 : 4.0; // pixels per point
            if (double(n - 1) <= span / bucket) {
                const double step = span / double(n - 1);
                const qsizetype first = std::max<qsizetype>(0, qsizetype(std::floor((visibleLeft - barLeft) / step)));
                const qsizetype last = std::min<qsizetype>(n - 1, qsizetype(std::ceil((visibleRight - barLeft) / step)));
                for (qsizetype i = first; i <= last; ++i)
                    m_points.emplace_back(barLeft + double(i) * step, yFor(weight[i]));
            } else {
                const double samplesPerPixel = double(n - 1) / span;
                for (double x = visibleLeft; x <= visibleRight; x += bucket) {
                    const qsizetype i0 = std::clamp<qsizetype>(qsizetype((x - barLeft) * samplesPerPixel), 0, n - 1);
                    const qsizetype i1 = std::clamp<qsizetype>(qsizetype((x + bucket - barLeft) * samplesPerPixel), i0, n - 1);
                    float peak = weight[i0];
                    for (qsizetype i = i0 + 1; i <= i1; ++i)
                        peak = std::max(peak, weight[i]);
                    m_points.emplace_back(x, yFor(peak));
                }
            }
            if (m_points.size() >= 2) {
                painter.setPen(m_weightPen);
                painter.drawPolyline(m_points.data(), int(m_points.size()));
            }
        }
        if (smooth)
            painter.setRenderHint(QPainter::Antialiasing, false);
    }

    if (r.width() >= M::MinClipDetail) {
        // The name, kept in view when the clip starts left of the lanes.
        const int textLeft = std::max(r.left(), HeaderWidth) + 7;
        const int textRight = std::min(r.left() + r.width(), laneRight) - 5;
        const int room = textRight - textLeft;
        if (room >= 12) {
            ClipLabel& label = m_clipLabels[std::size_t(index)];
            if (label.width != room) {
                label.text.setText(m_clipMetrics.elidedText(clip.name, Qt::ElideRight, room));
                label.text.prepare(QTransform(), m_clipFont);
                label.width = room;
            }
            painter.setFont(m_clipFont);
            painter.setPen(selected ? c.clipSelectedText : c.clipText);
            painter.drawStaticText(textLeft, r.top() + 4, label.text);
        }
        // Fade handles: small squares on the top border (not on locked tracks: they cannot be dragged).
        if (!locked) {
            for (TimelineEdge edge : {TimelineEdge::Start, TimelineEdge::End}) {
                if (edge == TimelineEdge::End && open)
                    break;
                const QPoint centre = g.fadeHandleRect(index, edge).center();
                painter.fillRect(QRect(centre.x() - 3, centre.y() - 3, 7, 7), borderColor);
                painter.fillRect(QRect(centre.x() - 2, centre.y() - 2, 5, 5), c.handle);
            }
        }
    }
    if (dimmed)
        painter.setOpacity(1.0);
}

void TimelineView::paintOverlays(QPainter& painter, const TimelineGeometry& g)
{
    const QRect lanes = g.lanesRect();
    const Colors& c = m_colors;
    if (m_dropActive && m_dropTrack >= 0) {
        const int x = g.xForTime(m_dropTime);
        const int width = std::max(90, int(m_pixelsPerSecond));
        paintGhost(painter, QRect(x, g.trackY(m_dropTrack) + M::ClipInset, width, TrackHeight - 2 * M::ClipInset), m_dropName);
        painter.fillRect(QRect(x - 1, lanes.top(), 2, lanes.height()), c.snap);
    }
    paintMoveGhosts(painter, g);
    if (m_snapLine >= 0) {
        const int x = g.xForTime(m_snapLine);
        painter.fillRect(QRect(x, lanes.top(), 1, lanes.height()), c.snap);
    }
    if (m_drag.mode == TimelineDragMode::RubberBand && m_drag.active && !m_drag.band.isEmpty()) {
        painter.setPen(c.bandBorder);
        painter.setBrush(c.band);
        painter.drawRect(m_drag.band.adjusted(0, 0, -1, -1));
    }
    // The playhead over every track.
    const int x = g.xForTime(m_playhead);
    if (x >= lanes.left() - 1 && x <= lanes.right() + 1)
        painter.fillRect(QRect(x, lanes.top(), 1, lanes.height()), c.playhead);
}

void TimelineView::paintGhost(QPainter& painter, const QRect& ghost, const QString& name)
{
    const Colors& c = m_colors;
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(QPen(c.clipSelectedBorder, 1.5, Qt::DashLine));
    painter.setBrush(withAlpha(c.clipSelected, 110));
    painter.drawRoundedRect(QRectF(ghost).adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setFont(m_clipFont);
    painter.setPen(c.clipSelectedText);
    painter.drawText(ghost.adjusted(8, 3, -4, 0), Qt::AlignLeft | Qt::AlignTop,
                     m_clipMetrics.elidedText(name, Qt::ElideRight, ghost.width() - 12));
}

void TimelineView::paintMoveGhosts(QPainter& painter, const TimelineGeometry& g)
{
    // Where a clip drag puts the clips, for as long as the editor has not moved them there (it
    // may refuse, or apply the move only on release).
    if (m_drag.mode != TimelineDragMode::Clip || !m_drag.active || m_drag.locked || (m_drag.last == 0 && m_drag.trackDelta == 0))
        return;
    QSet<std::pair<int, qint64>> shown; // (track, start) of the clips as they are now
    for (const TimelineClip& c : std::as_const(m_clips))
        shown.insert({c.track, c.start});
    const int laneRight = g.viewport.width();
    for (const TimelineClip& c : std::as_const(m_drag.moving)) {
        const int track = c.track + m_drag.trackDelta;
        const qint64 start = c.start + m_drag.last;
        if (track < 0 || track >= int(m_tracks.size()) || shown.contains({track, start}))
            continue;
        const int x0 = g.xForTime(start);
        const int x1 = c.end == TimelineOpenEnd ? laneRight : std::max(x0 + 1, g.xForTime(c.end + m_drag.last));
        paintGhost(painter, QRect(x0, g.trackY(track) + M::ClipInset, x1 - x0, TrackHeight - 2 * M::ClipInset), c.name);
    }
}

void TimelineView::paintFlag(QPainter& painter, const QRect& rect, TimelineTrackFlag flag, bool on)
{
    const Colors& c = m_colors;
    const QColor& lit = flag == TimelineTrackFlag::Mute ? c.mute : flag == TimelineTrackFlag::Solo ? c.solo : c.lock;
    painter.setRenderHint(QPainter::Antialiasing, true);
    painter.setPen(on ? lit.darker(130) : c.separator);
    painter.setBrush(on ? lit : c.flagOff);
    painter.drawRoundedRect(QRectF(rect).adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(on ? c.flagOnText : c.flagOffText);
    painter.drawText(rect, Qt::AlignCenter, QLatin1String(flagLetter(flag)));
}

void TimelineView::paintHeader(QPainter& painter, const TimelineGeometry& g)
{
    const Colors& c = m_colors;
    const QRect column(0, RulerHeight, HeaderWidth, std::max(0, g.viewport.height() - RulerHeight));
    painter.setClipRect(column);
    painter.fillRect(column, c.header);
    for (std::size_t i = 0; i < m_rows.rows.size(); ++i) {
        const TimelineRow& row = m_rows.rows[i];
        const int y = g.rowY(row);
        if (y > column.bottom())
            break;
        const int height = row.height();
        if (y + height <= column.top())
            continue;
        if (row.track < 0) {
            // The character: a bold label on a band that spans the lanes too.
            painter.fillRect(QRect(0, y, HeaderWidth, height), c.group);
            painter.fillRect(QRect(0, y, 3, height), c.bandBorder);
            painter.setFont(m_boldFont);
            painter.setPen(c.headerText);
            painter.drawText(QRect(10, y, HeaderWidth - 16, height), Qt::AlignLeft | Qt::AlignVCenter, m_rowLabels[i]);
        } else {
            const TimelineTrack& track = m_tracks[row.track];
            if (row.group >= 0)
                painter.fillRect(QRect(0, y, 3, height), withAlpha(c.bandBorder, 110));
            const int nameX = track.group.isEmpty() ? 10 : 22;
            painter.setFont(font());
            painter.setPen(trackDimmed(row.track) ? c.headerDim : c.headerText);
            painter.drawText(QRect(nameX, y, HeaderWidth - nameX, height), Qt::AlignLeft | Qt::AlignVCenter,
                             m_trackElided[std::size_t(row.track)]);
            painter.setFont(m_smallFont);
            for (TimelineTrackFlag flag : TimelineTrackFlags)
                paintFlag(painter, g.trackFlagRect(row.track, flag), flag, trackFlagValue(track, flag));
        }
        painter.setPen(c.separator);
        painter.drawLine(0, y + height - 1, HeaderWidth, y + height - 1);
    }
    painter.setPen(c.separator);
    painter.drawLine(HeaderWidth - 1, column.top(), HeaderWidth - 1, column.bottom());
    painter.setClipping(false);
}

void TimelineView::paintRuler(QPainter& painter, const TimelineGeometry& g)
{
    const Colors& c = m_colors;
    const QRect ruler = g.rulerRect();
    const int right = ruler.right() + 1;

    // Top-left corner: the playhead's time.
    const QRect corner(0, 0, HeaderWidth, RulerHeight);
    painter.fillRect(corner, c.ruler);
    painter.setFont(m_boldFont);
    painter.setPen(c.headerText);
    painter.drawText(corner.adjusted(10, 0, -8, 0), Qt::AlignLeft | Qt::AlignVCenter, m_time.format(m_playhead));
    painter.setFont(m_smallFont);
    painter.setPen(c.rulerText);
    painter.drawText(corner.adjusted(10, 0, -8, 0), Qt::AlignRight | Qt::AlignVCenter, m_frameRateLabel);
    painter.setPen(c.separator);
    painter.drawLine(HeaderWidth - 1, 0, HeaderWidth - 1, RulerHeight);

    painter.setClipRect(ruler);
    painter.fillRect(ruler, c.ruler);
    const Steps steps = rulerSteps();
    // Minor ticks (frames when zoomed in), then major ticks with labels.
    if (steps.minor > 0) {
        m_lines.clear();
        qint64 k = std::max<qint64>(0, floorDiv(floorDiv(g.timeForX(ruler.left()) * m_time.frameRate, m_time.ticksPerSecond), steps.minor));
        for (;; ++k) {
            const int x = g.xForTime(m_time.frameTime(k * steps.minor));
            if (x > right)
                break;
            m_lines.emplace_back(x, RulerHeight - 5, x, RulerHeight - 1);
        }
        painter.setPen(c.rulerTick);
        painter.drawLines(m_lines.data(), int(m_lines.size()));
    }
    painter.setFont(m_smallFont);
    const int labelY = 2 + m_smallMetrics.ascent();
    // Start one step early so that a label whose tick is just off the left still shows.
    qint64 k = std::max<qint64>(0, floorDiv(floorDiv(g.timeForX(ruler.left()) * m_time.frameRate, m_time.ticksPerSecond), steps.major) - 1);
    for (;; ++k) {
        const qint64 frame = k * steps.major;
        const int x = g.xForTime(m_time.frameTime(frame));
        if (x > right)
            break;
        painter.setPen(c.rulerText);
        painter.drawLine(x, 0, x, RulerHeight - 1);
        const qint64 seconds = frame / m_time.frameRate;
        const qint64 frames = frame % m_time.frameRate;
        const QString label = frames == 0
                                  ? QStringLiteral("%1:%2").arg(seconds / 60).arg(seconds % 60, 2, 10, QLatin1Char('0'))
                                  : QStringLiteral("%1:%2+%3")
                                        .arg(seconds / 60)
                                        .arg(seconds % 60, 2, 10, QLatin1Char('0'))
                                        .arg(frames, 2, 10, QLatin1Char('0'));
        painter.drawText(x + 4, labelY, label);
    }

    // Markers: a flag hanging from the bottom edge with the name beside it.
    painter.setRenderHint(QPainter::Antialiasing, true);
    for (int i = 0; i < int(m_markers.size()); ++i) {
        const QRect r = g.markerRect(i);
        if (r.right() < ruler.left() || r.left() > right)
            continue;
        const int x = g.xForTime(m_markers[i].time);
        const QRectF pill(x, r.top() + 0.5, r.width() - 5, r.height() - 1.5);
        painter.setPen(Qt::NoPen);
        painter.setBrush(c.marker);
        painter.drawRoundedRect(pill, 2, 2);
        const QPointF pole[] = {{x - 4.5, double(r.top()) + 0.5}, {x + 0.5, double(r.top()) + 0.5}, {x + 0.5, double(RulerHeight)}};
        painter.drawPolygon(pole, 3);
        painter.setPen(c.markerText);
        painter.drawText(QRectF(x + 4, r.top(), m_markerWidths[std::size_t(i)] + 2, r.height()),
                         Qt::AlignLeft | Qt::AlignVCenter, m_markers[i].name);
    }

    // The playhead's handle.
    const int x = g.xForTime(m_playhead);
    if (x >= ruler.left() - 6 && x <= right + 6) {
        const QPointF handle[] = {{x - 5.5, 1.0}, {x + 6.5, 1.0}, {x + 6.5, 13.0}, {x + 0.5, double(RulerHeight)},
                                  {x - 5.5, 13.0}};
        painter.setPen(QPen(c.playhead.darker(140), 1.0));
        painter.setBrush(c.playhead);
        painter.drawPolygon(handle, 5);
    }
    painter.setRenderHint(QPainter::Antialiasing, false);
    painter.setPen(c.separator);
    painter.drawLine(ruler.left(), RulerHeight - 1, right, RulerHeight - 1);
    painter.setClipping(false);
}

} // namespace thespis::widgets
