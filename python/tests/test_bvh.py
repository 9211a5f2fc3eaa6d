"""BVH import of real motion capture (../shared/data/mocap), export and round trips."""

import re

import numpy as np
import pytest

import thespis
from thespis import bvh
from conftest import all_bvh_files, mocap

BODY_FILES = ["cmu/02_01.bvh", "cmu/141_16.bvh", "cmu/131_01.bvh", "threejs/pirouette.bvh", "makehuman/walk1.bvh"]


def header_facts(path):
    """Joint count, channels per frame, frame count and frame time, read independently."""
    text = path.read_text(errors="replace")
    hierarchy, _, motion = text.partition("MOTION")
    joints = len(re.findall(r"^\s*(?:ROOT|JOINT)\s", hierarchy, re.M))
    channels = sum(int(c) for c in re.findall(r"CHANNELS\s+(\d+)", hierarchy))
    frames = int(re.search(r"Frames:\s*(\d+)", motion).group(1))
    frame_time = float(re.search(r"Frame Time:\s*([0-9.eE+-]+)", motion).group(1))
    return joints, channels, frames, frame_time


def aligned(q, reference):
    """q with each quaternion's sign flipped to the reference's hemisphere."""
    sign = np.sign(np.sum(q * reference, axis=-1))
    sign[sign == 0] = 1
    return q * sign[..., None]


@pytest.mark.parametrize("path", all_bvh_files(), ids=lambda p: p.name)
def test_every_file_imports_as_its_header_says(path):
    joints, channels, frames, frame_time = header_facts(path)
    skeleton, clip, report = bvh.load(path)
    assert report.joint_count == joints == skeleton.joint_count
    assert report.channel_count == channels
    assert report.frame_count == frames == clip.frame_count
    assert report.frame_time == pytest.approx(frame_time)
    assert clip.frame_rate == pytest.approx(1.0 / frame_time)
    assert clip.layout == skeleton.frame_layout
    assert np.all(np.isfinite(clip.frames))


@pytest.mark.parametrize("name", BODY_FILES)
def test_body_conventions_map_onto_hanim(name):
    skeleton, _, report = bvh.load(mocap(name))
    assert report.is_body, report.convention
    for joint in ("humanoid_root", "l_hip", "r_knee", "l_shoulder", "r_elbow", "skullbase"):
        assert skeleton.find(joint) is not None, f"{name}: {joint} not mapped ({report.convention})"
    # Unmapped joints are reported and kept, never dropped.
    for unmapped in report.unmapped:
        assert any(j.source_name == unmapped for j in skeleton.joints)


def test_face_rig_imports_with_its_own_skeleton():
    skeleton, clip, report = bvh.load(mocap("makehuman/face-poseunits.bvh"))
    assert not report.is_body
    assert clip.frame_count == 60
    assert skeleton.joint_count == report.joint_count


def test_frame_rate_override():
    _, clip, report = bvh.load(mocap("cmu/77_02.bvh"), frame_rate=60.0)
    assert clip.frame_rate == 60.0
    assert clip.domain.duration == pytest.approx((report.frame_count - 1) / 60.0)


@pytest.mark.parametrize("name", ["cmu/02_01.bvh", "threejs/pirouette.bvh", "makehuman/walk1.bvh"])
def test_write_then_parse_round_trip(name):
    skeleton, clip, _ = bvh.load(mocap(name))
    again = bvh.parse(bvh.write(skeleton, clip))
    assert again.skeleton.joint_names == skeleton.joint_names
    assert [j.source_name for j in again.skeleton.joints] == [j.source_name for j in skeleton.joints]
    assert again.clip.frame_count == clip.frame_count
    assert again.clip.frame_rate == pytest.approx(clip.frame_rate, rel=1e-6)
    n = skeleton.frame_layout.rotation_count
    q0 = clip.frames[:, : 4 * n].reshape(-1, n, 4)
    q1 = again.clip.frames[:, : 4 * n].reshape(-1, n, 4)
    np.testing.assert_allclose(aligned(q1, q0), q0, atol=1e-5)
    np.testing.assert_allclose(again.clip.frames[:, 4 * n:], clip.frames[:, 4 * n:], atol=1e-5, rtol=1e-6)


def test_save_then_load_round_trip(tmp_path):
    skeleton, clip, _ = bvh.load(mocap("cmu/141_16.bvh"))
    out = tmp_path / "wave copy.bvh"
    bvh.save(out, skeleton, clip)
    assert [p.name for p in tmp_path.iterdir()] == ["wave copy.bvh"]  # no temporary left behind
    loaded = bvh.load(str(out))  # str and os.PathLike both work
    assert loaded.report.frame_count == clip.frame_count
    times = np.linspace(0.0, clip.domain.end, 17)
    p0 = np.array([skeleton.world_positions(f) for f in clip.sample(times)])
    p1 = np.array([loaded.skeleton.world_positions(f) for f in loaded.clip.sample(times)])
    np.testing.assert_allclose(p1, p0, atol=1e-3)


def test_imported_clip_unpacks():
    imported = bvh.load(mocap("makehuman/walk1.bvh"))
    skeleton, clip, report = imported
    assert skeleton.joint_count == imported.skeleton.joint_count
    assert clip.frame_count == 14 and report.frame_count == 14


def test_user_mapping(tmp_path):
    mapping_file = tmp_path / "map.txt"
    mapping_file.write_text("# file joint  hanim\nHips humanoid_root\nLeftUpLeg l_hip\n")
    mapping = bvh.load_mapping(mapping_file)
    assert mapping == {"Hips": "humanoid_root", "LeftUpLeg": "l_hip"}
    skeleton, _, report = bvh.load(mocap("cmu/02_01.bvh"), mapping=mapping)
    assert skeleton.find("l_hip") is not None
    assert "RightUpLeg" in report.unmapped
    with pytest.raises(thespis.FormatError, match="line 2"):
        bvh.parse_mapping("Hips humanoid_root\nonly_one_word\n")


def test_unmapped_import_keeps_file_names():
    skeleton, _, _ = bvh.load(mocap("cmu/02_01.bvh"), map_to_hanim=False)
    assert skeleton.joint(0).name == "Hips"


def test_malformed_bvh_names_the_line():
    text = mocap("makehuman/walk1.bvh").read_text()
    broken = text.replace("OFFSET", "OFFSTE", 3)
    with pytest.raises(thespis.FormatError, match=r"line \d+") as info:
        bvh.parse(broken)
    assert info.value.code == thespis.ErrorCode.corrupt_data
    with pytest.raises(thespis.FormatError) as info:
        bvh.parse("this is not a bvh file")
    assert info.value.code == thespis.ErrorCode.not_our_format
    truncated = text[: len(text) // 2]
    with pytest.raises(thespis.FormatError, match="line"):
        bvh.parse(truncated)


def test_missing_file():
    with pytest.raises(FileNotFoundError, match="no_such.bvh"):
        bvh.load("no_such.bvh")


def test_save_refuses_a_clip_of_another_layout(tmp_path):
    skeleton, _, _ = bvh.load(mocap("makehuman/walk1.bvh"))
    _, other, _ = bvh.load(mocap("cmu/02_01.bvh"))
    with pytest.raises(ValueError, match="layout"):
        bvh.save(tmp_path / "x.bvh", skeleton, other)
    assert not (tmp_path / "x.bvh").exists()
