"""A job whose every line is answered asks the board where it stands at once, not at the next
poll: its end (or its wait for the operator) shows when the board says it is idle."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    yield harness
    harness.close()


def test_the_last_answer_asks_for_the_status_and_the_job_ends_on_its_report(
    plotter: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    session = plotter.gcode_session
    at = SourceRef("short", 1)
    # Moves to where the pen already stands: nothing to wait for but the board's word.
    program = Program("short", (Operation(OpKind.PEN_UP, at), *[move(at, X=0.0, Y=0.0)] * 5))
    assert runner.load(program) == []
    asked: list[float] = []

    def to_board(direction: Direction, data: bytes) -> bytes:
        """Every "?" on the wire, whoever wrote it (the window, or the feeder where the
        answer was read)."""
        if direction is Direction.TO_DEVICE and b"?" in data:
            asked.append(plotter.clock.now())
        return data

    plotter.loopback.set_manipulator(to_board)
    advanced: list[float] = []
    session.jobAdvanced.connect(lambda: advanced.append(plotter.clock.now()))
    runner.start()
    plotter.run_until(lambda: runner.state is not JobState.RUNNING, timeout=5)
    assert runner.state is JobState.DONE
    assert advanced, "the job's answers were never heard"
    last = advanced[-1]  # the batch with the job's last answer
    # Asked in the same turn as the last answer was heard, not a poll (status_ms) later.
    assert any(t == last for t in asked), (last, asked)
    period = session.settings.status_ms / 1000
    done_at = plotter.clock.now()
    assert done_at - last < period
