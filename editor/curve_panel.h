#pragma once
// CurvePanel: the curve editor of the selected action. Shows its weight and scale curves over the
// action's local time (widgets::CurveView) with the playhead; a preset chooser with its
// parameters (constant, linear / cubic fade, linear / cubic ADSR, dominance, keyframed) for the
// curve picked in "Edit"; numeric entry for the selected key; key add / move / delete and tangent
// edits on keyframed curves. Every change is one undoable edit (a drag merges into one), and the viewport
// follows because the document rebuilds its schedules after each.

#include <QWidget>

#include <optional>

#include "anim/curve.h"
#include "edit/scenario_edit.h"
#include "util/tick.h"
#include "widgets/curve_view.h"

class QComboBox;
class QDoubleSpinBox;
class QLabel;

namespace thespis::editor {

class Document;

class CurvePanel : public QWidget {
    Q_OBJECT
public:
    enum CurveIndex { WeightCurve = 0, ScaleCurve = 1 };

    explicit CurvePanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// The action shown; nullopt clears the panel.
    void setAction(std::optional<core::edit::ActionPath> action);
    std::optional<core::edit::ActionPath> action() const { return m_action; }
    /// The document's time; shown as the playhead in the action's local time.
    void setTime(core::Tick time);

    widgets::CurveView* view() const { return m_view; }
    QComboBox* presetCombo() const { return m_preset; }
    /// Which curve the preset controls edit.
    void setEditedCurve(CurveIndex curve);

signals:
    void problem(const QString& message);

private:
    void refresh();
    void refreshControls();
    const core::anim::Curve* curve(int index) const;
    core::anim::Curve presetCurve() const;
    void applyCurve(int index, core::Result<core::anim::Curve> curve, const QString& text, int mergeKey = -1,
                    bool finished = true);
    void onPresetEdited(int mergeKey);
    void onKeyAdd(int curve, QPointF at);
    void onKeysMove(const QList<widgets::CurveKeyRef>& keys, QPointF delta, bool finished);
    void onKeyValueEdited();

    Document* m_document = nullptr;
    std::optional<core::edit::ActionPath> m_action;
    core::Tick m_time = 0;
    double m_duration = 0;                     // the action's length; infinity when open-ended
    std::optional<core::anim::Curve> m_dragStart; // the dragged curve as it was when the drag began
    int m_dragCurve = -1;
    bool m_updating = false;                   // set while controls are filled from the document

    QLabel* m_title = nullptr;
    QComboBox* m_edited = nullptr;
    QComboBox* m_preset = nullptr;
    QDoubleSpinBox* m_attack = nullptr;
    QDoubleSpinBox* m_decay = nullptr;
    QDoubleSpinBox* m_sustain = nullptr;
    QDoubleSpinBox* m_release = nullptr;
    QDoubleSpinBox* m_peak = nullptr;
    QDoubleSpinBox* m_alpha = nullptr;
    QDoubleSpinBox* m_keyTime = nullptr;
    QDoubleSpinBox* m_keyValue = nullptr;
    widgets::CurveView* m_view = nullptr;
};

} // namespace thespis::editor
