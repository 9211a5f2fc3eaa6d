#pragma once
// JointMaskPanel: the joint-mask editor. Picks one of the scenario's named masks (shared by the
// actions that name it), shows it on the H-Anim skeleton of the document's first character as a
// tree and a paintable front-view picture (widgets::JointMaskView) — a face mask (one naming the
// face's regions, scene/face_mask.h) on the face's regions and channels instead — and offers new
// (body or face) / rename / delete, the presets, mirror and invert. Every change is one undoable edit of the document; a
// paint stroke is one, however many joints it touches.

#include <QWidget>

#include <string>
#include <vector>

#include "anim/joint_mask.h"
#include "anim/skeleton.h"

class QComboBox;
class QToolButton;

namespace thespis::widgets {
class JointMaskView;
}

namespace thespis::editor {

class Document;

class JointMaskPanel : public QWidget {
    Q_OBJECT
public:
    explicit JointMaskPanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// Shows the mask named `name` (an action's mask when it is selected); unknown names are ignored.
    void showMask(const QString& name);
    QString currentMask() const;
    widgets::JointMaskView* view() const { return m_view; }

signals:
    /// A change that could not be made, for the status bar.
    void problem(const QString& message);

private:
    void refresh();
    void refreshMaskList();
    int maskIndex() const;
    void report(const core::Result<void>& result);
    void onNewMask(bool face);
    void showBody(const core::anim::JointMask* mask);
    void showFace(const core::anim::JointMask& mask);
    void onRenameMask();
    void onDeleteMask();

    Document* m_document = nullptr;
    core::anim::Skeleton m_skeleton;
    bool m_face = false;             ///< the mask shown is a face mask (scene/face_mask.h)
    std::vector<std::string> m_keys; ///< per element shown, the name the mask gives it a weight by
    QComboBox* m_masks = nullptr;
    QToolButton* m_presets = nullptr;
    QToolButton* m_mirror = nullptr;
    QToolButton* m_invert = nullptr;
    QToolButton* m_add = nullptr;
    QToolButton* m_rename = nullptr;
    QToolButton* m_remove = nullptr;
    widgets::JointMaskView* m_view = nullptr;
};

} // namespace thespis::editor
