"""thespis-cli end to end: help, exit codes, messages, baking the demo to BVH, progress, Ctrl-C.

THESPIS_CLI names the executable (CTest sets it); the baked BVH files are read back with the
`thespis` Python package to check what was written.
"""

import json
import os
import pty
import select
import signal
import subprocess
import time
from pathlib import Path

import numpy as np
import pytest

import thespis

REPO = Path(__file__).resolve().parents[2]
DEMO = REPO / "resources" / "demo.thespis"
CLI = os.environ.get("THESPIS_CLI")

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, FAILURE, CANCELLED = 2, 3, 4, 130


def run(*args, env=None, timeout=120):
    full_env = dict(os.environ, **(env or {}))
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout, env=full_env)


@pytest.fixture
def demo():
    if not DEMO.exists():
        pytest.fail(f"the demo scenario {DEMO} is not in this checkout yet")
    return DEMO


@pytest.fixture
def demo_document(demo):
    return json.loads(demo.read_text())


def write_scenario(folder: Path, document) -> Path:
    path = folder / "edited.thespis"
    path.write_text(json.dumps(document))
    return path


# --- help and command line ----------------------------------------------------------------------

@pytest.mark.parametrize("command", ["validate", "bake-motion", "info"])
def test_every_subcommand_has_help(command):
    for flag in ("--help", "-h"):
        result = run(command, flag)
        assert result.returncode == 0, result.stderr
        assert result.stdout.startswith(f"Usage: thespis-cli {command} SCENARIO")
        assert "--help" in result.stdout
    assert run("help", command).stdout == run(command, "--help").stdout


def test_main_help_and_version():
    result = run("--help")
    assert result.returncode == 0
    for command in ("validate", "bake-motion", "info"):
        assert command in result.stdout
    version = run("--version")
    assert version.returncode == 0 and version.stdout.strip() == f"thespis-cli {thespis.__version__}"


def test_usage_errors_exit_2_and_show_usage():
    nothing = run()
    assert nothing.returncode == USAGE and "Usage:" in nothing.stderr
    unknown = run("frobnicate")
    assert unknown.returncode == USAGE and "unknown command 'frobnicate'" in unknown.stderr
    bad_option = run("validate", "x.thespis", "--colour")
    assert bad_option.returncode == USAGE
    assert "unknown option '--colour'" in bad_option.stderr
    assert "Usage: thespis-cli validate SCENARIO" in bad_option.stderr
    missing = run("bake-motion", "x.thespis", "--out", "a.bvh")
    assert missing.returncode == USAGE and "missing --character NAME" in missing.stderr
    no_value = run("bake-motion", "x.thespis", "--character")
    assert no_value.returncode == USAGE and "needs a value" in no_value.stderr


def test_bad_numbers_and_ranges_are_usage_errors(demo, tmp_path):
    out = tmp_path / "x.bvh"
    fps = run("bake-motion", demo, "--character", "Creon", "--out", out, "--fps", "fast")
    assert fps.returncode == USAGE and "--fps must be a number, not 'fast'" in fps.stderr
    negative = run("bake-motion", demo, "--character", "Creon", "--out", out, "--fps", "-5")
    assert negative.returncode == USAGE and "positive" in negative.stderr
    backwards = run("bake-motion", demo, "--character", "Creon", "--out", out, "--start", "4", "--end", "2")
    assert backwards.returncode == USAGE and "before --start" in backwards.stderr
    not_bvh = run("bake-motion", demo, "--character", "Creon", "--out", tmp_path / "x.fbx")
    assert not_bvh.returncode == USAGE and ".bvh" in not_bvh.stderr
    assert not out.exists()


# --- validate -------------------------------------------------------------------------------------

def test_validate_the_demo(demo):
    result = run("validate", demo)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "valid" in result.stdout


def test_validate_a_malformed_field(demo_document, tmp_path):
    demo_document["characters"][0]["layers"][0]["actions"][0]["start"] = "soon"
    result = run("validate", write_scenario(tmp_path, demo_document))
    assert result.returncode == INVALID
    assert "characters[0].layers[0].actions[0].start" in result.stderr
    assert "corrupt data" in result.stderr


def test_validate_reports_character_action_and_field(demo_document, tmp_path):
    character = demo_document["characters"][0]
    action = character["layers"][0]["actions"][0]
    action["clip"] = "no_such_clip"
    result = run("validate", write_scenario(tmp_path, demo_document))
    assert result.returncode == INVALID
    report = result.stdout
    assert "no_such_clip" in report and character["name"] in report and action["name"] in report
    assert "clip" in report
    assert "not valid" in result.stderr


def test_validate_lists_every_problem(demo_document, tmp_path):
    layer = demo_document["characters"][0]["layers"][0]
    layer["actions"][0]["clip"] = "first_missing"
    layer["actions"][1]["mask"] = "second_missing"
    result = run("validate", write_scenario(tmp_path, demo_document))
    assert result.returncode == INVALID
    assert "first_missing" in result.stdout and "second_missing" in result.stdout


def test_validate_a_missing_or_foreign_file(tmp_path):
    missing = run("validate", tmp_path / "absent.thespis")
    assert missing.returncode == INVALID and "does not exist" in missing.stderr
    newer = tmp_path / "newer.thespis"
    newer.write_text(json.dumps({"format": "thespis-scenario", "version": 999}))
    result = run("validate", newer)
    assert result.returncode == INVALID and "newer" in result.stderr


def test_info_lists_the_demo(demo, demo_document):
    result = run("info", demo)
    assert result.returncode == 0
    for character in demo_document["characters"]:
        assert f"Character '{character['name']}'" in result.stdout
        for clip in character["clips"]:
            assert f"clip '{clip['name']}'" in result.stdout


# --- bake-motion ----------------------------------------------------------------------------------

def test_bake_the_demo_to_bvh(demo, tmp_path):
    scenario = thespis.load_scenario(demo)
    runtime = thespis.build_runtime(scenario, demo.parent)
    name = scenario.characters[0].name
    out = tmp_path / "baked.bvh"
    fps = 30
    result = run("bake-motion", demo, "--character", name, "--fps", fps, "--out", out)
    assert result.returncode == 0, result.stderr
    expected_frames = round(runtime.duration * fps) + 1
    assert f"Baked {expected_frames} frames" in result.stdout and str(out) in result.stdout

    skeleton, clip, report = thespis.bvh.load(out)
    assert report.frame_count == clip.frame_count == expected_frames
    assert report.frame_time == pytest.approx(1.0 / fps)
    character = runtime.find_character(name)
    # The same joints (BVH lists them depth first, so the order may differ), and H-Anim names
    # map onto themselves.
    assert sorted(j.source_name for j in skeleton.joints) == sorted(character.skeleton.joint_names)
    assert sorted(skeleton.joint_names) == sorted(character.skeleton.joint_names)
    order = [skeleton.find(name) for name in character.skeleton.joint_names]

    # The written motion is the schedule's: compare world positions at a few frame times.
    for frame in (0, expected_frames // 3, expected_frames // 2, expected_frames - 1):
        t = frame / fps
        expected = character.skeleton.world_positions(character.body.evaluate(t))
        got = skeleton.world_positions(clip.frame(frame))[order]
        np.testing.assert_allclose(got, expected, atol=1e-4, err_msg=f"frame {frame}")
    assert [p.name for p in tmp_path.iterdir()] == ["baked.bvh"]


def test_bake_a_range_at_another_rate(demo, tmp_path):
    name = thespis.load_scenario(demo).characters[-1].name
    out = tmp_path / "part.bvh"
    result = run("bake-motion", demo, "--character", name, "--out", out, "--fps", 24, "--start", 1, "--end", 3.5,
                 "--quiet")
    assert result.returncode == 0, result.stderr
    assert result.stdout == "" and result.stderr == ""
    _, clip, report = thespis.bvh.load(out)
    assert clip.frame_count == 2.5 * 24 + 1
    assert report.frame_time == pytest.approx(1 / 24)


def test_unknown_character_is_a_clear_error(demo, tmp_path):
    out = tmp_path / "x.bvh"
    result = run("bake-motion", demo, "--character", "Nobody", "--out", out)
    assert result.returncode == INVALID
    assert "no character named 'Nobody'" in result.stderr
    for character in thespis.load_scenario(demo).characters:
        assert character.name in result.stderr
    assert not out.exists()


def test_missing_output_folder(demo, tmp_path):
    name = thespis.load_scenario(demo).characters[0].name
    result = run("bake-motion", demo, "--character", name, "--out", tmp_path / "no" / "x.bvh")
    assert result.returncode == INVALID and "does not exist" in result.stderr


def test_plain_progress_lines_when_not_on_a_terminal(demo, tmp_path):
    name = thespis.load_scenario(demo).characters[0].name
    result = run("bake-motion", demo, "--character", name, "--out", tmp_path / "x.bvh", "--fps", 10, "--end", 2)
    assert result.returncode == 0
    lines = result.stderr.splitlines()
    assert lines[-1] == "bake-motion: 21/21 frames (100%)"
    assert all(line.startswith("bake-motion: ") for line in lines) and "\r" not in result.stderr


def test_progress_bar_on_a_terminal(demo, tmp_path):
    name = thespis.load_scenario(demo).characters[0].name
    master, slave = pty.openpty()
    process = subprocess.Popen([CLI, "bake-motion", str(demo), "--character", name, "--out", str(tmp_path / "x.bvh"),
                                "--fps", "10", "--end", "2"], stdout=subprocess.DEVNULL, stderr=slave)
    os.close(slave)
    output = b""
    while True:
        ready, _, _ = select.select([master], [], [], 30)
        if not ready:
            break
        try:
            chunk = os.read(master, 4096)
        except OSError:  # the pty closes when the process exits
            break
        if not chunk:
            break
        output += chunk
    os.close(master)
    assert process.wait(timeout=30) == 0
    text = output.decode()
    assert "\r[" in text and "] 100% 21/21 frames" in text
    assert "bake-motion: " not in text  # bar, not plain lines


def test_ctrl_c_cancels_without_writing(demo, tmp_path):
    name = thespis.load_scenario(demo).characters[0].name
    out = tmp_path / "cancelled.bvh"
    # Slow each frame down (a testing aid of thespis-cli) so the bake is still running when
    # the interrupt arrives: 121 frames × 20 ms ≈ 2.4 s.
    env = dict(os.environ, THESPIS_CLI_FRAME_DELAY_MS="20")
    process = subprocess.Popen([CLI, "bake-motion", str(demo), "--character", name, "--out", str(out), "--fps", "10",
                                "--end", "12"], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    first = process.stderr.readline()  # the first progress line: the bake loop is running
    assert first.startswith("bake-motion: "), first
    process.send_signal(signal.SIGINT)
    stdout, stderr = process.communicate(timeout=30)
    assert process.returncode == CANCELLED, stderr
    assert "cancelled" in stderr and "was not written" in stderr
    assert not out.exists()
    assert list(tmp_path.iterdir()) == []  # no temporary file either
    assert "Baked" not in stdout
