#include "edit/content_edits.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "edit/document_edits.h"
#include "lighting/probe.h"
#include "util/text.h"

namespace thespis::core::edit {

namespace {

using namespace scenario;

Error invalid(std::string message)
{
    return makeError(ErrorCode::InvalidArgument, std::move(message));
}

Result<const Character*> characterAt(const Scenario& s, int index)
{
    if (index < 0 || std::size_t(index) >= s.characters.size())
        return invalid("There is no character " + std::to_string(index + 1) + " (the scenario has "
                       + std::to_string(s.characters.size()) + ").");
    return &s.characters[std::size_t(index)];
}

Result<const Layer*> layerAt(const Scenario& s, const LayerPath& p)
{
    auto character = characterAt(s, p.character);
    if (!character)
        return character.error();
    if (p.layer < 0 || std::size_t(p.layer) >= (*character)->layers.size())
        return invalid("Character " + inQuotes((*character)->name) + " has no layer " + std::to_string(p.layer + 1) + ".");
    return &(*character)->layers[std::size_t(p.layer)];
}

std::vector<std::string> characterNames(const Scenario& s)
{
    std::vector<std::string> names;
    for (const Character& c : s.characters)
        names.push_back(c.name);
    return names;
}

template <class T>
std::vector<std::string> namesOf(const std::vector<T>& items)
{
    std::vector<std::string> names;
    for (const T& item : items)
        names.push_back(item.name);
    return names;
}

bool isSkeleton(const std::string& skeleton)
{
    return skeleton == "hanim-loa1" || skeleton == "hanim-loa2" || skeleton == "hanim-25" || skeleton == "model"
           || (skeleton.starts_with("clip:") && skeleton.size() > 5);
}

Edit replaceCharacter(int index, const Character& before, Character after)
{
    return Edit(CharacterChange{index, before, std::move(after)});
}

} // namespace

// ---- Characters ------------------------------------------------------------------------------

Character newCharacter(const std::string& name, const std::string& model, const std::string& skeleton)
{
    Character character;
    character.name = name;
    character.model = model;
    character.skeleton = skeleton;
    Layer body;
    body.name = "body";
    Layer face;
    face.name = "face";
    face.kind = LayerKind::Face;
    character.layers = {body, face};
    return character;
}

Result<Edit> addCharacter(const Scenario& scenario, Character character)
{
    if (!isSkeleton(character.skeleton))
        return invalid("Unknown skeleton " + inQuotes(character.skeleton) + ".");
    if (character.skeleton == "model" && character.model.empty())
        return invalid("A character playing on its model's rig needs a model.");
    const std::vector<std::string> taken = characterNames(scenario);
    character.name = uniqueName(character.name.empty() ? "Actor" : character.name, taken);
    return Edit(CharacterChange{int(scenario.characters.size()), std::nullopt, std::move(character)});
}

Result<Edit> removeCharacter(const Scenario& scenario, int index)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    return Edit(CharacterChange{index, **character, std::nullopt});
}

Result<Edit> renameCharacter(const Scenario& scenario, int index, const std::string& name)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    if (name.empty())
        return invalid("A character needs a name.");
    for (std::size_t i = 0; i < scenario.characters.size(); ++i)
        if (int(i) != index && scenario.characters[i].name == name)
            return invalid("Another character is already named " + inQuotes(name) + ".");
    Character renamed = **character;
    renamed.name = name;
    return replaceCharacter(index, **character, std::move(renamed));
}

Result<Edit> duplicateCharacter(const Scenario& scenario, int index)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    Character copy = **character;
    copy.name = uniqueName((*character)->name, characterNames(scenario));
    // A metre to its right: along its own +X, turned by its heading.
    const double heading = copy.heading * std::numbers::pi / 180.0;
    copy.position.x += float(std::cos(heading));
    copy.position.z -= float(std::sin(heading));
    return Edit(CharacterChange{int(scenario.characters.size()), std::nullopt, std::move(copy)});
}

Result<Edit> setCharacterBody(const Scenario& scenario, int index, const std::string& model, const std::string& skeleton)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    if (!isSkeleton(skeleton))
        return invalid("Unknown skeleton " + inQuotes(skeleton) + ".");
    if (skeleton == "model" && model.empty())
        return invalid("The built-in humanoid has no rig of its own: choose an H-Anim skeleton for it.");
    Character changed = **character;
    if (changed.model != model) {
        changed.segmentTags.clear(); // they name the old body's segments
        changed.bake.clear();
    }
    if (model.empty())
        changed.faceMapping.clear(); // the humanoid's face follows no table
    changed.model = model;
    changed.skeleton = skeleton;
    return replaceCharacter(index, **character, std::move(changed));
}

Result<Edit> setCharacterFaceMapping(const Scenario& scenario, int index, const std::string& path)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    if ((*character)->model.empty() && !path.empty())
        return invalid("The built-in humanoid has its own face: only a glTF model follows a face mapping table.");
    Character changed = **character;
    changed.faceMapping = path;
    return replaceCharacter(index, **character, std::move(changed));
}

Result<Edit> setCharacterPlacement(const Scenario& scenario, int index, anim::Vec3 position, double heading)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    if (!std::isfinite(position.x) || !std::isfinite(position.y) || !std::isfinite(position.z) || !std::isfinite(heading))
        return invalid("A position and a heading are finite numbers.");
    Character placed = **character;
    placed.position = position;
    placed.heading = heading;
    return replaceCharacter(index, **character, std::move(placed));
}

// ---- Layers ----------------------------------------------------------------------------------

Result<Edit> addLayer(const Scenario& scenario, int index, const std::string& name, LayerKind kind)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    Layer layer;
    layer.kind = kind;
    layer.name = uniqueName(name.empty() ? std::string(layerKindName(kind)) : name, namesOf((*character)->layers));
    return Edit(LayerChange{{index, int((*character)->layers.size())}, std::nullopt, std::move(layer)});
}

Result<Edit> removeLayer(const Scenario& scenario, const LayerPath& path)
{
    auto layer = layerAt(scenario, path);
    if (!layer)
        return layer.error();
    if ((*layer)->lock)
        return invalid("Layer " + inQuotes((*layer)->name) + " is locked: unlock it to remove it.");
    return Edit(LayerChange{path, **layer, std::nullopt});
}

Result<Edit> renameLayer(const Scenario& scenario, const LayerPath& path, const std::string& name)
{
    auto layer = layerAt(scenario, path);
    if (!layer)
        return layer.error();
    if (name.empty())
        return invalid("A layer needs a name.");
    const Character& character = scenario.characters[std::size_t(path.character)];
    for (std::size_t l = 0; l < character.layers.size(); ++l)
        if (int(l) != path.layer && character.layers[l].name == name)
            return invalid(inQuotes(character.name) + " already has a layer named " + inQuotes(name) + ".");
    Layer renamed = **layer;
    renamed.name = name;
    return Edit(LayerChange{path, **layer, std::move(renamed)});
}

Result<Edit> moveLayer(const Scenario& scenario, const LayerPath& path, int delta)
{
    auto layer = layerAt(scenario, path);
    if (!layer)
        return layer.error();
    const int count = int(scenario.characters[std::size_t(path.character)].layers.size());
    const int to = path.layer + delta;
    if (to < 0 || to >= count)
        return invalid("Layer " + inQuotes((*layer)->name) + " cannot move further " + (delta < 0 ? "up." : "down."));
    Edit edit(LayerChange{path, **layer, std::nullopt});
    edit.add(LayerChange{{path.character, to}, std::nullopt, **layer});
    return edit;
}

// ---- Clips -----------------------------------------------------------------------------------

Result<Edit> addClips(const Scenario& scenario, int index, std::vector<ClipAsset> clips)
{
    auto character = characterAt(scenario, index);
    if (!character)
        return character.error();
    if (clips.empty())
        return invalid("There are no clips to add.");
    std::vector<std::string> names = namesOf((*character)->clips);
    Edit edit;
    int at = int((*character)->clips.size());
    for (ClipAsset& clip : clips) {
        if (clip.file.empty() && clip.joints.empty() && clip.scalars.empty() && !clip.idle)
            return invalid("A clip needs a file, keyframes or an idle motion database.");
        clip.name = uniqueName(clip.name.empty() ? "clip" : clip.name, names);
        names.push_back(clip.name);
        edit.add(ClipChange{{index, at++}, std::nullopt, std::move(clip)});
    }
    return edit;
}

Result<Edit> addIdleAction(const Scenario& scenario, const LayerPath& layerPath, const std::string& database, Tick start)
{
    auto layer = layerAt(scenario, layerPath);
    if (!layer)
        return layer.error();
    if ((*layer)->kind != LayerKind::Body)
        return invalid("Idle motion moves the body: put it on a body layer, not on " + inQuotes((*layer)->name) + ".");
    if (database.empty())
        return invalid("The idle motion needs a database (.idle) to play.");
    const Character& character = scenario.characters[std::size_t(layerPath.character)];
    // The character's own idle on that database when it has one: its program and amplitude stay.
    const auto own = std::find_if(character.clips.begin(), character.clips.end(), [&](const ClipAsset& clip) {
        return clip.idle && clip.idle->database == database;
    });
    Edit edit;
    Scenario after = scenario;
    std::string clipName;
    if (own != character.clips.end()) {
        clipName = own->name;
    } else {
        ClipAsset clip;
        clip.name = "idle";
        // Each character a program of its own: characters side by side do not shift in step.
        clip.idle = IdleSynthesizer{.database = database, .seed = std::uint64_t(layerPath.character + 1)};
        auto added = addClips(scenario, layerPath.character, {std::move(clip)});
        if (!added)
            return added.error();
        if (auto applied = added->apply(after); !applied)
            return applied.error();
        clipName = after.characters[std::size_t(layerPath.character)].clips.back().name;
        edit.append(std::move(*added));
    }
    auto action = actionFromClip(after, layerPath, clipName, start);
    if (!action)
        return action.error();
    auto inserted = insertActions(after, layerPath, {std::move(*action)});
    if (!inserted)
        return inserted.error();
    edit.append(std::move(*inserted));
    return edit;
}

Result<Edit> replaceClip(const Scenario& scenario, const CharacterItemPath& path, ClipAsset value)
{
    auto character = characterAt(scenario, path.character);
    if (!character)
        return character.error();
    const Character& c = **character;
    if (path.index < 0 || std::size_t(path.index) >= c.clips.size())
        return invalid(inQuotes(c.name) + " has no clip " + std::to_string(path.index + 1) + ".");
    const ClipAsset& before = c.clips[std::size_t(path.index)];
    if (value.name.empty())
        return invalid("A clip needs a name.");
    if (const auto wrong = value.blinks ? value.blinks->problem() : std::nullopt)
        return invalid("Clip " + inQuotes(value.name) + ", blinks, " + wrong->field + ": " + wrong->message + ".");
    for (std::size_t i = 0; i < c.clips.size(); ++i)
        if (int(i) != path.index && c.clips[i].name == value.name)
            return invalid(inQuotes(c.name) + " already has a clip named " + inQuotes(value.name) + ".");
    if (value.name == before.name)
        return Edit(ClipChange{path, before, std::move(value)});
    // A new name: everything that plays the clip follows it, in one edit.
    Character renamed = c;
    renamed.clips[std::size_t(path.index)] = std::move(value);
    const std::string& to = renamed.clips[std::size_t(path.index)].name;
    for (Layer& layer : renamed.layers)
        for (ActionSpec& action : layer.actions)
            if (action.clip == before.name)
                action.clip = to;
    for (Gesture& gesture : renamed.gestures)
        if (gesture.clip == before.name)
            gesture.clip = to;
    if (renamed.skeleton == "clip:" + before.name)
        renamed.skeleton = "clip:" + to;
    return replaceCharacter(path.character, c, std::move(renamed));
}

Result<Edit> removeClip(const Scenario& scenario, const CharacterItemPath& path)
{
    auto character = characterAt(scenario, path.character);
    if (!character)
        return character.error();
    const Character& c = **character;
    if (path.index < 0 || std::size_t(path.index) >= c.clips.size())
        return invalid(inQuotes(c.name) + " has no clip " + std::to_string(path.index + 1) + ".");
    const ClipAsset& clip = c.clips[std::size_t(path.index)];
    std::vector<std::string> users;
    for (const Layer& layer : c.layers)
        for (const ActionSpec& action : layer.actions)
            if (action.clip == clip.name)
                users.push_back("action " + inQuotes(action.name));
    for (const Gesture& gesture : c.gestures)
        if (gesture.clip == clip.name)
            users.push_back("gesture " + inQuotes(gesture.name));
    if (c.skeleton == "clip:" + clip.name)
        users.push_back("the character's skeleton");
    if (!users.empty()) {
        std::string list;
        for (std::size_t i = 0; i < users.size() && i < 5; ++i)
            list += (i ? ", " : "") + users[i];
        if (users.size() > 5)
            list += " and " + std::to_string(users.size() - 5) + " more";
        return invalid("Clip " + inQuotes(clip.name) + " is still used by " + list + ".");
    }
    return Edit(ClipChange{path, clip, std::nullopt});
}

// ---- The light -------------------------------------------------------------------------------

Result<Edit> setLighting(const Scenario& scenario, LightingSpec lighting)
{
    if (auto layout = lighting::parseProbeLayout(lighting.layout); !layout)
        return layout.error();
    if (!std::isfinite(lighting.rotation))
        return invalid("The light's rotation must be a number of degrees.");
    if (!std::isfinite(lighting.intensity) || lighting.intensity < 0)
        return invalid("The light's intensity must be zero or more.");
    return Edit(LightingChange{scenario.lighting, std::move(lighting)});
}

Result<Edit> setScript(const Scenario& scenario, const std::string& name, const std::string& source)
{
    if (name.empty())
        return invalid("A script needs a name.");
    std::vector<ScriptSpec> scripts = scenario.scripts;
    auto it = std::find_if(scripts.begin(), scripts.end(), [&](const ScriptSpec& s) { return s.name == name; });
    if (it == scripts.end())
        scripts.push_back(ScriptSpec{name, source, nlohmann::json::object()});
    else
        it->source = source;
    return Edit(ScriptsChange{scenario.scripts, std::move(scripts)});
}

Result<Edit> removeScript(const Scenario& scenario, const std::string& name)
{
    std::vector<ScriptSpec> scripts = scenario.scripts;
    if (std::erase_if(scripts, [&](const ScriptSpec& s) { return s.name == name; }) == 0)
        return makeError(ErrorCode::NotFound, "The scenario has no script named \"" + name + "\".");
    return Edit(ScriptsChange{scenario.scripts, std::move(scripts)});
}

} // namespace thespis::core::edit
