"""Blending schedules: blend results checked with NumPy, masks over real motion capture,
cut-off, nesting, editing while playing, caching."""

import math

import numpy as np
import pytest

import thespis
from thespis import BlendingAction, BlendingParams, BlendingSchedule, BlendMode, Curve, FrameLayout, JointMask, KeyframeClip
from conftest import mocap


def rot_z(angle):
    return np.array([0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)], np.float32)


def normalized(q):
    q = np.asarray(q, np.float64)
    return q / np.linalg.norm(q)


def assert_same_rotation(a, b, atol=1e-6):
    a, b = np.asarray(a, np.float64), np.asarray(b, np.float64)
    if np.dot(a, b) < 0:
        b = -b
    np.testing.assert_allclose(a, b, atol=atol)


def rotations(frame, count):
    return np.asarray(frame[: 4 * count]).reshape(count, 4)


@pytest.fixture
def layout():
    return FrameLayout(["root"], ["root"])


def constant_clip(layout, angle, translation=(0.0, 0.0, 0.0), seconds=2.0, name=""):
    frame = np.concatenate([rot_z(angle), np.asarray(translation, np.float32)])
    return KeyframeClip(layout, 10.0, np.tile(frame, (int(seconds * 10) + 1, 1)), name)


def test_two_actions_blend_normalized_by_weight(layout):
    schedule = BlendingSchedule(layout)
    a = constant_clip(layout, 0.0, (0.0, 0.0, 0.0))
    b = constant_clip(layout, 1.0, (4.0, 0.0, 0.0))
    schedule.add_action(a)
    schedule.add_action(b, weight=Curve.constant(3.0))
    frame = schedule.evaluate(1.0)
    assert frame.dtype == np.float32 and frame.shape == (7,)
    # Σw = 4 ≥ 1: x = Σ wᵢxᵢ / Σw; rotations are normalized after the weighted sum.
    assert_same_rotation(frame[:4], normalized(rot_z(0.0) + 3 * rot_z(1.0)))
    np.testing.assert_allclose(frame[4:], [3.0, 0.0, 0.0], atol=1e-6)


def test_weights_below_one_are_filled_with_the_rest_pose(layout):
    rest = np.array([*rot_z(-0.5), 1.0, 1.0, 1.0], np.float32)
    schedule = BlendingSchedule(layout, rest)
    schedule.add_action(constant_clip(layout, 1.0, (3.0, 1.0, 1.0)), weight=Curve.constant(0.25))
    frame = schedule.evaluate(0.5)
    assert_same_rotation(frame[:4], normalized(0.25 * rot_z(1.0) + 0.75 * rot_z(-0.5)))
    np.testing.assert_allclose(frame[4:], [1.5, 1.0, 1.0], atol=1e-6)
    np.testing.assert_array_equal(schedule.rest_pose, rest)
    # Before the action starts nothing drives the joint: the rest pose.
    late = BlendingSchedule(layout, rest)
    late.add_action(constant_clip(layout, 1.0), start=5.0)
    np.testing.assert_allclose(late.evaluate(1.0), rest, atol=1e-7)


def test_weight_curve_follows_the_action_time(layout):
    schedule = BlendingSchedule(layout)
    schedule.add_action(constant_clip(layout, 0.0, (0.0, 0.0, 0.0), seconds=4.0))
    schedule.add_action(constant_clip(layout, 0.0, (2.0, 0.0, 0.0), seconds=2.0), start=1.0,
                        weight=Curve.linear_fade(1.0, 1.0))
    times = np.array([0.5, 1.0, 1.5, 2.0, 2.5, 3.0])
    x = schedule.sample(times)[:, 4]
    w = np.array([0.0, 0.0, 0.5, 1.0, 0.5, 0.0])
    np.testing.assert_allclose(x, 2.0 * w / (1.0 + w), atol=1e-6)


def test_sample_returns_one_row_per_time(layout):
    schedule = BlendingSchedule(layout)
    schedule.add_action(constant_clip(layout, 0.3))
    frames = schedule.sample(np.linspace(0.0, 2.0, 9))
    assert frames.shape == (9, 7) and frames.dtype == np.float32
    with pytest.raises(ValueError, match="1-D"):
        schedule.sample(np.zeros((2, 2)))


def test_cut_off_fades_out_over_exactly_the_given_time(layout):
    schedule = BlendingSchedule(layout)
    action = schedule.add_action(constant_clip(layout, 0.0, (2.0, 0.0, 0.0)), render_outside_domain=True)
    assert schedule.cut_off_action(action, 3.0, 0.5)
    x = lambda t: schedule.evaluate(t)[4]
    assert x(2.99) == pytest.approx(2.0)
    assert 0.0 < x(3.25) < 2.0
    assert x(3.5) == pytest.approx(0.0, abs=1e-6)
    assert not schedule.is_finished(action, 3.49)
    assert schedule.is_finished(action, 3.5)
    assert schedule.end_time(action) == pytest.approx(3.5)
    assert not schedule.cut_off_action(12345, 0.0, 1.0)


def test_actions_can_be_added_and_removed_while_playing(layout):
    schedule = BlendingSchedule(layout)
    first = schedule.add_action(constant_clip(layout, 0.0, (1.0, 0.0, 0.0)), name="idle", render_outside_domain=True)
    assert schedule.evaluate(0.5)[4] == pytest.approx(1.0)
    revision = schedule.revision
    second = schedule.add_action(BlendingAction(constant_clip(layout, 0.0, (3.0, 0.0, 0.0)), BlendingParams(), 0.0, "wave"))
    assert schedule.revision != revision
    assert len(schedule) == 2 and schedule.action_ids == [first, second]
    assert schedule.evaluate(0.5)[4] == pytest.approx(2.0)
    assert schedule.find_action("wave") == second and schedule.find_action("nope") is None
    assert schedule.action(second).name == "wave" and schedule.action(999) is None
    assert schedule.remove_action(second) and not schedule.remove_action(second)
    assert schedule.evaluate(0.5)[4] == pytest.approx(1.0)
    assert schedule.is_finished(second, 0.0)  # gone
    assert math.isnan(schedule.end_time(second))
    schedule.set_action_start(first, 1.0)
    assert schedule.action(first).start == 1.0
    assert schedule.remove_finished_actions(100.0) == 0  # renders outside its domain: never finished
    schedule.clear()
    assert schedule.action_count == 0


def test_nested_schedule_equals_the_flattened_one(layout):
    a = constant_clip(layout, 0.2, (1.0, 0.0, 0.0), seconds=3.0)
    b = constant_clip(layout, 1.2, (0.0, 2.0, 0.0), seconds=1.0)
    flat = BlendingSchedule(layout)
    flat.add_action(a)
    flat.add_action(b, start=1.0, weight=Curve.cubic_fade(0.3, 0.3))
    inner = BlendingSchedule(layout)
    inner.add_action(a)
    inner.add_action(b, start=1.0, weight=Curve.cubic_fade(0.3, 0.3))
    outer = BlendingSchedule(layout)
    outer.add_action(inner)
    times = np.linspace(0.0, 3.0, 61)
    np.testing.assert_allclose(outer.sample(times), flat.sample(times), atol=1e-6)


def test_schedule_errors_are_value_errors(layout):
    schedule = BlendingSchedule(layout)
    other = FrameLayout(["knee"])
    with pytest.raises(ValueError, match="layout"):
        schedule.add_action(KeyframeClip(other, 30.0, other.neutral_frame()[None, :]))
    with pytest.raises(ValueError, match="nothing to play"):
        schedule.add_action(BlendingAction())
    with pytest.raises(ValueError, match="sustain"):
        schedule.add_action(constant_clip(layout, 0.0), weight=Curve.linear_adsr(0.1, 0.1, 2.0, 0.1))
    with pytest.raises(ValueError, match="rest"):
        BlendingSchedule(layout, np.zeros(3, np.float32))
    with pytest.raises(TypeError):
        schedule.add_action(None)


@pytest.fixture(scope="module")
def walk_and_wave():
    walk = thespis.bvh.load(mocap("cmu/02_01.bvh"))
    wave = thespis.bvh.load(mocap("cmu/141_16.bvh"))
    assert walk.skeleton.frame_layout == wave.skeleton.frame_layout
    return walk, wave


def test_wave_over_walk_under_an_upper_body_mask(walk_and_wave):
    walk, wave = walk_and_wave
    skeleton = walk.skeleton
    mask = JointMask.preset(thespis.MaskPreset.upper_body)
    schedule = BlendingSchedule(skeleton)
    schedule.add_action(walk.clip)
    schedule.add_action(wave.clip, mask=mask, mode=BlendMode.override)
    weights = mask.resolve(skeleton.frame_layout, skeleton.parents)
    n = skeleton.joint_count
    lower = [i for i in range(n) if weights[i] == 0.0]
    upper = [i for i in range(n) if weights[i] == 1.0]
    assert skeleton.find("l_knee") in lower and skeleton.find("r_elbow") in upper
    for t in np.linspace(0.0, 2.4, 13):
        got = rotations(schedule.evaluate(t), n)
        lower_expected = rotations(walk.clip.evaluate(t), n)
        upper_expected = rotations(wave.clip.evaluate(t), n)
        for j in lower:
            assert_same_rotation(got[j], lower_expected[j], 1e-6)
        for j in upper:
            assert_same_rotation(got[j], upper_expected[j], 1e-6)
        # The root translation belongs to the root joint (weight 0): the walk's.
        root_t = skeleton.translation_element(0)
        offset = skeleton.frame_layout.float_offset(root_t)
        np.testing.assert_allclose(schedule.evaluate(t)[offset:offset + 3], walk.clip.evaluate(t)[offset:offset + 3],
                                   atol=1e-5)


def test_cross_fade_has_no_pops(walk_and_wave):
    """During a cross-fade no joint turns faster than the faster input plus a small tolerance."""
    walk, wave = walk_and_wave
    n = walk.skeleton.joint_count
    schedule = BlendingSchedule(walk.skeleton)
    schedule.add_action(walk.clip, weight=Curve.cubic_fade(0.0, 1.0))
    schedule.add_action(wave.clip, start=1.5, weight=Curve.cubic_fade(1.0, 0.0))
    dt = 1.0 / 120.0
    times = np.arange(1.5, 2.5, dt)

    def quats(frames):
        return frames[:, : 4 * n].reshape(len(frames), n, 4).astype(np.float64)

    def angle(a, b):
        return 2 * np.arccos(np.abs(np.sum(a * b, axis=-1)).clip(0, 1))

    def angular_speed(frames):
        q = quats(frames)
        return angle(q[1:], q[:-1]) / dt

    walk_frames, wave_frames = walk.clip.sample(times), wave.clip.sample(times - 1.5)
    blended = angular_speed(schedule.sample(times))
    fastest_input = np.maximum(angular_speed(walk_frames), angular_speed(wave_frames))
    # Moving the weights also turns a joint, along the arc between the two inputs: at most
    # |dw/dt| (1.5/s for a 1 s cubic fade) times that arc's angle, twice over for the
    # normalized (nlerp) parametrisation. A pop would be a jump of a whole arc in one frame.
    between = angle(quats(walk_frames), quats(wave_frames))
    allowed = fastest_input + 2 * 1.5 * np.maximum(between[1:], between[:-1]) + 0.05
    assert np.all(blended <= allowed), np.max(blended - allowed)


def test_cache_returns_identical_frames_and_is_invalidated_by_edits(layout):
    schedule = BlendingSchedule(layout)
    schedule.add_action(constant_clip(layout, 0.4, (1.0, 0.0, 0.0)))
    cache = thespis.CachedBlendable(schedule, capacity=16)
    first = cache.evaluate(0.5)
    again = cache.evaluate(0.5)
    np.testing.assert_array_equal(first, again)
    assert cache.hits == 1 and cache.misses == 1 and cache.size == 1 and cache.capacity == 16
    schedule.add_action(constant_clip(layout, 0.4, (3.0, 0.0, 0.0)))
    edited = cache.evaluate(0.5)
    np.testing.assert_array_equal(edited, schedule.evaluate(0.5))
    assert edited[4] == pytest.approx(2.0)
    assert cache.misses == 2


def test_blenders_are_pluggable(layout):
    schedule = BlendingSchedule(layout)
    schedule.add_action(constant_clip(layout, 0.0))
    schedule.add_action(constant_clip(layout, 1.0))
    schedule.set_blender(thespis.LinearBlender())
    linear = schedule.evaluate(0.5)[:4]
    np.testing.assert_allclose(linear, (rot_z(0.0) + rot_z(1.0)) / 2, atol=1e-6)  # not normalized
    schedule.set_blender(thespis.QuaternionBlender())
    assert np.linalg.norm(schedule.evaluate(0.5)[:4]) == pytest.approx(1.0)
