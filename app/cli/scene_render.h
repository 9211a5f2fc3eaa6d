#pragma once
// What `render` and `run` share: the picture options, the scene built from a scenario with them,
// the camera that frames every character over the whole timeline (so a sequence does not jump),
// and writing the scene as it is posed into a PNG.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "arguments.h"
#include "render/camera.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"

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

struct SceneRender {
    std::unique_ptr<core::render::ScenarioScene> scene;
    std::unique_ptr<core::render::OffscreenRenderer> renderer;
    core::render::CameraView view;
    core::render::RgbaImage image;
    int width = 1280, height = 720;
    core::render::Shading shading = core::render::Shading::Prt;

    /// Draws the scene as it is posed now into `file`; prints what failed and returns the exit code.
    int write(const std::string& command, const std::filesystem::path& file);
};

/// Reads the picture options, loads the scenario, builds the scene and the renderer and frames
/// the camera; prints what is wrong and returns the exit code (ExitOk when `out` is ready).
int prepareSceneRender(const CommandSpec& spec, const ParsedArguments& arguments,
                       const std::filesystem::path& scenarioPath, bool quiet, SceneRender& out);

/// "frame_00042.png".
std::string frameFileName(long frame);

} // namespace thespis::cli
