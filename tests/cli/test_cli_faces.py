"""Faces end to end through thespis-cli render (issue 31): the demo's Creon blinks, and a blink
changes the picture on his face and nowhere else; close-ups of the built-in humanoid's face
neutral, with the jaw open and the tongue showing, in each of the six MPEG-4 expressions and
mid-blink, saved under <build>/test-artifacts/faces/ for people to look at and checked by colour
(unlit: each pixel is its material's colour).

THESPIS_CLI names the executable (CTest sets it).
"""

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

from pictures import read_png

CLI = os.environ.get("THESPIS_CLI")
RESOURCES = Path(__file__).resolve().parents[2] / "resources"
ARTIFACTS = Path(os.environ.get("THESPIS_TEST_ARTIFACTS", "test-artifacts")) / "faces"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

EXPRESSIONS = ["joy", "sadness", "anger", "fear", "disgust", "surprise"]


def render(scenario, out, *args):
    done = subprocess.run([CLI, "render", scenario, "--out", out, "--quiet", *map(str, args)],
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == 0, done.stderr
    return read_png(out)


def differing(a, b, threshold=24):
    """The pixels where two pictures differ by more than `threshold` in some channel."""
    (width, height, rows_a), (_, _, rows_b) = a, b
    return [(x, y) for y in range(height) for x in range(width)
            if max(abs(rows_a[y][4 * x + c] - rows_b[y][4 * x + c]) for c in range(3)) > threshold]


def count_colour(picture, colour, tolerance=12):
    width, height, rows = picture
    return sum(1 for y in range(height) for x in range(width)
               if all(abs(rows[y][4 * x + c] - colour[c]) <= tolerance for c in range(3)))


def face_scenario(path, channels):
    """A scenario of the built-in humanoid holding a face frame (channel name → value)."""
    names, values = list(channels), [float(v) for v in channels.values()]
    character = {"schema": "Character.4", "name": "Face", "skeleton": "hanim-25", "position": [0, 0, 0],
                 "heading": 0.0, "clips": [], "layers": []}
    if names:
        character["clips"].append({"schema": "Clip.3", "name": "pose", "frameRate": 30.0, "joints": [],
                                   "rootTranslation": False, "scalars": names, "frames": [values, values]})
        constant = lambda v: {"schema": "Curve.1", "kind": "constant", "value": v}  # noqa: E731
        character["layers"].append({
            "schema": "Layer.2", "name": "face", "kind": "face", "mode": "normalized",
            "actions": [{"schema": "Action.2", "name": "pose", "clip": "pose", "start": 0,
                         "modifiers": [{"schema": "Modifier.2", "kind": "loop", "count": 0}],
                         "weight": constant(1.0), "scale": constant(1.0), "mode": "normalized",
                         "renderOutsideDomain": False}]})
    document = {"format": "thespis-scenario", "version": 6, "schema": "Scenario.6", "name": "face",
                "duration": 705600000, "masks": [], "characters": [character]}
    path.write_text(json.dumps(document))
    return path


def close_up(scenario, out, shading="prt"):
    return render(scenario, out, "--close-up", "Face", "--azimuth", 0, "--elevation", 0, "--size", "320x320",
                  "--no-ground", "--shading", shading)


def srgb(linear):
    return [round(255 * (12.92 * c if c <= 0.0031308 else 1.055 * c ** (1 / 2.4) - 0.055)) for c in linear]


TONGUE, TEETH, IRIS = srgb([0.42, 0.08, 0.09]), srgb([0.78, 0.74, 0.62]), srgb([0.16, 0.075, 0.03])
MOUTH = srgb([0.16, 0.03, 0.03])


def test_the_demo_blinks_on_creons_face_and_nowhere_else(tmp_path):
    demo = json.loads((RESOURCES / "demo.thespis").read_text())
    creon = next(c for c in demo["characters"] if c["name"] == "Creon")
    blink = next(c for c in creon["clips"] if c["name"] == "blink")
    column = blink["scalars"].index("fap19")
    closed = max(range(len(blink["frames"])), key=lambda i: blink["frames"][i][column])
    at = closed / blink["frameRate"]
    # The same frame with Creon's face layer muted: a copy of the demo beside its own assets.
    copy = tmp_path / "demo"
    shutil.copytree(RESOURCES, copy, ignore=shutil.ignore_patterns("screenshots"))
    for layer in next(c for c in demo["characters"] if c["name"] == "Creon")["layers"]:
        if layer["kind"] == "face":
            layer["mute"] = True
    (copy / "muted.thespis").write_text(json.dumps(demo))
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    blinking = render(RESOURCES / "demo.thespis", ARTIFACTS / "demo_blink.png", "--time", at, "--size", "640x360")
    muted = render(copy / "muted.thespis", ARTIFACTS / "demo_blink_muted.png", "--time", at, "--size", "640x360")
    changed = differing(blinking, muted)
    assert changed, "a blink must show"
    xs, ys = [x for x, _ in changed], [y for _, y in changed]
    # Only on the face: a few pixels across, high in the picture (the heads are there).
    assert max(xs) - min(xs) < 40 and max(ys) - min(ys) < 30, (min(xs), max(xs), min(ys), max(ys))
    assert max(ys) < 360 * 0.35
    # In a close-up the closed lids cover Creon's irises.
    near = render(RESOURCES / "demo.thespis", ARTIFACTS / "creon_blink_close_up.png", "--time", at, "--close-up",
                  "Creon", "--azimuth", 0, "--elevation", 0, "--size", "240x240", "--shading", "unlit", "--no-ground")
    open_eyes = render(copy / "muted.thespis", ARTIFACTS / "creon_open_close_up.png", "--time", at, "--close-up",
                       "Creon", "--azimuth", 0, "--elevation", 0, "--size", "240x240", "--shading", "unlit",
                       "--no-ground")
    assert count_colour(open_eyes, IRIS) > 20
    assert count_colour(near, IRIS) < count_colour(open_eyes, IRIS) / 5


def test_close_ups_of_the_humanoids_face(tmp_path):
    ARTIFACTS.mkdir(parents=True, exist_ok=True)
    neutral = close_up(face_scenario(tmp_path / "neutral.thespis", {}), ARTIFACTS / "neutral.png", "unlit")
    close_up(face_scenario(tmp_path / "neutral.thespis", {}), ARTIFACTS / "neutral_lit.png")
    assert count_colour(neutral, IRIS) > 20, "the eyes are open"
    assert count_colour(neutral, TONGUE) < 10, "the mouth is shut"

    jaw = close_up(face_scenario(tmp_path / "jaw.thespis", {"fap3": 600, "fap44": 400, "fap45": 150}),
                   ARTIFACTS / "jaw_open.png", "unlit")
    close_up(face_scenario(tmp_path / "jaw.thespis", {"fap3": 600, "fap44": 400, "fap45": 150}),
             ARTIFACTS / "jaw_open_lit.png")
    assert count_colour(jaw, MOUTH) > 40, "the open mouth shows its dark inside"
    assert count_colour(jaw, TONGUE) > 5, "and the tongue"
    assert count_colour(jaw, TEETH) > 3, "and the teeth"
    assert count_colour(neutral, MOUTH) == 0

    # Half way through a blink: the upper lids half down (a blink is mostly theirs).
    blink = close_up(face_scenario(tmp_path / "blink.thespis", {"fap19": 512, "fap20": 512}),
                     ARTIFACTS / "mid_blink.png", "unlit")
    assert 0 < count_colour(blink, IRIS) < count_colour(neutral, IRIS), "half the iris hidden"

    pictures = {}
    for number, name in enumerate(EXPRESSIONS, start=1):
        scenario = face_scenario(tmp_path / f"{name}.thespis", {f"expression{number}": 1})
        pictures[name] = close_up(scenario, ARTIFACTS / f"{name}.png")
        assert len(differing(pictures[name], close_up(face_scenario(tmp_path / "n.thespis", {}),
                                                          tmp_path / "n.png"))) > 100, name
    for a in EXPRESSIONS:
        for b in EXPRESSIONS:
            if a < b:
                assert len(differing(pictures[a], pictures[b])) > 100, (a, b)


def layered_face_scenario(path, layers, masks):
    """A scenario of the built-in humanoid with face layers, bottom first: (name, {channel: value},
    mask name or ""), and the named face masks (name → {region or channel: weight})."""
    character = {"schema": "Character.4", "name": "Face", "skeleton": "hanim-25", "position": [0, 0, 0],
                 "heading": 0.0, "clips": [], "layers": []}
    constant = lambda v: {"schema": "Curve.1", "kind": "constant", "value": v}  # noqa: E731
    for name, channels, mask in layers:
        values = [float(v) for v in channels.values()]
        character["clips"].append({"schema": "Clip.3", "name": name, "frameRate": 30.0, "joints": [],
                                   "rootTranslation": False, "scalars": list(channels), "frames": [values, values]})
        character["layers"].append({
            "schema": "Layer.2", "name": name, "kind": "face", "mode": "normalized",
            "actions": [{"schema": "Action.2", "name": name, "clip": name, "start": 0, "mask": mask,
                         "modifiers": [{"schema": "Modifier.2", "kind": "loop", "count": 0}],
                         "weight": constant(1.0), "scale": constant(1.0), "mode": "normalized",
                         "renderOutsideDomain": False}]})
    document = {"format": "thespis-scenario", "version": 6, "schema": "Scenario.6", "name": "face",
                "duration": 705600000, "characters": [character],
                "masks": [{"name": name, "weights": weights, "defaultWeight": 0.0} for name, weights in masks.items()]}
    path.write_text(json.dumps(document))
    return path


def test_face_masks_give_speech_the_mouth_and_the_expression_the_brows(tmp_path):
    """The paper's face layering (§5.2): a speech layer over an expression, each weighted per FAP
    region — the speech mask keeps the expression's raised brows, which the speech layer would
    otherwise cover with its neutral ones."""
    out = ARTIFACTS / "masks"
    out.mkdir(parents=True, exist_ok=True)
    brows = {f"fap{n}": 300 for n in range(31, 37)}
    expression = ("surprised", {**brows, "fap3": 450}, "expression")
    masks = {"speech": {"mouth": 1.0, "tongue": 1.0, "cheeks": 0.5},
             "expression": {"eyes": 1.0, "brows": 1.0, "cheeks": 1.0, "nose": 1.0, "expressions": 1.0, "mouth": 1 / 3}}
    both = close_up(layered_face_scenario(tmp_path / "both.thespis",
                                          [expression, ("speech", {"fap3": 60}, "speech")], masks),
                    out / "speech_over_expression.png", "unlit")
    unmasked = close_up(layered_face_scenario(tmp_path / "unmasked.thespis",
                                              [expression, ("speech", {"fap3": 60}, "")], masks),
                        out / "speech_unmasked.png", "unlit")
    alone = close_up(layered_face_scenario(tmp_path / "alone.thespis", [expression], masks),
                     out / "expression_alone.png", "unlit")
    neutral = close_up(face_scenario(tmp_path / "neutral.thespis", {}), out / "neutral.png", "unlit")

    def mean_row(pixels):
        return sum(y for _, y in pixels) / len(pixels)

    brows_lost = differing(both, unmasked)   # the unmasked speech layer lowers the brows again
    speech_moved = differing(both, alone)    # the speech layer moves the mouth only
    raised = differing(alone, neutral)       # the expression moves brows and mouth
    assert len(brows_lost) > 50 and len(speech_moved) > 20 and len(raised) > 50
    assert mean_row(brows_lost) < mean_row(speech_moved) - 40, "brows above, mouth below"
    height = both[1]
    assert mean_row(brows_lost) < height / 2 < mean_row(speech_moved)
