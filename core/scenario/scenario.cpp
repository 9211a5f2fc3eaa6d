#include "scenario/scenario.h"

namespace thespis::core::scenario {

std::string rebasedPath(const std::string& path, const std::filesystem::path& from, const std::filesystem::path& to)
{
    if (path.empty() || std::filesystem::path(path).is_absolute() || from == to)
        return path;
    return (from / path).lexically_normal().lexically_relative(to).generic_string();
}

void rebaseClip(ClipAsset& clip, const std::filesystem::path& from, const std::filesystem::path& to)
{
    clip.file = rebasedPath(clip.file, from, to);
    if (clip.idle)
        clip.idle->database = rebasedPath(clip.idle->database, from, to);
}

void rebasePaths(Scenario& scenario, const std::filesystem::path& from, const std::filesystem::path& to)
{
    for (Character& character : scenario.characters) {
        character.model = rebasedPath(character.model, from, to);
        character.bake = rebasedPath(character.bake, from, to);
        for (ClipAsset& clip : character.clips)
            rebaseClip(clip, from, to);
    }
    scenario.lighting.probe = rebasedPath(scenario.lighting.probe, from, to);
    scenario.postureBases = rebasedPath(scenario.postureBases, from, to);
    for (PhantomOccluder& occluder : scenario.ar.occluders)
        occluder.model = rebasedPath(occluder.model, from, to);
}

const Character* Scenario::findCharacter(const std::string& characterName) const
{
    for (const Character& character : characters)
        if (character.name == characterName)
            return &character;
    return nullptr;
}

const ScriptSpec* Scenario::findScript(const std::string& scriptName) const
{
    for (const ScriptSpec& script : scripts)
        if (script.name == scriptName)
            return &script;
    return nullptr;
}

const NamedMask* Scenario::findMask(const std::string& maskName) const
{
    for (const NamedMask& mask : masks)
        if (mask.name == maskName)
            return &mask;
    return nullptr;
}

const Gesture* Character::findGesture(const std::string& gestureName) const
{
    for (const Gesture& gesture : gestures)
        if (gesture.name == gestureName)
            return &gesture;
    return nullptr;
}

const ClipAsset* Character::findClip(const std::string& clipName) const
{
    for (const ClipAsset& clip : clips)
        if (clip.name == clipName)
            return &clip;
    return nullptr;
}

} // namespace thespis::core::scenario
