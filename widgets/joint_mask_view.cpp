#include "widgets/joint_mask_view.h"

#include <QAction>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QLabel>
#include <QMenu>
#include <QMouseEvent>
#include <QPainter>
#include <QSlider>
#include <QSpinBox>
#include <QSplitter>
#include <QStyledItemDelegate>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace thespis::widgets {

namespace {

constexpr int JointRole = Qt::UserRole;      // column 0: the joint's index
constexpr int WeightRole = Qt::UserRole + 1; // column 1: the weight as a float
constexpr int NamedRole = Qt::UserRole + 2;  // column 1: whether the mask sets the joint
constexpr int MinRadius = 2;
constexpr int MaxRadius = 100;

QColor mix(const QColor& a, const QColor& b, qreal t)
{
    return QColor::fromRgbF(float(a.redF() + (b.redF() - a.redF()) * t), float(a.greenF() + (b.greenF() - a.greenF()) * t),
                            float(a.blueF() + (b.blueF() - a.blueF()) * t));
}

bool isDark(const QColor& c)
{
    return c.lightnessF() < 0.5;
}

// Colour of the inherited (not named) joints' text in the tree.
QColor inheritedTextColor(const QPalette& palette)
{
    return mix(palette.color(QPalette::Text), palette.color(QPalette::Base), 0.45);
}

// How wide the body is around the bone that ends at `joint` (name in lower case), in metres for
// a figure whose joints span 1.55 m vertically (ankles to skull base of a 1.75 m person). H-Anim
// names first, then the usual BVH / FBX ones; 0 for joints inside the head.
qreal bodyWidth(QString name)
{
    if (name.startsWith(QLatin1String("l_")) || name.startsWith(QLatin1String("r_")))
        name.remove(0, 2);
    auto starts = [&](const char* prefix) { return name.startsWith(QLatin1String(prefix)); };
    auto has = [&](const char* part) { return name.contains(QLatin1String(part)); };
    // Inside the head (drawn as one ellipse): no capsule of their own.
    if (starts("skull_tip") || has("eye") || has("temporomandibular") || has("forehead") || has("tongue")
        || has("jaw") || name == QLatin1String("head") || has("headtop") || has("head_end"))
        return 0;
    if (starts("sacroiliac") || starts("pelvis"))
        return 0.27;
    if (starts("vl") || has("abdomen") || has("lumbar"))
        return 0.27;
    if (starts("vt") || has("spine") || has("chest") || has("thorax"))
        return 0.30;
    if (starts("vc") || starts("skullbase") || has("neck"))
        return 0.11;
    if (has("hip"))
        return 0.17;
    if (has("knee") || has("upleg") || has("thigh"))
        return 0.15;
    if (has("ankle") || has("shin") || has("calf") || name.endsWith(QLatin1String("leg")))
        return 0.10;
    if (has("tarsal") || has("talar") || has("toe") || has("foot") || has("ball"))
        return 0.07;
    if (has("sternoclavicular") || has("acromioclavicular") || has("clavicle") || has("collar"))
        return 0.13;
    if (has("shoulder"))
        return 0.12;
    if (has("elbow") || has("upperarm") || (name.endsWith(QLatin1String("arm")) && !has("fore")))
        return 0.09;
    if (has("wrist") || has("forearm"))
        return 0.075;
    if (has("carpal") || has("phalangeal") || has("thumb") || has("index") || has("middle") || has("ring")
        || has("pinky") || has("hand") || has("finger"))
        return 0.035;
    return 0.05;
}

bool isHeadJoint(const QString& name)
{
    return name == QLatin1String("skullbase") || name == QLatin1String("head");
}

} // namespace

// ------------------------------------------------------------------------------------------------
// The body picture: lays the joints out to fit, paints the figure and turns mouse gestures into
// paint strokes. Reads the joints and brush settings from its view and emits through it.

class JointMaskPicture : public QWidget {
public:
    explicit JointMaskPicture(JointMaskView* view);

    void jointsChanged(bool structure, bool positions);
    QPointF screen(int joint) const;
    int jointAt(QPointF pos) const;
    void dropStroke();
    void brushChanged();

    QSize sizeHint() const override { return {440, 480}; }
    QSize minimumSizeHint() const override { return {180, 220}; }

protected:
    void paintEvent(QPaintEvent* event) override;
    void resizeEvent(QResizeEvent* event) override;
    void mousePressEvent(QMouseEvent* event) override;
    void mouseMoveEvent(QMouseEvent* event) override;
    void mouseReleaseEvent(QMouseEvent* event) override;
    void leaveEvent(QEvent* event) override;
    void hideEvent(QHideEvent* event) override;

private:
    void ensureLayout() const;
    void layoutJoints() const;
    bool touch(QPointF from, QPointF to);
    void emitStroke(bool finished);
    void setHover(QPointF pos, bool hovering);
    QRectF hoverRect() const;
    QRectF labelRect(const QFontMetrics& metrics) const;
    QString hoverText() const;
    qreal dotRadius() const { return m_dotRadius; }

    JointMaskView* m_view;

    // Layout, computed lazily for the current size and joint positions.
    mutable bool m_layoutDirty = true;
    mutable QVector<QPointF> m_screen;   // per joint, widget coordinates
    mutable QVector<qreal> m_bodyWidth;  // per joint, pixels: the body around the bone to its parent
    mutable QVector<qreal> m_metresWidth;// per joint, body width in metres (from its name)
    mutable QVector<QPointF> m_tip;      // per joint: where the hand / foot beyond a leaf wrist or
    mutable QVector<qreal> m_tipWidth;   // ankle ends, and its width in pixels (0: none)
    mutable QRectF m_head;               // the head ellipse, empty for none
    mutable QRectF m_figure;             // bounding box of the figure
    mutable qreal m_dotRadius = 5;
    mutable QVector<char> m_leafScratch; // per joint: has no children

    // The stroke in progress.
    Qt::MouseButton m_strokeButton = Qt::NoButton;
    float m_strokeWeight = 1;
    QPointF m_last;
    QVector<int> m_stroke;
    QVector<char> m_touched;                 // per joint
    QVector<std::pair<qreal, int>> m_found;  // scratch: joints found by one touch, with their order

    // Hover.
    QPointF m_hover;
    bool m_hovering = false;
    int m_hoverJoint = -1;
};

JointMaskPicture::JointMaskPicture(JointMaskView* view) : QWidget(view), m_view(view)
{
    setObjectName(QStringLiteral("jointPicture"));
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(true);
    setSizePolicy(QSizePolicy::Expanding, QSizePolicy::Expanding);
    setFocusPolicy(Qt::ClickFocus);
}

void JointMaskPicture::jointsChanged(bool structure, bool positions)
{
    const int count = int(m_view->m_joints.size());
    if (structure) {
        dropStroke();
        m_touched.fill(0, count);
        m_stroke.reserve(count);
        m_found.reserve(count);
        m_metresWidth.resize(count);
        for (int i = 0; i < count; ++i)
            m_metresWidth[i] = bodyWidth(m_view->m_joints[i].name.toLower());
    }
    if (structure || positions)
        m_layoutDirty = true;
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
    update();
}

void JointMaskPicture::dropStroke()
{
    m_strokeButton = Qt::NoButton;
    m_stroke.clear();
    m_touched.fill(0);
}

void JointMaskPicture::brushChanged()
{
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
    update();
}

void JointMaskPicture::ensureLayout() const
{
    if (m_layoutDirty)
        layoutJoints();
}

void JointMaskPicture::layoutJoints() const
{
    m_layoutDirty = false;
    const QVector<MaskJoint>& joints = m_view->m_joints;
    const int count = int(joints.size());
    m_screen.resize(count);
    m_bodyWidth.resize(count);
    m_tip.resize(count);
    m_tipWidth.fill(0, count);
    m_head = {};
    m_figure = {};
    const QFontMetrics metrics = fontMetrics();
    if (count == 0)
        return;

    // Bounds of the joints, then of the body drawn around them.
    qreal minX = std::numeric_limits<qreal>::max(), maxX = -minX, minY = minX, maxY = -minX;
    for (const MaskJoint& joint : joints) {
        minX = std::min(minX, joint.position.x());
        maxX = std::max(maxX, joint.position.x());
        minY = std::min(minY, joint.position.y());
        maxY = std::max(maxY, joint.position.y());
    }
    // Body widths follow the figure's size, so skeletons in centimetres look the same.
    qreal span = maxY - minY;
    if (span <= 1e-9)
        span = std::max(maxX - minX, 1e-9) * 1.5;
    if (span <= 1e-9)
        span = 1.55;
    const qreal size = span / 1.55;
    // Skeletons without hands or feet (H-Anim LOA 1) still get them: a short capsule beyond a
    // wrist or ankle that has no children, so that the figure reads as a body.
    QVector<char>& leaf = m_leafScratch;
    leaf.fill(1, count);
    for (const MaskJoint& joint : joints)
        if (joint.parent >= 0 && joint.parent < count)
            leaf[joint.parent] = 0;
    int headJoint = -1;
    for (int i = 0; i < count; ++i) {
        const qreal half = 0.5 * m_metresWidth.value(i) * size;
        const QPointF p = joints[i].position;
        minX = std::min(minX, p.x() - half);
        maxX = std::max(maxX, p.x() + half);
        minY = std::min(minY, p.y() - half);
        maxY = std::max(maxY, p.y() + half);
        const int parent = joints[i].parent;
        if (parent >= 0 && parent < i) {
            const QPointF q = joints[parent].position;
            minX = std::min(minX, q.x() - half);
            maxX = std::max(maxX, q.x() + half);
            minY = std::min(minY, q.y() - half);
            maxY = std::max(maxY, q.y() + half);
        }
        if (headJoint < 0 && isHeadJoint(joints[i].name.toLower()))
            headJoint = i;
        m_tip[i] = p;
        if (leaf[i]) {
            const QString name = joints[i].name.toLower();
            QPointF along(0, -1);
            if (parent >= 0 && parent < i) {
                const QPointF d = p - joints[parent].position;
                const qreal length = std::hypot(d.x(), d.y());
                if (length > 1e-6 * size)
                    along = d / length;
            }
            qreal tipWidth = 0;
            if (name.contains(QLatin1String("wrist"))) {
                m_tip[i] = p + along * (0.09 * size);
                tipWidth = 0.055 * size;
            } else if (name.contains(QLatin1String("ankle"))) {
                m_tip[i] = p + QPointF(0, -0.05 * size);
                tipWidth = 0.085 * size;
            }
            m_tipWidth[i] = tipWidth; // metres until converted below
            if (tipWidth > 0) {
                minX = std::min(minX, m_tip[i].x() - tipWidth / 2);
                maxX = std::max(maxX, m_tip[i].x() + tipWidth / 2);
                minY = std::min(minY, m_tip[i].y() - tipWidth / 2);
                maxY = std::max(maxY, m_tip[i].y() + tipWidth / 2);
            }
        }
    }
    // The head: an ellipse above the skull base, along the neck.
    QPointF headCentre;
    const qreal headRx = 0.095 * size, headRy = 0.12 * size;
    if (headJoint >= 0) {
        const QPointF base = joints[headJoint].position;
        QPointF up(0, 1);
        const int neck = joints[headJoint].parent;
        if (neck >= 0 && neck < headJoint) {
            const QPointF d = base - joints[neck].position;
            const qreal length = std::hypot(d.x(), d.y());
            if (length > 1e-6 * size)
                up = d / length;
        }
        headCentre = base + up * (0.10 * size);
        minX = std::min(minX, headCentre.x() - headRx);
        maxX = std::max(maxX, headCentre.x() + headRx);
        minY = std::min(minY, headCentre.y() - headRy);
        maxY = std::max(maxY, headCentre.y() + headRy);
    }

    // Fit with margins, keeping the aspect ratio; room for the L / R labels at the sides and the
    // footer (hint and legend) below.
    const qreal side = metrics.horizontalAdvance(QLatin1Char('M')) + 18;
    const QRectF fit = QRectF(rect()).adjusted(side, 14, -side, -(metrics.height() + 18));
    const qreal spanX = std::max(maxX - minX, 1e-9), spanY = std::max(maxY - minY, 1e-9);
    const qreal scale = std::max(1e-9, std::min(fit.width() / spanX, fit.height() / spanY));
    const QPointF centre = fit.center();
    const qreal midX = 0.5 * (minX + maxX), midY = 0.5 * (minY + maxY);
    auto toScreen = [&](QPointF p) { return QPointF(centre.x() + (p.x() - midX) * scale, centre.y() - (p.y() - midY) * scale); };
    for (int i = 0; i < count; ++i) {
        m_screen[i] = toScreen(joints[i].position);
        m_bodyWidth[i] = m_metresWidth.value(i) * size * scale;
        m_tip[i] = toScreen(m_tip[i]);
        m_tipWidth[i] *= scale;
    }
    if (headJoint >= 0) {
        const QPointF c = toScreen(headCentre);
        m_head = QRectF(c.x() - headRx * scale, c.y() - headRy * scale, 2 * headRx * scale, 2 * headRy * scale);
    }
    m_figure = QRectF(toScreen(QPointF(minX, maxY)), toScreen(QPointF(maxX, minY)));
    // Dots grow with the picture, within limits that keep them clickable and apart.
    m_dotRadius = std::clamp(0.022 * size * scale, 3.5, 6.5);
}

QPointF JointMaskPicture::screen(int joint) const
{
    ensureLayout();
    if (joint < 0 || joint >= m_screen.size())
        return {-1, -1};
    return m_screen[joint];
}

int JointMaskPicture::jointAt(QPointF pos) const
{
    ensureLayout();
    const qreal radius = m_view->m_brushRadius;
    qreal best = radius * radius;
    int found = -1;
    for (int i = 0; i < m_screen.size(); ++i) {
        const QPointF d = m_screen[i] - pos;
        const qreal distance = QPointF::dotProduct(d, d);
        // Ties go to the later joint: it is drawn on top.
        if (distance <= best) {
            best = distance;
            found = i;
        }
    }
    return found;
}

// Adds to the stroke every joint within the brush radius of the segment from → to, in the order
// the brush meets them. Returns whether any joint was new.
bool JointMaskPicture::touch(QPointF from, QPointF to)
{
    ensureLayout();
    const qreal radius = m_view->m_brushRadius;
    const QPointF segment = to - from;
    const qreal length2 = QPointF::dotProduct(segment, segment);
    m_found.clear(); // keeps the capacity reserved in jointsChanged()
    for (int i = 0; i < m_screen.size(); ++i) {
        if (m_touched.value(i))
            continue;
        const QPointF rel = m_screen[i] - from;
        const qreal t = length2 > 1e-12 ? std::clamp(QPointF::dotProduct(rel, segment) / length2, 0.0, 1.0) : 0.0;
        const QPointF d = rel - segment * t;
        const qreal distance2 = QPointF::dotProduct(d, d);
        if (distance2 > radius * radius)
            continue;
        // The brush meets a joint when it first comes within the radius: the point on the segment
        // `sqrt(r² − d²)` before the nearest one.
        const qreal meet = t * std::sqrt(length2) - std::sqrt(std::max(0.0, radius * radius - distance2));
        m_found.append({meet + 1e-6 * std::sqrt(distance2), i});
    }
    if (m_found.isEmpty())
        return false;
    std::sort(m_found.begin(), m_found.end());
    for (const auto& [order, joint] : m_found) {
        m_touched[joint] = 1;
        m_stroke.append(joint);
    }
    return true;
}

void JointMaskPicture::emitStroke(bool finished)
{
    // A copy (shared, no allocation): a slot that calls setJoints() may drop the stroke.
    const QVector<int> joints = m_stroke;
    emit m_view->weightsPaintRequested(joints, m_strokeWeight, finished);
}

void JointMaskPicture::mousePressEvent(QMouseEvent* event)
{
    const Qt::MouseButton button = event->button();
    if (m_strokeButton != Qt::NoButton || (button != Qt::LeftButton && button != Qt::RightButton)) {
        event->ignore();
        return;
    }
    const QPointF pos = event->position();
    setHover(pos, true);
    m_strokeButton = button;
    m_strokeWeight = button == Qt::LeftButton ? m_view->m_brushWeight : 0.0f;
    m_stroke.clear();
    m_touched.fill(0, int(m_view->m_joints.size()));
    m_last = pos;
    if (const int joint = jointAt(pos); joint >= 0)
        m_view->selectFromPicture(joint);
    if (m_strokeButton != Qt::NoButton && touch(pos, pos))
        emitStroke(false);
    update();
}

void JointMaskPicture::mouseMoveEvent(QMouseEvent* event)
{
    const QPointF pos = event->position();
    setHover(pos, true);
    if (m_strokeButton == Qt::NoButton)
        return;
    const QPointF from = m_last;
    m_last = pos;
    if (touch(from, pos))
        emitStroke(false);
}

void JointMaskPicture::mouseReleaseEvent(QMouseEvent* event)
{
    if (event->button() != m_strokeButton || m_strokeButton == Qt::NoButton) {
        event->ignore();
        return;
    }
    const QPointF pos = event->position();
    if (pos != m_last)
        touch(m_last, pos);
    const bool any = !m_stroke.isEmpty();
    if (any)
        emitStroke(true);
    dropStroke();
    update();
}

void JointMaskPicture::leaveEvent(QEvent*)
{
    setHover({}, false);
}

void JointMaskPicture::hideEvent(QHideEvent*)
{
    // The release will not come: close the stroke so that the editor ends its merge.
    if (m_strokeButton != Qt::NoButton && !m_stroke.isEmpty())
        emitStroke(true);
    dropStroke();
    m_hovering = false;
}

void JointMaskPicture::resizeEvent(QResizeEvent*)
{
    m_layoutDirty = true;
    if (m_hovering)
        m_hoverJoint = jointAt(m_hover);
}

QString JointMaskPicture::hoverText() const
{
    if (m_hoverJoint < 0 || m_hoverJoint >= m_view->m_joints.size())
        return {};
    const MaskJoint& joint = m_view->m_joints[m_hoverJoint];
    return QStringLiteral("%1  %2").arg(joint.name, QString::number(double(joint.weight), 'f', 2));
}

QRectF JointMaskPicture::labelRect(const QFontMetrics& metrics) const
{
    const QString text = hoverText();
    if (text.isEmpty())
        return {};
    const qreal w = metrics.horizontalAdvance(text) + 12, h = metrics.height() + 4;
    const qreal r = m_view->m_brushRadius;
    QRectF label(m_hover.x() + r * 0.75 + 4, m_hover.y() - r * 0.75 - h, w, h);
    if (label.right() > width() - 2)
        label.moveRight(m_hover.x() - r * 0.75 - 4);
    if (label.top() < 2)
        label.moveTop(m_hover.y() + r * 0.75 + 4);
    return label;
}

QRectF JointMaskPicture::hoverRect() const
{
    if (!m_hovering)
        return {};
    const qreal r = m_view->m_brushRadius + 2 + m_dotRadius + 4;
    return QRectF(m_hover.x() - r, m_hover.y() - r, 2 * r, 2 * r).united(labelRect(fontMetrics()).adjusted(-2, -2, 2, 2));
}

void JointMaskPicture::setHover(QPointF pos, bool hovering)
{
    const QRectF before = hoverRect();
    m_hover = pos;
    m_hovering = hovering;
    m_hoverJoint = hovering ? jointAt(pos) : -1;
    // Only the brush circle and the label move: repaint where they were and where they are, plus
    // the dots the brush covers (inside the circle's rectangle).
    update(before.toAlignedRect());
    update(hoverRect().toAlignedRect());
}

void JointMaskPicture::paintEvent(QPaintEvent* event)
{
    ensureLayout();
    const QRectF dirty = event->rect();
    QPainter painter(this);
    painter.setRenderHint(QPainter::Antialiasing);
    const QPalette& pal = palette();
    const QColor base = pal.color(QPalette::Base);
    const QColor text = pal.color(QPalette::Text);
    const bool dark = isDark(base);
    painter.fillRect(dirty, base);

    const QVector<MaskJoint>& joints = m_view->m_joints;
    const QFontMetrics metrics = fontMetrics();
    if (joints.isEmpty()) {
        painter.setPen(mix(text, base, 0.4));
        painter.drawText(rect().adjusted(16, 16, -16, -16), Qt::AlignCenter | Qt::TextWordWrap, JointMaskView::tr("No skeleton"));
        return;
    }
    const int count = int(joints.size());
    auto visible = [&](QPointF a, QPointF b, qreal pad) {
        return QRectF(a, b).normalized().adjusted(-pad, -pad, pad, pad).intersects(dirty);
    };

    // Silhouette: capsules along the bones and the head, first a little wider in the outline
    // colour, then in the fill colour, so that overlapping capsules merge into one outlined body.
    const QColor fill = mix(base, text, dark ? 0.09 : 0.06);
    const QColor outline = mix(base, text, dark ? 0.20 : 0.16);
    for (int pass = 0; pass < 2; ++pass) {
        const QColor color = pass == 0 ? outline : fill;
        const qreal extra = pass == 0 ? 2.5 : 0.0;
        painter.setBrush(color);
        painter.setPen(Qt::NoPen);
        if (!m_head.isEmpty())
            painter.drawEllipse(m_head.adjusted(-extra / 2, -extra / 2, extra / 2, extra / 2));
        for (int i = 0; i < count; ++i) {
            if (const qreal tw = m_tipWidth[i]; tw > 0 && visible(m_screen[i], m_tip[i], tw)) {
                painter.setPen(QPen(color, tw + extra, Qt::SolidLine, Qt::RoundCap));
                painter.drawLine(m_screen[i], m_tip[i]);
            }
            const qreal w = m_bodyWidth[i];
            if (w <= 0)
                continue;
            const int parent = joints[i].parent;
            const QPointF a = m_screen[i];
            const QPointF b = parent >= 0 && parent < i ? m_screen[parent] : a;
            if (!visible(a, b, w))
                continue;
            if (std::abs(a.x() - b.x()) + std::abs(a.y() - b.y()) < 0.5) {
                painter.setPen(Qt::NoPen);
                painter.drawEllipse(a, (w + extra) / 2, (w + extra) / 2);
            } else {
                painter.setPen(QPen(color, w + extra, Qt::SolidLine, Qt::RoundCap));
                painter.drawLine(a, b);
            }
        }
    }

    // L / R: the character faces the viewer, so its left is on the viewer's right.
    {
        QFont font = painter.font();
        font.setBold(true);
        painter.setFont(font);
        painter.setPen(mix(text, base, 0.45));
        // Beside the figure at about shoulder height, inside the margins kept for them.
        const qreal y = m_figure.top() + 0.3 * m_figure.height();
        const qreal w = metrics.horizontalAdvance(QLatin1Char('M')) + 8;
        const qreal leftX = std::max<qreal>(4, m_figure.left() - w - 8);
        const qreal rightX = std::min<qreal>(width() - 4 - w, m_figure.right() + 8);
        painter.drawText(QRectF(leftX, y - metrics.height(), w, 2 * metrics.height()), Qt::AlignCenter,
                         JointMaskView::tr("R", "the character's right side"));
        painter.drawText(QRectF(rightX, y - metrics.height(), w, 2 * metrics.height()), Qt::AlignCenter,
                         JointMaskView::tr("L", "the character's left side"));
        font.setBold(false);
        painter.setFont(font);
    }

    // Bones.
    painter.setPen(QPen(mix(base, text, 0.42), 1.5, Qt::SolidLine, Qt::RoundCap));
    for (int i = 0; i < count; ++i) {
        const int parent = joints[i].parent;
        if (parent >= 0 && parent < i && visible(m_screen[i], m_screen[parent], 2))
            painter.drawLine(m_screen[parent], m_screen[i]);
    }

    // Joints: full dots where the mask sets the weight, smaller ones where it is inherited.
    const qreal r = m_dotRadius;
    const int current = m_view->currentJoint();
    const qreal brush = m_view->m_brushRadius;
    const QColor ring = isDark(base) ? QColor(0x10, 0x12, 0x14) : QColor(0x40, 0x44, 0x4a);
    for (int i = 0; i < count; ++i) {
        const QPointF p = m_screen[i];
        if (!visible(p, p, r + 6))
            continue;
        const qreal radius = joints[i].named ? r : r * 0.72;
        painter.setPen(QPen(ring, 1.2));
        painter.setBrush(JointMaskView::weightColor(joints[i].weight, base));
        painter.drawEllipse(p, radius, radius);
        // Joints under the brush (what a click here would paint) get a thin ring.
        if (m_hovering && m_strokeButton == Qt::NoButton) {
            const QPointF d = p - m_hover;
            if (QPointF::dotProduct(d, d) <= brush * brush) {
                painter.setPen(QPen(text, 1));
                painter.setBrush(Qt::NoBrush);
                painter.drawEllipse(p, r + 2.5, r + 2.5);
            }
        }
    }
    if (current >= 0 && current < count) {
        painter.setPen(QPen(pal.color(QPalette::Highlight), 2.2));
        painter.setBrush(Qt::NoBrush);
        painter.drawEllipse(m_screen[current], r + 3.5, r + 3.5);
    }

    // Footer: how to paint, and the colour legend.
    {
        const qreal y = height() - metrics.height() - 8;
        const QColor muted = mix(text, base, 0.4);
        const qreal legendW = std::min<qreal>(72, width() * 0.2);
        const qreal digit = metrics.horizontalAdvance(QLatin1Char('0')) + 4;
        const QRectF legend(width() - 10 - digit - legendW, y + metrics.height() / 2.0 - 4, legendW, 8);
        if (QRectF(0, y - 2, width(), metrics.height() + 8).intersects(dirty)) {
            QLinearGradient gradient(legend.topLeft(), legend.topRight());
            for (int step = 0; step <= 4; ++step)
                gradient.setColorAt(step / 4.0, JointMaskView::weightColor(float(step / 4.0), base));
            painter.setPen(QPen(ring, 0.8));
            painter.setBrush(gradient);
            painter.drawRoundedRect(legend, 3, 3);
            painter.setPen(muted);
            painter.drawText(QRectF(legend.left() - digit - 2, y, digit, metrics.height()), Qt::AlignRight | Qt::AlignVCenter,
                             QStringLiteral("0"));
            painter.drawText(QRectF(legend.right() + 2, y, digit, metrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                             QStringLiteral("1"));
            const qreal hintW = legend.left() - digit - 20;
            if (hintW > 40)
                painter.drawText(QRectF(10, y, hintW, metrics.height()), Qt::AlignLeft | Qt::AlignVCenter,
                                 metrics.elidedText(JointMaskView::tr("Drag to paint · right-drag paints 0"), Qt::ElideRight,
                                                    int(hintW)));
        }
    }

    // The brush and the name of the joint under it.
    if (m_hovering) {
        const float weight = m_strokeButton == Qt::NoButton ? m_view->m_brushWeight : m_strokeWeight;
        QColor brushFill = JointMaskView::weightColor(weight, base);
        brushFill.setAlphaF(m_strokeButton == Qt::NoButton ? 0.10f : 0.22f);
        QColor brushLine = text;
        brushLine.setAlphaF(0.65f);
        painter.setPen(QPen(brushLine, 1.2, m_strokeButton == Qt::NoButton ? Qt::DashLine : Qt::SolidLine));
        painter.setBrush(brushFill);
        painter.drawEllipse(m_hover, brush, brush);
        const QRectF label = labelRect(metrics);
        if (!label.isEmpty()) {
            painter.setPen(Qt::NoPen);
            QColor back = pal.color(QPalette::ToolTipBase);
            back.setAlphaF(0.92f);
            painter.setBrush(back);
            painter.drawRoundedRect(label, 4, 4);
            painter.setPen(pal.color(QPalette::ToolTipText));
            painter.drawText(label, Qt::AlignCenter, hoverText());
        }
    }
}

// ------------------------------------------------------------------------------------------------
// The tree's delegate: paints the weight column as a number beside a small bar, edits it with a
// spin box and turns the edit into an intent instead of writing the model.

class WeightDelegate : public QStyledItemDelegate {
public:
    WeightDelegate(QObject* parent, std::function<void(int, float)> request)
        : QStyledItemDelegate(parent), m_request(std::move(request))
    {
    }

    void paint(QPainter* painter, const QStyleOptionViewItem& option, const QModelIndex& index) const override
    {
        if (index.column() != 1) {
            QStyledItemDelegate::paint(painter, option, index);
            return;
        }
        QStyleOptionViewItem opt = option;
        initStyleOption(&opt, index);
        opt.text.clear();
        const QWidget* widget = opt.widget;
        QStyle* style = widget ? widget->style() : nullptr;
        if (style)
            style->drawControl(QStyle::CE_ItemViewItem, &opt, painter, widget);

        const float weight = index.data(WeightRole).toFloat();
        const bool named = index.data(NamedRole).toBool();
        const bool selected = opt.state & QStyle::State_Selected;
        const QColor base = opt.palette.color(QPalette::Base);
        const QColor textColor = selected ? opt.palette.color(QPalette::HighlightedText) : opt.palette.color(QPalette::Text);
        const QRect r = opt.rect.adjusted(6, 0, -6, 0);
        const QFontMetrics metrics(opt.font);
        const int numberW = metrics.horizontalAdvance(QStringLiteral("0.00")) + 4;
        const QRectF bar(r.left(), r.center().y() - 2.5, std::max(8, r.width() - numberW - 6), 5);

        painter->save();
        painter->setRenderHint(QPainter::Antialiasing);
        painter->setPen(Qt::NoPen);
        painter->setBrush(mix(base, opt.palette.color(QPalette::Text), 0.14));
        painter->drawRoundedRect(bar, 2, 2);
        QColor fill = JointMaskView::weightColor(weight, base);
        if (!named)
            fill.setAlphaF(0.6f);
        if (weight > 0) {
            painter->setBrush(fill);
            painter->drawRoundedRect(QRectF(bar.left(), bar.top(), std::max(bar.height(), bar.width() * double(weight)), bar.height()), 2, 2);
        }
        painter->setFont(opt.font);
        painter->setPen(textColor);
        painter->drawText(QRect(r.right() - numberW, r.top(), numberW, r.height()), Qt::AlignRight | Qt::AlignVCenter,
                          QString::number(double(weight), 'f', 2));
        painter->restore();
    }

    QWidget* createEditor(QWidget* parent, const QStyleOptionViewItem&, const QModelIndex& index) const override
    {
        if (index.column() != 1)
            return nullptr; // joint names are not edited here
        auto* spin = new QDoubleSpinBox(parent);
        spin->setObjectName(QStringLiteral("weightEditor"));
        spin->setRange(0.0, 1.0);
        spin->setSingleStep(0.05);
        spin->setDecimals(2);
        spin->setFrame(false);
        spin->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
        return spin;
    }

    void setEditorData(QWidget* editor, const QModelIndex& index) const override
    {
        if (auto* spin = qobject_cast<QDoubleSpinBox*>(editor))
            spin->setValue(double(index.data(WeightRole).toFloat()));
    }

    void setModelData(QWidget* editor, QAbstractItemModel*, const QModelIndex& index) const override
    {
        // The view shows what the editor feeds it: ask instead of writing the model.
        auto* spin = qobject_cast<QDoubleSpinBox*>(editor);
        if (!spin)
            return;
        spin->interpretText();
        const float value = float(spin->value());
        const float shown = index.data(WeightRole).toFloat();
        // Typing the shown value into an inherited joint still means something: it names it.
        if (std::abs(value - shown) > 1e-4f || !index.data(NamedRole).toBool())
            m_request(index.siblingAtColumn(0).data(JointRole).toInt(), value);
    }

    void updateEditorGeometry(QWidget* editor, const QStyleOptionViewItem& option, const QModelIndex&) const override
    {
        editor->setGeometry(option.rect);
    }

private:
    std::function<void(int, float)> m_request;
};

// ------------------------------------------------------------------------------------------------

QColor JointMaskView::weightColor(float weight, const QColor& base)
{
    const float t = std::isfinite(weight) ? std::clamp(weight, 0.0f, 1.0f) : 0.0f;
    const bool dark = isDark(base);
    // Grey at 0 towards a saturated orange at 1, in HSL: the hue stays that of the accent while
    // saturation and lightness move, so half weights read as a muted version of the accent.
    const QColor zero = dark ? QColor(0x70, 0x74, 0x7b) : QColor(0xa9, 0xad, 0xb3);
    const QColor one = dark ? QColor(0xff, 0x8c, 0x1a) : QColor(0xef, 0x6c, 0x00);
    const float hue = one.hslHueF();
    const float saturation = zero.hslSaturationF() + (one.hslSaturationF() - zero.hslSaturationF()) * t;
    const float lightness = zero.lightnessF() + (one.lightnessF() - zero.lightnessF()) * t;
    return QColor::fromHslF(hue, saturation, lightness);
}

JointMaskView::JointMaskView(QWidget* parent) : QWidget(parent)
{
    m_tree = new QTreeWidget(this);
    m_tree->setObjectName(QStringLiteral("jointTree"));
    m_tree->setColumnCount(2);
    m_tree->setHeaderLabels({tr("Joint"), tr("Weight")});
    m_tree->setUniformRowHeights(true);
    // H-Anim hierarchies are deep (a spine of 24 vertebrae): a narrow indentation keeps names readable.
    m_tree->setIndentation(12);
    m_tree->setSelectionMode(QAbstractItemView::SingleSelection);
    m_tree->setEditTriggers(QAbstractItemView::DoubleClicked | QAbstractItemView::EditKeyPressed
                            | QAbstractItemView::SelectedClicked);
    m_tree->setContextMenuPolicy(Qt::CustomContextMenu);
    m_tree->setItemDelegate(new WeightDelegate(m_tree, [this](int joint, float weight) {
        if (joint >= 0 && joint < m_joints.size())
            emit weightRequested(joint, weight);
    }));
    m_tree->header()->setStretchLastSection(false);
    m_tree->header()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_tree->header()->setSectionResizeMode(1, QHeaderView::Fixed);
    m_tree->header()->resizeSection(1, m_tree->fontMetrics().horizontalAdvance(QStringLiteral("0.00")) + 56);
    m_tree->header()->setDefaultAlignment(Qt::AlignLeft | Qt::AlignVCenter);
    connect(m_tree, &QTreeWidget::currentItemChanged, this, [this](QTreeWidgetItem* current) { onCurrentItemChanged(current); });
    connect(m_tree, &QWidget::customContextMenuRequested, this, &JointMaskView::onTreeContextMenu);

    // The brush bar above the picture.
    auto* brushBar = new QWidget(this);
    brushBar->setObjectName(QStringLiteral("brushBar"));
    auto* bar = new QHBoxLayout(brushBar);
    bar->setContentsMargins(6, 4, 6, 4);
    bar->setSpacing(6);
    auto* weightLabel = new QLabel(tr("Brush weight"), brushBar);
    m_brushSlider = new QSlider(Qt::Horizontal, brushBar);
    m_brushSlider->setObjectName(QStringLiteral("brushWeightSlider"));
    m_brushSlider->setRange(0, 100);
    m_brushSlider->setPageStep(25);
    m_brushSlider->setMinimumWidth(60);
    m_brushSlider->setToolTip(tr("The weight a left-button stroke paints (the right button paints 0)"));
    m_brushSpin = new QDoubleSpinBox(brushBar);
    m_brushSpin->setObjectName(QStringLiteral("brushWeightSpin"));
    m_brushSpin->setRange(0.0, 1.0);
    m_brushSpin->setSingleStep(0.05);
    m_brushSpin->setDecimals(2);
    m_brushSpin->setToolTip(m_brushSlider->toolTip());
    weightLabel->setBuddy(m_brushSpin);
    auto* radiusLabel = new QLabel(tr("Radius"), brushBar);
    m_radiusSpin = new QSpinBox(brushBar);
    m_radiusSpin->setObjectName(QStringLiteral("brushRadiusSpin"));
    m_radiusSpin->setRange(MinRadius, MaxRadius);
    m_radiusSpin->setSuffix(tr(" px"));
    m_radiusSpin->setToolTip(tr("Radius of the brush in the picture"));
    radiusLabel->setBuddy(m_radiusSpin);
    bar->addWidget(weightLabel);
    bar->addWidget(m_brushSlider, 1);
    bar->addWidget(m_brushSpin);
    bar->addSpacing(8);
    bar->addWidget(radiusLabel);
    bar->addWidget(m_radiusSpin);
    connect(m_brushSlider, &QSlider::valueChanged, this, &JointMaskView::onBrushSliderMoved);
    connect(m_brushSpin, &QDoubleSpinBox::valueChanged, this, &JointMaskView::onBrushSpinChanged);
    connect(m_radiusSpin, &QSpinBox::valueChanged, this, &JointMaskView::onRadiusSpinChanged);

    m_picture = new JointMaskPicture(this);
    auto* right = new QWidget(this);
    auto* rightLayout = new QVBoxLayout(right);
    rightLayout->setContentsMargins(0, 0, 0, 0);
    rightLayout->setSpacing(0);
    rightLayout->addWidget(brushBar);
    rightLayout->addWidget(m_picture, 1);

    m_splitter = new QSplitter(Qt::Horizontal, this);
    m_splitter->setObjectName(QStringLiteral("jointMaskSplitter"));
    m_splitter->addWidget(m_tree);
    m_splitter->addWidget(right);
    m_splitter->setChildrenCollapsible(false);
    m_splitter->setStretchFactor(0, 0);
    m_splitter->setStretchFactor(1, 1);
    m_splitter->setSizes({320, 440});
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(m_splitter);

    setBrushWeight(m_brushWeight);
    setBrushRadius(m_brushRadius);
}

JointMaskView::~JointMaskView()
{
    // The picture's hide event (sent while QWidget tears the children down) must not emit a
    // finished stroke through a view that is half destroyed.
    m_picture->dropStroke();
}

QWidget* JointMaskView::picture() const
{
    return m_picture;
}

void JointMaskView::setJoints(QVector<MaskJoint> joints)
{
    bool sameStructure = joints.size() == m_joints.size();
    bool samePositions = sameStructure;
    for (int i = 0; sameStructure && i < joints.size(); ++i) {
        sameStructure = joints[i].name == m_joints[i].name && joints[i].parent == m_joints[i].parent;
        samePositions = samePositions && joints[i].position == m_joints[i].position;
    }
    for (MaskJoint& joint : joints)
        joint.weight = std::isfinite(joint.weight) ? std::clamp(joint.weight, 0.0f, 1.0f) : 0.0f;
    m_joints = std::move(joints);
    if (sameStructure) {
        for (int i = 0; i < m_joints.size(); ++i)
            updateItem(i);
    } else {
        buildTree();
    }
    m_picture->jointsChanged(!sameStructure, !samePositions);
}

void JointMaskView::buildTree()
{
    const QTreeWidgetItem* current = m_tree->currentItem();
    const QString currentName = current ? current->text(0) : QString();
    m_updating = true;
    m_tree->clear();
    m_items.clear();
    m_items.reserve(m_joints.size());
    QTreeWidgetItem* restore = nullptr;
    for (int i = 0; i < m_joints.size(); ++i) {
        const int parent = m_joints[i].parent;
        auto* item = parent >= 0 && parent < i ? new QTreeWidgetItem(m_items[parent]) : new QTreeWidgetItem(m_tree);
        item->setFlags(Qt::ItemIsSelectable | Qt::ItemIsEnabled | Qt::ItemIsEditable);
        item->setText(0, m_joints[i].name);
        item->setData(0, JointRole, i);
        m_items.append(item);
        if (!restore && !currentName.isEmpty() && m_joints[i].name == currentName)
            restore = item;
        updateItem(i);
    }
    m_tree->expandAll();
    if (restore)
        m_tree->setCurrentItem(restore);
    m_updating = false;
}

void JointMaskView::updateItem(int joint)
{
    QTreeWidgetItem* item = m_items.value(joint);
    if (!item)
        return;
    const MaskJoint& j = m_joints[joint];
    item->setData(1, WeightRole, j.weight);
    item->setData(1, NamedRole, j.named);
    item->setData(1, Qt::DisplayRole, QString::number(double(j.weight), 'f', 2));
    QFont font = m_tree->font();
    font.setItalic(!j.named);
    const QBrush foreground = j.named ? QBrush() : QBrush(inheritedTextColor(m_tree->palette()));
    for (int column = 0; column < 2; ++column) {
        item->setData(column, Qt::FontRole, j.named ? QVariant() : QVariant(font));
        item->setData(column, Qt::ForegroundRole, j.named ? QVariant() : QVariant(foreground));
    }
    item->setToolTip(0, j.named ? tr("%1: set by the mask").arg(j.name) : tr("%1: inherited").arg(j.name));
}

void JointMaskView::changeEvent(QEvent* event)
{
    QWidget::changeEvent(event);
    if (event->type() == QEvent::PaletteChange || event->type() == QEvent::FontChange) {
        for (int i = 0; i < m_items.size(); ++i)
            updateItem(i);
        m_picture->jointsChanged(false, true);
    }
}

void JointMaskView::onCurrentItemChanged(QTreeWidgetItem* current)
{
    m_picture->update();
    if (m_updating || !current)
        return;
    emit jointSelected(current->data(0, JointRole).toInt());
}

void JointMaskView::selectFromPicture(int joint)
{
    if (joint < 0 || joint >= m_items.size())
        return;
    if (currentJoint() != joint) {
        setCurrentJoint(joint);
        m_tree->scrollToItem(m_items[joint]);
    }
    emit jointSelected(joint);
}

void JointMaskView::setCurrentJoint(int joint)
{
    m_updating = true;
    m_tree->setCurrentItem(m_items.value(joint));
    m_updating = false;
    m_picture->update();
}

int JointMaskView::currentJoint() const
{
    const QTreeWidgetItem* item = m_tree->currentItem();
    return item ? item->data(0, JointRole).toInt() : -1;
}

void JointMaskView::onTreeContextMenu(const QPoint& pos)
{
    QTreeWidgetItem* item = m_tree->itemAt(pos);
    if (!item)
        return;
    const int joint = item->data(0, JointRole).toInt();
    QMenu menu(this);
    menu.setObjectName(QStringLiteral("jointWeightMenu"));
    menu.setTitle(m_joints.value(joint).name);
    const std::pair<float, QString> choices[] = {{1.0f, tr("Set to 1")}, {0.5f, tr("Set to 0.5")}, {0.0f, tr("Set to 0")}};
    for (const auto& [weight, text] : choices) {
        QAction* action = menu.addAction(text);
        const float value = weight;
        connect(action, &QAction::triggered, this, [this, joint, value] { emit weightRequested(joint, value); });
    }
    menu.exec(m_tree->viewport()->mapToGlobal(pos));
}

void JointMaskView::setBrushWeight(float weight)
{
    m_brushWeight = std::isfinite(weight) ? std::clamp(weight, 0.0f, 1.0f) : 1.0f;
    m_updating = true;
    m_brushSpin->setValue(double(m_brushWeight));
    m_brushSlider->setValue(int(std::lround(m_brushWeight * 100.0f)));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::setBrushRadius(int pixels)
{
    m_brushRadius = std::clamp(pixels, MinRadius, MaxRadius);
    m_updating = true;
    m_radiusSpin->setValue(m_brushRadius);
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onBrushSliderMoved(int value)
{
    if (m_updating)
        return;
    m_brushWeight = float(value) / 100.0f;
    m_updating = true;
    m_brushSpin->setValue(double(m_brushWeight));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onBrushSpinChanged(double value)
{
    if (m_updating)
        return;
    m_brushWeight = float(value);
    m_updating = true;
    m_brushSlider->setValue(int(std::lround(value * 100.0)));
    m_updating = false;
    m_picture->brushChanged();
}

void JointMaskView::onRadiusSpinChanged(int value)
{
    if (m_updating)
        return;
    m_brushRadius = value;
    m_picture->brushChanged();
}

QPoint JointMaskView::jointPosition(int joint) const
{
    const QPointF p = m_picture->screen(joint);
    return QPoint(int(std::lround(p.x())), int(std::lround(p.y())));
}

int JointMaskView::jointAt(QPoint picturePos) const
{
    return m_picture->jointAt(QPointF(picturePos));
}

} // namespace thespis::widgets
