"""A scenario naming its character's own face mapping table (format 8, "faceMapping"), through
thespis-cli: RobotExpressive (../shared/data) has no target its names say is joy, so a face clip
of joy leaves it still with the recognised table; the table `thespis-cli face-mapping --save-mapping`
wrote, edited to play joy on "Surprised" and named in the scenario, changes the close-up on the
head. A missing table is warned about naming the field and the file, and the picture is the
automatic one. Pictures go to <build>/test-artifacts/face_mapping_scenario/ for people to look at.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

from pictures import read_png

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"
ARTIFACTS = Path(os.environ.get("THESPIS_TEST_ARTIFACTS", "test-artifacts")) / "face_mapping_scenario"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)


def cli(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)


def robot_scenario(path, face_mapping=None):
    """RobotExpressive holding joy (expression 1) at full weight on its face layer."""
    constant = lambda v: {"schema": "Curve.1", "kind": "constant", "value": v}  # noqa: E731
    character = {"schema": "Character.5", "name": "Robot", "skeleton": "model", "model": str(ROBOT),
                 "clips": [{"schema": "Clip.4", "name": "joy", "frameRate": 30.0, "joints": [],
                            "rootTranslation": False, "scalars": ["expression1"], "frames": [[1.0], [1.0]]}],
                 "layers": [{"schema": "Layer.2", "name": "face", "kind": "face", "mode": "normalized",
                             "actions": [{"schema": "Action.2", "name": "joy", "clip": "joy", "start": 0,
                                          "modifiers": [{"schema": "Modifier.2", "kind": "loop", "count": 0}],
                                          "weight": constant(1.0), "scale": constant(1.0), "mode": "normalized",
                                          "renderOutsideDomain": False}]}]}
    if face_mapping:
        character["faceMapping"] = face_mapping
    document = {"format": "thespis-scenario", "version": 8, "schema": "Scenario.8", "name": "robot joy",
                "duration": 705600000, "masks": [], "characters": [character]}
    path.write_text(json.dumps(document))
    return path


def close_up(scenario, out):
    done = cli("render", scenario, "--out", out, "--close-up", "Robot", "--azimuth", 0, "--elevation", 0,
               "--size", "240x240", "--no-ground", "--shading", "unlit", "--time", 0.5)
    assert done.returncode == 0, done.stderr
    return read_png(out), done.stderr


def differing(a, b, threshold=24):
    (width, height, rows_a), (_, _, rows_b) = a, b
    return [(x, y) for y in range(height) for x in range(width)
            if max(abs(rows_a[y][4 * x + c] - rows_b[y][4 * x + c]) for c in range(3)) > threshold]


def test_the_saved_table_edited_and_named_in_the_scenario_plays_on_the_face(tmp_path):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    table = tmp_path / "tables" / "robot_face.json"
    table.parent.mkdir()
    saved = cli("face-mapping", ROBOT, "--save-mapping", table)
    assert saved.returncode == 0, saved.stderr
    edited = json.loads(table.read_text())
    edited["drives"].append({"target": "Surprised", "channel": "joy", "coefficient": 1.0})
    table.write_text(json.dumps(edited, indent=2))

    automatic, _ = close_up(robot_scenario(tmp_path / "automatic.thespis"), ARTIFACTS / "joy_automatic.png")
    own, warnings = close_up(robot_scenario(tmp_path / "own.thespis", "tables/robot_face.json"),
                             ARTIFACTS / "joy_own_table.png")
    assert "faceMapping" not in warnings, warnings
    changed = differing(automatic, own)
    assert len(changed) > 50, "joy must show on the face through the table"
    # On the head: RobotExpressive's "Surprised" raises its brows and stretches the head (the
    # picture's upper half), which the recognised table leaves at rest for joy.
    assert sum(1 for _, y in changed if y < 120) > 1000, len(changed)

    # The scenario validates with its table; without the file it is named, and the render falls back.
    assert cli("validate", tmp_path / "own.thespis").returncode == 0
    table.unlink()
    fallback, warnings = close_up(tmp_path / "own.thespis", ARTIFACTS / "joy_missing_table.png")
    assert "characters[0].faceMapping" in warnings and "robot_face.json" in warnings, warnings
    assert differing(fallback, automatic) == []
    refused = cli("validate", tmp_path / "own.thespis")
    assert refused.returncode != 0
    assert "characters[0].faceMapping" in refused.stdout + refused.stderr
