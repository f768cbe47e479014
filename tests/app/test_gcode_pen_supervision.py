"""A GRBL plotter's pen line lost or changed on the wire stops the job, on the emulator.

The loopback's manipulator stands for the noisy cable; the emulator reports its spindle
in ``A:`` as GRBL 1.1h does (``tests/e2e/test_e2e_accessories_grbl_sim.py``).
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness

#: Two rows, each a travel pen-up and a stroke pen-down (line 4 lowers the pen for the first).
PLOT = """G90 G21
G0 X10 Y10
M5
M3 S1000
G1 X60 Y10 F3000
M5
G0 X10 Y20
M3 S1000
G1 X60 Y20 F3000
M5
G0 X0 Y0
"""


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(0.5)
    yield harness
    harness.close()


def _run(
    plotter: StationHarness, tmp_path: Path, cable: Callable[[Direction, bytes], bytes] | None
) -> tuple[JobRunner, list[str]]:
    path = tmp_path / "rows.gcode"
    path.write_text(PLOT, encoding="ascii")
    profile = plotter.station.model.profile
    options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(load_job(path, ["X", "Y"], options)) == []
    if cable is not None:
        plotter.loopback.set_manipulator(cable)
    runner.start()
    plotter.run_until(lambda: runner.state in (JobState.DONE, JobState.FAILED), timeout=60)
    return runner, messages


class _nth_line:
    """A cable that changes the ``n``-th ``line`` the station writes into ``into``."""

    def __init__(self, n: int, line: bytes, into: bytes) -> None:
        self.left, self.line, self.into, self.done = n, line, into, False

    def __call__(self, direction: Direction, data: bytes) -> bytes:
        if direction is not Direction.TO_DEVICE or self.done:
            return data
        lines = data.splitlines(keepends=True)
        for i, line in enumerate(lines):
            if line == self.line:
                self.left -= 1
                if self.left == 0:
                    lines[i], self.done = self.into, True
        return b"".join(lines)


def _strokes(plotter: StationHarness) -> list[tuple[float, float, bool]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3), bool(e["pen"]))
        for e in plotter.gcode_emulator.event_log
        if e["event"] == "move"
    ]


def test_the_healthy_job_is_done_and_draws_both_rows(
    plotter: StationHarness, tmp_path: Path
) -> None:
    runner, messages = _run(plotter, tmp_path, None)
    assert runner.state is JobState.DONE, messages
    assert [(x, y) for x, y, pen in _strokes(plotter) if pen] == [(60.0, 10.0), (60.0, 20.0)]


def test_a_lost_pen_down_stops_the_job_naming_the_line(
    plotter: StationHarness, tmp_path: Path
) -> None:
    dropped = _nth_line(2, b"M3S1000\n", b"")  # the second row's pen down never arrives
    runner, messages = _run(plotter, tmp_path, dropped)

    assert dropped.done, "the fault was never injected"
    assert runner.state is JobState.FAILED
    failure = messages[-1]
    assert "rows.gcode:8" in failure and "'M3 S1000'" in failure, failure
    assert "counted as answered while the moves before it still ran" in failure, failure
    emulator = plotter.gcode_emulator
    events = [e["event"] for e in emulator.event_log]
    plotter.run_until(lambda: "reset" in [e["event"] for e in emulator.event_log], timeout=5)
    events = [e["event"] for e in emulator.event_log]
    assert "hold" in events[: events.index("reset")], events  # held, then reset
    # The return home never ran; the second row, drawn pen-up, was stopped.
    assert (0.0, 0.0, False) not in _strokes(plotter)


def test_a_pen_up_changed_into_a_pen_down_stops_the_travel(
    plotter: StationHarness, tmp_path: Path
) -> None:
    flipped = _nth_line(2, b"M5\n", b"M4\n")  # the pen up before row 2: one bit flipped
    runner, messages = _run(plotter, tmp_path, flipped)
    assert flipped.done
    assert runner.state is JobState.FAILED
    failure = messages[-1]
    assert "rows.gcode:6" in failure and "the pen is down" in failure, failure
    assert "A:C" in failure, failure


def test_a_travel_glued_to_the_pen_down_is_stopped_on_its_way(
    plotter: StationHarness, tmp_path: Path
) -> None:
    """Relay seed 138's fault at the machine's own speed: the line end between the travel and
    the pen down lost, GRBL lowers the pen first and draws the travel.  The M5 before it and
    the glued line are answered as the travel starts, so the pen down is counted as answered
    (with the next line's ok) while the travel still runs: the next report shows it."""
    glued = _nth_line(1, b"G0X10Y20\n", b"G0X10Y20")
    runner, messages = _run(plotter, tmp_path, glued)
    assert glued.done
    assert runner.state is JobState.FAILED
    failure = messages[-1]
    assert "rows.gcode:8" in failure and "moves before it still ran" in failure, failure
    travel = [(x, y) for x, y, pen in _strokes(plotter) if pen and y > 10.0 and x == 10.0]
    assert travel == []  # stopped before the travel ended at (10, 20)
