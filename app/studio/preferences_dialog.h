#pragma once
// PreferencesDialog: the studio's settings kept in QSettings — the user interface language
// (applies from the next start, as Qt widgets translate their texts when they are built) and
// how often open work is autosaved for crash recovery.

#include <QDialog>

class QComboBox;
class QLabel;
class QSpinBox;

namespace thespis::studio {

class PreferencesDialog : public QDialog {
    Q_OBJECT
public:
    explicit PreferencesDialog(QWidget* parent = nullptr);

    QComboBox* languageChoice() const { return m_language; }
    QSpinBox* autosaveMinutes() const { return m_autosave; }

    /// Minutes between autosaves as stored (default 1).
    static int storedAutosaveMinutes();

    /// Stores the choices (the dialog's OK does this).
    void apply();

private:
    QComboBox* m_language = nullptr;
    QLabel* m_restartNote = nullptr;
    QSpinBox* m_autosave = nullptr;
    QString m_initialLanguage;
};

} // namespace thespis::studio
