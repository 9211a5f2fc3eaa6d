#pragma once
// MaskJoint: one skeleton joint as JointMaskView shows it (name, parent, front-view position, the
// mask's weight). Plain data that the editor fills and the picture's layout reads.

#include <QPointF>
#include <QString>

namespace thespis::widgets {

/// One joint as the view shows it.
struct MaskJoint {
    QString name;       ///< H-Anim name, e.g. "l_shoulder"
    int parent = -1;    ///< index of the parent joint, -1 for the root (parents come before children)
    QPointF position;   ///< front view in metres: x to the viewer's right, y up (the character faces
                        ///< the viewer, so its left side is on the viewer's right)
    float weight = 0;   ///< the mask's resolved weight for this joint, 0..1
    bool named = false; ///< true: the mask sets this joint; false: inherited from an ancestor or the
                        ///< default (shown in grey italic)
};

} // namespace thespis::widgets
