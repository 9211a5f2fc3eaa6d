#pragma once
// The idle motion database (paper §4.3.1): recorded transitions between rest-posture categories
// (weight on the left foot, on both, on the right), as whole-body postures at a fixed rate, with
// the posture bases they are measured in and the spread of the small posture variations (§4.3.2).
// Built from standing recordings by idle_builder.h, played by idle_motion.h; many characters
// share one database.
//
// The file (.idle), little-endian:
//
//   char[8]  magic "THSPIDL\0"
//   u32      format version (1)
//   basis    whole body, then upper body (basis_io.h)
//   f32      frame rate of the segments
//   u32      category count, then each name (u32 length, UTF-8)
//   u32      variation count V, f32[V] the spread of PC 1 … V's small variations
//   u32      segment count, then per segment: u32 from, u32 to (categories), u32 first frame,
//            u32 frame count, source (u32 length, UTF-8), f32 start in the source (seconds)
//   u64      posture float count, f32[] the postures (78 per frame, segment after segment)
//   u32      CRC-32 of every byte before it

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

#include "motion/posture_basis.h"
#include "util/error.h"

namespace thespis::core::motion {

struct IdleSegment {
    int from = 0, to = 0;        ///< rest-posture categories it goes between
    std::uint32_t first = 0;     ///< its first frame among the database's postures
    std::uint32_t count = 0;     ///< frames
    std::string source;          ///< the recording it was cut from
    float sourceStart = 0;       ///< seconds into that recording
    bool operator==(const IdleSegment&) const = default;
};

struct IdleDatabase {
    PostureBasis whole, upper;
    float frameRate = 30;
    std::vector<std::string> categories;
    /// Spread (standard deviation) of the small variations along PC 1 … V of `whole`.
    std::vector<float> variation;
    std::vector<IdleSegment> segments;
    std::vector<float> postures; ///< whole-body postures, frame after frame

    static constexpr int kAlignmentPcs = 10; ///< PCs compared to join transitions (eq. 1)
    /// The first kAlignmentPcs PC values of every frame, made by index() (not stored).
    std::vector<float> alignment;

    int postureSize() const { return PostureLayout::of(PostureSet::WholeBody).size(); }
    std::span<const float> posture(std::uint32_t frame) const
    {
        return {postures.data() + std::size_t(frame) * std::size_t(postureSize()), std::size_t(postureSize())};
    }
    std::span<const float> alignmentPcs(std::uint32_t frame) const
    {
        return {alignment.data() + std::size_t(frame) * kAlignmentPcs, std::size_t(kAlignmentPcs)};
    }
    /// Checks the rules (segments inside the postures, categories known, values finite, …) and
    /// makes `alignment`. Readers and the builder call it.
    Result<void> index();
};

std::string encodeIdleDatabase(const IdleDatabase& database);
Result<IdleDatabase> parseIdleDatabase(std::string_view data, const std::filesystem::path& path);
Result<void> writeIdleDatabaseFile(const std::filesystem::path& path, const IdleDatabase& database);
Result<IdleDatabase> readIdleDatabaseFile(const std::filesystem::path& path);

} // namespace thespis::core::motion
