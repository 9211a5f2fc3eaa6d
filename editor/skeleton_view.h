#pragma once
// SkeletonView: the Skeletons tab — one stick figure per character (StickFigure), drawn by a
// widgets::PoseView from the poses the Session publishes each tick, framed once per cast on the
// whole timeline (the Session's timeline samples).

#include <QObject>

#include <string>
#include <utility>
#include <vector>

#include "editor/stick_figure.h"
#include "runtime/pose_set.h"

namespace thespis::widgets {
class PoseView;
}

namespace thespis::editor {

class Document;
class Session;

class SkeletonView : public QObject {
    Q_OBJECT
public:
    /// Registers with `session` (a view of its documents and poses).
    SkeletonView(widgets::PoseView* view, Session* session, QObject* parent = nullptr);

    const std::vector<StickFigure>& figures() const { return m_figures; }

private:
    // New figures for the session's characters; `frame`: aim the view on their timeline.
    void rebuild(bool frame);
    void onEdited();
    void show(const core::runtime::PoseSet& poses);

    widgets::PoseView* m_view;
    Session* m_session;
    std::vector<StickFigure> m_figures;
    std::vector<std::pair<std::string, std::string>> m_keys; // per character: name, skeleton
};

} // namespace thespis::editor
