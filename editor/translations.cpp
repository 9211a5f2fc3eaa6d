#include "editor/translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QTranslator>

namespace thespis::editor {

namespace {
const QString kPrefix = QStringLiteral(":/i18n");
} // namespace

QString installTranslators(QCoreApplication& app, const QLocale& locale)
{
    auto* qt = new QTranslator(&app);
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        app.installTranslator(qt);
    else
        delete qt;

    auto* ours = new QTranslator(&app);
    if (!ours->load(locale, QStringLiteral("thespis"), QStringLiteral("_"), kPrefix) &&
        !ours->load(QStringLiteral("thespis_en"), kPrefix)) {
        delete ours;
        return {};
    }
    app.installTranslator(ours);
    return ours->language();
}

QStringList availableLanguages()
{
    QStringList languages;
    for (const QFileInfo& file : QDir(kPrefix).entryInfoList({QStringLiteral("thespis_*.qm")}, QDir::Files, QDir::Name))
        languages << file.completeBaseName().mid(int(qstrlen("thespis_")));
    return languages;
}

} // namespace thespis::editor
