"""The job's progress follows the machine while a pen change waits for the moves before it.

GRBL answers ``M3``/``M5`` only once the planner has run dry (its ``spindle_sync``), so
the lines after a square's strokes stay unanswered until the last stroke is drawn.  The
dock showed "0 / 10 operations" for the whole square: the status reports proved the
strokes run, but only an answer made the driver tell the views.
"""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness

SQUARE = (
    "G21 G90\nG0 X10 Y10\nM3 S1000\nG1 X60 F3000\nG1 Y60\nG1 X10\nG1 Y10\n"
    "G1 X60 Y60\nM5\nG0 X0 Y0\n"
)


def test_strokes_proven_run_are_shown_before_the_pen_up_after_them_is_answered(
    qtbot: QtBot, tmp_path: Path
) -> None:
    harness = StationHarness(load_profile("grbl-plotter"))
    try:
        harness.connect()
        harness.run(0.5)
        path = tmp_path / "square.gcode"
        path.write_text(SQUARE, encoding="ascii")
        profile = harness.station.model.profile
        options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
        runner = JobRunner(harness.station, tmp_path / "checkpoints")
        told: list[int] = []
        runner.executedChanged.connect(lambda executed, _total: told.append(executed))
        assert runner.load(load_job(path, ["X", "Y"], options)) == []
        runner.start()
        # The fourth stroke (down the left side) under way: the pen up (M5, line 9) waits
        # for it and the diagonal, unanswered.
        x, y = harness.station.model.axes
        harness.run_until(lambda: y.position >= 59.9, timeout=20)
        harness.run_until(lambda: x.position <= 10.01 and y.position < 40.0, timeout=20)
        assert runner.state is JobState.RUNNING
        assert runner.progress.done < 9  # the M5 is not answered
        assert runner.progress.executed >= 5  # the first three strokes are behind it
        assert told[-1] == runner.progress.executed
        harness.run_until(lambda: runner.state is JobState.DONE, timeout=20)
    finally:
        harness.close()
