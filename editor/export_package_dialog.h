#pragma once
// ExportPackageDialog: File ▸ Export ▸ Package… What goes into the package (every file the
// scenario names, its size and the field that names it, and the total), where it is written,
// whether to bake the lighting of characters whose bake is missing or out of date first (into
// the package only), then the export itself as a job off the GUI thread (ExportPackageJob in a JobRunner) with a
// progress bar and Cancel. A file the scenario names that is missing is said before anything is
// written, naming the field; Export waits until it is fixed. Closing the dialog cancels the job
// and the old package, if any, stays as it was.

#include <QDialog>

#include "scenario/package_contents.h"

class QCheckBox;
class QDialogButtonBox;
class QLabel;
class QLineEdit;
class QProgressBar;
class QPushButton;
class QTableWidget;

namespace thespis::editor {

class Document;
class JobProgress;
class JobRunner;

class ExportPackageDialog : public QDialog {
    Q_OBJECT
public:
    /// Plans the package of `document`'s scenario as it is now.
    explicit ExportPackageDialog(const Document& document, QWidget* parent = nullptr);
    ~ExportPackageDialog() override;

    /// Where the package goes (what Choose… sets after its file dialog).
    void setOutput(const QString& path);
    /// Starts the export; false (and the message says why) when it cannot start.
    bool exportPackage();
    void cancel();
    bool isExporting() const;

    QTableWidget* contentsTable() const { return m_contents; }
    QLabel* messageLabel() const;
    QLineEdit* outputEdit() const { return m_output; }
    QProgressBar* progressBar() const;
    QPushButton* exportButton() const { return m_export; }
    QCheckBox* bakeCheck() const { return m_bake; }

signals:
    /// The package was written (its path).
    void exported(const QString& path);

private:
    void showPlan();
    void onFinished(const core::Result<void>& result);
    void updateEnabled();

    const Document& m_document;
    std::optional<core::scenario::PackagePlan> m_plan;
    QString m_planError;
    JobRunner* m_job = nullptr;
    QTableWidget* m_contents = nullptr;
    QLabel* m_summary = nullptr;
    QLineEdit* m_output = nullptr;
    QCheckBox* m_bake = nullptr;
    JobProgress* m_progress = nullptr;
    QPushButton* m_export = nullptr;
    QPushButton* m_cancel = nullptr;
};

} // namespace thespis::editor
