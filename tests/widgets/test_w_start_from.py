"""The jobs dock's "Run from…", with real clicks, against the emulated GRBL plotter.

The operator picks a line in the list (or clicks its stroke in the preview)
and clicks "Run from here"; the emulator's log judges what was drawn.  A
start the station cannot set up is refused in the dialog with file:line and
nothing moves; a click in the preview while picking moves nothing either.
"""

from __future__ import annotations

import threading
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QKeySequence
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run import start_point
from app.jobs.run.runner import JobRunner, JobState
from app.jobs.run.start_point import operation_at_line
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock
from widgets.jobs.start_from import SHORTCUT, StartFromDialog
from widgets.window.menus import SHORTCUTS

LEFT = Qt.MouseButton.LeftButton
PROFILE = load_profile("grbl-plotter")
#: Three strokes: lines 4, 5 (the feed set on line 4) and 8 (after a pen lift), G91 between.
FILE = [
    "G21 G90",  # 1
    "G0 X20 Y20",  # 2
    "M3 S1000",  # 3
    "G1 X80 Y20 F3000",  # 4
    "X80 Y80",  # 5
    "M5",  # 6
    "G0 X20 Y80",  # 7
    "M3 S1000\nG91\nX0 Y-40",  # 8, 9, 10
    "M5",  # 11
]


def strokes(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(PROFILE)
    harness.connect()
    harness.run(0.3)
    yield harness
    harness.close()


def loaded_dock(
    qtbot: QtBot, harness: StationHarness, tmp_path: Path, lines: list[str] = FILE
) -> JobsDock:
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.resize(820, 700)
    dock.show()
    qtbot.waitExposed(dock)
    path = tmp_path / "square.gcode"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    program = load_job(path, [a.name for a in PROFILE.axes], JobOptions(gcode=PROFILE.gcode))
    assert runner.load(program) == []
    return dock


def open_dialog(qtbot: QtBot, dock: JobsDock) -> StartFromDialog:
    assert dock.run_from_button.isEnabled()
    qtbot.mouseClick(dock.run_from_button, LEFT)
    dialog = dock.start_from.dialog
    assert dialog is not None
    qtbot.waitExposed(dialog)
    return dialog


def click_row(qtbot: QtBot, dialog: StartFromDialog, row: int) -> None:
    index = dialog.model.index(row, 0)
    dialog.lines.scrollTo(index)
    qtbot.mouseClick(dialog.lines.viewport(), LEFT, pos=dialog.lines.visualRect(index).center())


def click_plot(qtbot: QtBot, dock: JobsDock, x: float, y: float) -> None:
    preview = dock.preview
    view = preview.plot.getViewBox()
    pixel: QPoint = preview.plot_widget.mapFromScene(view.mapViewToScene(QPointF(x, y)))
    qtbot.mouseClick(preview.plot_widget.viewport(), LEFT, pos=pixel)


def test_run_from_a_line_picked_in_the_list_draws_from_there_on(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    runner = dock.runner
    program = runner.program
    assert program is not None
    dialog = open_dialog(qtbot, dock)
    assert not dialog.run_button.isEnabled()  # nothing picked yet
    start = operation_at_line(program, 5)
    click_row(qtbot, dialog, start)
    assert dialog.chosen() == start
    marked = dock.preview.question_marker.getData()
    assert (marked[0][0], marked[1][0]) == (80.0, 80.0)  # where line 5 goes
    qtbot.mouseClick(dialog.run_button, LEFT)
    plotter.run_until(lambda: runner.state is JobState.DONE, timeout=60)
    assert strokes(plotter) == [(80.0, 80.0), (20.0, 40.0)]
    assert dock.start_from.dialog is None  # it closed once the job started


def test_a_stroke_clicked_in_the_preview_is_picked_and_moves_nothing(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    program = dock.runner.program
    assert program is not None
    dialog = open_dialog(qtbot, dock)
    sent = len(plotter.written)
    click_plot(qtbot, dock, 20.0, 60.0)  # on line 10's stroke (20, 80) → (20, 40)
    plotter.run(0.3)
    assert dialog.chosen() == operation_at_line(program, 10)
    assert all(frame == b"?" for frame in plotter.written[sent:])  # status queries only
    # The list's context menu has Run from here too; the run draws line 10's stroke only.
    (action,) = [a for a in dialog.context_menu().actions() if a.text() == "Run from here"]
    action.trigger()
    plotter.run_until(lambda: dock.runner.state is JobState.DONE, timeout=60)
    assert strokes(plotter) == [(20.0, 40.0)]
    # Picking over, a click in the preview is a move request again.
    assert dock.preview.point_picker is None


def test_a_start_that_cannot_be_set_up_is_refused_in_the_dialog_with_file_and_line(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    runner = dock.runner
    dialog = open_dialog(qtbot, dock)
    # A checkpoint of this job waits (an earlier run stopped): the start is refused.
    program = runner.program
    assert program is not None
    runner.start_from(operation_at_line(program, 4))
    plotter.run_until(lambda: runner.progress.executed > operation_at_line(program, 4), timeout=30)
    runner.abort()
    assert runner.resume_available is not None
    dialog = open_dialog(qtbot, dock)
    click_row(qtbot, dialog, operation_at_line(program, 8))
    drawn = strokes(plotter)
    qtbot.mouseClick(dialog.run_button, LEFT)
    plotter.run_until(lambda: dialog.planning is None, timeout=30)
    plotter.run(0.3)
    assert runner.state is not JobState.RUNNING
    assert "square.gcode:8" in dialog.reason.text()
    assert "checkpoint" in dialog.reason.text()
    assert strokes(plotter) == drawn


def test_the_key_opens_the_list_and_help_lists_it(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    assert dock.start_from.action.shortcut() == QKeySequence(SHORTCUT)
    dock.start_from.action.trigger()
    assert dock.start_from.dialog is not None
    assert any(keys == SHORTCUT for keys, _ in SHORTCUTS)
    dock.start_from.dialog.close()
    # Nothing loaded, or a job under way: nothing to start from.
    dock.runner.start()
    assert not dock.run_from_button.isEnabled()
    assert dock.start_from.open() is None


def test_the_state_at_the_pick_is_worked_out_off_the_gui_thread_once(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    runner = dock.runner
    program = runner.program
    assert program is not None
    threads: list[threading.Thread] = []
    real = start_point._plan_start

    def recording(*args: Any) -> start_point.StartPlan:
        threads.append(threading.current_thread())
        return real(*args)

    monkeypatch.setattr(start_point, "_plan_start", recording)
    dialog = open_dialog(qtbot, dock)
    click_row(qtbot, dialog, operation_at_line(program, 5))
    qtbot.mouseClick(dialog.run_button, LEFT)
    # While it is worked out the dialog says so, and a second click starts nothing more.
    assert dialog.planning is not None
    assert not dialog.run_button.isEnabled()
    assert "Working out" in dialog.reason.text()
    plotter.run_until(lambda: runner.state is JobState.DONE, timeout=60)
    assert strokes(plotter) == [(80.0, 80.0), (20.0, 40.0)]
    # Once, on the worker; the runner's own call on the GUI thread found it remembered.
    assert len(threads) == 1
    assert threads[0] is not threading.main_thread()


def test_a_dialog_closed_while_the_state_is_worked_out_starts_nothing(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    dock = loaded_dock(qtbot, plotter, tmp_path)
    runner = dock.runner
    program = runner.program
    assert program is not None
    dialog = open_dialog(qtbot, dock)
    click_row(qtbot, dialog, operation_at_line(program, 5))
    qtbot.mouseClick(dialog.run_button, LEFT)
    planning = dialog.planning
    assert planning is not None
    sent = len(plotter.written)
    # Closed before the worker's answer is heard, and not yet deleted when it is.
    dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose, False)
    dialog.close()
    planning.join()
    plotter.run(0.5)
    assert runner.state is JobState.READY
    assert all(frame == b"?" for frame in plotter.written[sent:])  # status queries only
