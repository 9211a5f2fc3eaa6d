#pragma once
// A character's geometry split into named segments (paper §6.1.3: the VH is a hierarchy of mesh
// segments S1 … Si, one per H-Anim joint, plus hair, clothes …). This file holds what the
// lighting bake needs: bind-pose positions and normals in world space, triangles, and per
// segment its vertex and triangle ranges, its bind frame and its tags. The rendering issue
// extends it with skin weights, texture coordinates and materials.

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "anim/quat.h"
#include "util/error.h"

namespace thespis::core::scene {

using anim::Quatd;
using anim::Vec3;
using anim::Vec3d;

/// Paper §6.1.3: a receiver receives self-shadowing but casts none (left out of the proxy mesh
/// M′, transparent to rays); an occluder casts but receives none (in M′, no transfer baked);
/// None both casts and receives.
enum class SegmentRole : std::uint8_t { None, Receiver, Occluder };

const char* segmentRoleName(SegmentRole role); ///< "none", "receiver", "occluder"
Result<SegmentRole> parseSegmentRole(std::string_view name);

struct Segment {
    std::string name;          ///< unique within the character (mesh node name, or joint name)
    std::string joint;         ///< H-Anim joint whose frame the segment follows; "" if none
    std::uint32_t firstVertex = 0;
    std::uint32_t vertexCount = 0;
    std::uint32_t firstTriangle = 0;
    std::uint32_t triangleCount = 0;
    /// The segment's bind frame in world space: the transfer is stored in this frame, so at run
    /// time the light is rotated by the segment's current rotation (paper §6.1.1).
    Quatd bindRotation;
    Vec3d bindTranslation;
    SegmentRole role = SegmentRole::None;
};

/// Vertices and triangles are grouped by segment: segment s owns vertices
/// [firstVertex, firstVertex + vertexCount) and triangles [firstTriangle, …); triangle indices
/// are global vertex indices and never cross segments.
struct CharacterMesh {
    std::vector<Vec3> positions; ///< bind pose, world space, metres
    std::vector<Vec3> normals;   ///< unit length
    std::vector<std::uint32_t> indices; ///< 3 per triangle
    std::vector<Segment> segments;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return indices.size() / 3; }
    const Segment* findSegment(std::string_view name) const;
    Segment* findSegment(std::string_view name);
    /// Checks the invariants above (ranges, indices in the segment, unit normals, finite
    /// positions) and says what is broken.
    Result<void> validate() const;
};

/// Segment tags as users give them (scenario file or `--tags` JSON file: an object
/// {"segment name": {"role": "receiver"}, …} or {"name": "receiver", …}).
struct SegmentTag {
    std::string segment;
    SegmentRole role = SegmentRole::None;
    bool operator==(const SegmentTag&) const = default;
};

/// Applies tags by segment name; an unknown segment name is an error naming it (and the
/// segments that exist), nothing is applied then.
Result<void> applySegmentTags(CharacterMesh& mesh, const std::vector<SegmentTag>& tags);
/// Reads a tags JSON file (format above); errors name the file and the member.
Result<std::vector<SegmentTag>> readSegmentTagsFile(const std::filesystem::path& path);

} // namespace thespis::core::scene
