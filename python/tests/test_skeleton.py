"""Frame layouts, skeletons and the H-Anim standard humanoid."""

import numpy as np
import pytest

import thespis
from thespis import ElementKind, FrameLayout, Joint, Skeleton, hanim


def test_frame_layout_orders_elements_by_kind():
    layout = FrameLayout(["root", "knee"], ["root"], ["fap3"])
    assert (layout.rotation_count, layout.translation_count, layout.scalar_count) == (2, 1, 1)
    assert layout.element_count == 4 and layout.float_count == 2 * 4 + 3 + 1
    assert layout.translation_offset == 8 and layout.scalar_offset == 11
    assert layout.kind(2) == ElementKind.translation and layout.name(2) == "root"
    assert layout.float_offset(3) == 11
    assert layout.find("knee") == 1
    assert layout.find("root", ElementKind.translation) == 2
    assert layout.find("elbow") is None
    np.testing.assert_array_equal(layout.neutral_frame(), [0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0])
    assert layout == FrameLayout(["root", "knee"], ["root"], ["fap3"])
    with pytest.raises(IndexError):
        layout.kind(4)


def test_mpeg4_face_layout_has_68_faps_then_visemes_and_expressions():
    face = FrameLayout.mpeg4_face()
    assert face.scalar_count == 68 + 14 + 6 and face.rotation_count == 0
    assert face.scalar_names[0] == "fap1" and face.scalar_names[67] == "fap68"
    assert face.scalar_names[68] == "viseme1" and face.scalar_names[-1] == "expression6"


@pytest.mark.parametrize("level, count", [(hanim.Level.loa1, 18), (hanim.Level.loa2, 71), (hanim.Level.subset25, 25)])
def test_hanim_skeletons(level, count):
    skeleton = hanim.skeleton(level)
    assert skeleton.joint_count == count == len(skeleton)
    assert skeleton.joint_names == hanim.joint_names(level)
    assert skeleton.joint(0).name == "humanoid_root" and skeleton.joint(0).parent == -1
    parents = skeleton.parents
    assert all(p < i for i, p in enumerate(parents))
    assert all(hanim.is_joint_name(name) for name in skeleton.joint_names)
    # A body frame: one rotation per joint and the root translation.
    assert skeleton.frame_layout.rotation_count == count
    assert skeleton.translation_element(0) == count
    # joints are copies: a skeleton's invariants cannot be broken from Python.
    skeleton.joints[0].name = "renamed"
    assert skeleton.joint(0).name == "humanoid_root"


def test_hanim_names():
    assert hanim.mirror_name("l_elbow") == "r_elbow"
    assert hanim.mirror_name("skullbase") == "skullbase"
    assert hanim.parent_name("l_elbow") == "l_shoulder"
    assert hanim.from_hanim11("HumanoidRoot") == "humanoid_root"
    assert not hanim.is_joint_name("LeftArm")


def test_world_positions_of_the_rest_pose():
    skeleton = hanim.skeleton(hanim.Level.loa1)
    positions = skeleton.world_positions(skeleton.rest_frame())
    assert positions.shape == (18, 3) and positions.dtype == np.float64
    head = positions[skeleton.find("skullbase")]
    ankle = positions[skeleton.find("l_talocrural")]
    assert head[1] > 1.3 and ankle[1] < 0.2           # +Y up, metres
    assert positions[skeleton.find("l_shoulder")][0] > 0  # +X is the humanoid's left
    with pytest.raises(ValueError, match="values"):
        skeleton.world_positions(np.zeros(5, np.float32))


def test_world_positions_follow_a_rotation():
    # Two joints: rotating the root 90° about Z swings the child from +Y to −X.
    skeleton = Skeleton([Joint("root"), Joint("tip", parent=0, offset=(0.0, 1.0, 0.0))])
    frame = skeleton.rest_frame()
    s = np.sqrt(0.5)
    frame[0:4] = [0.0, 0.0, s, s]
    positions = skeleton.world_positions(frame)
    np.testing.assert_allclose(positions[1], [-1.0, 0.0, 0.0], atol=1e-6)


def test_skeleton_rules_are_value_errors():
    with pytest.raises(ValueError):
        Skeleton([])
    with pytest.raises(ValueError, match="knee"):
        Skeleton([Joint("root"), Joint("knee", parent=0), Joint("knee", parent=0)])
    with pytest.raises(ValueError):
        Skeleton([Joint("root"), Joint("child", parent=2), Joint("late", parent=0)])


def test_joint_fields_round_trip():
    j = Joint("l_knee", parent=3, offset=(0.0, -0.4, 0.0), source_name="LeftLeg", end_site=(0.0, -0.1, 0.0))
    assert j.offset == (0.0, -0.4, 0.0) and j.end_site == (0.0, -0.1, 0.0)
    assert j.source_name == "LeftLeg" and j.rotation_order == "ZXY" and not j.translates
