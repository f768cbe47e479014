"""A fault after the job's last operation was answered names the last one, not a crash.

Relay grbl-plotter seed 179: the port pulled, the job resumed, every line
answered; then a report off the path (a fragment glued to the next line)
stopped the machine.  The fault named no line, the runner named operation
``done`` (= the program's length) and the station crashed on it, status 3.
"""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.machines.supervision import MotionFault
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import square_program


def test_a_motion_fault_once_every_operation_is_answered_fails_the_job_at_the_last(
    qtbot: QtBot, tmp_path: Path
) -> None:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        program = square_program()
        assert runner.load(program) == []
        runner.start()
        harness.run_until(lambda: runner.done == len(program), timeout=30)
        assert runner.state is JobState.RUNNING  # every line answered, the last still run
        harness.gcode_session.stop_for_fault(MotionFault("off the path", None))
        harness.run_until(lambda: runner.state is JobState.FAILED, timeout=5)
        assert messages[-1] == "Job failed at square:8: off the path", messages
    finally:
        runner.deleteLater()
        harness.close()
