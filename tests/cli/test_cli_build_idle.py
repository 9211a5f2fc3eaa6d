"""thespis-cli build-idle end to end on the real CMU standing clips, the way a user goes: build a
database, name it in a scenario's clip, then check what a person would see — the character
stands where it was put with its feet on the floor, and never freezes — and the errors for a
database that is missing or damaged.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

import thespis

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
CMU = DATA / "mocap" / "cmu"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID = 2, 3


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def scenario_with_idle(folder, database, seed=3):
    path = folder / "idle.thespis"
    path.write_text(json.dumps({
        "format": "thespis-scenario", "version": 5, "schema": "Scenario.5", "name": "idle", "duration": 0,
        "characters": [{
            "schema": "Character.3", "name": "Ada", "skeleton": "hanim-loa1", "position": [0.4, 0.0, -0.3],
            "clips": [{"schema": "Clip.3", "name": "idle", "idle": {"database": database, "seed": seed}}],
            "layers": [{"schema": "Layer.2", "name": "body", "kind": "body", "mode": "normalized",
                        "actions": [{"schema": "Action.2", "name": "idle", "clip": "idle", "start": 0}]}],
        }],
    }))
    return path


@pytest.fixture(scope="module")
def database(tmp_path_factory):
    if not CMU.exists():
        pytest.fail(f"{CMU} is missing (../shared/data)")
    out = tmp_path_factory.mktemp("idle") / "standing.idle"
    result = run("build-idle", f"{CMU / '77_02.bvh'}@60", f"{CMU / '111_28.bvh'}+6", "--skip", "2", "--out", out)
    assert result.returncode == 0, result.stderr
    assert "categories left, both, right" in result.stdout
    assert "77_02.bvh: " in result.stdout and "111_28.bvh: " in result.stdout
    assert out.read_bytes().startswith(b"THSPIDL\0")
    return out


def test_a_character_idles_in_place_with_its_feet_on_the_floor(database, tmp_path):
    path = scenario_with_idle(tmp_path, str(database))
    validated = run("validate", path)
    assert validated.returncode == 0, validated.stderr
    info = run("info", path)
    assert "idle motion from" in info.stdout and "seed 3" in info.stdout

    scenario = thespis.load_scenario(path)
    runtime = thespis.build_runtime(scenario, tmp_path)
    ada = runtime.find_character("Ada")
    skeleton = ada.skeleton
    ankles = [skeleton.find("l_talocrural"), skeleton.find("r_talocrural")]
    rest_ankle = skeleton.world_positions(skeleton.rest_frame())[ankles[0]][1]
    root_path, ankle_heights, frames = [], [], []
    for t in np.arange(0.0, 60.0, 0.1):
        frame = ada.evaluate_body(float(t))
        world = skeleton.world_positions(frame)
        root_path.append(world[0])
        ankle_heights.append(min(world[a][1] for a in ankles))
        frames.append(frame)
    root_path, ankle_heights = np.array(root_path), np.array(ankle_heights)
    # Stands where it was put, facing where it faces: the root within 15 cm of its place.
    assert np.abs(root_path[:, 0] - 0.4).max() < 0.15 and np.abs(root_path[:, 2] + 0.3).max() < 0.15
    # The lower foot stays on the floor: its ankle about as high as at rest.
    assert np.abs(ankle_heights - rest_ankle).max() < 0.03
    # Never frozen: every second the body moves.
    frames = np.array(frames)
    for second in range(0, 590, 10):
        assert np.abs(frames[second + 10] - frames[second]).max() > 1e-3, f"still at {second / 10} s"
    # Scrubbing back gives the same frames.
    np.testing.assert_array_equal(ada.evaluate_body(12.3), ada.evaluate_body(12.3))


def test_a_missing_or_damaged_database_is_named(database, tmp_path):
    missing = run("validate", scenario_with_idle(tmp_path, "nowhere.idle"))
    assert missing.returncode == INVALID
    assert "nowhere.idle" in missing.stderr + missing.stdout
    damaged = tmp_path / "damaged.idle"
    data = bytearray(database.read_bytes())
    data[len(data) // 2] ^= 0x40
    damaged.write_bytes(bytes(data))
    result = run("validate", scenario_with_idle(tmp_path, "damaged.idle"))
    assert result.returncode == INVALID
    assert "damaged.idle" in result.stderr + result.stdout and "damaged" in (result.stderr + result.stdout)


def test_too_little_standing_says_so(tmp_path):
    if not CMU.exists():
        pytest.fail(f"{CMU} is missing (../shared/data)")
    result = run("build-idle", f"{CMU / '113_21.bvh'}+10.5", "--out", tmp_path / "short.idle")
    assert result.returncode == INVALID
    assert "Too few postures" in result.stderr
    assert not (tmp_path / "short.idle").exists()
    assert run("build-idle", "--out", tmp_path / "x.idle").returncode == USAGE
    assert run("build-idle", CMU / "77_02.bvh", "--out", tmp_path / "x.txt").returncode == USAGE
