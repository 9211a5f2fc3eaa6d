#pragma once
// JointMaskView: the joint-mask editor's view. A joint mask gives each skeleton joint a weight in
// [0, 1]; the view shows the skeleton as a tree (joint name + weight) and, beside it, a front-view
// body picture where the user clicks or paints joints with a brush (left button: the brush weight,
// right button: 0). A pure view: it knows nothing of masks or skeletons beyond the MaskJoint list
// the caller feeds; user gestures become intents (weightsPaintRequested, weightRequested,
// jointSelected) and what is shown changes only through the setters, which emit nothing, so the
// editor can apply each intent as an undoable command and feed the result back without loops.
// Owns a copy of the joints, the tree items and the brush settings.
// Files: the body picture in joint_mask_picture.h, its pure layout in joint_mask_layout.h.

#include <QColor>
#include <QPointF>
#include <QRectF>
#include <QString>
#include <QVector>
#include <QWidget>

#include "widgets/mask_joint.h"

class QDoubleSpinBox;
class QSlider;
class QSpinBox;
class QSplitter;
class QTreeWidget;
class QTreeWidgetItem;

namespace thespis::widgets {

class JointMaskPicture;

class JointMaskView : public QWidget {
    Q_OBJECT
public:
    explicit JointMaskView(QWidget* parent = nullptr);
    ~JointMaskView() override;

    /// Replaces the joints. Emits nothing. When names and parents are unchanged only weights,
    /// "named" flags and positions are updated in place, so the tree keeps its items, expansion,
    /// scroll position and selection (and a paint stroke in progress goes on); otherwise the tree
    /// is rebuilt (expanded, the selection kept by joint name) and a stroke in progress is dropped.
    /// Joints whose parent is not an earlier joint are shown as roots.
    void setJoints(QVector<MaskJoint> joints);
    const QVector<MaskJoint>& joints() const { return m_joints; }

    /// Draws a face instead of a body: no limbs around the "joints" (a face mask's regions and
    /// channels), an oval `outline` (metres, the joints' front-view frame) behind them. An empty
    /// rectangle draws the body again. Emits nothing.
    void setFaceOutline(QRectF outline);
    QRectF faceOutline() const { return m_faceOutline; }

    /// The value a left-button paint stroke writes (default 1), clamped to [0, 1]. Also shown and
    /// edited in the view's brush bar. Emits nothing.
    void setBrushWeight(float weight);
    float brushWeight() const { return m_brushWeight; }
    /// Radius of the brush circle in picture pixels (default 18), clamped to [2, 100]. Emits nothing.
    void setBrushRadius(int pixels);
    int brushRadius() const { return m_brushRadius; }

    /// The joint current in the tree and outlined in the picture, -1 for none. Emits nothing.
    void setCurrentJoint(int joint);
    int currentJoint() const;

    /// The body picture (tests send mouse events to it).
    QWidget* picture() const;
    /// The skeleton tree, object name "jointTree"; column 0 "Joint", column 1 "Weight".
    QTreeWidget* tree() const { return m_tree; }
    /// picture() coordinates of a joint's dot; (-1, -1) for an unknown joint.
    QPoint jointPosition(int joint) const;
    /// The joint whose dot is nearest `picturePos`, if within the brush radius; else -1.
    int jointAt(QPoint picturePos) const;

    /// Colour of a weight on the given base colour: neutral grey at 0 to a warm accent at 1.
    /// Shared by the picture's dots and the tree's weight bars.
    static QColor weightColor(float weight, const QColor& base);

signals:
    /// A paint stroke: every joint touched since the press (cumulative, in touch order) and the
    /// weight it writes (left button: the brush weight, right button: 0). Emitted on the press
    /// when it touches a joint, on each move that touches a new joint, and once with
    /// finished = true on release. A stroke that touches no joint emits nothing.
    void weightsPaintRequested(const QVector<int>& joints, float weight, bool finished);
    /// A weight typed in the tree's weight column, or picked in the tree's context menu.
    void weightRequested(int joint, float weight);
    /// The user made a joint current: in the tree, or by pressing on it in the picture.
    void jointSelected(int joint);

protected:
    void changeEvent(QEvent* event) override;

private:
    friend class JointMaskPicture;

    void buildTree();
    void updateItem(int joint);
    void onCurrentItemChanged(QTreeWidgetItem* current);
    void onTreeContextMenu(const QPoint& pos);
    void onBrushSliderMoved(int value);
    void onBrushSpinChanged(double value);
    void onRadiusSpinChanged(int value);
    // Called by the picture when the user presses on a joint.
    void selectFromPicture(int joint);

    QTreeWidget* m_tree = nullptr;
    JointMaskPicture* m_picture = nullptr;
    QSplitter* m_splitter = nullptr;
    QSlider* m_brushSlider = nullptr;
    QDoubleSpinBox* m_brushSpin = nullptr;
    QSpinBox* m_radiusSpin = nullptr;
    QVector<MaskJoint> m_joints;
    QRectF m_faceOutline;
    QVector<QTreeWidgetItem*> m_items; // one per joint
    float m_brushWeight = 1.0f;
    int m_brushRadius = 18;
    bool m_updating = false; // set while the view changes its own widgets: not user input
};

} // namespace thespis::widgets
