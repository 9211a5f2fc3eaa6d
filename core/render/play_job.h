#pragma once
// A scenario played to a video file as a job (util/job.h): over the frames of a tracked video —
// each frame tracked, the scenario drawn over it where the target is (ArCompositor), on the
// video's clock — or, without a video, on its own over the timeline (ScenarioPicture). The
// video is written atomically: a stopped or failed job leaves no file. `thespis-cli play` and
// Python run it.

#include <filesystem>
#include <string>
#include <vector>

#include "ar/tracking_session.h"
#include "ar/tracking_target.h"
#include "render/ar_compositor.h"
#include "render/scenario_picture.h"
#include "util/job.h"

namespace thespis::core::render {

struct PlayJob final : Job {
    static constexpr const char* PreparingStage = "Preparing the scene";
    static constexpr const char* FramesStage = "Playing";

    scenario::Scenario scenario;
    scenario::Assets assets{"."};
    std::filesystem::path output;      ///< .mp4 or .avi

    // Over video (when `video` is set):
    std::filesystem::path video;
    std::filesystem::path cameraFile;
    ar::TrackingTarget target;
    ArCompositorSettings compositor;

    // On its own:
    PictureSettings picture;           ///< size and look of the picture
    double fps = 30;

    // After run():
    std::int64_t frames = 0, tracked = 0;
    std::vector<std::string> warnings;

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;

private:
    Result<void> overVideo(JobContext& context);
    Result<void> onItsOwn(JobContext& context);
};

} // namespace thespis::core::render
