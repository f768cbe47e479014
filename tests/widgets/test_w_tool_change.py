"""The jobs dock asks for a G-code job's pen change as it asks for a drill's bit."""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.dock import JobsDock

LEFT = Qt.MouseButton.LeftButton


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    yield harness
    harness.close()


def test_the_prompt_band_says_which_pen_and_continue_goes_on_after_it(
    qtbot: QtBot, plotter: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    dock = JobsDock(plotter.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    dock.resize(820, 640)
    dock.show()
    job = tmp_path / "pens.gcode"
    job.write_text("G0 X5 Y5 F600\nM6 T2\nG0 X9 Y5\n", encoding="ascii")
    assert dock.open_path(job)
    qtbot.mouseClick(dock.run_button, LEFT)
    plotter.run_until(lambda: runner.state is JobState.WAITING, timeout=30)
    assert dock.prompt.isVisible()
    assert "change to pen T2" in dock.prompt_label.text()
    plotter.run(1.0)
    assert runner.state is JobState.WAITING  # it waits, however long
    arrived = [e["text"] for e in plotter.gcode_emulator.event_log if e["event"] == "line"]
    assert arrived[-1] == "G0X5Y5F600"
    qtbot.mouseClick(dock.continue_button, LEFT)
    assert not dock.prompt.isVisible()
    plotter.run_until(lambda: runner.state is JobState.DONE, timeout=30)
    arrived = [e["text"] for e in plotter.gcode_emulator.event_log if e["event"] == "line"]
    assert arrived[-1] == "G0X9Y5" and not [line for line in arrived if "M6" in line]
