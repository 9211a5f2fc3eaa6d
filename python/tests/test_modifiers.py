"""Modifiers: time stretch / warp / offset, loop, mirror, global transform, trim and split."""

import math

import numpy as np
import pytest

import thespis
from thespis import Curve, CurveKey, FrameLayout, KeyframeClip, TangentMode
from conftest import mocap


def rot_z(angle):
    return [0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)]


@pytest.fixture
def ramp():
    """One rotation turning 0 → 1 rad and a root moving 0 → 1 along x over 1 s (11 keys)."""
    layout = FrameLayout(["root"], ["root"])
    frames = np.array([rot_z(t) + [t, 0.0, 0.0] for t in np.linspace(0.0, 1.0, 11)], np.float32)
    return KeyframeClip(layout, 10.0, frames, "ramp")


def x_at(blendable, t):
    return float(blendable.evaluate(t)[4])


@pytest.fixture(scope="module")
def walk():
    return thespis.bvh.load(mocap("cmu/02_01.bvh"))


def test_time_stretch(ramp):
    slow = thespis.TimeStretch(ramp, 2.0)
    assert slow.factor == 2.0 and slow.source is not None
    assert slow.domain.duration == pytest.approx(2.0)
    assert x_at(slow, 1.0) == pytest.approx(0.5, abs=1e-6)
    with pytest.raises(ValueError):
        thespis.TimeStretch(ramp, 0.0)


def test_time_warp_by_a_curve(ramp):
    # local time 0…2 s plays source time 0…1 s along a straight line: half speed.
    warp = Curve.keyframed([CurveKey(0.0, 0.0, TangentMode.linear), CurveKey(2.0, 1.0, TangentMode.linear)])
    warped = thespis.TimeWarp(ramp, warp, 2.0)
    assert warped.domain.duration == pytest.approx(2.0)
    assert x_at(warped, 1.0) == pytest.approx(0.5, abs=1e-6)
    assert warped.warp == warp


def test_time_offset(ramp):
    late = thespis.TimeOffset(ramp, 3.0)
    assert late.domain == thespis.TimeDomain(3.0, 4.0)
    assert x_at(late, 3.25) == pytest.approx(0.25, abs=1e-6)


def test_loop(ramp):
    twice = thespis.Loop(ramp, 2)
    assert twice.count == 2 and twice.domain.duration == pytest.approx(2.0)
    assert x_at(twice, 1.25) == pytest.approx(x_at(ramp, 0.25), abs=1e-5)
    forever = thespis.Loop(ramp)
    assert forever.domain.open_ended
    assert x_at(forever, 7.5) == pytest.approx(0.5, abs=1e-5)


def test_trim_and_split(ramp):
    middle = thespis.Trim(ramp, 0.25, 0.75)
    assert middle.domain == thespis.TimeDomain(0.25, 0.75)
    assert x_at(middle, 0.5) == pytest.approx(0.5, abs=1e-6)
    assert x_at(middle, 0.9) == pytest.approx(0.75, abs=1e-6)  # held at the end
    before, after = thespis.split(ramp, 0.4)
    assert before.domain == thespis.TimeDomain(0.0, 0.4)
    assert after.domain == thespis.TimeDomain(0.4, 1.0)
    assert x_at(after, 0.7) == pytest.approx(0.7, abs=1e-6)
    with pytest.raises(ValueError):
        thespis.split(ramp, 2.0)
    with pytest.raises(ValueError):
        thespis.Trim(ramp, 0.8, 0.2)


def test_global_transform(ramp):
    turn = rot_z(math.pi / 2)
    moved = thespis.GlobalTransform(ramp, rotation=turn, translation=(0.0, 0.0, 5.0))
    frame = moved.evaluate(1.0)
    # R·t + T with R a quarter turn about z: (1, 0, 0) → (0, 1, 0).
    np.testing.assert_allclose(frame[4:7], [0.0, 1.0, 5.0], atol=1e-6)
    np.testing.assert_allclose(frame[:4], rot_z(math.pi / 2 + 1.0), atol=1e-6)
    assert moved.translation == (0.0, 0.0, 5.0)


def test_mirror_twice_is_the_clip_on_real_motion(walk):
    clip = walk.clip
    twice = thespis.Mirror(thespis.Mirror(clip))
    times = np.linspace(0.0, clip.domain.end, 29)
    original, mirrored = clip.sample(times), twice.sample(times)
    n = walk.skeleton.joint_count
    q0 = original[:, : 4 * n].reshape(-1, n, 4)
    q2 = mirrored[:, : 4 * n].reshape(-1, n, 4)
    same_sign = np.sign(np.sum(q0 * q2, axis=2))[..., None]
    np.testing.assert_allclose(q2 * same_sign, q0, atol=1e-6)
    np.testing.assert_allclose(mirrored[:, 4 * n:], original[:, 4 * n:], atol=1e-5)


def test_mirror_swaps_left_and_right():
    # On the symmetric H-Anim skeleton, a pose and its mirror image are reflections of each
    # other across the sagittal plane (x = 0): every joint lands where its mirror joint was.
    skeleton = thespis.hanim.skeleton(thespis.hanim.Level.loa1)
    rng = np.random.default_rng(7)
    frames = np.tile(skeleton.rest_frame(), (2, 1))
    for name in ("l_shoulder", "l_elbow", "r_hip", "sacroiliac", "vl5"):
        j = skeleton.find(name)
        frames[1, 4 * j:4 * j + 4] = rng.normal(size=4)
    root = skeleton.frame_layout.float_offset(skeleton.translation_element(0))
    frames[1, root:root + 3] += [0.3, 0.1, -0.2]
    clip = KeyframeClip(skeleton.frame_layout, 1.0, frames)
    p = skeleton.world_positions(clip.frame(1))
    m = skeleton.world_positions(thespis.Mirror(clip).evaluate(1.0))
    for j, name in enumerate(skeleton.joint_names):
        mirror_joint = skeleton.find(thespis.hanim.mirror_name(name))
        np.testing.assert_allclose(m[mirror_joint], p[j] * [-1, 1, 1], atol=1e-5, err_msg=name)


def test_modifiers_refuse_no_source(ramp):
    with pytest.raises(TypeError):
        thespis.TimeOffset(None, 1.0)
    with pytest.raises(TypeError):
        thespis.Loop(None)
