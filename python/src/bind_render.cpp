// Bindings of core/render as the submodule thespis.render: a scenario rendered headless (EGL on
// Mesa, no X server), as `thespis-cli render` does, into a NumPy RGBA image, and PNG output.

#include <optional>
#include <string>

#include "bind_common.h"
#include "errors.h"
#include "lighting/transfer_bake.h"
#include "render/offscreen_renderer.h"
#include "render/scenario_scene.h"
#include "render/shading.h"
#include "scenario/scenario_io.h"

namespace thespis::python {

using namespace pybind11::literals;
namespace render = core::render;

void bindRender(py::module_& m)
{
    py::module_ r = m.def_submodule("render", "Headless pictures of scenarios: PRT, Phong or unlit (OpenSceneGraph, EGL).");
    r.def(
        "render_scenario",
        [](const std::filesystem::path& path, double time, int width, int height, const std::string& shading,
           const std::optional<core::lighting::TransferBake>& bake, const std::optional<std::string>& character,
           int samples, bool ground, double azimuth, double elevation) {
            const render::Shading mode = unwrap(render::parseShading(shading));
            auto document = unwrap(core::scenario::loadScenario(path));
            render::ScenarioSceneOptions options;
            if (bake) {
                std::string name;
                if (character)
                    name = *character;
                else if (document.characters.size() == 1)
                    name = document.characters.front().name;
                else
                    throw py::value_error("The scenario has several characters: say which one the bake is for (character=…).");
                options.bakes[name] = std::make_shared<const core::lighting::TransferBake>(*bake);
            }
            render::RgbaImage image;
            {
                py::gil_scoped_release unlocked;
                const std::filesystem::path baseDir = path.parent_path().empty() ? "." : path.parent_path();
                auto scene = unwrap(render::ScenarioScene::create(document, baseDir, options));
                scene->scene().setShading(mode);
                scene->scene().setGroundVisible(ground);
                auto renderer = unwrap(render::OffscreenRenderer::create(width, height, samples));
                const render::CameraView view = render::frameBounds(scene->boundsOverTimeline(), azimuth, elevation,
                                                                    double(width) / height);
                scene->setTime(time);
                unwrap(renderer->render(scene->scene(), view, image));
            }
            return toArray<std::uint8_t>(image.rgba, {image.height, image.width, 4});
        },
        "path"_a, "time"_a = 0.0, "width"_a = 1280, "height"_a = 720, "shading"_a = "prt", "bake"_a = py::none(),
        "character"_a = py::none(), "samples"_a = 4, "ground"_a = true, "azimuth"_a = 20.0, "elevation"_a = 8.0,
        "Renders a .thespis scenario at `time` seconds into a height × width × 4 uint8 array (rows from the top). "
        "shading: 'prt', 'phong' or 'unlit'; bake: a thespis.lighting.TransferBake of `character`'s body "
        "(thespis-cli bake SCENARIO --character NAME). Raises OSError when no OpenGL context can be made.");
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
