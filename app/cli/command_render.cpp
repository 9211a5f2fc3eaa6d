// thespis-cli render: pictures of a scenario without any X server (EGL offscreen, Mesa's software
// GL when there is no GPU): one frame at --time, or a numbered sequence with --frames. The camera
// frames every character over the whole timeline, so a sequence does not jump.

#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "cancel.h"
#include "commands.h"
#include "exit_codes.h"
#include "lighting/transfer_bake.h"
#include "progress.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"

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

struct FrameRange {
    long first = 0, last = 0;
};

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

CommandSpec renderSpec()
{
    CommandSpec spec;
    spec.name = "render";
    spec.summary = "Render frames of a scenario to PNG, headless (no X server needed).";
    spec.positionals = {"SCENARIO"};
    spec.options = {
        {"out", "FILE.png|DIR/", "the picture to write, or the folder of a --frames sequence", true},
        {"time", "SECONDS", "the moment to render (default 0)"},
        {"frames", "A:B", "render frames A to B (inclusive) at --fps into DIR/frame_NNNNN.png"},
        {"fps", "N", "frame rate of --frames (default 30)"},
        {"size", "WxH", "picture size in pixels (default 1280x720)"},
        {"shading", "prt|phong|unlit", "PRT lighting (paper §6), Phong for comparison, or albedo only (default prt)"},
        {"bake", "FILE", "baked transfer (thespis-cli bake) for the character; without it PRT is unshadowed (DU)"},
        {"character", "NAME", "the character --bake belongs to (needed when the scenario has several)"},
        {"skinning", "lbs|dqs", "linear blend or dual-quaternion skinning (default lbs)"},
        {"azimuth", "DEGREES", "camera direction around the vertical: 0 in front, 90 from the character's left (default 20)"},
        {"elevation", "DEGREES", "camera height above the horizon (default 8)"},
        {"no-ground", "", "leave out the ground disc"},
        {"probe-background", "", "draw the scenario's light probe behind the characters"},
        {"samples", "N", "multisampling samples per pixel (default 4, 0 for none)"},
        {"quiet", "", "no progress and no summary"},
    };
    spec.description =
        "The light comes from the scenario's probe, or a default sky. Rendering uses EGL on Mesa's\n"
        "surfaceless platform, so it runs on servers and in CI; GALLIUM_DRIVER=llvmpipe forces software GL.\n"
        "Exit status: 0 written, 2 bad command line, 3 unreadable scenario, bake or probe,\n"
        "4 no OpenGL or the picture could not be written, 130 cancelled (frames written so far stay).";
    return spec;
}

int runRender(const CommandSpec& spec, const ParsedArguments& arguments)
{
    const std::filesystem::path scenarioPath = arguments.positionals[0];
    const std::filesystem::path outPath = *arguments.value("out");
    const bool quiet = arguments.has("quiet");
    int exitCode = ExitOk;

    Size size;
    if (const auto text = arguments.value("size")) {
        const auto parsed = parseSize(*text);
        if (!parsed)
            return usageError(spec, "--size must be WIDTHxHEIGHT in pixels (1 to 16384 each), e.g. 1280x720, not '" + *text + "'");
        size = *parsed;
    }
    std::optional<FrameRange> frames;
    if (const auto text = arguments.value("frames")) {
        frames = parseFrameRange(*text);
        if (!frames)
            return usageError(spec, "--frames must be FIRST:LAST frame numbers (0 ≤ FIRST ≤ LAST), not '" + *text + "'");
        if (arguments.has("time"))
            return usageError(spec, "give either --time or --frames, not both");
    } else if (arguments.has("fps")) {
        return usageError(spec, "--fps needs --frames");
    }
    double fps = 30;
    if (const auto text = arguments.value("fps")) {
        const auto value = parseNumber(*text);
        if (!value || !(*value > 0) || *value > 1000)
            return usageError(spec, "--fps must be a frame rate above 0 (at most 1000), not '" + *text + "'");
        fps = *value;
    }
    double time = 0;
    if (const auto text = arguments.value("time")) {
        const auto value = parseNumber(*text);
        if (!value || !std::isfinite(*value) || *value < 0)
            return usageError(spec, "--time must be a time in seconds (0 or more), not '" + *text + "'");
        time = *value;
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

    if (frames) {
        if (std::error_code ec; !std::filesystem::is_directory(outPath, ec) && !std::filesystem::create_directories(outPath, ec)) {
            printError(spec.name, "cannot create the folder " + outPath.string() + ": " + ec.message() + ".");
            return ExitFailure;
        }
    } else {
        const std::filesystem::path outDir = outPath.parent_path().empty() ? "." : outPath.parent_path();
        if (std::error_code ec; !std::filesystem::is_directory(outDir, ec)) {
            printError(spec.name, "cannot write " + outPath.string() + ": the folder " + outDir.string() + " does not exist.");
            return ExitInvalidInput;
        }
    }

    const auto document = loadScenarioReporting(spec.name, scenarioPath);
    if (!document)
        return ExitInvalidInput;
    render::ScenarioSceneOptions options;
    options.skinning = *skinning;
    options.probeBackground = arguments.has("probe-background");
    if (const auto bakePath = arguments.value("bake")) {
        std::string name;
        if (const auto character = arguments.value("character")) {
            name = *character;
        } else if (document->characters.size() == 1) {
            name = document->characters.front().name;
        } else {
            return usageError(spec, "the scenario has several characters; name the one --bake belongs to with --character");
        }
        if (!document->findCharacter(name)) {
            printError(spec.name, "the scenario has no character named '" + name + "'.");
            return ExitInvalidInput;
        }
        auto bake = core::lighting::readBakeFile(*bakePath);
        if (!bake) {
            printError(spec.name, bake.error());
            return ExitInvalidInput;
        }
        options.bakes[name] = std::make_shared<const core::lighting::TransferBake>(std::move(bake).value());
    }
    const std::filesystem::path baseDir = scenarioPath.parent_path().empty() ? "." : scenarioPath.parent_path();
    auto scenarioScene = render::ScenarioScene::create(*document, baseDir, options);
    if (!scenarioScene) {
        printError(spec.name, scenarioScene.error());
        if (arguments.has("bake"))
            std::fprintf(stderr, "thespis-cli render: a bake fits a character's body when it was made with "
                                 "'thespis-cli bake %s --character NAME'.\n", scenarioPath.string().c_str());
        return ExitInvalidInput;
    }
    render::ScenarioScene& scene = **scenarioScene;
    if (!quiet)
        for (const std::string& warning : scene.warnings())
            std::fprintf(stderr, "thespis-cli render: warning: %s\n", warning.c_str());
    scene.scene().setShading(*shading);
    scene.scene().setGroundVisible(!arguments.has("no-ground"));

    auto renderer = render::OffscreenRenderer::create(size.width, size.height, int(samples));
    if (!renderer) {
        printError(spec.name, renderer.error());
        return ExitFailure;
    }
    const render::CameraView view = render::frameBounds(scene.boundsOverTimeline(), *azimuth, *elevation,
                                                        double(size.width) / size.height);
    render::RgbaImage image;
    auto renderAt = [&](double seconds, const std::filesystem::path& file) -> int {
        scene.setTime(seconds);
        if (auto drawn = (*renderer)->render(scene.scene(), view, image); !drawn) {
            printError(spec.name, drawn.error());
            return ExitFailure;
        }
        if (auto written = render::writePng(file, image); !written) {
            printError(spec.name, written.error());
            return ExitFailure;
        }
        return ExitOk;
    };

    if (!frames) {
        if (const int status = renderAt(time, outPath); status != ExitOk)
            return status;
        if (!quiet)
            std::printf("Rendered %s at %.3f s (%dx%d, %s) to %s with %s.\n", scenarioPath.filename().string().c_str(),
                        time, size.width, size.height, render::shadingName(*shading), outPath.string().c_str(),
                        (*renderer)->glDescription().c_str());
        return ExitOk;
    }

    installInterruptHandlers();
    const long count = frames->last - frames->first + 1;
    ProgressReporter progress(stderr, "render", "frames", count, quiet);
    for (long frame = frames->first; frame <= frames->last; ++frame) {
        if (interrupted()) {
            progress.abandon();
            std::fprintf(stderr, "thespis-cli render: cancelled after %ld of %ld frames.\n", frame - frames->first, count);
            return ExitCancelled;
        }
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05ld.png", frame);
        if (const int status = renderAt(double(frame) / fps, outPath / name); status != ExitOk) {
            progress.abandon();
            return status;
        }
        progress.update(frame - frames->first + 1);
    }
    progress.finish();
    if (!quiet)
        std::printf("Rendered %ld frames (%ld to %ld at %g fps, %dx%d, %s) into %s.\n", count, frames->first,
                    frames->last, fps, size.width, size.height, render::shadingName(*shading), outPath.string().c_str());
    return ExitOk;
}

} // namespace thespis::cli
