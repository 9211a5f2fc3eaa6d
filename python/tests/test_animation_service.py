"""The paper's scripting style (§4.5): activate, cut off and wait for actions over a clock."""

import math

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
    schedule = anim.body_schedule("Creon")
    np.testing.assert_allclose(anim.evaluate_body("Creon"), schedule.rest_pose, atol=1e-6)


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
