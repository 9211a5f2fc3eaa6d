#pragma once
// BakePanel: the PRT bake of the studio (paper §6). Picks a character of the document, edits the
// bake settings (SH order, rays per vertex, transfer DU / DS / DSM, ray tracer, relaxation ε,
// threads), runs the bake as a background job (core's TransferBakeJob in a JobRunner) with a progress bar and Cancel, and applies the
// result as ONE undoable edit that points the character at its new bake file (Character::bake,
// written under <scenario folder>/bakes/). A cancelled or failed bake changes nothing. It says
// which bake the character uses now, and whether that one still fits its segment tags; a
// "Show PRT lighting" check box asks for the viewport's PRT or Phong shading.
//
// Owns its JobRunner. Changing or clearing the document cancels a running bake.

#include <QPointer>
#include <QString>
#include <QWidget>

#include <optional>
#include <string>
#include <vector>

#include "lighting/transfer_bake.h"
#include "scenario/scenario.h"
#include "util/error.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QSpinBox;

namespace thespis::editor {

class JobRunner;
class Document;

class BakePanel : public QWidget {
    Q_OBJECT
public:
    explicit BakePanel(QWidget* parent = nullptr);
    ~BakePanel() override;

    /// The document whose characters are baked (null: none). A running bake is cancelled first.
    void setDocument(Document* document);
    Document* document() const { return m_document; }

    JobRunner* job() const { return m_job; }
    bool isRunning() const;
    /// Starts baking the chosen character with the settings shown. When it cannot start (bad
    /// setting, no folder to write to, body that does not load) the status line says why and
    /// nothing changes.
    void start();
    /// Stops a running bake: nothing changes, the status says "cancelled".
    void cancel();

    /// The settings the widgets show, validated (the ε text must be a distance ≥ 0 in metres).
    core::Result<core::lighting::BakeSettings> settings() const;
    /// Shows `settings` in the widgets (order clamped to 1–6, rays to 16–4096).
    void setSettings(const core::lighting::BakeSettings& settings);
    /// The character baked, by index into the document's characters (-1: none).
    int currentCharacter() const;
    void setCurrentCharacter(int index);

    /// Where a bake of character `index` with `settings` would be written now:
    /// <baseDir>/bakes/<scenario file stem or "untitled">-<character>-<transfer>-o<order>-<8 hex>.prt;
    /// an error when the document's folder cannot be written to.
    core::Result<QString> outputPathFor(int index, const core::lighting::BakeSettings& settings) const;

    /// Shows the PRT-or-Phong choice without emitting prtPreviewToggled.
    void setPrtPreview(bool prt);
    bool prtPreview() const;

    // The widgets, for tests and for the studio's layout.
    QComboBox* characterCombo() const { return m_character; }
    QSpinBox* orderSpin() const { return m_order; }
    QComboBox* raysCombo() const { return m_rays; }
    QComboBox* transferCombo() const { return m_transfer; }
    QComboBox* backendCombo() const { return m_backend; }
    QLineEdit* epsilonEdit() const { return m_epsilon; }
    QSpinBox* threadsSpin() const { return m_threads; }
    QPushButton* startButton() const { return m_start; }
    QPushButton* cancelButton() const { return m_cancel; }
    QProgressBar* progressBar() const { return m_progress; }
    QCheckBox* prtPreviewCheck() const { return m_prtPreview; }
    /// The last bake's outcome: transfer, order, rays, seconds and Mrays/s; or the error; or
    /// "Cancelled — nothing changed."
    QString statusText() const;
    /// Which bake the chosen character uses now: "none — unshadowed (DU)", or its file name and
    /// on a second line its transfer, order and rays — or "stale" when it no longer fits the
    /// character's body or segment tags, "missing" when it cannot be read.
    QString currentBakeText() const;

signals:
    /// The user toggled "Show PRT lighting": true for PRT, false for Phong.
    void prtPreviewToggled(bool prt);

private:
    // What a bake was started from, to apply its result to the same character (and to see
    // whether the character changed while it baked).
    struct Running {
        std::string character;
        std::string skeleton, model;
        std::vector<core::scene::SegmentTag> segmentTags;
        core::lighting::BakeSettings settings;
        QString path; ///< the bake file being written
    };
    void refreshCharacters();
    void refreshCurrentBake();
    void updateEnabled();
    void setStatus(const QString& text, bool error);
    void onProgress(const QString& stage, qint64 done, qint64 total);
    void onFinished(const core::Result<void>& result);

    QPointer<Document> m_document;
    JobRunner* m_job = nullptr; // child
    std::optional<Running> m_running;
    QString m_currentBakeKey; // what refreshCurrentBake last looked at

    QComboBox* m_character = nullptr;
    QLabel* m_currentBake = nullptr;
    QSpinBox* m_order = nullptr;
    QLabel* m_coefficients = nullptr;
    QComboBox* m_rays = nullptr;
    QComboBox* m_transfer = nullptr;
    QComboBox* m_backend = nullptr;
    QLineEdit* m_epsilon = nullptr;
    QSpinBox* m_threads = nullptr;
    QPushButton* m_start = nullptr;
    QPushButton* m_cancel = nullptr;
    QProgressBar* m_progress = nullptr;
    QLabel* m_status = nullptr;
    QCheckBox* m_prtPreview = nullptr;
    QList<QWidget*> m_settingsWidgets;
};

} // namespace thespis::editor
