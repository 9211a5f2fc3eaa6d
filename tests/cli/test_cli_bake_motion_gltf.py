"""thespis-cli bake-motion to glTF 2.0, end to end on real files (../shared/data: RobotExpressive,
a CMU walk): the .glb read back as a character moves its joints where the BVH bake of the same
command puts them, with the feet on the floor; the animation alone; the same bytes from a
package; the built-in humanoid refused with the way out said.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import thespis

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
DEMO = ROOT / "resources" / "demo.thespis"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

INVALID = 3


def run(*args, timeout=600):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture
def robot_walks(tmp_path):
    document = thespis.Scenario()
    document.name = "Robot walks"
    character = thespis.Character("Robot", "model")
    character.model = str(DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb")
    character.clips = [thespis.ClipAsset("walk", str(DATA / "mocap" / "cmu" / "02_01.bvh"))]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("walk", "walk")]
    character.layers = [layer]
    document.characters = [character]
    scenario = tmp_path / "walk.thespis"
    thespis.save_scenario(scenario, document)
    return scenario


def test_the_glb_moves_the_model_as_the_bvh_does_feet_on_the_floor(robot_walks, tmp_path):
    glb, bvh = tmp_path / "walk.glb", tmp_path / "walk.bvh"
    for out in (glb, bvh):
        result = run("bake-motion", robot_walks, "--character", "Robot", "--out", out, "--quiet")
        assert result.returncode == 0, result.stderr
    model = thespis.scene.load_gltf_character(glb)
    clips = [clip for clip in model.clips if clip.name == "Robot"]
    assert len(clips) == 1, [clip.name for clip in model.clips]
    frames = np.asarray(clips[0].frames)
    baked = thespis.bvh.load(bvh)
    bvh_frames = np.asarray(baked.clip.frames)
    assert len(frames) == len(bvh_frames) == 86  # 2.83 s of the CMU walk at 30 fps
    skeleton = model.skeleton
    by_source = [baked.skeleton.joint_names.index(skeleton.joint(j).source_name) for j in range(skeleton.joint_count)]
    feet = [skeleton.joint_names.index(name) for name in ("l_talocrural", "r_talocrural")]
    rest = np.asarray(skeleton.world_positions(skeleton.rest_frame()))
    worst, lowest, highest = 0.0, np.inf, -np.inf
    for glb_frame, bvh_frame in zip(frames, bvh_frames):
        where = np.asarray(skeleton.world_positions(glb_frame))
        worst = max(worst, np.abs(where - np.asarray(baked.skeleton.world_positions(bvh_frame))[by_source]).max())
        lowest, highest = min(lowest, where[feet, 1].min()), max(highest, where[feet, 1].max())
    assert worst < 1e-4  # metres: BVH text against glTF floats
    # The feet step on the floor they stand on at rest, and leave it.
    assert rest[feet, 1].max() - 0.01 < lowest < rest[feet, 1].max() + 0.05
    assert highest > lowest + 0.2


def test_the_animation_alone_and_from_a_package(robot_walks, tmp_path):
    whole, alone = tmp_path / "walk.glb", tmp_path / "walk_only.glb"
    assert run("bake-motion", robot_walks, "--character", "Robot", "--out", whole, "--quiet").returncode == 0
    result = run("bake-motion", robot_walks, "--character", "Robot", "--out", alone, "--animation-only")
    assert result.returncode == 0, result.stderr
    assert alone.read_bytes()[:4] == b"glTF" and alone.stat().st_size < whole.stat().st_size / 4
    package = tmp_path / "walk.thespkg"
    assert run("export", robot_walks, "--out", package, "--quiet").returncode == 0
    from_package = tmp_path / "from_package.glb"
    assert run("bake-motion", package, "--character", "Robot", "--out", from_package, "--quiet").returncode == 0
    assert from_package.read_bytes() == whole.read_bytes()


def test_what_cannot_be_written_says_why(tmp_path):
    humanoid = run("bake-motion", DEMO, "--character", "Creon", "--out", tmp_path / "creon.glb")
    assert humanoid.returncode == INVALID and "built-in humanoid" in humanoid.stderr and ".bvh" in humanoid.stderr
    assert not (tmp_path / "creon.glb").exists()
    only = run("bake-motion", DEMO, "--character", "Creon", "--out", tmp_path / "creon.bvh", "--animation-only")
    assert only.returncode == 2 and "--animation-only goes with a .glb" in only.stderr
