"""The operator sees a GRBL job's lines as written while the board is sent them compact.

The developer's frame log shows both, row by row: the bytes that went, and the
line as the file has it (what the job list, the console and the checkpoint show).
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.app.test_gcode_resume_proof import run_as_the_api_does
from tests.helpers.harness import StationHarness
from widgets.developer.pane import DeveloperPane

GRBL = load_profile("grbl-plotter")
WRITTEN = ["G0 X5 Y5", "G1 X12.5 Y5 F1200 (first stroke)", "g1 x12.5 y9"]


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[tuple[StationHarness, DeveloperPane]]:
    harness = StationHarness(GRBL)
    pane = DeveloperPane(harness.station)
    qtbot.addWidget(pane)
    pane.show()
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    try:
        yield harness, pane
    finally:
        harness.close()


def test_the_frame_log_shows_the_job_as_written_the_board_gets_it_compact(
    plotter: tuple[StationHarness, DeveloperPane], tmp_path: Path
) -> None:
    harness, pane = plotter
    job = tmp_path / "strokes.gcode"
    job.write_text("\n".join(WRITTEN) + "\n", encoding="ascii")
    program = load_job(job, ["X", "Y"], JobOptions(gcode=GRBL.gcode, machine_title=GRBL.title))
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        assert runner.load(program) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        assert runner.state is JobState.DONE
        pane.log_view.flush()
        shown = pane.log_view.text
        # Each line sent is one row: the bytes on the wire, and the line as the file has it.
        rows = [row.split() for row in shown.splitlines() if " TX " in row and "?" not in row]
        pairs = [(row[2], " ".join(row[3:])) for row in rows[-3:]]
        assert pairs == [
            ("G0X5Y5\\n", "G0 X5 Y5"),
            ("G1X12.5Y5F1200\\n", "G1 X12.5 Y5 F1200"),
            ("G1X12.5Y9\\n", "g1 x12.5 y9"),
        ]
        arrived = [e["text"] for e in harness.gcode_emulator.event_log if e["event"] == "line"]
        assert arrived[-3:] == ["G0X5Y5", "G1X12.5Y5F1200", "G1X12.5Y9"]
    finally:
        runner.deleteLater()
