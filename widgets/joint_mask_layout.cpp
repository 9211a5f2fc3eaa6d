// The joint-mask picture's pure geometry: body widths by joint name, fitting the figure into a
// rectangle, picking a joint and the joints a brush stroke meets.

#include "widgets/joint_mask_layout.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace thespis::widgets {

qreal jointBodyWidth(QString name)
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

bool isHeadJoint(const QString& lowerName)
{
    return lowerName == QLatin1String("skullbase") || lowerName == QLatin1String("head");
}

void JointMaskLayout::fitInto(const QVector<MaskJoint>& joints, const QVector<qreal>& metresWidth, const QRectF& fit,
                              const QRectF& faceOutline)
{
    const int count = int(joints.size());
    screen.resize(count);
    bodyWidth.resize(count);
    tip.resize(count);
    tipWidth.fill(0, count);
    head = {};
    figure = {};
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
    QVector<char>& leaf = m_leaf;
    leaf.fill(1, count);
    for (const MaskJoint& joint : joints)
        if (joint.parent >= 0 && joint.parent < count)
            leaf[joint.parent] = 0;
    int headJoint = -1;
    for (int i = 0; i < count; ++i) {
        const qreal half = 0.5 * metresWidth.value(i) * size;
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
        if (headJoint < 0 && faceOutline.isEmpty() && isHeadJoint(joints[i].name.toLower()))
            headJoint = i;
        tip[i] = p;
        if (leaf[i]) {
            const QString name = joints[i].name.toLower();
            QPointF along(0, -1);
            if (parent >= 0 && parent < i) {
                const QPointF d = p - joints[parent].position;
                const qreal length = std::hypot(d.x(), d.y());
                if (length > 1e-6 * size)
                    along = d / length;
            }
            qreal tipMetres = 0;
            if (name.contains(QLatin1String("wrist"))) {
                tip[i] = p + along * (0.09 * size);
                tipMetres = 0.055 * size;
            } else if (name.contains(QLatin1String("ankle"))) {
                tip[i] = p + QPointF(0, -0.05 * size);
                tipMetres = 0.085 * size;
            }
            tipWidth[i] = tipMetres; // metres until converted below
            if (tipMetres > 0) {
                minX = std::min(minX, tip[i].x() - tipMetres / 2);
                maxX = std::max(maxX, tip[i].x() + tipMetres / 2);
                minY = std::min(minY, tip[i].y() - tipMetres / 2);
                maxY = std::max(maxY, tip[i].y() + tipMetres / 2);
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

    if (!faceOutline.isEmpty()) {
        minX = std::min(minX, faceOutline.left());
        maxX = std::max(maxX, faceOutline.right());
        minY = std::min(minY, faceOutline.top());
        maxY = std::max(maxY, faceOutline.bottom());
    }

    // Fit, keeping the aspect ratio.
    const qreal spanX = std::max(maxX - minX, 1e-9), spanY = std::max(maxY - minY, 1e-9);
    const qreal scale = std::max(1e-9, std::min(fit.width() / spanX, fit.height() / spanY));
    const QPointF centre = fit.center();
    const qreal midX = 0.5 * (minX + maxX), midY = 0.5 * (minY + maxY);
    auto toScreen = [&](QPointF p) { return QPointF(centre.x() + (p.x() - midX) * scale, centre.y() - (p.y() - midY) * scale); };
    for (int i = 0; i < count; ++i) {
        screen[i] = toScreen(joints[i].position);
        bodyWidth[i] = metresWidth.value(i) * size * scale;
        tip[i] = toScreen(tip[i]);
        tipWidth[i] *= scale;
    }
    if (headJoint >= 0) {
        const QPointF c = toScreen(headCentre);
        head = QRectF(c.x() - headRx * scale, c.y() - headRy * scale, 2 * headRx * scale, 2 * headRy * scale);
    }
    if (!faceOutline.isEmpty())
        head = QRectF(toScreen(QPointF(faceOutline.left(), faceOutline.bottom())),
                      toScreen(QPointF(faceOutline.right(), faceOutline.top())));
    figure = QRectF(toScreen(QPointF(minX, maxY)), toScreen(QPointF(maxX, minY)));
    // Dots grow with the picture, within limits that keep them clickable and apart.
    dotRadius = std::clamp(0.022 * size * scale, 3.5, 6.5);
}

int JointMaskLayout::jointAt(QPointF pos, qreal radius) const
{
    qreal best = radius * radius;
    int found = -1;
    for (int i = 0; i < screen.size(); ++i) {
        const QPointF d = screen[i] - pos;
        const qreal distance = QPointF::dotProduct(d, d);
        // Ties go to the later joint: it is drawn on top.
        if (distance <= best) {
            best = distance;
            found = i;
        }
    }
    return found;
}

void JointMaskLayout::brushHits(QPointF from, QPointF to, qreal radius, const QVector<char>& skip,
                                QVector<std::pair<qreal, int>>& found) const
{
    const QPointF segment = to - from;
    const qreal length2 = QPointF::dotProduct(segment, segment);
    found.clear(); // keeps the caller's capacity
    for (int i = 0; i < screen.size(); ++i) {
        if (skip.value(i))
            continue;
        const QPointF rel = screen[i] - from;
        const qreal t = length2 > 1e-12 ? std::clamp(QPointF::dotProduct(rel, segment) / length2, 0.0, 1.0) : 0.0;
        const QPointF d = rel - segment * t;
        const qreal distance2 = QPointF::dotProduct(d, d);
        if (distance2 > radius * radius)
            continue;
        // The brush meets a joint when it first comes within the radius: the point on the segment
        // `sqrt(r² − d²)` before the nearest one.
        const qreal meet = t * std::sqrt(length2) - std::sqrt(std::max(0.0, radius * radius - distance2));
        found.append({meet + 1e-6 * std::sqrt(distance2), i});
    }
    std::sort(found.begin(), found.end());
}

} // namespace thespis::widgets
