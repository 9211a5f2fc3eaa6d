#include "scene/foot_soles.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>
#include <set>

#include "scene/default_humanoid.h"

namespace thespis::core::scene {

std::vector<anim::BodyMeasure::SolePoint> footSoles(const Character& character)
{
    const anim::BodyMeasure body = anim::measureBody(character.skeleton);
    // The support points of each foot's mesh (the ankle's segments and those below it) towards
    // the floor and obliquely down all around: the vertices that touch the floor first however
    // the foot is turned (heel, toes, the edges of the sole).
    std::vector<anim::Vec3d> directions = {{0, -1, 0}};
    for (double elevation : {-60.0, -30.0, -10.0})
        for (int k = 0; k < 8; ++k) {
            const double e = elevation * std::numbers::pi / 180.0, a = k * std::numbers::pi / 4.0;
            directions.push_back({std::cos(e) * std::sin(a), std::sin(e), std::cos(e) * std::cos(a)});
        }
    std::vector<anim::BodyMeasure::SolePoint> soles;
    for (const char* side : {"l_", "r_"}) {
        const int ankle = character.skeleton.find(std::string(side) + "talocrural");
        if (ankle < 0)
            continue;
        std::set<int> foot;
        for (int j : body.footJoints)
            for (int a = j; a >= 0; a = character.skeleton.joint(a).parent)
                if (a == ankle)
                    foot.insert(j);
        struct Vertex {
            Vec3 position;
            int joint;
        };
        std::vector<Vertex> vertices;
        for (std::size_t s = 0; s < character.mesh.segments.size(); ++s) {
            const int joint = character.segmentJoint(s);
            if (!foot.count(joint))
                continue;
            const Segment& segment = character.mesh.segments[s];
            for (std::uint32_t v = segment.firstVertex; v < segment.firstVertex + segment.vertexCount; ++v)
                vertices.push_back({character.mesh.positions[v], joint});
        }
        if (vertices.empty())
            continue;
        std::set<std::size_t> chosen;
        for (const anim::Vec3d& d : directions) {
            const auto support = std::max_element(vertices.begin(), vertices.end(), [&](const Vertex& a, const Vertex& b) {
                return a.position.x * d.x + a.position.y * d.y + a.position.z * d.z
                       < b.position.x * d.x + b.position.y * d.y + b.position.z * d.z;
            });
            chosen.insert(std::size_t(support - vertices.begin()));
        }
        for (std::size_t v : chosen) {
            const Vertex& vertex = vertices[v];
            const anim::Vec3d& at = body.restPositions[std::size_t(vertex.joint)];
            soles.push_back({vertex.joint, {vertex.position.x - at.x, vertex.position.y - at.y, vertex.position.z - at.z}});
        }
    }
    return soles;
}

const std::vector<anim::BodyMeasure::SolePoint>& defaultHumanoidSoles(anim::hanim::Level level)
{
    static const auto soles = [] {
        std::map<anim::hanim::Level, std::vector<anim::BodyMeasure::SolePoint>> all;
        for (const anim::hanim::Level l : {anim::hanim::Level::Loa1, anim::hanim::Level::Loa2, anim::hanim::Level::Subset25})
            if (auto humanoid = makeDefaultHumanoid({.level = l}))
                all[l] = footSoles(*humanoid);
        return all;
    }();
    return soles.at(level);
}

} // namespace thespis::core::scene
