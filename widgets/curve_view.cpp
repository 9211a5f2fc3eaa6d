#include "widgets/curve_view.h"

#include <QActionGroup>
#include <QContextMenuEvent>
#include <QFontMetricsF>
#include <QKeyEvent>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>
#include <limits>

namespace thespis::widgets {

namespace {

constexpr qreal kKeyRadius = 5.5;       // half the diagonal of a key's diamond
constexpr qreal kKeyHitRadius = 8;      // how far from a key a click still picks it
constexpr qreal kHandleLength = 44;     // tangent handles, in pixels
constexpr qreal kHandleRadius = 3.5;
constexpr qreal kHandleHitRadius = 7;
constexpr qreal kCurveHitDistance = 10; // double-click this near a curve adds a key to it
constexpr qreal kDragThreshold = 3;     // pixels before a press becomes a drag
constexpr qreal kFramePaddingX = 28;    // frameAll() keeps the data this far inside the plot
constexpr qreal kFramePaddingY = 22;
constexpr double kOpenEndedSpan = 10;   // seconds shown for an open-ended action
constexpr double kMinSpan = 1e-5;
constexpr double kMaxSpan = 1e7;

QColor mix(const QColor& a, const QColor& b, qreal t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t), float(a.greenF() + (b.greenF() - a.greenF()) * t),
                            float(a.blueF() + (b.blueF() - a.blueF()) * t), float(a.alphaF() + (b.alphaF() - a.alphaF()) * t));
}

QColor withAlpha(QColor color, int alpha)
{
    color.setAlpha(alpha);
    return color;
}

// A "nice" grid step (1, 2 or 5 × 10^k) giving lines at least `minPixels` apart, and how many
// minor divisions it has (5 for 1 and 5, 4 for 2).
double niceStep(double pixelsPerUnit, double minPixels, int* minorDivisions)
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

int decimalsFor(double step)
{
    return std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 9);
}

QString formatNumber(double value, double step)
{
    if (std::abs(value) < step * 1e-6)
        value = 0; // no "-0"
    return QString::number(value, 'f', decimalsFor(step));
}

double distanceToSegment(QPointF p, QPointF a, QPointF b)
{
    const QPointF ab = b - a;
    const double lengthSquared = QPointF::dotProduct(ab, ab);
    const double t = lengthSquared > 0 ? std::clamp(QPointF::dotProduct(p - a, ab) / lengthSquared, 0.0, 1.0) : 0.0;
    const QPointF d = p - (a + t * ab);
    return std::hypot(d.x(), d.y());
}

bool lessByCurveThenKey(const CurveKeyRef& a, const CurveKeyRef& b)
{
    return a.curve != b.curve ? a.curve < b.curve : a.key < b.key;
}

bool hasHandles(CurveTangent mode)
{
    return mode == CurveTangent::Free || mode == CurveTangent::Broken;
}

} // namespace

struct CurveView::Mapping {
    QRectF plot;
    double t0 = 0, v0 = 0;
    double sx = 1, sy = 1; // pixels per second, pixels per value unit
    QPointF map(double t, double v) const { return {plot.left() + (t - t0) * sx, plot.bottom() - (v - v0) * sy}; }
    QPointF map(QPointF p) const { return map(p.x(), p.y()); }
    QPointF unmap(QPointF p) const { return {t0 + (p.x() - plot.left()) / sx, v0 + (plot.bottom() - p.y()) / sy}; }
};

// Everything is derived from the palette, but the plot stays dark-neutral in light themes too
// (as in Blender's and Maya's graph editors): coloured curves read best on a dark ground.
struct CurveView::Colors {
    QColor background, gutter, outside, gridMinor, gridMajor, gridEmphasis, domainEdge;
    QColor label, strongLabel, highlight, highlightText, keyOutline, selectedKey, handle;

    explicit Colors(const QPalette& palette)
    {
        const QColor base = palette.color(QPalette::Base);
        if (base.lightnessF() < 0.3) {
            background = base;
        } else {
            const QColor window = palette.color(QPalette::Window);
            const float hue = std::max(window.hslHueF(), 0.0f);
            background = QColor::fromHslF(hue, window.hslSaturationF() * 0.4f, 0.2f);
        }
        const QColor ink(235, 235, 235);
        gutter = background.darker(118);
        outside = withAlpha(QColor(0, 0, 0), 105);
        gridMinor = mix(background, ink, 0.045);
        gridMajor = mix(background, ink, 0.11);
        gridEmphasis = mix(background, ink, 0.32);
        domainEdge = mix(background, ink, 0.45);
        label = mix(background, ink, 0.62);
        strongLabel = mix(background, ink, 0.9);
        highlight = palette.color(QPalette::Highlight);
        if (highlight.lightnessF() < 0.5)
            highlight = highlight.lighter(130);
        highlightText = palette.color(QPalette::HighlightedText);
        keyOutline = background.darker(160);
        selectedKey = QColor(250, 250, 250);
        handle = mix(background, ink, 0.78);
    }
};

CurveView::CurveView(QWidget* parent) : QWidget(parent)
{
    setAttribute(Qt::WA_OpaquePaintEvent);
    setFocusPolicy(Qt::StrongFocus);
    setMouseTracking(true); // hover feedback on keys and handles
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    m_placeholder = tr("No curves to show");
    setStatusTip(tr("Click a key to select it, drag to move it; double-click a curve to add a key. "
                    "Wheel: zoom (Ctrl: values only, Shift: time only); middle-drag: pan; F: frame all."));
    updateGutters();

    m_menu = new QMenu(this);
    m_menu->setObjectName(QStringLiteral("curveViewMenu"));
    m_menu->addSection(tr("Tangents"));
    auto* group = new QActionGroup(this);
    group->setExclusionPolicy(QActionGroup::ExclusionPolicy::ExclusiveOptional);
    const std::array<QString, 5> texts = {tr("Auto Clamped"), tr("Linear"), tr("Constant"), tr("Free"), tr("Broken")};
    const std::array<QString, 5> tips = {tr("Smooth tangents that never overshoot neighbouring keys"),
                                         tr("Straight lines between keys"),
                                         tr("Hold the value until the next key"),
                                         tr("Smooth tangents you drag, the same on both sides"),
                                         tr("Tangents you drag, each side on its own")};
    const std::array<const char*, 5> names = {"tangentAutoClampedAction", "tangentLinearAction", "tangentConstantAction",
                                              "tangentFreeAction", "tangentBrokenAction"};
    for (std::size_t i = 0; i < m_modeActions.size(); ++i) {
        QAction* action = m_menu->addAction(texts[i]);
        action->setObjectName(QLatin1String(names[i]));
        action->setStatusTip(tips[i]);
        action->setToolTip(tips[i]);
        action->setCheckable(true);
        group->addAction(action);
        const auto mode = CurveTangent(i);
        connect(action, &QAction::triggered, this, [this, mode] { requestTangentMode(mode); });
        m_modeActions[i] = action;
    }
    m_menu->addSeparator();
    // The shortcut is handled by keyPressEvent(); the text after the tab only shows it.
    m_deleteAction = m_menu->addAction(tr("Delete Keys") + QStringLiteral("\tDel"));
    m_deleteAction->setObjectName(QStringLiteral("deleteKeysAction"));
    connect(m_deleteAction, &QAction::triggered, this, &CurveView::requestDelete);
    m_frameAllAction = m_menu->addAction(tr("Frame All") + QStringLiteral("\tF"));
    m_frameAllAction->setObjectName(QStringLiteral("frameAllAction"));
    connect(m_frameAllAction, &QAction::triggered, this, &CurveView::frameAll);
    updateMenuActions();
}

CurveView::~CurveView() = default;

// ---------------------------------------------------------------------------------------------
// Data

void CurveView::setCurves(QVector<CurveViewCurve> curves)
{
    m_curves = std::move(curves);
    normalizeSelection(m_selection);
    if (!keyAt(m_hoverKey))
        m_hoverKey = {};
    if (!keyAt(m_hoverHandle))
        m_hoverHandle = {};
    if (m_autoFrame)
        autoFrame();
    updateMenuActions();
    update();
}

void CurveView::setTimeRange(double start, double end)
{
    if (!std::isfinite(start))
        start = 0;
    if (std::isnan(end) || end < start)
        end = start;
    if (start == m_domainStart && end == m_domainEnd)
        return;
    m_domainStart = start;
    m_domainEnd = end;
    m_autoFrame = true; // another action: frame it
    autoFrame();
    update();
}

void CurveView::setPlayhead(double seconds)
{
    if (seconds == m_playhead)
        return;
    m_playhead = seconds;
    update();
}

void CurveView::setPlaceholderText(const QString& text)
{
    m_placeholder = text;
    update();
}

void CurveView::setSelectedKeys(const QList<CurveKeyRef>& keys)
{
    m_selection = keys;
    normalizeSelection(m_selection);
    updateMenuActions();
    update();
}

bool CurveView::isEditable(int curve) const
{
    if (curve < 0 || curve >= m_curves.size())
        return false;
    const CurveViewCurve& c = m_curves[curve];
    return !c.keys.isEmpty() || c.keyable;
}

const CurveViewKey* CurveView::keyAt(CurveKeyRef ref) const
{
    if (ref.curve < 0 || ref.curve >= m_curves.size())
        return nullptr;
    const QVector<CurveViewKey>& keys = m_curves[ref.curve].keys;
    return ref.key >= 0 && ref.key < keys.size() ? &keys[ref.key] : nullptr;
}

bool CurveView::isSelected(CurveKeyRef ref) const
{
    return std::binary_search(m_selection.begin(), m_selection.end(), ref, lessByCurveThenKey);
}

void CurveView::normalizeSelection(QList<CurveKeyRef>& keys) const
{
    keys.erase(std::remove_if(keys.begin(), keys.end(), [this](CurveKeyRef ref) { return !keyAt(ref); }), keys.end());
    std::sort(keys.begin(), keys.end(), lessByCurveThenKey);
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
}

void CurveView::changeSelection(QList<CurveKeyRef> keys)
{
    normalizeSelection(keys);
    if (keys == m_selection)
        return;
    m_selection = std::move(keys);
    updateMenuActions();
    update();
    emit selectionChanged();
}

// ---------------------------------------------------------------------------------------------
// Mapping and framing

void CurveView::updateGutters()
{
    const QFontMetricsF metrics(font());
    m_leftGutter = std::ceil(metrics.horizontalAdvance(QStringLiteral("-00.000")) + 12);
    m_bottomGutter = std::ceil(metrics.height() + 10);
}

QRectF CurveView::plotRect() const
{
    return QRectF(m_leftGutter, 0, std::max(qreal(width()) - m_leftGutter, qreal(1)),
                  std::max(qreal(height()) - m_bottomGutter, qreal(1)));
}

CurveView::Mapping CurveView::mapping() const
{
    Mapping m;
    m.plot = plotRect();
    m.t0 = m_t0;
    m.v0 = m_v0;
    m.sx = m.plot.width() / (m_t1 - m_t0);
    m.sy = m.plot.height() / (m_v1 - m_v0);
    return m;
}

QPointF CurveView::toWidget(QPointF curvePoint) const
{
    return mapping().map(curvePoint);
}

QPointF CurveView::fromWidget(QPointF pixel) const
{
    return mapping().unmap(pixel);
}

void CurveView::setVisible(double t0, double t1, double v0, double v1)
{
    if (!std::isfinite(t0) || !std::isfinite(t1) || !std::isfinite(v0) || !std::isfinite(v1))
        return;
    auto clampSpan = [](double& a, double& b) {
        const double span = std::clamp(b - a, kMinSpan, kMaxSpan);
        const double centre = 0.5 * (a + b);
        a = centre - 0.5 * span;
        b = centre + 0.5 * span;
    };
    clampSpan(t0, t1);
    clampSpan(v0, v1);
    m_t0 = t0;
    m_t1 = t1;
    m_v0 = v0;
    m_v1 = v1;
    update();
}

void CurveView::fitBounds(double t0, double t1, double v0, double v1)
{
    // Flat or single-point data still gets a sensible window around it.
    if (t1 - t0 < 1e-6) {
        t0 -= 0.5;
        t1 += 0.5;
    }
    if (v1 - v0 < 1e-6) {
        v0 -= 0.5;
        v1 += 0.5;
    }
    const QRectF plot = plotRect();
    const double usableW = std::max(plot.width() - 2 * kFramePaddingX, plot.width() * 0.5);
    const double usableH = std::max(plot.height() - 2 * kFramePaddingY, plot.height() * 0.5);
    const double padT = (t1 - t0) / usableW * (plot.width() - usableW) * 0.5;
    const double padV = (v1 - v0) / usableH * (plot.height() - usableH) * 0.5;
    setVisible(t0 - padT, t1 + padT, v0 - padV, v1 + padV);
}

double CurveView::domainViewEnd() const
{
    return std::isfinite(m_domainEnd) ? m_domainEnd : m_domainStart + kOpenEndedSpan;
}

void CurveView::autoFrame()
{
    // The action's domain in time, at least 0..1 in value (weights), and every key and sample
    // value (samples are taken only within the domain's window: an open-ended action may be
    // sampled far beyond what is shown).
    double t0 = m_domainStart, t1 = domainViewEnd(), v0 = 0, v1 = 1;
    const double sampleT0 = t0, sampleT1 = t1;
    for (const CurveViewCurve& curve : m_curves) {
        for (const QPointF& s : curve.samples) {
            if (s.x() >= sampleT0 && s.x() <= sampleT1 && std::isfinite(s.y())) {
                v0 = std::min(v0, s.y());
                v1 = std::max(v1, s.y());
            }
        }
        for (const CurveViewKey& k : curve.keys) {
            if (!std::isfinite(k.time) || !std::isfinite(k.value))
                continue;
            t0 = std::min(t0, k.time);
            t1 = std::max(t1, k.time);
            v0 = std::min(v0, k.value);
            v1 = std::max(v1, k.value);
        }
    }
    fitBounds(t0, t1, v0, v1);
}

void CurveView::frameAll()
{
    constexpr double inf = std::numeric_limits<double>::infinity();
    double t0 = inf, t1 = -inf, v0 = inf, v1 = -inf;
    auto grow = [&](double t, double v) {
        if (!std::isfinite(t) || !std::isfinite(v))
            return;
        t0 = std::min(t0, t);
        t1 = std::max(t1, t);
        v0 = std::min(v0, v);
        v1 = std::max(v1, v);
    };
    for (const CurveViewCurve& curve : m_curves) {
        for (const QPointF& s : curve.samples)
            grow(s.x(), s.y());
        for (const CurveViewKey& k : curve.keys)
            grow(k.time, k.value);
    }
    m_autoFrame = false;
    if (t0 > t1) { // nothing to fit: the domain
        fitBounds(m_domainStart, domainViewEnd(), 0, 1);
        return;
    }
    fitBounds(t0, t1, v0, v1);
}

// ---------------------------------------------------------------------------------------------
// Hit testing

QPointF CurveView::tangentHandle(CurveKeyRef ref, bool outSide) const
{
    const CurveViewKey* key = keyAt(ref);
    if (!key)
        return {};
    const Mapping m = mapping();
    // The slope's direction as it looks on screen (y down), a fixed length in pixels.
    const double slope = outSide ? key->outSlope : key->inSlope;
    double dx = m.sx, dy = -slope * m.sy;
    const double length = std::hypot(dx, dy);
    if (!(length > 0) || !std::isfinite(length)) {
        dx = 0;
        dy = slope > 0 ? -1 : 1;
    } else {
        dx /= length;
        dy /= length;
    }
    const QPointF direction(dx * kHandleLength, dy * kHandleLength);
    const QPointF centre = m.map(key->time, key->value);
    return outSide ? centre + direction : centre - direction;
}

CurveKeyRef CurveView::keyUnder(QPointF pixel) const
{
    const Mapping m = mapping();
    CurveKeyRef best;
    double bestDistance = kKeyHitRadius;
    // Later curves are drawn on top: on a tie they win.
    for (int c = int(m_curves.size()) - 1; c >= 0; --c) {
        const QVector<CurveViewKey>& keys = m_curves[c].keys;
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

CurveKeyRef CurveView::handleUnder(QPointF pixel, bool* outSide) const
{
    CurveKeyRef best;
    double bestDistance = kHandleHitRadius;
    for (const CurveKeyRef& ref : m_selection) {
        const CurveViewKey* key = keyAt(ref);
        if (!key || !hasHandles(key->mode))
            continue;
        for (bool out : {false, true}) {
            const QPointF d = tangentHandle(ref, out) - pixel;
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

int CurveView::editableCurveNear(QPointF pixel) const
{
    const Mapping m = mapping();
    const double window = (kCurveHitDistance + 1) / m.sx; // seconds either side worth checking
    const double t = m.unmap(pixel).x();
    int best = -1;
    double bestDistance = kCurveHitDistance;
    auto consider = [&](int curve, QPointF a, QPointF b) {
        const double distance = distanceToSegment(pixel, m.map(a), m.map(b));
        if (distance <= bestDistance) {
            bestDistance = distance;
            best = curve;
        }
    };
    for (int c = 0; c < m_curves.size(); ++c) {
        if (!isEditable(c))
            continue;
        const CurveViewCurve& curve = m_curves[c];
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

QList<CurveKeyRef> CurveView::keysIn(const QRectF& pixelRect) const
{
    const Mapping m = mapping();
    const QRectF rect = pixelRect.normalized();
    QList<CurveKeyRef> found;
    for (int c = 0; c < m_curves.size(); ++c) {
        const QVector<CurveViewKey>& keys = m_curves[c].keys;
        for (int k = 0; k < keys.size(); ++k)
            if (rect.contains(m.map(keys[k].time, keys[k].value)))
                found.append({c, k});
    }
    return found;
}

// ---------------------------------------------------------------------------------------------
// Intents

QPointF CurveView::moveDelta(QPointF pixel, Qt::KeyboardModifiers modifiers) const
{
    QPointF d = pixel - m_pressPos;
    if (modifiers & Qt::ShiftModifier) { // constrain to the dominant axis
        if (std::abs(d.x()) >= std::abs(d.y()))
            d.setY(0);
        else
            d.setX(0);
    }
    const Mapping m = mapping();
    return {d.x() / m.sx, -d.y() / m.sy};
}

void CurveView::emitTangent(QPointF pixel, bool finished)
{
    const CurveViewKey* key = keyAt(m_pressKey);
    if (!key)
        return;
    const Mapping m = mapping();
    const QPointF d = pixel - m.map(key->time, key->value);
    // The out handle stays right of its key and the in handle left: at worst it is vertical.
    const double dx = m_tangentOutSide ? std::max(d.x(), 1.0) : std::min(d.x(), -1.0);
    const double slope = (-d.y() / m.sy) / (dx / m.sx);
    double in = slope, out = slope;
    if (key->mode == CurveTangent::Broken) {
        in = m_tangentOutSide ? m_tangentIn : slope;
        out = m_tangentOutSide ? slope : m_tangentOut;
    }
    emit tangentRequested(m_pressKey, in, out, finished);
}

void CurveView::requestDelete()
{
    if (m_selection.isEmpty())
        return;
    m_autoFrame = false;
    const QList<CurveKeyRef> keys = m_selection;
    emit keysDeleteRequested(keys);
    // The indices no longer name the same keys once they are gone.
    m_selection.clear();
    m_hoverKey = {};
    updateMenuActions();
    update();
    emit selectionChanged();
}

void CurveView::requestTangentMode(CurveTangent mode)
{
    if (m_selection.isEmpty())
        return;
    emit tangentModeRequested(m_selection, mode);
    updateMenuActions(); // the check marks show the keys' modes, not the click, until told
}

void CurveView::updateMenuActions()
{
    const bool any = !m_selection.isEmpty();
    // The mode shared by every selected key, if any.
    int common = -1;
    for (const CurveKeyRef& ref : m_selection) {
        const CurveViewKey* key = keyAt(ref);
        const int mode = key ? int(key->mode) : -1;
        if (common == -1)
            common = mode;
        else if (common != mode)
            common = -2;
    }
    for (std::size_t i = 0; i < m_modeActions.size(); ++i) {
        m_modeActions[i]->setEnabled(any);
        m_modeActions[i]->setChecked(int(i) == common);
    }
    m_deleteAction->setEnabled(any);
}

// ---------------------------------------------------------------------------------------------
// Events

void CurveView::mousePressEvent(QMouseEvent* event)
{
    if (m_drag != Drag::None) // a second button during a gesture: the first one rules
        return;
    const QPointF pos = event->position();
    m_pressPos = pos;
    m_dragPos = pos;
    m_pressModifiers = event->modifiers();
    m_dragModifiers = event->modifiers();
    m_dragButton = event->button();
    if (event->button() == Qt::MiddleButton
        || (event->button() == Qt::LeftButton && (event->modifiers() & Qt::AltModifier))) {
        m_drag = Drag::Pan;
        m_panT0 = m_t0;
        m_panT1 = m_t1;
        m_panV0 = m_v0;
        m_panV1 = m_v1;
        setCursor(Qt::ClosedHandCursor);
        return;
    }
    if (event->button() != Qt::LeftButton) {
        QWidget::mousePressEvent(event);
        return;
    }
    const bool toggle = event->modifiers() & (Qt::ShiftModifier | Qt::ControlModifier);

    bool outSide = false;
    if (const CurveKeyRef handle = handleUnder(pos, &outSide); handle.curve >= 0) {
        const CurveViewKey* key = keyAt(handle);
        m_drag = Drag::Tangent;
        m_pressKey = handle;
        m_tangentOutSide = outSide;
        m_tangentMoved = false;
        m_tangentIn = key->inSlope;
        m_tangentOut = key->outSlope;
        return;
    }

    if (const CurveKeyRef key = keyUnder(pos); key.curve >= 0) {
        m_pressKey = key;
        m_collapseOnRelease = false;
        if (toggle) {
            QList<CurveKeyRef> keys = m_selection;
            if (isSelected(key))
                keys.removeOne(key);
            else
                keys.append(key);
            changeSelection(keys);
        } else if (!isSelected(key)) {
            changeSelection({key});
        } else {
            m_collapseOnRelease = m_selection.size() > 1;
        }
        m_drag = isSelected(key) ? Drag::PendingKey : Drag::None;
        return;
    }

    m_drag = Drag::PendingBox;
    m_selectionAtPress = m_selection;
}

void CurveView::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    const bool pastThreshold = (pos - m_pressPos).manhattanLength() >= kDragThreshold;
    switch (m_drag) {
    case Drag::None: {
        // Hover feedback.
        bool outSide = false;
        const CurveKeyRef handle = handleUnder(pos, &outSide);
        const CurveKeyRef key = handle.curve >= 0 ? CurveKeyRef{} : keyUnder(pos);
        if (!(handle == m_hoverHandle) || outSide != m_hoverHandleOut || !(key == m_hoverKey)) {
            m_hoverHandle = handle;
            m_hoverHandleOut = outSide;
            m_hoverKey = key;
            update();
        }
        break;
    }
    case Drag::PendingKey:
        if (!pastThreshold)
            break;
        m_drag = Drag::MovingKeys;
        m_dragKeys = m_selection;
        m_autoFrame = false;
        setCursor(Qt::SizeAllCursor);
        [[fallthrough]];
    case Drag::MovingKeys:
        m_dragPos = pos;
        m_dragModifiers = event->modifiers();
        update(); // the readout
        emit keysMoveRequested(m_dragKeys, moveDelta(pos, event->modifiers()), false);
        break;
    case Drag::PendingBox:
        if (!pastThreshold)
            break;
        m_drag = Drag::Box;
        [[fallthrough]];
    case Drag::Box: {
        m_dragPos = pos;
        QList<CurveKeyRef> keys = keysIn(QRectF(m_pressPos, pos));
        if (m_pressModifiers & (Qt::ShiftModifier | Qt::ControlModifier))
            keys += m_selectionAtPress;
        // Shown live; selectionChanged is emitted once, on release.
        normalizeSelection(keys);
        if (keys != m_selection) {
            m_selection = std::move(keys);
            updateMenuActions();
        }
        update();
        break;
    }
    case Drag::Tangent:
        if (!m_tangentMoved && !pastThreshold)
            break;
        m_tangentMoved = true;
        m_autoFrame = false;
        m_dragPos = pos;
        emitTangent(pos, false);
        break;
    case Drag::Pan: {
        const Mapping m = mapping();
        const QPointF d = pos - m_pressPos;
        const double dt = d.x() / m.sx, dv = d.y() / m.sy;
        m_autoFrame = false;
        setVisible(m_panT0 - dt, m_panT1 - dt, m_panV0 + dv, m_panV1 + dv);
        break;
    }
    }
}

void CurveView::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != m_dragButton)
        return;
    const QPointF pos = event->position();
    const Drag drag = m_drag;
    m_drag = Drag::None;
    unsetCursor();
    switch (drag) {
    case Drag::None:
        break;
    case Drag::PendingKey:
        if (m_collapseOnRelease)
            changeSelection({m_pressKey});
        break;
    case Drag::MovingKeys:
        emit keysMoveRequested(m_dragKeys, moveDelta(pos, event->modifiers()), true);
        m_dragKeys.clear();
        break;
    case Drag::PendingBox:
        if (m_pressModifiers & Qt::ControlModifier) {
            if (const int curve = editableCurveNear(pos); curve >= 0) {
                m_autoFrame = false;
                emit keyAddRequested(curve, fromWidget(pos));
            }
        } else if (!(m_pressModifiers & Qt::ShiftModifier)) {
            changeSelection({});
        }
        break;
    case Drag::Box:
        update();
        if (m_selection != m_selectionAtPress)
            emit selectionChanged();
        break;
    case Drag::Tangent:
        if (m_tangentMoved)
            emitTangent(pos, true);
        break;
    case Drag::Pan:
        break;
    }
}

void CurveView::mouseDoubleClickEvent(QMouseEvent* event)
{
    if (event->button() != Qt::LeftButton) {
        QWidget::mouseDoubleClickEvent(event);
        return;
    }
    // Not QWidget's default (a second press): a double-click only ever adds a key.
    m_drag = Drag::None;
    const QPointF pos = event->position();
    bool outSide = false;
    if (keyUnder(pos).curve >= 0 || handleUnder(pos, &outSide).curve >= 0)
        return;
    if (const int curve = editableCurveNear(pos); curve >= 0) {
        m_autoFrame = false;
        emit keyAddRequested(curve, fromWidget(pos));
    }
}

void CurveView::wheelEvent(QWheelEvent* event)
{
    const QPoint angle = event->angleDelta();
    const int steps = angle.y() != 0 ? angle.y() : angle.x(); // Shift turns the wheel sideways on some systems
    if (steps == 0) {
        event->ignore();
        return;
    }
    const double factor = std::pow(0.85, steps / 120.0);
    const bool valueOnly = event->modifiers() & Qt::ControlModifier;
    const bool timeOnly = event->modifiers() & Qt::ShiftModifier;
    const QPointF about = fromWidget(event->position());
    double t0 = m_t0, t1 = m_t1, v0 = m_v0, v1 = m_v1;
    if (!valueOnly) {
        t0 = about.x() - (about.x() - t0) * factor;
        t1 = about.x() + (t1 - about.x()) * factor;
    }
    if (!timeOnly) {
        v0 = about.y() - (about.y() - v0) * factor;
        v1 = about.y() + (v1 - about.y()) * factor;
    }
    m_autoFrame = false;
    setVisible(t0, t1, v0, v1);
    event->accept();
}

void CurveView::cancelDrag()
{
    if (m_drag == Drag::MovingKeys)
        emit keysMoveRequested(m_dragKeys, QPointF(0, 0), true);
    else if (m_drag == Drag::Tangent && m_tangentMoved)
        emit tangentRequested(m_pressKey, m_tangentIn, m_tangentOut, true);
    else if (m_drag == Drag::Box) {
        m_selection = m_selectionAtPress;
        updateMenuActions();
    }
    m_drag = Drag::None;
    m_dragKeys.clear();
    unsetCursor();
    update();
}

void CurveView::keyPressEvent(QKeyEvent* event)
{
    if (m_drag != Drag::None) {
        if (event->key() == Qt::Key_Escape || event->matches(QKeySequence::Undo)) {
            cancelDrag();
            return;
        }
        if (event->matches(QKeySequence::Redo))
            return; // nothing to redo while the drag's own edit is open
    }
    if (event->key() == Qt::Key_Delete || event->key() == Qt::Key_Backspace) {
        if (m_selection.isEmpty() || m_drag != Drag::None)
            event->ignore();
        else
            requestDelete();
        return;
    }
    if (event->key() == Qt::Key_F && !(event->modifiers() & ~Qt::KeypadModifier)) {
        frameAll();
        return;
    }
    if (event->matches(QKeySequence::SelectAll)) {
        QList<CurveKeyRef> all;
        for (int c = 0; c < m_curves.size(); ++c)
            for (int k = 0; k < m_curves[c].keys.size(); ++k)
                all.append({c, k});
        changeSelection(all);
        return;
    }
    QWidget::keyPressEvent(event);
}

void CurveView::contextMenuEvent(QContextMenuEvent* event)
{
    if (m_drag != Drag::None)
        return;
    // Right-clicking an unselected key acts on that key.
    if (const CurveKeyRef key = keyUnder(event->pos()); key.curve >= 0 && !isSelected(key))
        changeSelection({key});
    updateMenuActions();
    m_menu->popup(event->globalPos());
}

bool CurveView::event(QEvent* event)
{
    // During a drag, Escape, Undo and Redo belong to the view, not to window actions: an undo under
    // a drag would pull the document from under the drag's next steps.
    if (event->type() == QEvent::ShortcutOverride && m_drag != Drag::None) {
        auto* key = static_cast<QKeyEvent*>(event);
        if (key->key() == Qt::Key_Escape || key->matches(QKeySequence::Undo) || key->matches(QKeySequence::Redo)) {
            event->accept();
            return true;
        }
    }
    if (event->type() == QEvent::ToolTip) {
        // A key's tooltip says where it is exactly; elsewhere there is none.
        auto* help = static_cast<QHelpEvent*>(event);
        const CurveKeyRef ref = keyUnder(help->pos());
        if (const CurveViewKey* key = keyAt(ref); key && m_drag == Drag::None) {
            const QString mode = m_modeActions[std::size_t(key->mode)]->text();
            QToolTip::showText(help->globalPos(),
                               tr("%1, key %2\nTime %3 s, value %4\nTangents: %5")
                                   .arg(m_curves[ref.curve].name)
                                   .arg(ref.key + 1)
                                   .arg(QString::number(key->time, 'f', 3), QString::number(key->value, 'f', 3), mode),
                               this);
        } else {
            QToolTip::hideText();
            event->ignore();
        }
        return true;
    }
    return QWidget::event(event);
}

void CurveView::leaveEvent(QEvent* event)
{
    if (m_hoverKey.curve >= 0 || m_hoverHandle.curve >= 0) {
        m_hoverKey = {};
        m_hoverHandle = {};
        update();
    }
    QWidget::leaveEvent(event);
}

void CurveView::resizeEvent(QResizeEvent* event)
{
    if (m_autoFrame)
        autoFrame(); // the padding is in pixels
    QWidget::resizeEvent(event);
}

void CurveView::changeEvent(QEvent* event)
{
    if (event->type() == QEvent::FontChange)
        updateGutters();
    QWidget::changeEvent(event);
}

QSize CurveView::sizeHint() const
{
    return {700, 320};
}

QSize CurveView::minimumSizeHint() const
{
    return {400, 200};
}

// ---------------------------------------------------------------------------------------------
// Painting

void CurveView::paintEvent(QPaintEvent*)
{
    QPainter painter(this);
    const Colors colors(palette());
    const QRectF plot = plotRect();
    paintGrid(painter, colors, plot);

    painter.save();
    painter.setClipRect(plot);
    painter.setRenderHint(QPainter::Antialiasing);
    paintCurves(painter, colors, plot);
    paintPlayhead(painter, colors, plot);
    paintKeys(painter, colors, plot);
    if (m_drag == Drag::Box) {
        const QRectF band = QRectF(m_pressPos, m_dragPos).normalized();
        painter.setRenderHint(QPainter::Antialiasing, false);
        painter.setPen(QPen(colors.highlight, 1));
        painter.setBrush(withAlpha(colors.highlight, 45));
        painter.drawRect(band.adjusted(0.5, 0.5, -0.5, -0.5));
    }
    if (m_curves.isEmpty() && !m_placeholder.isEmpty()) {
        painter.setPen(colors.label);
        painter.drawText(plot.adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, m_placeholder);
    }
    painter.restore();

    painter.setRenderHint(QPainter::Antialiasing);
    paintOverlays(painter, colors, plot);
}

void CurveView::paintGrid(QPainter& painter, const Colors& colors, const QRectF& plot)
{
    const Mapping m = mapping();
    painter.fillRect(rect(), colors.gutter);
    painter.fillRect(plot, colors.background);

    // Outside the action's domain: shaded, with its edges marked.
    const double domainLeft = m.map(m_domainStart, 0).x();
    const double domainRight = std::isfinite(m_domainEnd) ? m.map(m_domainEnd, 0).x() : plot.right() + 1;
    if (domainLeft > plot.left())
        painter.fillRect(QRectF(plot.left(), plot.top(), std::min(domainLeft, plot.right()) - plot.left(), plot.height()), colors.outside);
    if (domainRight < plot.right())
        painter.fillRect(QRectF(std::max(domainRight, plot.left()), plot.top(), plot.right() - std::max(domainRight, plot.left()), plot.height()),
                         colors.outside);

    const QFontMetricsF metrics(painter.font());
    const double textHeight = metrics.height();

    // Time: vertical lines, labels along the bottom. Steps wide enough for the widest label.
    int timeMinor = 5;
    const double labelWidth = metrics.horizontalAdvance(tr("%1 s").arg(QStringLiteral("-00.00")));
    const double timeStep = niceStep(m.sx, labelWidth + 24, &timeMinor);
    const double timeMinorStep = timeStep / timeMinor;
    const bool drawTimeMinor = timeMinorStep * m.sx >= 8;
    // Value: horizontal lines, labels at the left.
    int valueMinor = 5;
    const double valueStep = niceStep(m.sy, textHeight * 2.2, &valueMinor);
    const double valueMinorStep = valueStep / valueMinor;
    const bool drawValueMinor = valueMinorStep * m.sy >= 7;

    painter.setRenderHint(QPainter::Antialiasing, false);
    auto crisp = [](double coordinate) { return std::floor(coordinate) + 0.5; };

    {
        const double step = drawTimeMinor ? timeMinorStep : timeStep;
        const long long first = (long long)std::ceil(m_t0 / step), last = (long long)std::floor(m_t1 / step);
        for (long long i = first; i <= last && last - first < 4000; ++i) {
            const bool major = !drawTimeMinor || i % timeMinor == 0;
            const double x = crisp(m.map(double(i) * step, 0).x());
            painter.setPen(major ? colors.gridMajor : colors.gridMinor);
            painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
        }
    }
    {
        const double step = drawValueMinor ? valueMinorStep : valueStep;
        const long long first = (long long)std::ceil(m_v0 / step), last = (long long)std::floor(m_v1 / step);
        for (long long i = first; i <= last && last - first < 4000; ++i) {
            const bool major = !drawValueMinor || i % valueMinor == 0;
            const double y = crisp(m.map(0, double(i) * step).y());
            painter.setPen(major ? colors.gridMajor : colors.gridMinor);
            painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
        }
    }
    // Value 0 and 1 (a weight's off and full) stand out.
    painter.setPen(QPen(colors.gridEmphasis, 1));
    for (double v : {0.0, 1.0}) {
        const double y = crisp(m.map(0, v).y());
        if (y >= plot.top() && y <= plot.bottom())
            painter.drawLine(QPointF(plot.left(), y), QPointF(plot.right(), y));
    }
    painter.setPen(QPen(colors.domainEdge, 1, Qt::DashLine));
    if (domainLeft >= plot.left() && domainLeft <= plot.right())
        painter.drawLine(QPointF(crisp(domainLeft), plot.top()), QPointF(crisp(domainLeft), plot.bottom()));
    if (domainRight >= plot.left() && domainRight <= plot.right())
        painter.drawLine(QPointF(crisp(domainRight), plot.top()), QPointF(crisp(domainRight), plot.bottom()));

    // Labels.
    painter.setPen(colors.label);
    {
        const long long first = (long long)std::ceil(m_t0 / timeStep), last = (long long)std::floor(m_t1 / timeStep);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double t = double(i) * timeStep;
            const double x = m.map(t, 0).x();
            const QString text = tr("%1 s").arg(formatNumber(t, timeStep));
            const double w = metrics.horizontalAdvance(text);
            const double left = std::clamp(x - w / 2, plot.left() + 2, double(width()) - w - 2);
            painter.drawText(QRectF(left, plot.bottom() + 3, w + 1, m_bottomGutter - 3), Qt::AlignHCenter | Qt::AlignTop, text);
        }
        // Tick marks into the gutter.
        painter.setPen(colors.gridEmphasis);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double x = crisp(m.map(double(i) * timeStep, 0).x());
            painter.drawLine(QPointF(x, plot.bottom()), QPointF(x, plot.bottom() + 3));
        }
    }
    {
        painter.setPen(colors.label);
        const long long first = (long long)std::ceil(m_v0 / valueStep), last = (long long)std::floor(m_v1 / valueStep);
        for (long long i = first; i <= last && last - first < 1000; ++i) {
            const double v = double(i) * valueStep;
            const double y = m.map(0, v).y();
            const double top = std::clamp(y - textHeight / 2, plot.top(), plot.bottom() - textHeight);
            painter.setPen(v == 0.0 || v == 1.0 ? colors.strongLabel : colors.label);
            painter.drawText(QRectF(0, top, m_leftGutter - 7, textHeight), Qt::AlignRight | Qt::AlignVCenter,
                             formatNumber(v, valueStep));
        }
    }
}

void CurveView::paintCurves(QPainter& painter, const Colors&, const QRectF&)
{
    const Mapping m = mapping();
    const double margin = 2 / m.sx; // one sample beyond each edge is kept anyway
    for (const CurveViewCurve& curve : m_curves) {
        const QVector<QPointF>& s = curve.samples;
        if (s.isEmpty())
            continue;
        // Only the samples on screen (and one either side, so the line reaches the edges).
        auto first = std::lower_bound(s.begin(), s.end(), m_t0 - margin, [](const QPointF& p, double x) { return p.x() < x; });
        auto last = std::upper_bound(s.begin(), s.end(), m_t1 + margin, [](double x, const QPointF& p) { return x < p.x(); });
        if (first != s.begin())
            --first;
        if (last != s.end())
            ++last;
        m_polyline.clear();
        QPointF previous(-1e9, -1e9);
        for (auto it = first; it != last; ++it) {
            const QPointF p = m.map(*it);
            // Dense sampling: drop points that land on the same pixel column and row.
            if (std::abs(p.x() - previous.x()) < 0.5 && std::abs(p.y() - previous.y()) < 0.5)
                continue;
            m_polyline.append(p);
            previous = p;
        }
        const bool keyed = !curve.keys.isEmpty() || curve.keyable;
        QPen pen(curve.color, keyed ? 2.0 : 1.75);
        pen.setCapStyle(Qt::RoundCap);
        pen.setJoinStyle(Qt::RoundJoin);
        if (!keyed) // parametric: the shape is fixed, so it looks different from an editable curve
            pen.setDashPattern({5, 3});
        painter.setPen(pen);
        painter.setBrush(Qt::NoBrush);
        if (m_polyline.size() == 1)
            painter.drawPoint(m_polyline.front());
        else
            painter.drawPolyline(m_polyline.constData(), int(m_polyline.size()));
    }
}

void CurveView::paintKeys(QPainter& painter, const Colors& colors, const QRectF& plot)
{
    const Mapping m = mapping();
    const QRectF visible = plot.adjusted(-kHandleLength - 8, -kHandleLength - 8, kHandleLength + 8, kHandleLength + 8);

    // Tangent handles of selected Free / Broken keys, under the keys.
    for (const CurveKeyRef& ref : m_selection) {
        const CurveViewKey* key = keyAt(ref);
        if (!key || !hasHandles(key->mode))
            continue;
        const QPointF centre = m.map(key->time, key->value);
        if (!visible.contains(centre))
            continue;
        for (bool out : {false, true}) {
            const QPointF end = tangentHandle(ref, out);
            const bool hot = (m_drag == Drag::Tangent && m_pressKey == ref && m_tangentOutSide == out)
                             || (m_drag == Drag::None && m_hoverHandle == ref && m_hoverHandleOut == out);
            painter.setPen(QPen(colors.handle, 1.25));
            painter.drawLine(centre, end);
            painter.setPen(QPen(colors.keyOutline, 1));
            painter.setBrush(hot ? colors.highlight : colors.handle);
            painter.drawEllipse(end, hot ? kHandleRadius + 1 : kHandleRadius, hot ? kHandleRadius + 1 : kHandleRadius);
        }
    }

    for (int c = 0; c < m_curves.size(); ++c) {
        const CurveViewCurve& curve = m_curves[c];
        for (int k = 0; k < curve.keys.size(); ++k) {
            const CurveViewKey& key = curve.keys[k];
            const QPointF p = m.map(key.time, key.value);
            if (!plot.adjusted(-10, -10, 10, 10).contains(p))
                continue;
            const CurveKeyRef ref{c, k};
            const bool selected = isSelected(ref);
            const bool hover = m_drag == Drag::None && m_hoverKey == ref;
            const qreal r = kKeyRadius + (selected ? 1 : 0) + (hover ? 0.5 : 0);
            if (selected) {
                painter.setPen(QPen(colors.highlight, 2));
                painter.setBrush(colors.selectedKey);
            } else {
                painter.setPen(QPen(hover ? colors.selectedKey : colors.keyOutline, 1.25));
                painter.setBrush(curve.color);
            }
            // Smooth keys are diamonds; Linear and Constant keys are squares.
            if (key.mode == CurveTangent::Linear || key.mode == CurveTangent::Constant) {
                const qreal half = r * 0.8;
                painter.drawRect(QRectF(p.x() - half, p.y() - half, 2 * half, 2 * half));
            } else {
                const QPointF diamond[4] = {{p.x(), p.y() - r}, {p.x() + r, p.y()}, {p.x(), p.y() + r}, {p.x() - r, p.y()}};
                painter.drawPolygon(diamond, 4);
            }
        }
    }
}

void CurveView::paintPlayhead(QPainter& painter, const Colors& colors, const QRectF& plot)
{
    const Mapping m = mapping();
    const double x = m.map(m_playhead, 0).x();
    if (!std::isfinite(x) || x < plot.left() - 1 || x > plot.right() + 1)
        return;
    painter.setPen(QPen(colors.highlight, 1.5));
    painter.drawLine(QPointF(x, plot.top()), QPointF(x, plot.bottom()));
    const QPointF marker[3] = {{x - 5, plot.top()}, {x + 5, plot.top()}, {x, plot.top() + 6}};
    painter.setPen(Qt::NoPen);
    painter.setBrush(colors.highlight);
    painter.drawPolygon(marker, 3);
}

void CurveView::paintOverlays(QPainter& painter, const Colors& colors, const QRectF& plot)
{
    // The playhead's time sits on the time axis, over the labels.
    const Mapping m = mapping();
    const QFontMetricsF metrics(painter.font());
    const double px = m.map(m_playhead, 0).x();
    if (std::isfinite(px) && px >= plot.left() - 1 && px <= plot.right() + 1) {
        const QString text = QString::number(m_playhead, 'f', 2);
        const double w = metrics.horizontalAdvance(text) + 10;
        const double left = std::clamp(px - w / 2, plot.left(), double(width()) - w);
        const QRectF box(left, plot.bottom() + 1, w, metrics.height() + 4);
        painter.setPen(Qt::NoPen);
        painter.setBrush(colors.highlight);
        painter.drawRoundedRect(box, 3, 3);
        painter.setPen(colors.highlightText);
        painter.drawText(box, Qt::AlignCenter, text);
    }

    // While keys move: how far, next to the cursor.
    if (m_drag == Drag::MovingKeys) {
        const QPointF delta = moveDelta(m_dragPos, m_dragModifiers);
        auto signedNumber = [](double value) {
            return (value >= 0 ? QStringLiteral("+") : QString()) + QString::number(value, 'f', 3);
        };
        const QString text = tr("Δt %1 s   Δv %2").arg(signedNumber(delta.x()), signedNumber(delta.y()));
        const QSizeF size(metrics.horizontalAdvance(text) + 12, metrics.height() + 6);
        QPointF corner = m_dragPos + QPointF(14, 14);
        corner.setX(std::min(corner.x(), plot.right() - size.width() - 2));
        corner.setY(std::min(corner.y(), plot.bottom() - size.height() - 2));
        const QRectF box(corner, size);
        painter.setPen(QPen(colors.gridEmphasis, 1));
        painter.setBrush(withAlpha(colors.gutter, 230));
        painter.drawRoundedRect(box.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
        painter.setPen(colors.strongLabel);
        painter.drawText(box, Qt::AlignCenter, text);
    }

    if (m_curves.isEmpty())
        return;
    // Legend: top-right corner, one row per curve.
    const double swatch = 18, gap = 6, padding = 6, rowHeight = metrics.height() + 2;
    double textWidth = 0;
    for (const CurveViewCurve& curve : m_curves)
        textWidth = std::max(textWidth, metrics.horizontalAdvance(curve.name));
    const QSizeF size(padding * 2 + swatch + gap + textWidth, padding * 2 + rowHeight * double(m_curves.size()) - 2);
    const QRectF box(plot.right() - size.width() - 8, plot.top() + 8, size.width(), size.height());
    painter.setPen(QPen(colors.gridEmphasis, 1));
    painter.setBrush(withAlpha(colors.gutter, 215));
    painter.drawRoundedRect(box.adjusted(0.5, 0.5, -0.5, -0.5), 3, 3);
    double y = box.top() + padding;
    for (const CurveViewCurve& curve : m_curves) {
        const bool keyed = !curve.keys.isEmpty() || curve.keyable;
        QPen pen(curve.color, keyed ? 2.5 : 2.0);
        if (!keyed)
            pen.setDashPattern({3, 2});
        pen.setCapStyle(Qt::FlatCap);
        painter.setPen(pen);
        const double cy = y + rowHeight / 2 - 1;
        painter.drawLine(QPointF(box.left() + padding, cy), QPointF(box.left() + padding + swatch, cy));
        painter.setPen(colors.strongLabel);
        painter.drawText(QRectF(box.left() + padding + swatch + gap, y, textWidth + 1, rowHeight), Qt::AlignLeft | Qt::AlignVCenter,
                         curve.name);
        y += rowHeight;
    }
}

} // namespace thespis::widgets
