"""thespis.speech: the demo's Creon speaks a tagged line from Python — the audio and its timing,
the visemes with their dominance curves, a gesture over its words, Insert as one undoable Edit —
the coarticulation dominance function against the paper's formula, and viseme sets as data."""

import math

import numpy as np
import pytest

import thespis
from thespis import speech

from conftest import SHARED_DATA, demo_scenario


def test_dominance_is_the_papers_equation_3():
    for alpha in (2.0, 5.0):
        for x in np.linspace(0, 1, 41):
            d = abs(x - 0.5) * 2
            assert speech.dominance(alpha, x) == pytest.approx(math.exp(-alpha * d) - d * math.exp(-alpha), abs=1e-12)
    assert speech.dominance(3.0, 0.5) == 1.0
    assert speech.dominance(3.0, 1.2) == 0.0


def test_creon_speaks_a_tagged_line_and_it_goes_into_the_scenario(tmp_path):
    wav = tmp_path / "line.wav"
    said = speech.speak('Pop <begin_gesture id="g1" anim="agree"/>the bubble<end_gesture id="g1"/>, Bob.',
                        voice="en-us", rate=160, wav=wav)
    assert said.spoken_text == "Pop the bubble, Bob."
    assert [w[0] for w in said.words] == ["Pop", "the", "bubble", "Bob"]
    assert said.rate == 22050 and said.samples.dtype == np.float32
    assert said.phonemes[-1][2] == pytest.approx(said.duration, abs=0.02)
    assert wav.stat().st_size > 44 + 2 * len(said.samples) - 4
    lips = [v for v in said.visemes if v["phoneme"] in ("P", "B")]
    assert len(lips) == 6 and all(v["name"] == "p_b_m" for v in lips)
    (gesture,) = said.gestures
    assert (gesture["start"], gesture["end"]) == (said.words[1][1], said.words[2][2])

    scenario = thespis.load_scenario(str(demo_scenario()))
    before = thespis.serialize_scenario(scenario)
    change = speech.insert(scenario, "Creon", said, at=1.5, audio="line.wav")
    change.apply(scenario)
    (line,) = [c for c in scenario.characters if c.name == "Creon"][0].speech
    assert line.audio == "line.wav" and line.text.startswith("Pop <begin_gesture")
    change.inverse().apply(scenario)
    assert thespis.serialize_scenario(scenario) == before


def test_bad_tags_name_their_line_and_column():
    with pytest.raises(thespis.FormatError, match="line 2, column 3"):
        speech.parse_tagged_text('Hello\n  <begin_gesture id="g1"/>there')
    text, gestures = speech.parse_tagged_text('Are you <begin_gesture id="g1" anim="nod"/>sure?<end_gesture id="g1"/>')
    assert text == "Are you sure?" and gestures[0]["anim"] == "nod" and text[gestures[0]["begin"]:gestures[0]["end"]] == "sure?"


def test_viseme_sets_are_data(tmp_path):
    sapi = speech.VisemeSet.builtin("sapi")
    assert sapi.visemes_of("EY") == [4, 6]
    assert speech.mpeg4_viseme("M") == 1
    sapi.visemes[1].alpha = 6.5
    sapi.save(tmp_path / "mine.json")
    assert speech.VisemeSet.load(tmp_path / "mine.json") == sapi
    broken = (tmp_path / "mine.json").read_text().replace('"alpha": 6.5', '"alpha": 0')
    with pytest.raises(thespis.FormatError, match=r"visemes\[1\]\.alpha"):
        speech.VisemeSet.parse(broken)


def test_voices_are_listed_and_unknown_ones_named():
    assert any(v["language"] == "en-us" for v in speech.voices())
    with pytest.raises(Exception, match="vulcan"):
        speech.speak("Hello", voice="vulcan")
