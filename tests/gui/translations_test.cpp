// Translations: the shipped languages load from the resources, translate the user interface,
// and English supplies the plural forms.

#include <QCoreApplication>
#include <QTest>
#include <QTranslator>

#include "editor/error_dialog.h"
#include "editor/scenario_tree_model.h"
#include "editor/translations.h"

using thespis::editor::ScenarioTreeModel;

class TranslationsTest : public QObject {
    Q_OBJECT
private slots:
    void cleanup();
    void shipsThreeLanguages();
    void germanTranslatesTheOutline();
    void frenchTranslatesErrors();
    void englishHasPluralForms();
    void unknownLanguageFallsBackToEnglish();

private:
    static QString header(int column)
    {
        ScenarioTreeModel model;
        return model.headerData(column, Qt::Horizontal).toString();
    }
};

void TranslationsTest::cleanup()
{
    for (QTranslator* translator : QCoreApplication::instance()->findChildren<QTranslator*>()) {
        QCoreApplication::removeTranslator(translator);
        delete translator;
    }
}

void TranslationsTest::shipsThreeLanguages()
{
    QCOMPARE(thespis::editor::availableLanguages(), (QStringList{"de", "en", "fr"}));
}

void TranslationsTest::germanTranslatesTheOutline()
{
    QCOMPARE(thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::German, QLocale::Germany)),
             QStringLiteral("de_DE"));
    QCOMPARE(header(ScenarioTreeModel::StartColumn), QStringLiteral("Beginn (s)"));
    QCOMPARE(ScenarioTreeModel::tr("%n clip(s)", nullptr, 1), QStringLiteral("1 Clip"));
    QCOMPARE(ScenarioTreeModel::tr("%n clip(s)", nullptr, 3), QStringLiteral("3 Clips"));
}

void TranslationsTest::frenchTranslatesErrors()
{
    QCOMPARE(thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::French, QLocale::France)),
             QStringLiteral("fr_FR"));
    QCOMPARE(thespis::editor::errorTitle(thespis::core::ErrorCode::CorruptData), QStringLiteral("Le fichier est endommagé"));
    QCOMPARE(header(ScenarioTreeModel::WeightColumn), QStringLiteral("Courbe de poids"));
}

void TranslationsTest::englishHasPluralForms()
{
    QCOMPARE(thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::English)),
             QStringLiteral("en_US"));
    QCOMPARE(ScenarioTreeModel::tr("%n clip(s)", nullptr, 1), QStringLiteral("1 clip"));
    QCOMPARE(ScenarioTreeModel::tr("%n clip(s)", nullptr, 2), QStringLiteral("2 clips"));
    QCOMPARE(ScenarioTreeModel::tr("keyframed, %n key(s)", nullptr, 1), QStringLiteral("keyframed, 1 key"));
    // English needs no other translation: the source text is shown.
    QCOMPARE(header(ScenarioTreeModel::StartColumn), QStringLiteral("Start (s)"));
}

void TranslationsTest::unknownLanguageFallsBackToEnglish()
{
    QCOMPARE(thespis::editor::installTranslators(*QCoreApplication::instance(), QLocale(QLocale::Japanese)),
             QStringLiteral("en_US"));
    QCOMPARE(ScenarioTreeModel::tr("%n clip(s)", nullptr, 1), QStringLiteral("1 clip"));
}

QTEST_MAIN(TranslationsTest)
#include "translations_test.moc"
