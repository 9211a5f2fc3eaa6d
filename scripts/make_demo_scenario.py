#!/usr/bin/python3
"""Writes resources/demo.thespis, the built-in demo scenario the studio opens.

Everything in it is made here: procedural clips stored inline as keyframes on H-Anim joints
(a right-arm wave, a head nod, eye blinks as MPEG-4 FAPs), the paper's idle motion synthesized
from the shipped CMU-derived database (resources/motion), two characters of the paper's script
(Creon and Antigone, §4.5) and their schedules.

The file is written in the exact form Thespis writes scenarios (key order, indentation, one
line per frame, numbers in their shortest form), so that loading and saving it in the studio
changes nothing; tests/core/scenario_test.cpp checks that byte for byte.

Axes as H-Anim: +Y up, the character faces +Z, +X is its left. A joint's rotation is in its
parent's frame; identity is the H-Anim rest pose (standing, arms at the sides).

Usage: /usr/bin/python3 scripts/make_demo_scenario.py [output path]
"""

import json
import math
import sys
from pathlib import Path

TICKS_PER_SECOND = 705_600_000
DEG = math.pi / 180.0


def ticks(seconds):
    return round(seconds * TICKS_PER_SECOND)


# --- quaternions (x, y, z, w) ----------------------------------------------------------------

def axis_angle(axis, degrees):
    half = degrees * DEG / 2.0
    s = math.sin(half)
    return (axis[0] * s, axis[1] * s, axis[2] * s, math.cos(half))


def mul(a, b):
    ax, ay, az, aw = a
    bx, by, bz, bw = b
    return (aw * bx + ax * bw + ay * bz - az * by,
            aw * by - ax * bz + ay * bw + az * bx,
            aw * bz + ax * by - ay * bx + az * bw,
            aw * bw - ax * bx - ay * by - az * bz)


X, Y, Z = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (0.0, 0.0, 1.0)


def rx(d): return axis_angle(X, d)
def ry(d): return axis_angle(Y, d)
def rz(d): return axis_angle(Z, d)


def number(value):
    """Four decimals (well inside float precision), never -0."""
    return round(value, 4) + 0.0


def smooth(u):
    u = min(1.0, max(0.0, u))
    return u * u * (3.0 - 2.0 * u)


# --- clips -----------------------------------------------------------------------------------

def clip(name, rate, joints, sample, duration, root_translation=False, scalars=()):
    """Samples `sample(t)` -> list of floats at `rate` over [0, duration] (both ends included,
    so a loop's last frame equals its first)."""
    count = round(duration * rate) + 1
    frames = []
    for k in range(count):
        values = sample(k / rate)
        frames.append([number(v) for v in values])
    out = {"schema": "Clip.4", "name": name, "frameRate": float(rate), "joints": list(joints),
           "rootTranslation": root_translation}
    if scalars:
        out["scalars"] = list(scalars)
    out["frames"] = frames
    return out


def idle_synthesizer(name, seed, amplitude=1.0):
    """The paper's idle motion (§4.3), synthesized from the database the product ships
    (resources/motion/cmu_standing.idle, made by scripts/make_motion_data.sh from CMU standing
    recordings): balance shifts and small posture variations, open-ended, each character its own
    seed."""
    return {"schema": "Clip.4", "name": name,
            "idle": {"database": "motion/cmu_standing.idle", "seed": seed, "amplitude": float(amplitude)}}


WAVE_JOINTS = ["r_sternoclavicular", "r_shoulder", "r_elbow", "r_radiocarpal"]


def wave_clip(name, waves, wave_period):
    """The right arm rises sideways until the forearm points up, the hand waves `waves` times,
    and the arm comes down again. Keyed as a body moves: the upper arm turns outwards about its
    length, so the elbow bends about its own hinge (the PCA of captured motion reads anything
    else as unnatural, and the dependent-joint filter would straighten it)."""
    rise = 0.6
    duration = rise + waves * wave_period + rise

    def sample(t):
        up = smooth(t / rise) * smooth((duration - t) / rise)
        waving = min(max(t - rise, 0.0), waves * wave_period)
        swing = math.sin(2.0 * math.pi * waving / wave_period) * smooth(min(t, duration - t) / rise)
        rotations = [
            rz(-8.0 * up),                                          # the clavicle lifts
            mul(rx(-15.0 * up), mul(rz(-100.0 * up), ry(-90.0 * up))),  # upper arm out, a little forward, turned out
            rx(-80.0 * up - 20.0 * swing),                          # the elbow bends the forearm up, waving
            rx(-10.0 * swing),                                      # the hand follows
        ]
        return [c for q in rotations for c in q]

    return clip(name, 30, WAVE_JOINTS, sample, duration)


POINT_JOINTS = ["r_shoulder", "r_elbow", "r_radiocarpal"]


def point_clip(name, hold):
    """The right arm rises forward, almost straight, and holds for `hold` seconds before it comes
    down: the shape of a pointing gesture, which BML's <pointing> (the Stage's pointing layer)
    turns at the shoulder toward its target."""
    rise = 0.5
    duration = rise + hold + rise

    def sample(t):
        up = smooth(t / rise) * smooth((duration - t) / rise)
        rotations = [
            mul(rx(-70.0 * up), rz(-15.0 * up)),  # the upper arm forward and a little out
            rx(-12.0 * up),                       # the elbow nearly straight
            rx(8.0 * up),                         # the hand in line with the forearm
        ]
        return [c for q in rotations for c in q]

    return clip(name, 30, POINT_JOINTS, sample, duration)


NOD_JOINTS = ["vc4", "skullbase"]


def nod_clip(name, nods, nod_period, degrees):
    def sample(t):
        angle = degrees * math.sin(math.pi * t / nod_period) ** 2
        return [c for q in (rx(0.4 * angle), rx(angle)) for c in q]

    return clip(name, 30, NOD_JOINTS, sample, nods * nod_period)


def blink_clip(name, period, at):
    """Both eyelids close and open once per period (FAP 19-22, eyelid closing, in IRISD units)."""
    def sample(t):
        u = (t - at) / 0.15
        closed = math.sin(math.pi * u) ** 2 if 0.0 <= u <= 1.0 else 0.0
        return [800.0 * closed, 800.0 * closed, 200.0 * closed, 200.0 * closed]

    return clip(name, 30, [], sample, period, scalars=["fap19", "fap20", "fap21", "fap22"])


def blink_generator(name, seed, rate=17.0):
    """Blinks at seeded moments, `rate` a minute (a person at rest: 17), open-ended."""
    return {"schema": "Clip.4", "name": name,
            "blinks": {"rate": float(rate), "seed": seed, "closeSeconds": 0.1, "shutSeconds": 0.03,
                       "openSeconds": 0.25}}


def expression_clip(name, expression, intensity, duration):
    """An MPEG-4 expression (1 joy … 6 surprise) held at `intensity` (the weight of its channel)
    for `duration` seconds, from a neutral first frame: played additively (relative to the first
    frame) it adds the expression to whatever the face does, blinks included."""
    return clip(name, 30, [], lambda t: [intensity if t > 0 else 0.0], duration, scalars=[f"expression{expression}"])


# --- curves, modifiers, actions ---------------------------------------------------------------

def constant(value):
    return {"schema": "Curve.1", "kind": "constant", "value": float(value)}


def fade(kind, fade_in, fade_out, peak=1.0):
    return {"schema": "Curve.1", "kind": kind, "fadeIn": float(fade_in), "fadeOut": float(fade_out),
            "peak": float(peak)}


def adsr(kind, attack, decay, sustain, release, peak=1.0):
    return {"schema": "Curve.1", "kind": kind, "attack": float(attack), "decay": float(decay),
            "sustain": float(sustain), "release": float(release), "peak": float(peak)}


def keyframed(keys):
    return {"schema": "Curve.1", "kind": "keyframed",
            "keys": [{"time": float(t), "value": float(v), "tangent": mode} for t, v, mode in keys]}


def modifier(kind, **params):
    out = {"schema": "Modifier.2", "kind": kind}
    out.update(params)
    return out


def action(name, clip_name, start, weight, scale=None, mask=None, mode="normalized", modifiers=()):
    out = {"schema": "Action.4", "name": name, "clip": clip_name, "start": ticks(start)}
    if modifiers:
        out["modifiers"] = list(modifiers)
    out["weight"] = weight
    out["scale"] = scale or constant(1.0)
    if mask:
        out["mask"] = mask
    out["mode"] = mode
    out["renderOutsideDomain"] = False
    return out


def layer(name, kind, actions):
    return {"schema": "Layer.3", "name": name, "kind": kind, "mode": "normalized", "actions": actions}


def gesture(name, clip_name, mask_name, fade_in, fade_out, dependent_joint_filter=False, filter_band=None):
    out = {"schema": "Gesture.2", "name": name, "clip": clip_name, "mask": mask_name,
           "fadeIn": ticks(fade_in), "fadeOut": ticks(fade_out),
           "dependentJointFilter": dependent_joint_filter}
    if filter_band:
        out["filterFadeFrom"], out["filterMuteAbove"] = filter_band
    return out


def speech_line(name, text, voice, rate, pitch):
    # No start: the line is said when a script says it. No audio: espeak-ng speaks the text.
    return {"schema": "SpeechLine.1", "name": name, "text": text, "voice": voice, "rate": rate, "pitch": pitch,
            "words": [], "phonemes": []}


def marker(name, time):
    return {"schema": "Marker.1", "name": name, "time": ticks(time)}


def mask(name, weights, default=0.0):
    return {"schema": "Mask.1", "name": name, "defaultWeight": float(default),
            "weights": dict(sorted((k, float(v)) for k, v in weights.items()))}


def scenario():
    creon = {
        # Creon stands on the left, turned towards Antigone.
        "schema": "Character.7", "name": "Creon", "skeleton": "hanim-25", "position": [-0.55, 0.0, 0.0],
        "heading": 25.0,
        "clips": [
            idle_synthesizer("creon_idle", seed=1),
            wave_clip("wave", waves=3, wave_period=0.6),
            nod_clip("nod", nods=2, nod_period=0.8, degrees=12.0),
            point_clip("point", hold=1.0),
            blink_clip("blink", period=3.2, at=0.4),
            expression_clip("stern", 3, 0.6, 3.0),
        ],
        "layers": [
            layer("body", "body", [
                # The base idle plays at full weight from the start, and never ends.
                action("creon_idle", "creon_idle", 0.0, constant(1.0)),
                action("creon_wave", "wave", 1.5, adsr("cubicAdsr", 0.4, 0.3, 0.85, 0.5),
                       mask="rightArm", mode="override"),
                action("creon_nod", "nod", 5.0, fade("linearFade", 0.25, 0.25), mask="head",
                       mode="additive", modifiers=[modifier("timeStretch", factor=1.25)]),
                action("creon_small_wave", "wave", 8.0,
                       keyframed([(0.0, 0.0, "autoClamped"), (0.5, 0.7, "autoClamped"),
                                  (2.0, 0.7, "linear"), (2.4, 0.0, "autoClamped")]),
                       scale=constant(0.6), mask="rightArm", mode="override"),
            ]),
            layer("face", "face", [
                action("creon_blinks", "blink", 0.0, constant(1.0), modifiers=[modifier("loop", count=0)]),
                # Stern (anger at 0.6) while Antigone nods, added over the blinks.
                action("creon_stern", "stern", 2.5, fade("cubicFade", 0.4, 0.6), mode="additive"),
            ]),
        ],
        # The gestures a speech script (or the studio's gesticon panel) can trigger.
        "gestures": [
            # The shipped posture database holds no waves: the paper's 20–30 would take most of
            # the elbow's bend for unnatural (43°); from PC 30 it keeps it within 10°.
            gesture("greet", "wave", "rightArm", 0.4, 0.5, dependent_joint_filter=True, filter_band=(30, 40)),
            gesture("agree", "nod", "head", 0.25, 0.25),
            # BML's POINT: <pointing target="Antigone"/> aims it at her.
            gesture("point", "point", "rightArm", 0.3, 0.4),
        ],
        # What the paper's script has him say (voiceService.activateAction): not on the timeline.
        "speech": [
            speech_line("CreonSpeech.Cam01CreonP1",
                        '<begin_gesture id="g1" anim="greet"/>Now<end_gesture id="g1"/>, tell me thou, not in '
                        "many words, but briefly: knewest thou that an edict had "
                        "forbidden this?", voice="en-gb", rate=140, pitch=35),
        ],
    }
    antigone = {
        "schema": "Character.7", "name": "Antigone", "skeleton": "hanim-25", "position": [0.55, 0.0, 0.0],
        "heading": -25.0,
        "clips": [
            idle_synthesizer("antigone_idle", seed=2),
            wave_clip("wave", waves=2, wave_period=0.8),
            nod_clip("nod", nods=2, nod_period=1.2, degrees=10.0),
            blink_generator("antigone_blinks", seed=2),
            expression_clip("smile", 1, 0.7, 2.0),
        ],
        "layers": [
            layer("body", "body", [
                action("antigone_idle", "antigone_idle", 0.0, constant(1.0)),
                action("antigone_nod", "nod", 3.0, fade("cubicFade", 0.2, 0.3), mask="head",
                       mode="additive", modifiers=[modifier("trim", start=0.0, end=1.2)]),
                # Her wave is Creon's motion played on the left arm: the mirror modifier swaps sides.
                action("antigone_wave", "wave", 6.0, adsr("linearAdsr", 0.5, 0.3, 0.9, 0.6),
                       mask="leftArm", mode="override", modifiers=[modifier("mirror", axis=0)]),
            ]),
            layer("face", "face", [
                # Her own blinks, synthesized, and a smile while she waves.
                action("antigone_blinks", "antigone_blinks", 0.0, constant(1.0)),
                action("antigone_smile", "smile", 5.8, fade("cubicFade", 0.4, 0.5), mode="additive"),
            ]),
        ],
        "gestures": [
            gesture("agree", "nod", "head", 0.2, 0.3),
        ],
        "speech": [
            speech_line("AntigoneSpeech.Cam01CreonP3",
                        'I knew it: <begin_gesture id="g1" anim="agree"/>could I help it?<end_gesture id="g1"/> '
                        "It was public.", voice="en-us", rate=160, pitch=70),
        ],
    }
    return {
        "format": "thespis-scenario",
        "version": 12,
        "schema": "Scenario.12",
        "name": "Antigone, act 1 (demo)",
        "duration": ticks(12.0),
        "masks": [
            mask("head", {"vc4": 0.5, "skullbase": 1.0}),
            mask("leftArm", {"l_sternoclavicular": 1.0}),
            mask("rightArm", {"r_sternoclavicular": 1.0}),
        ],
        "characters": [creon, antigone],
        # The posture PCA the dependent-joint filter of Creon's "greet" gesture works in.
        "postureBases": "motion/cmu_postures.pca",
        "markers": [marker("Creon greets", 1.5), marker("Antigone answers", 6.0)],
        # The paper's §4.5 script, kept in the scenario (the Script dock lists it).
        "scripts": [{"schema": "Script.1", "name": "antigone_creon", "source": PAPER_SCRIPT.read_text(encoding="utf-8")}],
    }


# --- writing, in the form Thespis writes ------------------------------------------------------

def scalar(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    return json.dumps(value, ensure_ascii=False)


def dump(value, indent=0):
    inner = " " * (indent + 2)
    if isinstance(value, dict):
        if not value:
            return "{}"
        items = [inner + json.dumps(k, ensure_ascii=False) + ": " + dump(v, indent + 2) for k, v in value.items()]
        return "{\n" + ",\n".join(items) + "\n" + " " * indent + "}"
    if isinstance(value, list):
        if not value:
            return "[]"
        if not any(isinstance(v, (dict, list)) for v in value):
            return "[" + ", ".join(scalar(v) for v in value) + "]"
        return "[\n" + ",\n".join(inner + dump(v, indent + 2) for v in value) + "\n" + " " * indent + "]"
    return scalar(value)


PAPER_SCRIPT = Path(__file__).resolve().parent.parent / "resources" / "scripts" / "antigone_creon.py"


def main():
    root = Path(__file__).resolve().parent.parent
    out = Path(sys.argv[1]) if len(sys.argv) > 1 else root / "resources" / "demo.thespis"
    out.write_text(dump(scenario()) + "\n", encoding="utf-8")
    print(f"wrote {out}")


if __name__ == "__main__":
    main()
