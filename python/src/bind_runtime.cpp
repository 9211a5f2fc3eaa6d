// thespis.runtime: clocks, the Stage and the paper's animation service (§4.5). The service keeps
// the paper's method names (activateAction_body, waitUntilActionFinished_body, …) with Pythonic
// aliases (activate_action_body, …). Waits release the GIL and look at Ctrl-C every 50 ms; a
// stopped service (request_stop, the studio's Stop) raises thespis.Cancelled in them.

#include "bind_common.h"
#include "errors.h"

#include <chrono>
#include <cmath>
#include <optional>

#include "runtime/animation_service.h"
#include "runtime/clock.h"
#include "motion/eye_ray.h"
#include "motion/gaze_target.h"
#include "runtime/sound.h"
#include "runtime/voice_service.h"
#include "runtime/stage.h"

namespace thespis::python {

using namespace pybind11::literals;
using core::secondsToTicks;
using core::ticksToSeconds;
using namespace core::runtime;

namespace {

constexpr std::chrono::milliseconds kSignalCheck{50};

/// Waits until the service's clock reaches `t`, letting other Python threads run and raising
/// KeyboardInterrupt on Ctrl-C.
void waitUntil(AnimationService& service, core::Tick t)
{
    while (true) {
        core::Result<bool> reached = false;
        {
            py::gil_scoped_release release;
            reached = service.waitUntil(t, kSignalCheck);
        }
        if (unwrap(std::move(reached)))
            return;
        if (PyErr_CheckSignals() != 0)
            throw py::error_already_set();
    }
}

std::shared_ptr<AnimationService> makeService(std::shared_ptr<Stage> stage, std::shared_ptr<Clock> clock)
{
    if (!stage)
        stage = std::make_shared<Stage>();
    if (!clock)
        clock = std::make_shared<ManualClock>();
    return std::make_shared<AnimationService>(std::move(stage), std::move(clock));
}

py::object gazeStateObject(const std::optional<core::motion::GazeState>& state)
{
    if (!state)
        return py::none();
    py::dict d;
    const char* parts[] = {"back", "chest", "neck"};
    for (std::size_t p = 0; p < 3; ++p)
        d[parts[p]] = py::make_tuple(state->heading[p], state->pitch[p]);
    d["eyes"] = py::make_tuple(state->eyeHeading, state->eyePitch);
    d["shifting"] = state->shifting;
    d["released"] = state->released;
    return d;
}

ActivateOptions activateOptions(std::optional<core::anim::Curve> weight, double fadeIn)
{
    ActivateOptions options;
    options.weight = std::move(weight);
    options.fadeIn = fadeIn;
    return options;
}

std::vector<float> evaluateOne(Stage& stage, const std::string& character, Track track, core::Tick t)
{
    const int index = stage.findCharacter(character);
    if (index < 0)
        unwrap(stage.actionNames(character, track)); // raises the KeyError naming the characters
    PoseSet poses = stage.makePoseSet();
    stage.evaluate(t, poses);
    CharacterPose& pose = poses.characters[std::size_t(index)];
    return std::move(track == Track::Body ? pose.body : pose.face);
}

/// Binds one track's methods under the paper's name (activateAction_body) and a Pythonic alias.
template <class Class>
void bindTrack(Class& c, Track track, const std::string& suffix)
{
    const auto twice = [&](const std::string& paper, const std::string& pythonic, auto&& f, auto... extra) {
        c.def((paper + suffix).c_str(), f, extra...);
        c.def((pythonic + suffix).c_str(), f, extra...);
    };
    twice(
        "activateAction_", "activate_action_",
        [track](AnimationService& s, const std::string& character, const std::string& action,
                std::optional<core::anim::Curve> weight, double fadeIn) {
            return unwrap(s.activateAction(character, track, action, activateOptions(std::move(weight), fadeIn)));
        },
        "character"_a, "action"_a, "weight"_a = py::none(), "fade_in"_a = 0.25,
        "Starts the named action now (optionally with another weight curve), fading in over `fade_in` seconds "
        "unless its curve already does; returns its id. KeyError names the known characters or actions.");
    twice(
        "cutOffAction_", "cut_off_action_",
        [track](AnimationService& s, const std::string& character, const std::string& action, double fade) {
            return unwrap(s.cutOffAction(character, track, action, fade));
        },
        "character"_a, "action"_a, "fade"_a = 0.5,
        "Fades the action out over `fade` seconds from now (the live one, else the authored one playing). "
        "False when it does not play.");
    twice(
        "waitUntilActionFinished_", "wait_until_action_finished_",
        [track](AnimationService& s, const std::string& character, const std::string& action, double offset) {
            const core::Tick t = unwrap(s.finishTime(character, track, action, offset));
            waitUntil(s, t);
            return ticksToSeconds(t);
        },
        "character"_a, "action"_a, "offset"_a = 0.0,
        "Waits until `offset` seconds after the action ends (negative: before its end, as the paper's "
        "scripts do); returns that time. ValueError for an action that never ends.");
    c.def(("remove_action_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action) {
              return unwrap(s.removeAction(character, track, action));
          },
          "character"_a, "action"_a, "Removes the live action at once; False when there is none.");
    c.def(("is_playing_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action) {
              return unwrap(s.isPlaying(character, track, action));
          },
          "character"_a, "action"_a);
    c.def(("is_action_finished_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action) {
              return !unwrap(s.isPlaying(character, track, action));
          },
          "character"_a, "action"_a, "True unless the action plays now.");
    c.def(("action_end_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action) {
              return unwrap(s.stage().actionEnd(character, track, action));
          },
          "character"_a, "action"_a, "When the action ends, in seconds (inf: never).");
    c.def(("time_until_finished_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action) {
              return unwrap(s.timeUntilFinished(character, track, action));
          },
          "character"_a, "action"_a);
    twice("initPlayerScope_", "init_player_scope_",
          [track](AnimationService& s, bool enabled) { s.initPlayerScope(track, enabled); }, "enabled"_a,
          "Plays this track or not (initPlayerScope_face(False): no facial animation).");
    c.def(("define_action_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, const std::string& action,
                  core::anim::BlendablePtr source, std::optional<core::anim::BlendingParams> params,
                  bool renderOutsideDomain) {
              unwrap(s.stage().defineAction(character, track, action,
                                            {std::move(source), params.value_or(core::anim::BlendingParams{}),
                                             renderOutsideDomain}));
          },
          "character"_a, "action"_a, "source"_a, "params"_a = py::none(), "render_outside_domain"_a = false,
          "Names an action the character can play: `source` blended with `params`.");
    c.def(("actions_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character) {
              return unwrap(s.stage().actionNames(character, track));
          },
          "character"_a);
    c.def(("evaluate_" + suffix).c_str(),
          [track](AnimationService& s, const std::string& character, std::optional<double> seconds) {
              const core::Tick t = seconds ? secondsToTicks(*seconds) : s.now();
              return toArray<float>(evaluateOne(s.stage(), character, track, t));
          },
          "character"_a, "seconds"_a = py::none(),
          "The character's frame at `seconds` (default: now), before placement (NumPy floats).");
}

} // namespace

// A gaze target from Python: "camera", "Antigone", "Antigone:l_radiocarpal", or three numbers.
core::motion::GazeTarget gazeTarget(const py::object& target)
{
    if (py::isinstance<py::str>(target))
        return unwrap(core::motion::parseGazeTarget(target.cast<std::string>()));
    const auto xyz = target.cast<std::vector<double>>();
    if (xyz.size() != 3)
        throw py::value_error("A gaze target point has three coordinates (x, y, z), not " + std::to_string(xyz.size()) + ".");
    return {core::motion::GazeTarget::Kind::Point, {xyz[0], xyz[1], xyz[2]}, {}, {}};
}


void bindRuntime(py::module_& m)
{
    py::module_ r = m.def_submodule("runtime", "The live runtime: clocks, the Stage and the animation service.");

    py::class_<Clock, std::shared_ptr<Clock>>(r, "Clock", "Where the runtime's time comes from.")
        .def("now", [](const Clock& c) { return ticksToSeconds(c.now()); }, "Seconds.")
        .def(
            "wait_until",
            [](Clock& c, double seconds) {
                const core::Tick t = secondsToTicks(seconds);
                while (true) {
                    bool reached = false;
                    {
                        py::gil_scoped_release release;
                        reached = c.waitUntil(t, {}, kSignalCheck);
                    }
                    if (reached)
                        return;
                    if (PyErr_CheckSignals() != 0)
                        throw py::error_already_set();
                }
            },
            "seconds"_a, "Waits until the clock reaches `seconds` (a ManualClock jumps there).");
    py::class_<ManualClock, Clock, std::shared_ptr<ManualClock>>(
        r, "ManualClock", "Simulated time: a wait jumps to the awaited time at once (batch work, tests).")
        .def(py::init([](double start) { return std::make_shared<ManualClock>(secondsToTicks(start)); }),
             "start"_a = 0.0)
        .def("set_time", [](ManualClock& c, double s) { c.setTime(secondsToTicks(s)); }, "seconds"_a)
        .def(
            "advance",
            [](ManualClock& c, double seconds) {
                if (!(seconds >= 0))
                    throw py::value_error("A clock cannot go back in time (advance by " + std::to_string(seconds) +
                                          " s).");
                c.advance(secondsToTicks(seconds));
                return ticksToSeconds(c.now());
            },
            "seconds"_a, "Moves forward; returns the new time.")
        .def(
            "set_jump_hook",
            [](ManualClock& c, py::object hook) {
                if (hook.is_none()) {
                    c.setJumpHook({});
                    return;
                }
                // Called by waits (GIL released) before each jump; False or an exception stops the wait.
                c.setJumpHook([hook = std::make_shared<py::object>(std::move(hook))](core::Tick from, core::Tick to) {
                    py::gil_scoped_acquire gil;
                    try {
                        const py::object keep = (*hook)(ticksToSeconds(from), ticksToSeconds(to));
                        return keep.is_none() || keep.cast<bool>();
                    } catch (py::error_already_set& error) {
                        error.discard_as_unraisable("thespis.ManualClock jump hook");
                        return false;
                    }
                });
            },
            "hook"_a,
            "hook(from_seconds, to_seconds) is called before each jump forward (e.g. to record or render what "
            "happens in between); returning False stops the wait. None removes it.");
    py::class_<RealTimeClock, Clock, std::shared_ptr<RealTimeClock>>(r, "RealTimeClock",
                                                                      "Wall-clock seconds since it was made.")
        .def(py::init([](double start) { return std::make_shared<RealTimeClock>(secondsToTicks(start)); }),
             "start"_a = 0.0);
    py::class_<ExternalClock, Clock, std::shared_ptr<ExternalClock>>(
        r, "ExternalClock", "Set from outside (video frames, audio, the studio's playhead); waits block until it gets there.")
        .def(py::init([](double start) { return std::make_shared<ExternalClock>(secondsToTicks(start)); }),
             "start"_a = 0.0)
        .def("set_time", [](ExternalClock& c, double s) { c.setTime(secondsToTicks(s)); }, "seconds"_a);

    py::class_<Stage, std::shared_ptr<Stage>>(r, "Stage",
                                              "Every character's authored schedules with live actions over them.")
        .def(py::init<>())
        .def(py::init([](const core::scenario::ScenarioRuntime& runtime) { return std::make_shared<Stage>(runtime); }),
             "runtime"_a, "A stage playing a built scenario (its schedules are shared with `runtime`).")
        .def_property_readonly("characters", &Stage::characterNames)
        .def("add_character",
             [](Stage& s, std::string name, const core::anim::Skeleton& skeleton) {
                 return unwrap(s.addCharacter(std::move(name), skeleton));
             },
             "name"_a, "skeleton"_a)
        .def("reset_live", &Stage::resetLive, "Removes every live action and restores authored ones cut off.")
        .def_property_readonly("ticks", &Stage::ticks, "How many times the stage was evaluated.");

    py::class_<AnimationService, std::shared_ptr<AnimationService>> service(
        r, "AnimationService",
        "The paper's animation service: actions activated, cut off and waited for at the clock's time.");
    service
        .def(py::init([](std::shared_ptr<Clock> clock, std::shared_ptr<Stage> stage) {
                 return makeService(std::move(stage), std::move(clock));
             }),
             "clock"_a = nullptr, "stage"_a = nullptr,
             "A service over `stage` (default: an empty one) at `clock`'s time (default: a ManualClock).")
        .def_static(
            "from_runtime",
            [](const core::scenario::ScenarioRuntime& runtime, std::shared_ptr<Clock> clock) {
                return makeService(std::make_shared<Stage>(runtime), std::move(clock));
            },
            "runtime"_a, "clock"_a = nullptr,
            "A service with every character of a built scenario: its clips and named actions are its actions.")
        .def_property_readonly("stage", &AnimationService::sharedStage)
        .def_property_readonly("clock", &AnimationService::sharedClock)
        .def("now", [](const AnimationService& s) { return ticksToSeconds(s.now()); })
        .def("characters", [](AnimationService& s) { return s.stage().characterNames(); })
        .def("add_character",
             [](AnimationService& s, std::string name, const core::anim::Skeleton& skeleton) {
                 return unwrap(s.stage().addCharacter(std::move(name), skeleton));
             },
             "name"_a, "skeleton"_a)
        .def(
            "wait",
            [](AnimationService& s, double seconds) {
                const core::Tick t = s.now() + secondsToTicks(std::max(seconds, 0.0));
                waitUntil(s, t);
                return ticksToSeconds(t);
            },
            "seconds"_a, "Waits a number of seconds; returns the time reached.")
        .def("start_player", &AnimationService::startPlayer,
             "Asks the host to play the stage: the studio's transport starts. A batch run (thespis-cli run, a plain "
             "python3 script) plays at every frame it evaluates, so there it changes nothing.")
        .def("stop_player", &AnimationService::stopPlayer,
             "Asks the host to pause: the studio's transport stops. Changes nothing in a batch run.")
        .def("request_stop", &AnimationService::requestStop,
             "Stops every wait of this service, now and later (raises thespis.Cancelled in them).");
    bindTrack(service, Track::Body, "body");
    bindTrack(service, Track::Face, "face");
    service
        .def(
            "gaze_body",
            [](AnimationService& s, const std::string& character, const py::object& target, const std::string& influence,
               double offsetAngle, const std::string& offsetDirection, bool saccades, bool talking, std::uint64_t seed) {
                core::motion::GazeSettings settings;
                settings.influence = unwrap(core::motion::parseGazeInfluence(influence));
                unwrap(core::motion::setGazeOffset(settings, offsetAngle, offsetDirection));
                settings.saccades = saccades;
                settings.talking = talking;
                settings.seed = seed;
                unwrap(s.gaze(character, gazeTarget(target), settings));
            },
            "character"_a, "target"_a, "influence"_a = "SHOULDER", "offset_angle"_a = 0.0, "offset_direction"_a = "",
            "saccades"_a = true, "talking"_a = false, "seed"_a = 1,
            "Turns the character's eyes, head and body toward `target` from now, over everything else it plays: "
            "\"camera\", a character (\"Antigone\": between her eyes; \"Antigone:l_radiocarpal\": her left wrist) "
            "or a point (x, y, z). influence is BML's: EYES, HEAD, SHOULDER or WAIST. Fixating, the eyes make Eyes "
            "Alive's saccades (talking: more often away).")
        .def("stopGaze", [](AnimationService& s, const std::string& character) { return unwrap(s.stopGaze(character)); },
             "character"_a, "Lets go of the gaze: the body turns back to its pose. False when no gaze was on.")
        .def("stop_gaze", [](AnimationService& s, const std::string& character) { return unwrap(s.stopGaze(character)); },
             "character"_a, "Alias of stopGaze.")
        .def(
            "gaze_state",
            [](AnimationService& s, const std::string& character) {
                return gazeStateObject(unwrap(s.stage().gazeState(character)));
            },
            "character"_a,
            "What the gaze does (degrees): (heading, pitch) of back, chest, neck and eyes, heading + left, pitch + "
            "down; None when no gaze is on.")
        .def(
            "eye_ray",
            [](AnimationService& s, const std::string& character, double seconds) {
                const core::anim::Skeleton skeleton = unwrap(s.stage().skeleton(character));
                const auto rig = unwrap(core::motion::GazeRig::create(skeleton));
                PoseSet poses = s.stage().makePoseSet();
                s.stage().evaluate(secondsToTicks(seconds), poses);
                const CharacterPose& pose = poses.characters[std::size_t(s.stage().findCharacter(character))];
                const auto ray = core::motion::placed(core::motion::eyeRay(rig, skeleton, pose.body, pose.face),
                                                      pose.placement);
                return py::make_tuple(py::make_tuple(ray.origin.x, ray.origin.y, ray.origin.z),
                                      py::make_tuple(ray.direction.x, ray.direction.y, ray.direction.z));
            },
            "character"_a, "seconds"_a,
            "Where the character looks at `seconds` in the scene (metres): ((x, y, z) between its eyes, unit (x, y, z) "
            "of its line of sight) — its head turned by its eyes, as a viewer sees it.")
        .def(
            "set_camera_position",
            [](AnimationService& s, std::optional<std::vector<double>> xyz) {
                if (xyz && xyz->size() != 3)
                    throw py::value_error("The camera position has three coordinates.");
                s.stage().setCameraPosition(xyz ? std::optional<core::anim::Vec3d>({(*xyz)[0], (*xyz)[1], (*xyz)[2]})
                                                : std::nullopt);
            },
            "position"_a, "Where the camera is in the scene (metres), which gaze targets \"camera\" look at.");

    py::class_<SoundService, std::shared_ptr<SoundService>>(
        r, "SoundService",
        "The voice and sound service: sound files (WAV, OGG, FLAC; names relative to base_dir) started at the "
        "clock's time, in sync with the stage; mixed to a WAV headless.")
        .def(py::init([](const std::filesystem::path& baseDir, std::shared_ptr<Clock> clock, int mixRate) {
                 return std::make_shared<SoundService>(baseDir, clock ? clock : std::make_shared<ManualClock>(), mixRate);
             }),
             "base_dir"_a = std::filesystem::path("."), "clock"_a = nullptr, "mix_rate"_a = 48000)
        .def(
            "play",
            [](SoundService& s, const std::string& sound, double volume, const std::string& character) {
                return unwrap(s.play(sound, volume, character));
            },
            "sound"_a, "volume"_a = 1.0, "character"_a = "", "Starts the sound now; returns its activation id.")
        .def(
            "sndmpPlayMedia", [](SoundService& s, const std::string& sound, double volume) { return unwrap(s.play(sound, volume)); },
            "sound"_a, "volume"_a = 1.0, "The paper's sndService.sndmpPlayMedia(sound).")
        .def("sndmpStopMedia", &SoundService::stop, "sound"_a, "The paper's sndService.sndmpStopMedia(sound).")
        .def("stop", &SoundService::stop, "sound"_a, "Stops the sound now; False when it does not play.")
        .def("is_playing", &SoundService::isPlaying, "sound"_a)
        .def("length", [](SoundService& s, const std::string& sound) { return unwrap(s.length(sound)); }, "sound"_a,
             "Seconds.")
        .def_property_readonly("mix_rate", &SoundService::mixRate)
        .def(
            "mix",
            [](const SoundService& s, double start, double seconds) {
                std::vector<float> out(std::size_t(std::max(seconds, 0.0) * s.mixRate()));
                s.mix(secondsToTicks(start), out);
                return toArray<float>(out);
            },
            "start"_a, "seconds"_a, "What plays from `start` for `seconds`, mono at mix_rate (NumPy floats).")
        .def(
            "write_wav",
            [](const SoundService& s, const std::filesystem::path& path, double start, double end) {
                unwrap(s.writeWav(path, secondsToTicks(start), secondsToTicks(end)));
            },
            "path"_a, "start"_a, "end"_a, "Writes the mix of [start, end) as a 16-bit mono WAV.");

    py::class_<VoiceService, std::shared_ptr<VoiceService>>(
        r, "VoiceService",
        "The voice service of the paper's scripts: a character says one of its speech lines (audio, visemes and face "
        "gestures on the stage), or plays a sound file as its voice.")
        .def(py::init<std::shared_ptr<Stage>, std::shared_ptr<SoundService>>(), "stage"_a, "sound"_a)
        .def(
            "activateAction",
            [](VoiceService& v, const std::string& character, const std::string& speech, double volume) {
                return unwrap(v.activateAction(character, speech, volume));
            },
            "character"_a, "speech"_a, "volume"_a = 1.0,
            "The paper's voiceService.activateAction(character, speech, volume): the character's speech line of that "
            "name from now (its audio, or its text spoken by its voice; its visemes and face gestures on the stage), "
            "else the sound file of that name. Returns the sound's activation id.")
        .def("stop", &VoiceService::stop, "character"_a, "speech"_a, "Stops the line now; False when it does not play.")
        .def("is_playing", &VoiceService::isPlaying, "character"_a, "speech"_a)
        .def_property_readonly("warnings", &VoiceService::warnings,
                               "Problems of the last activation that did not stop it (a gesture it cannot play).")
        .def_property_readonly("sound", &VoiceService::sound, "The sound service it plays through.");
}

} // namespace thespis::python
