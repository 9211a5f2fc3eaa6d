#include "editor/autosave.h"

#include <QCoreApplication>
#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>
#include <QTimer>

#include <algorithm>

#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "scenario/scenario_io.h"
#include "util/file_io.h"

namespace thespis::editor {

namespace {

constexpr int kDefaultIntervalMs = 60 * 1000;

QString sidecarOf(const QString& recoveryFile)
{
    return recoveryFile.left(recoveryFile.size() - int(QStringLiteral(".thespis").size())) + QStringLiteral(".json");
}

bool processRunning(qint64 pid)
{
    return pid > 0 && QFileInfo::exists(QStringLiteral("/proc/%1").arg(pid));
}

} // namespace

Autosaver::Autosaver(QObject* parent) : QObject(parent), m_timer(new QTimer(this))
{
    m_timer->setInterval(kDefaultIntervalMs);
    connect(m_timer, &QTimer::timeout, this, [this] { saveNow(); });
    m_timer->start();
}

Autosaver::~Autosaver() = default; // a copy left here is what a crash would have left: kept

void Autosaver::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    discard();
    m_document = document;
    m_dirty = false;
    if (!m_document)
        return;
    connect(m_document, &Document::edited, this, [this] { m_dirty = true; });
    connect(m_document, &Document::modifiedChanged, this, [this](bool modified) {
        if (!modified)
            discard(); // saved, or undone back to the saved state
        else
            m_dirty = true;
    });
    // A recovered document starts modified: keep it safe too.
    m_dirty = m_document->isModified();
}

void Autosaver::setInterval(int milliseconds)
{
    m_timer->setInterval(std::max(1, milliseconds));
}

int Autosaver::interval() const
{
    return m_timer->interval();
}

QString Autosaver::recoveryDir()
{
    const QString dir = QStandardPaths::writableLocation(QStandardPaths::AppLocalDataLocation) + QStringLiteral("/recovery");
    QDir().mkpath(dir);
    return dir;
}

bool Autosaver::saveNow()
{
    if (!m_document || !m_dirty || !m_document->isModified())
        return true;
    if (m_file.isEmpty()) {
        static int counter = 0;
        m_file = recoveryDir() + QStringLiteral("/%1-%2.thespis").arg(QCoreApplication::applicationPid()).arg(++counter);
    }
    if (auto saved = core::scenario::saveScenario(toFsPath(m_file), m_document->scenario()); !saved) {
        emit failed(tr("Autosave failed: %1").arg(QString::fromStdString(saved.error().message)));
        return false;
    }
    QJsonObject info;
    info[QStringLiteral("original")] = m_document->filePath();
    info[QStringLiteral("baseDir")] = m_document->baseDir();
    info[QStringLiteral("package")] = m_document->packagePath();
    info[QStringLiteral("pid")] = QCoreApplication::applicationPid();
    info[QStringLiteral("saved")] = QDateTime::currentDateTimeUtc().toString(Qt::ISODate);
    const QByteArray json = QJsonDocument(info).toJson();
    if (auto written = core::writeFileAtomically(toFsPath(sidecarOf(m_file)), std::string_view(json.constData(), std::size_t(json.size())));
        !written) {
        emit failed(tr("Autosave failed: %1").arg(QString::fromStdString(written.error().message)));
        return false;
    }
    m_dirty = false;
    emit autosaved(m_file);
    return true;
}

void Autosaver::discard()
{
    if (m_file.isEmpty())
        return;
    QFile::remove(m_file);
    QFile::remove(sidecarOf(m_file));
    m_file.clear();
}

QList<Autosaver::Recovery> Autosaver::pendingRecoveries()
{
    QList<Recovery> found;
    const QDir dir(recoveryDir());
    for (const QFileInfo& sidecar : dir.entryInfoList({QStringLiteral("*.json")}, QDir::Files)) {
        QFile file(sidecar.absoluteFilePath());
        if (!file.open(QIODevice::ReadOnly))
            continue;
        const QJsonObject info = QJsonDocument::fromJson(file.readAll()).object();
        const QString scenario = sidecar.absolutePath() + QLatin1Char('/') + sidecar.completeBaseName() + QStringLiteral(".thespis");
        if (!QFileInfo::exists(scenario) || processRunning(info.value(QStringLiteral("pid")).toInteger()))
            continue;
        Recovery recovery;
        recovery.recoveryFile = scenario;
        recovery.originalPath = info.value(QStringLiteral("original")).toString();
        recovery.baseDir = info.value(QStringLiteral("baseDir")).toString();
        recovery.packagePath = info.value(QStringLiteral("package")).toString();
        recovery.savedAt = QDateTime::fromString(info.value(QStringLiteral("saved")).toString(), Qt::ISODate);
        found.push_back(recovery);
    }
    std::sort(found.begin(), found.end(), [](const Recovery& a, const Recovery& b) { return a.savedAt > b.savedAt; });
    return found;
}

void Autosaver::removeRecovery(const Recovery& recovery)
{
    QFile::remove(recovery.recoveryFile);
    QFile::remove(sidecarOf(recovery.recoveryFile));
}

} // namespace thespis::editor
