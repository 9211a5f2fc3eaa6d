#include "anim/blending_schedule.h"

#include <algorithm>
#include <atomic>
#include <cmath>

namespace thespis::core::anim {
namespace {

// Edits take stamps from one increasing counter, so a schedule's revision (the largest stamp
// in its tree) changes on any edit anywhere below it, even a removal.
std::uint64_t nextStamp()
{
    static std::atomic<std::uint64_t> counter{0};
    return ++counter;
}

// Scales a frame's motion relative to the rest pose: rotation rest·(rest⁻¹·q)^s, values
// rest + s·(x − rest).
void scaleFrame(const FrameLayout& layout, std::span<const float> rest, float s, std::span<float> frame)
{
    for (int r = 0; r < layout.rotationCount(); ++r) {
        const Quat& base = rotationAt(rest, r);
        Quat& q = rotationAt(frame, r);
        q = normalize(base * power(conjugate(base) * q, s));
    }
    for (std::size_t k = layout.translationOffset(); k < layout.floatCount(); ++k)
        frame[k] = rest[k] + s * (frame[k] - rest[k]);
}

} // namespace

BlendingSchedule::BlendingSchedule(FrameLayoutPtr layout, std::vector<float> rest, std::vector<int> parents)
    : m_layout(std::move(layout)), m_rest(std::move(rest)), m_parents(std::move(parents)),
      m_blender(defaultBlender()), m_stamp(nextStamp())
{
    if (m_rest.size() != m_layout->floatCount())
        m_rest = neutralFrame(*m_layout);
    if (m_parents.size() != std::size_t(m_layout->rotationCount()))
        m_parents.clear();
    sortAndResize();
}

BlendingSchedule::BlendingSchedule(const Skeleton& skeleton)
    : BlendingSchedule(skeleton.frameLayout(), skeleton.restFrame(), skeleton.parents())
{
}

void BlendingSchedule::touch()
{
    m_stamp = nextStamp();
}

Result<void> BlendingSchedule::prepare(Entry& entry) const
{
    const BlendingAction& action = entry.action;
    const std::string label = "Action '" + action.name + "'";
    if (!action.source)
        return makeError(ErrorCode::InvalidSchedule, label + " has nothing to play.");
    if (action.source.get() == this || action.source->plays(*this))
        return makeError(ErrorCode::InvalidSchedule, label + " would play the schedule inside itself.");
    if (action.source->layout() != m_layout && !(*action.source->layout() == *m_layout))
        return makeError(ErrorCode::InvalidSchedule,
                         label + " plays frames of another skeleton or layout than the schedule's.",
                         "source layout: " + std::to_string(action.source->layout()->elementCount())
                             + " elements, schedule layout: " + std::to_string(m_layout->elementCount()));
    if (!std::isfinite(action.start))
        return makeError(ErrorCode::InvalidSchedule, label + " has a start time that is not a finite number.");
    if (auto ok = action.params.weight.validate(); !ok)
        return makeError(ErrorCode::InvalidSchedule, label + ", weight curve: " + ok.error().message);
    if (auto ok = action.params.scale.validate(); !ok)
        return makeError(ErrorCode::InvalidSchedule, label + ", scale curve: " + ok.error().message);
    entry.maskWeights.clear();
    if (action.params.mask) {
        if (auto ok = action.params.mask->validate(); !ok)
            return makeError(ErrorCode::InvalidSchedule, label + ": " + ok.error().message);
        entry.maskWeights = action.params.mask->resolve(*m_layout, m_parents);
    }
    const TimeDomain domain = action.source->domain();
    entry.duration = domain.openEnded() ? std::numeric_limits<double>::infinity() : domain.duration();
    entry.reference.clear();
    if (action.params.mode == BlendMode::Additive) {
        if (action.params.additiveReference == AdditiveReference::FirstFrame) {
            entry.reference.resize(m_layout->floatCount());
            action.source->evaluate(domain.start, entry.reference);
        } else {
            entry.reference = m_rest;
        }
    }
    return {};
}

void BlendingSchedule::sortAndResize()
{
    std::stable_sort(m_actions.begin(), m_actions.end(), [](const Entry& a, const Entry& b) {
        return a.action.start < b.action.start || (a.action.start == b.action.start && a.id < b.id);
    });
    resizeBuffers();
}

void BlendingSchedule::resizeBuffers()
{
    const std::size_t n = m_actions.size();
    m_frames.resize(n * m_layout->floatCount());
    m_weights.resize(n * std::size_t(m_layout->elementCount()));
    m_inputs.resize(n);
    m_contributing.resize(n);
    m_sourceCoverage.resize(std::size_t(m_layout->elementCount()));
    m_totals.resize(std::size_t(m_layout->elementCount()));
    touch();
}

Result<ActionId> BlendingSchedule::addAction(BlendingAction action)
{
    Entry entry;
    entry.action = std::move(action);
    if (auto ok = prepare(entry); !ok)
        return ok.error();
    entry.id = m_nextId++;
    const ActionId id = entry.id;
    // Its id is the largest, so it goes after every action starting no later: the order stays
    // sorted without sorting again (schedules are built one action at a time, in start order).
    const auto at = std::upper_bound(m_actions.begin(), m_actions.end(), entry.action.start,
                                     [](double start, const Entry& e) { return start < e.action.start; });
    m_actions.insert(at, std::move(entry));
    resizeBuffers();
    return id;
}

bool BlendingSchedule::removeAction(ActionId id)
{
    const auto it = std::find_if(m_actions.begin(), m_actions.end(), [&](const Entry& e) { return e.id == id; });
    if (it == m_actions.end())
        return false;
    m_actions.erase(it);
    resizeBuffers();
    return true;
}

bool BlendingSchedule::cutOffAction(ActionId id, double at, double fadeDuration)
{
    Entry* entry = find(id);
    if (!entry || !std::isfinite(at) || !(fadeDuration >= 0))
        return false;
    entry->cutOffAt = at;
    entry->cutOffFade = fadeDuration;
    touch();
    return true;
}

bool BlendingSchedule::restoreAction(ActionId id)
{
    Entry* entry = find(id);
    if (!entry)
        return false;
    entry->cutOffAt = std::numeric_limits<double>::infinity();
    entry->cutOffFade = 0;
    touch();
    return true;
}

Result<void> BlendingSchedule::setActionStart(ActionId id, double start)
{
    Entry* entry = find(id);
    if (!entry)
        return makeError(ErrorCode::InvalidArgument, "There is no action " + std::to_string(id) + " in the schedule.");
    if (!std::isfinite(start))
        return makeError(ErrorCode::InvalidSchedule, "An action's start time must be a finite number.");
    entry->action.start = start;
    sortAndResize();
    return {};
}

Result<void> BlendingSchedule::setActionParams(ActionId id, BlendingParams params)
{
    Entry* entry = find(id);
    if (!entry)
        return makeError(ErrorCode::InvalidArgument, "There is no action " + std::to_string(id) + " in the schedule.");
    Entry changed = *entry;
    changed.action.params = std::move(params);
    if (auto ok = prepare(changed); !ok)
        return ok;
    *entry = std::move(changed);
    touch();
    return {};
}

Result<void> BlendingSchedule::setActionSource(ActionId id, BlendablePtr source)
{
    Entry* entry = find(id);
    if (!entry)
        return makeError(ErrorCode::InvalidArgument, "There is no action " + std::to_string(id) + " in the schedule.");
    Entry changed = *entry;
    changed.action.source = std::move(source);
    if (auto ok = prepare(changed); !ok)
        return ok;
    *entry = std::move(changed);
    touch();
    return {};
}

int BlendingSchedule::removeFinishedActions(double t)
{
    const auto before = m_actions.size();
    std::erase_if(m_actions, [&](const Entry& e) { return t >= endTime(e.id); });
    const int removed = int(before - m_actions.size());
    if (removed > 0)
        sortAndResize();
    return removed;
}

void BlendingSchedule::clear()
{
    m_actions.clear();
    sortAndResize();
}

BlendingSchedule::Entry* BlendingSchedule::find(ActionId id)
{
    for (Entry& e : m_actions)
        if (e.id == id)
            return &e;
    return nullptr;
}

const BlendingSchedule::Entry* BlendingSchedule::find(ActionId id) const
{
    return const_cast<BlendingSchedule*>(this)->find(id);
}

bool BlendingSchedule::active(const Entry& entry, double t) const
{
    const double local = t - entry.action.start;
    if (local < 0)
        return false;
    if (t >= entry.cutOffAt + entry.cutOffFade)
        return false;
    return entry.action.renderOutsideDomain || local <= entry.duration;
}

bool BlendingSchedule::isFinished(ActionId id, double t) const
{
    return !find(id) || t >= endTime(id);
}

double BlendingSchedule::endTime(ActionId id) const
{
    const Entry* entry = find(id);
    if (!entry)
        return std::nan("");
    const double natural = entry->action.renderOutsideDomain ? std::numeric_limits<double>::infinity()
                                                             : entry->action.start + entry->duration;
    return std::min(natural, entry->cutOffAt + entry->cutOffFade);
}

const BlendingAction* BlendingSchedule::action(ActionId id) const
{
    const Entry* entry = find(id);
    return entry ? &entry->action : nullptr;
}

std::vector<ActionId> BlendingSchedule::actionIds() const
{
    std::vector<ActionId> ids;
    ids.reserve(m_actions.size());
    for (const Entry& e : m_actions)
        ids.push_back(e.id);
    return ids;
}

ActionId BlendingSchedule::findAction(const std::string& name) const
{
    for (const Entry& e : m_actions)
        if (e.action.name == name)
            return e.id;
    return 0;
}

void BlendingSchedule::setBlender(std::shared_ptr<const FrameBlender> blender)
{
    m_blender = blender ? std::move(blender) : defaultBlender();
    touch();
}

TimeDomain BlendingSchedule::domain() const
{
    double end = 0;
    for (const Entry& e : m_actions)
        end = std::max(end, endTime(e.id));
    return {0.0, end};
}

bool BlendingSchedule::plays(const BlendableObject& other) const
{
    for (const Entry& e : m_actions)
        if (e.action.source.get() == &other || e.action.source->plays(other))
            return true;
    return false;
}

std::uint64_t BlendingSchedule::revision() const
{
    std::uint64_t revision = m_stamp;
    for (const Entry& e : m_actions)
        revision = std::max(revision, e.action.source->revision());
    return revision;
}

void BlendingSchedule::evaluate(double t, std::span<float> out) const
{
    evaluateInto(t, out, {});
}

void BlendingSchedule::evaluateWithCoverage(double t, std::span<float> out, std::span<float> coverage) const
{
    evaluateInto(t, out, coverage);
}

void BlendingSchedule::evaluateInto(double t, std::span<float> out, std::span<float> coverage) const
{
    const std::size_t floats = m_layout->floatCount();
    const auto elements = std::size_t(m_layout->elementCount());
    std::size_t normalized = 0;
    for (std::size_t i = 0; i < m_actions.size(); ++i) {
        const Entry& entry = m_actions[i];
        m_contributing[i] = 0;
        if (!active(entry, t))
            continue;
        const BlendingParams& params = entry.action.params;
        const double local = t - entry.action.start;
        // An action that renders outside its domain has no end for its curves: a fade-out or
        // release would otherwise stop it at its source's end, defeating the flag.
        const double span = entry.action.renderOutsideDomain ? std::numeric_limits<double>::infinity() : entry.duration;
        double weight = params.weight.evaluate(local, span);
        if (t > entry.cutOffAt)
            weight *= entry.cutOffFade > 0 ? 1.0 - smoothStep((t - entry.cutOffAt) / entry.cutOffFade) : 0.0;
        if (!(weight > 0))
            continue;

        const std::span<float> frame(m_frames.data() + i * floats, floats);
        const BlendableObject& source = *entry.action.source;
        const bool partial = source.hasCoverage();
        if (partial)
            source.evaluateWithCoverage(source.domain().start + local, frame, m_sourceCoverage);
        else
            source.evaluate(source.domain().start + local, frame);
        if (!params.scale.isIdentity()) {
            const double scale = params.scale.evaluate(local, span);
            if (scale != 1.0)
                scaleFrame(*m_layout, m_rest, float(scale), frame);
        }

        const std::span<float> weights(m_weights.data() + i * elements, elements);
        if (entry.maskWeights.empty())
            std::fill(weights.begin(), weights.end(), float(weight));
        else
            for (std::size_t e = 0; e < elements; ++e)
                weights[e] = float(weight) * entry.maskWeights[e];
        if (partial)
            for (std::size_t e = 0; e < elements; ++e)
                weights[e] *= m_sourceCoverage[e];
        for (const auto& custom : params.custom)
            custom->modulate(local, *m_layout, weights);

        m_contributing[i] = 1;
        if (params.mode == BlendMode::Normalized)
            m_inputs[normalized++] = BlendInput{frame.data(), weights.data()};
    }

    // Coverage is passed on only while normalized actions alone play (see the header).
    bool layered = false;
    for (std::size_t i = 0; i < m_actions.size(); ++i)
        layered = layered || (m_contributing[i] && m_actions[i].action.params.mode != BlendMode::Normalized);
    const std::span<const BlendInput> pool(m_inputs.data(), normalized);
    const bool fillRest = coverage.empty() || layered;
    // One normalized action alone is the blend (a weighted average of one) where it is nested
    // (its weights are the coverage) or where it drives every element fully (nothing of the rest
    // pose shows): the common case of a layer, a live schedule or the base under gestures playing
    // one action. Skipping the blend changes nothing but rounding, and keeps its frame exact.
    const bool alone = normalized == 1 &&
                       (!fillRest || std::all_of(pool[0].weights, pool[0].weights + elements, [](float w) { return w >= 1.0f; }));
    if (alone) {
        std::copy_n(pool[0].values, floats, out.data());
        if (!coverage.empty())
            for (std::size_t e = 0; e < elements; ++e)
                coverage[e] = fillRest ? 1.0f : std::min(pool[0].weights[e], 1.0f);
    } else {
        m_blender->blend(*m_layout, pool, m_rest, out, m_totals, fillRest);
        if (!coverage.empty())
            for (std::size_t e = 0; e < elements; ++e)
                coverage[e] = fillRest ? 1.0f : std::min(m_totals[e], 1.0f);
    }

    for (std::size_t i = 0; i < m_actions.size(); ++i) {
        const Entry& entry = m_actions[i];
        if (!m_contributing[i] || entry.action.params.mode == BlendMode::Normalized)
            continue;
        const BlendInput input{m_frames.data() + i * floats, m_weights.data() + i * elements};
        if (entry.action.params.mode == BlendMode::Override)
            m_blender->overlay(*m_layout, input, out);
        else
            m_blender->add(*m_layout, input, entry.reference, out);
    }
}

} // namespace thespis::core::anim
