#include "preferences_dialog.h"

#include <QComboBox>
#include <QDialogButtonBox>
#include <QFormLayout>
#include <QLabel>
#include <QSettings>
#include <QSpinBox>
#include <QVBoxLayout>

#include "editor/translations.h"

namespace thespis::studio {

namespace {
const QString kAutosaveKey = QStringLiteral("autosave/minutes");
} // namespace

PreferencesDialog::PreferencesDialog(QWidget* parent) : QDialog(parent)
{
    setObjectName(QStringLiteral("preferencesDialog"));
    setWindowTitle(tr("Preferences"));
    auto* layout = new QVBoxLayout(this);
    auto* form = new QFormLayout;
    layout->addLayout(form);

    m_language = new QComboBox(this);
    m_language->setObjectName(QStringLiteral("languageChoice"));
    m_language->addItem(tr("System default (%1)").arg(editor::nativeLanguageName(QLocale().name().left(2))), QString());
    for (const QString& language : editor::availableLanguages())
        m_language->addItem(editor::nativeLanguageName(language), language);
    m_initialLanguage = editor::preferredLanguage();
    m_language->setCurrentIndex(std::max(0, m_language->findData(m_initialLanguage)));
    form->addRow(tr("&Language:"), m_language);
    m_restartNote = new QLabel(tr("The new language is used from the next start of the studio."), this);
    m_restartNote->setObjectName(QStringLiteral("restartNote"));
    m_restartNote->setWordWrap(true);
    m_restartNote->setVisible(false);
    form->addRow(QString(), m_restartNote);
    connect(m_language, &QComboBox::currentIndexChanged, this,
            [this] { m_restartNote->setVisible(m_language->currentData().toString() != m_initialLanguage); });

    m_autosave = new QSpinBox(this);
    m_autosave->setObjectName(QStringLiteral("autosaveMinutes"));
    m_autosave->setRange(1, 60);
    m_autosave->setSuffix(tr(" min"));
    m_autosave->setValue(storedAutosaveMinutes());
    m_autosave->setToolTip(tr("How often open work is copied to a recovery file, offered after a crash"));
    form->addRow(tr("&Autosave every:"), m_autosave);

    auto* buttons = new QDialogButtonBox(QDialogButtonBox::Ok | QDialogButtonBox::Cancel, this);
    connect(buttons, &QDialogButtonBox::accepted, this, [this] {
        apply();
        accept();
    });
    connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
    layout->addWidget(buttons);
}

int PreferencesDialog::storedAutosaveMinutes()
{
    return std::clamp(QSettings().value(kAutosaveKey, 1).toInt(), 1, 60);
}

void PreferencesDialog::apply()
{
    editor::setPreferredLanguage(m_language->currentData().toString());
    QSettings().setValue(kAutosaveKey, m_autosave->value());
}

} // namespace thespis::studio
