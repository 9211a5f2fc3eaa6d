#pragma once
// PoseSampler: evaluates one character's body schedule at a time and turns the frame into world
// joint positions for PoseView. Every buffer is sized once in the constructor, so sampling at
// 60 Hz allocates nothing. Holds a pointer to the character's runtime, which must outlive it
// (the Document owns both the runtime and, through the window, the samplers).

#include <QVector3D>

#include <span>
#include <utility>
#include <vector>

#include "anim/quat.h"
#include "scenario/scenario_runtime.h"
#include "widgets/pose_view.h"

namespace thespis::editor {

class PoseSampler {
public:
    explicit PoseSampler(const core::scenario::CharacterRuntime& character);

    /// Evaluates the body schedule at `seconds` and updates positions(). No allocation.
    void sample(double seconds);
    /// Takes a body frame evaluated elsewhere (a Stage's, on this skeleton's layout, before
    /// placement) and updates positions(). Frames of another size are ignored. No allocation.
    void setFrame(std::span<const float> frame);
    const std::string& name() const { return m_character->name; }
    /// World position of every joint of the character's skeleton (skeleton units, H-Anim axes).
    std::span<const QVector3D> positions() const { return m_positions; }
    /// The last frame sampled (the skeleton's layout).
    std::span<const float> frame() const { return m_frame; }

    /// How PoseView should draw this character: parents, sides from H-Anim (or common Left/Right)
    /// joint names, the head joint and a head size matching the rest pose's height.
    widgets::PoseFigure figure(const QColor& color) const;

    /// Smallest box holding every joint over [0, duration], sampled every `step` seconds; used
    /// to frame the view once instead of following the character. Leaves the sampler at time 0.
    std::pair<QVector3D, QVector3D> sweepBounds(double duration, double step);

private:
    void computeWorldPositions();

    const core::scenario::CharacterRuntime* m_character;
    std::vector<float> m_frame;
    std::vector<core::anim::Vec3d> m_world;
    std::vector<core::anim::Quatd> m_orientation;
    std::vector<QVector3D> m_positions;
};

} // namespace thespis::editor
