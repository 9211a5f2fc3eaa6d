"""thespis-cli play end to end: the demo played on its own to a small video, and the command line
mistakes a user makes (a video without its camera, a board without a video, a wrong extension).
The demo over real footage of a board is PlayJob's test (tests/core/play_job_test.cpp), which
writes the footage first.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
DEMO = Path(__file__).resolve().parents[2] / "resources" / "demo.thespis"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID = 2, 3


def run(*args, timeout=600):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def test_the_demo_plays_to_a_video(tmp_path):
    out = tmp_path / "demo.mp4"
    result = run("play", DEMO, "--out", out, "--size", "160x90", "--fps", 4, "--samples", 0)
    assert result.returncode == 0, result.stderr
    assert "Played demo.thespis:" in result.stdout and "frames at 4 fps" in result.stdout
    assert out.stat().st_size > 1000
    assert not (tmp_path / "demo.partial.mp4").exists()


def test_mistakes_say_what_is_wrong(tmp_path):
    video = DATA / "vision" / "video" / "cockatoo.mp4"
    no_camera = run("play", DEMO, "--video", video, "--board", "aruco-grid:DICT_4X4_50:4x3:0.04:0.01", "--out",
                    tmp_path / "a.mp4")
    assert no_camera.returncode == USAGE and "--video needs --camera" in no_camera.stderr
    no_video = run("play", DEMO, "--board", "aruco-grid:DICT_4X4_50:4x3:0.04:0.01", "--out", tmp_path / "a.mp4")
    assert no_video.returncode == USAGE and "go with --video" in no_video.stderr
    extension = run("play", DEMO, "--out", tmp_path / "a.mov")
    assert extension.returncode == USAGE and "written as .mp4 or .avi" in extension.stderr
    other_size = run("play", DEMO, "--video", video, "--camera", DATA / "vision" / "aruco_real" / "tutorial_camera_charuco.yml",
                     "--board", "charuco:DICT_6X6_250:5x7:0.04:0.02", "--out", tmp_path / "a.mp4", "--quiet")
    assert other_size.returncode == INVALID and "is for 640 × 480 pictures but cockatoo.mp4 is" in other_size.stderr
    assert not (tmp_path / "a.mp4").exists()
