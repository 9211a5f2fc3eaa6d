#pragma once
// BlendingAction and BlendingSchedule (paper §4.2).
//
// An action is a blendable, its blending parameters, a start time and a flag saying whether it
// renders outside its source's domain. A schedule holds actions keyed by start time and is
// itself a blendable, so schedules nest. Actions can be added, cut off and removed between two
// evaluations while it plays. Evaluation allocates nothing: every buffer is sized when an action
// is added. A schedule is evaluated by one thread at a time.
//
// Evaluation at time t, for each action whose local time u = t − start is in [0, duration]
// (or u ≥ 0 when it renders outside its domain):
//   1. the source frame at source-domain start + u, scaled by the scale curve (relative to rest);
//   2. element weights = weight curve(u, duration) × mask × custom params × cut-off fade;
//   3. Normalized actions are blended together (FrameBlender::blend, rest pose filling Σw < 1);
//   4. Override and Additive actions are then applied on top, in start-time order.
// Nested, a schedule passes on its coverage (how much of each element its normalized actions
// drive), so a parent blends it like the actions it holds: nesting normalized actions equals
// flattening them. While an override or additive action plays inside, its frame is complete
// (rest pose filled in) and covers every element.

#include <cstdint>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "anim/blendable.h"
#include "anim/blending_params.h"
#include "anim/frame_blender.h"
#include "anim/skeleton.h"
#include "util/error.h"

namespace thespis::core::anim {

using ActionId = std::uint64_t;

struct BlendingAction {
    std::string name;
    BlendablePtr source;
    BlendingParams params;
    double start = 0;                  ///< seconds, in the schedule's time
    bool renderOutsideDomain = false;  ///< keep playing (source clamped or synthesizing) after its end
};

class BlendingSchedule final : public BlendableObject {
public:
    /// A schedule on `layout`; `rest` is the pose of elements nobody drives (default: neutral).
    /// `parents` (optional) gives each rotation element's parent, so masks inherit down the tree.
    explicit BlendingSchedule(FrameLayoutPtr layout, std::vector<float> rest = {},
                              std::vector<int> parents = {});
    /// A body schedule for a skeleton: its layout, rest pose and hierarchy.
    explicit BlendingSchedule(const Skeleton& skeleton);

    /// Adds an action. Errors: no source, a source on another layout, a source that plays this
    /// schedule (a cycle), invalid curves or mask.
    Result<ActionId> addAction(BlendingAction action);
    /// Removes an action at once. False when there is no such action.
    bool removeAction(ActionId id);
    /// Fades the action out over `fadeDuration` seconds starting at time `at` (a cubic fade),
    /// after which it is finished. False when there is no such action.
    bool cutOffAction(ActionId id, double at, double fadeDuration);
    /// Takes back a cut-off: the action plays to its natural end again. False when there is no
    /// such action.
    bool restoreAction(ActionId id);
    /// Changes an action's start time / parameters (re-sorting, re-resolving the mask).
    Result<void> setActionStart(ActionId id, double start);
    Result<void> setActionParams(ActionId id, BlendingParams params);
    Result<void> setActionSource(ActionId id, BlendablePtr source);
    /// Removes every action that isFinished() at time t; returns how many.
    int removeFinishedActions(double t);
    void clear();

    /// True when t ≥ endTime(id): the action has ended naturally (not rendering outside its
    /// domain) or its cut-off fade is over; also when it does not exist. Evaluation at exactly
    /// the end still plays a natural end's last frame (its weight curve has usually reached 0).
    bool isFinished(ActionId id, double t) const;
    /// Time at which the action ends (∞ when open-ended), or NaN when it does not exist.
    double endTime(ActionId id) const;
    const BlendingAction* action(ActionId id) const;
    /// Ids in evaluation order (start time, then insertion order).
    std::vector<ActionId> actionIds() const;
    int actionCount() const { return int(m_actions.size()); }
    /// The id of the first action with this name, or 0.
    ActionId findAction(const std::string& name) const;

    void setBlender(std::shared_ptr<const FrameBlender> blender);
    const std::vector<float>& restPose() const { return m_rest; }

    const FrameLayoutPtr& layout() const override { return m_layout; }
    /// From 0 (a schedule's own time origin, so nesting one at start S plays it shifted by S)
    /// to the latest action end; open-ended if any action is. Empty schedules: [0, 0].
    TimeDomain domain() const override;
    void evaluate(double t, std::span<float> out) const override;
    bool hasCoverage() const override { return true; }
    void evaluateWithCoverage(double t, std::span<float> out, std::span<float> coverage) const override;
    std::uint64_t revision() const override;
    bool plays(const BlendableObject& other) const override;

private:
    struct Entry {
        ActionId id = 0;
        BlendingAction action;
        std::vector<float> maskWeights;    // resolved mask, one per element (empty: all 1)
        std::vector<float> reference;      // additive reference pose
        double duration = 0;               // source domain length (∞ when open-ended)
        double cutOffAt = std::numeric_limits<double>::infinity();
        double cutOffFade = 0;
    };

    Result<void> prepare(Entry& entry) const;
    void sortAndResize();
    void resizeBuffers(); // the evaluation buffers, for the number of actions
    Entry* find(ActionId id);
    const Entry* find(ActionId id) const;
    bool active(const Entry& entry, double t) const;
    void evaluateInto(double t, std::span<float> out, std::span<float> coverage) const;
    void touch();

    FrameLayoutPtr m_layout;
    std::vector<float> m_rest;
    std::vector<int> m_parents;
    std::shared_ptr<const FrameBlender> m_blender;
    std::vector<Entry> m_actions; // sorted by (start, id)
    ActionId m_nextId = 1;
    std::uint64_t m_stamp = 0; // a process-wide increasing stamp taken at every edit

    // Scratch, sized by sortAndResize(), reused by every evaluate().
    mutable std::vector<float> m_frames;  // one frame per action
    mutable std::vector<float> m_weights; // one weight per element per action
    mutable std::vector<BlendInput> m_inputs;
    mutable std::vector<unsigned char> m_contributing; // per action, this evaluation
    mutable std::vector<float> m_sourceCoverage;       // one per element, for nested schedules
    mutable std::vector<float> m_totals;               // one per element: the blend's total weights
};

} // namespace thespis::core::anim
