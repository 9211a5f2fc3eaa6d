"""thespis-cli bake-motion to glTF 2.0, end to end on real files (../shared/data: the glTF
characters, a CMU walk; the demo's built-in humanoids): the .glb read back as a character moves its
joints where the BVH bake of the same command puts them, with the feet on the floor; the animation
alone; the same bytes from a package; every .glb through the Khronos glTF-Validator and three.js's
GLTFLoader (tests/js, installed from npm by scripts/install-deps.sh: a missing Node or package
fails, it is not skipped), with no error the source model does not have itself; the built-in
humanoid written whole and read back with the same poses.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import numpy as np
import pytest

import thespis

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
DEMO = ROOT / "resources" / "demo.thespis"
CHECK = ROOT / "tests" / "js" / "check_gltf.mjs"
WALK = DATA / "mocap" / "cmu" / "02_01.bvh"

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


def check(glb):
    """The validator's report and what three.js's GLTFLoader made of the file."""
    node = shutil.which("node")
    assert node, "Node.js is missing: scripts/install-deps.sh installs it"
    assert (CHECK.parent / "node_modules" / "gltf-validator").is_dir() and (CHECK.parent / "node_modules" / "three").is_dir(), \
        "tests/js/node_modules is missing: scripts/install-deps.sh runs npm ci there"
    result = subprocess.run([node, CHECK, glb], capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr
    return json.loads(result.stdout)


def error_codes(report):
    return {m["code"] for m in report["validator"]["messages"] if m["severity"] == "error"}


def walking(tmp_path, name, model, clip=WALK):
    """A scenario where the character `name` (a glTF model, or the built-in humanoid when None)
    plays `clip` (CMU 02_01, or a glTF file's first animation)."""
    document = thespis.Scenario()
    document.name = name + " walks"
    character = thespis.Character(name, "model" if model else "hanim-25")
    if model:
        character.model = str(model)
    character.clips = [thespis.ClipAsset("walk", str(clip))]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("walk", "walk")]
    character.layers = [layer]
    document.characters = [character]
    scenario = tmp_path / (name + ".thespis")
    thespis.save_scenario(scenario, document)
    return scenario


MODELS = {
    "CesiumMan": DATA / "characters" / "CesiumMan" / "CesiumMan.glb",
    "RobotExpressive": DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb",
    "RiggedFigure": DATA / "characters" / "RiggedFigure" / "RiggedFigure.gltf",
    "RiggedSimple": DATA / "characters" / "RiggedSimple" / "RiggedSimple.gltf",  # not a humanoid: its own animation
}


@pytest.mark.parametrize("name", sorted(MODELS))
def test_the_glb_of_each_shared_character_passes_the_validator_and_three_js(name, tmp_path):
    scenario = walking(tmp_path, name, MODELS[name], MODELS[name] if name == "RiggedSimple" else WALK)
    source = check(MODELS[name])
    whole, alone = tmp_path / "whole.glb", tmp_path / "alone.glb"
    baked = run("bake-motion", scenario, "--character", name, "--out", whole)
    assert baked.returncode == 0, baked.stderr
    assert run("bake-motion", scenario, "--character", name, "--out", alone, "--animation-only", "--quiet").returncode == 0
    frames = int(re.search(r"Baked (\d+) frames", baked.stdout).group(1))
    assert frames == 86 if name != "RiggedSimple" else frames > 30  # the walk's 2.83 s at 30 fps; the cylinder's own 2 s
    for glb in (whole, alone):
        report = check(glb)
        # Nothing the model did not have itself (CesiumMan's and the robot's weights do not sum to
        # 1 in their own files); nothing the bake left unused.
        assert error_codes(report) <= error_codes(source), (glb.name, report["validator"]["messages"][:5])
        unused = [m for m in report["validator"]["messages"] if m["code"] == "UNUSED_OBJECT"]
        assert len(unused) <= len([m for m in source["validator"]["messages"] if m["code"] == "UNUSED_OBJECT"])
        three = report["three"]
        assert three["error"] is None, (glb.name, three["error"])
        assert [a["name"] for a in three["animations"]] == [name]
        assert abs(three["animations"][0]["duration"] - (frames - 1) / 30) < 1e-5
    assert check(whole)["three"]["animations"][0]["tracks"] >= check(alone)["three"]["animations"][0]["tracks"] >= 2
    assert check(whole)["three"]["skinnedMeshes"] == source["three"]["skinnedMeshes"] or MODELS[name].suffix == ".gltf"
    assert check(alone)["three"]["meshes"] == 0


def test_the_robots_face_plays_on_its_morph_targets_in_three_js(robot_walks, tmp_path):
    glb = tmp_path / "walk.glb"
    assert run("bake-motion", robot_walks, "--character", "Robot", "--out", glb, "--quiet").returncode == 0
    assert check(glb)["three"]["morphTargets"] == check(MODELS["RobotExpressive"])["three"]["morphTargets"] > 0


def world_rotations(skeleton, frame):
    """Each joint's world rotation (x, y, z, w) for a frame of local rotations (world-aligned rest)."""
    local = np.asarray(frame[:4 * skeleton.joint_count], dtype=np.float64).reshape(-1, 4)
    world = np.zeros_like(local)
    for j in range(skeleton.joint_count):
        parent = skeleton.joint(j).parent
        world[j] = local[j] if parent < 0 else multiply(world[parent], local[j])
    return world


def multiply(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return np.array([aw * bx + ax * bw + ay * bz - az * by, aw * by - ax * bz + ay * bw + az * bx,
                     aw * bz + ax * by - ay * bx + az * bw, aw * bw - ax * bx - ay * by - az * bz])


def angle_between(a, b):
    return 2 * np.arccos(np.clip(abs(np.dot(a, b)) / (np.linalg.norm(a) * np.linalg.norm(b)), 0, 1))


@pytest.mark.parametrize("case", ["demo Creon", "demo Antigone", "CMU walk"])
def test_the_built_in_humanoid_goes_out_whole_and_comes_back_with_the_same_poses(case, tmp_path):
    if case == "CMU walk":
        scenario, name = walking(tmp_path, "Ada", None), "Ada"
    else:
        scenario, name = DEMO, case.split()[1]
    glb, bvh = tmp_path / (name + ".glb"), tmp_path / (name + ".bvh")
    for out in (glb, bvh):
        result = run("bake-motion", scenario, "--character", name, "--out", out, "--quiet")
        assert result.returncode == 0, result.stderr
    report = check(glb)
    assert report["validator"]["errors"] == 0 and report["validator"]["warnings"] == 0, report["validator"]["messages"][:5]
    three = report["three"]
    assert three["error"] is None and three["skinnedMeshes"] >= 1 and three["bones"] >= 25
    # Imported again (as Add Character does): the same skeleton, and the same poses as the BVH
    # bake of the same command, joint by joint, within 1e-4 rad and 0.1 mm from the root. The
    # .glb carries the pose as the studio draws it, which lifts the body where a foot would go
    # through the floor: the root only ever rises above the BVH's, never moves sideways.
    model = thespis.scene.load_gltf_character(glb)
    assert model.mesh.vertex_count > 1000
    clips = [clip for clip in model.clips if clip.name == name]
    assert len(clips) == 1, [clip.name for clip in model.clips]
    baked = thespis.bvh.load(bvh)
    frames, bvh_frames = np.asarray(clips[0].frames), np.asarray(baked.clip.frames)
    assert len(frames) == len(bvh_frames) > 60
    assert abs(three["animations"][0]["duration"] - (len(frames) - 1) / 30) < 1e-5
    skeleton = model.skeleton
    order = [baked.skeleton.joint_names.index(skeleton.joint(j).name) for j in range(skeleton.joint_count)]
    assert len(order) == baked.skeleton.joint_count
    worst_angle = worst_place = worst_sideways = 0.0
    for ours, theirs in zip(frames, bvh_frames):
        mine, reference = world_rotations(skeleton, ours), world_rotations(baked.skeleton, theirs)[order]
        worst_angle = max(worst_angle, max(angle_between(a, b) for a, b in zip(mine, reference)))
        here, there = np.asarray(skeleton.world_positions(ours)), np.asarray(baked.skeleton.world_positions(theirs))[order]
        worst_place = max(worst_place, np.abs((here - here[0]) - (there - there[0])).max())
        lift = here[0] - there[0]
        worst_sideways = max(worst_sideways, abs(lift[0]), abs(lift[2]), -lift[1])
    assert worst_angle < 1e-4 and worst_place < 1e-4 and worst_sideways < 1e-4, (worst_angle, worst_place, worst_sideways)


def test_what_cannot_be_written_says_why(tmp_path):
    only = run("bake-motion", DEMO, "--character", "Creon", "--out", tmp_path / "creon.bvh", "--animation-only")
    assert only.returncode == 2 and "--animation-only goes with a .glb" in only.stderr
    nobody = run("bake-motion", DEMO, "--character", "Nobody", "--out", tmp_path / "nobody.glb")
    assert nobody.returncode == INVALID and "Creon" in nobody.stderr
    assert not (tmp_path / "nobody.glb").exists()
