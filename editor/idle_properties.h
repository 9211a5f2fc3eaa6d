#pragma once
// IdleProperties: on the Properties page of an action that plays idle motion (paper §4.3), the
// idle clip's own settings — the motion database it plays, the seed of the character's motion
// program, the amplitude of the small posture variations (ClipSettingsBox: shared by the actions
// playing the clip, one undoable command per change).

#include "editor/clip_settings_box.h"

class QDoubleSpinBox;
class QLabel;
class QPushButton;
class QSpinBox;

namespace thespis::editor {

class Document;

class IdleProperties : public ClipSettingsBox {
    Q_OBJECT
public:
    explicit IdleProperties(QWidget* parent = nullptr);

    /// Shows the idle clip `clip` of `character` (hidden when that clip is not idle motion).
    void show(Document* document, int character, const std::string& clip, bool editable);
    /// Plays the database at `path` (Choose… after its file dialog).
    void setDatabase(const QString& path);

    QLabel* databaseLabel() const { return m_database; }
    QSpinBox* seedEdit() const { return m_seed; }
    QDoubleSpinBox* amplitudeEdit() const { return m_amplitude; }

private:
    QLabel* m_database = nullptr;
    QPushButton* m_choose = nullptr;
    QSpinBox* m_seed = nullptr;
    QDoubleSpinBox* m_amplitude = nullptr;
};

} // namespace thespis::editor
