#pragma once
// The values a CurveView shows and names: curves with their samples and keys, tangent modes and
// references to keys. Plain data that the editor fills and the view's geometry and painting read.

#include <QColor>
#include <QList>
#include <QMetaType>
#include <QPointF>
#include <QString>
#include <QVector>

namespace thespis::widgets {

/// How a key's tangents are chosen. Auto clamped, Linear and Constant are computed by the curve;
/// Free and Broken use the key's own slopes (Free: in = out; Broken: each side on its own), and
/// only those two show draggable tangent handles.
enum class CurveTangent { AutoClamped, Linear, Constant, Free, Broken };

/// One key of a keyframed curve, in the curve's units: time in seconds, slopes in value / second.
struct CurveViewKey {
    double time = 0, value = 0;
    CurveTangent mode = CurveTangent::AutoClamped;
    double inSlope = 0, outSlope = 0;
};

/// One curve as the view shows it.
struct CurveViewCurve {
    QString name;               ///< "Weight", "Scale": shown in the legend
    QColor color;
    QVector<QPointF> samples;   ///< the evaluated curve (x = seconds, ascending; y = value): a polyline
    QVector<CurveViewKey> keys; ///< empty for parametric curves (fades / ADSR): drawn, not key-editable
    /// Accepts new keys (double-click, Ctrl+click) even while `keys` is empty, e.g. a keyframed
    /// curve whose last key was deleted. Curves with keys are always editable.
    bool keyable = false;
};

/// A key by position: index of the curve in setCurves() and of the key in that curve.
struct CurveKeyRef {
    int curve = -1;
    int key = -1;
    bool operator==(const CurveKeyRef&) const = default;
};

} // namespace thespis::widgets

Q_DECLARE_METATYPE(thespis::widgets::CurveKeyRef)
Q_DECLARE_METATYPE(QList<thespis::widgets::CurveKeyRef>)
Q_DECLARE_METATYPE(thespis::widgets::CurveTangent)
