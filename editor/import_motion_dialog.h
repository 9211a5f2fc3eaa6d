#pragma once
// ImportMotionDialog: File ▸ Import Motion… (and files dropped from the file manager). Reads each
// file (core::scenario::planClipImport) for the chosen character and shows what it found: its
// clips (a glTF file's animations, to tick), the joint naming convention, its unit, joints left
// unmapped, how its body was stood up, and whether it moves the character at all; the joint
// mapping of the selected file as a table the user can correct (and load from or save to a
// mapping file). A file that cannot be read says why (file and line) and adds nothing. On
// Import, edit() is the one undoable edit that adds every ticked clip.

#include <QDialog>
#include <QStringList>

#include <map>
#include <optional>
#include <string>
#include <vector>

#include "edit/scenario_edit.h"
#include "scenario/clip_import.h"

class QComboBox;
class QLabel;
class QPushButton;
class QTableWidget;
class QTreeWidget;
class QTreeWidgetItem;

namespace thespis::editor {

class Document;

class ImportMotionDialog : public QDialog {
    Q_OBJECT
public:
    ImportMotionDialog(const Document& document, QStringList files, int character, QWidget* parent = nullptr);

    /// The character the clips go to.
    int character() const;
    /// The edit adding every ticked clip of every readable file (nullopt: nothing to add).
    std::optional<core::edit::Edit> edit() const;
    /// The names the ticked clips will have (in the edit's order).
    QStringList clipNames() const;

    QComboBox* characterChoice() const { return m_character; }
    QTreeWidget* fileTree() const { return m_files; }
    QTableWidget* mappingTable() const { return m_mapping; }
    QLabel* reportLabel() const { return m_report; }
    QPushButton* importButton() const { return m_import; }
    QPushButton* applyMappingButton() const { return m_applyMapping; }
    /// Saves the selected file's mapping table (the Save Mapping… button without its dialog).
    bool saveMapping(const QString& path);
    /// Reads a mapping file into the selected file's table and re-reads the file with it.
    bool loadMapping(const QString& path);

private:
    struct Entry {
        QString path;
        std::optional<core::scenario::ClipImport> plan;
        QString error; ///< the reader's message when the file could not be read
        std::map<std::string, std::string> mapping; ///< the user's table; empty: automatic
    };

    void plan(Entry& entry);
    void rebuild();
    void showSelected();
    int selectedEntry() const;
    void onApplyMapping();
    void updateImportButton();

    const Document& m_document;
    std::vector<Entry> m_entries;
    QComboBox* m_character = nullptr;
    QTreeWidget* m_files = nullptr;
    QLabel* m_report = nullptr;
    QLabel* m_mappingTitle = nullptr;
    QTableWidget* m_mapping = nullptr;
    QPushButton* m_applyMapping = nullptr;
    QPushButton* m_loadMapping = nullptr;
    QPushButton* m_saveMapping = nullptr;
    QPushButton* m_import = nullptr;
    bool m_filling = false;
};

} // namespace thespis::editor
