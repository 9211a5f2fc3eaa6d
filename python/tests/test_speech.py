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
    with pytest.raises(ValueError, match="runtime"):  # the gesture's length comes from the gesticon as built
        speech.insert(scenario, "Creon", said, at=1.5, audio="line.wav")
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    change = speech.insert(scenario, "Creon", said, at=1.5, audio="line.wav", runtime=runtime)
    change.apply(scenario)
    creon = [c for c in scenario.characters if c.name == "Creon"][0]
    line = creon.speech[-1]
    assert line.audio == "line.wav" and line.text.startswith("Pop <begin_gesture")
    # The nod fades in before "the" and is wholly there when the word starts.
    agree = next(g for g in creon.gestures if g.name == "agree")
    nod = next(layer for layer in creon.layers if layer.name == "Gestures").actions[-1]
    assert nod.name == "g1 agree"
    fade_in = agree.fade_in / thespis.TICKS_PER_SECOND
    assert nod.start_seconds == pytest.approx(1.5 + said.words[1][1] - fade_in, abs=1e-3)
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
    # Each SAPI viseme shows on the face as an MPEG-4 one: p_b_m (21) as MPEG-4's 1.
    assert (sapi.visemes[21].name, sapi.visemes[21].mpeg4) == ("p_b_m", 1)
    bob = speech.speak("Bob", visemes=sapi)
    assert {(v["viseme"], v["mpeg4"]) for v in bob.visemes if v["phoneme"] == "B"} == {(21, 1)}
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


def test_a_librivox_recording_is_aligned_and_inserted_with_its_file():
    base = SHARED_DATA / "speech" / "pocketsphinx" / "librivox" / "sense_and_sensibility_01_austen_64kb-0880"
    transcript = base.with_suffix(".txt").read_text().split()
    aligned = speech.align(base.with_suffix(".wav"), " ".join(transcript))
    assert [w[0].lower() for w in aligned.words] == [w.lower() for w in transcript]
    starts = [w[1] for w in aligned.words]
    assert starts == sorted(starts) and aligned.phonemes[-1][2] > aligned.words[-1][1]
    scenario = thespis.load_scenario(str(demo_scenario()))
    speech.insert(scenario, "Creon", aligned, at=1.0).apply(scenario)
    line = scenario.find_character("Creon").speech[-1]
    assert line.audio == str(base.with_suffix(".wav")) and line.start == thespis.seconds_to_ticks(1.0)


def test_a_preview_plays_the_lips_live_on_the_stage():
    scenario = thespis.load_scenario(str(demo_scenario()))
    service = thespis.AnimationService.from_runtime(thespis.build_runtime(scenario, demo_scenario().parent),
                                                    thespis.ManualClock())
    said = speech.speak("Bob.", voice="en-us")
    performed = speech.perform(service.stage, "Creon", said, at=2.0)
    assert performed["action"] == "speech line" and performed["visemes"] >= 3
    b = next(p for p in said.phonemes if p[0] == "B")
    closed_lips = 68  # a face frame is FAP 1 … 68, then the weights of the 14 visemes (p_b_m first)
    assert service.evaluate_face("Creon", 2.0 + (b[1] + b[2]) / 2)[closed_lips] > 0.6
    assert service.evaluate_face("Creon", 1.9)[closed_lips] == 0.0
