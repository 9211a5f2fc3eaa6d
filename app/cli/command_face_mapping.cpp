// thespis-cli face-mapping MODEL: a glTF model's morph targets and face joints, and the face
// mapping table that drives them — the one its names are recognised as (ARKit, Oculus visemes,
// expression names, eye and jaw bones) or one read from a file — with a warning for each target
// or joint the table names that the model lacks. --save-mapping writes the table to edit.

#include <cstdio>
#include <string>

#include "commands.h"
#include "exit_codes.h"
#include "scene/face_mapping.h"
#include "scene/face_naming.h"
#include "scene/gltf_character.h"

namespace thespis::cli {
namespace {

namespace scene = core::scene;

const char* sideText(scene::MorphDrive::Side side)
{
    switch (side) {
    case scene::MorphDrive::Side::Both: return "";
    case scene::MorphDrive::Side::Positive: return ", positive values only";
    case scene::MorphDrive::Side::Negative: return ", negative values only";
    }
    return "";
}

void printMapping(const scene::FaceMapping& mapping)
{
    for (const scene::FaceMappingDrive& drive : mapping.drives)
        std::printf("  %s <- %s x %.9g%s\n", drive.target.c_str(), scene::faceChannelName(drive.channel).c_str(),
                    drive.coefficient, sideText(drive.side));
    for (const scene::FaceMappingJoint& joint : mapping.joints)
        std::printf("  joint %s <- %s, about (%g, %g, %g), %.9g rad per unit\n", joint.joint.c_str(),
                    scene::faceChannelName(joint.channel).c_str(), joint.axis.x, joint.axis.y, joint.axis.z,
                    joint.radiansPerUnit);
}

} // namespace

CommandSpec faceMappingSpec()
{
    CommandSpec spec;
    spec.name = "face-mapping";
    spec.summary = "Show a glTF model's morph targets and the face mapping table that drives them.";
    spec.positionals = {"MODEL"};
    spec.options = {{"mapping", "FILE", "use this face mapping table instead of the recognised one"},
                    {"save-mapping", "FILE", "write the table (recognised or read) as JSON, to edit"}};
    spec.description =
        "Without --mapping the table comes from the names Thespis recognises: ARKit blendshapes, Oculus\n"
        "visemes, expression targets (Angry, Sad, ...), targets named after face channels, eye and jaw\n"
        "bones. Each drive is printed as TARGET <- CHANNEL x COEFFICIENT; targets or joints the table\n"
        "names that the model lacks are warned about, one line each.\n"
        "Exit status: 0 shown, 3 unreadable model or table, 4 the table could not be written, 2 bad\n"
        "command line.";
    return spec;
}

int runFaceMapping(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path path = arguments.positionals[0];
    scene::GltfCharacterOptions options;
    options.loadTextures = false;
    if (const auto file = arguments.value("mapping")) {
        auto mapping = scene::loadFaceMapping(*file);
        if (!mapping) {
            printError(spec.name, mapping.error());
            return ExitInvalidInput;
        }
        options.faceMapping = std::move(*mapping);
    }
    auto character = scene::loadGltfCharacter(path, options);
    if (!character) {
        printError(spec.name, character.error());
        return ExitInvalidInput;
    }
    const std::vector<std::string> names = scene::morphTargetNames(*character);
    std::printf("Model %s (%s): %zu morph target%s\n", character->name.c_str(), path.string().c_str(), names.size(),
                names.size() == 1 ? "" : "s");
    for (const scene::MorphTarget& target : character->face.targets)
        std::printf("  %s: moves %zu %s\n", target.name.c_str(), target.vertices.size(),
                    target.vertices.size() == 1 ? "vertex" : "vertices");

    const scene::FaceMapping mapping =
        options.faceMapping ? *options.faceMapping : scene::recogniseFaceMapping(*character);
    if (options.faceMapping)
        std::printf("Face mapping '%s' from %s:\n", mapping.name.c_str(), arguments.value("mapping")->c_str());
    else if (mapping.empty())
        std::printf("Face mapping: none recognised (write one and give it with --mapping)\n");
    else
        std::printf("Face mapping recognised (%s):\n", mapping.name.c_str());
    printMapping(mapping);
    for (const std::string& warning : character->warnings)
        if (warning.find("face mapping") != std::string::npos)
            std::fprintf(stderr, "thespis-cli %s: warning: %s\n", spec.name.c_str(), warning.c_str());

    if (const auto out = arguments.value("save-mapping")) {
        if (auto saved = scene::saveFaceMapping(*out, mapping); !saved) {
            printError(spec.name, saved.error());
            return ExitFailure;
        }
        std::printf("Wrote %s\n", out->c_str());
    }
    return ExitOk;
}

} // namespace thespis::cli
