"""Resume after a board's own reset that left it in alarm: the job waits, nothing is streamed.

Real GRBL answers a reset in mid-motion with ``ALARM:3`` (its position is no
longer trusted) and takes no line until ``$X`` or ``$H``; a board with homing
on also powers up in alarm.  Resume must then say so and keep the job
paused, not stream lines the board would refuse (``error:9``).
"""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import SQUARE, square_program


def strokes(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


def moves(harness: StationHarness) -> list[dict[str, object]]:
    return [e for e in harness.gcode_emulator.event_log if e["event"] == "move"]


def test_resume_after_a_self_reset_into_alarm_waits_for_the_unlock(
    qtbot: QtBot, tmp_path: Path
) -> None:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program()) == []
        runner.start()
        harness.run_until(lambda: len(strokes(harness)) >= 1, timeout=30)
        # Its reset button in mid-motion: GRBL resets and raises ALARM:3.
        harness.gcode_emulator.soft_reset()
        harness.gcode_emulator.trigger_alarm(3)
        harness.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        harness.run(1.0)
        assert harness.station.model.link_state is LinkState.CONNECTED
        assert len(messages) == 1 and "restarted" in messages[0], messages  # said once
        choice = runner.resume_choice
        assert choice is not None and choice.position_lost
        sent_before = len(harness.written)
        # The operator picks the line before clearing the alarm: the machine is looked at
        # first, and an alarm keeps the job paused, said once.
        drawn_so_far = len(moves(harness))
        pick = [i for i, op in enumerate(runner.program or ()) if op.target][drawn_so_far]
        assert pick in choice.candidates
        runner.resume_at(pick)
        harness.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        harness.run(2.0)
        alarms = [m for m in messages if "in alarm" in m]
        assert len(alarms) == 1, messages
        assert runner.state is JobState.PAUSED and runner.needs_operator
        job_lines = [w for w in harness.written[sent_before:] if w.strip() not in (b"?", b"")]
        assert job_lines == []  # nothing streamed into the alarm
        assert harness.gcode_session.errors == 0
        # The operator unlocks it; Resume now carries the job to its end from the pick.
        assert harness.gcode_session.send_line("$X")
        harness.run_until(lambda: harness.gcode_session.machine_state == "Idle", timeout=5)
        runner.resume()
        harness.run_until(
            lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), 60
        )
        assert runner.state is JobState.DONE, messages
        drawn = strokes(harness)
        assert drawn == SQUARE[1:]  # each side once, none skipped
    finally:
        runner.deleteLater()
        harness.close()
