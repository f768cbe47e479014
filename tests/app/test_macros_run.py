"""Macros run on the emulated GRBL plotter as small jobs, or are refused before a byte is sent.

The wire is watched where the station writes it (the harness records every
byte the link sends) and where the machine acts (the emulator's event log).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.runner import JobRunner
from app.jobs.run.states import ACTIVE, JobState
from app.machine import LinkState
from app.macros.machines import macros_available
from app.macros.runner import MacroRunner
from app.macros.store import Macro
from app.profiles import load_profile
from tests.helpers.harness import StationHarness


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    yield harness
    harness.close()


@pytest.fixture
def macros(grbl: StationHarness, tmp_path: Path) -> Iterator[MacroRunner]:
    runner = MacroRunner(grbl.station, tmp_path / "macro-checkpoints")
    yield runner
    runner.deleteLater()


def heard(runner: MacroRunner) -> list[str]:
    said: list[str] = []
    runner.message.connect(said.append)
    return said


def job_lines(harness: StationHarness) -> list[str]:
    """The G-code lines the emulated board received (status queries are not lines)."""
    return [e["text"] for e in harness.gcode_emulator.event_log if e["event"] == "line"]


def position(harness: StationHarness) -> tuple[float, float]:
    where = harness.gcode_emulator.position()
    return round(where["X"], 3), round(where["Y"], 3)


def run_macro(harness: StationHarness, runner: MacroRunner, macro: Macro) -> None:
    assert runner.run(macro), "refused"
    harness.run_until(lambda: runner.state not in ACTIVE, timeout=60)


def test_an_out_of_travel_macro_is_refused_before_a_byte_is_sent(
    grbl: StationHarness, macros: MacroRunner
) -> None:
    said = heard(macros)
    grbl.run(0.5)
    lines_before = len(job_lines(grbl))
    written_before = len(grbl.written)
    assert not macros.run(Macro("Park", "G90\nG0 X900 Y10\nG0 X0 Y0"))
    grbl.run(1.0)
    sent = [w for w in grbl.written[written_before:] if w.strip() != b"?"]
    assert sent == []  # only the status queries the session always sends
    assert len(job_lines(grbl)) == lines_before
    assert macros.state is JobState.IDLE
    assert 'macro "Park":2: X 900 is outside the travel 0…300' in said[-1]


def test_a_macro_runs_as_a_job_and_its_relative_moves_start_where_the_machine_stands(
    grbl: StationHarness, macros: MacroRunner
) -> None:
    run_macro(grbl, macros, Macro("Corner", "G90\nG0 X50 Y20"))
    assert macros.state is JobState.DONE
    assert position(grbl) == (50.0, 20.0)
    run_macro(grbl, macros, Macro("Nudge", "G91\nG0 X-10 Y5\nG90"))
    assert macros.state is JobState.DONE
    assert position(grbl) == (40.0, 25.0)
    assert "G0X-10Y5" in [line.replace(" ", "") for line in job_lines(grbl)]


def test_a_relative_move_is_checked_from_where_the_machine_stands(
    grbl: StationHarness, macros: MacroRunner
) -> None:
    run_macro(grbl, macros, Macro("Corner", "G0 X5 Y5"))
    said = heard(macros)
    lines_before = len(job_lines(grbl))
    # From 0 this would be inside the travel; from X5 it leaves it.
    assert not macros.run(Macro("Back", "G91\nG0 X-10"))
    assert 'macro "Back":2: X -5 is outside the travel 0…300' in said[-1]
    grbl.run(0.5)
    assert len(job_lines(grbl)) == lines_before


def test_a_macro_the_preflight_refuses_names_its_line(
    grbl: StationHarness, macros: MacroRunner
) -> None:
    said = heard(macros)
    assert not macros.run(Macro("Draw", "G90\nG1 X10"))  # no feed rate: GRBL's error:22
    assert 'macro "Draw":2: feed rate undefined' in said[-1]
    assert not macros.run(Macro("Motor", "G0 X1\nM18"))  # not the plotter's repertoire
    assert 'macro "Motor":2: M18' in said[-1]
    assert not macros.run(Macro("Empty", "; nothing\n"))
    assert "no G-code to send" in said[-1]


def test_a_macro_is_refused_while_a_job_runs_and_a_job_while_a_macro_runs(
    grbl: StationHarness, macros: MacroRunner, tmp_path: Path
) -> None:
    job = JobRunner(grbl.station, tmp_path / "checkpoints")
    job_said: list[str] = []
    job.message.connect(job_said.append)
    program = Program(
        "far",
        (
            Operation(OpKind.COMMENT, SourceRef("far", 1), message="go"),
            move(SourceRef("far", 2), X=250.0, Y=150.0),
        ),
    )
    assert job.load(program) == []
    job.start()
    assert job.state in ACTIVE
    said = heard(macros)
    assert not macros.run(Macro("Park", "G0 X0 Y0"))
    assert "a job is under way" in said[-1]
    grbl.run_until(lambda: job.state is JobState.DONE, timeout=60)
    assert macros.run(Macro("Home", "G0 X0 Y0"))
    job.start()
    assert job.state is JobState.DONE  # not started again
    assert "Cannot run the job: a macro is under way" in job_said[-1]
    grbl.run_until(lambda: macros.state is JobState.DONE, timeout=60)
    # The macro's end gave the jog lock back: a jog is the operator's again.
    assert grbl.station.model.jog_lock_reason is None
    job.deleteLater()


def test_a_macro_is_refused_while_disconnected(grbl: StationHarness, macros: MacroRunner) -> None:
    said = heard(macros)
    grbl.station.close_link()
    grbl.run(0.2)
    assert not macros.run(Macro("Park", "G0 X0 Y0"))
    assert "not connected" in said[-1]


def test_stop_ends_a_macro_and_the_machine_stops(grbl: StationHarness, macros: MacroRunner) -> None:
    assert macros.run(Macro("Far", "G0 X290 Y190"))
    grbl.run_until(lambda: position(grbl)[0] > 20.0, timeout=30)
    macros.abort()
    assert macros.state is JobState.ABORTED
    grbl.run(3.0)
    stopped_at = position(grbl)
    grbl.run(3.0)
    assert position(grbl) == stopped_at
    assert stopped_at[0] < 290.0
    # The next run starts from its start, not from the aborted run's checkpoint.
    said = heard(macros)
    run_macro(grbl, macros, Macro("Far", "G0 X290 Y190"))
    assert macros.state is JobState.DONE, said
    assert position(grbl) == (290.0, 190.0)


def test_a_lost_link_pauses_a_macro_and_it_goes_on_once_back(
    grbl: StationHarness, macros: MacroRunner
) -> None:
    said = heard(macros)
    assert macros.run(Macro("Walk", "G1 X20 F300\nG1 X40\nG1 X60\nG1 X80"))
    grbl.run_until(lambda: position(grbl)[0] > 5.0, timeout=30)
    grbl.loopback.sever("cable pulled")
    grbl.run_until(lambda: macros.state is JobState.PAUSED, timeout=5)
    grbl.loopback.set_manipulator(None)
    grbl.run_until(lambda: grbl.station.model.link_state is LinkState.CONNECTED, timeout=30)
    assert macros.state is JobState.PAUSED  # nothing went on by itself over a new link
    macros.resume()  # the operator's Resume: the runner looks at the machine first
    grbl.run_until(lambda: macros.state not in ACTIVE, timeout=120)
    assert macros.state is JobState.DONE, said
    assert position(grbl) == (80.0, 0.0)
    strokes = [e["pos"]["X"] for e in grbl.gcode_emulator.event_log if e["event"] == "move"]
    assert strokes == sorted(strokes)  # nothing went back and forth


def test_macros_are_for_machines_sent_gcode_text() -> None:
    assert macros_available(load_profile("grbl-plotter"))
    assert macros_available(load_profile("corexy-plotter"))
    assert not macros_available(load_profile("usb3"))
    assert not macros_available(load_profile("pcb-drill"))
    assert not macros_available(load_profile("xy-stage"))


@pytest.mark.parametrize(
    ("profile", "far", "inside", "where"),
    [
        ("corexy-plotter", "G0 X900 Y10", "G0 X20 Y15", {"X": 20.0, "Y": 15.0}),
        ("string-art", "G0 X900", "G0 X20 A90", {"X": 20.0, "A": 90.0}),
    ],
)
def test_every_gcode_machine_refuses_out_of_travel_and_runs_the_rest(
    qtbot: QtBot, tmp_path: Path, profile: str, far: str, inside: str, where: dict[str, float]
) -> None:
    harness = StationHarness(load_profile(profile))
    harness.connect()
    runner = MacroRunner(harness.station, tmp_path / "macros")
    try:
        said = heard(runner)
        harness.run(0.5)
        before = len(job_lines(harness))
        assert not runner.run(Macro("Far", far))
        assert 'macro "Far":1: X 900 is outside the travel' in said[-1]
        harness.run(0.5)
        assert len(job_lines(harness)) == before
        run_macro(harness, runner, Macro("Inside", inside))
        assert runner.state is JobState.DONE, said
        reached = harness.gcode_emulator.position()
        assert {axis: round(reached[axis], 3) for axis in where} == where
    finally:
        runner.deleteLater()
        harness.close()


def test_a_machine_without_gcode_text_refuses_every_macro(qtbot: QtBot, tmp_path: Path) -> None:
    harness = StationHarness(load_profile("usb3"))
    harness.connect()
    runner = MacroRunner(harness.station, tmp_path / "macros")
    try:
        said = heard(runner)
        written = len(harness.written)
        assert not runner.run(Macro("Park", "G0 X0"))
        assert "takes no G-code macros" in said[-1]
        assert len(harness.written) == written
    finally:
        runner.deleteLater()
        harness.close()
