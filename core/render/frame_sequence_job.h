#pragma once
// Rendering a numbered frame sequence of a scenario as a job (util/job.h): frames first … last
// at `fps` into folder/frame_NNNNN.png. `thespis-cli render --frames` and Python's
// thespis.render.render_frames run it. The picture (and its GL context) is made on the thread
// that runs the job. Each frame is written atomically; a stopped or failed sequence takes back
// the frames it wrote, so a cancelled job leaves no file.

#include <filesystem>
#include <string>
#include <vector>

#include "render/scenario_picture.h"
#include "util/job.h"

namespace thespis::core::render {

struct FrameSequenceJob final : Job {
    static constexpr const char* PreparingStage = "Preparing the scene";
    static constexpr const char* FramesStage = "Rendering frames";

    scenario::Scenario scenario;
    scenario::Assets assets{"."}; ///< where the scenario's files are
    PictureSettings picture;
    long first = 0, last = 0; ///< frame numbers, inclusive
    double fps = 30;
    std::filesystem::path folder; ///< created when missing

    std::vector<std::string> warnings; ///< after run(): the scene's (ScenarioScene::warnings)
    std::string glDescription;         ///< after run(): the OpenGL that drew

    std::string title() const override;
    /// 0 ≤ first ≤ last, fps > 0, a folder.
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;

private:
    std::vector<std::filesystem::path> m_written;
};

} // namespace thespis::core::render
