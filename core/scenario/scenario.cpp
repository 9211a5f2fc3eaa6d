#include "scenario/scenario.h"

namespace thespis::core::scenario {

std::string rebasedPath(const std::string& path, const std::filesystem::path& from, const std::filesystem::path& to,
                        const KeptNames& keep)
{
    if (path.empty() || std::filesystem::path(path).is_absolute() || from == to || (keep && keep(path)))
        return path;
    return (from / path).lexically_normal().lexically_relative(to).generic_string();
}

void rebaseClip(ClipAsset& clip, const std::filesystem::path& from, const std::filesystem::path& to, const KeptNames& keep)
{
    clip.file = rebasedPath(clip.file, from, to, keep);
    if (clip.idle)
        clip.idle->database = rebasedPath(clip.idle->database, from, to, keep);
}

void rebasePaths(Scenario& scenario, const std::filesystem::path& from, const std::filesystem::path& to,
                 const KeptNames& keep)
{
    for (Character& character : scenario.characters) {
        character.model = rebasedPath(character.model, from, to, keep);
        character.bake = rebasedPath(character.bake, from, to, keep);
        character.faceMapping = rebasedPath(character.faceMapping, from, to, keep);
        for (SpeechLine& line : character.speech)
            line.audio = rebasedPath(line.audio, from, to, keep);
        for (ClipAsset& clip : character.clips)
            rebaseClip(clip, from, to, keep);
    }
    scenario.lighting.probe = rebasedPath(scenario.lighting.probe, from, to, keep);
    scenario.postureBases = rebasedPath(scenario.postureBases, from, to, keep);
    for (PhantomOccluder& occluder : scenario.ar.occluders)
        occluder.model = rebasedPath(occluder.model, from, to, keep);
}

const char* layerKindName(LayerKind kind)
{
    switch (kind) {
    case LayerKind::Body: return "body";
    case LayerKind::Face: return "face";
    case LayerKind::Gaze: break;
    }
    return "gaze";
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

std::optional<BlinkClip::Problem> BlinkClip::problem() const
{
    if (!(rate >= 1 && rate <= 120))
        return Problem{"rate", "must be 1 to 120 blinks a minute, found " + std::to_string(rate)};
    if (!(closeSeconds > 0))
        return Problem{"closeSeconds", "must be positive, found " + std::to_string(closeSeconds)};
    if (!(shutSeconds >= 0))
        return Problem{"shutSeconds", "must not be negative, found " + std::to_string(shutSeconds)};
    if (!(openSeconds > 0))
        return Problem{"openSeconds", "must be positive, found " + std::to_string(openSeconds)};
    if (closeSeconds + shutSeconds + openSeconds >= 0.4)
        return Problem{"openSeconds", "a whole blink must take less than 0.4 s (closing, shut and opening)"};
    return std::nullopt;
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
