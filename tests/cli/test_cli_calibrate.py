"""thespis-cli calibrate end to end on OpenCV's real chessboard photos
(../shared/data/vision/calibration): the intrinsics OpenCV's own sample found, the summary a
person reads, the camera file OpenCV reads back, and the errors for a wrong board or too few
views.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import re
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
VIEWS = DATA / "vision" / "calibration"

pytestmark = pytest.mark.skipif(not CLI, reason="THESPIS_CLI (the thespis-cli executable) is not set")

USAGE, INVALID = 2, 3


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def views():
    if not VIEWS.exists():
        pytest.skip(f"{VIEWS} is missing (../shared/data)")
    return sorted(VIEWS.glob("left*.jpg"))


def matrix(text, name):
    """The numbers of an OpenCV YAML matrix field."""
    block = text.split(name + ":", 1)[1].split("data:", 1)[1].split("]", 1)[0]
    return [float(x) for x in re.findall(r"[-+0-9.eE]+", block)]


def test_the_chessboard_photos_give_opencvs_intrinsics(views, tmp_path):
    out = tmp_path / "camera.yml"
    result = run("calibrate", *views, "--board", "chessboard:9x6:0.025", "--fix-aspect", "--out", out)
    assert result.returncode == 0, result.stderr
    gold = (VIEWS / "left_intrinsics.yml").read_text()
    mine = out.read_text()
    assert mine.startswith("%YAML:1.0")
    fx, _, cx, _, fy, cy, *_ = matrix(mine, "camera_matrix")
    gfx, _, gcx, _, _, gcy, *_ = matrix(gold, "camera_matrix")
    assert fx == fy and abs(fx - gfx) < 0.005 * gfx and abs(cx - gcx) < 1 and abs(cy - gcy) < 1
    assert len(matrix(mine, "distortion_coefficients")) == 5
    summary = result.stdout.splitlines()
    assert summary[0].startswith("Calibrated 640 × 480")
    rms = float(re.search(r"RMS reprojection error ([\d.]+) px", summary[0]).group(1))
    assert abs(rms - 0.39) < 0.05
    assert sum(1 for line in summary if line.strip().startswith("left")) == 13


def test_a_wrong_board_or_too_few_views_say_what_to_do(views, tmp_path):
    out = tmp_path / "camera.yml"
    wrong = run("calibrate", *views, "--board", "chessboard:10x7:0.025", "--out", out, "--quiet")
    assert wrong.returncode == INVALID
    assert "inner corners counted right" in wrong.stderr
    assert not out.exists()
    few = run("calibrate", *views[:2], "--board", "chessboard:9x6:0.025", "--out", out)
    assert few.returncode == USAGE and "at least 3 views" in few.stderr
    spec = run("calibrate", *views, "--board", "chessboard:9x6", "--out", out)
    assert spec.returncode == USAGE and "expected chessboard:COLUMNSxROWS:SQUARE" in spec.stderr
