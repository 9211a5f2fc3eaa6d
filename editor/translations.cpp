#include "editor/translations.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>
#include <QLibraryInfo>
#include <QSettings>
#include <QTranslator>

namespace thespis::editor {

namespace {
const QString kPrefix = QStringLiteral(":/i18n");
const QString kLanguageKey = QStringLiteral("ui/language");
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

QString preferredLanguage()
{
    return QSettings().value(kLanguageKey).toString();
}

void setPreferredLanguage(const QString& language)
{
    QSettings settings;
    if (language.isEmpty())
        settings.remove(kLanguageKey);
    else
        settings.setValue(kLanguageKey, language);
}

QLocale preferredLocale()
{
    const QString language = preferredLanguage();
    return language.isEmpty() ? QLocale() : QLocale(language);
}

QString nativeLanguageName(const QString& language)
{
    if (language == QLatin1String("en"))
        return QStringLiteral("English"); // Qt names it "American English"
    QString name = QLocale(language).nativeLanguageName();
    if (!name.isEmpty())
        name[0] = name[0].toUpper(); // "français" → "Français", as a menu entry
    return name;
}

} // namespace thespis::editor
