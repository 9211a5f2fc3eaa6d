"""Scenario documents: the demo's load / save / parse / serialize round trips, editing from
Python, building runnable schedules, validation and errors naming the field."""

import json
import math

import numpy as np
import pytest

import thespis
from conftest import REPO, demo_scenario


@pytest.fixture
def demo():
    return thespis.load_scenario(demo_scenario())


def test_demo_loads(demo):
    assert demo.name
    assert len(demo.characters) >= 1
    assert demo.duration >= 0
    assert demo.duration_seconds == pytest.approx(demo.duration / thespis.TICKS_PER_SECOND)
    first = demo.characters[0]
    assert demo.find_character(first.name) == first
    assert demo.find_character("no such character") is None
    for character in demo.characters:
        for layer in character.layers:
            for action in layer.actions:
                assert action.start_seconds == pytest.approx(thespis.ticks_to_seconds(action.start))


def test_serialize_parse_round_trip(demo):
    text = thespis.serialize_scenario(demo)
    document = json.loads(text)
    assert document["format"] == thespis.SCENARIO_FORMAT == "thespis-scenario"
    assert document["version"] == thespis.SCENARIO_VERSION
    assert thespis.parse_scenario(text) == demo
    assert thespis.serialize_scenario(thespis.parse_scenario(text)) == text


def test_save_load_round_trip(demo, tmp_path):
    path = tmp_path / f"copy{thespis.SCENARIO_EXTENSION}"
    thespis.save_scenario(path, demo)
    assert [p.name for p in tmp_path.iterdir()] == [path.name]  # atomic: no temporary left
    assert thespis.load_scenario(path) == demo


def test_unknown_fields_survive_a_round_trip(demo):
    document = json.loads(thespis.serialize_scenario(demo))
    document["studioLayout"] = {"panels": ["timeline", "curves"]}
    document["characters"][0]["costume"] = "red"
    again = thespis.parse_scenario(json.dumps(document))
    assert again.extra["studioLayout"] == {"panels": ["timeline", "curves"]}
    assert again.characters[0].extra == {"costume": "red"}
    rewritten = json.loads(thespis.serialize_scenario(again))
    assert rewritten["studioLayout"] == {"panels": ["timeline", "curves"]}
    assert rewritten["characters"][0]["costume"] == "red"


def test_editing_from_python_changes_the_document(demo):
    # Document objects are values: edit a copy of a list and assign it back.
    characters = demo.characters
    characters[0].name = "Renamed"
    assert demo.characters[0].name != "Renamed"
    layers = characters[0].layers
    count = len(layers[0].actions)
    action = thespis.ActionSpec("extra_action", characters[0].clips[0].name, thespis.seconds_to_ticks(0.5))
    action.weight = thespis.Curve.cubic_fade(0.2, 0.2)
    layers[0].actions = layers[0].actions + [action]
    characters[0].layers = layers
    demo.characters = characters
    assert demo.characters[0].name == "Renamed"
    assert len(demo.characters[0].layers[0].actions) == count + 1
    assert demo.find_character("Renamed") == demo.characters[0]
    again = thespis.parse_scenario(thespis.serialize_scenario(demo))
    assert again.characters[0].name == "Renamed"
    added = again.characters[0].layers[0].actions[count]
    assert added.name == "extra_action" and added.start == thespis.seconds_to_ticks(0.5)
    assert added.weight == thespis.Curve.cubic_fade(0.2, 0.2)


def test_a_kept_item_stays_valid_when_its_list_grows(demo):
    first = demo.characters[0]
    demo.characters = demo.characters + [thespis.Character(f"extra{i}") for i in range(50)]
    assert first.name == demo.characters[0].name  # a copy: never a dangling view


def test_a_scenario_built_from_scratch():
    scenario = thespis.Scenario("scratch")
    ada = thespis.Character("Ada", "hanim-loa1")
    clip = thespis.ClipAsset("still")
    clip.joints = ["humanoid_root", "l_elbow"]
    clip.root_translation = True
    clip.frame_rate = 10.0
    frames = np.array([[0, 0, 0, 1, 0, 0, 0.3826834, 0.9238795, 0, 0.9, 0]] * 11, np.float32)
    clip.frames = frames.ravel()
    ada.clips = [clip]
    layer = thespis.Layer("body")
    layer.actions = [thespis.ActionSpec("hold", "still", 0)]
    ada.layers = [layer]
    scenario.characters = [ada]
    scenario.duration_seconds = 1.0
    assert thespis.validate_scenario(scenario) == []
    runtime = thespis.build_runtime(scenario)
    assert runtime.duration == pytest.approx(1.0)
    ada_runtime = runtime.find_character("Ada")
    frame = ada_runtime.body.evaluate(0.5)
    elbow = ada_runtime.skeleton.find("l_elbow")
    np.testing.assert_allclose(abs(frame[4 * elbow + 3]), 0.9238795, atol=1e-5)
    assert thespis.parse_scenario(thespis.serialize_scenario(scenario)) == scenario


def test_build_runtime_of_the_demo(demo):
    runtime = thespis.build_runtime(demo, demo_scenario().parent)
    assert [c.name for c in runtime.characters] == [c.name for c in demo.characters]
    assert runtime.duration > 0 and math.isfinite(runtime.duration)
    for character, spec in zip(runtime.characters, demo.characters):
        assert len(character.layers) == len(spec.layers)
        assert [len(ids) for ids in character.action_ids] == [len(layer.actions) for layer in spec.layers]
        assert character.body.layout == character.skeleton.frame_layout
        frames = character.body.sample(np.linspace(0.0, runtime.duration, 25))
        assert frames.shape == (25, character.skeleton.frame_layout.float_count)
        assert np.all(np.isfinite(frames))
        n = character.skeleton.joint_count
        norms = np.linalg.norm(frames[:, : 4 * n].reshape(25, n, 4), axis=2)
        np.testing.assert_allclose(norms, 1.0, atol=1e-5)
        for name, clip in character.clips.items():
            assert clip.layout == character.skeleton.frame_layout
            if {c.name: c for c in spec.clips}[name].idle is None:
                assert isinstance(clip, thespis.KeyframeClip)
            else:  # synthesized: open-ended
                assert isinstance(clip, thespis.Blendable) and math.isinf(clip.domain.end)
    assert thespis.validate_scenario(demo, demo_scenario().parent) == []


def test_malformed_field_is_a_format_error_naming_it(demo):
    document = json.loads(thespis.serialize_scenario(demo))
    document["characters"][0]["layers"][0]["actions"][0]["start"] = "soon"
    with pytest.raises(thespis.FormatError, match=r"characters\[0\]\.layers\[0\]\.actions\[0\]\.start") as info:
        thespis.parse_scenario(json.dumps(document))
    assert isinstance(info.value, ValueError)
    assert info.value.code == thespis.ErrorCode.corrupt_data


def test_newer_version_is_refused(demo):
    document = json.loads(thespis.serialize_scenario(demo))
    document["version"] = thespis.SCENARIO_VERSION + 1
    with pytest.raises(thespis.FormatError, match="newer") as info:
        thespis.parse_scenario(json.dumps(document))
    assert info.value.code == thespis.ErrorCode.newer_version


def test_not_a_scenario():
    with pytest.raises(thespis.FormatError) as info:
        thespis.parse_scenario('{"format": "something-else", "version": 1}')
    assert info.value.code == thespis.ErrorCode.not_our_format
    with pytest.raises(thespis.FormatError):
        thespis.parse_scenario("{ not json")


def test_invalid_references_are_listed_by_validate(demo):
    characters = demo.characters
    layers = characters[0].layers
    actions = layers[0].actions
    action = actions[0]
    action.clip = "missing_clip"
    layers[0].actions = actions
    characters[0].layers = layers
    demo.characters = characters
    problems = thespis.validate_scenario(demo, demo_scenario().parent)
    assert problems, "a reference to a missing clip must be a problem"
    text = str(problems[0])
    assert "missing_clip" in text and demo.characters[0].name in text and action.name in text
    assert all(isinstance(p, thespis.Error) for p in problems)
    with pytest.raises(ValueError, match="missing_clip"):
        thespis.build_runtime(demo, demo_scenario().parent)


def test_missing_scenario_file(tmp_path):
    with pytest.raises(FileNotFoundError):
        thespis.load_scenario(tmp_path / "absent.thespis")


# Format 2: layer mute / solo / lock, gestures (the gesticon), markers, the character's bake.


def test_demo_lists_gestures_and_markers(demo):
    creon = demo.find_character("Creon")
    assert [g.name for g in creon.gestures] == ["greet", "agree", "point"]
    greet = creon.find_gesture("greet")
    assert greet == creon.gestures[0]
    assert (greet.clip, greet.mask) == ("wave", "rightArm")
    assert (greet.fade_in, greet.fade_out) == (282240000, 352800000)
    assert thespis.ticks_to_seconds(greet.fade_in) == pytest.approx(0.4)
    assert greet.dependent_joint_filter is True
    assert creon.find_gesture("agree").clip == "nod"
    assert creon.find_gesture("bow") is None
    assert [(m.name, m.time) for m in demo.markers] == [
        ("Creon greets", 1058400000),
        ("Antigone answers", 4233600000),
    ]
    assert thespis.ticks_to_seconds(demo.markers[0].time) == pytest.approx(1.5)
    for character in demo.characters:
        assert character.bake == ""
        for layer in character.layers:
            assert (layer.mute, layer.solo, layer.lock) == (False, False, False)


def scenario_with_format_2_fields():
    scenario = thespis.Scenario("format2")
    ada = thespis.Character("Ada", "hanim-loa1")
    ada.bake = "bakes/ada.prt"
    ada.clips = [thespis.ClipAsset("wave", "wave.bvh")]
    body = thespis.Layer("body")
    body.mute = True
    face = thespis.Layer("face", thespis.LayerKind.face)
    face.solo = True
    face.lock = True
    ada.layers = [body, face]
    greet = thespis.Gesture("greet", "wave", "rightArm")
    greet.fade_in = thespis.seconds_to_ticks(0.25)
    greet.fade_out = thespis.seconds_to_ticks(0.5)
    greet.dependent_joint_filter = True
    ada.gestures = [greet, thespis.Gesture("shrug", "wave")]
    scenario.characters = [ada]
    scenario.markers = [thespis.Marker("cue", thespis.seconds_to_ticks(1.0)), thespis.Marker("end", 7)]
    return scenario


def test_format_2_fields_survive_save_and_load(tmp_path):
    scenario = scenario_with_format_2_fields()
    path = tmp_path / f"format2{thespis.SCENARIO_EXTENSION}"
    thespis.save_scenario(path, scenario)
    again = thespis.load_scenario(path)
    assert again == scenario
    ada = again.find_character("Ada")
    assert ada.bake == "bakes/ada.prt"
    assert [(l.name, l.mute, l.solo, l.lock) for l in ada.layers] == [
        ("body", True, False, False),
        ("face", False, True, True),
    ]
    assert [g.name for g in ada.gestures] == ["greet", "shrug"]
    greet = ada.find_gesture("greet")
    assert (greet.clip, greet.mask, greet.dependent_joint_filter) == ("wave", "rightArm", True)
    assert (greet.fade_in, greet.fade_out) == (thespis.seconds_to_ticks(0.25), thespis.seconds_to_ticks(0.5))
    shrug = ada.find_gesture("shrug")
    assert (shrug.mask, shrug.fade_in, shrug.fade_out, shrug.dependent_joint_filter) == ("", 0, 0, False)
    assert [(m.name, m.time) for m in again.markers] == [("cue", thespis.TICKS_PER_SECOND), ("end", 7)]
    # == compares each new field: a document that differs in one of them is not equal.
    for field in ("markers", "bake", "gestures", "fade_out", "mute"):
        changed = thespis.load_scenario(path)
        ada = changed.characters[0]
        if field == "markers":
            changed.markers = changed.markers[:1]
        elif field == "bake":
            ada.bake = ""
        elif field == "gestures":
            ada.gestures = ada.gestures[1:]
        elif field == "fade_out":
            gestures = ada.gestures
            gestures[0].fade_out += 1
            ada.gestures = gestures
        else:
            layers = ada.layers
            layers[0].mute = False
            ada.layers = layers
        changed.characters = [ada]
        assert changed != scenario, field


def test_format_2_fields_are_written_under_their_json_names():
    document = json.loads(thespis.serialize_scenario(scenario_with_format_2_fields()))
    ada = document["characters"][0]
    assert ada["bake"] == "bakes/ada.prt"
    assert ada["gestures"][0]["name"] == "greet" and ada["gestures"][0]["dependentJointFilter"] is True
    assert ada["layers"][0]["mute"] is True and ada["layers"][1]["lock"] is True
    assert [m["name"] for m in document["markers"]] == ["cue", "end"]


def test_adding_a_marker_and_a_gesture_to_the_demo(demo, tmp_path):
    markers = demo.markers
    markers.append(thespis.Marker("Curtain", thespis.seconds_to_ticks(9.0)))
    assert len(demo.markers) == 2  # a copy until assigned back
    demo.markers = markers
    characters = demo.characters
    creon = next(c for c in characters if c.name == "Creon")
    creon.gestures = creon.gestures + [thespis.Gesture("bow", "nod", "head")]
    demo.characters = characters
    path = tmp_path / "edited.thespis"
    thespis.save_scenario(path, demo)
    again = thespis.load_scenario(path)
    assert again == demo
    assert [m.name for m in again.markers] == ["Creon greets", "Antigone answers", "Curtain"]
    assert again.find_character("Creon").find_gesture("bow").mask == "head"


def test_unknown_fields_of_gestures_and_markers_survive(demo):
    document = json.loads(thespis.serialize_scenario(demo))
    creon = next(c for c in document["characters"] if c["name"] == "Creon")
    creon["gestures"][0]["hint"] = "big"
    document["markers"][1]["colour"] = "#ff8800"
    again = thespis.parse_scenario(json.dumps(document))
    assert again.find_character("Creon").gestures[0].extra == {"hint": "big"}
    assert again.markers[1].extra == {"colour": "#ff8800"}
    rewritten = json.loads(thespis.serialize_scenario(again))
    assert next(c for c in rewritten["characters"] if c["name"] == "Creon")["gestures"][0]["hint"] == "big"
    assert rewritten["markers"][1]["colour"] == "#ff8800"


@pytest.mark.parametrize(
    "target, field, value",
    [
        (lambda: thespis.Layer("body"), "mute", "yes"),
        (lambda: thespis.Layer("body"), "solo", [True]),
        (lambda: thespis.Layer("body"), "lock", "locked"),
        (lambda: thespis.Marker("cue"), "time", "soon"),
        (lambda: thespis.Marker("cue"), "time", 1.5),
        (lambda: thespis.Marker("cue"), "name", 3),
        (lambda: thespis.Gesture("greet"), "fade_in", "slow"),
        (lambda: thespis.Gesture("greet"), "clip", 7),
        (lambda: thespis.Gesture("greet"), "dependent_joint_filter", "on"),
        (lambda: thespis.Character("Ada"), "bake", 5),
        (lambda: thespis.Character("Ada"), "gestures", [thespis.Marker("cue")]),
        (lambda: thespis.Scenario("s"), "markers", [thespis.Gesture("greet")]),
    ],
)
def test_a_wrong_type_raises_type_error(target, field, value):
    with pytest.raises(TypeError):
        setattr(target(), field, value)


def test_format_2_reprs():
    layer = thespis.Layer("body")
    layer.mute = True
    assert repr(layer) == "<thespis.Layer 'body' 0 actions muted>"
    assert repr(thespis.Marker("cue", 5)) == "<thespis.Marker 'cue' at 5 ticks>"
    assert repr(thespis.Gesture("greet", "wave")) == "<thespis.Gesture 'greet' clip 'wave'>"
