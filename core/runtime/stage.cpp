#include "runtime/stage.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "anim/curve.h"

namespace thespis::core::runtime {

using anim::ActionId;
using anim::BlendingAction;
using anim::BlendingSchedule;
using anim::BlendMode;

namespace {

constexpr double Infinity = std::numeric_limits<double>::infinity();

const char* trackName(Track track) { return track == Track::Body ? "body" : "face"; }

/// A live action's fade-in over what plays: scales its weights by a cubic ramp.
class FadeIn final : public anim::CustomBlendingParams {
public:
    explicit FadeIn(double seconds) : m_seconds(seconds) {}
    void modulate(double localTime, const anim::FrameLayout&, std::span<float> weights) const override
    {
        if (localTime >= m_seconds)
            return;
        const float f = float(anim::smoothStep(std::max(localTime, 0.0) / m_seconds));
        for (float& w : weights)
            w *= f;
    }

private:
    double m_seconds;
};

/// An action that plays from 0 for ever.
BlendingAction forever(std::string name, anim::BlendablePtr source)
{
    BlendingAction action;
    action.name = std::move(name);
    action.source = std::move(source);
    action.renderOutsideDomain = true;
    return action;
}

std::string joinNames(const std::vector<std::string>& names)
{
    std::string text;
    for (const std::string& name : names)
        text += (text.empty() ? "" : ", ") + name;
    return text.empty() ? "none" : text;
}

} // namespace

/// What plays below the live layered actions this tick, as the first action they go over.
class Stage::HeldFrame final : public anim::BlendableObject {
public:
    HeldFrame(anim::FrameLayoutPtr layout, std::vector<float> initial)
        : m_layout(std::move(layout)), frame(std::move(initial))
    {
    }
    const anim::FrameLayoutPtr& layout() const override { return m_layout; }
    anim::TimeDomain domain() const override { return {0, Infinity}; }
    void evaluate(double, std::span<float> out) const override { std::copy(frame.begin(), frame.end(), out.begin()); }

private:
    anim::FrameLayoutPtr m_layout;

public:
    std::vector<float> frame;
};

Stage::Stage(scenario::ScenarioRuntime runtime) : m_runtime(std::move(runtime))
{
    m_performers.reserve(m_runtime.characters.size());
    for (scenario::CharacterRuntime& character : m_runtime.characters) {
        Performer performer;
        performer.name = character.name;
        // Built from a valid runtime: nesting its schedules cannot fail.
        [[maybe_unused]] const Result<void> made =
            initPerformer(performer, character.skeleton, character.body, character.face);
        assert(made);
        fillLibrary(performer, character);
        cacheAuthored(performer.body);
        cacheAuthored(performer.face);
        m_performers.push_back(std::move(performer));
    }
}

void Stage::fillLibrary(Performer& performer, scenario::CharacterRuntime& character)
{
    for (TrackState* track : {&performer.body, &performer.face}) {
        track->library.clear();
        track->authoredLayers.clear();
    }
    performer.body.authored = character.body;
    performer.face.authored = character.face;
    for (const auto& [name, clip] : character.clips)
        performer.body.library[name] = ActionTemplate{clip, {}, false};
    for (const auto& [name, clip] : character.faceClips)
        performer.face.library[name] = ActionTemplate{clip, {}, false};
    for (std::size_t l = 0; l < character.layers.size(); ++l) {
        BlendingSchedule& layer = *character.layers[l];
        TrackState& track = *layer.layout() == *character.skeleton.frameLayout() ? performer.body : performer.face;
        track.authoredLayers.push_back(character.layers[l]);
        for (const ActionId id : character.actionIds[l])
            if (const BlendingAction* action = layer.action(id); action && !action->name.empty())
                track.library[action->name] = ActionTemplate{action->source, action->params, action->renderOutsideDomain};
    }
    for (const auto& [name, gesture] : character.gestures) {
        const BlendingAction& played = gesture.played();
        (gesture.face ? performer.face : performer.body).library[name] =
            ActionTemplate{played.source, played.params, played.renderOutsideDomain, gesture.fadeIn, gesture.fadeOut,
                           {gesture.hold, gesture.stroke}};
    }
}

Result<std::optional<ActionTemplate>> Stage::actionTemplate(const std::string& character, Track track,
                                                            const std::string& action) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    const TrackState& s = state(**performer, track);
    const auto found = s.library.find(action);
    return found == s.library.end() ? std::nullopt : std::optional<ActionTemplate>(found->second);
}

scenario::ScenarioRuntime Stage::runtimeCopy() const
{
    const std::lock_guard lock(m_mutex);
    return m_runtime;
}

Result<void> Stage::setRuntime(scenario::ScenarioRuntime runtime)
{
    const std::lock_guard lock(m_mutex);
    if (runtime.characters.size() != m_performers.size())
        return makeError(ErrorCode::InvalidArgument, "The scenario's characters changed: the stage must be rebuilt.");
    for (std::size_t i = 0; i < m_performers.size(); ++i) {
        const scenario::CharacterRuntime& next = runtime.characters[i];
        if (next.name != m_performers[i].name ||
            !(*next.skeleton.frameLayout() == *m_performers[i].body.live->layout()))
            return makeError(ErrorCode::InvalidArgument,
                             "Character \"" + next.name + "\" changed: the stage must be rebuilt.");
    }
    m_authoredCuts.clear(); // they were cut in the old schedules
    m_runtime = std::move(runtime);
    for (std::size_t i = 0; i < m_performers.size(); ++i) {
        fillLibrary(m_performers[i], m_runtime.characters[i]); // live actions play on
        // The gaze actions may have changed: the one playing is looked up again, and a gaze one
        // started lets go unless it still plays.
        m_performers[i].authoredCue = -1;
        if (m_performers[i].gaze && m_performers[i].gaze->authored)
            m_performers[i].gaze->release = 0.0;
        m_performers[i].authoredPointing = -1;
        if (m_performers[i].pointing && m_performers[i].pointing->authored)
            m_performers[i].pointing.reset();
        cacheAuthored(m_performers[i].body);
        cacheAuthored(m_performers[i].face);
    }
    return {};
}

Result<void> Stage::initPerformer(Performer& performer, const anim::Skeleton& skeleton,
                                  std::shared_ptr<const BlendingSchedule> body,
                                  std::shared_ptr<const BlendingSchedule> face)
{
    const auto faceLayout = anim::FrameLayout::mpeg4Face();
    performer.skeleton = skeleton;
    if (auto rig = motion::GazeRig::create(skeleton))
        performer.gazeRig = std::move(rig).value();
    const std::pair<TrackState*, std::shared_ptr<const BlendingSchedule>> tracks[] = {{&performer.body, body},
                                                                                        {&performer.face, face}};
    for (auto [track, authored] : tracks) {
        track->authored = std::move(authored);
        const bool isBody = track == &performer.body; // clang 14 cannot capture a structured binding
        const auto make = [&] {
            return isBody ? std::make_shared<BlendingSchedule>(skeleton) : std::make_shared<BlendingSchedule>(faceLayout);
        };
        track->synthesizers = make();
        track->live = make();
        track->layered = make();
        track->below = std::make_shared<HeldFrame>(track->layered->layout(), track->layered->restPose());
        if (auto id = track->layered->addAction(forever("below", track->below)); !id)
            return id.error();
        track->scratch = track->layered->restPose();
        track->coverage.assign(std::size_t(track->layered->layout()->elementCount()), 0.0f);
    }
    return {};
}

Result<int> Stage::addCharacter(std::string name, const anim::Skeleton& skeleton)
{
    const std::lock_guard lock(m_mutex);
    for (const Performer& p : m_performers)
        if (p.name == name)
            return makeError(ErrorCode::InvalidArgument, "There is already a character called \"" + name + "\".");
    Performer performer;
    performer.name = std::move(name);
    if (auto made = initPerformer(performer, skeleton, nullptr, nullptr); !made)
        return made.error();
    m_performers.push_back(std::move(performer));
    return int(m_performers.size()) - 1;
}

int Stage::characterCount() const
{
    const std::lock_guard lock(m_mutex);
    return int(m_performers.size());
}

std::vector<std::string> Stage::characterNames() const
{
    const std::lock_guard lock(m_mutex);
    std::vector<std::string> names;
    for (const Performer& p : m_performers)
        names.push_back(p.name);
    return names;
}

int Stage::findCharacter(const std::string& name) const
{
    const std::lock_guard lock(m_mutex);
    for (std::size_t i = 0; i < m_performers.size(); ++i)
        if (m_performers[i].name == name)
            return int(i);
    return -1;
}

Result<anim::Skeleton> Stage::skeleton(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    return (*performer)->skeleton;
}

Result<speech::BmlLexicon> Stage::bmlLexicon(const std::string& character) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    const auto index = std::size_t(*performer - m_performers.data());
    return index < m_runtime.characters.size() ? m_runtime.characters[index].bmlLexicon : speech::BmlLexicon::defaults();
}

Result<Stage::Performer*> Stage::find(const std::string& character)
{
    for (Performer& p : m_performers)
        if (p.name == character)
            return &p;
    std::vector<std::string> names;
    for (const Performer& p : m_performers)
        names.push_back(p.name);
    return makeError(ErrorCode::NotFound,
                     "There is no character \"" + character + "\" on the stage (it has: " + joinNames(names) + ").");
}

Result<const Stage::Performer*> Stage::find(const std::string& character) const
{
    auto found = const_cast<Stage*>(this)->find(character);
    if (!found)
        return found.error();
    return static_cast<const Performer*>(*found);
}

Stage::TrackState& Stage::state(Performer& performer, Track track)
{
    return track == Track::Body ? performer.body : performer.face;
}

const Stage::TrackState& Stage::state(const Performer& performer, Track track)
{
    return track == Track::Body ? performer.body : performer.face;
}

Result<void> Stage::defineAction(const std::string& character, Track track, const std::string& action,
                                 ActionTemplate source)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    TrackState& s = state(**performer, track);
    if (auto fits = fitsTrack(s, character, track, action, source); !fits)
        return fits;
    s.library[action] = std::move(source);
    return {};
}

Result<void> Stage::fitsTrack(const TrackState& s, const std::string& character, Track track, const std::string& action,
                              const ActionTemplate& source)
{
    if (!source.source || !(*source.source->layout() == *s.live->layout()))
        return makeError(ErrorCode::InvalidArgument, "Action \"" + action + "\" of " + character + " needs a " +
                                                         trackName(track) + " source on the " + trackName(track) +
                                                         "'s layout.");
    return {};
}

Result<std::vector<std::string>> Stage::actionNames(const std::string& character, Track track) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    std::vector<std::string> names;
    for (const auto& [name, source] : state(**performer, track).library)
        names.push_back(name);
    return names;
}

Result<void> Stage::setSynthesizer(const std::string& character, Track track, const std::string& slot,
                                   anim::BlendablePtr source)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    TrackState& s = state(**performer, track);
    if (auto old = s.synthSlots.find(slot); old != s.synthSlots.end()) {
        s.synthesizers->removeAction(old->second);
        s.synthSlots.erase(old);
    }
    if (source) {
        auto id = s.synthesizers->addAction(forever(slot, std::move(source)));
        if (!id)
            return id.error();
        s.synthSlots[slot] = *id;
    }
    return {};
}

void Stage::setTrackEnabled(Track track, bool enabled)
{
    const std::lock_guard lock(m_mutex);
    (track == Track::Body ? m_bodyEnabled : m_faceEnabled) = enabled;
}

Result<ActionId> Stage::activateAction(const std::string& character, Track track, const std::string& action,
                                       Tick at, const ActivateOptions& options)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    TrackState& s = state(**performer, track);
    const auto source = s.library.find(action);
    if (source == s.library.end()) {
        std::vector<std::string> names;
        for (const auto& [name, unused] : s.library)
            names.push_back(name);
        return makeError(ErrorCode::NotFound, "Character \"" + character + "\" has no " + trackName(track) +
                                                  " action \"" + action + "\" (it has: " + joinNames(names) + ").");
    }
    return activate(s, action, source->second, at, options);
}

Result<ActionId> Stage::playAction(const std::string& character, Track track, const std::string& action,
                                   const ActionTemplate& source, Tick at, const ActivateOptions& options)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    TrackState& s = state(**performer, track);
    if (auto fits = fitsTrack(s, character, track, action, source); !fits)
        return fits.error();
    return activate(s, action, source, at, options);
}

Result<ActionId> Stage::activate(TrackState& s, const std::string& action, const ActionTemplate& source, Tick at,
                                 const ActivateOptions& options)
{
    const double start = ticksToSeconds(at);
    dropFinished(s, start);

    BlendingAction live;
    live.name = action;
    live.source = source.source;
    live.params = source.params;
    live.renderOutsideDomain = source.renderOutsideDomain;
    live.start = start;
    if (options.weight)
        live.params.weight = *options.weight;
    const double duration = live.source->domain().duration();
    if (options.fadeIn > 0 && live.params.weight.evaluate(0.0, duration) > 0)
        live.params.custom.push_back(std::make_shared<FadeIn>(options.fadeIn));

    const bool normalized = live.params.mode == BlendMode::Normalized;
    BlendingSchedule& schedule = normalized ? *s.live : *s.layered;
    auto id = schedule.addAction(std::move(live));
    if (!id)
        return id.error();
    if (auto previous = s.latest.find(action); previous != s.latest.end() && previous->second.schedule)
        s.superseded.push_back(previous->second);
    s.latest[action] = Activation{&schedule, *id, start, 0};
    ++(normalized ? s.liveCount : s.layeredCount);
    return *id;
}

std::optional<Stage::Activation> Stage::lookUp(const TrackState& track, const std::string& action, Tick at) const
{
    if (auto live = track.latest.find(action); live != track.latest.end())
        return live->second;
    // Authored: the latest of that name to start by `at`.
    const double t = ticksToSeconds(at);
    std::optional<Activation> found;
    for (const auto& layer : track.authoredLayers)
        for (const ActionId id : layer->actionIds()) {
            const BlendingAction* a = layer->action(id);
            if (a->name == action && a->start <= t && (!found || a->start > found->start))
                found = Activation{layer.get(), id, a->start, 0};
        }
    return found;
}

Result<bool> Stage::cutOffAction(const std::string& character, Track track, const std::string& action, Tick at,
                                 double fadeSeconds)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    const TrackState& s = state(**performer, track);
    const auto found = lookUp(s, action, at);
    const double t = ticksToSeconds(at);
    if (!found || found->start > t || found->finished(t))
        return false;
    if (!found->schedule->cutOffAction(found->id, t, std::max(fadeSeconds, 0.0)))
        return false;
    if (!s.latest.contains(action))
        m_authoredCuts.push_back(*found);
    return true;
}

Result<bool> Stage::removeAction(const std::string& character, Track track, const std::string& action)
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    TrackState& s = state(**performer, track);
    const auto live = s.latest.find(action);
    if (live == s.latest.end())
        return false;
    Activation& a = live->second;
    if (!a.schedule)
        return false; // finished and dropped already
    a.end = a.start;
    drop(s, a);
    return true;
}

Result<bool> Stage::isPlaying(const std::string& character, Track track, const std::string& action, Tick at) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    const auto found = lookUp(state(**performer, track), action, at);
    const double t = ticksToSeconds(at);
    return found && found->start <= t && !found->finished(t);
}

Result<double> Stage::actionEnd(const std::string& character, Track track, const std::string& action) const
{
    const std::lock_guard lock(m_mutex);
    auto performer = find(character);
    if (!performer)
        return performer.error();
    const auto found = lookUp(state(**performer, track), action, std::numeric_limits<Tick>::max());
    if (!found)
        return makeError(ErrorCode::NotFound, "Character \"" + character + "\" has not played " + trackName(track) +
                                                  " action \"" + action + "\": activate it first.");
    return found->endTime();
}

Result<double> Stage::timeUntilFinished(const std::string& character, Track track, const std::string& action,
                                        Tick at) const
{
    auto end = actionEnd(character, track, action);
    if (!end)
        return end;
    return std::max(0.0, *end - ticksToSeconds(at));
}

void Stage::resetLive()
{
    const std::lock_guard lock(m_mutex);
    for (Performer& performer : m_performers) {
        performer.gaze.reset();
        performer.pointing.reset();
        performer.authoredCue = -1; // the scenario's gaze and pointing actions playing start again
        performer.authoredPointing = -1;
        for (TrackState* s : {&performer.body, &performer.face}) {
            for (auto& [name, activation] : s->latest)
                if (activation.schedule)
                    drop(*s, activation);
            for (Activation& activation : s->superseded)
                drop(*s, activation);
            for (const auto& [name, id] : s->synthSlots)
                s->synthesizers->removeAction(id);
            s->latest.clear();
            s->superseded.clear();
            s->synthSlots.clear();
        }
    }
    for (const Activation& cut : m_authoredCuts)
        cut.schedule->restoreAction(cut.id);
    m_authoredCuts.clear();
}

void Stage::drop(TrackState& track, Activation& activation)
{
    --(activation.schedule == track.live.get() ? track.liveCount : track.layeredCount);
    activation.schedule->removeAction(activation.id);
    activation.schedule = nullptr;
}

void Stage::dropFinished(TrackState& track, double seconds)
{
    if (track.liveCount == 0 && track.layeredCount == 0)
        return;
    for (auto& [name, a] : track.latest)
        if (a.schedule && a.schedule->isFinished(a.id, seconds)) {
            a.end = a.schedule->endTime(a.id);
            drop(track, a);
        }
    std::erase_if(track.superseded, [&](Activation& a) {
        if (!a.schedule->isFinished(a.id, seconds))
            return false;
        drop(track, a);
        return true;
    });
}

PoseSet Stage::makePoseSet() const
{
    const std::lock_guard lock(m_mutex);
    PoseSet poses;
    for (std::size_t i = 0; i < m_performers.size(); ++i)
        poses.characters.push_back(
            CharacterPose{m_performers[i].body.live->restPose(), placement(i), m_performers[i].face.live->restPose()});
    return poses;
}

void Stage::evaluateTrack(TrackState& track, double seconds, std::vector<float>& out) const
{
    const anim::FrameLayout& layout = *track.live->layout();
    const auto overlayByCoverage = [&](const anim::BlendableObject& schedule) {
        schedule.evaluateWithCoverage(seconds, track.scratch, track.coverage);
        m_blender->overlay(layout, anim::BlendInput{track.scratch.data(), track.coverage.data()}, out);
    };
    // 1, 2: the synthesizers, and the authored schedule over them; alone, the authored one as is.
    if (track.synthesizers->actionCount() > 0) {
        track.synthesizers->evaluate(seconds, out);
        if (track.played)
            overlayByCoverage(*track.played);
    } else if (track.played) {
        track.played->evaluate(seconds, out);
    } else {
        std::copy(track.live->restPose().begin(), track.live->restPose().end(), out.begin());
    }
    // 3: live Normalized actions take over by how much they drive.
    if (track.liveCount > 0)
        overlayByCoverage(*track.live);
    // 4: live Override and Additive actions go over all that.
    if (track.layeredCount > 0) {
        std::copy(out.begin(), out.end(), track.below->frame.begin());
        track.layered->evaluate(seconds, out);
    }
}

void Stage::evaluate(Tick t, PoseSet& out)
{
    const std::lock_guard lock(m_mutex);
    const double seconds = ticksToSeconds(t);
    out.time = t;
    ++m_ticks;
    for (std::size_t i = 0; i < m_performers.size() && i < out.characters.size(); ++i) {
        Performer& performer = m_performers[i];
        out.characters[i].placement = placement(i);
        // A track turned off shows its rest pose, whatever the pose set held before.
        const auto play = [&](bool enabled, TrackState& track, std::vector<float>& frame) {
            if (!enabled) {
                std::copy(track.live->restPose().begin(), track.live->restPose().end(), frame.begin());
                return;
            }
            dropFinished(track, seconds);
            evaluateTrack(track, seconds, frame);
        };
        play(m_bodyEnabled, performer.body, out.characters[i].body);
        play(m_faceEnabled, performer.face, out.characters[i].face);
    }
    applyGazes(seconds, out);
    applyPointing(seconds, out);
}

anim::Placement Stage::placement(std::size_t performer) const
{
    return performer < m_runtime.characters.size() ? m_runtime.characters[performer].placement : anim::Placement{};
}

std::uint64_t Stage::ticks() const
{
    const std::lock_guard lock(m_mutex);
    return m_ticks;
}

void Stage::cacheAuthored(TrackState& track) const
{
    // A character an edit did not touch keeps its schedule, and so its cached frames.
    if (track.cache && track.cache->source() == track.authored && track.cache->capacity() == m_cacheFrames) {
        track.played = track.cache;
        return;
    }
    track.cache = m_cacheFrames > 0 && track.authored
                      ? std::make_shared<anim::CachedBlendable>(track.authored, m_cacheFrames)
                      : nullptr;
    track.played = track.cache ? anim::BlendablePtr(track.cache) : anim::BlendablePtr(track.authored);
}

void Stage::setFrameCache(int frames)
{
    const std::lock_guard lock(m_mutex);
    m_cacheFrames = std::max(frames, 0);
    for (Performer& performer : m_performers) {
        cacheAuthored(performer.body);
        cacheAuthored(performer.face);
    }
}

std::uint64_t Stage::frameCacheHits() const
{
    const std::lock_guard lock(m_mutex);
    std::uint64_t hits = 0;
    for (const Performer& performer : m_performers)
        for (const TrackState* track : {&performer.body, &performer.face})
            if (track->cache)
                hits += track->cache->hits();
    return hits;
}

} // namespace thespis::core::runtime
