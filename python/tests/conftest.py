"""Shared paths for the thespis pytest suite.

The tests import the public `thespis` package (PYTHONPATH points at the build tree's
python/ folder; CTest sets it). Real data lives beside the repository in ../shared/data,
found from this file's location unless THESPIS_SHARED_DATA says otherwise.
"""

import os
from pathlib import Path

import pytest

REPO = Path(__file__).resolve().parents[2]
SHARED_DATA = Path(os.environ.get("THESPIS_SHARED_DATA", REPO.parent / "shared" / "data")).resolve()
MOCAP = SHARED_DATA / "mocap"
RESOURCES = REPO / "resources"
DEMO = RESOURCES / "demo.thespis"


def mocap(relative: str) -> Path:
    path = MOCAP / relative
    if not path.exists():
        pytest.fail(f"missing real test data {path} (expected ../shared/data beside the repository)")
    return path


def demo_scenario() -> Path:
    if not DEMO.exists():
        pytest.fail(f"the demo scenario {DEMO} is not in this checkout yet")
    return DEMO


def all_bvh_files():
    return sorted(MOCAP.rglob("*.bvh"))
