"""``M6 Tn`` in a G-code job is a wait for the operator ("change to pen T2"), never a line sent.

What the operator relies on: the job stops with everything before the change
run, nothing is sent to the board while it waits (however long), the M6 line
itself never reaches the board (GRBL would refuse it), and Continue goes on
with the line after it.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.formats.gcode.tool_change import tool_change
from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import OpKind
from app.jobs.run.runner import JobState
from app.profiles import load_profile
from app.station import Station
from tests.app.test_compact_wire import read, start, station_on
from tests.app.test_gcode_job_pulled import BoardPort

GRBL = load_profile("grbl-plotter")


@pytest.mark.parametrize(
    ("code", "tool"),
    [("M6 T2", "2"), ("M06 T02", "2"), ("T3 M6", "3"), ("m6t12", "12"), ("M6", "")],
)
def test_a_change_line_names_its_tool(code: str, tool: str) -> None:
    assert tool_change(code) == tool


@pytest.mark.parametrize("code", ["M60", "M6.1 T2", "G0 X1 M6 T2", "T2", "T2 M6 T3", "M6 T300"])
def test_other_lines_are_no_change(code: str) -> None:
    assert tool_change(code) is None


def test_the_loader_makes_each_change_a_wait_with_its_prompt(tmp_path: Path) -> None:
    job = tmp_path / "pens.gcode"
    job.write_text("G0 X1 Y1\nM6 T2 (red)\nT03 M06\nM6\nG0 X2 Y2\n", encoding="ascii")
    program = load_job(job, ["X", "Y"], JobOptions(gcode=GRBL.gcode, machine_title=GRBL.title))
    waits = [(op.source.line, op.message) for op in program if op.kind is OpKind.WAIT]
    assert waits == [(2, "change to pen T2: red"), (3, "change to pen T3"), (4, "change the pen")]
    assert all(not op.line for op in program if op.kind is OpKind.WAIT)  # nothing to send


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[tuple[Station, BoardPort]]:
    station, port = station_on("grbl-plotter", qtbot)
    try:
        yield station, port
    finally:
        station.shutdown()


def test_m6_t2_waits_for_the_operator_and_goes_on_with_the_line_after(
    grbl: tuple[Station, BoardPort], tmp_path: Path
) -> None:
    station, port = grbl
    asked: list[str] = []
    runner = start(station, port, tmp_path, "G0 X1 Y1 F600\nM6 T2\nG1 X5 Y1 F600\n")
    runner.waitingForOperator.connect(asked.append)
    assert port.lines()[2:] == [b"G0X1Y1F600\n"]  # the lines before the change, no more
    read(station, b"ok\r\n")
    idle_there = b"<Idle|MPos:1.000,1.000,0.000|Bf:15,127|FS:0,0>\r\n"
    read(station, idle_there)
    assert runner.state is JobState.WAITING
    assert asked == ["change to pen T2"]
    for _ in range(5):  # however long it waits, nothing more goes
        read(station, idle_there)
    assert port.lines()[2:] == [b"G0X1Y1F600\n"]
    assert runner.state is JobState.WAITING
    runner.confirm()
    # The line after the change; the M6 line never went (GRBL would refuse it: error:20).
    assert port.lines()[2:] == [b"G0X1Y1F600\n", b"G1X5Y1F600\n"]
    assert runner.state is JobState.RUNNING
    assert not [line for line in port.lines() if b"M6" in line]
    read(station, b"ok\r\n")
    read(station, b"<Idle|MPos:5.000,1.000,0.000|Bf:15,127|FS:0,0>\r\n")
    assert runner.state is JobState.DONE
