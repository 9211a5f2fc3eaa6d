#include "runtime/animation_service.h"

#include <cmath>

namespace thespis::core::runtime {

AnimationService::AnimationService(std::shared_ptr<Stage> stage, std::shared_ptr<Clock> clock)
    : m_stage(std::move(stage)), m_clock(std::move(clock))
{
}

Result<anim::ActionId> AnimationService::activateAction(const std::string& character, Track track,
                                                        const std::string& action, const ActivateOptions& options)
{
    return m_stage->activateAction(character, track, action, now(), options);
}

Result<bool> AnimationService::cutOffAction(const std::string& character, Track track, const std::string& action,
                                            double fadeSeconds)
{
    return m_stage->cutOffAction(character, track, action, now(), fadeSeconds);
}

Result<bool> AnimationService::removeAction(const std::string& character, Track track, const std::string& action)
{
    return m_stage->removeAction(character, track, action);
}

Result<bool> AnimationService::isPlaying(const std::string& character, Track track, const std::string& action) const
{
    return m_stage->isPlaying(character, track, action, now());
}

Result<double> AnimationService::timeUntilFinished(const std::string& character, Track track,
                                                   const std::string& action) const
{
    return m_stage->timeUntilFinished(character, track, action, now());
}

Result<Tick> AnimationService::finishTime(const std::string& character, Track track, const std::string& action,
                                          double offsetSeconds) const
{
    auto end = m_stage->actionEnd(character, track, action);
    if (!end)
        return end.error();
    if (!std::isfinite(*end))
        return makeError(ErrorCode::InvalidArgument, "Action \"" + action + "\" of " + character +
                                                         " never ends (it loops or holds its last frame): "
                                                         "cut it off first, or wait a number of seconds.");
    // The first tick at or after that time, so that the action has really finished there.
    const double seconds = *end + offsetSeconds;
    Tick t = secondsToTicks(seconds);
    if (ticksToSeconds(t) < seconds)
        ++t;
    return t;
}

Result<Tick> AnimationService::waitUntilActionFinished(const std::string& character, Track track,
                                                       const std::string& action, double offsetSeconds)
{
    auto t = finishTime(character, track, action, offsetSeconds);
    if (!t)
        return t;
    if (auto reached = waitUntil(*t); !reached)
        return reached.error();
    return *t;
}

Result<Tick> AnimationService::wait(double seconds)
{
    const Tick t = now() + secondsToTicks(std::max(seconds, 0.0));
    if (auto reached = waitUntil(t); !reached)
        return reached.error();
    return t;
}

Result<bool> AnimationService::waitUntil(Tick t, Clock::Patience patience)
{
    if (m_clock->waitUntil(t, m_stop.get_token(), patience))
        return true;
    if (m_stop.stop_requested())
        return makeError(ErrorCode::Cancelled, "The script was stopped while it waited.");
    return m_clock->now() >= t;
}

void AnimationService::startPlayer()
{
    if (m_playerControl)
        m_playerControl(true);
}

void AnimationService::stopPlayer()
{
    if (m_playerControl)
        m_playerControl(false);
}

} // namespace thespis::core::runtime
