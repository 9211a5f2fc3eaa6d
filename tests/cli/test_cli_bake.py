"""thespis-cli bake end to end: a real glTF character, tags from a file or a scenario, the
summary, the bake file read back with the `thespis` package, errors, and Ctrl-C.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import json
import os
import signal
import subprocess
from pathlib import Path

import numpy as np
import pytest

import thespis
from thespis import lighting, scene

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"
PROBE = DATA / "probes" / "polyhaven_1k" / "venice_sunset_1k.hdr"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, FAILURE, CANCELLED = 2, 3, 4, 130


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def robot():
    if not ROBOT.exists():
        pytest.fail(f"{ROBOT} is missing (../shared/data)")
    return ROBOT


@pytest.fixture(scope="module")
def robot_mesh(robot):
    return scene.load_gltf_mesh(robot)


def test_bake_writes_a_file_the_package_reads(robot, robot_mesh, tmp_path):
    out = tmp_path / "robot.prt"
    result = run("bake", robot, "--order", "3", "--rays", "16", "--transfer", "ds", "--out", out)
    assert result.returncode == 0, result.stderr
    assert f"{robot_mesh.vertex_count} vertices" in result.stdout
    assert "Mrays/s" in result.stdout and "rays (16 per vertex, embree)" in result.stdout
    bake = lighting.TransferBake.load(out)
    assert bake.order == 3 and bake.transfer_kind == "ds" and bake.rays_per_vertex == 16
    assert bake.vertex_count == robot_mesh.vertex_count
    bake.check_matches(robot_mesh)
    assert np.isfinite(bake.transfer).all()


def test_tags_file_makes_an_occluder_unbaked_and_is_reproducible(robot, robot_mesh, tmp_path):
    occluder = robot_mesh.segments[0].name
    tags = tmp_path / "tags.json"
    tags.write_text(json.dumps({occluder: "occluder"}))
    outputs = []
    for threads in ("1", "2"):
        out = tmp_path / f"tagged{threads}.prt"
        result = run("bake", robot, "--order", "2", "--rays", "9", "--tags", tags, "--threads", threads,
                     "--out", out, "--quiet")
        assert result.returncode == 0, result.stderr
        assert result.stdout == ""
        outputs.append(out.read_bytes())
    assert outputs[0] == outputs[1]  # bit-identical whatever the thread count
    bake = lighting.TransferBake.load(tmp_path / "tagged1.prt")
    baked = {s.name: s.baked for s in bake.segments}
    assert baked[occluder] is False
    assert sum(baked.values()) == len(baked) - 1


def test_tags_from_a_scenario_character(robot, robot_mesh, tmp_path):
    receiver = robot_mesh.segments[-1].name
    document = thespis.Scenario()
    character = thespis.Character("Robot", "hanim-loa1")
    character.model = str(robot)
    character.segment_tags = [scene.SegmentTag(receiver, scene.SegmentRole.RECEIVER)]
    document.characters = [character]
    path = tmp_path / "robot.thespis"
    thespis.save_scenario(path, document)
    out = tmp_path / "robot.prt"
    result = run("bake", robot, "--order", "2", "--rays", "4", "--scenario", path, "--out", out)
    assert result.returncode == 0, result.stderr
    roles = {s.name: s.role for s in lighting.TransferBake.load(out).segments}
    assert roles[receiver] == scene.SegmentRole.RECEIVER


def test_probe_lights_the_bake(robot, tmp_path):
    if not PROBE.exists():
        pytest.fail(f"{PROBE} is missing")
    result = run("bake", robot, "--order", "3", "--rays", "16", "--transfer", "du", "--probe", PROBE,
                 "--layout", "latlong", "--out", tmp_path / "lit.prt")
    assert result.returncode == 0, result.stderr
    assert "Under venice_sunset_1k.hdr: vertex luminance" in result.stdout


@pytest.mark.parametrize(
    "arguments, message",
    [
        (["--transfer", "glossy"], "--transfer: "),
        (["--backend", "optix"], "--backend: "),
        (["--order", "12"], "--order must be a whole number from 1 to 11"),
        (["--rays", "0"], "--rays must be a whole number from 1"),
        (["--epsilon", "-1"], "--epsilon must be a distance"),
        (["--layout", "latlong"], "--layout needs --probe"),
        (["--character", "A"], "--character needs --scenario"),
    ],
)
def test_bad_command_lines_are_usage_errors(robot, tmp_path, arguments, message):
    result = run("bake", robot, "--out", tmp_path / "x.prt", *arguments)
    assert result.returncode == USAGE, result.stderr
    assert message in result.stderr
    assert not (tmp_path / "x.prt").exists()


def test_unreadable_inputs_are_named(robot, tmp_path):
    missing = run("bake", tmp_path / "nobody.glb", "--out", tmp_path / "x.prt")
    assert missing.returncode == INVALID and "nobody.glb" in missing.stderr

    garbage = tmp_path / "garbage.glb"
    garbage.write_bytes(b"glTF\x02\x00\x00\x00garbage")
    broken = run("bake", garbage, "--out", tmp_path / "x.prt")
    assert broken.returncode == INVALID and "garbage.glb" in broken.stderr

    tags = tmp_path / "tags.json"
    tags.write_text(json.dumps({"no such segment": "receiver"}))
    unknown = run("bake", robot, "--tags", tags, "--out", tmp_path / "x.prt")
    assert unknown.returncode == INVALID and "no such segment" in unknown.stderr

    bad_probe = tmp_path / "probe.hdr"
    bad_probe.write_text("not an image")
    probe = run("bake", robot, "--probe", bad_probe, "--out", tmp_path / "x.prt")
    assert probe.returncode == INVALID and "probe.hdr" in probe.stderr
    assert not (tmp_path / "x.prt").exists()


def test_ctrl_c_cancels_without_writing(robot, tmp_path):
    out = tmp_path / "cancelled.prt"
    # Enough rays on one thread for the bake to run for seconds: the first progress line comes
    # at 10 %, then the interrupt arrives while the workers are busy.
    process = subprocess.Popen([CLI, "bake", str(robot), "--rays", "16384", "--threads", "1", "--out", str(out)],
                               stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    first = process.stderr.readline()
    assert first.startswith("bake: "), first
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=60)
    assert process.returncode == CANCELLED, stderr
    assert "cancelled" in stderr and "was not written" in stderr
    assert list(tmp_path.iterdir()) == []  # neither the file nor a temporary
    assert "Baked" not in stdout
