// The curve view's pure geometry: mapping, framing, grid steps, tangent handles and hit tests.

#include "widgets/curve_geometry.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace thespis::widgets {

using M = CurveMetrics;

CurveMapping CurveMapping::fit(const QRectF& plot, const CurveRange& range)
{
    CurveMapping m;
    m.plot = plot;
    m.t0 = range.t0;
    m.v0 = range.v0;
    m.sx = plot.width() / (range.t1 - range.t0);
    m.sy = plot.height() / (range.v1 - range.v0);
    return m;
}

bool curveKeyLess(const CurveKeyRef& a, const CurveKeyRef& b)
{
    return a.curve != b.curve ? a.curve < b.curve : a.key < b.key;
}

bool hasTangentHandles(CurveTangent mode)
{
    return mode == CurveTangent::Free || mode == CurveTangent::Broken;
}

const CurveViewKey* curveKeyAt(const QVector<CurveViewCurve>& curves, CurveKeyRef ref)
{
    if (ref.curve < 0 || ref.curve >= curves.size())
        return nullptr;
    const QVector<CurveViewKey>& keys = curves[ref.curve].keys;
    return ref.key >= 0 && ref.key < keys.size() ? &keys[ref.key] : nullptr;
}

bool isCurveEditable(const QVector<CurveViewCurve>& curves, int curve)
{
    if (curve < 0 || curve >= curves.size())
        return false;
    const CurveViewCurve& c = curves[curve];
    return !c.keys.isEmpty() || c.keyable;
}

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double lengthSquared = QPointF::dotProduct(ab, ab);
    const double t = lengthSquared > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

double niceGridStep(double pixelsPerUnit, double minPixels, int* minorDivisions)
{
    const double raw = minPixels / std::max(pixelsPerUnit, 1e-12);
    const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    for (double factor : {1.0, 2.0, 5.0, 10.0}) {
        if (factor * magnitude >= raw * (1 - 1e-9)) {
            *minorDivisions = factor == 2.0 ? 4 : 5;
            return factor * magnitude;
        }
    }
    *minorDivisions = 5;
    return 10.0 * magnitude;
}

// --- framing --------------------------------------------------------------------------------------

CurveRange framedRange(const QRectF& plot, CurveRange data)
{
    // Flat or single-point data still gets a sensible window around it.
    if (data.t1 - data.t0 < 1e-6) {
        data.t0 -= 0.5;
        data.t1 += 0.5;
    }
    if (data.v1 - data.v0 < 1e-6) {
        data.v0 -= 0.5;
        data.v1 += 0.5;
    }
    const double usableW = std::max(plot.width() - 2 * M::FramePaddingX, plot.width() * 0.5);
    const double usableH = std::max(plot.height() - 2 * M::FramePaddingY, plot.height() * 0.5);
    const double padT = (data.t1 - data.t0) / usableW * (plot.width() - usableW) * 0.5;
    const double padV = (data.v1 - data.v0) / usableH * (plot.height() - usableH) * 0.5;
    return {data.t0 - padT, data.t1 + padT, data.v0 - padV, data.v1 + padV};
}

std::optional<CurveRange> curveDataBounds(const QVector<CurveViewCurve>& curves)
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    CurveRange r{inf, -inf, inf, -inf};
    auto grow = [&](double t, double v) {
        if (!std::isfinite(t) || !std::isfinite(v))
            return;
        r.t0 = std::min(r.t0, t);
        r.t1 = std::max(r.t1, t);
        r.v0 = std::min(r.v0, v);
        r.v1 = std::max(r.v1, v);
    };
    for (const CurveViewCurve& curve : curves) {
        for (const QPointF& s : curve.samples)
            grow(s.x(), s.y());
        for (const CurveViewKey& k : curve.keys)
            grow(k.time, k.value);
    }
    if (r.t0 > r.t1)
        return std::nullopt;
    return r;
}

CurveRange domainBounds(const QVector<CurveViewCurve>& curves, double start, double end)
{
    // Samples count only within the domain: an open-ended action may be sampled far beyond what is shown.
    CurveRange r{start, end, 0, 1};
    for (const CurveViewCurve& curve : curves) {
        for (const QPointF& s : curve.samples) {
            if (s.x() >= start && s.x() <= end && std::isfinite(s.y())) {
                r.v0 = std::min(r.v0, s.y());
                r.v1 = std::max(r.v1, s.y());
            }
        }
        for (const CurveViewKey& k : curve.keys) {
            if (!std::isfinite(k.time) || !std::isfinite(k.value))
                continue;
            r.t0 = std::min(r.t0, k.time);
            r.t1 = std::max(r.t1, k.time);
            r.v0 = std::min(r.v0, k.value);
            r.v1 = std::max(r.v1, k.value);
        }
    }
    return r;
}

// --- tangents and moves ---------------------------------------------------------------------------

QPointF tangentHandlePoint(const CurveMapping& m, const CurveViewKey& key, bool outSide)
{
    // The slope's direction as it looks on screen (y down), a fixed length in pixels.
    const double slope = outSide ? key.outSlope : key.inSlope;
    double dx = m.sx, dy = -slope * m.sy;
    const double length = std::hypot(dx, dy);
    if (!(length > 0) || !std::isfinite(length)) {
        dx = 0;
        dy = slope > 0 ? -1 : 1;
    } else {
        dx /= length;
        dy /= length;
    }
    const QPointF direction(dx * M::HandleLength, dy * M::HandleLength);
    const QPointF centre = m.map(key.time, key.value);
    return outSide ? centre + direction : centre - direction;
}

double tangentSlopeTowards(const CurveMapping& m, const CurveViewKey& key, QPointF pixel, bool outSide)
{
    const QPointF d = pixel - m.map(key.time, key.value);
    const double dx = outSide ? std::max(d.x(), 1.0) : std::min(d.x(), -1.0);
    return (-d.y() / m.sy) / (dx / m.sx);
}

QPointF keyMoveDelta(const CurveMapping& m, QPointF from, QPointF to, bool constrain)
{
    QPointF d = to - from;
    if (constrain) {
        if (std::abs(d.x()) >= std::abs(d.y()))
            d.setY(0);
        else
            d.setX(0);
    }
    return {d.x() / m.sx, -d.y() / m.sy};
}

// --- hit testing ----------------------------------------------------------------------------------

CurveKeyRef curveKeyUnder(const CurveMapping& m, const QVector<CurveViewCurve>& curves, QPointF pixel)
{
    CurveKeyRef best;
    double bestDistance = M::KeyHitRadius;
    // Later curves are drawn on top: on a tie they win.
    for (int c = int(curves.size()) - 1; c >= 0; --c) {
        const QVector<CurveViewKey>& keys = curves[c].keys;
        for (int k = int(keys.size()) - 1; k >= 0; --k) {
            const QPointF d = m.map(keys[k].time, keys[k].value) - pixel;
            const double distance = std::hypot(d.x(), d.y());
            if (distance < bestDistance) {
                bestDistance = distance;
                best = {c, k};
            }
        }
    }
    return best;
}

CurveKeyRef curveHandleUnder(const CurveMapping& m, const QVector<CurveViewCurve>& curves,
                             const QList<CurveKeyRef>& selection, QPointF pixel, bool* outSide)
{
    CurveKeyRef best;
    double bestDistance = M::HandleHitRadius;
    for (const CurveKeyRef& ref : selection) {
        const CurveViewKey* key = curveKeyAt(curves, ref);
        if (!key || !hasTangentHandles(key->mode))
            continue;
        for (bool out : {false, true}) {
            const QPointF d = tangentHandlePoint(m, *key, out) - pixel;
            const double distance = std::hypot(d.x(), d.y());
            if (distance < bestDistance) {
                bestDistance = distance;
                best = ref;
                *outSide = out;
            }
        }
    }
    return best;
}

int editableCurveNear(const CurveMapping& m, const QVector<CurveViewCurve>& curves, QPointF pixel)
{
    const double window = (M::CurveHitDistance + 1) / m.sx; // seconds either side worth checking
    const double t = m.unmap(pixel).x();
    int best = -1;
    double bestDistance = M::CurveHitDistance;
    auto consider = [&](int curve, QPointF a, QPointF b) {
        const double distance = distanceToSegment(pixel, m.map(a), m.map(b));
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = curve;
        }
    };
    for (int c = 0; c < curves.size(); ++c) {
        if (!isCurveEditable(curves, c))
            continue;
        const CurveViewCurve& curve = curves[c];
        if (!curve.samples.isEmpty()) {
            const QVector<QPointF>& s = curve.samples;
            auto first = std::lower_bound(s.begin(), s.end(), t - window, [](const QPointF& p, double x) { return p.x() < x; });
            auto last = std::upper_bound(s.begin(), s.end(), t + window, [](double x, const QPointF& p) { return x < p.x(); });
            if (first != s.begin())
                --first;
            if (last != s.end())
                ++last;
            if (last - first == 1)
                consider(c, *first, *first);
            for (auto it = first; it + 1 < last; ++it)
                consider(c, it[0], it[1]);
        } else {
            // No samples given: the straight lines between keys will do.
            const QVector<CurveViewKey>& k = curve.keys;
            if (k.size() == 1)
                consider(c, {k[0].time, k[0].value}, {k[0].time, k[0].value});
            for (int i = 0; i + 1 < k.size(); ++i)
                consider(c, {k[i].time, k[i].value}, {k[i + 1].time, k[i + 1].value});
        }
    }
    return best;
}

QList<CurveKeyRef> curveKeysIn(const CurveMapping& m, const QVector<CurveViewCurve>& curves, const QRectF& pixelRect)
{
    const QRectF rect = pixelRect.normalized();
    QList<CurveKeyRef> found;
    for (int c = 0; c < curves.size(); ++c) {
        const QVector<CurveViewKey>& keys = curves[c].keys;
        for (int k = 0; k < keys.size(); ++k)
            if (rect.contains(m.map(keys[k].time, keys[k].value)))
                found.append({c, k});
    }
    return found;
}

} // namespace thespis::widgets
