"""thespis-cli calibrate end to end on OpenCV's real chessboard photos
(../shared/data/vision/calibration): the intrinsics OpenCV's own sample found, the summary a
person reads, the camera file OpenCV reads back, and the errors for a wrong board or too few
views. And on the ChArUco photos of OpenCV's aruco tutorial (../shared/data/vision/aruco_real):
the tutorial's calibration, within what four views can say; an ArUco grid refused.

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
CHARUCO = DATA / "vision" / "aruco_real"
CHARUCO_BOARD = "charuco:DICT_6X6_250:5x7:0.04:0.02"  # the tutorial's units

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID = 2, 3


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def views():
    if not VIEWS.exists():
        pytest.fail(f"{VIEWS} is missing (../shared/data)")
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


@pytest.fixture(scope="module")
def charuco_views():
    if not CHARUCO.exists():
        pytest.fail(f"{CHARUCO} is missing (../shared/data)")
    return sorted(CHARUCO.glob("charuco_img_0*.jpg"))


def test_the_charuco_photos_give_the_tutorials_intrinsics(charuco_views, views, tmp_path):
    # Measured: fx 473.09, fy 474.07, centre (317.79, 261.09), RMS 0.178 px, standard deviations
    # fx 20.1, fy 19.7, cx 2.0, cy 13.7 px. The tutorial's file: fx 452.5, fy 456.8, centre
    # (317.7, 277.8), RMS 0.182 px. Four views pin fx, fy and cy down loosely (see
    # tests/core/calibration_test.cpp), hence 6 % and 25 px; cx and the RMS are sharp.
    assert len(charuco_views) == 4
    out = tmp_path / "camera.yml"
    chessboard = views[0]  # the same size, but no ChArUco board: left out, not fatal
    result = run("calibrate", *charuco_views, chessboard, "--board", CHARUCO_BOARD, "--out", out)
    assert result.returncode == 0, result.stderr
    mine = out.read_text()
    assert mine.startswith("%YAML:1.0")
    tutorial = (CHARUCO / "tutorial_camera_charuco.yml").read_text()
    fx, _, cx, _, fy, cy, *_ = matrix(mine, "camera_matrix")
    tfx, _, tcx, _, tfy, tcy, *_ = matrix(tutorial, "camera_matrix")
    assert abs(fx - tfx) < 0.06 * tfx and abs(fy - tfy) < 0.06 * tfy
    assert abs(cx - tcx) < 3 and abs(cy - tcy) < 25
    assert len(matrix(mine, "distortion_coefficients")) == 5
    summary = result.stdout.splitlines()
    assert summary[0].startswith("Calibrated 640 × 480")
    rms = float(re.search(r"RMS reprojection error ([\d.]+) px", summary[0]).group(1))
    assert 0 < rms < 0.2
    written = float(re.search(r"avg_reprojection_error: ([-+0-9.eE]+)", mine).group(1))
    assert abs(written - rms) < 0.0005
    deviation = float(re.search(r"Standard deviations: fx ([\d.]+),", summary[1]).group(1))
    assert 10 < deviation < 0.1 * fx
    per_view = {line.split(":")[0].strip(): line for line in summary if line.startswith("  ")}
    for view in charuco_views:
        found = re.search(r": ([\d.]+) px \((\d+) corners\)", per_view[view.name])
        assert found, per_view[view.name]
        assert float(found.group(1)) < 0.3 and int(found.group(2)) >= 22
    assert "board not found, left out" in per_view[chessboard.name]


def test_an_aruco_grid_or_a_wrong_charuco_board_say_what_to_do(charuco_views, tmp_path):
    out = tmp_path / "camera.yml"
    grid = run("calibrate", *charuco_views, "--board", "aruco-grid:DICT_6X6_250:5x7:0.04:0.01", "--out", out)
    assert grid.returncode == USAGE
    assert "chessboard" in grid.stderr and "ChArUco board" in grid.stderr
    wrong = run("calibrate", *charuco_views, "--board", "charuco:DICT_4X4_50:5x7:0.04:0.02", "--out", out, "--quiet")
    assert wrong.returncode == INVALID
    assert "found in 0 of 4 views" in wrong.stderr and "dictionary" in wrong.stderr
    assert not out.exists()
