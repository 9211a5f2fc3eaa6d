#pragma once
// What `render` and `run` share: the picture options, read into core's PictureSettings, and the
// picture (core/render/scenario_picture.h) made from them.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arguments.h"
#include "render/scenario_picture.h"
#include "scenario/open_scenario.h"

namespace thespis::cli {

struct FrameRange {
    long first = 0, last = 0;
};
/// "A:B" with 0 ≤ A ≤ B.
std::optional<FrameRange> parseFrameRange(const std::string& text);
/// --frames, when given; a bad value prints the usage error and sets exitCode.
std::optional<FrameRange> frameRangeOption(const CommandSpec& spec, const ParsedArguments& arguments, int& exitCode);
/// Makes the folder a frame sequence goes into; prints why not and returns ExitFailure.
int makeFrameFolder(const std::string& command, const std::filesystem::path& folder);
/// --fps (default 30); on a bad value prints the usage error and sets exitCode.
std::optional<double> frameRateOption(const CommandSpec& spec, const ParsedArguments& arguments, int& exitCode);

/// Appends the picture options (size, shading, bake and character, skinning, camera, ground,
/// probe background, samples) and --quiet to a command's options.
void addPictureOptions(CommandSpec& spec);

/// Reads the picture options into `out` (a bake is read and given to its character of
/// `document`); prints what is wrong and returns the exit code.
int readPictureSettings(const CommandSpec& spec, const ParsedArguments& arguments,
                        const core::scenario::Scenario& document, core::render::PictureSettings& out);

/// Reads the picture options and makes the picture of the opened scenario (scene, renderer,
/// framed camera) on this thread; prints what is wrong (and the scene's warnings unless quiet)
/// and returns the exit code (ExitOk when `out` is ready).
int makePicture(const CommandSpec& spec, const ParsedArguments& arguments, const std::filesystem::path& scenarioPath,
                const core::scenario::OpenedScenario& document, bool quiet,
                std::unique_ptr<core::render::ScenarioPicture>& out);

/// Draws the picture as it is posed now into `file`; prints what failed and returns the exit code.
int writePicture(const std::string& command, core::render::ScenarioPicture& picture, const std::filesystem::path& file);

/// The error of a scene that could not be made, with a hint when a bake was given.
void printSceneError(const CommandSpec& spec, const ParsedArguments& arguments, const std::filesystem::path& scenarioPath,
                     const core::Error& error);

} // namespace thespis::cli
