"""A character's own BML lexicon from Python (format 12): read on Character.bml_lexicon, set by
thespis.edit (one undo step each), kept by saving, and used by thespis.speech.insert_bml and
thespis.bml.Realizer.perform unless their lexicon= says otherwise."""

import pytest

import thespis

from conftest import demo_scenario

BEAT = '<bml id="b"><gesture id="g1" lexeme="BEAT"/></bml>'
GREET = '<bml id="b"><gesture id="g1" lexeme="GREET"/></bml>'


def runtime_of(scenario):
    return thespis.build_runtime(scenario, demo_scenario().parent)


def inserted(scenario, **options):
    """The name of the gesture action insert_bml puts on Creon's timeline for BEAT."""
    edit = thespis.speech.insert_bml(scenario, runtime_of(scenario), "Creon", thespis.speech.speak(BEAT), at=1.0,
                                     **options)
    after = thespis.parse_scenario(thespis.serialize_scenario(scenario))
    edit.apply(after)
    return next(layer for layer in after.characters[0].layers if layer.name == "Gestures").actions[-1].name


def performed_end(scenario, xml, **options):
    """When Creon's block ends, played live from 1 s: each gesticon entry has its own length."""
    service = thespis.AnimationService.from_runtime(runtime_of(scenario), thespis.ManualClock())
    return thespis.bml.Realizer(service).perform("Creon", xml, at=1.0, **options)["end"]


def test_a_row_set_by_an_edit_changes_what_beat_plays_and_undoes():
    scenario = thespis.load_scenario(demo_scenario())
    assert scenario.characters[0].bml_lexicon is None, "the demo keeps the defaults"
    assert thespis.edit.bml_lexicon_rows(scenario, 0)["BEAT"] == "agree"
    assert thespis.edit.bml_lexicon_rows(scenario, 1) == {"AGREE": "agree", "BEAT": "agree", "NOD": "agree"}
    assert inserted(scenario) == "g1 agree"
    agree, greet = performed_end(scenario, BEAT), performed_end(scenario, GREET)
    assert agree != greet

    edit = thespis.edit.set_bml_lexeme(scenario, 0, "beat", "greet")
    assert "bml lexicon" in repr(edit)
    edit.apply(scenario)
    assert scenario.characters[0].bml_lexicon["BEAT"] == "greet"
    assert inserted(scenario) == "g1 greet"
    assert performed_end(scenario, BEAT) == greet
    # An explicit lexicon= is laid over the character's.
    assert inserted(scenario, lexicon={"beat": "agree"}) == "g1 agree"
    assert performed_end(scenario, BEAT, lexicon={"BEAT": "agree"}) == agree
    # Saved and read back it stays; the edit's inverse takes it back.
    again = thespis.parse_scenario(thespis.serialize_scenario(scenario))
    assert again.characters[0].bml_lexicon == scenario.characters[0].bml_lexicon
    edit.inverse().apply(scenario)
    assert scenario.characters[0].bml_lexicon is None
    assert inserted(scenario) == "g1 agree"


def test_tables_are_set_whole_checked_and_reset():
    scenario = thespis.load_scenario(demo_scenario())
    thespis.edit.set_bml_lexicon(scenario, 0, {"shrug": "agree"}).apply(scenario)
    assert scenario.characters[0].bml_lexicon == {"SHRUG": "agree"}
    thespis.edit.rename_bml_lexeme(scenario, 0, "SHRUG", "beat").apply(scenario)
    assert scenario.characters[0].bml_lexicon == {"BEAT": "agree"}
    with pytest.raises(ValueError, match="juggle"):
        thespis.edit.set_bml_lexeme(scenario, 0, "BEAT", "juggle")
    thespis.edit.set_bml_lexicon(scenario, 0, None).apply(scenario)
    assert scenario.characters[0].bml_lexicon is None
    # The property reads and writes a character's own table (a copy of the character).
    creon = scenario.characters[0]
    creon.bml_lexicon = {"WAVE": "point"}
    assert creon.bml_lexicon == {"WAVE": "point"}
    assert thespis.bml.default_lexicon()["POINT"] == "point"
