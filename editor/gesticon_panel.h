#pragma once
// GesticonPanel: the gesticon editor (paper §5): the gesture database of one character of the
// document — name, clip, body part (mask), default fades, dependent-joint filter — as an
// editable table (GesticonModel) with combo boxes for the clip and the body part and spin boxes
// for the fades; Add / Remove / Rename, each one undoable edit; and Preview, which plays the
// selected gesture on the character in every view (3D, Skeletons, posture chart, AR).
//
// A preview does not change the document: the gesture plays as a live action on the Session's
// Stage — the action the runtime built for it (its mask, its fades, its filter), as a script's
// activateAction_body would play it — from the playhead, and the clock plays to the end of the
// gesture. The live action is removed, and the playhead returns to where the preview began, when
// the gesture ends, when the user stops (the Stop button, or pausing the clock), on any edit and
// when the document or character changes.
//
// Before / After plays the gesture twice from the same time: without the dependent-joint filter
// (paper §4.4), then with it, a line above the buttons saying which one plays.
//
// Below, the character's BML lexemes (BmlLexiconBox): which gesture BML's <gesture lexeme> plays.

#include <QPointer>
#include <QWidget>

#include <optional>

#include "scenario/scenario_runtime.h"
#include "util/error.h"

class QComboBox;
class QLabel;
class QTableView;
class QToolButton;

namespace thespis::editor {

class BmlLexiconBox;
class Document;
class GesticonModel;
class Session;

class GesticonPanel : public QWidget {
    Q_OBJECT
public:
    explicit GesticonPanel(QWidget* parent = nullptr);
    ~GesticonPanel() override;

    /// The document edited (null: none). Shows its first character.
    void setDocument(Document* document);
    /// The session whose stage and clock previews play on; without one Preview is disabled.
    void setSession(Session* session);

    QTableView* table() const { return m_table; }
    GesticonModel* model() const { return m_model; }
    QComboBox* characterCombo() const { return m_characters; }
    QToolButton* previewButton() const { return m_preview; }
    QToolButton* compareButton() const { return m_compare; }
    /// The character's BML lexemes, below the gestures.
    BmlLexiconBox* lexiconBox() const { return m_lexicon; }
    /// What plays in a Before / After preview ("Before: …", "After: …"), empty otherwise.
    QString playing() const;
    /// The text of the message line (the last refused edit or failed preview), empty when none.
    QString message() const;

    /// Index of the character shown (-1: none).
    int currentCharacter() const;
    void setCurrentCharacter(int character);
    /// The selected rows, in order (the current row when nothing is selected).
    QList<int> selectedRows() const;
    /// Selects one row (and makes it current).
    void selectRow(int row);

    /// Adds a gesture playing the character's first clip, named "gesture", "gesture 2", …, and
    /// selects it. One undoable edit.
    void addGesture();
    /// Removes the selected gestures: one undoable edit, however many.
    void removeSelected();
    /// Starts editing the name of the current gesture in the table.
    void renameSelected();
    /// Plays the selected gesture on its character (see the class comment); restarts when a
    /// preview is already playing. Failures go to the message line.
    void preview();
    /// Plays the selected gesture without the dependent-joint filter, then with it.
    void compareFilter();
    /// Ends a preview (its live action goes); nothing when none plays.
    void stopPreview();
    bool isPreviewing() const { return m_previewing; }

signals:
    void previewingChanged(bool previewing);

private:
    void refreshCharacters();
    void updateActions();
    void showMessage(const QString& message);
    void onClockTime(core::Tick time);
    // Starts a preview; `filter` overrides the gesture's dependent-joint flag.
    void startPreview(std::optional<bool> filter);
    // Stops the preview playing now from the event loop: for stops asked for from inside the
    // clock's or the document's signals, which the stop's own clock changes must not re-enter.
    void stopPreviewLater();

    QPointer<Document> m_document;
    QPointer<Session> m_session;
    GesticonModel* m_model = nullptr;
    QComboBox* m_characters = nullptr;
    QTableView* m_table = nullptr;
    QToolButton* m_add = nullptr;
    QToolButton* m_remove = nullptr;
    QToolButton* m_rename = nullptr;
    QToolButton* m_preview = nullptr;
    QToolButton* m_compare = nullptr;
    QLabel* m_message = nullptr;
    QLabel* m_playing = nullptr;
    BmlLexiconBox* m_lexicon = nullptr;
    QString m_keptSelection; // the current gesture's name across a model reset

    // The preview playing, if any.
    bool m_previewing = false;
    int m_comparePass = 0; // 1: before (filter off), 2: after (filter on); 0: a plain preview
    int m_previewSerial = 0;
    core::Tick m_previewStart = 0;
    core::Tick m_previewEnd = 0;
    core::Tick m_previewClockDuration = 0; // what the preview set the clock's duration to
    core::Tick m_savedClockDuration = 0;
    bool m_savedLooping = false;
    bool m_previewOnFace = false; // a face gesture plays on the face track
    std::string m_previewCharacter, m_previewAction; // the live action the preview plays, and whose
};

} // namespace thespis::editor
