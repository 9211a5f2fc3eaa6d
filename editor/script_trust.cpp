#include "editor/script_trust.h"

#include <QCryptographicHash>
#include <QFile>
#include <QSettings>
#include <QStringList>

namespace thespis::editor {
namespace {

const QString kTrustedKey = QStringLiteral("scripts/trustedFiles");
constexpr int kMaxTrusted = 500; // oldest forgotten first

} // namespace

QString ScriptTrust::fileHash(const QString& path)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly))
        return {};
    QCryptographicHash hash(QCryptographicHash::Sha256);
    if (!hash.addData(&file))
        return {};
    return QString::fromLatin1(hash.result().toHex());
}

bool ScriptTrust::isTrusted(const QString& path)
{
    const QString hash = fileHash(path);
    return !hash.isEmpty() && QSettings().value(kTrustedKey).toStringList().contains(hash);
}

void ScriptTrust::trust(const QString& path)
{
    const QString hash = fileHash(path);
    if (hash.isEmpty())
        return;
    QSettings settings;
    QStringList hashes = settings.value(kTrustedKey).toStringList();
    hashes.removeAll(hash);
    hashes.append(hash);
    while (hashes.size() > kMaxTrusted)
        hashes.removeFirst();
    settings.setValue(kTrustedKey, hashes);
}

} // namespace thespis::editor
