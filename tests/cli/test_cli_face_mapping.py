"""thespis-cli face-mapping on RobotExpressive (../shared/data): its morph targets and the table its
names are recognised as, the table saved to edit and given back with --mapping (a warning naming
each target the model lacks), and a broken table refused naming the file and the field.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
ROBOT = DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

INVALID = 3


def run(*args):
    return subprocess.run([CLI, "face-mapping", *map(str, args)], capture_output=True, text=True, timeout=120)


def test_the_recognised_table_is_shown_saved_and_given_back(tmp_path):
    saved = tmp_path / "robot_face.json"
    result = run(ROBOT, "--save-mapping", saved)
    assert result.returncode == 0, result.stderr
    assert "3 morph targets" in result.stdout
    assert "Face mapping recognised (expression targets" in result.stdout
    for line in ("  Angry <- anger x 1", "  Surprised <- surprise x 1", "  Sad <- sadness x 1"):
        assert line in result.stdout.splitlines(), result.stdout
    table = json.loads(saved.read_text())
    assert table["format"] == "thespis-face-mapping"

    # Edited: Angry played at half by anger, and a target the robot lacks.
    next(drive for drive in table["drives"] if drive["target"] == "Angry")["coefficient"] = 0.5
    table["drives"].append({"target": "Blink_L", "channel": "close_t_l_eyelid", "coefficient": 1 / 1024})
    saved.write_text(json.dumps(table))
    edited = run(ROBOT, "--mapping", saved)
    assert edited.returncode == 0, edited.stderr
    assert "  Angry <- anger x 0.5" in edited.stdout.splitlines()
    assert edited.stderr.count("warning:") == 1
    assert 'the morph target "Blink_L", which RobotExpressive does not have' in edited.stderr


def test_a_broken_table_or_model_is_refused_naming_where(tmp_path):
    bad = tmp_path / "bad.json"
    bad.write_text('{"format": "thespis-face-mapping", "version": 1, "drives": [{"target": "a", "channel": 3}]}')
    result = run(ROBOT, "--mapping", bad)
    assert result.returncode == INVALID
    assert str(bad) in result.stderr and "drives[0].coefficient" in result.stderr
    missing = run(tmp_path / "none.glb")
    assert missing.returncode == INVALID
    assert "none.glb" in missing.stderr
