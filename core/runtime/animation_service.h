#pragma once
// AnimationService (paper §4.5): the scripting face of the runtime. It plays a Stage at its
// Clock's time: actions activated now, cut off now, and waits until an action has finished (or
// a number of seconds before that, as the paper's scripts do with a negative offset). The stage
// is played by its host, once per tick: the studio's Session, the CLI's render loop, or a
// Python caller's evaluate; the paper's start_player / stop_player ask that host to play or to
// pause (the studio's transport). A script is stopped through requestStop(): every wait in
// progress or to come returns Cancelled.

#include <functional>
#include <memory>
#include <stop_token>
#include <string>

#include "runtime/clock.h"
#include "runtime/stage.h"

namespace thespis::core::runtime {

class AnimationService {
public:
    AnimationService(std::shared_ptr<Stage> stage, std::shared_ptr<Clock> clock);

    Stage& stage() { return *m_stage; }
    const std::shared_ptr<Stage>& sharedStage() const { return m_stage; }
    Clock& clock() { return *m_clock; }
    const std::shared_ptr<Clock>& sharedClock() const { return m_clock; }
    Tick now() const { return m_clock->now(); }

    Result<anim::ActionId> activateAction(const std::string& character, Track track, const std::string& action,
                                          const ActivateOptions& options = {});
    Result<bool> cutOffAction(const std::string& character, Track track, const std::string& action,
                              double fadeSeconds);
    Result<bool> removeAction(const std::string& character, Track track, const std::string& action);
    Result<bool> isPlaying(const std::string& character, Track track, const std::string& action) const;
    /// Seconds until the action ends (0 when it has, ∞ when it never does).
    Result<double> timeUntilFinished(const std::string& character, Track track, const std::string& action) const;

    /// When to stop waiting for the action: `offsetSeconds` after its end (negative: before).
    /// Errors: an action never played, or one that never ends.
    Result<Tick> finishTime(const std::string& character, Track track, const std::string& action,
                            double offsetSeconds) const;
    /// Waits until that time; returns it. Cancelled when stopped.
    Result<Tick> waitUntilActionFinished(const std::string& character, Track track, const std::string& action,
                                         double offsetSeconds);
    /// Waits `seconds` from now.
    Result<Tick> wait(double seconds);
    /// Waits until the clock reaches `t`, `patience` at a time (false: not yet; call again).
    /// Cancelled when stopped.
    Result<bool> waitUntil(Tick t, Clock::Patience patience = Clock::Forever);

    /// Turns the character's eyes, head and body toward `target` from now (Stage::gaze).
    Result<void> gaze(const std::string& character, const GazeTarget& target, const motion::GazeSettings& settings)
    {
        return m_stage->gaze(character, target, settings, now());
    }
    /// Lets go of the gaze from now; false when none was on.
    Result<bool> stopGaze(const std::string& character) { return m_stage->stopGaze(character, now()); }

    /// initPlayerScope_face(False): the face track is not played.
    void initPlayerScope(Track track, bool enabled) { m_stage->setTrackEnabled(track, enabled); }
    /// What start_player / stop_player do: `control(true)` asks the host to play, false to
    /// pause. Hosts that always play (batch runs on a manual clock) set none, and then the two
    /// calls change nothing.
    void setPlayerControl(std::function<void(bool play)> control) { m_playerControl = std::move(control); }
    void startPlayer();
    void stopPlayer();

    /// Stops every wait, now and later (a script is being stopped).
    void requestStop() { m_stop.request_stop(); }
    bool stopRequested() const { return m_stop.stop_requested(); }

private:
    std::shared_ptr<Stage> m_stage;
    std::shared_ptr<Clock> m_clock;
    std::function<void(bool)> m_playerControl;
    std::stop_source m_stop;
};

} // namespace thespis::core::runtime
