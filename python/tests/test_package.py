"""Scenario packages from Python: the built-in demo and a scenario of real files
(../shared/data: a CMU clip) exported with thespis.export_package, opened with open_package
and played straight from it (the same poses as from the folder), imported with extract_to
(every file byte-identical); a damaged package refused naming the entry; a missing file named
with its field."""

import hashlib
import os
import zipfile
from pathlib import Path

import numpy as np
import pytest

import thespis

ROOT = Path(__file__).resolve().parents[2]
DEMO = ROOT / "resources" / "demo.thespis"
SHARED_DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))


def shared(relative):
    path = SHARED_DATA / relative
    if not path.exists():
        pytest.fail(f"missing real test data {path} (expected ../shared/data beside the repository)")
    return path


def poses(scenario, base_dir):
    runtime = thespis.build_runtime(scenario, base_dir)
    return [c.evaluate_body(t) for c in runtime.characters for t in (0.0, 1.1, 4.2)]


def test_the_demo_plays_from_its_package_and_imports_byte_identical(tmp_path):
    calls = []
    result = thespis.export_package(DEMO, tmp_path / "demo.thespkg", progress=lambda done, total: calls.append(total))
    assert [e.name for e in result.entries] == ["demo.thespis", "motion/cmu_standing.idle", "motion/cmu_postures.pca",
                                              "dialogue/antigone/antigone.aiml"]
    assert 0 < result.package_bytes < result.content_bytes and calls
    package = thespis.open_package(tmp_path / "demo.thespkg")
    assert package.scenario_entry == "demo.thespis" and package.writer.startswith("Thespis ")
    assert package.read("motion/cmu_postures.pca") == (DEMO.parent / "motion" / "cmu_postures.pca").read_bytes()
    assert thespis.validate_scenario(package.scenario, package) == []
    demo = thespis.load_scenario(DEMO)
    for a, b in zip(poses(demo, DEMO.parent), poses(package.scenario, package), strict=True):
        np.testing.assert_array_equal(a, b)
    scenario = package.extract_to(tmp_path / "imported")
    assert scenario == tmp_path / "imported" / "demo.thespis"
    for entry in package.entries:
        data = (tmp_path / "imported" / entry.name).read_bytes()
        assert hashlib.sha256(data).hexdigest() == entry.sha256


def test_a_scenario_object_with_a_real_clip(tmp_path):
    document = thespis.Scenario()
    character = thespis.Character("Walker", "hanim-loa1")
    character.clips = [thespis.ClipAsset("walk", str(shared("mocap/cmu/02_01.bvh")))]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("walk", "walk")]
    character.layers = [layer]
    document.characters = [character]
    thespis.export_package(document, tmp_path / "walk.thespkg", base_dir=tmp_path, scenario_entry="walk.thespis")
    package = thespis.open_package(tmp_path / "walk.thespkg")
    assert package.scenario.characters[0].clips[0].file == "assets/02_01.bvh"
    for a, b in zip(poses(document, tmp_path), poses(package.scenario, package), strict=True):
        np.testing.assert_array_equal(a, b)
    frames = thespis.bake_motion(package.scenario, "Walker", tmp_path / "walk.bvh", base_dir=package, end=1.0)
    assert frames == 31


def test_damage_and_missing_files_are_named(tmp_path):
    thespis.export_package(DEMO, tmp_path / "demo.thespkg")
    with zipfile.ZipFile(tmp_path / "demo.thespkg") as source, \
            zipfile.ZipFile(tmp_path / "changed.thespkg", "w", zipfile.ZIP_DEFLATED) as changed:
        for info in source.infolist():
            data = source.read(info)
            changed.writestr(info, data if info.filename != "motion/cmu_postures.pca" else data[:-1] + b"!")
    with pytest.raises(thespis.FormatError, match='"motion/cmu_postures.pca" does not match its SHA-256'):
        thespis.open_package(tmp_path / "changed.thespkg")
    document = thespis.Scenario()
    character = thespis.Character("Creon", "hanim-loa1")
    character.clips = [thespis.ClipAsset("wave", "nowhere.bvh")]
    document.characters = [character]
    with pytest.raises(Exception, match=r"characters\[Creon\]\.clips\[wave\]\.file names nowhere.bvh"):
        thespis.export_package(document, tmp_path / "broken.thespkg", base_dir=tmp_path)
    assert not (tmp_path / "broken.thespkg").exists()


def test_render_calls_take_a_package(tmp_path):
    """thespis.render's calls open a package wherever they open a scenario file: the same picture."""
    package = tmp_path / "demo.thespkg"
    thespis.export_package(DEMO, package)
    from_package = thespis.render.render_scenario(package, 1.5, width=96, height=72, samples=0)
    from_folder = thespis.render.render_scenario(DEMO, 1.5, width=96, height=72, samples=0)
    np.testing.assert_array_equal(from_package, from_folder)
    assert from_package[..., 3].any()
    written = thespis.render.render_frames(package, tmp_path / "frames", 3, 4, width=96, height=72, samples=0)
    assert isinstance(written, list)
    assert sorted(p.name for p in (tmp_path / "frames").iterdir()) == ["frame_00003.png", "frame_00004.png"]
