#pragma once
// The curve view's geometry as pure values: (seconds, value) ↔ pixels for a plot rectangle and a
// visible range, framing data into a plot, grid steps, tangent handles, and hit testing of keys,
// handles and curves. No widget here: CurveView builds a CurveMapping for each paint or event, and
// tests build one by hand.

#include <QList>
#include <QPointF>
#include <QRectF>
#include <QVector>

#include <optional>

#include "widgets/curve_types.h"

namespace thespis::widgets {

/// Sizes in pixels.
struct CurveMetrics {
    static constexpr qreal KeyRadius = 5.5;        ///< half the diagonal of a key's diamond
    static constexpr qreal KeyHitRadius = 8;       ///< how far from a key a click still picks it
    static constexpr qreal HandleLength = 44;      ///< from a key to the end of its tangent handle
    static constexpr qreal HandleRadius = 3.5;
    static constexpr qreal HandleHitRadius = 7;
    static constexpr qreal CurveHitDistance = 10;  ///< a double-click this near a curve adds a key to it
    static constexpr qreal FramePaddingX = 28;     ///< framing keeps the data this far inside the plot
    static constexpr qreal FramePaddingY = 22;
};

/// A range of time (seconds) and value shown in the plot.
struct CurveRange {
    double t0 = 0, t1 = 1, v0 = 0, v1 = 1;
};

/// (seconds, value) ↔ pixels: t0 at the plot's left, v0 at its bottom, values up.
struct CurveMapping {
    QRectF plot;
    double t0 = 0, v0 = 0;
    double sx = 1, sy = 1; ///< pixels per second, pixels per value unit

    /// The mapping that shows `range` in `plot`.
    static CurveMapping fit(const QRectF& plot, const CurveRange& range);
    QPointF map(double t, double v) const { return {plot.left() + (t - t0) * sx, plot.bottom() - (v - v0) * sy}; }
    QPointF map(QPointF p) const { return map(p.x(), p.y()); }
    QPointF unmap(QPointF p) const { return {t0 + (p.x() - plot.left()) / sx, v0 + (plot.bottom() - p.y()) / sy}; }
};

bool curveKeyLess(const CurveKeyRef& a, const CurveKeyRef& b); ///< by curve, then key
bool hasTangentHandles(CurveTangent mode);                     ///< Free and Broken keys only
const CurveViewKey* curveKeyAt(const QVector<CurveViewCurve>& curves, CurveKeyRef ref); ///< null if none
/// A curve with keys, or one that accepts them.
bool isCurveEditable(const QVector<CurveViewCurve>& curves, int curve);
double distanceToSegment(QPointF p, QPointF a, QPointF b);

/// A "nice" grid step (1, 2 or 5 × 10^k) giving lines at least `minPixels` apart, and how many
/// minor divisions it has (5 for 1 and 5, 4 for 2).
double niceGridStep(double pixelsPerUnit, double minPixels, int* minorDivisions);

/// `data` widened when flat (to at least 1 each way) and padded so that it sits FramePadding pixels
/// inside `plot` (at most a quarter of the plot each side).
CurveRange framedRange(const QRectF& plot, CurveRange data);
/// Every finite sample and key; nothing when there are none.
std::optional<CurveRange> curveDataBounds(const QVector<CurveViewCurve>& curves);
/// The domain [start, end] in time, at least 0..1 in value, every key, and the sample values within the domain.
CurveRange domainBounds(const QVector<CurveViewCurve>& curves, double start, double end);

/// The end of a key's tangent handle: HandleLength pixels from the key along its in (outSide =
/// false, to the left) or out slope, as the slope looks with this mapping.
QPointF tangentHandlePoint(const CurveMapping& m, const CurveViewKey& key, bool outSide);
/// The slope that points a key's handle at `pixel`; the out handle stays right of its key, the in
/// handle left (at worst vertical).
double tangentSlopeTowards(const CurveMapping& m, const CurveViewKey& key, QPointF pixel, bool outSide);
/// The (seconds, value) move for a drag from `from` to `to`; `constrain` keeps the dominant axis only.
QPointF keyMoveDelta(const CurveMapping& m, QPointF from, QPointF to, bool constrain);

/// The key nearest to `pixel` within KeyHitRadius (later curves, drawn on top, win ties), or none.
CurveKeyRef curveKeyUnder(const CurveMapping& m, const QVector<CurveViewCurve>& curves, QPointF pixel);
/// A handle of a selected Free / Broken key within HandleHitRadius; outSide says which one.
CurveKeyRef curveHandleUnder(const CurveMapping& m, const QVector<CurveViewCurve>& curves,
                             const QList<CurveKeyRef>& selection, QPointF pixel, bool* outSide);
/// The editable curve whose polyline (or, without samples, the lines between its keys) passes
/// nearest to `pixel`, within CurveHitDistance; -1 if none.
int editableCurveNear(const CurveMapping& m, const QVector<CurveViewCurve>& curves, QPointF pixel);
/// Every key inside `pixelRect` (any corner order), by curve then key.
QList<CurveKeyRef> curveKeysIn(const CurveMapping& m, const QVector<CurveViewCurve>& curves, const QRectF& pixelRect);

} // namespace thespis::widgets
