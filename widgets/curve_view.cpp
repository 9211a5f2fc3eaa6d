#include "widgets/curve_view.h"

#include <QActionGroup>
#include <QContextMenuEvent>
#include <QFontMetricsF>
#include <QHelpEvent>
#include <QKeyEvent>
#include <QMenu>
#include <QToolTip>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace thespis::widgets {

namespace {

constexpr double kOpenEndedSpan = 10; // seconds shown for an open-ended action
constexpr double kMinSpan = 1e-5;
constexpr double kMaxSpan = 1e7;

} // namespace

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

bool CurveView::isSelected(CurveKeyRef ref) const
{
    return std::binary_search(m_selection.begin(), m_selection.end(), ref, curveKeyLess);
}

void CurveView::normalizeSelection(QList<CurveKeyRef>& keys) const
{
    keys.erase(std::remove_if(keys.begin(), keys.end(), [this](CurveKeyRef ref) { return !keyAt(ref); }), keys.end());
    std::sort(keys.begin(), keys.end(), curveKeyLess);
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

CurveMapping CurveView::mapping() const
{
    return CurveMapping::fit(plotRect(), m_range);
}

QPointF CurveView::toWidget(QPointF curvePoint) const
{
    return mapping().map(curvePoint);
}

QPointF CurveView::fromWidget(QPointF pixel) const
{
    return mapping().unmap(pixel);
}

QPointF CurveView::tangentHandle(CurveKeyRef ref, bool outSide) const
{
    const CurveViewKey* key = keyAt(ref);
    return key ? tangentHandlePoint(mapping(), *key, outSide) : QPointF();
}

void CurveView::setVisibleRange(CurveRange range)
{
    if (!std::isfinite(range.t0) || !std::isfinite(range.t1) || !std::isfinite(range.v0) || !std::isfinite(range.v1))
        return;
    auto clampSpan = [](double& a, double& b) {
        const double span = std::clamp(b - a, kMinSpan, kMaxSpan);
        const double centre = 0.5 * (a + b);
        a = centre - 0.5 * span;
        b = centre + 0.5 * span;
    };
    clampSpan(range.t0, range.t1);
    clampSpan(range.v0, range.v1);
    m_range = range;
    update();
}

double CurveView::domainViewEnd() const
{
    return std::isfinite(m_domainEnd) ? m_domainEnd : m_domainStart + kOpenEndedSpan;
}

void CurveView::autoFrame()
{
    setVisibleRange(framedRange(plotRect(), domainBounds(m_curves, m_domainStart, domainViewEnd())));
}

void CurveView::frameAll()
{
    m_autoFrame = false;
    // With nothing to fit: the domain.
    const CurveRange bounds = curveDataBounds(m_curves).value_or(CurveRange{m_domainStart, domainViewEnd(), 0, 1});
    setVisibleRange(framedRange(plotRect(), bounds));
}

// ---------------------------------------------------------------------------------------------
// Intents

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
    CurveRange range = m_range;
    if (!valueOnly) {
        range.t0 = about.x() - (about.x() - range.t0) * factor;
        range.t1 = about.x() + (range.t1 - about.x()) * factor;
    }
    if (!timeOnly) {
        range.v0 = about.y() - (about.y() - range.v0) * factor;
        range.v1 = about.y() + (range.v1 - about.y()) * factor;
    }
    m_autoFrame = false;
    setVisibleRange(range);
    event->accept();
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

} // namespace thespis::widgets
