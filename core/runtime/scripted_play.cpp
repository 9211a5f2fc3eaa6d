#include "runtime/scripted_play.h"

namespace thespis::core::runtime {

Result<ScriptHost> playScript(const PlayScript& script, std::shared_ptr<Stage> stage, const scenario::Assets& assets,
                              const std::function<Result<void>(Tick until)>& writeUntil, std::stop_token stop)
{
    ScriptHost host{std::move(stage), std::make_shared<ManualClock>(), nullptr};
    host.sound = std::make_shared<SoundService>(assets, host.clock);
    Result<void> frames;
    host.clock->setJumpHook([&](Tick, Tick to) {
        if (stop.stop_requested())
            return false;
        frames = writeUntil(to);
        if (frames)
            return true;
        script.stop();
        return false;
    });
    Result<void> ran;
    {
        // A script that computes without waiting is ended too.
        std::stop_callback onStop(stop, [&] { script.stop(); });
        ran = script.run(host);
    }
    host.clock->setJumpHook({});
    if (!frames)
        return frames.error();
    if (stop.stop_requested())
        return makeError(ErrorCode::Cancelled, "stopped");
    if (!ran)
        return ran.error();
    return host;
}

} // namespace thespis::core::runtime
