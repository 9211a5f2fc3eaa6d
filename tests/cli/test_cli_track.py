"""thespis-cli track end to end on real photos: the ChArUco tutorial's views
(../shared/data/vision/aruco_real) played as a picture sequence with the tutorial's calibration,
one CSV row per frame with the board's pose; and the errors a user meets: a camera file for another
resolution, a board spec that does not parse, a picture target without its width.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import csv
import math
import os
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
ARUCO = DATA / "vision" / "aruco_real"
BOARD = "charuco:DICT_6X6_250:5x7:0.04:0.02"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID = 2, 3


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def views():
    if not ARUCO.exists():
        pytest.fail(f"{ARUCO} is missing (../shared/data)")
    return sorted(ARUCO.glob("charuco_img_0*.jpg")) + [ARUCO / "chocclusion_original.jpg"]


def test_the_tutorial_photos_give_one_pose_per_frame(views, tmp_path):
    out = tmp_path / "poses.csv"
    result = run("track", *views, "--camera", ARUCO / "tutorial_camera_charuco.yml", "--board", BOARD,
                 "--fps", 1, "--out", out)
    assert result.returncode == 0, result.stderr
    assert "in 5 of 5 frames (100.0 %); lost 0 times" in result.stdout
    assert "Capture to pose:" in result.stdout
    with out.open() as f:
        rows = list(csv.DictReader(f))
    assert [int(r["frame"]) for r in rows] == [0, 1, 2, 3, 4]
    for row in rows:
        assert row["tracked"] == "1"
        # The photos were taken 35–41 cm from the board, looking at it from the front.
        distance = math.dist((0, 0, 0), [float(row[k]) for k in ("tx", "ty", "tz")])
        assert 0.3 < float(row["tz"]) < 0.45 and distance < 0.5
        angle = math.degrees(math.hypot(*[float(row[k]) for k in ("rx", "ry", "rz")]))
        assert angle < 45, "the board faces the camera"
        # Photos held still: the markers' edges show no smear, and the tilt is not in doubt.
        assert 0 <= float(row["blur_px"]) < 2 and 0 <= float(row["blur_deg"]) < 180
        assert float(row["ambiguity"]) == 0 or float(row["ambiguity"]) > 3


def test_mistakes_say_what_is_wrong(views, tmp_path):
    out = tmp_path / "poses.csv"
    video = DATA / "vision" / "video" / "cockatoo.mp4"
    other = run("track", video, "--camera", ARUCO / "tutorial_camera_charuco.yml", "--board", BOARD, "--out", out,
                "--quiet")
    assert other.returncode == INVALID
    assert "is for 640 × 480 pictures but cockatoo.mp4 is" in other.stderr
    assert not out.exists()
    spec = run("track", *views, "--camera", ARUCO / "tutorial_camera_charuco.yml", "--board", "charuco:DICT_6X6_250:5x7",
               "--out", out)
    assert spec.returncode == USAGE and "expected charuco:DICTIONARY:COLUMNSxROWS:SQUARE:MARKER" in spec.stderr
    width = run("track", *views, "--camera", ARUCO / "tutorial_camera_charuco.yml", "--target",
                DATA / "vision" / "features" / "graf1.png", "--out", out)
    assert width.returncode == USAGE and "--target needs --width" in width.stderr
    both = run("track", *views, "--camera", ARUCO / "tutorial_camera_charuco.yml", "--board", BOARD, "--target",
               DATA / "vision" / "features" / "graf1.png", "--width", 0.3, "--out", out)
    assert both.returncode == USAGE and "either a board or a picture" in both.stderr
