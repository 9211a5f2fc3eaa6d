#include "scenario/scenario_character.h"

#include <array>
#include <iterator>

#include "scene/default_humanoid.h"
#include "scene/foot_soles.h"
#include "scene/gltf_character.h"

namespace thespis::core::scenario {

namespace {

// The humanoid's level follows the animation skeleton, so every animated joint has its
// segment; a BVH skeleton ("clip:NAME") drives LOA 1 by its H-Anim names.
anim::hanim::Level humanoidLevel(const std::string& skeleton)
{
    if (skeleton == "hanim-loa2")
        return anim::hanim::Level::Loa2;
    if (skeleton == "hanim-25")
        return anim::hanim::Level::Subset25;
    return anim::hanim::Level::Loa1;
}

// Shirts of the built-in humanoid by character, so that a scene's characters can be told apart
// (linear RGB: blue, terracotta, green, plum, ochre).
constexpr std::array<float, 3> kShirts[] = {
    {0.07f, 0.17f, 0.45f}, {0.45f, 0.12f, 0.06f}, {0.09f, 0.30f, 0.12f}, {0.28f, 0.08f, 0.30f}, {0.50f, 0.33f, 0.05f}};

} // namespace

Result<scene::Character> loadCharacterBody(const Scenario& scenario, std::size_t characterIndex,
                                           const Assets& assets)
{
    const Character& spec = scenario.characters.at(characterIndex);
    const std::string field = "characters[" + std::to_string(characterIndex) + "]";
    auto fail = [&](const std::string& member, const Error& error) {
        return makeError(error.code, field + "." + member + " (" + spec.name + "): " + error.message, error.detail);
    };
    Result<scene::Character> body = spec.model.empty()
                                        ? scene::makeDefaultHumanoid({.level = humanoidLevel(spec.skeleton),
                                                                      .shirtColor = kShirts[characterIndex % std::size(kShirts)]})
                                        : scene::loadGltfCharacter(assets.path(spec.model));
    if (!body)
        return fail(spec.model.empty() ? "skeleton" : "model", body.error());
    body->name = spec.name;
    if (auto tagged = scene::applySegmentTags(body->mesh, spec.segmentTags); !tagged)
        return fail("segments", tagged.error());
    return body;
}

anim::FrameRetarget retargetOntoBody(const anim::Skeleton& animation, const scene::Character& body)
{
    anim::RetargetOptions retarget;
    retarget.targetSoles = scene::footSoles(body);
    if (animation.joints() == body.skeleton.joints())
        retarget.sourceSoles = retarget.targetSoles; // the body's own rig: the same feet
    return anim::FrameRetarget(animation, body.skeleton, retarget);
}

} // namespace thespis::core::scenario
