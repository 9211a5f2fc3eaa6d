"""Joint masks: presets over H-Anim, inheritance down the hierarchy, mirror, invert, validation."""

import numpy as np
import pytest

import thespis
from thespis import JointMask, MaskPreset


@pytest.fixture(scope="module")
def loa2():
    return thespis.hanim.skeleton(thespis.hanim.Level.loa2)


def resolved(mask, skeleton):
    weights = mask.resolve(skeleton.frame_layout, skeleton.parents)
    assert weights.dtype == np.float32 and weights.shape == (skeleton.frame_layout.element_count,)
    return {name: float(weights[i]) for i, name in enumerate(skeleton.joint_names)}, weights


def test_upper_body_preset_covers_spine_arms_and_head_only(loa2):
    by_joint, weights = resolved(JointMask.preset(MaskPreset.upper_body), loa2)
    for joint in ("vl5", "vt6", "skullbase", "l_shoulder", "r_elbow", "r_carpal_distal_interphalangeal_3"):
        assert by_joint[joint] == 1.0, joint
    for joint in ("humanoid_root", "sacroiliac", "l_hip", "r_knee", "l_talocrural"):
        assert by_joint[joint] == 0.0, joint
    # The root translation element takes its joint's weight.
    root_translation = loa2.translation_element(0)
    assert weights[root_translation] == 0.0


def test_lower_body_is_the_complement_of_upper_body(loa2):
    upper, _ = resolved(JointMask.preset(MaskPreset.upper_body), loa2)
    lower, _ = resolved(JointMask.preset(MaskPreset.lower_body), loa2)
    for joint in loa2.joint_names:
        assert upper[joint] + lower[joint] == 1.0, joint


def test_unnamed_joints_inherit_from_their_nearest_named_ancestor(loa2):
    mask = JointMask({"l_shoulder": 0.5, "l_radiocarpal": 1.0}, default_weight=0.1)
    by_joint, _ = resolved(mask, loa2)
    assert by_joint["l_elbow"] == 0.5                 # child of l_shoulder
    assert by_joint["l_carpometacarpal_1"] == 1.0     # below l_radiocarpal
    assert by_joint["r_shoulder"] == pytest.approx(0.1)  # nothing named above it: default
    # Without the hierarchy every unnamed joint takes the default.
    flat = mask.resolve(loa2.frame_layout)
    assert flat[loa2.find("l_elbow")] == pytest.approx(0.1)


def test_mirrored_swaps_sides_and_inverted_complements(loa2):
    left = JointMask.preset(MaskPreset.left_arm)
    right = JointMask.preset(MaskPreset.right_arm)
    assert left.mirrored() == right
    assert left.mirrored().mirrored() == left
    by_joint, _ = resolved(left.inverted(), loa2)
    assert by_joint["l_elbow"] == 0.0 and by_joint["r_elbow"] == 1.0 and by_joint["skullbase"] == 1.0


def test_weights_and_edits():
    mask = JointMask({"skullbase": 1.0})
    assert mask.weight("skullbase") == 1.0
    assert mask.weight("l_knee") is None
    mask.set_weight("l_knee", 0.25)
    mask.default_weight = 0.5
    assert mask.weights == {"skullbase": 1.0, "l_knee": 0.25}
    assert mask.default_weight == 0.5
    assert JointMask.preset(MaskPreset.full_body).default_weight == 1.0


def test_validate_names_the_bad_joint():
    JointMask({"l_knee": 1.0}).validate()
    with pytest.raises(ValueError, match="l_knee"):
        JointMask({"l_knee": 1.5}).validate()
    with pytest.raises(ValueError, match="default weight"):
        JointMask({}, default_weight=-0.5).validate()


def test_resolve_checks_the_parents_length(loa2):
    with pytest.raises(ValueError, match="parents"):
        JointMask().resolve(loa2.frame_layout, [0, 1])
    bad = list(loa2.parents)
    bad[3] = 40  # not an earlier joint: would be read out of order (or out of bounds)
    with pytest.raises(ValueError, match=r"parents\[3\]"):
        JointMask().resolve(loa2.frame_layout, bad)
    with pytest.raises(ValueError, match=r"parents\[3\]"):
        thespis.BlendingSchedule(loa2.frame_layout, None, bad)
