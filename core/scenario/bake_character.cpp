#include "scenario/bake_character.h"

#include "scenario/asset_resolver.h"
#include "scenario/package.h"
#include "scenario/package_resolver.h"
#include "scenario/scenario_character.h"
#include "scenario/scenario_io.h"
#include "scene/gltf_mesh.h"

namespace thespis::core::scenario {

namespace {

struct OpenScenario {
    Scenario scenario;
    Assets assets;
};

Result<OpenScenario> openScenarioFile(const std::filesystem::path& file)
{
    if (file.extension() == kPackageExtension) {
        Result<OpenedPackage> opened = openPackage(file);
        if (!opened)
            return opened.error();
        return OpenScenario{std::move(opened->scenario), std::move(opened->assets)};
    }
    Result<Scenario> scenario = loadScenario(file);
    if (!scenario)
        return scenario.error();
    return OpenScenario{std::move(scenario).value(), Assets::besideFile(file)};
}

/// The index of the character named `name`, or of the only one when `name` is empty.
Result<std::size_t> chooseCharacter(const Scenario& scenario, const std::filesystem::path& file, const std::string& name)
{
    for (std::size_t i = 0; i < scenario.characters.size(); ++i)
        if (scenario.characters[i].name == name || (name.empty() && scenario.characters.size() == 1))
            return i;
    std::string names;
    for (const Character& character : scenario.characters)
        names += (names.empty() ? "" : ", ") + character.name;
    return makeError(ErrorCode::InvalidArgument,
                     (name.empty() ? "The scenario " + file.string() + " has several characters; name the one to bake"
                                   : "The scenario " + file.string() + " has no character named '" + name + "'")
                         + " (its characters: " + (names.empty() ? "none" : names) + ").");
}

/// The scenario of `file` and the index of its character `name` (or its only one).
struct ScenarioCharacter {
    OpenScenario opened;
    std::size_t index = 0;
};

Result<ScenarioCharacter> openCharacter(const std::filesystem::path& file, const std::string& name)
{
    Result<OpenScenario> opened = openScenarioFile(file);
    if (!opened)
        return opened.error();
    Result<std::size_t> index = chooseCharacter(opened->scenario, file, name);
    if (!index)
        return index.error();
    return ScenarioCharacter{std::move(opened).value(), *index};
}

} // namespace

bool isScenarioFile(const std::filesystem::path& file)
{
    return file.extension() == FileExtension || file.extension() == kPackageExtension;
}

Result<scene::CharacterMesh> loadBakeCharacter(const BakeCharacter& source)
{
    scene::CharacterMesh mesh;
    if (isScenarioFile(source.file)) {
        if (!source.tagsScenario.empty() || !source.splitSkinnedByJoint)
            return makeError(ErrorCode::InvalidArgument,
                             "The scenario " + source.file.string()
                                 + " brings its character's own tags and segments: take no tags from another scenario "
                                   "and keep skinned meshes split.");
        Result<ScenarioCharacter> found = openCharacter(source.file, source.character);
        if (!found)
            return found.error();
        Result<scene::Character> body = loadCharacterBody(found->opened.scenario, found->index, found->opened.assets);
        if (!body)
            return body.error();
        mesh = std::move(body->mesh);
    } else {
        if (!source.character.empty() && source.tagsScenario.empty())
            return makeError(ErrorCode::InvalidArgument, "A character name ('" + source.character
                                                             + "') needs a scenario: the glTF file "
                                                             + source.file.string() + " has one character.");
        Result<scene::CharacterMesh> loaded =
            scene::loadGltfMesh(source.file, scene::GltfMeshOptions{.splitSkinnedByJoint = source.splitSkinnedByJoint});
        if (!loaded)
            return loaded.error();
        mesh = std::move(loaded).value();
        if (!source.tagsScenario.empty()) {
            Result<ScenarioCharacter> found = openCharacter(source.tagsScenario, source.character);
            if (!found)
                return found.error();
            const Character& character = found->opened.scenario.characters[found->index];
            if (Result<void> tagged = scene::applySegmentTags(mesh, character.segmentTags); !tagged)
                return tagged.error();
        }
    }
    if (!source.tagsFile.empty()) {
        Result<std::vector<scene::SegmentTag>> tags = scene::readSegmentTagsFile(source.tagsFile);
        if (!tags)
            return tags.error();
        if (Result<void> tagged = scene::applySegmentTags(mesh, *tags); !tagged)
            return tagged.error();
    }
    return mesh;
}

} // namespace thespis::core::scenario
