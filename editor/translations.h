#pragma once
// Loads the user interface translations: Qt's own strings and Thespis' (compiled from
// translations/*.ts into the resource folder :/i18n). English needs a translation too: it
// supplies the plural forms of "%n action(s)" ("1 action", "2 actions").

#include <QLocale>
#include <QStringList>

class QCoreApplication;

namespace thespis::editor {

/// Installs translators on `app` for `locale`; a language Thespis is not translated to falls
/// back to English. Returns the languages of the Thespis translation loaded ("de", "en", …).
QString installTranslators(QCoreApplication& app, const QLocale& locale = QLocale());

/// The languages Thespis ships, as in the .qm names ("de", "en", "fr").
QStringList availableLanguages();

/// The language chosen in Preferences ("de", "fr", …), or empty for the system's.
QString preferredLanguage();
/// Remembers the choice (empty: follow the system); it applies from the next start.
void setPreferredLanguage(const QString& language);
/// The locale to translate into: the preferred language, else the system's.
QLocale preferredLocale();
/// A language's name in that language ("Deutsch", "Français"), for choosing it.
QString nativeLanguageName(const QString& language);

} // namespace thespis::editor
