#pragma once
// VisemeTable: a viseme set (core/speech/viseme_set.h) shown and edited as a table — per viseme
// the phonemes that show it and its coarticulation α, weight and spread (paper §5.2: "for each
// viseme, the value of the α parameter can be chosen. Also, the weight of each function, as well
// as its spread (overlap)"), and the MPEG-4 viseme the face shows it as — with Load…, Save… and
// a choice of the built-in sets (MPEG-4, Oculus, SAPI). An entry the set refuses is put back, and the reason shown.
#include <QWidget>

#include "speech/viseme_set.h"

class QComboBox;
class QLabel;
class QTableWidget;
class QTableWidgetItem;

namespace thespis::editor {

class VisemeTable : public QWidget {
    Q_OBJECT
public:
    explicit VisemeTable(QWidget* parent = nullptr);

    const core::speech::VisemeSet& visemes() const { return m_set; }
    /// Shows `set` (refused with the reason when it does not validate).
    core::Result<void> setVisemes(core::speech::VisemeSet set);
    QTableWidget* table() const { return m_table; }
    QComboBox* builtInChoice() const { return m_builtIn; }
    /// Reads or writes a "thespis-visemes" file; errors name the file and field.
    core::Result<void> load(const QString& path);
    core::Result<void> save(const QString& path) const;

signals:
    void visemesChanged();

private:
    void fill();
    void onEdited(QTableWidgetItem* item);
    void showProblem(const QString& text);

    core::speech::VisemeSet m_set;
    QTableWidget* m_table = nullptr;
    QLabel* m_problem = nullptr;
    QComboBox* m_builtIn = nullptr;
    bool m_filling = false;
};

} // namespace thespis::editor
