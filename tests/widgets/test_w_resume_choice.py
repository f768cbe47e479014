"""The resume-line pick in the jobs dock, with real clicks, against the emulated plotters.

A board that reset while its cable was out stopped in the middle of a stroke:
which lines ran is not proven, so the dock lists the candidates, highlights
their segments in the preview and moves nothing until the operator picks one.
The emulator's log judges the drawing.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import SQUARE, square_program
from widgets.jobs.dock import JobsDock
from widgets.jobs.resume_choice import INDEX_ROLE

LEFT = Qt.MouseButton.LeftButton


def strokes(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


@pytest.fixture(params=["corexy-plotter", "grbl-plotter"])
def plotter(qtbot: QtBot, request: pytest.FixtureRequest) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile(request.param))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    yield harness
    harness.close()


def click_row(qtbot: QtBot, dock: JobsDock, row: int) -> None:
    lines = dock.resume_choice.lines
    item = lines.item(row)
    lines.scrollToItem(item)
    qtbot.mouseClick(lines.viewport(), LEFT, pos=lines.visualItemRect(item).center())


def test_the_operator_picks_the_resume_line_with_the_candidates_highlighted(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    dock = JobsDock(plotter.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.resize(820, 700)
    dock.show()
    assert runner.load(square_program()) == []
    qtbot.mouseClick(dock.run_button, LEFT)
    emulator = plotter.gcode_emulator
    plotter.run_until(lambda: 30.0 < emulator.position()["Y"] < 90.0, timeout=20)
    plotter.loopback.sever("cable pulled")
    emulator.soft_reset()  # mid-stroke, its banner lost with the cable
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
    plotter.run_until(lambda: plotter.station.model.link_state is LinkState.CONNECTED, timeout=30)
    assert not dock.resume_choice.isVisible()
    drawn_before = strokes(plotter)
    qtbot.mouseClick(dock.resume_button, LEFT)
    plotter.run_until(lambda: runner.resume_choice is not None, timeout=10)
    choice = runner.resume_choice
    assert choice is not None
    assert dock.resume_choice.isVisible()
    assert dock.resume_choice.label.text() == choice.text
    assert not dock.resume_button.isEnabled()  # Resume alone would not say where
    # Strokes among the candidates: nothing is picked for the operator.
    assert choice.default is None and dock.resume_choice.chosen() is None
    assert not dock.resume_choice.resume_button.isEnabled()
    xs, ys = dock.preview.candidate_curve.getData()
    assert xs is not None and len(xs) >= 2  # the candidates' segments are highlighted
    highlighted = set(zip(xs.round(3).tolist(), ys.round(3).tolist(), strict=True))
    assert (110.0, 110.0) in highlighted  # the stroke it stopped in
    plotter.run(2.0)
    assert strokes(plotter) == drawn_before  # nothing moved while the operator looks
    # The paper shows the square's first side and half the second: the operator clicks the
    # second side's line.
    program = runner.program
    assert program is not None
    lines = dock.resume_choice.lines
    rows = {int(lines.item(r).data(INDEX_ROLE)): r for r in range(lines.count())}
    second = next(i for i, op in enumerate(program) if op.target == {"X": 110.0, "Y": 110.0})
    click_row(qtbot, dock, rows[second])
    assert dock.resume_choice.chosen() == second
    marked = dock.preview.question_marker.getData()
    assert (marked[0][0], marked[1][0]) == (110.0, 110.0)  # where the picked line goes
    assert dock.resume_choice.resume_button.isEnabled()
    qtbot.mouseClick(dock.resume_choice.resume_button, LEFT)
    plotter.run_until(lambda: runner.state in (JobState.DONE, JobState.FAILED), timeout=60)
    assert runner.state is JobState.DONE
    assert strokes(plotter) == SQUARE[1:]  # every side once, none skipped
    assert not dock.resume_choice.isVisible()
    assert len(dock.preview.candidate_curve.getData()[0] or ()) == 0
    runner.deleteLater()
