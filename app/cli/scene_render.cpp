#include "scene_render.h"

#include <cmath>
#include <cstdio>

#include "commands.h"
#include "exit_codes.h"
#include "lighting/transfer_bake.h"

namespace thespis::cli {
namespace {

namespace render = core::render;

struct Size {
    int width = 1280, height = 720;
};

std::optional<Size> parseSize(const std::string& text)
{
    const auto x = text.find('x');
    if (x == std::string::npos)
        return std::nullopt;
    const auto width = parseNumber(std::string_view(text).substr(0, x));
    const auto height = parseNumber(std::string_view(text).substr(x + 1));
    if (!width || !height || *width != std::floor(*width) || *height != std::floor(*height) || *width < 1 ||
        *height < 1 || *width > 16384 || *height > 16384)
        return std::nullopt;
    return Size{int(*width), int(*height)};
}

std::optional<double> angleOption(const CommandSpec& spec, const ParsedArguments& arguments, const std::string& name,
                                  double fallback, int& exitCode)
{
    const auto text = arguments.value(name);
    if (!text)
        return fallback;
    const auto value = parseNumber(*text);
    if (!value || !std::isfinite(*value) || std::abs(*value) > 360) {
        exitCode = usageError(spec, "--" + name + " must be an angle in degrees (−360 to 360), not '" + *text + "'");
        return std::nullopt;
    }
    return *value;
}

} // namespace

std::optional<FrameRange> parseFrameRange(const std::string& text)
{
    const auto colon = text.find(':');
    if (colon == std::string::npos)
        return std::nullopt;
    const auto first = parseNumber(std::string_view(text).substr(0, colon));
    const auto last = parseNumber(std::string_view(text).substr(colon + 1));
    if (!first || !last || *first != std::floor(*first) || *last != std::floor(*last) || *first < 0 || *last < *first ||
        *last > 10'000'000)
        return std::nullopt;
    return FrameRange{long(*first), long(*last)};
}

std::optional<FrameRange> frameRangeOption(const CommandSpec& spec, const ParsedArguments& arguments, int& exitCode)
{
    const auto text = arguments.value("frames");
    if (!text)
        return std::nullopt;
    auto frames = parseFrameRange(*text);
    if (!frames)
        exitCode = usageError(spec, "--frames must be FIRST:LAST frame numbers (0 ≤ FIRST ≤ LAST), not '" + *text + "'");
    return frames;
}

int makeFrameFolder(const std::string& command, const std::filesystem::path& folder)
{
    if (std::error_code ec; !std::filesystem::is_directory(folder, ec) && !std::filesystem::create_directories(folder, ec)) {
        printError(command, "cannot create the folder " + folder.string() + ": " + ec.message() + ".");
        return ExitFailure;
    }
    return ExitOk;
}

std::optional<double> frameRateOption(const CommandSpec& spec, const ParsedArguments& arguments, int& exitCode)
{
    const auto text = arguments.value("fps");
    if (!text)
        return 30.0;
    const auto value = parseNumber(*text);
    if (!value || !(*value > 0) || *value > 1000) {
        exitCode = usageError(spec, "--fps must be a frame rate above 0 (at most 1000), not '" + *text + "'");
        return std::nullopt;
    }
    return *value;
}

void addPictureOptions(CommandSpec& spec)
{
    spec.options.insert(spec.options.end(), {
        {"size", "WxH", "picture size in pixels (default 1280x720)"},
        {"shading", "prt|phong|unlit", "PRT lighting (paper §6), Phong for comparison, or albedo only (default prt)"},
        {"bake", "FILE", "baked transfer (thespis-cli bake) for the character; without it PRT is unshadowed (DU)"},
        {"character", "NAME", "the character --bake belongs to (needed when the scenario has several)"},
        {"skinning", "lbs|dqs", "linear blend or dual-quaternion skinning (default lbs)"},
        {"azimuth", "DEGREES", "camera direction around the vertical: 0 in front, 90 from the character's left (default 20)"},
        {"elevation", "DEGREES", "camera height above the horizon (default 8)"},
        {"close-up", "CHARACTER", "frame that character's head, following it (--azimuth then counts from where it looks)"},
        {"no-ground", "", "leave out the ground disc"},
        {"probe-background", "", "draw the scenario's light probe behind the characters"},
        {"samples", "N", "multisampling samples per pixel (default 4, 0 for none)"},
        {"quiet", "", "no progress and no summary"},
    });
}

int readPictureSettings(const CommandSpec& spec, const ParsedArguments& arguments,
                        const core::scenario::Scenario& document, render::PictureSettings& out)
{
    int exitCode = ExitOk;
    if (const auto text = arguments.value("size")) {
        const auto parsed = parseSize(*text);
        if (!parsed)
            return usageError(spec, "--size must be WIDTHxHEIGHT in pixels (1 to 16384 each), e.g. 1280x720, not '" + *text + "'");
        out.width = parsed->width;
        out.height = parsed->height;
    }
    const auto shading = choiceOption(spec, arguments, "shading", render::Shading::Prt, render::parseShading, exitCode);
    const auto skinning = choiceOption(spec, arguments, "skinning", core::scene::SkinningMethod::Linear,
                                       core::scene::parseSkinningMethod, exitCode);
    const auto samples = integerOption(spec, arguments, "samples", 0, 16, exitCode).value_or(4);
    const auto azimuth = angleOption(spec, arguments, "azimuth", 20.0, exitCode);
    const auto elevation = angleOption(spec, arguments, "elevation", 8.0, exitCode);
    if (exitCode != ExitOk)
        return exitCode;
    if (arguments.has("character") && !arguments.has("bake"))
        return usageError(spec, "--character needs --bake");
    out.shading = *shading;
    out.skinning = *skinning;
    out.samples = int(samples);
    out.azimuth = *azimuth;
    out.elevation = *elevation;
    out.ground = !arguments.has("no-ground");
    if (const auto closeUp = arguments.value("close-up")) {
        if (!document.findCharacter(*closeUp)) {
            printError(spec.name, "--close-up: the scenario has no character named '" + *closeUp + "'.");
            return ExitInvalidInput;
        }
        out.closeUp = *closeUp;
    }
    out.probeBackground = arguments.has("probe-background");
    if (const auto bakePath = arguments.value("bake")) {
        std::string name;
        if (const auto character = arguments.value("character")) {
            name = *character;
        } else if (document.characters.size() == 1) {
            name = document.characters.front().name;
        } else {
            return usageError(spec, "the scenario has several characters; name the one --bake belongs to with --character");
        }
        if (!document.findCharacter(name)) {
            printError(spec.name, "the scenario has no character named '" + name + "'.");
            return ExitInvalidInput;
        }
        auto bake = core::lighting::readBakeFile(*bakePath);
        if (!bake) {
            printError(spec.name, bake.error());
            return ExitInvalidInput;
        }
        out.bakes[name] = std::make_shared<const core::lighting::TransferBake>(std::move(bake).value());
    }
    return ExitOk;
}

void printSceneError(const CommandSpec& spec, const ParsedArguments& arguments, const std::filesystem::path& scenarioPath,
                     const core::Error& error)
{
    printError(spec.name, error);
    if (arguments.has("bake"))
        std::fprintf(stderr, "thespis-cli %s: a bake fits a character's body when it was made with "
                             "'thespis-cli bake %s --character NAME'.\n", spec.name.c_str(), scenarioPath.string().c_str());
}

int makePicture(const CommandSpec& spec, const ParsedArguments& arguments, const std::filesystem::path& scenarioPath,
                const core::scenario::OpenedScenario& document, bool quiet, std::unique_ptr<render::ScenarioPicture>& out)
{
    render::PictureSettings settings;
    if (const int status = readPictureSettings(spec, arguments, document.scenario, settings); status != ExitOk)
        return status;
    auto picture = render::ScenarioPicture::create(document.scenario, document.assets, settings);
    if (!picture) {
        printSceneError(spec, arguments, scenarioPath, picture.error());
        return picture.error().code == core::ErrorCode::IoError || picture.error().code == core::ErrorCode::Internal
                   ? ExitFailure
                   : ExitInvalidInput;
    }
    out = std::move(picture).value();
    if (!quiet)
        for (const std::string& warning : out->scene().warnings())
            std::fprintf(stderr, "thespis-cli %s: warning: %s\n", spec.name.c_str(), warning.c_str());
    return ExitOk;
}

int writePicture(const std::string& command, render::ScenarioPicture& picture, const std::filesystem::path& file)
{
    if (auto written = picture.writePng(file); !written) {
        printError(command, written.error());
        return ExitFailure;
    }
    return ExitOk;
}

} // namespace thespis::cli
