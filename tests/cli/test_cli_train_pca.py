"""thespis-cli train-pca end to end on the real CMU clips: the summary a person reads, the file it
writes, and the errors for clips that cannot be used.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import re
import subprocess
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
CMU = DATA / "mocap" / "cmu"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID = 2, 3


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


@pytest.fixture(scope="module")
def clips():
    if not CMU.exists():
        pytest.fail(f"{CMU} is missing (../shared/data)")
    return [CMU / "113_21.bvh", CMU / "141_16.bvh", CMU / "02_01.bvh", f"{CMU / '77_02.bvh'}@60"]


def test_trains_both_bases_and_says_how_much_the_leading_pcs_explain(clips, tmp_path):
    out = tmp_path / "postures.pca"
    result = run("train-pca", *clips, "--skip", "1", "--out", out)
    assert result.returncode == 0, result.stderr
    assert out.read_bytes().startswith(b"THSPPCA\0")
    assert "of 4 clips" in result.stdout
    for body, dimensions in (("Whole body", 78), ("Upper body", 45)):
        line = next(l for l in result.stdout.splitlines() if l.startswith(body))
        assert f"({dimensions} dimensions)" in line
        shares = [float(x) for x in re.findall(r"([\d.]+) %", line)]
        assert len(shares) == 3 and 0 < shares[0] < shares[1] < shares[2] <= 100, line
    # The same clips give the same file.
    again = tmp_path / "again.pca"
    assert run("train-pca", *clips, "--skip", "1", "--out", again, "--quiet").returncode == 0
    assert again.read_bytes() == out.read_bytes()


def test_too_few_frames_says_so(clips, tmp_path):
    result = run("train-pca", clips[0], "--rate", "1", "--out", tmp_path / "few.pca")
    assert result.returncode == INVALID
    assert "Too few postures" in result.stderr
    assert not (tmp_path / "few.pca").exists()


def test_a_missing_clip_is_named(clips, tmp_path):
    result = run("train-pca", clips[0], tmp_path / "nowhere.bvh", "--out", tmp_path / "x.pca")
    assert result.returncode == INVALID
    assert "nowhere.bvh" in result.stderr


def test_bad_arguments_are_usage_errors(clips, tmp_path):
    assert run("train-pca", "--out", tmp_path / "x.pca").returncode == USAGE
    bad_rate = run("train-pca", f"{clips[0]}@fast", "--out", tmp_path / "x.pca")
    assert bad_rate.returncode == USAGE and "after '@'" in bad_rate.stderr
    wrong = run("train-pca", clips[0], "--out", tmp_path / "x.txt")
    assert wrong.returncode == USAGE and ".pca" in wrong.stderr
    assert "CLIP..." in run("train-pca", "--help").stdout
