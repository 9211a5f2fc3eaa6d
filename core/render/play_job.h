#pragma once
// A scenario played to a video file as a job (util/job.h): over the frames of a tracked video —
// each frame tracked, the scenario drawn over it where the target is (ArCompositor), on the
// video's clock — or, without a video, on its own over the timeline (ScenarioPicture). A script
// may play along (the paper's §4.5 scripts): it runs on a manual clock, and each of its waits
// first writes the frames before the wait's end, so the video shows its live actions as a player
// would. The sounds it plays are mixed into a WAV beside the video. Outputs are written
// atomically: a stopped or failed job leaves no file. `thespis-cli play` runs it.

#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "ar/tracking_session.h"
#include "ar/tracking_target.h"
#include "render/ar_compositor.h"
#include "render/scenario_picture.h"
#include "runtime/scripted_play.h"
#include "util/job.h"

namespace thespis::core::render {

class PlayFrameWriter; // play_job.cpp's own

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

    /// Plays along when set. On its own the video lasts until the scenario's end or the script's,
    /// whichever is later; over a video, the scenario is no longer looped but follows the script.
    std::optional<runtime::PlayScript> script;
    /// A 16-bit mono WAV of what played (the characters' speech lines and the script's sounds) over
    /// the video's length; empty: none.
    std::filesystem::path audio;

    // After run():
    std::int64_t frames = 0, tracked = 0;
    double seconds = 0;                ///< the video's length
    std::size_t sounds = 0;            ///< sounds that played (speech lines, the script's)
    std::vector<std::string> warnings;

    std::string title() const override;
    Result<void> validate() const override;
    Result<void> run(JobContext& context) override;
    void discardOutput() override;

private:
    Result<void> overVideo(JobContext& context);
    Result<void> onItsOwn(JobContext& context);
    Result<void> play(JobContext& context, PlayFrameWriter& frames, const std::shared_ptr<runtime::Stage>& stage);
};

} // namespace thespis::core::render
