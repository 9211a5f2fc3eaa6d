#include "editor/posture_chart_panel.h"

#include <QComboBox>
#include <QHBoxLayout>
#include <QVBoxLayout>

#include <cmath>

#include "editor/character_choice.h"
#include "editor/document.h"
#include "editor/session.h"
#include "editor/qt_conversions.h"
#include "motion/dependent_joint_filter.h"
#include "widgets/component_chart.h"

namespace thespis::editor {

namespace {

const QColor kPoseColor(0x3b, 0x7d, 0xd8);
const QColor kCapturedColor(0xe0, 0x7b, 0x26);

} // namespace

PostureChartPanel::PostureChartPanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("postureChartPanel"));
    auto* layout = new QVBoxLayout(this);
    auto* top = new QHBoxLayout;
    m_characters = addCharacterChoice(this, top, QStringLiteral("postureChartCharacter"),
                                      tr("The character whose posture at the playhead is charted"));
    layout->addLayout(top);
    m_chart = new widgets::ComponentChart(this);
    m_chart->setToolTip(tr("Each bar: how far the pose is along one principal component of the upper body's posture "
                           "space. The line: how far recorded motion typically goes along it. A hand-keyed pose "
                           "shows more in the high components; the dependent-joint filter fades and mutes them."));
    layout->addWidget(m_chart, 1);
    connect(m_characters, &QComboBox::currentIndexChanged, this, [this] { rebuild(); });
    setDocument(nullptr);
}

void PostureChartPanel::setDocument(Document* document)
{
    m_document = document;
    m_assets.clear();
    QSignalBlocker quiet(m_characters);
    fillCharacterChoice(m_characters, m_document);
    rebuild();
}

void PostureChartPanel::setSession(Session* session)
{
    if (m_session)
        disconnect(m_session, nullptr, this, nullptr);
    m_session = session;
    if (m_session) {
        connect(m_session, &Session::posesChanged, this, &PostureChartPanel::plot);
        // After the session gave its stage the edited runtime (which the chart reads).
        connect(m_session, &Session::edited, this, [this] {
            const QSignalBlocker quiet(m_characters);
            fillCharacterChoice(m_characters, m_document);
            rebuild();
        });
    }
    rebuild();
}

void PostureChartPanel::setDefaultBases(const QString& path)
{
    m_defaultBases = path;
    rebuild();
}

void PostureChartPanel::rebuild()
{
    m_bases.reset();
    m_map.reset();
    m_character = -1;
    m_magnitudes.clear();
    auto fail = [this](const QString& message) {
        m_chart->setSeries({}, {});
        m_chart->setMessage(message);
    };
    const int c = m_characters->currentIndex();
    if (!m_document || c < 0 || std::size_t(c) >= m_document->scenario().characters.size())
        return fail(tr("No character to chart."));
    const std::string basesName =
        m_document->scenario().postureBases.empty() ? m_defaultBases.toStdString() : m_document->scenario().postureBases;
    if (basesName.empty())
        return fail(tr("No posture bases: name a .pca file (thespis-cli train-pca) as the scenario's postureBases."));
    auto bases = m_assets.postureBases(basesName, m_document->assets());
    if (!bases)
        return fail(tr("The posture bases could not be read: %1").arg(fromUtf8(bases.error().message)));
    if (!m_session || !m_session->stage())
        return fail(tr("Nothing plays."));
    const auto& played = m_session->stage()->runtime();
    const auto* runtime = played.findCharacter(m_document->scenario().characters[std::size_t(c)].name);
    if (!runtime || !runtime->body)
        return fail(tr("The character has no body motion to chart."));
    auto map = core::motion::PostureMap::create(runtime->skeleton, core::motion::PostureSet::UpperBody);
    if (!map)
        return fail(tr("Cannot chart this character's posture: %1").arg(fromUtf8(map.error().message)));
    m_bases = std::move(*bases);
    m_map = std::move(*map);
    m_character = c;
    m_pose = std::size_t(runtime - played.characters.data());
    m_layout = runtime->skeleton.frameLayout();
    m_frame = runtime->skeleton.restFrame();
    m_posture.assign(std::size_t(m_map->layout().size()), 0.0f);
    m_pcs.assign(m_posture.size(), 0.0f);
    m_magnitudes.assign(m_posture.size(), 0.0f);
    plot(m_session->poses());
}

void PostureChartPanel::plot(const core::runtime::PoseSet& poses)
{
    if (!m_map || !m_bases || m_pose >= poses.characters.size())
        return;
    const core::runtime::CharacterPose& shown = poses.characters[m_pose];
    if (shown.body.size() != m_frame.size())
        return;
    // The pose on screen: the body placed where the character stands.
    std::copy(shown.body.begin(), shown.body.end(), m_frame.begin());
    shown.placement.apply(*m_layout, m_frame);
    m_map->toPosture(m_frame, m_posture);
    const core::motion::PostureBasis& basis = m_bases->upper;
    basis.project(m_posture, m_pcs);
    // Energy beyond the filter's first kept band: the pose's against recorded motion's.
    const core::motion::FilterBand band;
    double poseAbove = 0, poseAll = 0, capturedAbove = 0, capturedAll = 0;
    widgets::ChartSeries pose{tr("this pose |PC|"), kPoseColor, {}};
    widgets::ChartSeries captured{tr("captured motion, typical (√eigenvalue)"), kCapturedColor, {}};
    for (std::size_t i = 0; i < m_pcs.size(); ++i) {
        m_magnitudes[i] = std::abs(m_pcs[i]);
        const double lambda = std::max(0.0f, basis.eigenvalues()[i]);
        pose.values.push_back(m_magnitudes[i]);
        captured.values.push_back(float(std::sqrt(lambda)));
        const double energy = double(m_pcs[i]) * m_pcs[i];
        poseAll += energy;
        capturedAll += lambda;
        if (int(i) >= band.fadeFrom) {
            poseAbove += energy;
            capturedAbove += lambda;
        }
    }
    m_chart->setSeries(std::move(pose), {std::move(captured)});
    m_chart->setBands({{band.fadeFrom + 1, band.muteAbove, tr("filter fades")},
                       {band.muteAbove + 1, int(m_pcs.size()), tr("filter mutes")}});
    m_chart->setCaption(tr("%1 at %2 s — energy above PC %3: this pose %4 %, captured motion %5 %")
                            .arg(m_characters->currentText())
                            .arg(core::ticksToSeconds(poses.time), 0, 'f', 2)
                            .arg(band.fadeFrom)
                            .arg(poseAll > 0 ? 100 * poseAbove / poseAll : 0.0, 0, 'f', 1)
                            .arg(capturedAll > 0 ? 100 * capturedAbove / capturedAll : 0.0, 0, 'f', 1));
    m_chart->setMessage({});
}

} // namespace thespis::editor
