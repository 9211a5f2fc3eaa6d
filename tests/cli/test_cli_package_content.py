"""What a package carries besides the files a scenario names: lighting bakes made first on request
(`export --bake`, into the package only, refreshed when they no longer fit) and the sounds a
script names (../shared/data's pocketsphinx recording), which then play from the package.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import subprocess
import wave
import zipfile
from pathlib import Path

import numpy as np
import pytest

import thespis

from test_cli_render import read_png

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
DEMO = ROOT / "resources" / "demo.thespis"
SPEECH = DATA / "speech" / "pocketsphinx" / "cards" / "001.wav"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)

SMALL = ["--size", "160x90", "--samples", "0"]


def run(*args, timeout=600):
    return subprocess.run([CLI, *map(str, args)], capture_output=True, text=True, timeout=timeout)


def demo_copy(tmp_path):
    """The demo imported into a folder of its own, which the test may change."""
    package = tmp_path / "demo.thespkg"
    assert run("export", DEMO, "--out", package, "--quiet").returncode == 0
    folder = tmp_path / "demo"
    assert run("import", package, "--to", folder, "--quiet").returncode == 0
    return folder / "demo.thespis"


def entries(package):
    with zipfile.ZipFile(package) as archive:
        return archive.namelist()


def differing_pixels(a, b):
    (_, _, rows_a), (_, _, rows_b) = read_png(a), read_png(b)
    return sum(x != y for ra, rb in zip(rows_a, rows_b) for x, y in zip(ra, rb))


def test_bakes_made_first_go_into_the_package_only(tmp_path):
    scenario = demo_copy(tmp_path)
    before = sorted(p.name for p in scenario.parent.rglob("*"))
    baked = tmp_path / "baked.thespkg"
    result = run("export", scenario, "--out", baked, "--bake", "--rays", 16)
    assert result.returncode == 0, result.stderr
    assert "Baked the lighting of Creon: it had none." in result.stdout
    assert "Baked the lighting of Antigone: it had none." in result.stdout
    assert {"bakes/Creon.prt", "bakes/Antigone.prt"} <= set(entries(baked))
    assert sorted(p.name for p in scenario.parent.rglob("*")) == before  # the folder is as it was
    info = run("info", baked)
    assert "lighting bake: bakes/Creon.prt" in info.stdout

    # The package lights its characters with the bakes (shadowed), the plain one without.
    plain = tmp_path / "plain.thespkg"
    assert run("export", scenario, "--out", plain, "--quiet").returncode == 0
    lit, unlit = tmp_path / "lit.png", tmp_path / "unlit.png"
    rendered = run("render", baked, "--time", 2, "--out", lit, "--size", "320x180")
    assert rendered.returncode == 0 and "left out" not in rendered.stderr, rendered.stderr
    assert run("render", plain, "--time", 2, "--out", unlit, "--size", "320x180").returncode == 0
    assert differing_pixels(lit, unlit) > 1000

    # Bakes that fit are kept; one that no longer reads is made again.
    folder = tmp_path / "with_bakes"
    assert run("import", baked, "--to", folder, "--quiet").returncode == 0
    again = run("export", folder / "demo.thespis", "--out", tmp_path / "again.thespkg", "--bake", "--rays", 16)
    assert again.returncode == 0 and "Baked" not in again.stdout, again.stdout
    (folder / "bakes" / "Creon.prt").write_bytes(b"THSPPRT\0 cut short")
    refreshed = run("export", folder / "demo.thespis", "--out", tmp_path / "refreshed.thespkg", "--bake", "--rays", 16)
    assert refreshed.returncode == 0, refreshed.stderr
    assert "Baked the lighting of Creon: its bake bakes/Creon.prt cannot be read" in refreshed.stdout
    assert "Antigone" not in refreshed.stdout
    assert run("export", folder / "demo.thespis", "--out", tmp_path / "x.thespkg", "--rays", 8).returncode == 2


def test_the_sounds_a_script_names_come_along_and_play(tmp_path):
    scenario = demo_copy(tmp_path)
    document = thespis.load_scenario(scenario)
    talk = thespis.Script("talk", "\n".join([
        "# Creon's line (it's a recording from elsewhere)",
        "animService.wait(0.5)",
        f"voiceService.activateAction('Creon', {str(SPEECH)!r}, 1.0)",
        "animService.wait(1.0)",
    ]) + "\n")
    document.scripts = [*document.scripts, talk]
    thespis.save_scenario(scenario, document)
    package = tmp_path / "talk.thespkg"
    result = run("export", scenario, "--out", package)
    assert result.returncode == 0, result.stderr
    assert "assets/001.wav" in entries(package)
    packed = thespis.open_package(package)
    source = [s for s in packed.scenario.scripts if s.name == "talk"][0].source
    assert "'assets/001.wav'" in source and str(SPEECH) not in source

    # Played from the package, in a fresh folder, the voice is heard.
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    moved = elsewhere / "talk.thespkg"
    package.rename(moved)
    out = tmp_path / "talk.avi"
    played = run("play", moved, "--script", "talk", "--audio", "--out", out, "--fps", 10, *SMALL)
    assert played.returncode == 0, played.stderr
    with wave.open(str(tmp_path / "talk.wav")) as w:
        samples = np.frombuffer(w.readframes(w.getnframes()), dtype="<i2")
    assert np.abs(samples[:24000]).max() == 0 and np.abs(samples[24000:]).max() > 1000
