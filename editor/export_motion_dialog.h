#pragma once
// ExportMotionDialog: File ▸ Export ▸ Motion… — a character's motion over the scenario, baked
// at a frame rate and written for other tools: a glTF 2.0 .glb (the character's own glTF model
// with the motion, or the built-in humanoid written whole as a glTF character; or, with
// "Animation only", the nodes and the animation, which play onto the model by node name) or a
// BVH clip. The bake runs as a job off the GUI thread (MotionBakeJob in a JobRunner, the same
// job `thespis-cli bake-motion` runs) with a progress bar and Cancel; a cancelled or failed bake
// leaves no file, and an existing file is replaced only when the new one is whole.

#include <QDialog>

#include "util/error.h"

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;

namespace thespis::editor {

class Document;
class JobProgress;
class JobRunner;

class ExportMotionDialog : public QDialog {
    Q_OBJECT
public:
    /// Bakes from `document` as it is now; `character` is chosen first (out of range: the first).
    ExportMotionDialog(const Document& document, int character, QWidget* parent = nullptr);
    ~ExportMotionDialog() override;

    /// Where the file goes; its extension (.glb or .bvh) is the format.
    void setOutput(const QString& path);
    void setCharacter(int character);
    void setAnimationOnly(bool animationOnly);
    void setFrameRate(double framesPerSecond);
    /// Starts the bake; false (and the message says why) when it cannot start.
    bool exportMotion();
    void cancel();
    bool isExporting() const;

    QLabel* messageLabel() const;
    QProgressBar* progressBar() const;
    QPushButton* exportButton() const { return m_export; }

signals:
    /// The file was written (its path).
    void exported(const QString& path);

private:
    void onFinished(const core::Result<void>& result);
    void updateEnabled();

    const Document& m_document;
    JobRunner* m_job = nullptr;
    QComboBox* m_character = nullptr;
    QDoubleSpinBox* m_fps = nullptr;
    QLineEdit* m_output = nullptr;
    QCheckBox* m_animationOnly = nullptr;
    JobProgress* m_progress = nullptr;
    QPushButton* m_export = nullptr;
    QPushButton* m_cancel = nullptr;
    QString m_namedAfter; // the character the file name was made from
};

} // namespace thespis::editor
