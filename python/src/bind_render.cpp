// Bindings of core/render as the submodule thespis.render: a scenario rendered headless (EGL on
// Mesa, no X server), as `thespis-cli render` does, into a NumPy RGBA image or a frame sequence
// (the same job the CLI runs), and PNG output.

#include <optional>
#include <string>

#include "bind_common.h"
#include "errors.h"
#include "lighting/transfer_bake.h"
#include "render/frame_sequence_job.h"
#include "render/scenario_picture.h"
#include "render/shading.h"
#include "run_job.h"
#include "scenario/open_scenario.h"
#include "scenario/scenario_io.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace render = core::render;

namespace {

render::PictureSettings pictureSettings(const core::scenario::Scenario& document, int width, int height,
                                        const std::string& shading,
                                        const std::optional<core::lighting::TransferBake>& bake,
                                        const std::optional<std::string>& character, int samples, bool ground,
                                        double azimuth, double elevation)
{
    render::PictureSettings settings;
    settings.width = width;
    settings.height = height;
    settings.shading = unwrap(render::parseShading(shading));
    settings.samples = samples;
    settings.ground = ground;
    settings.azimuth = azimuth;
    settings.elevation = elevation;
    if (bake) {
        std::string name;
        if (character)
            name = *character;
        else if (document.characters.size() == 1)
            name = document.characters.front().name;
        else
            throw py::value_error("The scenario has several characters: say which one the bake is for (character=…).");
        settings.bakes[name] = std::make_shared<const core::lighting::TransferBake>(*bake);
    }
    return settings;
}

} // namespace

void bindRender(py::module_& m)
{
    py::module_ r = m.def_submodule("render", "Headless pictures of scenarios: PRT, Phong or unlit (OpenSceneGraph, EGL).");
    r.def(
        "render_scenario",
        [](const std::filesystem::path& path, double time, int width, int height, const std::string& shading,
           const std::optional<core::lighting::TransferBake>& bake, const std::optional<std::string>& character,
           int samples, bool ground, double azimuth, double elevation) {
            auto opened = unwrap(core::scenario::openScenario(path));
            const render::PictureSettings settings = pictureSettings(opened.scenario, width, height, shading, bake, character,
                                                                     samples, ground, azimuth, elevation);
            render::RgbaImage image;
            {
                py::gil_scoped_release unlocked;
                auto picture = unwrap(render::ScenarioPicture::create(opened.scenario, opened.assets, settings));
                picture->scene().playAt(core::secondsToTicks(time));
                image = *unwrap(picture->draw());
            }
            return toArray<std::uint8_t>(image.rgba, {image.height, image.width, 4});
        },
        "path"_a, "time"_a = 0.0, "width"_a = 1280, "height"_a = 720, "shading"_a = "prt", "bake"_a = py::none(),
        "character"_a = py::none(), "samples"_a = 4, "ground"_a = true, "azimuth"_a = 20.0, "elevation"_a = 8.0,
        "Renders a scenario (.thespis) or a package (.thespkg) at `time` seconds into a height × width × 4 uint8 array (rows from the top). "
        "shading: 'prt', 'phong' or 'unlit'; bake: a thespis.lighting.TransferBake of `character`'s body "
        "(thespis-cli bake SCENARIO --character NAME). Raises OSError when no OpenGL context can be made.");
    r.def(
        "render_frames",
        [](const std::filesystem::path& path, const std::filesystem::path& folder, long first, long last, double fps,
           int width, int height, const std::string& shading, const std::optional<core::lighting::TransferBake>& bake,
           const std::optional<std::string>& character, int samples, bool ground, double azimuth, double elevation,
           const py::object& progress) {
            render::FrameSequenceJob job;
            auto opened = unwrap(core::scenario::openScenario(path));
            job.scenario = std::move(opened.scenario);
            job.picture = pictureSettings(job.scenario, width, height, shading, bake, character, samples, ground,
                                          azimuth, elevation);
            job.assets = std::move(opened.assets);
            job.first = first;
            job.last = last;
            job.fps = fps;
            job.folder = folder;
            runJob(job, progress);
            return job.warnings;
        },
        "path"_a, "folder"_a, "first"_a, "last"_a, py::kw_only(), "fps"_a = 30.0, "width"_a = 1280, "height"_a = 720,
        "shading"_a = "prt", "bake"_a = py::none(), "character"_a = py::none(), "samples"_a = 4, "ground"_a = true,
        "azimuth"_a = 20.0, "elevation"_a = 8.0, "progress"_a = py::none(),
        "Renders frames first … last of a scenario (.thespis) or a package (.thespkg) at `fps` into folder/frame_NNNNN.png, as "
        "`thespis-cli render --frames` does (the same job); returns the scene's warnings. Releases the GIL; "
        "progress(done, total) is called on this thread; Ctrl-C (or an exception in progress) stops it and the "
        "frames written are taken back.");
    r.def(
        "write_png",
        [](const std::filesystem::path& path, const py::array_t<std::uint8_t, py::array::c_style | py::array::forcecast>& image) {
            if (image.ndim() != 3 || image.shape(2) != 4)
                throw py::value_error("The image must be a height × width × 4 (RGBA) uint8 array.");
            render::RgbaImage picture;
            picture.height = int(image.shape(0));
            picture.width = int(image.shape(1));
            picture.rgba.assign(image.data(), image.data() + image.size());
            unwrap(render::writePng(path, picture));
        },
        "path"_a, "image"_a, "Writes an RGBA image as PNG (atomically).");
}

} // namespace thespis::python
