#pragma once
// CharacterDialog: Character ▸ Add Character… A name and a body — the built-in humanoid at an
// H-Anim level, or a glTF model (which then plays on its own rig) whose own animations can come
// along as clips. character() is the character to add, clips() the model's animations ticked.

#include <QDialog>

#include <vector>

#include "scenario/scenario.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QRadioButton;

namespace thespis::editor {

class CharacterDialog : public QDialog {
    Q_OBJECT
public:
    /// `baseDir`: the scenario's folder, which the model's path is made relative to.
    CharacterDialog(const QString& baseDir, const QString& suggestedName, QWidget* parent = nullptr);

    /// Uses this glTF file as the body (what Browse… does after its file dialog).
    void setModelFile(const QString& path);

    core::scenario::Character character() const;
    /// The model's animations as clips when "Import its animations" is ticked (paths relative to
    /// the scenario's folder), else none.
    std::vector<core::scenario::ClipAsset> clips() const;

    QLineEdit* nameEdit() const { return m_name; }
    QRadioButton* humanoidChoice() const { return m_humanoid; }
    QRadioButton* modelChoice() const { return m_modelChoice; }
    QComboBox* levelChoice() const { return m_level; }
    QCheckBox* importClipsCheck() const { return m_importClips; }
    QLabel* modelLabel() const { return m_modelLabel; }

private:
    void updateState();

    QString m_baseDir;
    QString m_modelPath; ///< absolute
    std::vector<core::scenario::ClipAsset> m_modelClips;
    QLineEdit* m_name = nullptr;
    QRadioButton* m_humanoid = nullptr;
    QRadioButton* m_modelChoice = nullptr;
    QComboBox* m_level = nullptr;
    QLabel* m_modelLabel = nullptr;
    QPushButton* m_browse = nullptr;
    QCheckBox* m_importClips = nullptr;
    QPushButton* m_ok = nullptr;
};

} // namespace thespis::editor
