"""GRBL's G92 work offset at the station (FIDELITY G8-03), on the emulated GRBL plotter.

GRBL 1.1 keeps the machine position (MPos) and moves only the work position
(WPos = MPos - WCO) on ``G92``, and reports its offset (``WCO:``) only now
and then.  The station must keep the two apart: the DRO shows the work
position (and the machine position beside it), the travel is judged in
machine coordinates, typed moves are work coordinates as GRBL takes them,
and a job resumed after a lost link finds its place with the offset applied.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Program, SourceRef, move
from app.jobs.run.gcode_stream import file_offset
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import SQUARE, square_program
from widgets.panels.info import InfoPanel

#: Where G92 X0 Y0 is said: machine (20, 10) becomes work (0, 0).
OFFSET = (20.0, 10.0)


def grbl_with_offset(status_mask: int) -> StationHarness:
    """The GRBL plotter, ``$10`` set, moved to machine (20, 10) and told ``G92 X0 Y0`` there."""
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    session = harness.gcode_session
    for line in (f"$10={status_mask}", "G90 G0 X20 Y10", "G92 X0 Y0"):
        assert session.send_line(line)
    harness.run_until(lambda: session.settled and session.machine_state == "Idle", timeout=10)
    harness.run(0.5)
    return harness


@pytest.fixture(params=[3, 0], ids=["MPos", "WPos"])
def board(request: pytest.FixtureRequest, qtbot: QtBot) -> Iterator[StationHarness]:
    harness = grbl_with_offset(request.param)
    try:
        yield harness
    finally:
        harness.close()


def settle(harness: StationHarness) -> None:
    session = harness.gcode_session
    harness.run_until(lambda: session.settled and session.machine_state == "Idle", timeout=20)
    harness.run(0.5)  # a report or two after the last line


def test_g8_03_the_dro_shows_the_work_position_and_the_machine_position_beside_it(
    qtbot: QtBot, board: StationHarness
) -> None:
    model = board.station.model
    assert [a.position for a in model.axes[:2]] == pytest.approx(list(OFFSET))
    assert [a.work_position for a in model.axes[:2]] == pytest.approx([0.0, 0.0])
    panel = InfoPanel(model)
    qtbot.addWidget(panel)
    panel.show()
    for index in range(2):
        panel._show_axis(index)
    assert panel.positions[0].text() == "0.000 mm"
    assert panel.machine_positions[0].isVisible()
    assert "20.000" in panel.machine_positions[0].text()
    # Well after the report that carried WCO, the positions stay right (GRBL sends it
    # only every 10th report while idle).
    board.run(3.0)
    assert model.axes[0].work_position == pytest.approx(0.0)
    assert model.axes[0].position == pytest.approx(20.0)
    # G92.1: the two agree again and the machine figure is hidden.
    assert board.gcode_session.send_line("G92.1")
    settle(board)
    panel._show_axis(0)
    assert panel.positions[0].text() == "20.000 mm"
    assert not panel.machine_positions[0].isVisible()


def test_g8_03_a_relative_move_after_g92_moves_by_its_distance(board: StationHarness) -> None:
    """The bug: +5 mm after G92 went to work X25, machine X45 (the offset counted twice)."""
    session = board.gcode_session
    assert session.move_relative(0, 5.0)
    settle(board)
    assert board.gcode_emulator.position()["X"] == pytest.approx(25.0)
    assert board.station.model.axes[0].work_position == pytest.approx(5.0)
    # An absolute move from a panel is to a machine position, sent as GRBL's work one.
    assert session.move_absolute(1, 50.0)
    settle(board)
    assert board.gcode_emulator.position()["Y"] == pytest.approx(50.0)


def test_g8_03_the_travel_is_judged_in_machine_coordinates(board: StationHarness) -> None:
    session = board.gcode_session
    # Work X290 is machine X310: past the 300 mm travel.
    refusal = session.console.beyond_travel("G0 X290")
    assert refusal is not None and "310.000" in refusal.reason
    # Work X-10 is machine X10: inside.
    assert session.console.beyond_travel("G0 X-10") is None
    assert session.console.beyond_travel("G91 G0 X285") is not None  # from machine 20: 305
    assert session.console.beyond_travel("G53 G0 X290") is None  # G53: machine coordinates
    assert not session.move_absolute(0, 301.0)
    assert session.move_absolute(0, 295.0)
    settle(board)
    assert board.gcode_emulator.position()["X"] == pytest.approx(295.0)


def drawn(harness: StationHarness) -> list[tuple[float, float, bool]]:
    """Every move the emulator finished, in machine coordinates: (x, y, pen down)."""
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3), bool(e["pen"]))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move"
    ]


def test_g8_03_a_job_after_g92_runs_offset_and_resumes_in_place_after_a_cut_link(
    qtbot: QtBot, tmp_path: Path
) -> None:
    harness = grbl_with_offset(3)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program(back_home=True)) == []
        runner.start()
        harness.run_until(lambda: len(drawn(harness)) >= 5, timeout=30)
        harness.loopback.sever("cable pulled")
        harness.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        harness.run(8.0)  # the board runs what it had planned, alone
        harness.loopback.set_manipulator(None)
        harness.run_until(
            lambda: harness.station.model.link_state is LinkState.CONNECTED, timeout=30
        )
        runner.resume()
        harness.run_until(
            lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), 60
        )
        assert runner.state is JobState.DONE, messages
        # It found where it stood on the path (work position = the program's coordinates).
        assert any("every answered line ran" in m for m in messages), messages
        dx, dy = OFFSET
        strokes = [m for m in drawn(harness) if m[2]]
        expected = [(x + dx, y + dy, True) for x, y in SQUARE[1:]]
        assert strokes == expected  # drawn once each, where the work offset puts it
        assert drawn(harness)[-1] == (dx, dy, False)  # work 0, 0
    finally:
        runner.deleteLater()
        harness.close()


def test_g8_03_a_board_that_lost_its_offset_in_a_reset_gets_it_back_on_resume(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """A USB GRBL board resets when its port reopens, and a reset clears G92: the rest of
    the job would run shifted by the offset.  Resume sets it again at the resume point."""
    harness = grbl_with_offset(3)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program(back_home=True)) == []
        before = len(drawn(harness))  # the moves that set the offset up
        runner.start()
        harness.run_until(lambda: len(drawn(harness)) >= 3, timeout=30)
        harness.loopback.sever("cable pulled")
        harness.gcode_emulator.soft_reset()  # the board resets as its port reopens
        assert harness.gcode_emulator.work_offset()["X"] == 0.0
        harness.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        harness.loopback.set_manipulator(None)
        harness.run_until(
            lambda: harness.station.model.link_state is LinkState.CONNECTED, timeout=30
        )
        runner.resume()
        # Stopped mid-stroke with its planner (and its banner) lost: the operator picks the
        # line from the paper, the stroke it was in.
        harness.run_until(lambda: runner.resume_choice is not None, timeout=10)
        program = runner.program
        assert program is not None
        moves = [i for i, op in enumerate(program) if op.target]
        runner.resume_at(moves[len(drawn(harness)) - before])
        harness.run_until(
            lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), 60
        )
        assert runner.state is JobState.DONE, messages
        assert harness.gcode_emulator.work_offset() == {"X": 20.0, "Y": 10.0, "Z": 0.0}
        dx, dy = OFFSET
        strokes = [(x, y) for x, y, down in drawn(harness) if down]
        # Each once, none skipped, nothing drawn shifted.
        assert strokes == [(x + dx, y + dy) for x, y in SQUARE[1:]], strokes
        assert drawn(harness)[-1] == (dx, dy, False)
    finally:
        runner.deleteLater()
        harness.close()


def test_g8_03_the_files_own_g92_is_known_at_each_operation(tmp_path: Path) -> None:
    profile = load_profile("grbl-plotter")
    source = tmp_path / "g92.gcode"
    source.write_text(
        "G21 G90\nG0 X10 Y10\nG4 P0.1\nG92 X0 Y0\nG1 X5 Y5 F1000\nG92 X1\nG0 X2\nG92.1\nG0 X3\n",
        encoding="utf-8",
    )
    program = load_job(
        source, ["X", "Y"], JobOptions(gcode=profile.gcode, machine_title=profile.title)
    )
    texts = [op.line for op in program]
    at = {text: k for k, text in enumerate(texts)}
    assert file_offset(program, at["G1 X5 Y5 F1000"], ["X", "Y"]) == {"X": 10.0, "Y": 10.0}
    # At machine X15 (program 15): G92 X1 makes the X offset 14.
    assert file_offset(program, at["G0 X2"], ["X", "Y"]) == {"X": 14.0, "Y": 10.0}
    assert file_offset(program, at["G0 X3"], ["X", "Y"]) == {"X": 0.0, "Y": 0.0}


def test_g8_03_a_job_is_checked_against_the_travel_with_the_offset(
    qtbot: QtBot, tmp_path: Path
) -> None:
    harness = grbl_with_offset(3)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        # X290 is inside 0…300 as written, but machine X310 with the offset.
        far = Program("far", (move(SourceRef("far", 1), X=290.0, Y=0.0),))
        assert runner.load(far) != []
        near = Program("near", (move(SourceRef("near", 1), X=-15.0, Y=-5.0),))
        assert runner.load(near) == []  # machine (5, 5)
    finally:
        runner.deleteLater()
        harness.close()
