#pragma once
// Dependent-joint motion (paper §4.4): a gesture keyed on a few joints (an arm) gains the motion
// of the joints that depend on it (spine, neck, the other shoulder) by a scaling filter on its
// upper-body PCs. The leading PCs hold what people do together; the high ones what a posture
// does that people hardly ever do, like moving an arm with nothing else following. The filter
// keeps PCs up to `fadeFrom`, fades them out linearly until `muteAbove`, and mutes the rest (the
// paper: from 20, muted above 30 of 48), then rebuilds the posture: the keyed joints move a
// little, the others follow. Only the upper body is filtered, so the root and the legs (the idle
// motion under a gesture) are as they were.
//
// A modifier on any body blendable of a skeleton with the H-Anim upper-body joints; evaluate()
// allocates nothing.

#include <memory>
#include <vector>

#include "anim/modifiers.h"
#include "anim/skeleton.h"
#include "motion/posture.h"
#include "motion/posture_basis.h"
#include "util/error.h"

namespace thespis::core::motion {

struct FilterBand {
    int fadeFrom = 20;  ///< PCs 1 … fadeFrom are kept
    int muteAbove = 30; ///< PCs above it are muted; between, a linear fade
    bool operator==(const FilterBand&) const = default;
};

/// The filter's scale of PC `index` (1-based).
float filterScale(const FilterBand& band, int index);

class DependentJointFilter final : public anim::Modifier {
public:
    /// Errors: the basis is not an upper-body basis, the band is not 1 ≤ fadeFrom ≤ muteAbove, or
    /// the skeleton lacks upper-body joints (named).
    static Result<std::shared_ptr<DependentJointFilter>> create(anim::BlendablePtr source, const anim::Skeleton& skeleton,
                                                                std::shared_ptr<const PostureBasis> upper,
                                                                FilterBand band = {});

    const FilterBand& band() const { return m_band; }
    anim::TimeDomain domain() const override { return m_source->domain(); }
    void evaluate(double t, std::span<float> out) const override;
    /// Filters a frame of the skeleton in place.
    void filter(std::span<float> frame) const;

private:
    DependentJointFilter(anim::BlendablePtr source) : Modifier(std::move(source)) {}

    std::shared_ptr<const PostureBasis> m_upper;
    FilterBand m_band;
    PostureMap m_map;
    std::vector<float> m_scales; ///< per PC
};

} // namespace thespis::core::motion
