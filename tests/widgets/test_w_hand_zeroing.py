"""Zeroing the string-art winder by hand, as an operator clicks it (FIDELITY S0-24).

The original's white buttons: the first press switches the holding current
off so the operator turns the axes by hand, the second declares where they
stand the zero, with the needle's X at the board radius.  The station does
it with Release motors (``M18``) and Zero here (``G92``): no motion is sent,
and the release goes through the motion gate — refused while a job is under
way or the machine moves.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.program import build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.jobs.program import Operation, OpKind, Program, SourceRef
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.panels.gcode import GcodePanel

A, X, Z = 0, 1, 2


@pytest.fixture
def winder(qtbot: QtBot) -> Iterator[tuple[StationHarness, GcodePanel]]:
    harness = StationHarness(load_profile("string-art"))
    harness.connect()
    harness.run(0.3)
    panel = GcodePanel(harness.station)
    qtbot.addWidget(panel)
    panel.show()
    try:
        yield harness, panel
    finally:
        harness.close()


def sent(harness: StationHarness, mark: int) -> bytes:
    return b"".join(harness.written[mark:])


def messages(harness: StationHarness) -> list[str]:
    said: list[str] = []
    harness.station.model.message.connect(said.append)
    return said


def click(qtbot: QtBot, button: object) -> None:
    qtbot.mouseClick(button, Qt.MouseButton.LeftButton)  # type: ignore[arg-type]


def test_s0_24_release_turn_by_hand_and_zero_here_sets_x_to_the_board_radius(
    qtbot: QtBot, winder: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = winder
    session, emulator, model = harness.gcode_session, harness.gcode_emulator, harness.station.model
    assert panel.hand_group.isVisible()
    assert not panel.zero_here_button.isEnabled()  # only after the release
    assert session.move_absolute(X, 40.0)
    harness.run_until(lambda: session.settled, timeout=10)
    said = messages(harness)

    mark, events = len(harness.written), len(emulator.event_log)
    click(qtbot, panel.release_button)
    assert sent(harness, mark) == b"M18\n"
    harness.run_until(lambda: emulator.drivers_off == {"A", "X", "Z"}, timeout=2)
    assert panel.zero_here_button.isEnabled()

    # The operator turns the base and pulls the needle out to the board's edge.
    assert emulator.turn_by_hand("A", 33.0) and emulator.turn_by_hand("X", 95.5)
    harness.run(0.5)

    panel.board_radius.setFocus()
    panel.board_radius.selectAll()
    qtbot.keyClicks(panel.board_radius, "135.5")
    mark = len(harness.written)
    click(qtbot, panel.zero_here_button)
    assert sent(harness, mark) == b"G92 A0.000 X135.500 Z0.000\n"
    harness.run_until(lambda: session.settled, timeout=5)
    harness.run(0.5)
    assert emulator.position() == {"A": 0.0, "X": 135.5, "Z": 0.0}
    assert [a.position for a in model.axes] == [0.0, 135.5, 0.0]
    assert not panel.zero_here_button.isEnabled()
    assert any("Zeroed by hand" in m for m in said)
    # Nothing moved: the log holds no move since the release.
    assert not any(e["event"] == "move" for e in emulator.event_log[events:])


def test_s0_24_release_is_refused_while_the_machine_moves(
    qtbot: QtBot, winder: tuple[StationHarness, GcodePanel]
) -> None:
    harness, panel = winder
    session, emulator = harness.gcode_session, harness.gcode_emulator
    said = messages(harness)
    assert session.move_absolute(X, 200.0)
    harness.run_until(lambda: emulator.state == "Run", timeout=2)
    harness.run(0.5)
    mark = len(harness.written)
    click(qtbot, panel.release_button)
    harness.run(0.3)
    assert b"M18" not in sent(harness, mark) and not emulator.drivers_off
    assert any(m.startswith("Not released: the motors are not released:") for m in said)
    assert not panel.zero_here_button.isEnabled()
    # Zero here without a release is refused too (called as the button would).
    assert not panel.zero_here() and b"G92" not in sent(harness, mark)


def test_s0_24_release_is_refused_while_a_job_is_under_way(
    qtbot: QtBot, winder: tuple[StationHarness, GcodePanel], tmp_path: Path
) -> None:
    harness, panel = winder
    emulator = harness.gcode_emulator
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    wait = Operation(OpKind.WAIT, SourceRef("job", 1), message="insert the nails")
    assert runner.load(Program("job", (wait,))) == []
    runner.start()
    harness.run_until(lambda: runner.state is JobState.WAITING, timeout=5)
    said = messages(harness)
    mark = len(harness.written)
    click(qtbot, panel.release_button)
    harness.run(0.3)
    assert b"M18" not in sent(harness, mark) and not emulator.drivers_off
    assert any("a job is under way" in m for m in said)
    runner.abort()


def test_s0_24_the_board_radius_follows_the_string_art_job_loaded(
    winder: tuple[StationHarness, GcodePanel], tmp_path: Path
) -> None:
    harness, panel = winder
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    panel.follow_jobs(runner)
    assert panel.board_radius.value() == 120.0
    job = StringArtJob(StringArtParams(tvar=0, nails=8, radius_cm=14.5), (0, 3, 6, 1, 4))
    assert runner.load(build_program(job, harness.station.profile)) == []
    assert panel.board_radius.value() == 145.0
