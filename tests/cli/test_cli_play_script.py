"""thespis-cli play with a script and its sound (the headless player): the script drives the
clock, the video shows its live actions and lasts as long as it plays, its sounds are written to
a WAV beside the video; the same from a package, by the name of a script the package keeps; and
`run` on a package.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import subprocess
import wave
from pathlib import Path

import numpy as np
import pytest

import thespis

CLI = os.environ.get("THESPIS_CLI")
REPO = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", REPO.parent / "shared" / "data"))
DEMO = REPO / "resources" / "demo.thespis"
SPEECH = DATA / "speech" / "pocketsphinx" / "cards" / "001.wav"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, CANCELLED = 2, 3, 130
SMALL = ["--size", "160x90", "--samples", "0"]
FPS = 10


def run(*args, timeout=600):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def frames_of(video):
    return [(frame.time, np.asarray(frame.image, dtype=np.int16)) for frame in thespis.ar.open_video(video)]


def changed_pixels(a, b):
    """Pixels where a channel differs by more than JPEG noise."""
    return int((np.abs(a - b).max(axis=2) > 40).sum())


def talking_script(tmp_path, speech):
    path = tmp_path / "talk.py"
    path.write_text("\n".join([
        "animService.wait(0.5)",
        f"voiceService.activateAction('Creon', {str(speech)!r}, 1.0)",
        "animService.activateAction_body('Creon', 'creon_wave')",
        "animService.waitUntilActionFinished_body('Creon', 'creon_wave')",
        "print('Creon waved until', round(animService.now(), 3))",
    ]) + "\n")
    return path


def test_a_script_plays_along_with_its_voice(tmp_path):
    demo_seconds = thespis.load_scenario(DEMO).duration_seconds
    talk = talking_script(tmp_path, SPEECH)
    out = tmp_path / "talk.avi"  # Motion JPEG: a frame's picture does not depend on the others
    result = run("play", DEMO, "--script", talk, "--audio", "--out", out, "--fps", FPS, *SMALL)
    assert result.returncode == 0, result.stderr
    assert "Creon waved until" in result.stdout
    assert "1 sound played" in result.stdout and str(tmp_path / "talk.wav") in result.stdout

    played = frames_of(out)
    plain_out = tmp_path / "plain.avi"
    assert run("play", DEMO, "--out", plain_out, "--fps", FPS, *SMALL).returncode == 0
    plain = frames_of(plain_out)
    # The script ends before the scenario does: the video is the scenario's length.
    assert len(played) == len(plain) == int(demo_seconds * FPS) + 1
    # Before the script acts the pictures are the scenario's; once Creon waves live they are not.
    assert all(np.array_equal(p[1], q[1]) for p, q in zip(played[:5], plain[:5]))
    assert max(changed_pixels(p[1], q[1]) for p, q in zip(played[6:20], plain[6:20])) > 30

    # The voice, beside the video, as long as it: silent until 0.5 s, then the recording.
    with wave.open(str(tmp_path / "talk.wav")) as w:
        assert (w.getnchannels(), w.getsampwidth(), w.getframerate()) == (1, 2, 48000)
        assert w.getnframes() == round(len(played) / FPS * 48000)
        samples = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2")
    with wave.open(str(SPEECH)) as w:
        recorded = w.getnframes() / w.getframerate()
    assert np.abs(samples[:24000]).max() == 0
    assert np.abs(samples[24000:24000 + int(recorded * 48000)]).max() > 1000
    assert np.abs(samples[24000 + int(recorded * 48000) + 480:]).max() == 0


def test_a_script_longer_than_the_scenario_makes_the_video_longer(tmp_path):
    demo_seconds = thespis.load_scenario(DEMO).duration_seconds
    longer = tmp_path / "longer.py"
    longer.write_text(f"animService.wait({demo_seconds + 1.5})\n")
    out = tmp_path / "longer.mp4"
    result = run("play", DEMO, "--script", longer, "--out", out, "--fps", FPS, "--quiet", *SMALL)
    assert result.returncode == 0, result.stderr
    assert len(frames_of(out)) == int((demo_seconds + 1.5) * FPS) + 1


def test_a_package_plays_its_kept_script(tmp_path):
    package = tmp_path / "demo.thespkg"
    assert run("export", DEMO, "--out", package, "--quiet").returncode == 0
    out = tmp_path / "from_package.avi"
    result = run("play", package, "--script", "antigone_creon", "--out", out, "--fps", FPS, *SMALL)
    assert result.returncode == 0, result.stderr
    assert "Antigone answered Creon at" in result.stdout
    beside = tmp_path / "from_folder.avi"
    assert run("play", DEMO, "--script", "antigone_creon", "--out", beside, "--fps", FPS, "--quiet", *SMALL).returncode == 0
    a, b = frames_of(out), frames_of(beside)
    assert len(a) == len(b) and all(np.array_equal(p[1], q[1]) for p, q in zip(a, b))
    ran = run("run", package, "--script", "antigone_creon")
    assert ran.returncode == 0, ran.stderr
    assert "Antigone answered Creon at" in ran.stdout


def test_a_script_that_raises_leaves_no_video(tmp_path):
    bad = tmp_path / "bad.py"
    bad.write_text("animService.wait(1.0)\nundefined_name\n")
    out = tmp_path / "bad.mp4"
    result = run("play", DEMO, "--script", bad, "--audio", "--out", out, "--fps", FPS, *SMALL)
    assert result.returncode == INVALID
    assert "bad.py, line 2" in result.stderr and "NameError" in result.stderr
    assert not out.exists() and not (tmp_path / "bad.wav").exists()
    missing = run("play", DEMO, "--script", "monologue", "--out", out)
    assert missing.returncode == INVALID and "antigone_creon" in missing.stderr
