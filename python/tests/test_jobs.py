"""Long work from Python runs the same core jobs as the CLI and the studio: progress on this
thread, an exception in the callback (or Ctrl-C) stops the job, and a stopped job leaves no file.
Real data: the demo scenario and a Poly Haven probe."""

import numpy as np
import pytest

import thespis
from thespis import lighting, render
from conftest import SHARED_DATA, demo_scenario


def test_bake_motion_writes_the_frames_it_reports(tmp_path):
    scenario = thespis.load_scenario(demo_scenario())
    character = scenario.characters[0].name
    out = tmp_path / "demo.bvh"
    reports = []
    frames = thespis.bake_motion(scenario, character, out, base_dir=demo_scenario().parent, fps=10, end=2.0,
                                 progress=lambda done, total: reports.append((done, total)))
    assert frames == 21
    assert reports and reports[-1] == (21, 21)
    skeleton, clip, report = thespis.bvh.load(out)
    assert clip.frame_count == 21


def test_bake_motion_writes_a_gltf_animation(tmp_path):
    # CesiumMan walking a CMU clip: the .glb read back gives its motion, the animation alone too.
    scenario = thespis.Scenario()
    character = thespis.Character("Cesium", "model")
    character.model = str(SHARED_DATA / "characters" / "CesiumMan" / "CesiumMan.glb")
    character.clips = [thespis.ClipAsset("walk", str(SHARED_DATA / "mocap" / "cmu" / "02_01.bvh"))]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("walk", "walk")]
    character.layers = [layer]
    scenario.characters = [character]
    frames = thespis.bake_motion(scenario, "Cesium", tmp_path / "walk.glb", base_dir=tmp_path, fps=10, end=1.0)
    assert frames == 11
    read = thespis.scene.load_gltf_character(tmp_path / "walk.glb")
    walk = [clip for clip in read.clips if clip.name == "Cesium"][0]
    assert walk.frame_count == 31  # 1 s, resampled at the import's 30 fps
    assert not np.allclose(walk.frames[0], walk.frames[-1])
    thespis.bake_motion(scenario, "Cesium", tmp_path / "only.glb", base_dir=tmp_path, fps=10, end=1.0, animation_only=True)
    assert (tmp_path / "only.glb").stat().st_size < (tmp_path / "walk.glb").stat().st_size / 4


def test_bake_motion_refuses_an_unknown_character(tmp_path):
    scenario = thespis.load_scenario(demo_scenario())
    with pytest.raises(KeyError, match="Nobody"):
        thespis.bake_motion(scenario, "Nobody", tmp_path / "x.bvh", base_dir=demo_scenario().parent)
    assert not (tmp_path / "x.bvh").exists()


def test_a_stopped_frame_sequence_takes_its_frames_back(tmp_path):
    def stop_after_two(done, total):
        if done >= 2:
            raise RuntimeError("enough")

    folder = tmp_path / "frames"
    with pytest.raises(RuntimeError, match="enough"):
        render.render_frames(demo_scenario(), folder, 0, 300, width=64, height=48, samples=0,
                             progress=stop_after_two)
    assert folder.is_dir() and not any(folder.iterdir())


def test_render_frames_writes_the_sequence(tmp_path):
    folder = tmp_path / "frames"
    render.render_frames(demo_scenario(), folder, 4, 5, width=64, height=48, samples=0)
    assert sorted(p.name for p in folder.iterdir()) == ["frame_00004.png", "frame_00005.png"]


def test_project_probe_runs_as_a_job_with_progress():
    reports = []
    light = lighting.project_probe(SHARED_DATA / "probes/polyhaven_1k/venice_sunset_1k.hdr", order=3,
                                   progress=lambda done, total: reports.append((done, total)))
    assert light.shape == (3, 9) and np.all(np.isfinite(light)) and light[0, 0] > 0
    assert reports and reports[-1] == (1, 1)
