"""Operation texts and click-to-move messages write numbers as the window's language does
("najet na X10,500" in Czech and Slovak), while the line sent for the same operation keeps
its decimal point.

Each test removes the translations it installed, so the rest of the suite reads English.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app import i18n
from app.jobs.program import Program, SourceRef, check_limits, move
from app.jobs.render.gcode import GcodeSettings, render_operation
from protocol.stage.codec import CommandId
from tests.helpers.harness import StationHarness
from widgets.jobs.operation_text import operation_text
from widgets.jobs.preview import JobPreview
from widgets.jobs.start_from import OperationsModel

#: The language and how it writes 10.5 and 2.25 with three decimals.
LANGUAGES = [("cs", "X10,500 Y2,250"), ("sk", "X10,500 Y2,250"), ("en", "X10.500 Y2.250")]


@pytest.fixture(autouse=True)
def english_afterwards(qapp: object) -> Iterator[None]:
    yield
    i18n.remove()


def _program() -> Program:
    return Program("job", (move(SourceRef("job.csv", 3), X=10.5, Y=2.25),))


@pytest.mark.parametrize(("language", "where"), LANGUAGES)
def test_the_operation_list_writes_the_languages_numbers_and_the_wire_keeps_points(
    i18n_cache: Path, language: str, where: str
) -> None:
    assert i18n.install(language, i18n_cache) == language
    program = _program()
    op = program[0]
    shown = operation_text(op)
    assert shown.endswith(f" {where}") and shown.startswith("move to ") == (language == "en")
    # The start-from list's row, as its view shows it.
    model = OperationsModel(program, lambda _line: "10.5, 2.25")
    row = model.data(model.index(0))
    assert isinstance(row, str) and f"{shown}   (" in row
    assert row.endswith("(10.5, 2.25)")  # the file's own line, quoted as written
    # The runner's messages (Operation.describe) and the limits' refusals too.
    assert where in op.describe()
    refusal = str(check_limits(program, {"X": (0.0, 5.0), "Y": (0.0, 5.0)})[0])
    assert f"X {'10,5' if language != 'en' else '10.5'} " in refusal
    assert refusal.endswith("0…5")
    # What is sent for it is the machine's, whatever the window's language.
    assert render_operation(op, GcodeSettings()) == "G0 X10.500 Y2.250"


@pytest.mark.parametrize("language", ["cs", "sk"])
def test_click_to_move_says_the_target_in_the_languages_numbers(
    qtbot: QtBot, harness: StationHarness, i18n_cache: Path, language: str
) -> None:
    assert i18n.install(language, i18n_cache) == language
    asked: list[str] = []
    preview = JobPreview(harness.station, confirm=lambda text: bool(asked.append(text)) or True)
    qtbot.addWidget(preview)
    preview.set_program(_program())
    harness.connect()
    harness.run(1.0)
    assert preview.request_move(12.25, 7.5)
    assert "X 12,250, Y 7,500" in asked[0] and "X 12,250, Y 7,500" in preview.last_message
    harness.run(1.0)
    sent = [c for c in harness.emulator.command_log if c.command == CommandId.MOVE_ABS]
    assert len(sent) == 2  # and the moves went out, in the machine's own units
