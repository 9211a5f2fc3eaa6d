"""Keyframe clips made from NumPy arrays: creation rules, frames, interpolation."""

import gc
import math

import numpy as np
import pytest

import thespis
from thespis import FrameLayout, KeyframeClip


def rot_z(angle):
    return [0.0, 0.0, math.sin(angle / 2), math.cos(angle / 2)]


@pytest.fixture
def layout():
    return FrameLayout(["root", "arm"], ["root"], ["blink"])


def make_clip(layout, angles, rate=10.0):
    frames = np.array([rot_z(a) + rot_z(2 * a) + [a, 0.0, 0.0] + [a / math.pi] for a in angles], np.float32)
    return KeyframeClip(layout, rate, frames, "spin")


def test_create_from_numpy(layout):
    clip = make_clip(layout, [0.0, 0.5, 1.0])
    assert clip.name == "spin" and clip.frame_rate == 10.0 and clip.frame_count == 3
    assert clip.layout == layout
    assert clip.domain == thespis.TimeDomain(0.0, 0.2)
    assert clip.frames.shape == (3, layout.float_count)
    np.testing.assert_allclose(clip.frame(1)[:4], rot_z(0.5), atol=1e-7)


def test_frames_view_is_read_only_and_keeps_the_clip_alive(layout):
    frames = make_clip(layout, [0.0, 1.0]).frames
    gc.collect()
    assert not frames.flags.writeable
    assert frames[1, 8] == pytest.approx(1.0)
    with pytest.raises(ValueError):
        frames[0, 0] = 5.0


def test_evaluate_slerps_rotations_and_lerps_the_rest(layout):
    clip = make_clip(layout, [0.0, 1.0])
    frame = clip.evaluate(0.05)  # halfway between the keys
    assert frame.dtype == np.float32 and frame.shape == (layout.float_count,)
    np.testing.assert_allclose(frame[:4], rot_z(0.5), atol=1e-6)
    np.testing.assert_allclose(frame[4:8], rot_z(1.0), atol=1e-6)
    assert frame[8] == pytest.approx(0.5) and frame[11] == pytest.approx(0.5 / math.pi)
    # Outside the domain a clip holds its end frames.
    np.testing.assert_allclose(clip.evaluate(-1.0), clip.frame(0), atol=1e-7)
    np.testing.assert_allclose(clip.evaluate(9.0), clip.frame(1), atol=1e-7)


def test_sample_and_evaluate_into(layout):
    clip = make_clip(layout, [0.0, 0.2, 0.4, 0.6])
    times = np.array([0.0, 0.1, 0.15, 0.3])
    frames = clip.sample(times)
    assert frames.shape == (4, layout.float_count)
    out = np.empty(layout.float_count, np.float32)
    for t, row in zip(times, frames):
        clip.evaluate_into(float(t), out)
        np.testing.assert_array_equal(out, row)
    with pytest.raises(ValueError, match="values"):
        clip.evaluate_into(0.0, np.empty(3, np.float32))
    with pytest.raises(TypeError):
        clip.evaluate_into(0.0, np.empty(layout.float_count, np.float64))  # would be a silent copy


def test_rotations_are_normalized(layout):
    frames = np.array([[0, 0, 0, 2.0] + [0, 0, 0, 1] + [0, 0, 0] + [0]], np.float32)
    clip = KeyframeClip(layout, 30.0, frames)
    np.testing.assert_allclose(clip.frame(0)[:4], [0, 0, 0, 1])


def test_creation_errors_name_the_problem(layout):
    good = np.tile(layout.neutral_frame(), (2, 1))
    with pytest.raises(ValueError, match="frame rate"):
        KeyframeClip(layout, 0.0, good)
    with pytest.raises(ValueError, match="values per frame"):
        KeyframeClip(layout, 30.0, np.zeros((2, 5), np.float32))
    bad = good.copy()
    bad[1, 9] = np.nan
    with pytest.raises(ValueError, match="frame 1"):
        KeyframeClip(layout, 30.0, bad)
    zero = good.copy()
    zero[0, 4:8] = 0
    with pytest.raises(ValueError, match="arm"):
        KeyframeClip(layout, 30.0, zero)
    with pytest.raises(IndexError):
        KeyframeClip(layout, 30.0, good).frame(2)


def test_remap_clip_matches_elements_by_name(layout):
    clip = make_clip(layout, [0.0, 1.0])
    target = FrameLayout(["arm", "leg"], ["root"])
    rest = target.neutral_frame()
    rest[4:8] = rot_z(0.3)
    remapped, dropped = thespis.remap_clip(clip, target, rest)
    assert remapped.layout == target
    assert sorted(dropped) == ["blink", "root"]
    np.testing.assert_allclose(remapped.frame(1)[:4], rot_z(2.0), atol=1e-6)   # arm
    np.testing.assert_allclose(remapped.frame(1)[4:8], rot_z(0.3), atol=1e-6)  # leg from rest
    np.testing.assert_allclose(remapped.frame(1)[8:11], [1.0, 0.0, 0.0])       # root translation
    with pytest.raises(ValueError):
        thespis.remap_clip(clip, target, rest[:3])
