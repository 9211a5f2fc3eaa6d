"""thespis-cli export, import and validate on packages, end to end: the built-in demo and a
scenario of real third-party files (../shared/data: the CesiumMan glTF, a CMU clip, a Poly Haven
probe) exported, validated, imported into a fresh folder (every file byte-identical, the scenario
valid and playing the same poses there); packages another tool might make — a path out of the
package, an absolute path, a symbolic link, a name twice, a zip bomb, a changed entry, a newer
format — refused, each naming the entry, with nothing written.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import hashlib
import json
import os
import subprocess
import warnings
import zipfile
from pathlib import Path

import numpy as np
import pytest

import thespis

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
DEMO = ROOT / "resources" / "demo.thespis"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

USAGE, INVALID, FAILURE = 2, 3, 4


def run(*args, timeout=300):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def shared(relative):
    path = DATA / relative
    if not path.exists():
        pytest.fail(f"missing real test data {path} (expected ../shared/data beside the repository)")
    return path


def poses(path):
    """Every character's body frame at a few times, as the runtime plays the scenario file."""
    runtime = thespis.build_runtime(thespis.load_scenario(path), str(Path(path).parent))
    return [c.evaluate_body(t) for c in runtime.characters for t in (0.0, 0.7, 2.3, 5.1)]


def export_and_import(scenario, tmp_path):
    package = tmp_path / "play.thespkg"
    result = run("export", scenario, "--out", package, "--list")
    assert result.returncode == 0, result.stderr
    assert "Wrote" in result.stdout and package.exists()
    result = run("validate", package)
    assert result.returncode == 0, result.stdout + result.stderr
    assert "each as its manifest says" in result.stdout and ": valid." in result.stdout
    folder = tmp_path / "elsewhere"
    result = run("import", package, "--to", folder)
    assert result.returncode == 0, result.stderr
    with zipfile.ZipFile(package) as archive:
        names = archive.namelist()
        manifest = json.loads(archive.read("manifest.json"))
    assert names[0] == "manifest.json"
    assert manifest["format"] == "thespis-package" and manifest["version"] == 1
    for entry in manifest["entries"]:
        data = (folder / entry["name"]).read_bytes()
        assert len(data) == entry["size"] and hashlib.sha256(data).hexdigest() == entry["sha256"], entry["name"]
    imported = folder / manifest["scenario"]
    for before, after in zip(poses(scenario), poses(imported), strict=True):
        np.testing.assert_array_equal(before, after)
    return manifest, folder


def test_the_demo_travels_in_a_package(tmp_path):
    manifest, folder = export_and_import(DEMO, tmp_path)
    names = [entry["name"] for entry in manifest["entries"]]
    assert names == ["demo.thespis", "motion/cmu_standing.idle", "motion/cmu_postures.pca",
                     "dialogue/antigone/antigone.aiml"]
    for name in names[1:]:
        assert (folder / name).read_bytes() == (DEMO.parent / name).read_bytes()


def test_real_files_from_elsewhere_come_along(tmp_path):
    document = thespis.Scenario()
    document.name = "Cesium walks"
    character = thespis.Character("Cesium", "model")
    character.model = str(shared("characters/CesiumMan/CesiumMan.glb"))
    character.clips = [thespis.ClipAsset("walk", str(shared("mocap/cmu/02_01.bvh")))]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("walk", "walk")]
    character.layers = [layer]
    document.characters = [character]
    document.lighting = thespis.LightingSpec(str(shared("probes/polyhaven_1k/venice_sunset_1k.hdr")))
    source = tmp_path / "source"
    source.mkdir()
    scenario = source / "walk.thespis"
    thespis.save_scenario(scenario, document)
    manifest, folder = export_and_import(scenario, tmp_path)
    names = {entry["name"] for entry in manifest["entries"]}
    assert names == {"walk.thespis", "assets/CesiumMan.glb", "assets/02_01.bvh", "assets/venice_sunset_1k.hdr"}
    assert (folder / "assets" / "CesiumMan.glb").read_bytes() == shared("characters/CesiumMan/CesiumMan.glb").read_bytes()
    imported = thespis.load_scenario(folder / "walk.thespis")
    assert imported.characters[0].model == "assets/CesiumMan.glb"


def test_a_missing_file_is_named_and_nothing_is_written(tmp_path):
    document = thespis.Scenario()
    character = thespis.Character("Creon", "hanim-loa1")
    character.clips = [thespis.ClipAsset("wave", "motion/nowhere.bvh")]
    document.characters = [character]
    scenario = tmp_path / "broken.thespis"
    thespis.save_scenario(scenario, document)
    package = tmp_path / "broken.thespkg"
    result = run("export", scenario, "--out", package)
    assert result.returncode == INVALID
    assert "characters[Creon].clips[wave].file names motion/nowhere.bvh" in result.stderr
    assert not package.exists()


def write_package(path, entries, listed=None, version=1):
    """A zip as another tool might write it: manifest.json first, listing `listed` (default: all)."""
    listed = entries if listed is None else listed
    manifest = {"format": "thespis-package", "version": version, "writer": "a test", "scenario": "play.thespis",
                "entries": [{"name": n, "size": len(d), "sha256": hashlib.sha256(d).hexdigest()} for n, d, *_ in listed]}
    with warnings.catch_warnings(), zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        warnings.simplefilter("ignore")  # zipfile warns about a duplicate name: that is the point
        archive.writestr("manifest.json", json.dumps(manifest))
        for name, data, *link in entries:
            info = zipfile.ZipInfo(name)
            info.compress_type = zipfile.ZIP_DEFLATED
            if link:
                info.create_system = 3
                info.external_attr = (0o120777 << 16)
            archive.writestr(info, data)
    return path


@pytest.fixture(scope="module")
def scenario_bytes(tmp_path_factory):
    path = tmp_path_factory.mktemp("scenario") / "play.thespis"
    thespis.save_scenario(path, thespis.Scenario())
    return path.read_bytes()


@pytest.mark.parametrize("case, words", [
    ("climbs", '"../../.bashrc" climbs out of the package'),
    ("absolute", '"/tmp/evil.sh" is an absolute path'),
    ("link", '"motion/a.bvh" is a symbolic link'),
    ("twice", '"motion/a.bvh" appears twice'),
    ("bomb", '"motion/zeros.bvh" expands'),
    ("changed", '"motion/a.bvh" does not match its SHA-256'),
    ("unlisted", '"motion/a.bvh" is not listed in the manifest'),
    ("newer", "newer"),
])
def test_unsafe_packages_are_refused_naming_the_entry(tmp_path, scenario_bytes, case, words):
    play = ("play.thespis", scenario_bytes)
    clip = ("motion/a.bvh", b"HIERARCHY\n")
    package = tmp_path / f"{case}.thespkg"
    if case == "climbs":
        write_package(package, [play, ("../../.bashrc", b"rm -rf ~")])
    elif case == "absolute":
        write_package(package, [play, ("/tmp/evil.sh", b"x")])
    elif case == "link":
        write_package(package, [play, ("motion/a.bvh", b"/etc/passwd", True)])
    elif case == "twice":
        write_package(package, [play, clip, ("motion/a.bvh", b"MOTION\n")], listed=[play, clip])
    elif case == "bomb":
        write_package(package, [play, ("motion/zeros.bvh", bytes(20 << 20))])
    elif case == "changed":
        write_package(package, [play, ("motion/a.bvh", b"HIERARCHX\n")], listed=[play, clip])
    elif case == "unlisted":
        write_package(package, [play, clip], listed=[play])
    else:
        write_package(package, [play], version=9)
    for command in (["validate", package], ["import", package, "--to", tmp_path / "out"]):
        result = run(*command)
        assert result.returncode == INVALID, (command, result.stdout, result.stderr)
        assert words in result.stdout + result.stderr, (command, result.stdout, result.stderr)
    assert not (tmp_path / "out").exists() or not any((tmp_path / "out").iterdir())


def test_import_refuses_to_overwrite_a_different_file(tmp_path):
    package = tmp_path / "demo.thespkg"
    assert run("export", DEMO, "--out", package, "--quiet").returncode == 0
    folder = tmp_path / "folder"
    (folder / "motion").mkdir(parents=True)
    (folder / "motion" / "cmu_postures.pca").write_bytes(b"mine")
    result = run("import", package, "--to", folder)
    assert result.returncode == INVALID
    assert "cmu_postures.pca is already there and differs" in result.stderr
    assert (folder / "motion" / "cmu_postures.pca").read_bytes() == b"mine"
    assert not (folder / "demo.thespis").exists()


def test_command_lines(tmp_path):
    assert run("export", DEMO).returncode == USAGE
    assert run("import", tmp_path / "none.thespkg").returncode == USAGE
    result = run("import", tmp_path / "none.thespkg", "--to", tmp_path / "x")
    assert result.returncode == INVALID and "none.thespkg does not exist" in result.stderr


def test_a_package_plays_renders_and_bakes_without_import(tmp_path):
    package = tmp_path / "demo.thespkg"
    assert run("export", DEMO, "--out", package, "--quiet").returncode == 0
    from_package = tmp_path / "from_package.bvh"
    from_folder = tmp_path / "from_folder.bvh"
    result = run("bake-motion", package, "--character", "Creon", "--end", "2", "--out", from_package)
    assert result.returncode == 0, result.stderr
    assert run("bake-motion", DEMO, "--character", "Creon", "--end", "2", "--out", from_folder).returncode == 0
    assert from_package.read_bytes() == from_folder.read_bytes()
    picture = tmp_path / "frame.png"
    result = run("render", package, "--time", "1.5", "--size", "160x120", "--out", picture)
    assert result.returncode == 0, result.stderr
    assert picture.stat().st_size > 0
    video = tmp_path / "demo.avi"
    result = run("play", package, "--size", "160x120", "--out", video)
    assert result.returncode == 0, result.stderr
    assert video.stat().st_size > 0


def test_run_and_validate_take_a_package_too(tmp_path):
    """Wherever a scenario file is taken, its package is: a script run over the package's frames
    gives the very pictures the folder gives, and validate checks the package's scenario."""
    package = tmp_path / "demo.thespkg"
    assert run("export", DEMO, "--out", package, "--quiet").returncode == 0
    result = run("validate", package)
    assert result.returncode == 0, result.stderr
    assert "valid" in result.stdout and "a package by" in result.stdout
    script = ROOT / "resources" / "scripts" / "antigone_creon.py"
    frames = {}
    for name, scenario in (("package", package), ("folder", DEMO)):
        out = tmp_path / name
        result = run("run", scenario, "--script", script, "--frames", "40:44", "--fps", "30", "--out", f"{out}/",
                     "--size", "96x72", "--samples", "1", "--quiet", timeout=300)
        assert result.returncode == 0, result.stderr
        frames[name] = sorted(out.iterdir())
        assert [p.name for p in frames[name]] == [f"frame_{i:05d}.png" for i in range(40, 45)]
    for a, b in zip(frames["package"], frames["folder"], strict=True):
        assert a.read_bytes() == b.read_bytes(), a.name
