"""BML and gaze through thespis-cli (issue 33): `speak --bml` puts a block's speech, gesture, nod,
raised brows and gaze on the demo's timeline, `info` lists them, and close-ups of the built-in
humanoid looking to its left, to its right and into the camera (saved under
<build>/test-artifacts/gaze/ for people to look at) show its pupils where it looks.

THESPIS_CLI names the executable (CTest sets it).
"""

import json
import os
import subprocess
from pathlib import Path

import pytest

from pictures import read_png

CLI = os.environ.get("THESPIS_CLI")
RESOURCES = Path(__file__).resolve().parents[2] / "resources"
ARTIFACTS = Path(os.environ.get("THESPIS_TEST_ARTIFACTS", "test-artifacts")) / "gaze"
TICKS = 705600000

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)


def run(*args):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=300)


def cli(*args):
    done = run(*args)
    assert done.returncode == 0, done.stderr
    return done.stdout


GREETING = """<bml id="greet" characterId="Creon">
  <speech id="s1"><text>Hear me, <sync id="t1"/>Antigone.</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <head id="h1" lexeme="NOD" start="g1:stroke + 0.2"/>
  <faceLexeme id="f1" lexeme="RAISE_BROWS" start="s1:start" end="s1:end"/>
  <gaze id="z1" target="Antigone" influence="HEAD" start="s1:start" end="s1:end"/>
</bml>
"""


def layers_of(scenario, character):
    found = next(c for c in json.loads(Path(scenario).read_text())["characters"] if c["name"] == character)
    return {layer["name"]: layer for layer in found["layers"]}


def test_speak_bml_puts_every_behaviour_on_its_layer(tmp_path):
    block = tmp_path / "greet.xml"
    block.write_text(GREETING)
    out = tmp_path / "greeted.thespis"
    said = cli("speak", RESOURCES / "demo.thespis", "--character", "Creon", "--bml", block, "--at", 2,
               "--voice", "en-gb", "--scenario-out", out)
    assert 'Inserted BML block "greet"' in said and "1 gesture(s), 1 head gesture(s), 1 face lexeme(s), 1 gaze(s)" in said
    layers = layers_of(out, "Creon")
    gaze = layers["Gaze"]
    assert gaze["kind"] == "gaze"
    look = gaze["actions"][0]
    assert look["gaze"]["target"] == "Antigone" and look["gaze"]["influence"] == "HEAD"
    assert look["start"] == 2 * TICKS and "clip" not in look
    assert layers["Head"]["mode"] == "additive" and layers["Face lexemes"]["kind"] == "face"
    assert any(a["name"] == "g1 agree" for a in layers["Gestures"]["actions"])
    speech = next(c for c in json.loads(out.read_text())["characters"] if c["name"] == "Creon")["speech"]
    assert speech[-1]["name"] == "s1" and speech[-1]["text"] == "Hear me, Antigone."
    # The gaze ends with the speech, on the word timing espeak-ng gave.
    words = speech[-1]["words"]
    stretch = look["modifiers"][0]["factor"]
    assert abs(stretch - words[-1]["end"]) < 0.25, (stretch, words)
    info = cli("info", out)
    assert "layer 'Gaze' (gaze, normalized): 1 action" in info and "looks at 'Antigone' (HEAD) from 2.000 s" in info
    assert cli("validate", out).strip() != ""


def test_speak_bml_keeps_where_a_pointing_gesture_points(tmp_path):
    block = tmp_path / "point.xml"
    block.write_text('<bml id="show"><pointing id="p1" target="Antigone" mode="RIGHT_HAND"/></bml>')
    out = tmp_path / "pointed.thespis"
    said = cli("speak", RESOURCES / "demo.thespis", "--character", "Creon", "--bml", block, "--at", 1.5,
               "--scenario-out", out)
    assert "1 gesture(s)" in said
    point = layers_of(out, "Creon")["Gestures"]["actions"][-1]
    assert point["clip"] == "point" and point["start"] == int(1.5 * TICKS)
    assert point["pointing"] == {"target": "Antigone", "hand": "RIGHT_HAND"}
    assert "action 'p1 point' points at 'Antigone' (RIGHT_HAND)" in cli("info", out)
    assert cli("validate", out).strip() != ""


def test_bml_errors_name_the_line_and_column(tmp_path):
    block = tmp_path / "bad.xml"
    block.write_text('<bml id="b">\n  <gesture id="g1" lexeme="JUGGLE"/>\n</bml>\n')
    done = run("speak", RESOURCES / "demo.thespis", "--character", "Creon", "--bml", block,
               "--scenario-out", tmp_path / "never.thespis")
    assert done.returncode == 3, done.stderr
    assert "line 2, column 3" in done.stderr and "JUGGLE" in done.stderr
    assert not (tmp_path / "never.thespis").exists()
    block.write_text("Hello there.")
    done = run("speak", RESOURCES / "demo.thespis", "--character", "Creon", "--bml", block,
               "--scenario-out", tmp_path / "never.thespis")
    assert done.returncode == 2 and "is not BML" in done.stderr


def face_only(path):
    """The built-in humanoid standing still at the origin, facing the camera of a close-up."""
    character = {"schema": "Character.6", "name": "Face", "skeleton": "hanim-25", "clips": [], "layers": []}
    path.write_text(json.dumps({"format": "thespis-scenario", "version": 9, "schema": "Scenario.9", "name": "face",
                                "duration": 3 * TICKS, "masks": [], "characters": [character]}))
    return path


SCLERA = [231, 228, 223]  # sRGB of the eyes' whites, unlit
PUPIL = [26, 26, 26]


def centroid_x(picture, colour, tolerance=10):
    width, height, rows = picture
    xs = [x for y in range(height) for x in range(width)
          if all(abs(rows[y][4 * x + c] - colour[c]) <= tolerance for c in range(3))]
    assert len(xs) > 10, f"hardly any pixel of {colour}"
    return sum(xs) / len(xs)


def test_close_ups_show_the_eyes_looking_left_right_and_into_the_camera(tmp_path):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    face = face_only(tmp_path / "face.thespis")
    # The character faces +z: its left is +x, which a camera in front shows on the picture's right.
    targets = {"camera": "camera", "left": "1.2 1.55 1.5", "right": "-1.2 1.55 1.5"}
    pupils = {}
    for name, target in targets.items():
        block = tmp_path / f"{name}.xml"
        block.write_text(f'<bml id="look"><gaze id="z" target="{target}" influence="EYES" start="0" end="2.5"/></bml>')
        looking = tmp_path / f"{name}.thespis"
        cli("speak", face, "--character", "Face", "--bml", block, "--scenario-out", looking, "--quiet")
        picture = ARTIFACTS / f"look_{name}.png"
        # Big enough for the pupils to be a few hundred pixels.
        cli("render", looking, "--out", picture, "--time", 1.5, "--close-up", "Face", "--azimuth", 0,
            "--elevation", 0, "--size", "960x960", "--no-ground", "--shading", "unlit", "--samples", 0, "--quiet")
        cli("render", looking, "--out", ARTIFACTS / f"look_{name}_lit.png", "--time", 1.5, "--close-up", "Face",
            "--azimuth", 0, "--elevation", 0, "--size", "320x320", "--no-ground", "--quiet")
        seen = read_png(picture)
        # Where the pupils sit in the whites of the eyes, in pixels (+: the picture's right).
        pupils[name] = centroid_x(seen, PUPIL) - centroid_x(seen, SCLERA)
    assert abs(pupils["camera"]) < 2.0, pupils
    assert pupils["left"] > 3.0 and pupils["right"] < -3.0, pupils


def test_speak_bml_looks_lexemes_up_in_the_characters_own_lexicon(tmp_path):
    """Creon keeps a BML lexicon of his own (format 12) in which BEAT is his greet: speak --bml
    puts greet on the timeline for it, where the demo's defaults put agree."""
    block = tmp_path / "beat.xml"
    block.write_text('<bml id="b"><gesture id="g1" lexeme="BEAT"/></bml>')
    document = json.loads((RESOURCES / "demo.thespis").read_text())
    for character in document["characters"]:  # the demo's files, found from the copies' folder
        for clip in character["clips"]:
            if "idle" in clip:
                clip["idle"]["database"] = str(RESOURCES / clip["idle"]["database"])
    document["postureBases"] = str(RESOURCES / document["postureBases"])
    defaults = tmp_path / "defaults.thespis"
    defaults.write_text(json.dumps(document))
    creon = next(c for c in document["characters"] if c["name"] == "Creon")
    creon["bmlLexicon"] = {"BEAT": "greet"}
    own = tmp_path / "own.thespis"
    own.write_text(json.dumps(document))

    def inserted(scenario):
        out = tmp_path / ("out_" + scenario.name)
        cli("speak", scenario, "--character", "Creon", "--bml", block, "--scenario-out", out)
        return layers_of(out, "Creon")["Gestures"]["actions"][-1]["name"]

    assert inserted(defaults) == "g1 agree"
    assert inserted(own) == "g1 greet"
