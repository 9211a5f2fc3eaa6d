#pragma once
// FacePosePanel: the face pose editor (paper §4.2, §5.2). MPEG-4's FAPs in their groups (mouth
// and jaw, eyes, brows, cheeks, tongue, head, nose, ears) and the weights of the 6 expressions
// and 14 visemes as sliders; while "Pose" is on, the pose plays live on the chosen character's
// face (a live action on the Stage's face track over what the face plays, the document
// unchanged), so the 3D view — turned to a close-up of the face — shows each change at once. The
// pose may start from the face at the playhead. "Save" adds it to the character as a face clip,
// and to its gesticon as a face gesture when asked: one undoable step.

#include <QPointer>
#include <QWidget>

#include <array>
#include <string>
#include <vector>

#include "scene/fap.h"

class QCheckBox;
class QComboBox;
class QLabel;
class QLineEdit;
class QPushButton;
class QSlider;
class QSpinBox;
class QToolBox;

namespace thespis::editor {

class Document;
class Session;

class FacePosePanel : public QWidget {
    Q_OBJECT
public:
    explicit FacePosePanel(QWidget* parent = nullptr);
    ~FacePosePanel() override;

    void setDocument(Document* document);
    void setSession(Session* session);

    int currentCharacter() const;
    void setCurrentCharacter(int character);
    /// The face frame being posed (kFaceChannelCount values: FAPs in their units, the visemes'
    /// and expressions' weights 0 … 1).
    const std::array<float, core::scene::kFaceChannelCount>& pose() const { return m_pose; }
    /// Sets one channel as its slider would (clamped to the slider's range).
    void setChannel(int channel, float value);
    /// Plays the pose live on the character (on) or stops (off).
    void setPosing(bool posing);
    bool isPosing() const { return m_posing; }
    /// Starts from the character's face as it is at the playhead.
    void takeFromPlayhead();
    /// Every channel back to 0: the neutral face.
    void reset();
    /// Adds the pose to the character as a face clip named `name` (and as a gesture of that name
    /// when `gesture`), as one undoable edit. False, with message() saying why, when refused.
    bool save(const QString& name, bool gesture);

    QSlider* slider(int channel) const { return m_sliders[std::size_t(channel)]; }
    QToolBox* groups() const { return m_groups; }
    QString message() const;

signals:
    /// The 3D view should turn to a close-up of this character's face.
    void closeUpRequested(int character);

private:
    void addGroup(const QString& title, const std::vector<int>& channels);
    void showChannel(int channel);
    void replay();
    void stopPlaying();
    void showMessage(const QString& message);
    void updateActions();

    Document* m_document = nullptr;
    QPointer<Session> m_session; // the session may go first when the window closes
    std::array<float, core::scene::kFaceChannelCount> m_pose{};
    std::array<QSlider*, core::scene::kFaceChannelCount> m_sliders{};
    std::array<QSpinBox*, core::scene::kFaceChannelCount> m_spins{};
    bool m_posing = false;
    bool m_updating = false;
    std::string m_playingCharacter; ///< whose face the live action is on ("" none)
    QComboBox* m_characters = nullptr;
    QPushButton* m_posingButton = nullptr;
    QPushButton* m_fromPlayhead = nullptr;
    QPushButton* m_reset = nullptr;
    QToolBox* m_groups = nullptr;
    QLineEdit* m_name = nullptr;
    QCheckBox* m_asGesture = nullptr;
    QPushButton* m_save = nullptr;
    QLabel* m_message = nullptr;
};

} // namespace thespis::editor
