#pragma once
// Idle motion (paper §4.3) as an open-ended blendable: a character never stands frozen.
//   - Balance shifting: a motion program — references into a shared IdleDatabase, no motion data
//     of its own — plays one recorded transition after another, each starting in the category
//     the previous one ended in. The next transition and the frame it joins at are chosen by the
//     weighted PC distance (eq. 1) to where the previous one ended, a seeded random pick among
//     the closest. It is modified to join smoothly: it starts from where the last one ended, the
//     difference fading out over a blend with the engine's cubic curve.
//   - Small posture variations: gradient noise on the leading PCs, each with the spread the data
//     itself shows (IdleDatabase::variation) times an amplitude.
// Deterministic in t for a seed: the program grows as time goes on, one choice after another
// from the seed, so any frame is the same whichever order frames are asked in. evaluate()
// allocates nothing (the program grows in room reserved ahead, a few entries a minute).
// The posture is played on the H-Anim 25-joint skeleton, stood with its lower foot on the floor
// (an idle always stands: a join or a variation must not lift both feet nor sink one), and
// retargeted onto the character's.

#include <cstdint>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

#include "anim/blendable.h"
#include "anim/retarget.h"
#include "motion/idle_database.h"
#include "motion/posture.h"
#include "util/error.h"

namespace thespis::core::motion {

struct IdleOptions {
    std::uint64_t seed = 1;
    float amplitude = 1;       ///< of the small variations (0: none; 1: as in the data)
    double blendSeconds = 1.0; ///< how long a join's difference takes to fade out
};

class IdleMotion final : public anim::BlendableObject {
public:
    /// Errors: the character lacks joints the idle needs (named), or the options are out of range.
    static Result<std::shared_ptr<IdleMotion>> create(std::shared_ptr<const IdleDatabase> database,
                                                      const anim::Skeleton& character, const IdleOptions& options = {});

    const IdleOptions& options() const { return m_options; }
    const IdleDatabase& database() const { return *m_database; }

    const anim::FrameLayoutPtr& layout() const override { return m_layout; }
    anim::TimeDomain domain() const override { return {0.0}; }
    void evaluate(double t, std::span<float> out) const override;

    /// The whole-body posture at t (before it is put on a skeleton), into 78 floats.
    void posture(double t, std::span<float> out) const;

    /// One step of the motion program: which segment plays from when, from which frame.
    struct ProgramEntry {
        std::uint32_t segment = 0;
        double start = 0, end = 0; ///< seconds
        float firstFrame = 0;      ///< the segment's frame at `start`
    };
    /// The program's entries up to time t (it grows to cover t).
    std::vector<ProgramEntry> program(double t) const;

private:
    IdleMotion() = default;
    /// Grows the program until an entry starts after t; the caller holds m_mutex.
    void extendProgram(double t) const;
    ProgramEntry nextEntry(const ProgramEntry* previous, std::size_t index) const;
    void sample(const ProgramEntry& entry, double t, float* posture) const;

    std::shared_ptr<const IdleDatabase> m_database;
    IdleOptions m_options;
    anim::FrameLayoutPtr m_layout;
    // What turns a posture into the character's frame (the posture skeleton's map and rest, the
    // retarget that stands the character's feet on the floor): one per character skeleton,
    // shared by every idle on it, so that a crowd reads one copy.
    struct Rig;
    static std::shared_ptr<const Rig> rigFor(const anim::Skeleton& character);
    std::shared_ptr<const Rig> m_rig;
    // The small variations: per varied PC two octaves of noise, weighted by the PC's spread and
    // the amplitude. Each octave keeps the slopes of the cell it was last in (they change every
    // few seconds).
    struct NoiseOctave {
        std::uint64_t channel = 0;
        double spread = 1, octave = 1; ///< x = octave · (t · kNoiseFrequency · spread)
        float weight = 1;
        std::int64_t cell = std::numeric_limits<std::int64_t>::min();
        float a = 0, b = 0;            ///< slopes at the cell's ends
    };
    mutable std::vector<NoiseOctave> m_octaves;
    mutable std::mutex m_mutex;
    mutable std::vector<ProgramEntry> m_program;
    // The join being played: its program index and the difference it fades out (frames come in
    // order, so it is found once per join).
    mutable std::size_t m_joinIndex = 0;
    mutable std::vector<float> m_joinOffset;
};

} // namespace thespis::core::motion
