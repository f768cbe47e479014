"""An alarm is said once, and a job it stops is paused until the operator acts.

Issue 30: after a reset on real GRBL the station repeated "the machine is in
alarm" about 30 times a second, and the job never ended.  A board repeats its
alarm (on each reset while locked, a switch that bounces, a reply line
repeated on the wire); each copy was a new "Machine alarm n" in the status
bar, and a hard limit mid-job left the job "running" for good, waiting for
answers the board would never give.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

import stepdeck
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import SQUARE, square_program


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    try:
        yield harness
    finally:
        harness.close()


def said(messages: list[str], word: str) -> list[str]:
    return [m for m in messages if word in m]


def strokes(harness: StationHarness) -> list[tuple[float, float]]:
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in harness.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


def test_an_alarm_repeated_is_said_once_until_the_board_leaves_it(
    plotter: StationHarness,
) -> None:
    messages: list[str] = []
    plotter.station.model.message.connect(messages.append)
    emulator = plotter.gcode_emulator
    emulator.trigger_alarm(2)
    plotter.run(0.5)
    emulator.trigger_alarm(2)  # the same alarm again: the board never left it
    plotter.run(0.5)
    assert len(said(messages, "Machine alarm 2")) == 1, messages
    emulator.trigger_alarm(1)  # another alarm is news
    plotter.run(0.5)
    assert len(said(messages, "Machine alarm 1")) == 1, messages
    assert plotter.gcode_session.limit_lock.unlock()  # GRBL's lock: reset, then $X
    plotter.run_until(lambda: plotter.gcode_session.machine_state == "Idle", timeout=3)
    emulator.trigger_alarm(2)  # out of it and back in: said again
    plotter.run(0.5)
    assert len(said(messages, "Machine alarm 2")) == 2, messages


def test_an_alarm_mid_job_pauses_it_once_and_the_resume_draws_each_stroke_once(
    plotter: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program()) == []
        runner.start()
        plotter.run_until(lambda: len(strokes(plotter)) >= 1, timeout=30)
        emulator = plotter.gcode_emulator
        emulator.trigger_alarm(1)  # a limit switch mid-stroke
        plotter.run(0.3)
        emulator.trigger_alarm(1)  # and again: it bounces
        plotter.run(2.0)
        assert runner.state is JobState.PAUSED and runner.needs_operator, messages
        assert len(messages) == 1 and "alarm 1" in messages[0], messages
        written = len(plotter.written)
        plotter.run(2.0)
        job_lines = [w for w in plotter.written[written:] if w.strip() not in (b"?", b"!", b"")]
        assert job_lines == []  # nothing streamed into the alarm
        # The operator resets and unlocks it (its position kept) and resumes.
        assert plotter.gcode_session.limit_lock.unlock()
        plotter.run_until(lambda: plotter.gcode_session.machine_state == "Idle", timeout=3)
        runner.resume()
        plotter.run_until(
            lambda: runner.state is not JobState.RUNNING or runner.needs_operator, timeout=60
        )
        if runner.resume_choice is not None:  # stopped mid-stroke: the operator picks it
            drawn = len(strokes(plotter))
            program = runner.program or ()
            pick = [i for i, op in enumerate(program) if op.target][drawn + 1]
            assert pick in runner.resume_choice.candidates
            runner.resume_at(pick)
            plotter.run_until(lambda: runner.state is not JobState.RUNNING, timeout=60)
        assert runner.state is JobState.DONE, messages
        assert strokes(plotter) == SQUARE[1:]  # each side once, none skipped
    finally:
        runner.deleteLater()


def test_an_alarm_then_the_boards_restart_is_said_once(
    plotter: StationHarness, tmp_path: Path
) -> None:
    """Real GRBL after its reset in motion says ALARM:3, then its banner (the restart)."""
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program()) == []
        runner.start()
        plotter.run_until(lambda: len(strokes(plotter)) >= 1, timeout=30)
        plotter.gcode_emulator.trigger_alarm(3)
        plotter.gcode_emulator.soft_reset()
        plotter.run(2.0)
        assert runner.state is JobState.PAUSED and runner.needs_operator
        assert len(messages) == 1 and "alarm 3" in messages[0], messages
        # Unlocked and resumed: its position may be lost, so the operator picks the line.
        assert plotter.gcode_session.send_line("$X")
        plotter.run_until(lambda: plotter.gcode_session.machine_state == "Idle", timeout=3)
        runner.resume()
        plotter.run_until(lambda: runner.resume_choice is not None, timeout=5)
        choice = runner.resume_choice
        assert choice is not None and choice.position_lost
        assert len(messages) == 2, messages
    finally:
        runner.deleteLater()


def test_the_api_fails_a_job_an_alarm_stopped_and_its_progress_says_so(
    qapp: object, tmp_path: Path
) -> None:
    """A script has no operator to clear the alarm: the job fails, said once, no hang."""
    plotter = stepdeck.connect("grbl-plotter", emulator=True, simulated=True)
    try:
        job = tmp_path / "zigzag.gcode"
        job.write_text(
            "G21 G90\nM3 S1000\n"
            + "".join(f"G1 X{40 * (k % 2)} Y{k} F3000\n" for k in range(1, 30))
            + "M5\n",
            encoding="utf-8",
        )
        emulator = plotter.station.gcode_emulator
        assert emulator is not None
        messages: list[str] = []
        states: list[str] = []
        after: list[bytes] = []  # what the station wrote once the limit tripped

        def progress(p: stepdeck.Progress) -> None:
            states.append(p.state)
            if p.done >= 6 and "tripped" not in states:
                states.append("tripped")
                emulator.trigger_alarm(1)  # a limit switch, twice: it bounces
                emulator.trigger_alarm(1)
                plotter.station.link.dataSent.connect(after.append)

        with pytest.raises(stepdeck.JobFailed) as failed:
            plotter.run(
                job, on_progress=progress, on_message=messages.append, checkpoint_dir=tmp_path
            )
        assert "alarm 1" in str(failed.value)
        assert "reset" in str(failed.value)  # GRBL's lock: what clears it is said
        # Into GRBL's lock after a limit (ALARM:1) nothing of the job goes, nor a reset.
        assert [w for w in after if w != b"?"] == [], after
        assert len(said(messages, "alarm")) == 1, messages
        assert states[-1] == "failed"
        assert len(said(plotter.messages, "Machine alarm 1")) == 1, plotter.messages
    finally:
        plotter.close()
