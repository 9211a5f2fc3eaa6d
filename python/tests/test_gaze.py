"""Gaze from Python (the animation service's gaze_body / stopGaze): on the demo, Creon turns his
eyes and head to Antigone over his authored motion, lets go, and bad targets are named."""

import numpy as np
import pytest

import thespis

from conftest import demo_scenario


def demo_service():
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    return thespis.AnimationService.from_runtime(runtime, thespis.ManualClock()), runtime


def play(service, start, end, step=1 / 60):
    for t in np.arange(start, end, step):
        service.clock.set_time(t)
        service.evaluate_body("Creon", t)


def test_creon_looks_at_antigone_and_lets_go():
    service, _ = demo_service()
    without, _ = demo_service()  # the same stage, no gaze
    service.clock.set_time(1.0)
    service.gaze_body("Creon", "Antigone", influence="HEAD", saccades=False)
    play(service, 1.0, 3.0)
    state = service.gaze_state("Creon")
    neck, eyes = state["neck"], state["eyes"]
    assert not state["shifting"]
    # Antigone stands to Creon's side: head and eyes turn the same way, the head by at least half.
    assert abs(neck[0]) > 5 and np.sign(neck[0]) == np.sign(eyes[0])
    assert abs(neck[0]) >= 0.45 * abs(neck[0] + eyes[0])
    body = service.evaluate_body("Creon", 3.0)
    assert np.abs(body - without.evaluate_body("Creon", 3.0)).max() > 0.02, "the neck turned"
    face = service.evaluate_face("Creon", 3.0)
    assert abs(face[22]) > 1000, "the eyes turned (FAP 23, in 1e-5 rad)"

    assert service.stopGaze("Creon")
    play(service, 3.0, 6.0)
    assert service.gaze_state("Creon") is None
    np.testing.assert_allclose(service.evaluate_body("Creon", 6.0), without.evaluate_body("Creon", 6.0), atol=1e-6)
    assert not service.stop_gaze("Creon")


def test_targets_are_points_joints_or_the_camera():
    service, _ = demo_service()
    service.gaze_body("Creon", (0.0, 1.6, 3.0))
    service.gaze_body("Creon", "Antigone:l_radiocarpal", influence="EYES", offset_angle=5, offset_direction="UPLEFT")
    service.gaze_body("Creon", "camera")
    with pytest.raises(KeyError, match="Nobody"):
        service.gaze_body("Creon", "Nobody")
    with pytest.raises(KeyError, match="tail"):
        service.gaze_body("Creon", "Antigone:tail")
    with pytest.raises(ValueError, match="ELBOW"):
        service.gaze_body("Creon", "camera", influence="ELBOW")
    with pytest.raises(ValueError, match="three"):
        service.gaze_body("Creon", (1.0, 2.0))


BLOCK = """<bml xmlns="http://www.bml-initiative.org/bml/bml-1.0" id="bml1">
  <speech id="s1"><text>Hear me, <sync id="t1"/>Antigone.</text></speech>
  <gesture id="g1" lexeme="BEAT" stroke="s1:t1"/>
  <gaze id="z1" target="Antigone" influence="HEAD" start="s1:start"/>
</bml>"""


def test_bml_plays_on_the_words_and_calls_back_its_sync_points():
    service, _ = demo_service()
    block = thespis.bml.parse(BLOCK)
    assert [b["kind"] for b in block["behaviors"]] == ["speech", "gesture", "gaze"]
    assert block["behaviors"][1]["sync"] == {"stroke": "s1:t1"}
    heard = []
    realizer = thespis.bml.Realizer(service)
    performed = realizer.perform("Creon", BLOCK, voice="en-gb", at=0.5,
                                 on_event=lambda name, t: heard.append((name, round(service.now() - t, 6))))
    times = dict((name, t) for t, name in performed["events"])
    assert times["g1:stroke"] == pytest.approx(times["s1:t1"])
    assert times["bml1:start"] == 0.5 and times["bml1:end"] > times["s1:t1"] > 0.5
    assert [n for n, _ in heard] == [name for _, name in performed["events"]]
    assert all(lag == 0 for _, lag in heard), "each called back when the clock reached it"
    assert realizer.events("Creon", "bml1") == performed["events"]
    # Without on_event perform returns at once; poll() gives each event once as the clock reaches it.
    again = realizer.perform("Creon", BLOCK.replace('id="bml1"', 'id="bml2"'), voice="en-gb")
    first = realizer.poll()
    assert ("bml2:start", "Creon") in [e[1:] for e in first] and all(t <= service.now() for t, _, _ in first)
    stroke = dict((name, t) for t, name in again["events"])["g1:stroke"]
    service.clock.wait_until(stroke)
    polled = realizer.poll()
    assert polled and polled[-1][0] <= stroke and "g1:stroke" in [name for _, name, _ in polled]
    assert realizer.poll() == []
    assert service.gaze_state("Creon") is not None
    with pytest.raises(thespis.FormatError, match="line 1, column"):
        thespis.bml.parse("<bml id='b'><gesture lexeme='BEAT'/></bml>")


def test_bml_goes_on_the_timeline_and_a_gaze_layer_plays_from_the_scenario():
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    said = thespis.speech.speak('<bml id="b1"><speech id="s1"><text>Hear me, Antigone.</text></speech>'
                                '<gaze id="z1" target="Antigone" influence="HEAD" start="s1:start" end="s1:end"/>'
                                '<head id="h1" lexeme="NOD" start="s1:end"/></bml>', voice="en-gb")
    assert said.bml_block == "b1" and [w[0] for w in said.bml_speeches["s1"]] == ["Hear", "me", "Antigone"]
    edit = thespis.speech.insert_bml(scenario, runtime, "Creon", said, at=1.0)
    edit.apply(scenario)
    creon = next(c for c in scenario.characters if c.name == "Creon")
    gaze = next(layer for layer in creon.layers if layer.name == "Gaze")
    assert gaze.kind == thespis.LayerKind.gaze
    look = gaze.actions[0]
    assert look.gaze == thespis.GazeSpec("Antigone", "HEAD") and look.start_seconds == 1.0
    with pytest.raises(ValueError, match="tagged text"):
        thespis.speech.insert_bml(scenario, runtime, "Creon", thespis.speech.speak("Hello.", voice="en-gb"))

    # Another gaze added by hand goes on the same layer; played from the scenario he turns to her.
    thespis.edit.add_gaze(scenario, 0, thespis.GazeSpec("camera"), start=4 * thespis.TICKS_PER_SECOND, seconds=1.5).apply(scenario)
    assert [a.gaze.target for a in gaze_layer(scenario).actions] == ["Antigone", "camera"]
    service = thespis.AnimationService.from_runtime(thespis.build_runtime(scenario, demo_scenario().parent),
                                                    thespis.ManualClock())
    play(service, 0.0, 2.0)
    state = service.gaze_state("Creon")
    assert state is not None and abs(state["neck"][0]) > 5


def gaze_layer(scenario):
    return next(layer for layer in scenario.characters[0].layers if layer.name == "Gaze")


def test_a_bml_pointing_keeps_its_target_on_the_timeline():
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    said = thespis.speech.speak('<bml id="b2"><pointing id="p1" target="Antigone" mode="LEFT_HAND"/></bml>')
    thespis.speech.insert_bml(scenario, runtime, "Creon", said, at=2.0).apply(scenario)
    creon = next(c for c in scenario.characters if c.name == "Creon")
    point = next(layer for layer in creon.layers if layer.name == "Gestures").actions[-1]
    assert point.clip == "point" and point.pointing == thespis.PointingSpec("Antigone", "LEFT_HAND")
    # Saved and read back it points the same.
    again = next(c for c in thespis.parse_scenario(thespis.serialize_scenario(scenario)).characters if c.name == "Creon")
    assert next(layer for layer in again.layers if layer.name == "Gestures").actions[-1].pointing == point.pointing
