"""Characters and rendering from Python: the built-in humanoid, glTF characters mapped onto
H-Anim, skinning into a pose, and a scenario rendered headless into a NumPy image."""

import os
from pathlib import Path

import numpy as np
import pytest

import thespis
from thespis import hanim, render, scene

DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
CESIUM = DATA / "characters" / "CesiumMan" / "CesiumMan.glb"
DEMO = Path(__file__).resolve().parents[2] / "resources" / "demo.thespis"


def test_default_humanoid_is_a_skinned_hanim_character():
    body = scene.default_humanoid(hanim.Level.subset25)
    body.validate()
    assert body.skeleton.joint_count == 25
    assert 25000 <= body.mesh.triangle_count <= 40000  # the body's 20 000 and the face's
    names = {segment.name for segment in body.mesh.segments}
    assert {"skull", "hair", "l_thigh", "r_upperarm", "l_eyeball", "tongue"} <= names
    weights = body.skin_weights
    assert weights.shape == (body.mesh.vertex_count, body.influences)
    np.testing.assert_allclose(weights.sum(axis=1), 1.0, atol=1e-3)
    with pytest.raises(ValueError):
        scene.default_humanoid(detail=0.0)


def test_skinning_the_rest_frame_gives_the_rest_mesh_and_a_turn_moves_the_head():
    body = scene.default_humanoid()
    rest = body.skeleton.rest_frame()
    positions, normals = body.skin(rest)
    np.testing.assert_allclose(positions, body.mesh.positions, atol=1e-6)
    np.testing.assert_allclose(np.linalg.norm(normals, axis=1), 1.0, atol=1e-4)
    turned = rest.copy()
    skull = body.skeleton.find("skullbase")
    turned[4 * skull:4 * skull + 4] = [0.0, np.sin(0.5), 0.0, np.cos(0.5)]  # 60° about y
    for method in (scene.SkinningMethod.LBS, scene.SkinningMethod.DQS):
        moved, _ = body.skin(turned, method)
        head = next(s for s in body.mesh.segments if s.name == "skull")
        part = slice(head.first_vertex, head.first_vertex + head.vertex_count)
        assert np.abs(moved[part] - positions[part]).max() > 0.05
        feet = next(s for s in body.mesh.segments if s.name == "l_talus")
        part = slice(feet.first_vertex, feet.first_vertex + feet.vertex_count)
        np.testing.assert_allclose(moved[part], positions[part], atol=1e-6)
    with pytest.raises(ValueError, match="values"):
        body.skin(rest[:-1])


def test_gltf_character_maps_onto_hanim():
    if not CESIUM.exists():
        pytest.fail(f"{CESIUM} is missing (../shared/data)")
    cesium = scene.load_gltf_character(CESIUM)
    cesium.validate()
    joints = {cesium.skeleton.joint(i).name for i in range(cesium.skeleton.joint_count)}
    assert {"humanoid_root", "skullbase", "l_elbow", "r_knee"} <= joints
    assert len(cesium.clips) == 1 and cesium.clips[0].frame_rate == 30.0
    assert scene.automatic_hanim_name("mixamorig:LeftForeArm") == "l_elbow"
    with pytest.raises(FileNotFoundError):
        scene.load_gltf_character(DATA / "nowhere.glb")


def test_render_scenario_draws_the_demo(tmp_path):
    image = render.render_scenario(DEMO, time=2.0, width=160, height=90, shading="unlit")
    assert image.shape == (90, 160, 4) and image.dtype == np.uint8
    assert (image[0] == image[0, 0]).all(), "the top row is background"
    assert (image[45] != image[0, 0]).any(axis=1).sum() > 5, "the characters are in the middle"
    lit = render.render_scenario(DEMO, time=2.0, width=160, height=90)
    assert not np.array_equal(lit, image)
    out = tmp_path / "demo.png"
    render.write_png(out, image)
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    with pytest.raises(ValueError, match="shading"):
        render.render_scenario(DEMO, shading="toon")
