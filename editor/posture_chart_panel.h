#pragma once
// PostureChartPanel: the paper's Figs. 4–5 for the pose on screen — the magnitude of each
// principal component of a character's upper-body posture at the playhead (bars), against what
// captured motion shows at each component (the square root of the basis' eigenvalue: the
// typical size of a recorded posture's component), with the dependent-joint filter's band shaded
// and the share of the pose's energy above the band's start. A hand-keyed pose stands out by its
// energy in the high components, which the filter (paper §4.4) removes.
//
// The basis is the scenario's (Scenario::postureBases), else the one shipped with the studio.
// Charts the poses the Session publishes each tick, so what a script or a live action does
// shows; characters whose skeleton lacks H-Anim's upper-body joints, or a basis that cannot be
// read, are said so on the chart.

#include <QPointer>
#include <QWidget>

#include <memory>
#include <optional>
#include <vector>

#include "motion/posture.h"
#include "motion/posture_bases.h"
#include "runtime/pose_set.h"
#include "scenario/clip_file.h"

class QComboBox;

namespace thespis::widgets {
class ComponentChart;
}

namespace thespis::editor {

class Document;
class Session;

class PostureChartPanel : public QWidget {
    Q_OBJECT
public:
    explicit PostureChartPanel(QWidget* parent = nullptr);

    void setDocument(Document* document);
    /// The session whose poses are charted (null: none).
    void setSession(Session* session);
    /// The posture bases (.pca, absolute path) used when the scenario names none.
    void setDefaultBases(const QString& path);

    widgets::ComponentChart* chart() const { return m_chart; }
    QComboBox* characterCombo() const { return m_characters; }
    /// The components charted (|PC| of the pose, PC 1 first), empty when none are.
    const std::vector<float>& components() const { return m_magnitudes; }

private:
    // Reads the basis and maps the chosen character's skeleton; then plots.
    void rebuild();
    void plot(const core::runtime::PoseSet& poses);

    QPointer<Document> m_document;
    QPointer<Session> m_session;
    QString m_defaultBases;
    QComboBox* m_characters = nullptr;
    widgets::ComponentChart* m_chart = nullptr;
    core::scenario::AssetCache m_assets;
    std::shared_ptr<const core::motion::PostureBases> m_bases;
    std::optional<core::motion::PostureMap> m_map;
    int m_character = -1;     // in the document's characters
    std::size_t m_pose = 0;   // the character's index in the stage's pose sets
    core::anim::FrameLayoutPtr m_layout; // its skeleton's
    std::vector<float> m_frame, m_posture, m_pcs, m_magnitudes;
};

} // namespace thespis::editor
