"""The paper's animation service (§4.5, core/runtime bound as thespis.runtime): activate, cut off
and wait for actions over a clock, with the paper's method names and Pythonic aliases."""

import math
import threading
import time

import numpy as np
import pytest

import thespis
from thespis import AnimationService, ManualClock, RealTimeClock
from conftest import demo_scenario, mocap


@pytest.fixture
def service():
    walk = thespis.bvh.load(mocap("cmu/02_01.bvh"))
    wave = thespis.bvh.load(mocap("cmu/141_16.bvh"))
    anim = AnimationService(ManualClock())
    anim.add_character("Creon", walk.skeleton)
    anim.define_action_body("Creon", "walk", walk.clip)
    anim.define_action_body("Creon", "idle", thespis.Loop(walk.clip),
                            thespis.BlendingParams(weight=thespis.Curve.cubic_fade(0.5, 0.0)))
    anim.define_action_body("Creon", "wave", wave.clip,
                            thespis.BlendingParams(weight=thespis.Curve.cubic_fade(0.3, 0.3),
                                                   mask=thespis.JointMask.preset(thespis.MaskPreset.right_arm),
                                                   mode=thespis.BlendMode.override))
    return anim, walk, wave


def test_paper_script_timing(service):
    anim, walk, wave = service
    clock = anim.clock
    anim.activate_action_body("Creon", "idle")
    clock.advance(1.0)
    anim.activate_action_body("Creon", "wave")
    # waitUntilActionFinished_body(Creon, "wave", -1.0): one second before the wave ends.
    t = anim.wait_until_action_finished_body("Creon", "wave", -1.0)
    assert t == pytest.approx(1.0 + wave.clip.domain.duration - 1.0)
    assert not anim.is_action_finished_body("Creon", "wave")
    anim.wait_until_action_finished_body("Creon", "wave")
    assert anim.is_action_finished_body("Creon", "wave")
    # cutOffAction_body(Creon, "idle", 3.0): the idle fades out over exactly 3 s.
    cut_at = clock.now()
    assert anim.cut_off_action_body("Creon", "idle", 3.0)
    assert anim.action_end_body("Creon", "idle") == pytest.approx(cut_at + 3.0)
    end = anim.wait_until_action_finished_body("Creon", "idle")
    assert end == pytest.approx(cut_at + 3.0)
    assert anim.is_action_finished_body("Creon", "idle")
    np.testing.assert_allclose(anim.evaluate_body("Creon"), walk.skeleton.rest_frame(), atol=1e-6)


def test_activated_actions_play_from_the_clock_time(service):
    anim, walk, _ = service
    anim.clock.advance(2.0)
    anim.activate_action_body("Creon", "walk")
    np.testing.assert_allclose(anim.evaluate_body("Creon", 2.5), walk.clip.evaluate(0.5), atol=1e-6)
    # Weight override at activation.
    anim.activate_action_body("Creon", "walk", weight=thespis.Curve.constant(0.0))
    np.testing.assert_allclose(anim.evaluate_body("Creon", 2.5), walk.clip.evaluate(0.5), atol=1e-6)


def test_unknown_names_are_clear_key_errors(service):
    anim, _, _ = service
    with pytest.raises(KeyError, match="dance.*idle, walk, wave"):
        anim.activate_action_body("Creon", "dance")
    with pytest.raises(KeyError, match="Antigone"):
        anim.activate_action_body("Antigone", "walk")
    assert not anim.cut_off_action_body("Creon", "walk")


def test_waiting_for_an_open_ended_action_is_refused(service):
    anim, _, _ = service
    anim.activate_action_body("Creon", "idle")
    assert math.isinf(anim.action_end_body("Creon", "idle"))
    with pytest.raises(ValueError, match="never ends"):
        anim.wait_until_action_finished_body("Creon", "idle")


def test_manual_clock_never_goes_back():
    clock = ManualClock(5.0)
    clock.wait_until(3.0)
    assert clock.now() == 5.0
    with pytest.raises(ValueError):
        clock.advance(-1.0)


def test_real_time_clock_sleeps():
    clock = RealTimeClock()
    clock.wait_until(0.05)
    assert clock.now() >= 0.05


def test_service_from_the_demo_runtime():
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    anim = AnimationService.from_runtime(runtime)
    assert anim.characters() == [c.name for c in scenario.characters]
    first = scenario.characters[0]
    body_actions = [a.name for layer in first.layers if layer.kind == thespis.LayerKind.body for a in layer.actions]
    available = anim.actions_body(first.name)
    for name in body_actions + [clip.name for clip in first.clips if clip.joints]:
        assert name in available
    action = body_actions[0]
    anim.activate_action_body(first.name, action)
    frame = anim.evaluate_body(first.name, 0.5)
    assert frame.shape == (runtime.characters[0].skeleton.frame_layout.float_count,)
    assert np.all(np.isfinite(frame))


def demo_service(clock=None):
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    return AnimationService.from_runtime(runtime, clock), runtime


def test_the_papers_script_runs_as_written():
    """§4.5's Antigone/Creon script with the demo's action names, on a manual clock."""
    animService, runtime = demo_service()
    Antigone, Creon = "Antigone", "Creon"
    animService.initPlayerScope_face(False)
    animService.start_player()
    animService.activateAction_body(Antigone, "antigone_idle")
    animService.activateAction_body(Creon, "creon_wave")
    reached = animService.waitUntilActionFinished_body(Creon, "creon_wave", -1.0)
    wave_length = runtime.characters[0].clips["wave"].domain.duration
    assert reached == pytest.approx(wave_length - 1.0)
    animService.activateAction_body(Creon, "creon_nod")
    assert animService.cutOffAction_body(Antigone, "antigone_idle", 3.0)
    animService.activateAction_body(Antigone, "antigone_wave")
    end = animService.waitUntilActionFinished_body(Antigone, "antigone_wave", -1.0)
    animService.activateAction_body(Antigone, "antigone_idle")
    animService.stop_player()
    assert end > reached
    assert animService.is_playing_body(Antigone, "antigone_idle")
    # The face track is off: Creon's face stays neutral although he blinks at 0.5 s (his lids
    # half shut then), which a second service with the face track on shows.
    assert not np.any(animService.evaluate_face(Creon, 0.5))
    assert not np.any(animService.evaluate_face(Creon))
    blinking, _ = demo_service()
    assert np.any(blinking.evaluate_face(Creon, 0.5))


def test_unknown_characters_are_named_with_the_known_ones():
    anim, _ = demo_service()
    with pytest.raises(KeyError, match="Ismene.*Creon, Antigone"):
        anim.activateAction_body("Ismene", "creon_idle")
    assert isinstance(thespis.ErrorCode.not_found, thespis.ErrorCode)


def test_a_wait_on_an_external_clock_follows_the_driver_and_stops_on_request():
    clock = thespis.ExternalClock()
    anim, _ = demo_service(clock)
    anim.activate_action_body("Creon", "creon_wave")
    done = []
    waiter = threading.Thread(target=lambda: done.append(anim.wait_until_action_finished_body("Creon", "creon_wave")))
    waiter.start()
    time.sleep(0.05)
    assert not done
    clock.set_time(100.0)
    waiter.join(5)
    assert done and done[0] < 100.0
    failures = []

    def wait_for_ever():
        try:
            anim.wait(3600.0)
        except thespis.Cancelled as e:
            failures.append(e)

    stuck = threading.Thread(target=wait_for_ever)
    stuck.start()
    time.sleep(0.05)
    anim.request_stop()
    stuck.join(5)
    assert not stuck.is_alive() and failures


def test_a_live_action_fades_in_over_the_authored_motion():
    anim, runtime = demo_service()
    anim.clock.advance(2.5)
    before = anim.evaluate_body("Creon")
    anim.activate_action_body("Creon", "nod")
    np.testing.assert_allclose(anim.evaluate_body("Creon"), before, atol=1e-5)
    nod = runtime.characters[0].clips["nod"].evaluate(0.5)
    assert np.abs(anim.evaluate_body("Creon", 3.0) - nod).max() < 1e-4


def test_a_script_plays_the_gesticon_and_face_clips():
    """activateAction_body plays a gesture of the character's gesticon (its fades, body part and
    filter); activateAction_face plays a clip of FAP values; unknown names list what exists."""
    clock = thespis.ExternalClock()
    anim, _ = demo_service(clock)
    assert "greet" in anim.actions_body("Creon") and "blink" in anim.actions_face("Creon")
    before = anim.evaluate_body("Creon", 1.4)
    anim.activateAction_body("Creon", "greet")
    assert np.abs(anim.evaluate_body("Creon", 1.4) - before).max() > 0.05
    assert not np.any(anim.evaluate_face("Creon", 1.5))  # between the authored blinks
    clock.set_time(1.0)
    anim.activateAction_face("Creon", "blink")
    assert np.any(anim.evaluate_face("Creon", 1.5))  # the lids half shut, 0.5 s into the blink
    with pytest.raises(KeyError, match="greet"):
        anim.activateAction_body("Creon", "bow")
