#include "scenario/scenario_character.h"

#include <array>
#include <iterator>

#include "scene/default_humanoid.h"
#include "scene/foot_soles.h"
#include "scene/gltf_character.h"
#include "util/text.h"

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

// "characters[2].faceMapping (Creon)": the field of a character and who it is, for messages.
std::string characterField(const Scenario& scenario, std::size_t characterIndex, const std::string& member)
{
    return "characters[" + std::to_string(characterIndex) + "]." + member + " ("
           + scenario.characters.at(characterIndex).name + ")";
}

} // namespace

Result<std::optional<scene::FaceMapping>> readCharacterFaceMapping(const Scenario& scenario, std::size_t characterIndex,
                                                                  const Assets& assets)
{
    const Character& spec = scenario.characters.at(characterIndex);
    if (spec.faceMapping.empty())
        return std::optional<scene::FaceMapping>();
    const std::string field = characterField(scenario, characterIndex, "faceMapping");
    if (spec.model.empty())
        return makeError(ErrorCode::InvalidArgument,
                         field + ": only a glTF model's morph targets follow a face mapping table; the built-in "
                                 "humanoid has its own face and leaves \"" + spec.faceMapping + "\" out.");
    // Parsed from the resolver's bytes: a package serves the table straight from its zip.
    auto text = assets.read(spec.faceMapping);
    if (!text)
        return makeError(text.error().code, field + ": " + text.error().message, text.error().detail);
    auto mapping = scene::parseFaceMapping(*text);
    if (!mapping)
        return makeError(mapping.error().code,
                         field + ": " + assets.where(spec.faceMapping) + ": " + lowerFirst(mapping.error().message),
                         mapping.error().detail);
    return std::optional<scene::FaceMapping>(std::move(mapping).value());
}

Result<scene::Character> loadCharacterBody(const Scenario& scenario, std::size_t characterIndex,
                                           const Assets& assets)
{
    const Character& spec = scenario.characters.at(characterIndex);
    const std::string field = "characters[" + std::to_string(characterIndex) + "]";
    auto fail = [&](const std::string& member, const Error& error) {
        return makeError(error.code, field + "." + member + " (" + spec.name + "): " + error.message, error.detail);
    };
    // A table that cannot be used leaves the face to the recognised one: nothing else is lost.
    scene::GltfCharacterOptions options;
    std::string tableProblem;
    if (auto table = readCharacterFaceMapping(scenario, characterIndex, assets))
        options.faceMapping = std::move(*table);
    else
        tableProblem = table.error().message;
    Result<scene::Character> body = spec.model.empty()
                                        ? scene::makeDefaultHumanoid({.level = humanoidLevel(spec.skeleton),
                                                                      .shirtColor = kShirts[characterIndex % std::size(kShirts)]})
                                        : scene::loadGltfCharacter(assets.path(spec.model), options);
    if (!body)
        return fail(spec.model.empty() ? "skeleton" : "model", body.error());
    body->name = spec.name;
    if (!tableProblem.empty())
        body->warnings.push_back(tableProblem + (spec.model.empty() ? std::string()
                                                 : " Its face follows the table recognised from the model's names."));
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
