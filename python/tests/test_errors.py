"""Core errors become the right Python exceptions, with messages, `code` and `detail`."""

import json

import numpy as np
import pytest

import thespis
from conftest import mocap


def test_exception_hierarchy():
    assert issubclass(thespis.FormatError, ValueError)
    assert issubclass(thespis.Cancelled, KeyboardInterrupt)
    assert thespis.FormatError.__module__ == "thespis"


def test_file_not_found_error(tmp_path):
    missing = tmp_path / "nowhere.bvh"
    with pytest.raises(FileNotFoundError, match="nowhere.bvh") as info:
        thespis.bvh.load(missing)
    assert info.value.code == thespis.ErrorCode.file_not_found
    assert isinstance(info.value.detail, str)
    with pytest.raises(FileNotFoundError):
        thespis.load_scenario(tmp_path / "nowhere.thespis")


def test_format_errors_for_malformed_and_foreign_files(tmp_path):
    bad = tmp_path / "bad.bvh"
    bad.write_text("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 zero 0\n")
    with pytest.raises(thespis.FormatError, match="line 4") as info:
        thespis.bvh.load(bad)
    assert info.value.code == thespis.ErrorCode.corrupt_data
    not_bvh = tmp_path / "photo.bvh"
    not_bvh.write_bytes(b"\x89PNG\r\n\x1a\n")
    with pytest.raises(thespis.FormatError) as info:
        thespis.bvh.load(not_bvh)
    assert info.value.code == thespis.ErrorCode.not_our_format
    with pytest.raises(ValueError):  # a FormatError is a ValueError, so generic handlers work
        thespis.parse_scenario("[1, 2, 3]")


def test_newer_version_is_a_format_error():
    with pytest.raises(thespis.FormatError) as info:
        thespis.parse_scenario(json.dumps({"format": "thespis-scenario", "version": 1000, "schema": "Scenario.1000"}))
    assert info.value.code == thespis.ErrorCode.newer_version
    assert "1000" in str(info.value)


def test_invalid_arguments_are_value_errors():
    with pytest.raises(ValueError) as info:
        thespis.TimeStretch(thespis.KeyframeClip(thespis.FrameLayout(["a"]), 30.0, np.array([[0, 0, 0, 1.0]])), -1.0)
    assert info.value.code == thespis.ErrorCode.invalid_argument
    assert str(info.value)


def test_invalid_schedules_are_value_errors():
    schedule = thespis.BlendingSchedule(thespis.FrameLayout(["a"]))
    other = thespis.KeyframeClip(thespis.FrameLayout(["b"]), 30.0, np.array([[0, 0, 0, 1.0]]), "other")
    with pytest.raises(ValueError, match="other") as info:
        schedule.add_action(other, name="other")
    assert info.value.code == thespis.ErrorCode.invalid_schedule


def test_io_errors_are_os_errors(tmp_path):
    skeleton, clip, _ = thespis.bvh.load(mocap("makehuman/walk1.bvh"))
    with pytest.raises(OSError) as info:
        thespis.bvh.save(tmp_path / "missing_folder" / "walk.bvh", skeleton, clip)
    assert info.value.code == thespis.ErrorCode.io_error
    with pytest.raises(OSError):
        thespis.save_scenario(tmp_path / "missing_folder" / "x.thespis", thespis.Scenario("x"))


def test_errors_as_values():
    problems = thespis.validate_scenario(thespis.Scenario("empty"))
    for problem in problems:
        assert isinstance(problem.code, thespis.ErrorCode) and problem.message
    bad = thespis.Scenario("bad")
    bad.characters = [thespis.Character("", "hanim-loa1")]
    problems = thespis.validate_scenario(bad)
    assert problems and "name" in problems[0].message
    assert "invalid schedule" in str(problems[0]) or problems[0].code == thespis.ErrorCode.invalid_schedule
