"""GRBL's lock after a hard or soft limit, as the station lives with it (manual clock).

GRBL 1.1h (protocol.c, ``EXEC_CRITICAL_EVENT``) says ``ALARM:1``/``ALARM:2`` and
``[MSG:Reset to continue]``, then answers nothing, not even ``?``, until a 0x18;
after it, still in alarm.  The station must not take that silence for a lost link,
must reset before it unlocks (a ``$X`` sent into the lock is lost), and nothing may
move: neither the reset nor ``$X`` moves an axis, and a job the alarm paused stays
paused.
"""

from __future__ import annotations

from pathlib import Path

from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode import timing
from app.machines.gcode.limit_lock import waiting_text
from tests.app.test_gcode_alarm_once import plotter
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import square_program

__all__ = ["plotter"]  # the fixture, used by name


def events(harness: StationHarness, kind: str) -> list[dict[str, object]]:
    return [dict(e) for e in harness.gcode_emulator.event_log if e["event"] == kind]


def test_a_board_locked_after_a_limit_is_shown_in_alarm_not_lost(plotter: StationHarness) -> None:
    model = plotter.station.model
    states: list[LinkState] = []
    model.linkStateChanged.connect(states.append)
    messages: list[str] = []
    model.message.connect(messages.append)
    plotter.gcode_emulator.trigger_alarm(2)
    plotter.run(3 * timing.SILENCE_S)  # far past what a silent board is given
    assert plotter.gcode_session.limit_lock.waiting
    assert model.link_state is LinkState.CONNECTED and model.link_detail == waiting_text()
    assert LinkState.LOST not in states and LinkState.STALE not in states, states
    assert not [m for m in messages if "silent" in m], messages
    assert plotter.station.link.is_open  # nothing reopened
    # The reset ends the lock: the board answers again, still in alarm; the link as before.
    plotter.gcode_session.limit_lock.reset()
    plotter.run_until(lambda: plotter.gcode_session.machine_state == "Alarm", timeout=2)
    assert not plotter.gcode_session.limit_lock.waiting
    assert model.link_detail == plotter.station.link.describe()


def test_a_board_that_says_alarm_1_and_answers_on_is_not_waited_for(
    plotter: StationHarness,
) -> None:
    """Another firmware's ALARM:1 without GRBL's lock: its next status report ends the wait,
    so a board that then falls silent is still found lost."""
    session = plotter.gcode_session
    session.receive_injected(b"ALARM:1\r\n")
    assert session.limit_lock.waiting
    plotter.run(0.5)  # the emulated board (not locked) answers its status queries
    assert not session.limit_lock.waiting


def test_unlock_resets_first_and_sends_x_after_the_banner_nothing_moves(
    plotter: StationHarness,
) -> None:
    emulator = plotter.gcode_emulator
    assert plotter.gcode_session.send_line("G0 X20 Y10", "intent")
    plotter.run_until(lambda: emulator.position() == {"X": 20.0, "Y": 10.0, "Z": 0.0}, timeout=10)
    plotter.run(0.3)
    emulator.trigger_alarm(1)
    plotter.run(1.0)
    moved = len(events(plotter, "move"))
    written = len(plotter.written)
    assert plotter.gcode_session.limit_lock.unlock()
    plotter.run_until(lambda: len(events(plotter, "unlock")) == 1, timeout=3)
    plotter.run_until(lambda: plotter.gcode_session.machine_state == "Idle", timeout=3)
    sent = [w for w in plotter.written[written:] if w != b"?"]
    assert sent == [b"\x18", b"$X\n"], sent  # the reset, then $X once its banner came
    kinds = [e["event"] for e in emulator.event_log if e["event"] in ("reset", "line")]
    assert kinds[-2:] == ["reset", "line"]  # on the board too: the reset, then the line
    assert [e["text"] for e in events(plotter, "line")][-1] == "$X"
    assert len(events(plotter, "move")) == moved  # neither the reset nor $X moved anything
    assert emulator.position() == {"X": 20.0, "Y": 10.0, "Z": 0.0}


def test_a_job_paused_by_a_hard_limit_stays_paused_through_reset_and_unlock(
    plotter: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    try:
        assert runner.load(square_program()) == []
        runner.start()
        plotter.run_until(lambda: len(events(plotter, "move")) >= 2, timeout=30)
        plotter.gcode_emulator.trigger_alarm(1)
        plotter.run(3 * timing.SILENCE_S)
        assert runner.state is JobState.PAUSED and runner.needs_operator
        assert plotter.station.model.link_state is LinkState.CONNECTED
        assert not plotter.station.model.any_moving  # stopped, not "run" as last reported
        moved = len(events(plotter, "move"))
        written = len(plotter.written)
        runner.resume()  # into the lock: no report would ever come, so it says so and waits
        plotter.run(2.0)
        assert runner.state is JobState.PAUSED and runner.needs_operator
        assert [w for w in plotter.written[written:] if w != b"?"] == []
        assert plotter.gcode_session.limit_lock.unlock()
        plotter.run_until(lambda: len(events(plotter, "unlock")) == 1, timeout=3)
        plotter.run(2.0)
        assert plotter.gcode_session.machine_state == "Idle"
        assert runner.state is JobState.PAUSED  # the operator resumes it, nobody else
        sent = [w for w in plotter.written[written:] if w != b"?"]
        assert sent == [b"\x18", b"$X\n"], sent  # nothing of the job
        assert len(events(plotter, "move")) == moved
    finally:
        runner.deleteLater()
