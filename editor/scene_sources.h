#pragma once
// SceneSources: what a studio scene (the 3D view's, the AR preview's) was built from — each
// character's body (skeleton, model, bake, segment tags, face mapping table and when its file
// last changed) and the light. An edit that changes any
// of it needs the scene built again; one that does not (schedules, clips, actions) plays on the
// same scene, which draws the Session's stage as it is.

#include <algorithm>
#include <string>
#include <vector>

#include "scenario/asset_resolver.h"
#include "scenario/scenario.h"
#include "scene/character_mesh.h"

namespace thespis::editor {

struct SceneSources {
    struct Body {
        std::string name, skeleton, model, bake;
        std::vector<core::scene::SegmentTag> segmentTags;
        std::string faceMapping;
        long long faceMappingStamp = 0; // a table saved again under its name changes the face
        bool operator==(const Body&) const = default;
    };
    std::vector<Body> bodies;
    core::scenario::LightingSpec lighting;
    bool operator==(const SceneSources&) const = default;

    static SceneSources of(const core::scenario::Scenario& scenario, const core::scenario::Assets& assets)
    {
        SceneSources sources{{}, scenario.lighting};
        for (const core::scenario::Character& character : scenario.characters)
            sources.bodies.push_back({character.name, character.skeleton, character.model, character.bake,
                                      character.segmentTags, character.faceMapping,
                                      character.faceMapping.empty() ? 0 : assets.stamp(character.faceMapping)});
        return sources;
    }
    /// The same characters, by name and in order (other bodies or light maybe).
    bool sameCast(const SceneSources& other) const
    {
        return bodies.size() == other.bodies.size()
               && std::equal(bodies.begin(), bodies.end(), other.bodies.begin(),
                             [](const Body& a, const Body& b) { return a.name == b.name; });
    }
};

} // namespace thespis::editor
