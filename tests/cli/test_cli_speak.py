"""Speech end to end through thespis-cli (issues 32, 33): a character says tagged text with `speak`,
the line goes into the scenario with its visemes, close-ups show the lips shut on the "m" of
"hmm" and open on "ah" (saved under <build>/test-artifacts/speech/ for people to look at), and
`play --audio` puts the line's audio where it is on the timeline.

THESPIS_CLI names the executable (CTest sets it).
"""

import json
import os
import subprocess
import wave
from pathlib import Path

import pytest

from pictures import read_png

CLI = os.environ.get("THESPIS_CLI")
RESOURCES = Path(__file__).resolve().parents[2] / "resources"
ARTIFACTS = Path(os.environ.get("THESPIS_TEST_ARTIFACTS", "test-artifacts")) / "speech"
TICKS = 705600000

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)


def cli(*args):
    done = subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return done.stdout


def srgb(linear):
    return [round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055)) for c in linear]


MOUTH = srgb([0.16, 0.03, 0.03])


def count_colour(picture, colour, tolerance=12):
    width, height, rows = picture
    return sum(1 for y in range(height) for x in range(width)
               if all(abs(rows[y][4 * x + c] - colour[c]) <= tolerance for c in range(3)))


def face_only(path):
    """The built-in humanoid standing still, nothing else: its face is all the speech's."""
    character = {"schema": "Character.6", "name": "Face", "skeleton": "hanim-25", "clips": [], "layers": []}
    path.write_text(json.dumps({"format": "thespis-scenario", "version": 9, "schema": "Scenario.9", "name": "face",
                                "duration": 3 * TICKS, "masks": [], "characters": [character]}))
    return path


def phoneme_middle(scenario, phoneme, nth=0):
    line = json.loads(scenario.read_text())["characters"][0]["speech"][0]
    found = [p for p in line["phonemes"] if p["phoneme"] == phoneme][nth]
    return line["start"] / TICKS + (found["start"] + found["end"]) / 2


def test_hmm_shuts_the_lips_and_ah_opens_them(tmp_path):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    spoken = tmp_path / "spoken.thespis"
    out = cli("speak", face_only(tmp_path / "face.thespis"), "--character", "Face", "--text", "Hmm. Ah.", "--at", 0.5,
              "--out", tmp_path / "hmm_ah.wav", "--scenario-out", spoken)
    assert "Face says 2 words" in out
    line = json.loads(spoken.read_text())["characters"][0]["speech"][0]
    assert line["audio"] == "hmm_ah.wav" and line["text"] == "Hmm. Ah."
    pictures = {}
    for name, time in (("hmm", phoneme_middle(spoken, "M")), ("ah", phoneme_middle(spoken, "AA")), ("rest", 0.2)):
        out = ARTIFACTS / f"{name}.png"
        cli("render", spoken, "--out", out, "--time", time, "--close-up", "Face", "--azimuth", 0, "--elevation", 0,
            "--size", "320x320", "--no-ground", "--shading", "unlit", "--quiet")
        cli("render", spoken, "--out", ARTIFACTS / f"{name}_lit.png", "--time", time, "--close-up", "Face",
            "--azimuth", 0, "--elevation", 0, "--size", "320x320", "--no-ground", "--quiet")
        pictures[name] = count_colour(read_png(out), MOUTH)
    assert pictures["rest"] == 0 and pictures["hmm"] == 0, pictures
    assert pictures["ah"] > 40, pictures


def test_play_puts_the_lines_audio_where_it_is_on_the_timeline(tmp_path):
    spoken = tmp_path / "spoken.thespis"
    cli("speak", face_only(tmp_path / "face.thespis"), "--character", "Face", "--text", "Hello there.", "--at", 1.0,
        "--out", tmp_path / "hello.wav", "--scenario-out", spoken)
    cli("play", spoken, "--out", tmp_path / "played.mp4", "--audio", "--size", "160x120",
        "--quiet")
    with wave.open(str(tmp_path / "played.wav")) as played:
        rate = played.getframerate()
        samples = played.readframes(played.getnframes())
    values = [int.from_bytes(samples[i:i + 2], "little", signed=True) for i in range(0, len(samples), 2)]

    def loudness(start, end):
        window = values[int(start * rate):int(end * rate)]
        return (sum(v * v for v in window) / max(len(window), 1)) ** 0.5

    assert loudness(0.0, 0.95) < 50, "silence before the line"
    assert loudness(1.0, 1.8) > 500, "the line from 1 s"


def test_a_tagged_gesture_lands_on_the_gestures_layer_spanning_its_words(tmp_path):
    """Issue 33: `speak --text` with a body gesture tagged round "my good friend" puts the
    gesticon's greet on Creon's Gestures layer, fading in before "my" and out after "friend"."""
    spoken = tmp_path / "spoken.thespis"
    out = cli("speak", RESOURCES / "demo.thespis", "--character", "Creon", "--text",
              'Listen, <begin_gesture id="g1" anim="greet"/>my good friend<end_gesture id="g1"/> today.',
              "--at", 0.5, "--out", tmp_path / "greet.wav", "--scenario-out", spoken)
    assert "1 body gestures" in out, out
    creon = next(c for c in json.loads(spoken.read_text())["characters"] if c["name"] == "Creon")
    layer = next(layer for layer in creon["layers"] if layer["name"] == "Gestures")
    [action] = layer["actions"]
    greet = next(g for g in creon["gestures"] if g["name"] == "greet")
    assert action["name"] == "g1 greet" and action["clip"] == greet["clip"]
    line = creon["speech"][-1]
    words = {w["text"]: (line["start"] + w["start"] * TICKS, line["start"] + w["end"] * TICKS) for w in line["words"]}
    clip = next(c for c in creon["clips"] if c["name"] == greet["clip"])
    [stretch] = [m for m in action["modifiers"] if m["kind"] == "timeStretch"]
    length = (len(clip["frames"]) - 1) / clip["frameRate"] * stretch["factor"] * TICKS
    frame = TICKS / 30
    assert abs(action["start"] - (words["my"][0] - greet["fadeIn"])) <= frame
    assert abs(action["start"] + length - (words["friend"][1] + greet["fadeOut"])) <= frame
    assert action["weight"]["fadeIn"] == pytest.approx(greet["fadeIn"] / TICKS)
    assert action["weight"]["fadeOut"] == pytest.approx(greet["fadeOut"] / TICKS)
    assert any(m["kind"] == "dependentJointFilter" for m in action["modifiers"]), "the entry's band filters it"
