// thespis-cli info SCENARIO: what a scenario holds — characters (body, placement), clips and
// their import options, layers and actions, the light, masks — read from the document alone (clips are not loaded), so it works on scenarios whose
// BVH files are missing too.

#include <algorithm>
#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "util/tick.h"

namespace thespis::cli {
namespace {

namespace scenario = core::scenario;

const char* placementName(scenario::Placement placement)
{
    switch (placement) {
    case scenario::Placement::World: return "";
    case scenario::Placement::Character: return ", starts at the character";
    case scenario::Placement::Continue: return ", continues the previous action";
    }
    return "";
}

const char* modeName(core::anim::BlendMode mode)
{
    switch (mode) {
    case core::anim::BlendMode::Normalized: return "normalized";
    case core::anim::BlendMode::Additive: return "additive";
    case core::anim::BlendMode::Override: return "override";
    }
    return "?";
}

std::string clipSummary(const scenario::ClipAsset& clip)
{
    if (!clip.file.empty()) {
        std::string text = "file " + clip.file;
        if (!clip.animation.empty())
            text += ", animation '" + clip.animation + "'";
        char number[64];
        if (clip.frameRateOverride > 0) {
            std::snprintf(number, sizeof number, ", at %g fps", clip.frameRateOverride);
            text += number;
        }
        if (clip.unit > 0) {
            std::snprintf(number, sizeof number, ", %g m per unit", clip.unit);
            text += number;
        }
        if (!clip.fitGround)
            text += ", not fitted to the floor";
        if (clip.keepCalibrationFrame)
            text += ", keeps its calibration frame";
        if (!clip.mapping.empty())
            text += ", " + std::to_string(clip.mapping.size()) + " joints mapped by hand";
        return text;
    }
    if (clip.idle) {
        char amplitude[64];
        std::snprintf(amplitude, sizeof amplitude, "%g", clip.idle->amplitude);
        return "idle motion from " + clip.idle->database + ", seed " + std::to_string(clip.idle->seed) +
               ", variations x" + amplitude;
    }
    const std::size_t perFrame = clip.valuesPerFrame();
    const std::size_t frames = perFrame ? clip.frames.size() / perFrame : 0;
    char text[160];
    std::snprintf(text, sizeof text, "inline, %zu joints, %zu scalars, %zu frames at %g fps", clip.joints.size(),
                  clip.scalars.size(), frames, clip.frameRate);
    return text;
}

} // namespace

CommandSpec infoSpec()
{
    CommandSpec spec;
    spec.name = "info";
    spec.summary = "List a scenario's characters, clips, layers, actions and masks.";
    spec.positionals = {"SCENARIO|PACKAGE"};
    spec.description = "Reads only the scenario (clips are not loaded); a package is checked first.\n"
                       "Exit status: 0 read, 3 unreadable or malformed, 2 bad command line.";
    return spec;
}

int runInfo(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path path = arguments.positionals[0];
    const auto opened = openScenarioReporting(spec.name, path);
    if (!opened)
        return ExitInvalidInput;
    const scenario::Scenario* document = &opened->scenario;

    std::printf("Scenario '%s' (%s)\n", document->name.c_str(), path.string().c_str());
    if (document->duration > 0)
        std::printf("  duration: %.3f s\n", core::ticksToSeconds(document->duration));
    else
        std::printf("  duration: up to the last action's end\n");
    for (const scenario::Character& character : document->characters) {
        std::printf("Character '%s' (%s, skeleton %s) at (%g, %g, %g) m facing %g°\n", character.name.c_str(),
                    character.model.empty() ? "built-in humanoid" : ("model " + character.model).c_str(),
                    character.skeleton.c_str(), double(character.position.x), double(character.position.y),
                    double(character.position.z), character.heading);
        if (!character.bake.empty())
            std::printf("  lighting bake: %s\n", character.bake.c_str());
        if (!character.faceMapping.empty())
            std::printf("  face mapping table: %s\n", character.faceMapping.c_str());
        for (const scenario::ClipAsset& clip : character.clips)
            std::printf("  clip '%s': %s\n", clip.name.c_str(), clipSummary(clip).c_str());
        for (const scenario::Layer& layer : character.layers) {
            std::printf("  layer '%s' (%s, %s): %zu action%s\n", layer.name.c_str(),
                        scenario::layerKindName(layer.kind), modeName(layer.mode),
                        layer.actions.size(), layer.actions.size() == 1 ? "" : "s");
            for (const scenario::ActionSpec& action : layer.actions)
                if (action.gaze)
                    std::printf("    action '%s': looks at '%s' (%s) from %.3f s\n", action.name.c_str(),
                                action.gaze->target.c_str(), action.gaze->influence.c_str(),
                                core::ticksToSeconds(action.start));
                else
                    std::printf("    action '%s': clip '%s' at %.3f s, %s%s%s%s%s\n", action.name.c_str(),
                                action.clip.c_str(), core::ticksToSeconds(action.start), modeName(action.mode),
                                action.mask.empty() ? "" : ", mask '", action.mask.c_str(), action.mask.empty() ? "" : "'",
                                placementName(action.placement));
            for (const scenario::ActionSpec& action : layer.actions)
                if (action.pointing)
                    std::printf("    action '%s' points at '%s' (%s)\n", action.name.c_str(),
                                action.pointing->target.c_str(), action.pointing->hand.c_str());
        }
    }
    if (document->lighting.probe.empty())
        std::printf("Light: the default sky\n");
    else
        std::printf("Light: probe %s (%s), turned %g°, intensity %g\n", document->lighting.probe.c_str(),
                    document->lighting.layout.c_str(), document->lighting.rotation, document->lighting.intensity);
    for (const scenario::NamedMask& mask : document->masks)
        std::printf("Mask '%s': %zu joints, default weight %g\n", mask.name.c_str(), mask.mask.weights().size(),
                    double(mask.mask.defaultWeight()));
    for (const scenario::ScriptSpec& script : document->scripts)
        std::printf("Script '%s': %zu lines (thespis-cli run %s --script %s)\n", script.name.c_str(),
                    std::size_t(std::count(script.source.begin(), script.source.end(), '\n')), path.string().c_str(),
                    script.name.c_str());
    return ExitOk;
}

} // namespace thespis::cli
