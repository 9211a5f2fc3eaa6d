#include "motion/idle_motion.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "anim/curve.h"
#include "anim/hanim.h"
#include "anim/simd.h"
#include "motion/gradient_noise.h"
#include "motion/posture.h"

namespace thespis::core::motion {

namespace {

constexpr std::size_t kPostureFloats = 78;
constexpr std::size_t kFrameFloats = 128; // room for the posture skeleton's frame (103 floats)
constexpr std::size_t kProgramRoom = 512; // entries reserved ahead: most of an hour of idle
constexpr int kClosest = 3;                // the next transition is picked among this many closest
// Gradient noise's two octaves, mixed to a standard deviation of about 1 (measured over 10⁶
// samples: one octave's is 0.141).
constexpr float kNoiseScale = 1.0f / 0.1074f;
constexpr double kNoiseFrequency = 0.4; // Hz of PC 1's variation; higher PCs a little faster
constexpr std::size_t kMaxVariedPcs = 16; // PCs varied at most (the databases hold 10)

} // namespace

struct IdleMotion::Rig {
    std::vector<anim::Joint> character; ///< the skeleton it is for
    PostureMap map;                     ///< onto the posture skeleton
    std::vector<float> rest;            ///< the posture skeleton's rest frame
    anim::FrameRetarget retarget;       ///< posture skeleton → character, feet on the floor
};

std::shared_ptr<const IdleMotion::Rig> IdleMotion::rigFor(const anim::Skeleton& character)
{
    static std::mutex mutex;
    static std::vector<std::weak_ptr<const Rig>> rigs;
    std::lock_guard lock(mutex);
    std::erase_if(rigs, [](const std::weak_ptr<const Rig>& rig) { return rig.expired(); });
    for (const std::weak_ptr<const Rig>& weak : rigs)
        if (auto rig = weak.lock(); rig && rig->character == character.joints())
            return rig;
    const anim::Skeleton& postures = postureSkeleton();
    auto rig = std::make_shared<const Rig>(Rig{character.joints(), *PostureMap::create(postures, PostureSet::WholeBody),
                                               postures.restFrame(), anim::FrameRetarget(postures, character)});
    rigs.push_back(rig);
    return rig;
}

Result<std::shared_ptr<IdleMotion>> IdleMotion::create(std::shared_ptr<const IdleDatabase> database,
                                                       const anim::Skeleton& character, const IdleOptions& options)
{
    if (!database || database->segments.empty() || database->alignment.empty())
        return makeError(ErrorCode::InvalidArgument, "The idle motion has no indexed database to play.");
    if (!(options.amplitude >= 0) || !std::isfinite(options.amplitude) || options.amplitude > 10)
        return makeError(ErrorCode::InvalidArgument, "The idle's amplitude must be between 0 and 10.");
    if (!(options.blendSeconds > 0) || options.blendSeconds > 5)
        return makeError(ErrorCode::InvalidArgument, "The idle's blend must be between 0 and 5 seconds.");
    // The joints the idle moves that every H-Anim body has (LOA 1); a body may lack the spine's
    // and the clavicles' (the retarget gives their turn to the joints below).
    std::vector<std::string> missing;
    for (const std::string& joint : anim::hanim::jointNames(anim::hanim::Level::Loa1))
        if (character.find(joint) < 0)
            missing.push_back(joint);
    if (!missing.empty()) {
        std::string names;
        for (const std::string& joint : missing)
            names += (names.empty() ? "" : ", ") + joint;
        return makeError(ErrorCode::InvalidArgument,
                         "The character's skeleton lacks joints the idle motion moves: " + names +
                             ". Map its joints onto H-Anim names (Character ▸ Skeleton), or play the idle on another "
                             "character.");
    }
    auto idle = std::shared_ptr<IdleMotion>(new IdleMotion());
    idle->m_database = std::move(database);
    idle->m_options = options;
    idle->m_layout = character.frameLayout();
    idle->m_rig = rigFor(character);
    if (!idle->m_rig->retarget.matchesFeet())
        return makeError(ErrorCode::InvalidArgument,
                         "The idle motion cannot stand this character on the floor: its feet were not found.");
    idle->m_program.reserve(kProgramRoom);
    idle->m_joinOffset.assign(kPostureFloats, 0.0f);
    const IdleDatabase& db = *idle->m_database;
    for (std::size_t i = 0; options.amplitude > 0 && i < std::min(db.variation.size(), kMaxVariedPcs); ++i) {
        // Higher PCs a little faster; a second octave a little over twice as fast, weaker.
        // Each PC moves by its own spread in the data, times the amplitude.
        const double spread = 1.0 + 0.15 * double(i);
        const float scale = options.amplitude * db.variation[i] * kNoiseScale;
        idle->m_octaves.push_back(
            {.channel = noiseChannel(options.seed, std::uint32_t(i)), .spread = spread, .weight = 0.7f * scale});
        idle->m_octaves.push_back({.channel = noiseChannel(options.seed, std::uint32_t(i) + 1000),
                                   .spread = spread, .octave = 2.13, .weight = 0.3f * scale});
    }
    return idle;
}

IdleMotion::ProgramEntry IdleMotion::nextEntry(const ProgramEntry* previous, std::size_t index) const
{
    const IdleDatabase& db = *m_database;
    const double rate = db.frameRate;
    const std::uint64_t choice = mixBits(m_options.seed * 0x9e3779b97f4a7c15ULL + index);
    if (!previous) {
        const auto segment = std::uint32_t(choice % db.segments.size());
        return {segment, 0.0, double(db.segments[segment].count - 1) / rate, 0.0f};
    }
    const IdleSegment& current = db.segments[previous->segment];
    const std::span<const float> here = db.alignmentPcs(current.first + current.count - 1);
    // A transition plays at least one blend long, so that its join offset has faded at its end.
    const auto minimumFrames = std::uint32_t(std::ceil(m_options.blendSeconds * rate)) + 1;

    struct Candidate {
        float distance;
        std::uint32_t segment, frame;
    };
    constexpr float kNone = std::numeric_limits<float>::max();
    std::array<Candidate, kClosest> best;
    best.fill({kNone, 0, 0});
    for (int pass = 0; pass < 2 && best[0].distance == kNone; ++pass)
        for (std::uint32_t s = 0; s < db.segments.size(); ++s) {
            const IdleSegment& next = db.segments[s];
            // First pass: transitions leaving the category this one ends in; else any.
            if ((pass == 0 && next.from != current.to) || next.count < minimumFrames + 1)
                continue;
            const std::uint32_t lastJoin = std::min(next.count / 2, next.count - 1 - minimumFrames);
            Candidate closest{kNone, s, 0};
            for (std::uint32_t j = 0; j <= lastJoin; ++j) {
                const float distance =
                    db.whole.distance(here, db.alignmentPcs(next.first + j), IdleDatabase::kAlignmentPcs);
                if (distance < closest.distance)
                    closest = {distance, s, j};
            }
            if (closest.distance < best.back().distance) {
                best.back() = closest;
                std::sort(best.begin(), best.end(),
                          [](const Candidate& a, const Candidate& b) { return a.distance < b.distance; });
            }
        }
    // Among the closest (not much further than the closest of all), a seeded pick; the transition
    // just played only when there is no other.
    std::array<const Candidate*, kClosest> pool{};
    int available = 0;
    for (const Candidate& c : best)
        if (c.distance != kNone && c.distance <= 2 * best[0].distance + 1e-3f &&
            (c.segment != previous->segment || available == 0))
            pool[std::size_t(available++)] = &c;
    if (available == 0) // only transitions too short: play the same one again
        return {previous->segment, previous->end, previous->end + double(current.count - 1) / rate, 0.0f};
    const Candidate& pick = *pool[std::size_t(choice % std::uint64_t(available))];
    const IdleSegment& next = db.segments[pick.segment];
    ProgramEntry entry;
    entry.segment = pick.segment;
    entry.start = previous->end;
    entry.firstFrame = float(pick.frame);
    entry.end = entry.start + double(next.count - 1 - pick.frame) / rate;
    return entry;
}

void IdleMotion::extendProgram(double t) const
{
    if (m_program.empty())
        m_program.push_back(nextEntry(nullptr, 0));
    while (m_program.back().start <= t)
        m_program.push_back(nextEntry(&m_program.back(), m_program.size()));
}

std::vector<IdleMotion::ProgramEntry> IdleMotion::program(double t) const
{
    std::lock_guard lock(m_mutex);
    extendProgram(t);
    std::vector<ProgramEntry> entries;
    for (const ProgramEntry& entry : m_program)
        if (entry.start <= t)
            entries.push_back(entry);
    return entries;
}

void IdleMotion::sample(const ProgramEntry& entry, double t, float* posture) const
{
    const IdleDatabase& db = *m_database;
    const IdleSegment& segment = db.segments[entry.segment];
    const double position = std::clamp<double>(entry.firstFrame + (t - entry.start) * db.frameRate, 0.0,
                                               double(segment.count - 1));
    const auto frame = std::min(std::uint32_t(position), segment.count - 2);
    const float u = float(position - frame);
    const float* a = db.postures.data() + std::size_t(segment.first + frame) * kPostureFloats;
    const float* b = a + kPostureFloats;
    for (std::size_t i = 0; i < kPostureFloats; ++i)
        posture[i] = a[i] + u * (b[i] - a[i]);
}

void IdleMotion::posture(double t, std::span<float> out) const
{
    t = std::max(0.0, t);
    ProgramEntry entry;
    std::array<float, kPostureFloats> joinOffset;
    std::array<float, kMaxVariedPcs> noise{};
    bool joining = false;
    {
        std::lock_guard lock(m_mutex);
        extendProgram(t);
        const auto after = std::upper_bound(m_program.begin(), m_program.end(), t,
                                            [](double time, const ProgramEntry& e) { return time < e.start; });
        const std::size_t k = std::size_t(after - m_program.begin()) - 1; // the first entry starts at 0
        entry = m_program[k];
        if (k > 0 && t < entry.start + m_options.blendSeconds) {
            // The join: the new transition starts where the last one ended (their difference
            // added, fading out over the blend with the engine's cubic curve), so the motion
            // never jumps.
            if (m_joinIndex != k) {
                std::array<float, kPostureFloats> ended, starts;
                const ProgramEntry& previous = m_program[k - 1];
                sample(previous, previous.end, ended.data());
                sample(entry, entry.start, starts.data());
                for (std::size_t i = 0; i < kPostureFloats; ++i)
                    m_joinOffset[i] = ended[i] - starts[i];
                m_joinIndex = k;
            }
            std::copy(m_joinOffset.begin(), m_joinOffset.end(), joinOffset.begin());
            joining = true;
        }
        // Small variations: gradient noise along the leading PCs.
        for (std::size_t n = 0; n < m_octaves.size(); ++n) {
            NoiseOctave& o = m_octaves[n];
            const double x = o.octave * (t * kNoiseFrequency * o.spread);
            const double cell = std::floor(x);
            if (const auto i = std::int64_t(cell); i != o.cell) {
                o.cell = i;
                o.a = noiseSlope(o.channel, i);
                o.b = noiseSlope(o.channel, i + 1);
            }
            noise[n / 2] += o.weight * gradientNoiseIn(o.a, o.b, float(x - cell));
        }
    }
    float* posture = out.data();
    sample(entry, t, posture);
    if (joining) {
        static const anim::Curve fade = anim::Curve::cubicFade(0.0, 1.0);
        const float w = float(fade.evaluate((t - entry.start) / m_options.blendSeconds, 1.0));
        for (std::size_t i = 0; i < kPostureFloats; ++i)
            posture[i] += w * joinOffset[i];
    }
    // Each varied PC's noise along its eigenvector (rows of the basis every character shares):
    // four posture floats at a time, summed over the PCs in a register.
    const std::size_t varied = m_octaves.size() / 2;
    const float* directions = m_database->whole.components().data();
    std::size_t j = 0;
    for (; j + 4 <= kPostureFloats; j += 4) {
        anim::simd::F4 sum = anim::simd::load(posture + j);
        for (std::size_t i = 0; i < varied; ++i)
            sum += anim::simd::splat(noise[i]) * anim::simd::load(directions + i * kPostureFloats + j);
        anim::simd::store(posture + j, sum);
    }
    for (; j < kPostureFloats; ++j)
        for (std::size_t i = 0; i < varied; ++i)
            posture[j] += noise[i] * directions[i * kPostureFloats + j];
}

void IdleMotion::evaluate(double t, std::span<float> out) const
{
    std::array<float, kPostureFloats> posture;
    this->posture(t, posture);
    std::array<float, kFrameFloats> frame;
    std::copy(m_rig->rest.begin(), m_rig->rest.end(), frame.begin());
    const std::span<float> onPostures(frame.data(), m_rig->rest.size());
    m_rig->map.toFrame(posture, onPostures);
    // Onto the character (its own skeleton too: then rotations are copied exactly), the lower
    // foot on the floor: an idle always stands, so a join or a variation must neither lift both
    // feet nor sink one.
    m_rig->retarget.apply(onPostures, out, std::numeric_limits<float>::infinity());
}

} // namespace thespis::core::motion
