"""Thespis: the MIRAnim blending engine, scenario documents and PRT lighting, from Python.

Everything here comes from the compiled core (``thespis._thespis``); the pure-Python helpers
(``AnimationService``) follow the scripting style of the paper (§4.5). Times are seconds as
floats in the engine, integer ticks in documents. Frames are NumPy float32 arrays laid out as
``FrameLayout`` says: every rotation (x, y, z, w), then translations (x, y, z), then scalars.

``thespis.scene`` loads characters (glTF meshes and whole characters with skeleton, skin and
clips, or the built-in humanoid; segments with receiver / occluder tags; skinning);
``thespis.lighting`` has spherical harmonics, HDR probes and the transfer bake;
``thespis.render`` draws scenarios headless into NumPy images; ``thespis.edit`` makes the studio's
undoable scenario edits (each returns an ``Edit``: ``apply(scenario)``, ``inverse()``).

Errors from the core raise ``FileNotFoundError``, ``thespis.FormatError`` (a ``ValueError``:
not our format, malformed data naming the line or field, or a newer version), ``ValueError``
(invalid arguments or schedules), ``OSError`` (I/O) or ``thespis.Cancelled``. Each carries
``code`` (a ``thespis.ErrorCode``) and ``detail`` attributes.
"""

import sys as _sys

from . import _thespis
from ._thespis import *  # noqa: F401,F403  (the public API is the compiled module's)
from ._thespis import __version__, bvh, edit, hanim, lighting, render, scene  # noqa: F401
from ._thespis import Cancelled, FormatError  # noqa: F401
from .animation_service import AnimationService, ManualClock, RealTimeClock  # noqa: F401

# The compiled submodules are attributes of _thespis; registering them also makes
# `import thespis.edit` (and `from thespis.scene import ...`) work.
for _name in ("bvh", "edit", "hanim", "lighting", "render", "scene"):
    _sys.modules[f"{__name__}.{_name}"] = getattr(_thespis, _name)
del _name

__all__ = sorted(
    [name for name in dir(_thespis) if not name.startswith("_")]
    + ["AnimationService", "ManualClock", "RealTimeClock"]
)
