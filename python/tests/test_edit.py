"""thespis.edit: the studio's undoable scenario edits on the demo — each function returns an Edit,
apply() changes the Scenario in place, inverse() takes it back, refused edits raise ValueError
with the core's message and leave the scenario as it was."""

import pytest

import thespis
from thespis import edit
from conftest import RESOURCES, demo_scenario

SECOND = thespis.TICKS_PER_SECOND


@pytest.fixture
def demo():
    return thespis.load_scenario(demo_scenario())


def with_second_body_layer(scenario):
    """Creon (character 0) gets an empty body layer 'gestures' right after 'body': layers are
    body (0), gestures (1), face (2)."""
    characters = scenario.characters
    layers = characters[0].layers
    assert [layer.kind for layer in layers] == [thespis.LayerKind.body, thespis.LayerKind.face]
    layers.insert(1, thespis.Layer("gestures", thespis.LayerKind.body))
    characters[0].layers = layers
    scenario.characters = characters
    return scenario


def test_paths_are_values_and_load_from_tuples():
    assert edit.ActionPath(0, 1, 2) == edit.ActionPath((0, 1, 2))
    assert edit.ActionPath(0, 1, 2) != edit.ActionPath(0, 1, 3)
    assert edit.ActionPath(0, 1, 2).layer_path == edit.LayerPath(0, 1)
    assert edit.CharacterItemPath(1, 0).index == 0
    assert len({edit.LayerPath(0, 1), edit.LayerPath(0, 1), edit.LayerPath(1, 0)}) == 2
    assert repr(edit.ActionPath(0, 1, 2)) == "ActionPath(0, 1, 2)"
    with pytest.raises(TypeError):
        edit.ActionPath((0, 1))


def test_move_in_time_and_to_another_body_layer_then_back(demo):
    scenario = with_second_body_layer(demo)
    original = thespis.load_scenario(demo_scenario())
    original = with_second_body_layer(original)
    wave = scenario.characters[0].layers[0].actions[1]
    assert wave.name == "creon_wave"

    move = edit.move_actions(scenario, [edit.ActionPath(0, 0, 1)], SECOND, layer_delta=1)
    assert edit.moved_action_paths(scenario, [(0, 0, 1)], 1) == [edit.ActionPath(0, 1, 0)]
    assert len(move) >= 2 and not move.changes_nothing()
    assert scenario == original  # making the edit changes nothing

    move.apply(scenario)
    body, gestures, face = scenario.characters[0].layers
    assert [a.name for a in body.actions] == ["creon_idle", "creon_nod", "creon_small_wave"]
    assert [a.name for a in gestures.actions] == ["creon_wave"]
    assert gestures.actions[0].start == wave.start + SECOND
    assert gestures.actions[0].clip == wave.clip and gestures.actions[0].mask == wave.mask
    assert face == original.characters[0].layers[2]
    assert scenario != original

    move.inverse().apply(scenario)
    assert scenario == original


def test_move_in_time_only(demo):
    original = thespis.load_scenario(demo_scenario())
    move = edit.move_actions(demo, [(1, 0, 2)], -SECOND // 2)
    move.apply(demo)
    assert demo.characters[1].layers[0].actions[2].start == original.characters[1].layers[0].actions[2].start - SECOND // 2
    move.inverse().apply(demo)
    assert demo == original


def test_refused_edits_raise_and_change_nothing(demo):
    scenario = with_second_body_layer(demo)
    before = thespis.serialize_scenario(scenario)

    with pytest.raises(ValueError, match='already a mask named "leftArm"') as refused:
        edit.rename_mask(scenario, 0, "leftArm")
    assert refused.value.code == thespis.ErrorCode.invalid_argument

    with pytest.raises(ValueError, match="face"):  # a body action cannot go to the face layer
        edit.move_actions(scenario, [(0, 0, 1)], 0, layer_delta=2)

    edit.set_layer_flag(scenario, (0, 1), edit.LayerFlag.lock, True).apply(scenario)
    assert scenario.characters[0].layers[1].lock
    locked = thespis.serialize_scenario(scenario)
    with pytest.raises(ValueError, match='Layer "gestures" is locked'):
        edit.move_actions(scenario, [(0, 0, 1)], SECOND, layer_delta=1)
    assert thespis.serialize_scenario(scenario) == locked

    edit.set_layer_flag(scenario, (0, 1), edit.LayerFlag.lock, False).apply(scenario)
    assert thespis.serialize_scenario(scenario) == before


def test_an_edit_made_for_another_state_is_refused_by_apply(demo):
    original = thespis.load_scenario(demo_scenario())
    move = edit.move_actions(demo, [(0, 0, 1), (0, 0, 2)], SECOND)
    move.apply(demo)
    moved = thespis.serialize_scenario(demo)
    with pytest.raises(ValueError, match="does not fit the document"):
        move.apply(demo)  # its `before` values are gone now
    assert thespis.serialize_scenario(demo) == moved  # nothing half-applied
    move.inverse().apply(demo)
    assert demo == original


def test_add_and_remove_marker_round_trip(demo):
    original = thespis.load_scenario(demo_scenario())
    names = [m.name for m in demo.markers]
    add = edit.add_marker(demo, thespis.Marker("Creon turns", 3 * SECOND))
    assert "+marker" in repr(add)
    add.apply(demo)
    # Kept ordered by time: between the 1.5 s and 6 s markers.
    assert [m.name for m in demo.markers] == [names[0], "Creon turns", names[1]]
    assert demo.markers[1].time == 3 * SECOND

    edit.move_marker(demo, 1, 4 * SECOND).apply(demo)
    assert demo.markers[1].time == 4 * SECOND

    remove = edit.remove_marker(demo, 1)
    remove.apply(demo)
    assert demo == original
    remove.inverse().apply(demo)
    assert demo.markers[1] == thespis.Marker("Creon turns", 4 * SECOND)

    with pytest.raises(ValueError, match="no marker 7"):
        edit.remove_marker(demo, 7)


def test_set_character_bake_round_trip(demo):
    original = thespis.load_scenario(demo_scenario())
    assert edit.set_character_bake(demo, 0, "").changes_nothing()
    bake = edit.set_character_bake(demo, 0, "bakes/creon.prt")
    bake.apply(demo)
    assert demo.characters[0].bake == "bakes/creon.prt"
    assert demo.characters[1].bake == ""
    bake.inverse().apply(demo)
    assert demo == original


def test_masks(demo):
    original = thespis.load_scenario(demo_scenario())
    steps = []

    def do(e):
        e.apply(demo)
        steps.append(e)

    do(edit.add_mask(demo, "spine", thespis.JointMask()))
    assert demo.masks[-1].name == "spine"
    do(edit.set_mask_weights(demo, 3, ["vl5", "skullbase"], 0.5))
    assert demo.masks[3].mask.weight("vl5") == pytest.approx(0.5)
    assert demo.masks[3].mask.weight("skullbase") == pytest.approx(0.5)
    do(edit.rename_mask(demo, 0, "neck"))  # renames the actions and gestures that use it
    assert demo.characters[0].layers[0].actions[2].mask == "neck"
    with pytest.raises(ValueError, match='Mask "neck" is still used by action "creon_nod"'):
        edit.remove_mask(demo, 0)
    do(edit.remove_mask(demo, 3))
    assert [m.name for m in demo.masks] == ["neck", "leftArm", "rightArm"]

    for e in reversed(steps):
        e.inverse().apply(demo)
    assert demo == original


def test_gestures_actions_and_runtime_edits(demo):
    original = thespis.load_scenario(demo_scenario())
    steps = []

    def do(e):
        e.apply(demo)
        steps.append(e)

    do(edit.add_gesture(demo, 1, thespis.Gesture("greet", "wave", "rightArm")))
    assert demo.characters[1].find_gesture("greet").clip == "wave"
    with pytest.raises(ValueError, match="already has a gesture"):
        edit.add_gesture(demo, 1, thespis.Gesture("greet", "wave"))
    do(edit.replace_gesture(demo, (1, 1), thespis.Gesture("greet", "nod", "head")))
    assert demo.characters[1].gestures[1].clip == "nod"
    do(edit.remove_gesture(demo, edit.CharacterItemPath(1, 0)))
    assert [g.name for g in demo.characters[1].gestures] == ["greet"]

    action = edit.action_from_clip(demo, (0, 0), "wave", 8 * SECOND)
    assert action.name == "wave" and action.start == 8 * SECOND
    do(edit.insert_actions(demo, (0, 0), [action]))
    assert demo.characters[0].layers[0].actions[-1].name == "wave"

    renamed = demo.characters[0].layers[0].actions[1]
    renamed.name = "creon_greets"
    do(edit.replace_action(demo, (0, 0, 1), renamed))
    assert demo.characters[0].layers[0].actions[1].name == "creon_greets"

    runtime = thespis.build_runtime(demo, RESOURCES)
    span = edit.action_span(demo, runtime, (0, 0, 1))
    assert span is not None and span.start == demo.characters[0].layers[0].actions[1].start
    assert span.end > span.start
    assert edit.action_span(demo, runtime, (0, 0, 99)) is None
    do(edit.split_action(demo, (0, 0, 1), span, (span.start + span.end) // 2))
    assert len(demo.characters[0].layers[0].actions) == 6
    with pytest.raises(ValueError, match="inside the action"):
        edit.split_action(demo, (0, 0, 1), span, span.end + SECOND)

    count = len(demo.characters[0].layers[0].actions)
    do(edit.remove_actions(demo, [(0, 0, count - 1)]))
    assert len(demo.characters[0].layers[0].actions) == count - 1

    for e in reversed(steps):
        e.inverse().apply(demo)
    assert demo == original


def test_remove_with_ripple_closes_the_gap(demo):
    original = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(demo, RESOURCES)
    span = edit.action_span(demo, runtime, (1, 0, 1))
    last = demo.characters[1].layers[0].actions[2].start
    ripple = edit.remove_actions(demo, [(1, 0, 1)], ripple_with=runtime)
    ripple.apply(demo)
    actions = demo.characters[1].layers[0].actions
    assert [a.name for a in actions] == ["antigone_idle", "antigone_wave"]
    assert actions[1].start == last - (span.end - span.start)
    ripple.inverse().apply(demo)
    assert demo == original


def test_segment_tags_and_layer_flags(demo):
    original = thespis.load_scenario(demo_scenario())
    tag = thespis.scene.SegmentTag("head")
    tags = edit.set_segment_tags(demo, 0, [tag])
    tags.apply(demo)
    assert [t.segment for t in demo.characters[0].segment_tags] == ["head"]
    with pytest.raises(ValueError, match="distinct"):
        edit.set_segment_tags(demo, 0, [tag, tag])
    mute = edit.set_layer_flag(demo, edit.LayerPath(0, 1), edit.LayerFlag.mute, True)
    mute.apply(demo)
    assert demo.characters[0].layers[1].mute
    both = edit.Edit()
    assert len(both) == 0 and both.changes_nothing()
    both.append(tags)
    both.append(mute)
    assert len(both) == 2
    both.inverse().apply(demo)
    assert demo == original
