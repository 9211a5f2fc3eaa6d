"""Conversation from Python (thespis.dialogue, issue 34): the demo's bot and the whole of Rosie
answer with the category that did, a conversation saved and restored goes on, a real recording is
heard through a bot's own grammar, and Antigone converses on the demo's stage — her answer spoken
while her eyes are on the visitor — then goes back to the script."""

import numpy as np
import pytest

import thespis

from conftest import REPO, RESOURCES, SHARED_DATA, demo_scenario

ANTIGONE = RESOURCES / "dialogue" / "antigone"
CARDS_BOT = REPO / "tests" / "data" / "dialogue" / "cards"
CARDS = SHARED_DATA / "speech" / "pocketsphinx" / "cards"
ROSIE = SHARED_DATA / "dialogue" / "rosie"


def test_the_bot_answers_with_its_category_and_the_state_goes_on():
    bot = thespis.dialogue.load([ANTIGONE])
    assert len(bot) > 30 and bot.problems == []
    talk = thespis.dialogue.Conversation(bot)
    answer = talk.respond("Why did you bury him?")
    assert answer["words"] == "Because the laws of the gods are older than any king's edict."
    assert '<begin_gesture id="g1" anim="agree"/>' in answer["text"], "the nod's tags stay for the speech"
    assert answer["matched"][-1]["pattern"] == "WHY DID YOU BURY HIM"
    assert answer["matched"][-1]["file"].endswith("antigone.aiml") and answer["matched"][-1]["line"] > 0
    assert talk.respond("My name is Ada")["words"] == "Welcome to Thebes, Ada."
    later = thespis.dialogue.Conversation.restore(bot, talk.save())
    assert later.respond("What is my name?")["words"] == "You are Ada."
    with pytest.raises(thespis.FormatError):
        thespis.dialogue.Conversation.restore(bot, '{"format": "thespis-conversation", "version": 1, "predicates": 3}')
    with pytest.raises(FileNotFoundError):
        thespis.dialogue.load([ANTIGONE / "missing.aiml"])


def test_rosie_loads_whole_and_answers():
    if not ROSIE.exists():
        pytest.fail(f"{ROSIE} is missing (../shared/data)")
    rosie = thespis.dialogue.load([ROSIE])
    assert len(rosie) > 12000
    assert any("acronym" in p for p in rosie.problems), rosie.problems
    answer = thespis.dialogue.Conversation(rosie).respond("Hello")
    assert answer["words"] and answer["matched"]


def test_a_real_recording_is_heard_through_the_bots_grammar():
    bot = thespis.dialogue.load([CARDS_BOT])
    grammar = bot.grammar()
    assert grammar["jsgf"].startswith("#JSGF") and "clubs" in grammar["words"]
    assert 0 < grammar["graph_states"] and len(grammar["words"]) <= grammar["graph_word_arcs"]
    heard = thespis.dialogue.Recogniser(bot).recognise_file(CARDS / "003.wav")
    assert heard["understood"] and heard["text"] == "seven of clubs", heard
    assert [w for w, _, _ in heard["words"]] == ["seven", "of", "clubs"]


def test_antigone_converses_on_the_stage_then_goes_back_to_the_script():
    scenario = thespis.load_scenario(demo_scenario())
    runtime = thespis.build_runtime(scenario, demo_scenario().parent)
    clock = thespis.ManualClock()
    service = thespis.AnimationService.from_runtime(runtime, clock)
    sound = thespis.SoundService(demo_scenario().parent, clock)
    interaction = thespis.dialogue.InteractionService(service, sound)
    clock.set_time(1.0)
    interaction.converse("Antigone", thespis.dialogue.load([ANTIGONE]), visitor="Creon")
    assert interaction.conversing("Antigone")
    said = interaction.hear("Antigone", "who is Creon?")
    assert said["answer"]["words"].startswith("Creon is my uncle")
    assert said["start"] == pytest.approx(1.0) and said["end"] > 3.0
    assert sound.is_playing("Antigone: answer 1")
    for t in np.arange(1.0, said["end"], 1 / 30):
        clock.set_time(t)
        service.evaluate_body("Antigone", t)
    assert service.gaze_state("Antigone") is not None, "her eyes on the visitor"
    assert [e["heard"] for e in interaction.transcript("Antigone")] == ["who is Creon?"]
    assert interaction.hand_back("Antigone") and not interaction.conversing("Antigone")
    with pytest.raises(ValueError, match="not conversing"):
        interaction.hear("Antigone", "hello")
