#include "editor/job_progress.h"

#include <QBoxLayout>
#include <QLabel>
#include <QProgressBar>

#include <algorithm>

#include "editor/qt_conversions.h"
#include "util/error.h"

namespace thespis::editor {

namespace {
const QString kErrorStyle = QStringLiteral("color: #c0392b;");
} // namespace

JobProgress::JobProgress(const QString& idle, QWidget* parent) : QWidget(parent)
{
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_bar = new QProgressBar(this);
    m_bar->setObjectName(QStringLiteral("jobProgressBar"));
    m_bar->setRange(0, 1);
    m_bar->setValue(0);
    m_bar->setFormat(idle);
    m_bar->setAlignment(Qt::AlignCenter);
    layout->addWidget(m_bar);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("jobProgressMessage"));
    m_message->setWordWrap(true);
    layout->addWidget(m_message);
}

void JobProgress::started()
{
    m_message->clear();
    m_bar->setFormat(tr("Starting…"));
}

void JobProgress::setProgress(const QString& stage, qint64 done, qint64 total)
{
    m_bar->setRange(0, 1000);
    m_bar->setValue(total > 0 ? int(1000 * std::min(done, total) / total) : 0);
    m_bar->setFormat(tr("%1 — %p%").arg(stage));
}

void JobProgress::failed(const core::Error& error)
{
    const bool cancelled = error.code == core::ErrorCode::Cancelled;
    m_bar->setRange(0, 1);
    m_bar->setValue(0);
    m_bar->setFormat(cancelled ? tr("Cancelled") : tr("Failed"));
    m_message->setText(cancelled ? tr("Cancelled: nothing was written.") : fromUtf8(error.message));
    m_message->setStyleSheet(cancelled ? QString() : kErrorStyle);
}

void JobProgress::refused(const QString& why)
{
    m_message->setText(why);
    m_message->setStyleSheet(kErrorStyle);
}

void JobProgress::finished(const QString& title, const QString& text)
{
    m_bar->setRange(0, 1);
    m_bar->setValue(1);
    m_bar->setFormat(title);
    m_message->setText(text);
    m_message->setStyleSheet(QString());
}

} // namespace thespis::editor
