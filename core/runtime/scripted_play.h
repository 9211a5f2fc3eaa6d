#pragma once
// A script playing along a headless render (the paper's §4.5 scripts): it runs on a manual
// clock from 0, and each of its waits first lets the renderer write every frame before the
// wait's end, so the frames show its live actions exactly as a player at those times would.
// `thespis-cli play` (a video, render::PlayJob) and `thespis-cli run` (numbered pictures) both
// play scripts through this one loop.

#include <functional>
#include <memory>
#include <stop_token>

#include "runtime/clock.h"
#include "runtime/sound.h"
#include "runtime/stage.h"
#include "scenario/asset_resolver.h"
#include "util/error.h"

namespace thespis::core::runtime {

/// What a script playing along is given: the stage, the manual clock it plays on, and the sound
/// service on that clock (voiceService).
struct ScriptHost {
    std::shared_ptr<Stage> stage;
    std::shared_ptr<ManualClock> clock;
    std::shared_ptr<SoundService> sound;
};

/// A script to run. Core knows no Python: the front end says how to run one to its end (in the
/// calling thread) and how to end it from elsewhere.
struct PlayScript {
    std::function<Result<void>(const ScriptHost&)> run;
    std::function<void()> stop;
};

/// Runs `script` on `stage` from time 0. Before the clock jumps to a time, `writeUntil(time)`
/// writes the frames before it; a failure there, or `stop`, ends the script. Returns the host as
/// the script left it (the clock at its end, the sounds it played), or the first failure: the
/// frames', Cancelled when stopped, else the script's.
Result<ScriptHost> playScript(const PlayScript& script, std::shared_ptr<Stage> stage, const scenario::Assets& assets,
                              const std::function<Result<void>(Tick until)>& writeUntil, std::stop_token stop);

} // namespace thespis::core::runtime
