"""thespis.face: face mapping tables from Python — RobotExpressive's recognised expressions played
onto its mesh and in a headless render of a scenario's face layer, a table made, saved, loaded and
applied with warnings for what the model lacks, a table given when the model is loaded, and reader
errors that name the field."""

import json

import numpy as np
import pytest

import thespis
from thespis import edit, face, render, scene

from conftest import SHARED_DATA

ROBOT = SHARED_DATA / "characters" / "RobotExpressive" / "RobotExpressive.glb"


def frame(**channels):
    values = np.zeros(face.CHANNEL_COUNT, np.float32)
    for name, value in channels.items():
        values[face.find_channel(name)] = value
    return values


def test_robot_expressives_targets_are_recognised_and_anger_moves_exactly_the_angry_target():
    robot = scene.load_gltf_character(ROBOT)
    assert face.morph_target_names(robot) == ["Angry", "Surprised", "Sad"]
    mapping = face.recognise_mapping(robot)
    assert "expression targets" in mapping.name
    by_target = {drive.target: face.channel_name(drive.channel) for drive in mapping.drives}
    assert by_target == {"Angry": "anger", "Surprised": "surprise", "Sad": "sadness"}

    rest, _ = face.deform(robot, np.zeros(face.CHANNEL_COUNT, np.float32))
    np.testing.assert_array_equal(rest, robot.mesh.positions)
    angry, _ = face.deform(robot, frame(anger=1.0))
    moved = np.flatnonzero(np.any(angry != rest, axis=1))
    assert len(moved) > 100
    half, _ = face.deform(robot, frame(anger=0.5))
    np.testing.assert_allclose(half[moved] - rest[moved], 0.5 * (angry[moved] - rest[moved]), atol=1e-6)
    with pytest.raises(ValueError, match="88"):
        face.deform(robot, np.zeros(3, np.float32))


def test_a_table_is_made_saved_loaded_and_applied_with_a_warning_per_missing_name(tmp_path):
    mapping = face.Mapping(
        "studio rig",
        [face.Drive("Sad", "sadness", 1.0), face.Drive("Blink_L", "close_t_l_eyelid", 1 / 1024, face.Side.POSITIVE)],
        [face.JointDrive("EyeBone_L", "yaw_l_eyeball", (0, 1, 0), 1e-5)],
    )
    path = tmp_path / "rig.json"
    face.save_mapping(path, mapping)
    document = json.loads(path.read_text())
    assert document["format"] == "thespis-face-mapping" and document["version"] == 1
    assert document["drives"][1] == {"target": "Blink_L", "channel": "close_t_l_eyelid",
                                     "coefficient": 1 / 1024, "side": "positive"}
    loaded = face.load_mapping(path)
    assert loaded == mapping
    assert face.Mapping.from_json(mapping.to_json()) == mapping

    robot = scene.load_gltf_character(ROBOT)
    warnings = face.apply_mapping(robot, loaded)
    assert warnings == [
        'The face mapping "studio rig" drives the morph target "Blink_L", which RobotExpressive does not have.',
        'The face mapping "studio rig" turns the joint "EyeBone_L", which RobotExpressive does not have.',
    ]
    # Only Sad plays now: anger moves nothing, sadness moves the Sad target.
    rest, _ = face.deform(robot, np.zeros(face.CHANNEL_COUNT, np.float32))
    np.testing.assert_array_equal(face.deform(robot, frame(anger=1.0))[0], rest)
    assert np.any(face.deform(robot, frame(sadness=1.0))[0] != rest)

    given = scene.load_gltf_character(ROBOT, face_mapping=loaded)
    assert any("Blink_L" in warning for warning in given.warnings)


def test_reader_errors_name_the_file_and_the_field(tmp_path):
    path = tmp_path / "bad.json"
    path.write_text(json.dumps({"format": "thespis-face-mapping", "version": 1,
                                "drives": [{"target": "a", "channel": "open_mouth", "coefficient": 1}]}))
    with pytest.raises(thespis.FormatError, match=r"bad\.json.*drives\[0\]\.channel"):
        face.load_mapping(path)
    with pytest.raises(ValueError, match="not a face channel"):
        face.Drive("a", "open_mouth", 1.0)
    with pytest.raises(FileNotFoundError):
        face.load_mapping(tmp_path / "none.json")


def test_a_face_layer_plays_robot_expressives_anger_in_a_render(tmp_path):
    document = thespis.Scenario()
    document.name = "Angry robot"
    robot = thespis.Character("Robot", "model")
    robot.model = str(ROBOT)
    anger = thespis.ClipAsset("anger", "")
    anger.frame_rate = 1.0
    anger.scalars = ["expression3"]
    anger.frames = np.array([1.0, 1.0], np.float32)
    robot.clips = [anger]
    layer = thespis.Layer("face", thespis.LayerKind.face)
    layer.actions = [thespis.ActionSpec("anger", "anger")]
    robot.layers = [layer]
    document.characters = [robot]
    angry = tmp_path / "angry.thespis"
    thespis.save_scenario(angry, document)
    layer.mute = True
    robot.layers = [layer]
    document.characters = [robot]
    calm = tmp_path / "calm.thespis"
    thespis.save_scenario(calm, document)

    pictures = [render.render_scenario(path, time=0.5, width=240, height=320, shading="unlit", ground=False)
                for path in (calm, angry)]
    render.write_png(tmp_path / "angry.png", pictures[1])
    changed = np.any(pictures[0] != pictures[1], axis=2)
    rows = np.flatnonzero(changed.any(axis=1))
    assert changed.sum() > 20, "anger changed no pixel"
    # Only the head changes: the rows that differ are all in the picture's upper half.
    figure = np.flatnonzero(np.any(pictures[0][:, :, :3] != pictures[0][0, 0, :3], axis=2).any(axis=1))
    assert rows.max() < (figure.min() + figure.max()) / 2


def test_the_humanoids_face_has_mpeg4_feature_points_and_units():
    from thespis import scene
    body = scene.default_humanoid()
    units = face.fap_units(body)
    assert abs(units["ES"] * 1024 - 0.064) < 0.004  # pupils 64 mm apart
    assert units["AU"] == 1e-5
    points = face.feature_points(body)
    assert {"2.1", "2.2", "3.5", "9.15"} <= set(points)
    assert points["3.5"][0] > 0 > points["3.6"][0]  # the left pupil is on the face's left (+x)
    assert face.fap(3) == {"number": 3, "name": "open_jaw", "unit": "MNS", "bidirectional": False,
                           "direction": "down", "feature_point": "2.1"}
    # open_jaw of 400 lowers the chin by 400 MNS units.
    frame = np.zeros(face.CHANNEL_COUNT, dtype=np.float32)
    frame[face.find_channel("open_jaw")] = 400
    positions, _ = face.deform(body, frame)
    chin = [i for i, p in enumerate(body.mesh.positions) if tuple(p) == points["2.1"]][0]
    assert abs((points["2.1"][1] - positions[chin][1]) - 400 * units["MNS"]) < 0.01 * 400 * units["MNS"]


def test_face_masks_weigh_the_face_by_region():
    speech = face.mask_preset(face.MaskPreset.speech)
    assert face.is_face_mask(speech)
    assert not face.is_face_mask(thespis.JointMask.preset(thespis.MaskPreset.upper_body))
    assert set(face.REGIONS) >= {"mouth", "eyes", "brows", "tongue", "expressions"}
    assert face.channel_region("open_jaw") == "mouth"
    assert face.channel_region("raise_l_i_eyebrow") == "brows"
    assert face.channel_region("viseme3") == "mouth"
    assert face.channel_region("joy") == "expressions"
    weights = speech.resolve(thespis.FrameLayout.mpeg4_face())
    assert weights[face.find_channel("open_jaw")] == 1.0
    assert weights[face.find_channel("raise_l_i_eyebrow")] == 0.0
    speech.set_weight("fap31", 0.5)
    mirrored = face.mirrored_mask(speech).resolve(thespis.FrameLayout.mpeg4_face())
    assert mirrored[face.find_channel("raise_r_i_eyebrow")] == 0.5
    assert mirrored[face.find_channel("raise_l_i_eyebrow")] == 0.0


def test_a_scenario_character_names_its_own_table(tmp_path):
    """Character.face_mapping (format 8): saved and read back, set by an undoable edit, checked by
    validate_scenario (a missing file and the built-in humanoid are named by their field)."""
    face.save_mapping(tmp_path / "joy.json", face.Mapping("joy", [face.Drive("Surprised", "joy", 1.0)], []))
    scenario = thespis.Scenario("robot")
    scenario.characters = [edit.new_character("Robot", str(ROBOT), "model"),
                           edit.new_character("Ann")]
    assert scenario.characters[0].face_mapping == ""
    change = edit.set_character_face_mapping(scenario, 0, "joy.json")
    change.apply(scenario)
    assert scenario.characters[0].face_mapping == "joy.json"
    assert thespis.validate_scenario(scenario, tmp_path) == []
    back = thespis.parse_scenario(thespis.serialize_scenario(scenario))
    assert back.characters[0].face_mapping == "joy.json"
    change.inverse().apply(scenario)
    assert scenario.characters[0].face_mapping == ""
    with pytest.raises(ValueError, match="built-in humanoid"):
        edit.set_character_face_mapping(scenario, 1, "joy.json")

    characters = scenario.characters
    characters[0].face_mapping = "gone.json"
    characters[1].face_mapping = "joy.json"
    scenario.characters = characters
    problems = [problem.message for problem in thespis.validate_scenario(scenario, tmp_path)]
    assert any(p.startswith("characters[0].faceMapping (Robot)") and "gone.json" in p for p in problems), problems
    assert any(p.startswith("characters[1].faceMapping (Ann)") for p in problems), problems
