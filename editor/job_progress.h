#pragma once
// JobProgress: the bottom of a dialog that runs a job (Export Package, Export Motion): a progress
// bar that shows the job's stage and share, and a message line that says what was written, why
// nothing was, or that it was cancelled (errors in red).

#include <QWidget>

class QLabel;
class QProgressBar;

namespace thespis::core {
struct Error;
}

namespace thespis::editor {

class JobProgress : public QWidget {
    Q_OBJECT
public:
    /// `idle`: the bar's text before any run ("Not exported yet").
    JobProgress(const QString& idle, QWidget* parent = nullptr);

    QProgressBar* bar() const { return m_bar; }
    QLabel* message() const { return m_message; }

    void started();
    /// JobRunner::progress: counts above 2³¹ do not fit a bar, so it shows thousandths.
    void setProgress(const QString& stage, qint64 done, qint64 total);
    /// A refusal or a failure (red), or "Cancelled: nothing was written."
    void failed(const core::Error& error);
    void refused(const QString& why);
    /// Done: the bar full with `title`, the message `text`.
    void finished(const QString& title, const QString& text);

private:
    QProgressBar* m_bar = nullptr;
    QLabel* m_message = nullptr;
};

} // namespace thespis::editor
