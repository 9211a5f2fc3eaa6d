"""thespis-cli render end to end: the demo scenario as single frames and sequences in each
shading, a scenario bake used for PRT, and the errors a user can make. Headless: EGL on Mesa.

THESPIS_CLI names the executable (CTest sets it).
"""

import os
import subprocess
from pathlib import Path

import pytest

from pictures import read_png

CLI = os.environ.get("THESPIS_CLI")
DEMO = Path(__file__).resolve().parents[2] / "resources" / "demo.thespis"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, FAILURE = 2, 3, 4


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def test_renders_the_demo_in_every_shading(tmp_path):
    pictures = {}
    for shading in ("prt", "phong", "unlit"):
        out = tmp_path / f"demo_{shading}.png"
        result = run("render", DEMO, "--time", "2", "--size", "160x90", "--shading", shading, "--out", out)
        assert result.returncode == 0, result.stderr
        assert f"(160x90, {shading})" in result.stdout
        width, height, rows = read_png(out)
        assert (width, height) == (160, 90)
        # The top rows are the background above the characters; the middle holds them.
        background = rows[0][0:4]
        assert all(rows[1][x * 4:x * 4 + 4] == background for x in range(width))
        middle = rows[height // 2]
        assert sum(middle[x * 4:x * 4 + 4] != background for x in range(width)) > 5
        pictures[shading] = b"".join(rows)
    assert len(set(pictures.values())) == 3, "the three shadings must look different"


def test_renders_a_numbered_sequence(tmp_path):
    out = tmp_path / "frames"
    result = run("render", DEMO, "--frames", "3:6", "--fps", "10", "--size", "64x36", "--out", out)
    assert result.returncode == 0, result.stderr
    assert sorted(p.name for p in out.iterdir()) == [f"frame_{i:05d}.png" for i in range(3, 7)]
    assert "Rendered 4 frames" in result.stdout
    assert "render: 4/4 frames (100%)" in result.stderr  # plain progress lines off a terminal


def test_a_scenario_bake_lights_its_character(tmp_path):
    bake = tmp_path / "creon.prt"
    baked = run("bake", DEMO, "--character", "Creon", "--order", "3", "--rays", "16", "--out", bake, "--quiet")
    assert baked.returncode == 0, baked.stderr
    plain, lit = tmp_path / "plain.png", tmp_path / "lit.png"
    assert run("render", DEMO, "--time", "2", "--size", "96x54", "--out", plain).returncode == 0
    result = run("render", DEMO, "--time", "2", "--size", "96x54", "--bake", bake, "--character", "Creon", "--out", lit)
    assert result.returncode == 0, result.stderr
    assert read_png(plain)[2] != read_png(lit)[2], "shadowed transfer must change the picture"


def test_errors_name_the_problem(tmp_path):
    out = tmp_path / "x.png"
    bad_size = run("render", DEMO, "--size", "wide", "--out", out)
    assert bad_size.returncode == USAGE and "--size must be WIDTHxHEIGHT" in bad_size.stderr
    both = run("render", DEMO, "--time", "1", "--frames", "0:2", "--out", tmp_path)
    assert both.returncode == USAGE and "either --time or --frames" in both.stderr
    missing = run("render", tmp_path / "nowhere.thespis", "--out", out)
    assert missing.returncode == INVALID and "nowhere.thespis" in missing.stderr
    no_folder = run("render", DEMO, "--out", tmp_path / "no" / "x.png")
    assert no_folder.returncode == INVALID and "does not exist" in no_folder.stderr
    garbage = tmp_path / "garbage.prt"
    garbage.write_bytes(b"not a bake")
    bad_bake = run("render", DEMO, "--bake", garbage, "--character", "Creon", "--out", out)
    assert bad_bake.returncode == INVALID and "garbage.prt" in bad_bake.stderr
    several = run("render", DEMO, "--bake", garbage, "--out", out)
    assert several.returncode == USAGE and "--character" in several.stderr
    assert not out.exists()
