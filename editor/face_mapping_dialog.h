#pragma once
// FaceMappingDialog: edits a face mapping table (core/scene/face_mapping.h) for one glTF model —
// its drives (a morph target of the model ← a face channel × a coefficient, of the channel's
// positive or negative part or both) and its joint drives (a joint turned about an axis by radians
// per unit of a channel), rows added and removed; under the tables, every target and joint the
// table names that the model lacks; Load…, Save As… (atomic) and Recognise from Model (the table
// the model's names give). The dialog edits a value: whoever opened it takes mapping() when it is
// accepted (the character's Properties page saves it and sets the character's table in one step).

#include <QDialog>

#include "scene/character.h"
#include "scene/face_mapping.h"

class QLabel;
class QPushButton;
class QTableWidget;

namespace thespis::editor {

/// Asks for a face mapping table file to open (`save` false) or to write, starting in `start`;
/// empty when the user cancels. A Qt file dialog, which tests can answer.
QString chooseFaceMappingFile(QWidget* parent, const QString& title, const QString& start, bool save);

class FaceMappingDialog : public QDialog {
    Q_OBJECT
public:
    /// `model` is the glTF character the table is for (its targets and joints are offered);
    /// `folder` is where Load… and Save As… start.
    FaceMappingDialog(const core::scene::Character& model, const core::scene::FaceMapping& mapping,
                      const QString& folder, QWidget* parent = nullptr);

    /// The table as the rows show it now.
    core::scene::FaceMapping mapping() const;
    void setMapping(const core::scene::FaceMapping& mapping);
    /// Reads a table file into the rows; false (and a message box) when it cannot be read.
    bool loadFile(const QString& path);
    /// Writes the rows to a table file, atomically; false (and a message box) when it fails.
    bool saveFile(const QString& path);

    QTableWidget* drivesTable() const { return m_drives; }
    QTableWidget* jointsTable() const { return m_joints; }
    QLabel* missingLabel() const { return m_missing; }
    QPushButton* recogniseButton() const { return m_recognise; }

private:
    void addDriveRow(const core::scene::FaceMappingDrive& drive);
    void addJointRow(const core::scene::FaceMappingJoint& joint);
    void updateMissing();

    const core::scene::Character& m_model;
    QString m_folder;
    std::string m_name; // the table's name, kept as loaded
    QTableWidget* m_drives = nullptr;
    QTableWidget* m_joints = nullptr;
    QLabel* m_missing = nullptr;
    QPushButton* m_recognise = nullptr;
};

} // namespace thespis::editor
