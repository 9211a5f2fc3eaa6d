#include "scene/character_mesh.h"

#include <algorithm>
#include <cmath>
#include <exception>
#include <set>
#include <utility>

#include <nlohmann/json.hpp>

#include "util/file_io.h"

namespace thespis::core::scene {

const char* segmentRoleName(SegmentRole role)
{
    switch (role) {
    case SegmentRole::None: return "none";
    case SegmentRole::Receiver: return "receiver";
    case SegmentRole::Occluder: return "occluder";
    }
    return "none";
}

Result<SegmentRole> parseSegmentRole(std::string_view name)
{
    for (SegmentRole role : {SegmentRole::None, SegmentRole::Receiver, SegmentRole::Occluder})
        if (name == segmentRoleName(role))
            return role;
    return makeError(ErrorCode::InvalidArgument,
                     "Unknown segment role \"" + std::string(name) + "\": use none, receiver or occluder.");
}

const Segment* CharacterMesh::findSegment(std::string_view name) const
{
    for (const Segment& segment : segments)
        if (segment.name == name)
            return &segment;
    return nullptr;
}

Segment* CharacterMesh::findSegment(std::string_view name)
{
    return const_cast<Segment*>(std::as_const(*this).findSegment(name));
}

Result<void> CharacterMesh::validate() const
{
    auto broken = [](std::string message) { return makeError(ErrorCode::CorruptData, std::move(message)); };
    if (normals.size() != positions.size())
        return broken("The mesh has " + std::to_string(positions.size()) + " positions but " +
                      std::to_string(normals.size()) + " normals.");
    if (indices.size() % 3 != 0)
        return broken("The mesh's index count " + std::to_string(indices.size()) + " is not a multiple of 3.");
    for (std::size_t v = 0; v < positions.size(); ++v) {
        const Vec3& p = positions[v];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            return broken("Vertex " + std::to_string(v) + " has a position that is not finite.");
        const Vec3& n = normals[v];
        const double length = std::sqrt(double(n.x) * n.x + double(n.y) * n.y + double(n.z) * n.z);
        if (!(std::abs(length - 1.0) < 1e-3))
            return broken("Vertex " + std::to_string(v) + " has a normal of length " + std::to_string(length) +
                          " (normals must be unit length).");
    }
    // Segments partition the vertices and the triangles, in order.
    std::size_t nextVertex = 0;
    std::size_t nextTriangle = 0;
    std::set<std::string_view> names;
    for (const Segment& segment : segments) {
        const std::string where = "Segment \"" + segment.name + "\"";
        if (segment.name.empty())
            return broken("A segment has no name (segment " + std::to_string(&segment - segments.data()) + ").");
        if (!names.insert(segment.name).second)
            return broken(where + " appears twice: segment names must be unique.");
        if (segment.firstVertex != nextVertex || segment.firstTriangle != nextTriangle)
            return broken(where + " does not start where the previous segment ends.");
        nextVertex += segment.vertexCount;
        nextTriangle += segment.triangleCount;
        if (nextVertex > positions.size() || nextTriangle > triangleCount())
            return broken(where + " reaches past the end of the mesh.");
        const std::size_t vertexEnd = std::size_t(segment.firstVertex) + segment.vertexCount;
        for (std::size_t i = std::size_t(segment.firstTriangle) * 3; i < nextTriangle * 3; ++i)
            if (indices[i] < segment.firstVertex || indices[i] >= vertexEnd)
                return broken(where + ": triangle " + std::to_string(i / 3) + " uses vertex " +
                              std::to_string(indices[i]) + ", which is outside the segment.");
    }
    if (nextVertex != positions.size() || nextTriangle != triangleCount())
        return broken("The segments do not cover every vertex and triangle of the mesh.");
    return {};
}

Result<void> applySegmentTags(CharacterMesh& mesh, const std::vector<SegmentTag>& tags)
{
    for (const SegmentTag& tag : tags) {
        if (mesh.findSegment(tag.segment))
            continue;
        std::string known;
        for (const Segment& segment : mesh.segments)
            known += (known.empty() ? "" : ", ") + segment.name;
        return makeError(ErrorCode::InvalidArgument,
                         "The tags name a segment \"" + tag.segment + "\" that the character does not have.",
                         "segments: " + known);
    }
    for (const SegmentTag& tag : tags) {
        Segment* segment = mesh.findSegment(tag.segment);
        segment->role = tag.role;
    }
    return {};
}

Result<std::vector<SegmentTag>> readSegmentTagsFile(const std::filesystem::path& path)
{
    using json = nlohmann::ordered_json;
    const std::string file = path.string();
    Result<std::string> text = readTextFile(path);
    if (!text)
        return text.error();
    json document;
    try {
        document = json::parse(*text);
    } catch (const std::exception& e) {
        return makeError(ErrorCode::CorruptData, "The tags file " + file + " is not valid JSON.", e.what());
    }
    if (!document.is_object())
        return makeError(ErrorCode::CorruptData,
                         "The tags file " + file + " must hold a JSON object {\"segment\": {\"role\": …}}.");

    auto bad = [&](const std::string& member, const std::string& what) {
        return makeError(ErrorCode::CorruptData, "In the tags file " + file + ", \"" + member + "\" " + what);
    };
    std::vector<SegmentTag> tags;
    for (const auto& [name, value] : document.items()) {
        SegmentTag tag;
        tag.segment = name;
        if (value.is_string()) {
            Result<SegmentRole> role = parseSegmentRole(value.get<std::string>());
            if (!role)
                return bad(name, "has an unknown role: " + role.error().message);
            tag.role = *role;
        } else if (value.is_object()) {
            for (const auto& [key, field] : value.items()) {
                const std::string member = name + "." + key;
                if (key == "posture")
                    return bad(member, "is no longer a tag: posture-independent / -dependent tags never changed the "
                                       "bake or the renderer and were removed; delete the member.");
                if (key != "role")
                    return bad(member, "is not a tag member (use \"role\").");
                if (!field.is_string())
                    return bad(member, "must be a string.");
                Result<SegmentRole> role = parseSegmentRole(field.get<std::string>());
                if (!role)
                    return bad(member, "is wrong: " + role.error().message);
                tag.role = *role;
            }
        } else {
            return bad(name, "must be a role string or an object {\"role\": …}.");
        }
        tags.push_back(std::move(tag));
    }
    return tags;
}

} // namespace thespis::core::scene
