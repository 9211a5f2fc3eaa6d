#include "editor/timeline_panel.h"

#include <QAction>
#include <QDir>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>
#include <set>

#include "edit/content_edits.h"
#include "editor/commands/command_ids.h"
#include "editor/document.h"
#include "editor/qt_conversions.h"
#include "widgets/timeline_view.h"

namespace thespis::editor {

using core::Tick;
using core::edit::ActionPath;
using core::edit::LayerPath;

namespace {

constexpr int kThumbnailSamples = 49; // odd, so the action's middle, where a dominance curve peaks, is sampled
constexpr double kOpenEndedThumbnail = 10.0; // seconds of an open-ended action's weight shown

// The fade lengths the timeline's handles show: the envelope's attack and release.
std::pair<double, double> fadesOf(const core::anim::Curve& weight)
{
    using core::anim::CurveKind;
    if (weight.kind() == CurveKind::Constant || weight.kind() == CurveKind::Keyframed)
        return {0.0, 0.0};
    return {weight.envelope().attack, weight.envelope().release};
}

} // namespace

TimelinePanel::TimelinePanel(QWidget* parent) : QWidget(parent)
{
    setObjectName(QStringLiteral("timelinePanel"));
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    m_view = new widgets::TimelineView(this);
    m_view->setObjectName(QStringLiteral("timelineView"));
    m_view->setTicksPerSecond(core::TicksPerSecond);
    m_view->setFrameRate(m_frameRate);
    layout->addWidget(m_view);

    auto makeAction = [this](const QString& text, const QKeySequence& key, const QString& name, auto slot) {
        auto* action = new QAction(text, this);
        action->setShortcut(key);
        action->setObjectName(name);
        // Window-wide: Delete and Ctrl+C work whichever panel last had the focus.
        action->setShortcutContext(Qt::WindowShortcut);
        connect(action, &QAction::triggered, this, slot);
        return action;
    };
    m_delete = makeAction(tr("&Delete"), QKeySequence::Delete, QStringLiteral("deleteActions"), [this] { onDelete(false); });
    m_rippleDelete = makeAction(tr("Ripple De&lete"), QKeySequence(Qt::SHIFT | Qt::Key_Delete),
                                QStringLiteral("rippleDeleteActions"), [this] { onDelete(true); });
    m_copy = makeAction(tr("&Copy"), QKeySequence::Copy, QStringLiteral("copyActions"), [this] { onCopy(); });
    m_paste = makeAction(tr("&Paste"), QKeySequence::Paste, QStringLiteral("pasteActions"), [this] { onPaste(); });
    m_duplicate = makeAction(tr("D&uplicate"), QKeySequence(Qt::CTRL | Qt::Key_D), QStringLiteral("duplicateActions"),
                             [this] { onDuplicate(); });
    m_split = makeAction(tr("&Split at Playhead"), QKeySequence(Qt::CTRL | Qt::Key_K), QStringLiteral("splitAction"),
                         [this] { onSplit(); });
    m_snap = new QAction(tr("S&napping"), this);
    m_snap->setObjectName(QStringLiteral("snapping"));
    m_snap->setCheckable(true);
    m_snap->setChecked(true);
    m_snap->setStatusTip(tr("Snap to frames, clip edges, markers and the playhead (hold Ctrl while dragging to bypass)"));
    connect(m_snap, &QAction::toggled, m_view, &widgets::TimelineView::setSnapping);

    connect(m_view, &widgets::TimelineView::seekRequested, this,
            [this](qint64 ticks) { emit seekRequested(ticks); });
    connect(m_view, &widgets::TimelineView::selectionChanged, this, [this](const QList<int>& ids) {
        const auto paths = pathsOf(ids);
        emit currentActionChanged(paths.empty() ? std::nullopt : std::optional<ActionPath>(paths.front()));
    });
    connect(m_view, &widgets::TimelineView::clipActivated, this, [this](int id) {
        if (id >= 0 && std::size_t(id) < m_clipPaths.size())
            emit actionActivated(m_clipPaths[std::size_t(id)]);
    });
    connect(m_view, &widgets::TimelineView::clipsMoveRequested, this, &TimelinePanel::onMoveRequested);
    connect(m_view, &widgets::TimelineView::clipTrimRequested, this,
            [this](int id, widgets::TimelineEdge edge, qint64 time, bool finished) {
                if (!m_document || id < 0 || std::size_t(id) >= m_clipPaths.size())
                    return;
                const ActionPath path = m_clipPaths[std::size_t(id)];
                const auto span = core::edit::actionSpan(m_document->scenario(), m_document->runtime(), path);
                if (!span)
                    return;
                report(m_document->edit(core::edit::trimAction(m_document->scenario(), path, *span,
                                                               edge == widgets::TimelineEdge::Start ? core::edit::Edge::Start
                                                                                                    : core::edit::Edge::End,
                                                               time, core::ticksPerFrame(m_frameRate)),
                                        tr("Trim Action"), Merge{TrimActionId, finished}));
            });
    connect(m_view, &widgets::TimelineView::clipFadeRequested, this,
            [this](int id, widgets::TimelineEdge edge, qint64 length, bool finished) {
                if (!m_document || id < 0 || std::size_t(id) >= m_clipPaths.size())
                    return;
                const double seconds = core::ticksToSeconds(length);
                const bool in = edge == widgets::TimelineEdge::Start;
                report(m_document->edit(core::edit::setActionFades(m_document->scenario(), m_clipPaths[std::size_t(id)],
                                                                   in ? std::optional(seconds) : std::nullopt,
                                                                   in ? std::nullopt : std::optional(seconds)),
                                        in ? tr("Change Fade In") : tr("Change Fade Out"), Merge{FadeActionId, finished}));
            });
    connect(m_view, &widgets::TimelineView::trackFlagRequested, this,
            [this](int track, widgets::TimelineTrackFlag flag, bool on) {
                if (!m_document || track < 0 || std::size_t(track) >= m_tracks.size())
                    return;
                const auto f = flag == widgets::TimelineTrackFlag::Mute   ? core::edit::LayerFlag::Mute
                               : flag == widgets::TimelineTrackFlag::Solo ? core::edit::LayerFlag::Solo
                                                                          : core::edit::LayerFlag::Lock;
                const QString names[] = {on ? tr("Mute Layer") : tr("Unmute Layer"), on ? tr("Solo Layer") : tr("Unsolo Layer"),
                                         on ? tr("Lock Layer") : tr("Unlock Layer")};
                report(m_document->edit(core::edit::setLayerFlag(m_document->scenario(), m_tracks[std::size_t(track)], f, on),
                                        names[int(f)]));
            });
    connect(m_view, &widgets::TimelineView::markerAddRequested, this, [this](qint64 time) {
        if (!m_document)
            return;
        core::scenario::Marker marker;
        marker.name = tr("Marker %1").arg(m_document->scenario().markers.size() + 1).toStdString();
        marker.time = time;
        report(m_document->edit(core::edit::addMarker(m_document->scenario(), std::move(marker)), tr("Add Marker")));
    });
    connect(m_view, &widgets::TimelineView::markerMoveRequested, this, [this](int index, qint64 time, bool finished) {
        if (m_document)
            report(m_document->edit(core::edit::moveMarker(m_document->scenario(), index, time), tr("Move Marker"),
                                    Merge{MoveMarkerId, finished}));
    });
    connect(m_view, &widgets::TimelineView::markerRemoveRequested, this, [this](int index) {
        if (m_document)
            report(m_document->edit(core::edit::removeMarker(m_document->scenario(), index), tr("Remove Marker")));
    });
    connect(m_view, &widgets::TimelineView::filesDropRequested, this, [this](int track, qint64 time, const QStringList& files) {
        if (track >= 0 && std::size_t(track) < m_tracks.size())
            emit filesDropped(m_tracks[std::size_t(track)], core::Tick(time), files);
    });
    connect(m_view, &widgets::TimelineView::clipDropRequested, this, [this](int track, qint64 time, const QString& clip) {
        if (!m_document || track < 0 || std::size_t(track) >= m_tracks.size())
            return;
        const LayerPath layer = m_tracks[std::size_t(track)];
        auto action = core::edit::actionFromClip(m_document->scenario(), layer, clip.toStdString(), time);
        if (!action) {
            report(action.error());
            return;
        }
        addActionAtEnd(layer, core::edit::insertActions(m_document->scenario(), layer, {*action}),
                       tr("Add Action %1").arg(clip));
    });
    connect(m_view, &widgets::TimelineView::synthesizerDropRequested, this, [this](int track, qint64 time, const QString& kind) {
        if (!m_document || track < 0 || std::size_t(track) >= m_tracks.size() || kind != QStringLiteral("idle"))
            return;
        const LayerPath layer = m_tracks[std::size_t(track)];
        // Named as the scenario names its files: relative to its folder, or as the character's
        // idle clip on the same file already names it (that clip then plays).
        std::string database = QDir::fromNativeSeparators(QDir(m_document->baseDir()).relativeFilePath(m_idleDatabase)).toStdString();
        std::error_code error;
        for (const auto& clip : m_document->scenario().characters[std::size_t(layer.character)].clips)
            if (clip.idle && std::filesystem::equivalent(m_document->assets().path(clip.idle->database), toFsPath(m_idleDatabase), error))
                database = clip.idle->database;
        addActionAtEnd(layer, core::edit::addIdleAction(m_document->scenario(), layer, database, time), tr("Add Idle Motion"));
    });
    setDocument(nullptr);
}

void TimelinePanel::addActionAtEnd(const LayerPath& layer, core::Result<core::edit::Edit> edit, const QString& text)
{
    const auto& layers = m_document->scenario().characters[std::size_t(layer.character)].layers;
    const int index = int(layers[std::size_t(layer.layer)].actions.size());
    auto done = m_document->edit(std::move(edit), text);
    report(done);
    if (done)
        selectActions({{layer.character, layer.layer, index}});
}

void TimelinePanel::setDocument(Document* document)
{
    if (m_document)
        disconnect(m_document, nullptr, this, nullptr);
    m_document = document;
    m_moveDrag.reset();
    if (m_document)
        connect(m_document, &Document::edited, this, [this] { refresh(); });
    m_view->setSelectedClips({});
    refresh();
    m_view->frameAll();
}

void TimelinePanel::setTime(core::Tick time)
{
    m_playhead = time;
    m_view->setPlayhead(m_playhead);
    m_view->ensureTimeVisible(m_playhead);
}

void TimelinePanel::setFrameRate(int framesPerSecond)
{
    if (framesPerSecond < 1)
        return;
    m_frameRate = framesPerSecond;
    m_view->setFrameRate(framesPerSecond);
}

void TimelinePanel::refresh()
{
    const auto selected = selectedActions();
    m_tracks.clear();
    m_clipPaths.clear();
    QVector<widgets::TimelineTrack> tracks;
    QVector<widgets::TimelineClip> clips;
    QVector<widgets::TimelineMarker> markers;
    QVector<widgets::TimelineCaption> captions;
    if (m_document) {
        const auto& scenario = m_document->scenario();
        for (int c = 0; c < int(scenario.characters.size()); ++c) {
            const auto& character = scenario.characters[std::size_t(c)];
            for (int l = 0; l < int(character.layers.size()); ++l) {
                const auto& layer = character.layers[std::size_t(l)];
                widgets::TimelineTrack track;
                track.name = QString::fromStdString(layer.name);
                track.group = QString::fromStdString(character.name);
                track.muted = layer.mute;
                track.solo = layer.solo;
                track.locked = layer.lock;
                track.kind = QString::fromLatin1(core::scenario::layerKindName(layer.kind));
                tracks.push_back(track);
                m_tracks.push_back({c, l});
                for (int a = 0; a < int(layer.actions.size()); ++a) {
                    const auto& spec = layer.actions[std::size_t(a)];
                    const ActionPath path{c, l, a};
                    const auto span = core::edit::actionSpan(scenario, m_document->runtime(), path);
                    widgets::TimelineClip clip;
                    clip.id = int(m_clipPaths.size());
                    clip.track = int(tracks.size()) - 1;
                    clip.name = QString::fromStdString(spec.name);
                    clip.start = spec.start;
                    clip.end = !span || span->openEnded ? widgets::TimelineView::OpenEnd : span->end;
                    const double duration = span && !span->openEnded ? core::ticksToSeconds(span->end - span->start)
                                                                     : core::anim::Curve::Infinite;
                    const auto [fadeIn, fadeOut] = fadesOf(spec.weight);
                    clip.fadeIn = core::secondsToTicks(fadeIn);
                    clip.fadeOut = std::isfinite(duration) ? core::secondsToTicks(fadeOut) : 0;
                    const double shown = std::isfinite(duration) ? duration : kOpenEndedThumbnail;
                    clip.weight.reserve(kThumbnailSamples);
                    for (int i = 0; i < kThumbnailSamples; ++i)
                        clip.weight.push_back(float(spec.weight.evaluate(shown * i / (kThumbnailSamples - 1), duration)));
                    clips.push_back(std::move(clip));
                    m_clipPaths.push_back(path);
                }
                // The words of the character's speech lines, with the visemes and gestures they drive.
                if ((layer.kind == core::scenario::LayerKind::Face && layer.name == "Speech") ||
                    (layer.kind == core::scenario::LayerKind::Body && layer.name == "Gestures"))
                    for (const auto& line : character.speech)
                        if (line.start)
                            for (const auto& word : line.words)
                                captions.push_back({int(tracks.size()) - 1, QString::fromStdString(word.text),
                                                    *line.start + core::secondsToTicks(word.start),
                                                    *line.start + core::secondsToTicks(word.end)});
            }
        }
        for (const auto& marker : scenario.markers)
            markers.push_back({QString::fromStdString(marker.name), marker.time});
    }
    m_view->setTracks(std::move(tracks));
    m_view->setClips(std::move(clips));
    m_view->setMarkers(std::move(markers));
    m_view->setCaptions(std::move(captions));
    m_view->setDuration(m_document ? m_document->previewDuration() : 0);
    selectActions(selected);
    const bool open = m_document != nullptr;
    for (QAction* action : {m_delete, m_rippleDelete, m_copy, m_paste, m_duplicate, m_split})
        action->setEnabled(open);
}

std::vector<ActionPath> TimelinePanel::pathsOf(const QList<int>& ids) const
{
    std::vector<ActionPath> paths;
    for (int id : ids)
        if (id >= 0 && std::size_t(id) < m_clipPaths.size())
            paths.push_back(m_clipPaths[std::size_t(id)]);
    std::sort(paths.begin(), paths.end());
    return paths;
}

std::optional<ActionPath> TimelinePanel::currentAction() const
{
    const std::vector<ActionPath> selected = selectedActions();
    if (selected.empty())
        return std::nullopt;
    return selected.front();
}

std::vector<ActionPath> TimelinePanel::selectedActions() const
{
    return pathsOf(m_view->selectedClips());
}

int TimelinePanel::clipId(const ActionPath& action) const
{
    const auto it = std::find(m_clipPaths.begin(), m_clipPaths.end(), action);
    return it == m_clipPaths.end() ? -1 : int(it - m_clipPaths.begin());
}

void TimelinePanel::selectActions(const std::vector<ActionPath>& actions)
{
    QList<int> ids;
    for (const ActionPath& action : actions)
        if (const int id = clipId(action); id >= 0)
            ids.push_back(id);
    m_view->setSelectedClips(ids);
    emit currentActionChanged(actions.empty() || ids.empty() ? std::nullopt
                                                             : std::optional<ActionPath>(m_clipPaths[std::size_t(ids.front())]));
}

void TimelinePanel::report(const core::Result<void>& result)
{
    if (!result)
        emit problem(QString::fromStdString(result.error().message));
}

void TimelinePanel::onMoveRequested(const QList<int>& ids, qint64 delta, int trackDelta, bool finished)
{
    if (!m_document)
        return;
    // The view sends the total since the press, always with the ids of the press: they name the
    // actions only until a step moves some to another layer, so the drag keeps the paths.
    if (!m_moveDrag)
        m_moveDrag = MoveDrag{m_document->scenario(), pathsOf(ids), {}, 0};
    MoveDrag& drag = *m_moveDrag;
    core::edit::Edit step; // empty: nothing more to do (still ends the drag's command when finished)
    auto wanted = core::edit::moveActions(drag.start, drag.actions, delta, trackDelta);
    if (!wanted)
        report(wanted.error());
    else if (!(*wanted == drag.applied))
        step = drag.applied.stepTo(*wanted);
    auto done = m_document->edit(std::move(step), tr("Move %n Action(s)", nullptr, int(drag.actions.size())),
                                 Merge{MoveActionsId, finished});
    report(done);
    if (wanted && done) {
        drag.applied = std::move(wanted).value();
        drag.appliedLayers = trackDelta;
    }
    // The moved actions stay selected, wherever they are now.
    selectActions(core::edit::movedActionPaths(drag.start, drag.actions, drag.appliedLayers));
    if (finished)
        m_moveDrag.reset();
}

void TimelinePanel::onDelete(bool ripple)
{
    const auto paths = selectedActions();
    if (!m_document || paths.empty())
        return;
    const auto edit = core::edit::removeActions(m_document->scenario(), paths, ripple ? &m_document->runtime() : nullptr);
    const QString text = ripple ? tr("Ripple Delete %n Action(s)", nullptr, int(paths.size()))
                                : tr("Delete %n Action(s)", nullptr, int(paths.size()));
    if (auto done = m_document->edit(edit, text); done)
        selectActions({});
    else
        report(done);
}

void TimelinePanel::onCopy()
{
    const auto paths = selectedActions();
    if (!m_document || paths.empty())
        return;
    m_clipboard.clear();
    Tick earliest = std::numeric_limits<Tick>::max();
    for (const ActionPath& p : paths)
        earliest = std::min(earliest, m_document->scenario().characters[std::size_t(p.character)]
                                          .layers[std::size_t(p.layer)].actions[std::size_t(p.action)].start);
    for (const ActionPath& p : paths) {
        auto spec = m_document->scenario().characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions[std::size_t(p.action)];
        spec.start -= earliest;
        m_clipboard.emplace_back(p.layerPath(), std::move(spec));
    }
}

void TimelinePanel::onPaste()
{
    if (!m_document || m_clipboard.empty())
        return;
    // Into the layers they came from, starting at the playhead.
    core::edit::Edit edit;
    std::vector<ActionPath> pasted;
    core::scenario::Scenario preview = m_document->scenario();
    for (const auto& [layer, spec] : m_clipboard) {
        auto copy = spec;
        copy.start += m_playhead;
        auto insert = core::edit::insertActions(preview, layer, {copy});
        if (!insert) {
            report(insert.error());
            return;
        }
        (void)insert->apply(preview);
        pasted.push_back({layer.character, layer.layer,
                          int(preview.characters[std::size_t(layer.character)].layers[std::size_t(layer.layer)].actions.size()) - 1});
        edit.append(std::move(*insert));
    }
    auto done = m_document->edit(std::move(edit), tr("Paste %n Action(s)", nullptr, int(m_clipboard.size())));
    report(done);
    if (done)
        selectActions(pasted);
}

void TimelinePanel::onDuplicate()
{
    const auto paths = selectedActions();
    if (!m_document || paths.empty())
        return;
    // Copies placed right after the selection, so they do not cover it.
    Tick first = std::numeric_limits<Tick>::max(), last = 0;
    for (const ActionPath& p : paths) {
        const auto span = core::edit::actionSpan(m_document->scenario(), m_document->runtime(), p);
        if (!span)
            continue;
        first = std::min(first, span->start);
        last = std::max(last, span->openEnded ? span->start + core::TicksPerSecond : span->end);
    }
    core::edit::Edit edit;
    std::vector<ActionPath> copies;
    core::scenario::Scenario preview = m_document->scenario();
    for (const ActionPath& p : paths) {
        auto spec = preview.characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions[std::size_t(p.action)];
        spec.start += last - first;
        auto insert = core::edit::insertActions(preview, p.layerPath(), {spec});
        if (!insert) {
            report(insert.error());
            return;
        }
        (void)insert->apply(preview);
        copies.push_back({p.character, p.layer,
                          int(preview.characters[std::size_t(p.character)].layers[std::size_t(p.layer)].actions.size()) - 1});
        edit.append(std::move(*insert));
    }
    auto done = m_document->edit(std::move(edit), tr("Duplicate %n Action(s)", nullptr, int(paths.size())));
    report(done);
    if (done)
        selectActions(copies);
}

void TimelinePanel::onSplit()
{
    const auto paths = selectedActions();
    if (!m_document || paths.size() != 1) {
        emit problem(tr("Select one action to split at the playhead."));
        return;
    }
    const auto span = core::edit::actionSpan(m_document->scenario(), m_document->runtime(), paths.front());
    if (!span)
        return;
    report(m_document->edit(core::edit::splitAction(m_document->scenario(), paths.front(), *span, m_playhead),
                            tr("Split Action")));
}

} // namespace thespis::editor
