"""A resumed G-code job waits until the board stands: no line goes while it still runs old ones.

The race the issue saw once under load (corexy-plotter, cable pulled): the
board finished a stroke, answered it, and in that same control cycle made
the status report the resume had asked for.  The next line it had been sent
before the pull was still in its receive buffer, not yet parsed, so the
report said ``Idle``.  The station took that for a board standing, sent its
way back, and the board ran the old lines first: strokes drawn twice, or
supervision stopping the job.

Here the race is made on the harness's manual clock, one control cycle per
step: the board is asked for its status every cycle, and the cable loses
every report but the one made in such a cycle.  The emulator's log judges.
"""

from __future__ import annotations

import re
from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.jobs.run.standing import Standing, StandingProof
from app.machine import LinkState
from app.profiles import load_profile
from protocol.gcode.codec import StatusReport
from protocol.transport.loopback import Direction
from tests.app.test_gcode_resume_proof import EXPECTED, pen_down_moves, run_as_the_api_does, zigzag
from tests.helpers.harness import StationHarness

#: One control cycle of the emulated boards (GcodeConfig.control_cycle).
CYCLE_S = 0.005
_REPORT = re.compile(rb"<[^>]*>\r?\n?")


def _between_lines(report: bytes, rx_buffer: int) -> bool:
    """A report of a board idle with a line still unparsed in its receive buffer."""
    text = report.decode("ascii", "replace")
    bf = re.search(r"\|Bf:(\d+),(\d+)", text)
    return text.startswith("<Idle") and bf is not None and int(bf.group(2)) < rx_buffer - 1


def test_a_resume_waits_for_a_board_that_still_has_lines_it_was_sent_before_the_pull(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """(The emulated GRBL board parses a line as soon as its planner has room, so it never
    says Idle with a line unparsed: only the CoreXY plotter shows the gap.)"""
    profile = load_profile("corexy-plotter")
    settings = profile.gcode
    assert settings is not None
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    emulator = harness.gcode_emulator
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        harness.run_until(lambda: len(pen_down_moves(harness)) >= 3, 60)
        # Pulled just after the board has been sent the next stroke's lines.
        harness.run_until(lambda: emulator.unacknowledged > 20, 10)
        harness.loopback.sever("cable pulled")
        harness.run_until(
            lambda: (
                runner.state is JobState.PAUSED
                and harness.station.model.link_state is LinkState.CONNECTED
            ),
            10,
        )
        assert emulator.unacknowledged > 0, "the board ran out before the resume"
        seen: list[bytes] = []

        def only_a_report_between_lines(direction: Direction, data: bytes) -> bytes:
            if direction is not Direction.TO_HOST or seen:
                return data

            def keep(match: re.Match[bytes]) -> bytes:
                if not seen and _between_lines(match.group(0), settings.rx_buffer):
                    seen.append(match.group(0))
                    return match.group(0)
                return b""

            return _REPORT.sub(keep, data)

        harness.loopback.set_manipulator(only_a_report_between_lines)
        runner.resume()
        start = harness.clock.now()
        while not seen:
            assert harness.clock.now() - start < 30, "no report was made between two lines"
            assert emulator.unacknowledged > 0, "the board ran out of lines without a gap"
            emulator.receive(b"?")  # asked every control cycle
            harness.step(CYCLE_S)
        harness.loopback.set_manipulator(None)
        run_as_the_api_does(harness, runner)
        assert runner.state is JobState.DONE, messages
        assert pen_down_moves(harness) == EXPECTED, messages  # each stroke once, in order
    finally:
        runner.deleteLater()
        harness.close()


def _report(state: str, x: float, bf: tuple[int, int] | None) -> StatusReport:
    planner, rx = bf if bf is not None else (None, None)
    return StatusReport(state, (x, 5.0, 0.0), 0.0, 0.0, planner, rx)


def test_idle_proves_standing_only_with_the_planner_and_the_buffer_empty() -> None:
    proof = StandingProof()
    assert proof.judge(_report("Run", 1.0, (15, 128)), 15, 128) is Standing.BUSY
    assert proof.judge(_report("Idle", 1.0, (15, 100)), 15, 128) is Standing.BUSY  # a line waits
    assert proof.judge(_report("Idle", 1.0, (14, 128)), 15, 128) is Standing.BUSY  # a block waits
    assert proof.judge(_report("Idle", 1.0, (15, 127)), 15, 128) is Standing.STANDS


def test_without_buffer_figures_a_second_idle_report_at_the_same_place_proves_it() -> None:
    """A fresh GRBL board ($10=1) reports no Bf: a line left in its buffer would be parsed
    before the next report, which then shows Run or another place."""
    proof = StandingProof()
    assert proof.judge(_report("Idle", 1.0, None), 0, 128) is Standing.ASK_AGAIN
    assert proof.judge(_report("Idle", 2.0, None), 0, 128) is Standing.ASK_AGAIN  # it moved
    assert proof.judge(_report("Run", 2.0, None), 0, 128) is Standing.BUSY
    assert proof.judge(_report("Idle", 2.0, None), 0, 128) is Standing.ASK_AGAIN  # after Run
    assert proof.judge(_report("Idle", 2.0, None), 0, 128) is Standing.STANDS
    proof.forget()
    assert proof.judge(_report("Idle", 2.0, None), 0, 128) is Standing.ASK_AGAIN
