#pragma once
// The joint-mask picture's geometry as pure values: how wide the body is around each joint (from
// its name), where the joints, the body's capsules, hands, feet and head land when the figure is
// fitted into a rectangle, which joint a click picks, and which joints a brush stroke meets, in
// order. No widget here: JointMaskPicture keeps one layout for its size, and tests build one by hand.

#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>

#include <utility>

#include "widgets/mask_joint.h"

namespace thespis::widgets {

/// How wide the body is around the bone that ends at a joint (name in lower case), in metres for a
/// figure whose joints span 1.55 m vertically (ankles to skull base of a 1.75 m person). H-Anim
/// names first, then the usual BVH / FBX ones; 0 for joints inside the head.
qreal jointBodyWidth(QString lowerName);
/// The joint the head is drawn above (H-Anim "skullbase", or "head"); name in lower case.
bool isHeadJoint(const QString& lowerName);

/// The figure fitted into a rectangle, in its pixels.
struct JointMaskLayout {
    QVector<QPointF> screen;   ///< per joint
    QVector<qreal> bodyWidth;  ///< per joint: the body around the bone to its parent
    QVector<QPointF> tip;      ///< per joint: where the hand / foot beyond a leaf wrist or ankle ends
    QVector<qreal> tipWidth;   ///< per joint: that hand or foot's width (0: none)
    QRectF head;               ///< the head ellipse, empty for none
    QRectF figure;             ///< bounding box of the figure
    qreal dotRadius = 5;       ///< joint dots grow with the picture, within clickable limits

    /// Lays `joints` (with their body widths in metres, from jointBodyWidth()) out to fit `fit`,
    /// keeping the aspect ratio. Reuses this layout's buffers.
    /// A non-empty `faceOutline` (metres) is drawn as the head instead: an oval around a face.
    void fitInto(const QVector<MaskJoint>& joints, const QVector<qreal>& metresWidth, const QRectF& fit,
                 const QRectF& faceOutline = {});
    /// The joint whose dot is nearest `pos` within `radius` (the later one on a tie: it is drawn on
    /// top), else -1.
    int jointAt(QPointF pos, qreal radius) const;
    /// Every joint not flagged in `skip` that a brush of `radius` meets moving from `from` to `to`,
    /// in the order it meets them, as (distance along the stroke, joint), into `found` (cleared first).
    void brushHits(QPointF from, QPointF to, qreal radius, const QVector<char>& skip,
                   QVector<std::pair<qreal, int>>& found) const;

private:
    QVector<char> m_leaf; // scratch: per joint, has no children
};

} // namespace thespis::widgets
