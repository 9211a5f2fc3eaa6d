"""Bringing your own content with thespis.edit: a scenario built from nothing — characters on the
built-in humanoid and on a glTF model, real motion capture and glTF animations imported, layers,
placement, the light — each step an Edit whose inverse takes it back."""

import math

import pytest

import thespis
from thespis import edit
from conftest import SHARED_DATA, mocap


def apply(scenario, change):
    change.apply(scenario)
    return change


def hips(runtime_character, seconds):
    """World position of the character's humanoid_root at `seconds`."""
    frame = runtime_character.evaluate_body(seconds)
    skeleton = runtime_character.skeleton
    return skeleton.world_positions(frame)[skeleton.find("humanoid_root")]


def test_build_a_scenario_from_nothing_and_undo_it(tmp_path):
    scenario = thespis.Scenario("from nothing")
    steps = []
    steps.append(apply(scenario, edit.add_character(scenario, edit.new_character("Walker"))))
    robot = edit.new_character("Robot", str(SHARED_DATA / "characters/RobotExpressive/RobotExpressive.glb"), "model")
    steps.append(apply(scenario, edit.add_character(scenario, robot)))
    steps.append(apply(scenario, edit.set_character_placement(scenario, 1, (2.0, 0.0, 0.0), -30.0)))
    assert [c.name for c in scenario.characters] == ["Walker", "Robot"]

    runtime = thespis.build_runtime(scenario, tmp_path)
    walk = thespis.plan_clip_import(mocap("cmu/02_01.bvh"), tmp_path, runtime.characters[0].skeleton)
    assert walk.report.convention == "cmu"
    assert walk.report.unit_name.startswith("CMU")
    assert walk.problem == ""
    assert walk.mapping["LeftUpLeg"] == "l_hip"
    # CMU's LHipJoint and RHipJoint have no H-Anim name, but the legs below them carry their turn.
    assert walk.report.unmapped == ["LHipJoint", "RHipJoint"]
    assert walk.moving_nothing == []
    assert [clip.name for clip in walk.clips] == ["02_01"]
    assert not walk.clips[0].file.startswith("/")  # relative to the scenario's folder
    steps.append(apply(scenario, edit.add_clips(scenario, 0, walk.clips)))

    gltf = thespis.plan_clip_import(SHARED_DATA / "characters/RobotExpressive/RobotExpressive.glb", tmp_path,
                                    runtime.characters[1].skeleton)
    assert "Walking" in [clip.animation for clip in gltf.clips]
    assert len(gltf.clips) == 14
    assert gltf.moving_nothing == []  # on its own rig every joint plays
    on_walker = thespis.plan_clip_import(SHARED_DATA / "characters/RobotExpressive/RobotExpressive.glb", tmp_path,
                                         runtime.characters[0].skeleton)
    assert on_walker.moving_nothing == ["PoleTarget.L", "PoleTarget.R"]  # the rig's IK targets
    steps.append(apply(scenario, edit.add_clips(scenario, 1, [c for c in gltf.clips if c.name == "Walking"])))

    for character, clip in ((0, "02_01"), (1, "Walking")):
        action = edit.action_from_clip(scenario, (character, 0), clip, 0)
        assert action.placement == thespis.Placement.continue_  # motion capture goes on from where it is
        steps.append(apply(scenario, edit.insert_actions(scenario, (character, 0), [action])))
    steps.append(apply(scenario, edit.add_layer(scenario, 0, "gestures")))
    steps.append(apply(scenario, edit.move_layer(scenario, (0, 2), -1)))
    assert [layer.name for layer in scenario.characters[0].layers] == ["body", "gestures", "face"]
    light = thespis.LightingSpec()
    light.probe = str(SHARED_DATA / "probes/polyhaven_1k/venice_sunset_1k.hdr")
    light.layout = "latlong"
    light.rotation = 90.0
    light.intensity = 1.5
    steps.append(apply(scenario, edit.set_lighting(scenario, light)))

    # Saved and read back, it plays: the walker stands at its place at hip height and walks.
    path = tmp_path / "mine.thespis"
    thespis.save_scenario(path, scenario)
    again = thespis.load_scenario(path)
    assert again == scenario
    runtime = thespis.build_runtime(again, tmp_path)
    walker = runtime.characters[0]
    start, later = hips(walker, 0.0), hips(walker, 2.0)
    assert math.hypot(start[0], start[2]) < 0.15
    assert 0.85 < start[1] < 1.05
    assert math.hypot(later[0] - start[0], later[2] - start[2]) > 1.5
    assert walker.clip_reports["02_01"].calibration_frame is False
    robot_start = hips(runtime.characters[1], 0.0)
    assert abs(robot_start[0] - 2.0) < 0.3

    # Every step undone, newest first: the empty scenario again.
    for step in reversed(steps):
        step.inverse().apply(scenario)
    assert scenario == thespis.Scenario("from nothing")


def test_refused_edits_say_why():
    scenario = thespis.Scenario("s")
    edit.add_character(scenario, edit.new_character("A")).apply(scenario)
    edit.add_character(scenario, edit.new_character("B")).apply(scenario)
    with pytest.raises(ValueError, match="already named"):
        edit.rename_character(scenario, 1, "A")
    with pytest.raises(ValueError, match="no rig of its own"):
        edit.set_character_body(scenario, 0, "", "model")
    with pytest.raises(ValueError, match="cannot move further up"):
        edit.move_layer(scenario, (0, 0), -1)
    bad = thespis.LightingSpec()
    bad.intensity = -1.0
    with pytest.raises(ValueError, match="intensity"):
        edit.set_lighting(scenario, bad)


def test_a_file_that_moves_nothing_and_one_that_does_not_parse(tmp_path):
    scenario = thespis.Scenario("s")
    edit.add_character(scenario, edit.new_character("A")).apply(scenario)
    skeleton = thespis.build_runtime(scenario, tmp_path).characters[0].skeleton
    face = thespis.plan_clip_import(mocap("makehuman/face-poseunits.bvh"), tmp_path, skeleton)
    assert face.joints_moved == 0
    assert "moves none of the character's joints" in face.problem
    broken = tmp_path / "broken.bvh"
    broken.write_text("HIERARCHY\nROOT Hips\n{\n  OFFSET 0 0\n")
    with pytest.raises(thespis.FormatError, match="broken.bvh, line 4"):
        thespis.plan_clip_import(broken, tmp_path, skeleton)


def test_a_corrected_mapping_is_used_and_saved(tmp_path):
    scenario = thespis.Scenario("s")
    edit.add_character(scenario, edit.new_character("A")).apply(scenario)
    skeleton = thespis.build_runtime(scenario, tmp_path).characters[0].skeleton
    plan = thespis.plan_clip_import(mocap("cmu/02_01.bvh"), tmp_path, skeleton)
    mapping = {joint: name for joint, name in plan.mapping.items() if joint != name}
    del mapping["LeftArm"]  # left as it is named in the file: the left arm no longer moves
    corrected = thespis.plan_clip_import(mocap("cmu/02_01.bvh"), tmp_path, skeleton, mapping)
    assert corrected.report.convention == "user"
    assert "LeftArm" in corrected.report.unmapped
    assert corrected.clips[0].mapping == mapping
    thespis.save_mapping(tmp_path / "cmu.map", mapping)
    text = (tmp_path / "cmu.map").read_text()
    assert "LeftUpLeg  l_hip" in text
    assert "LeftArm" not in text
    assert corrected.joints_moved == plan.joints_moved - 1
