"""thespis-cli run end to end: the paper's §4.5 script on the demo scenario, headless, and what
a script can do wrong (raise, name an unknown action, never end).

THESPIS_CLI names the executable (CTest sets it).
"""

import os
import signal
import subprocess
import time
from pathlib import Path

import pytest

from test_cli_render import read_png

CLI = os.environ.get("THESPIS_CLI")
REPO = Path(__file__).resolve().parents[2]
DEMO = REPO / "resources" / "demo.thespis"
PAPER_SCRIPT = REPO / "resources" / "scripts" / "antigone_creon.py"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, CANCELLED = 2, 3, 130
SMALL = ["--size", "160x90", "--samples", "0"]


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def script(tmp_path, text, name="s.py"):
    path = tmp_path / name
    path.write_text(text)
    return path


def differing_pixels(a, b):
    (_, _, rows_a), (_, _, rows_b) = read_png(a), read_png(b)
    return sum(x != y for ra, rb in zip(rows_a, rows_b) for x, y in zip(ra, rb))


def test_the_papers_script_plays_over_the_demo(tmp_path):
    out = tmp_path / "frames"
    result = run("run", DEMO, "--script", PAPER_SCRIPT, "--frames", "0:120", "--fps", "30", "--out", out, *SMALL)
    assert result.returncode == 0, result.stderr
    assert "Antigone answered Creon at" in result.stdout
    assert len(list(out.glob("frame_*.png"))) == 121
    # Creon waves live from the start (his authored wave comes at 1.5 s): the frame at 1 s differs
    # from the scenario rendered without the script, while the first frame is the same.
    plain = tmp_path / "plain"
    assert run("render", DEMO, "--frames", "0:120", "--fps", "30", "--out", plain, *SMALL).returncode == 0
    assert differing_pixels(out / "frame_00000.png", plain / "frame_00000.png") == 0
    assert differing_pixels(out / "frame_00030.png", plain / "frame_00030.png") > 200


def test_a_script_that_raises_shows_its_traceback_and_line(tmp_path):
    bad = script(tmp_path, "animService.activateAction_body('Creon', 'creon_wave')\n\nundefined_name\n")
    result = run("run", DEMO, "--script", bad)
    assert result.returncode == INVALID
    assert "Traceback" in result.stderr and "s.py, line 3: NameError" in result.stderr


def test_an_unknown_action_is_named_with_the_known_ones(tmp_path):
    bad = script(tmp_path, "animService.activateAction_body('Creon', 'creon_dance')\n")
    result = run("run", DEMO, "--script", bad)
    assert result.returncode == INVALID
    assert "creon_dance" in result.stderr and "creon_idle" in result.stderr and "creon_wave" in result.stderr
    bad = script(tmp_path, "animService.activateAction_body('Ismene', 'creon_idle')\n")
    result = run("run", DEMO, "--script", bad)
    assert "Ismene" in result.stderr and "Creon, Antigone" in result.stderr


def test_ctrl_c_stops_an_endless_script(tmp_path):
    endless = script(tmp_path, "print('looping', flush=True)\nwhile True:\n    pass\n")
    process = subprocess.Popen([CLI, "run", DEMO, "--script", endless], stdout=subprocess.PIPE,
                               stderr=subprocess.PIPE, text=True)
    assert process.stdout.readline().strip() == "looping"
    process.send_signal(signal.SIGINT)
    _, err = process.communicate(timeout=30)
    assert process.returncode == CANCELLED, err
    assert "cancelled" in err


def test_command_line_mistakes(tmp_path):
    assert run("run", DEMO).returncode == USAGE  # --script is required
    assert run("run", DEMO, "--script", tmp_path / "missing.py").returncode == INVALID
    ok = script(tmp_path, "pass\n")
    assert run("run", DEMO, "--script", ok, "--frames", "0:3").returncode == USAGE  # no --out
    assert run("run", DEMO, "--script", ok, "--out", tmp_path).returncode == USAGE  # no --frames


def test_a_script_kept_in_the_scenario_runs_by_name(tmp_path):
    result = run("run", DEMO, "--script", "antigone_creon")
    assert result.returncode == 0, result.stderr
    assert "Antigone answered Creon at" in result.stdout
    # After the act she is handed to the interaction service with her bot, found among the
    # scenario's files.
    assert "Antigone takes questions" in result.stdout
    info = run("info", DEMO)
    assert "Script 'antigone_creon'" in info.stdout
    missing = run("run", DEMO, "--script", "monologue")
    assert missing.returncode == INVALID
    assert "monologue" in missing.stderr and "antigone_creon" in missing.stderr


def test_sounds_a_script_plays_are_mixed_into_a_wav(tmp_path):
    import wave
    speech = Path(os.environ.get("THESPIS_SHARED_DATA", REPO.parent / "shared" / "data")) / "speech" / "pocketsphinx" / "cards" / "001.wav"
    talk = script(tmp_path, "\n".join([
        "animService.wait(0.5)",
        f"voiceService.activateAction('Creon', {str(speech)!r}, 1.0)",
        "animService.activateAction_body('Creon', 'creon_wave')",
        "animService.waitUntilActionFinished_body('Creon', 'creon_wave')",
    ]) + "\n")
    out, audio = tmp_path / "frames", tmp_path / "speech.wav"
    result = run("run", DEMO, "--script", talk, "--frames", "0:59", "--out", out, "--audio", audio, *SMALL)
    assert result.returncode == 0, result.stderr
    with wave.open(str(audio)) as w:
        assert (w.getnchannels(), w.getsampwidth(), w.getframerate()) == (1, 2, 48000)
        assert w.getnframes() == 96000  # the 60 frames at 30 fps: 2 s
        samples = w.readframes(w.getnframes())
    values = [int.from_bytes(samples[i:i + 2], "little", signed=True) for i in range(0, len(samples), 2)]
    assert max(map(abs, values[:24000])) == 0  # silence until the voice starts at 0.5 s
    assert max(map(abs, values[24000:])) > 1000  # then the speech
    missing = script(tmp_path, "voiceService.activateAction('Creon', 'no_such.wav', 1.0)\n", "m.py")
    bad = run("run", DEMO, "--script", missing)
    assert bad.returncode == INVALID and "no_such.wav" in bad.stderr


def test_the_demo_characters_say_their_lines_in_the_papers_script(tmp_path):
    import wave
    out, audio = tmp_path / "frames", tmp_path / "voices.wav"
    result = run("run", DEMO, "--script", "antigone_creon", "--frames", "0:89", "--fps", "30", "--out", out,
                 "--audio", audio, *SMALL)
    assert result.returncode == 0, result.stderr
    with wave.open(str(audio)) as w:
        samples = w.readframes(w.getnframes())
    values = [int.from_bytes(samples[i:i + 2], "little", signed=True) for i in range(0, len(samples), 2)]
    # Creon's line (voiceService.activateAction with his speech line, spoken by espeak-ng) from the start.
    assert max(map(abs, values[:48000])) > 1000
    assert "Antigone answered Creon at" in result.stdout


def test_a_character_told_to_look_at_the_camera_looks_at_the_one_rendering(tmp_path):
    # Headless, the render's camera is the camera: Creon's eyes and head turn to it, where with no
    # camera known his gaze would wait and stay at nothing.
    look = script(tmp_path, "\n".join([
        "animService.gaze_body('Creon', 'camera', influence='HEAD', saccades=False)",
        "animService.wait(1.5)",
        "state = animService.gaze_state('Creon')",
        "print('neck', *('%.2f' % v for v in state['neck']), 'eyes', *('%.2f' % v for v in state['eyes']))",
    ]) + "\n")
    result = run("run", DEMO, "--script", look, "--frames", "0:59", "--out", tmp_path / "frames", *SMALL)
    assert result.returncode == 0, result.stderr
    words = next(line for line in result.stdout.splitlines() if line.startswith("neck")).split()
    neck, eyes = (float(words[1]), float(words[2])), (float(words[4]), float(words[5]))
    # The demo's camera frames both from in front: Creon, turned towards Antigone, turns his
    # head and eyes back toward it.
    assert abs(neck[0]) + abs(eyes[0]) > 5, (neck, eyes)
