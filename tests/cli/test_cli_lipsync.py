"""thespis-cli lipsync on real read speech (LibriVox, ../shared/data/speech/pocketsphinx/librivox):
the table of phonemes a recording and its transcript give, the words recognised without one, a
word pocketsphinx lacks (in espeak-ng's speech), and the errors a user meets.

THESPIS_CLI names the executable and THESPIS_SHARED_DATA the real data (CTest sets both).
"""

import csv
import os
import re
import subprocess
import wave
from pathlib import Path

import pytest

CLI = os.environ.get("THESPIS_CLI")
DATA = Path(os.environ.get("THESPIS_SHARED_DATA", Path(__file__).resolve().parents[3] / "shared" / "data"))
LIBRIVOX = DATA / "speech" / "pocketsphinx" / "librivox"
LINE = LIBRIVOX / "sense_and_sensibility_01_austen_64kb-0870.wav"
ARPABET = set("AA AE AH AO AW AY B CH D DH EH ER EY F G HH IH IY JH K L M N NG OW OY P R S SH T TH UH UW V W Y Z ZH".split())

if not CLI:
    pytest.fail("THESPIS_CLI (the thespis-cli executable) is not set", pytrace=False)
if not LINE.exists():
    pytest.fail(f"{LINE} is missing (../shared/data)", pytrace=False)

USAGE, INVALID, FAILURE = 2, 3, 4


def run(*args):
    return subprocess.run([CLI, "lipsync", *map(str, args)], capture_output=True, text=True, timeout=300)


def read_table(path):
    with path.open(newline="") as f:
        return list(csv.DictReader(f, delimiter="\t"))


def words_of(rows):
    """The words of the rows in order, each once (its phonemes are consecutive rows)."""
    words, previous = [], None
    for row in rows:
        if row["word"] and row["word"] != previous:
            words.append(row["word"])
        previous = row["word"] or None
    return words


def test_a_recording_and_its_transcript_give_one_row_per_phoneme(tmp_path):
    out = tmp_path / "timing.tsv"
    result = run(LINE, "--text-file", LINE.with_suffix(".txt"), "--out", out)
    assert result.returncode == 0, result.stderr
    assert f"Wrote {out}." in result.stdout
    assert "warning" not in result.stderr

    rows = read_table(out)
    assert list(rows[0].keys()) == ["start", "end", "word", "phoneme", "viseme"]
    assert words_of(rows) == LINE.with_suffix(".txt").read_text().split()
    with wave.open(str(LINE)) as w:
        duration = w.getnframes() / w.getframerate()
    # The rows tile the recording: from its start to its end, each where the one before ends.
    assert float(rows[0]["start"]) == 0
    assert abs(float(rows[-1]["end"]) - duration) < 0.001
    for before, row in zip(rows, rows[1:]):
        assert row["start"] == before["end"]
    for row in rows:
        assert float(row["start"]) < float(row["end"])
        if row["word"]:
            assert row["phoneme"] in ARPABET
            assert 1 <= int(row["viseme"]) <= 14
        else:
            assert (row["phoneme"], row["viseme"]) == ("SIL", "0")
    # MPEG-4's viseme 1 is p, b, m: "mister" starts with it.
    first = next(row for row in rows if row["word"] == "mister")
    assert (first["phoneme"], first["viseme"]) == ("M", "1")


def test_without_a_transcript_the_words_are_recognised(tmp_path):
    out = tmp_path / "timing.tsv"
    line = LIBRIVOX / "sense_and_sensibility_01_austen_64kb-0880.wav"
    result = run(line, "--out", out)
    assert result.returncode == 0, result.stderr
    heard = re.search(r"^Recognised: (.*)$", result.stdout, re.MULTILINE).group(1).split()
    truth = line.with_suffix(".txt").read_text().split()
    assert sum(word in truth for word in heard) >= len(truth) // 2, heard
    assert words_of(read_table(out)) == heard


def test_a_word_missing_from_the_dictionary_is_pronounced_by_espeak_with_a_warning(tmp_path):
    speech = tmp_path / "thespis.wav"
    text = "Thespis stands on the stage."
    subprocess.run(["espeak-ng", "-v", "en-us", "-w", str(speech), text], check=True, timeout=60)
    out = tmp_path / "timing.tsv"
    result = run(speech, "--text", text, "--out", out)
    assert result.returncode == 0, result.stderr
    assert result.stderr.count("warning:") == 1
    assert '"Thespis" is not in pocketsphinx\'s dictionary' in result.stderr
    rows = read_table(out)
    assert words_of(rows) == ["Thespis", "stands", "on", "the", "stage"]
    assert [row["phoneme"] for row in rows if row["word"] == "Thespis"][0] == "TH"


def test_mistakes_are_refused_naming_what_is_wrong(tmp_path):
    out = tmp_path / "timing.tsv"
    missing = run(tmp_path / "none.wav", "--text", "hello", "--out", out)
    assert missing.returncode == INVALID
    assert "none.wav" in missing.stderr

    both = run(LINE, "--text", "hello", "--text-file", LINE.with_suffix(".txt"), "--out", out)
    assert both.returncode == USAGE
    assert "not both" in both.stderr

    empty = run(LINE, "--text", "  ", "--out", out)
    assert empty.returncode == USAGE
    assert "--text has no words" in empty.stderr

    no_transcript_file = run(LINE, "--text-file", tmp_path / "none.txt", "--out", out)
    assert no_transcript_file.returncode == INVALID
    assert "none.txt" in no_transcript_file.stderr

    # Far more words than the recording has time for.
    too_long = run(LINE, "--text", " ".join([LINE.with_suffix(".txt").read_text()] * 6), "--out", out)
    assert too_long.returncode == INVALID
    assert f"{LINE}: the transcript could not be aligned" in too_long.stderr

    unwritable = run(LINE, "--text-file", LINE.with_suffix(".txt"), "--out", tmp_path / "no" / "such" / "timing.tsv")
    assert unwritable.returncode == FAILURE
    assert "timing.tsv" in unwritable.stderr
    assert not out.exists()

    nowhere = run(LINE, "--text", "hello")
    assert nowhere.returncode == USAGE and "--out, --scenario-out or both" in nowhere.stderr
    alone = run(LINE, "--text", "hello", "--scenario-out", tmp_path / "s.thespis")
    assert alone.returncode == USAGE and "--scenario and --character" in alone.stderr


def test_a_recording_goes_into_the_demo_as_the_studios_lip_sync_does(tmp_path):
    demo = Path(__file__).resolve().parents[2] / "resources" / "demo.thespis"
    out = tmp_path / "scenes" / "demo_lipsync.thespis"
    out.parent.mkdir()
    result = run(LINE, "--text-file", LINE.with_suffix(".txt"), "--scenario", demo, "--character", "Antigone",
                 "--at", "2.5", "--scenario-out", out)
    assert result.returncode == 0, result.stderr
    assert "Inserted into" in result.stdout and "for Antigone from 2.5 s" in result.stdout
    import json
    scenario = json.loads(out.read_text())
    antigone = next(c for c in scenario["characters"] if c["name"] == "Antigone")
    line = antigone["speech"][-1]
    # The recording stays where it is, named from the new scenario's folder.
    assert (out.parent / line["audio"]).resolve() == LINE.resolve()
    assert line["start"] == int(round(2.5 * 705_600_000))
    assert [w["text"].lower() for w in line["words"]] == LINE.with_suffix(".txt").read_text().lower().split()
    speech = next(layer for layer in antigone["layers"] if layer["name"] == "Speech")
    lips = [a for a in speech["actions"] if a["clip"] == "viseme p_b_m"]
    assert len(speech["actions"]) > 50 and lips
    # Every clip the demo names still resolves from the new folder: the scenario plays.
    check = subprocess.run([CLI, "validate", str(out)], capture_output=True, text=True, timeout=120)
    assert check.returncode == 0, check.stderr
