#include "editor/skeleton_view.h"

#include <algorithm>

#include "editor/document.h"
#include "editor/session.h"
#include "widgets/pose_view.h"

namespace thespis::editor {

namespace {
std::vector<std::pair<std::string, std::string>> castOf(const Document* document)
{
    std::vector<std::pair<std::string, std::string>> keys;
    if (document)
        for (const core::scenario::Character& character : document->scenario().characters)
            keys.emplace_back(character.name, character.skeleton);
    return keys;
}
} // namespace

SkeletonView::SkeletonView(widgets::PoseView* view, Session* session, QObject* parent)
    : QObject(parent), m_view(view), m_session(session)
{
    session->addView([this](Document*) { rebuild(true); }, this);
    connect(session, &Session::edited, this, &SkeletonView::onEdited);
    connect(session, &Session::posesChanged, this, &SkeletonView::show);
}

void SkeletonView::onEdited()
{
    // Characters added, removed or given another skeleton: new figures, framed anew.
    if (castOf(m_session->document()) != m_keys)
        rebuild(true);
}

void SkeletonView::rebuild(bool frame)
{
    const Document* document = m_session->document();
    m_keys = castOf(document);
    m_figures.clear();
    std::vector<widgets::PoseFigure> figures;
    if (document && m_session->stage())
        for (const core::scenario::CharacterRuntime& character : m_session->stage()->runtime().characters) {
            m_figures.emplace_back(character.name, character.skeleton);
            figures.push_back(m_figures.back().figure(widgets::figureColor(int(figures.size()))));
        }
    m_view->setFigures(std::move(figures));

    // The box every joint stays in over the timeline.
    bool haveBounds = false;
    QVector3D low, high;
    if (!m_figures.empty())
        for (const core::runtime::PoseSet& sample : m_session->timelineSamples())
            for (std::size_t c = 0; c < m_figures.size() && c < sample.characters.size(); ++c) {
                m_figures[c].setPose(sample.characters[c]);
                for (const QVector3D& p : m_figures[c].positions()) {
                    low = haveBounds ? QVector3D(std::min(low.x(), p.x()), std::min(low.y(), p.y()), std::min(low.z(), p.z())) : p;
                    high = haveBounds ? QVector3D(std::max(high.x(), p.x()), std::max(high.y(), p.y()), std::max(high.z(), p.z())) : p;
                    haveBounds = true;
                }
            }
    // H-Anim skeletons are in metres; a skeleton taken from a BVH file keeps the file's unit,
    // which BVH does not name.
    const bool metres = std::none_of(m_keys.begin(), m_keys.end(), [](const auto& key) { return key.second.starts_with("clip:"); });
    m_view->setLengthUnit(metres ? tr("m", "metres") : tr("units", "length unit of a BVH file"));
    if (haveBounds && frame)
        m_view->setSceneBounds(low, high);
    else if (!haveBounds)
        m_view->clearSceneBounds();
    if (document && m_figures.empty())
        m_view->setPlaceholderText(tr("This scenario has no characters yet."));
    else
        m_view->setPlaceholderText(tr("No scenario is open.\nUse File ▸ Open… (Ctrl+O) to open a .thespis file."));
    show(m_session->poses());
}

void SkeletonView::show(const core::runtime::PoseSet& poses)
{
    for (std::size_t c = 0; c < m_figures.size() && c < poses.characters.size(); ++c) {
        m_figures[c].setPose(poses.characters[c]);
        m_view->setFigurePositions(int(c), m_figures[c].positions());
    }
}

} // namespace thespis::editor
