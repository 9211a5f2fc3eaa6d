"""Conversation through thespis-cli chat (issue 34): typed lines answered by the demo's bot and
by the whole of Rosie, real recordings (pocketsphinx's cards) recognised against the grammar made
from a bot's patterns and answered, speech outside that grammar rejected into the bot's "not
understood" category, the state kept between runs, and Antigone speaking her answers on the demo.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import os
import subprocess
import wave
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
ROOT = Path(__file__).resolve().parents[2]
RESOURCES = ROOT / "resources"
ANTIGONE = RESOURCES / "dialogue" / "antigone"
CARDS_BOT = ROOT / "tests" / "data" / "dialogue" / "cards"
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", ROOT.parent / "shared" / "data"))
CARDS = DATA / "speech" / "pocketsphinx" / "cards"
ROSIE = DATA / "dialogue" / "rosie"

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)
for needed in (CARDS / "001.wav", ROSIE):
    if not needed.exists():
        pytest.fail(f"{needed} is missing (../shared/data)", pytrace=False)


def chat(*args, lines=None, status=0):
    done = subprocess.run([CLI, "chat", *map(str, args)], input="".join(l + "\n" for l in lines or []),
                          capture_output=True, text=True, timeout=300)
    assert done.returncode == status, done.stderr
    return done.stdout.splitlines(), done.stderr


def test_typed_lines_get_one_answer_line_each_and_the_state_lasts(tmp_path):
    state = tmp_path / "visitor.json"
    answers, _ = chat("--aiml", ANTIGONE, "--no-speech", "--state", state,
                      lines=["Hello!", "who is Creon?", "What will happen to you?", "yes", "My name is Ada."])
    assert answers == [
        "Greetings, stranger. Ask me what you will, before Creon's guards return.",  # gesture tags taken out
        "Creon is my uncle, and now king of Thebes. His word is law, he says.",
        "Creon will wall me up in a tomb of stone. Do you want to know more?",
        "Then know that his own house will pay for it, his son and his wife.",  # the topic of the answer before
        "Welcome to Thebes, Ada.",
    ]
    assert state.exists()
    again, _ = chat("--aiml", ANTIGONE, "--no-speech", "--state", state, lines=["what is my name"])
    assert again == ["You are Ada."]
    fresh, _ = chat("--aiml", ANTIGONE, "--no-speech", lines=["what is my name"])
    assert fresh == ["You have not told me yet."]


def test_a_line_nothing_matches_gets_an_empty_line():
    answers, _ = chat("--aiml", CARDS_BOT, lines=["hello", "ten of clubs"])
    assert answers == ["", "The ten of clubs: a fine card."]


def test_rosie_answers_and_says_what_she_lacks():
    answers, problems = chat("--aiml", ROSIE, "--no-speech", lines=["Hello", "My name is Ada", "What is my name?"])
    assert len(answers) == 3 and all(answers), answers
    assert "Ada" in answers[2], answers
    # Rosie's files name two sets she does not ship: said with file and line, the rest loads.
    assert "acronym" in problems and ".aiml:" in problems, problems


@pytest.mark.parametrize("recording, heard, answer", [
    ("001.wav", "ten of clubs", "The ten of clubs: a fine card."),
    ("003.wav", "seven of clubs", "The seven of clubs: a fine card."),
    ("004.wav", "five five", "A pair of fives."),
])
def test_real_recordings_are_heard_through_the_bots_own_grammar(recording, heard, answer):
    lines, _ = chat("--aiml", CARDS_BOT, "--wav", CARDS / recording, "--no-speech")
    assert len(lines) == 2, lines
    assert lines[0].startswith(f"heard: {heard} (confidence "), lines
    assert lines[1] == answer


def test_speech_the_grammar_does_not_cover_is_not_understood():
    # A card called to the demo's bot: nothing of hers sounds like it.
    lines, _ = chat("--aiml", ANTIGONE, "--wav", CARDS / "001.wav", "--no-speech")
    assert lines[0].startswith("heard: nothing understood"), lines
    assert lines[1] in ("Forgive me, I did not understand. Ask me again?", "The wind took your words. Say it once more?")


def test_antigone_speaks_her_answers_on_the_demo(tmp_path):
    out = tmp_path / "antigone.wav"
    answers, problems = chat(RESOURCES / "demo.thespis", "--character", "Antigone", "--aiml", ANTIGONE, "--out", out,
                             lines=["Why did you bury him?", "Thank you"])
    assert answers == ["Because the laws of the gods are older than any king's edict.", "The gods keep you, stranger."]
    assert "warning" not in problems, problems
    with wave.open(str(out)) as voice:
        seconds = voice.getnframes() / voice.getframerate()
        samples = voice.readframes(voice.getnframes())
    # Both answers one after the other, with a pause between: about five seconds of her voice.
    assert 4 < seconds < 12, seconds
    assert max(abs(int.from_bytes(samples[i:i + 2], "little", signed=True)) for i in range(0, len(samples), 2)) > 3000


def test_bad_input_is_said_with_its_place(tmp_path):
    bad = tmp_path / "bad.aiml"
    bad.write_text('<aiml>\n<category><pattern>HI</pattern><template>Hi there.</template></category>\n'
                   '<category><pattern>BYE<pattern><template>x</template></category>\n</aiml>\n')
    answers, problems = chat("--aiml", bad, lines=["hi"], status=0)
    assert f"{bad}:3" in problems, problems
    _, missing = chat("--aiml", tmp_path / "nothing.aiml", lines=["hi"], status=3)
    assert "nothing.aiml" in missing
    _, usage = chat("--aiml", ANTIGONE, "--character", "Antigone", lines=["hi"], status=2)
    assert "SCENARIO" in usage
