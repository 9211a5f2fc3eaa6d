#pragma once
// Autosaver: keeps a recovery copy of the open document so that a crash loses at most a minute
// of work. While the document has unsaved changes, its scenario is written (atomically) every
// interval to <app data>/recovery/<pid>-<n>.thespis, with a small .json beside it naming the
// original file, its folder, the package it plays from and the writing process. A save, a clean close or a new document
// removes the copy. At the next start, copies whose process is gone are offered for recovery.

#include <QDateTime>
#include <QObject>
#include <QString>

class QTimer;

namespace thespis::editor {

class Document;

class Autosaver : public QObject {
    Q_OBJECT
public:
    struct Recovery {
        QString recoveryFile;  ///< the autosaved scenario
        QString originalPath;  ///< the file it was opened from; empty for an unsaved document
        QString baseDir;       ///< where its relative paths resolve
        QString packagePath;   ///< the package it played from; empty: none
        QDateTime savedAt;
    };

    explicit Autosaver(QObject* parent = nullptr);
    ~Autosaver() override;

    /// Watches `document` (null: none); removes the copy of the previous one.
    void setDocument(Document* document);
    /// Default one minute.
    void setInterval(int milliseconds);
    int interval() const;
    /// Writes the copy now when there are unsaved changes not yet in it; false on failure.
    bool saveNow();
    /// Removes the copy of the current document (after a save or a clean close).
    void discard();
    QString recoveryFile() const { return m_file; }

    /// The folder of the copies (created on first use).
    static QString recoveryDir();
    /// Copies left by processes that are no longer running, newest first.
    static QList<Recovery> pendingRecoveries();
    /// Removes a copy once it was recovered or declined.
    static void removeRecovery(const Recovery& recovery);

signals:
    void autosaved(const QString& file);
    void failed(const QString& message);

private:
    Document* m_document = nullptr;
    QTimer* m_timer = nullptr;
    QString m_file;
    bool m_dirty = false; // changed since the last copy
};

} // namespace thespis::editor
