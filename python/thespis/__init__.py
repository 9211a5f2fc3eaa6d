"""Thespis: the MIRAnim blending engine, scenario documents and PRT lighting, from Python.

Everything here comes from the compiled core (``thespis._thespis``). ``thespis.runtime`` (also
re-exported here: ``AnimationService``, ``Stage``, the clocks) is the paper's animation service
(§4.5), with its method names (``activateAction_body``, ``waitUntilActionFinished_body``) and
Pythonic aliases. Times are seconds as
floats in the engine, integer ticks in documents. Frames are NumPy float32 arrays laid out as
``FrameLayout`` says: every rotation (x, y, z, w), then translations (x, y, z), then scalars.

``thespis.scene`` loads characters (glTF meshes and whole characters with skeleton, skin and
clips, or the built-in humanoid; segments with receiver / occluder tags; skinning);
``thespis.face`` has face mapping tables (face channels → a model's own morph targets and face
joints: recognised, loaded, saved, applied) and evaluates face frames onto a character's mesh;
``thespis.lighting`` has spherical harmonics, HDR probes and the transfer bake;
``thespis.render`` draws scenarios headless into NumPy images; ``thespis.edit`` makes the studio's
undoable scenario edits (each returns an ``Edit``: ``apply(scenario)``, ``inverse()``);
``thespis.ar`` calibrates cameras and tracks boards and pictures in frames (NumPy BGR images);
``thespis.speech`` speaks tagged text with espeak-ng (audio, word and phoneme timing, visemes
weighted by the coarticulation dominance curve) and inserts it into a scenario; ``thespis.bml``
reads BML blocks and realises them on the Stage (speech, gestures, faceLexemes, head nods, gaze),
and the animation service's ``gaze_body`` / ``stopGaze`` turn a character's eyes and head;
``thespis.dialogue`` loads AIML bots, converses, listens for what a bot can answer and lets a
character of the stage converse (``InteractionService``, a script's ``interactionService``).

Errors from the core raise ``FileNotFoundError``, ``thespis.FormatError`` (a ``ValueError``:
not our format, malformed data naming the line or field, or a newer version), ``ValueError``
(invalid arguments or schedules), ``OSError`` (I/O) or ``thespis.Cancelled``. Each carries
``code`` (a ``thespis.ErrorCode``) and ``detail`` attributes.
"""

import sys as _sys

# Inside the studio or `thespis-cli run`, the compiled module is built into the program.
if "_thespis" in _sys.builtin_module_names:
    import _thespis

    _sys.modules[__name__ + "._thespis"] = _thespis
else:
    from . import _thespis
from ._thespis import *  # noqa: F401,F403  (the public API is the compiled module's)
from ._thespis import __version__, ar, bml, bvh, dialogue, edit, face, hanim, lighting, motion, render, runtime, scene, speech  # noqa: F401
from ._thespis import Cancelled, FormatError  # noqa: F401

AnimationService, Stage = runtime.AnimationService, runtime.Stage
ExternalClock, ManualClock, RealTimeClock = runtime.ExternalClock, runtime.ManualClock, runtime.RealTimeClock
SoundService, VoiceService = runtime.SoundService, runtime.VoiceService

# The compiled submodules are attributes of _thespis; registering them also makes
# `import thespis.edit` (and `from thespis.scene import ...`) work.
for _name in ("ar", "bml", "bvh", "dialogue", "edit", "face", "hanim", "lighting", "motion", "render", "runtime", "scene", "speech"):
    _sys.modules[f"{__name__}.{_name}"] = getattr(_thespis, _name)
del _name

__all__ = sorted(
    [name for name in dir(_thespis) if not name.startswith("_")]
    + ["AnimationService", "ExternalClock", "ManualClock", "RealTimeClock", "SoundService", "Stage", "VoiceService"]
)
