// Translations: the shipped languages load from the resources, translate the user interface,
// every string of the sources is translated (with the same placeholders), and English supplies
// the plural forms.

#include <QCoreApplication>
#include <QFile>
#include <QRegularExpression>
#include <QSet>
#include <QXmlStreamReader>
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
    void everyStringIsTranslated_data();
    void everyStringIsTranslated();

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

void TranslationsTest::everyStringIsTranslated_data()
{
    QTest::addColumn<QString>("file");
    QTest::newRow("German") << QStringLiteral(THESPIS_TS_DIR "/thespis_de.ts");
    QTest::newRow("French") << QStringLiteral(THESPIS_TS_DIR "/thespis_fr.ts");
    QTest::newRow("English plurals") << QStringLiteral(THESPIS_TS_DIR "/thespis_en.ts");
}

void TranslationsTest::everyStringIsTranslated()
{
    // The .ts files are refreshed from the sources by the thespis_update_translations target;
    // a string added since then, or left unfinished, is listed here.
    QFETCH(QString, file);
    QFile ts(file);
    QVERIFY2(ts.open(QIODevice::ReadOnly), qPrintable(file));
    const QRegularExpression placeholder(QStringLiteral("%(?:L?\\d+|n)"));
    auto placeholders = [&](const QString& text) {
        QSet<QString> found;
        for (auto it = placeholder.globalMatch(text); it.hasNext();)
            found.insert(it.next().captured());
        return found;
    };
    QXmlStreamReader xml(&ts);
    QString source;
    QStringList problems;
    int messages = 0;
    while (!xml.atEnd()) {
        if (xml.readNext() != QXmlStreamReader::StartElement)
            continue;
        if (xml.name() == QLatin1String("source")) {
            source = xml.readElementText();
            ++messages;
        } else if (xml.name() == QLatin1String("translation")) {
            if (xml.attributes().value(QLatin1String("type")) == QLatin1String("unfinished"))
                problems << QStringLiteral("not translated: ") + source;
            const QString text = xml.readElementText(QXmlStreamReader::IncludeChildElements);
            if (!text.isEmpty() && !placeholders(text).contains(placeholders(source)))
                problems << QStringLiteral("placeholders differ: ") + source + QStringLiteral(" → ") + text;
        }
    }
    QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
    QVERIFY(messages > 0);
    QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
}

QTEST_MAIN(TranslationsTest)
#include "translations_test.moc"
