"""Every GRBL 1.1 alarm and error explained in English, Czech and Slovak, each shown once.

The codes are GRBL's own (its ``doc/csv`` tables in tests/third_party/grbl): a
code missing here would reach the operator as a bare number.
"""

from __future__ import annotations

import csv
from collections.abc import Iterator
from pathlib import Path

import pytest

from app import i18n
from app.machines.gcode.grbl_codes import ALARMS, ERRORS, Explainer, Remedy, explain
from app.machines.gcode.meanings import alarm_meaning
from protocol.gcode.codec import ALARM_MESSAGES

GRBL_DOC = Path(__file__).resolve().parents[1] / "third_party" / "grbl" / "doc" / "csv"


def grbl_codes(name: str) -> dict[int, str]:
    """GRBL's table: code → its description (English)."""
    with (GRBL_DOC / f"{name}_codes_en_US.csv").open(encoding="utf-8") as table:
        rows = list(csv.reader(table))[1:]
    return {int(row[0]): row[2].strip() for row in rows}


@pytest.fixture
def english_afterwards(qapp: object) -> Iterator[None]:
    yield
    i18n.remove()


def test_every_code_of_grbl_s_documentation_is_here() -> None:
    assert sorted(ALARMS) == sorted(grbl_codes("alarm"))
    assert sorted(ERRORS) == sorted(grbl_codes("error"))
    # The meanings are GRBL's own words (the probe alarms shortened to what a plotter needs).
    for code, text in grbl_codes("error").items():
        assert explain("error", code).meaning == text


@pytest.mark.parametrize("language", ["cs", "sk"])
def test_every_code_has_its_text_in_three_languages(
    language: str, english_afterwards: None, tmp_path: Path
) -> None:
    english = {
        (kind, code): explain(kind, code)
        for kind, table in (("ALARM", ALARMS), ("error", ERRORS))
        for code in table
    }
    assert all(e.meaning and e.action for e in english.values())
    assert i18n.install(language, tmp_path / "qm") == language
    for key, source in english.items():
        spoken = explain(*key)
        assert spoken.meaning and spoken.meaning != source.meaning, (language, key)
        assert spoken.action and spoken.action != source.action, (language, key)
    assert explain("error", 99).meaning != "A code GRBL 1.1 does not document."


@pytest.mark.parametrize("language", ["cs", "sk"])
def test_the_codecs_alarm_words_cover_grbls_table_in_three_languages(
    language: str, english_afterwards: None, tmp_path: Path
) -> None:
    """The status bar's "Machine alarm n" speaks the codec's words: GRBL 1.1h has ten."""
    assert sorted(ALARM_MESSAGES) == sorted(grbl_codes("alarm"))
    english = {code: alarm_meaning(code) for code in ALARM_MESSAGES}
    assert i18n.install(language, tmp_path / "qm") == language
    for code, source in english.items():
        assert alarm_meaning(code) != source, (language, code)


def test_a_lost_position_is_offered_homing_only() -> None:
    for code in (1, 3, 6, 7, 8, 9, 10):
        assert ALARMS[code].remedies == (Remedy.HOME,), code
    assert Remedy.UNLOCK in ALARMS[2].remedies  # a soft limit keeps the position


def test_nothing_repeats_while_nothing_changes() -> None:
    shown = Explainer()
    first = shown.reply("ALARM", 2)
    assert first is not None and first.title == "ALARM:2"
    assert shown.reply("ALARM", 2) is None  # the board repeats it: nothing new
    assert shown.reply("error", 9) is None  # every line refused while in alarm: no news
    assert shown.state("Alarm") is False
    assert shown.state("Idle") is True  # out of the alarm: done with
    again = shown.reply("ALARM", 2)
    assert again is not None  # the same alarm again after a change: shown again
    other = shown.reply("ALARM", 1)
    assert other is not None and other.remedies == (Remedy.HOME,)
    assert shown.accepted() is False  # an ok does not end an alarm
    shown.state("Idle")
    error = shown.reply("error", 22)
    assert error is not None and shown.reply("error", 22) is None
    assert shown.accepted() is True  # a line accepted again: the error is over
    assert shown.reply("error", 22) is not None
