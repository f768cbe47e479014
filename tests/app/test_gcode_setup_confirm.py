"""A set-up whose confirmation never comes does not hold the job for good.

Relay grbl-plotter seed 168: 7 bytes dropped at byte 11 took ``\\n$G\\n`` from
the job's set-up.  ``G90 G21 G17`` stayed unended in GRBL's line buffer
(``Bf:`` cannot show it there), the two answers were taken for lost ones, and
the job waited for the ``[GC:…]`` of a ``$G`` the board never had: hung.
"""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from protocol.transport.loopback import Direction, Manipulator
from tests.app.test_gcode_resume_proof import (
    EXPECTED,
    pen_down_moves,
    run_as_the_api_does,
    zigzag,
)
from tests.helpers.harness import StationHarness
from tests.helpers.pen_square import SQUARE, square_program

REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))


def lose_line_bytes(first: int, last: int, dropped: bytearray) -> Manipulator:
    """Drop the line bytes ``first…last`` (1-based, real-time bytes not counted) to the board."""
    lines_bytes = 0

    def manipulate(direction: Direction, data: bytes) -> bytes:
        nonlocal lines_bytes
        if direction is not Direction.TO_DEVICE:
            return data
        kept = bytearray()
        for byte in data:
            if byte not in REALTIME:
                lines_bytes += 1
                if first <= lines_bytes <= last:
                    dropped.append(byte)
                    continue
            kept.append(byte)
        return bytes(kept)

    return manipulate


def test_a_set_up_cut_before_any_line_of_a_job_that_ends_home_goes_on_without_asking(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """Standing where it began, a plot that ends there could be done or not begun; but no
    line of it went, so nothing of it ran: no question (the relay's run asked for a pick
    among 30 operations 'sent but not proven run', none of them sent)."""
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dropped = bytearray()
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.loopback.set_manipulator(lose_line_bytes(12, 15, dropped))
        assert runner.load(square_program(back_home=True)) == []
        runner.start()
        run_as_the_api_does(harness, runner, timeout=60)
        assert bytes(dropped) == b"\n$G\n"
        assert runner.resume_choice is None and runner.state is JobState.DONE, messages
        drawn = [
            (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
            for e in harness.gcode_emulator.event_log
            if e["event"] == "move" and e["pen"]
        ]
        assert drawn == SQUARE[1:]
    finally:
        runner.deleteLater()
        harness.close()


def test_a_set_up_cut_on_the_wire_is_sent_again_and_the_job_draws_each_stroke_once(
    qtbot: QtBot, tmp_path: Path
) -> None:
    profile = load_profile("grbl-plotter")
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dropped = bytearray()
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        harness.station.model.message.connect(messages.append)
        # The set-up's end and its $G: the line bytes 12…15 on the way to the board.
        harness.loopback.set_manipulator(lose_line_bytes(12, 15, dropped))
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        run_as_the_api_does(harness, runner, timeout=60)
        assert bytes(dropped) == b"\n$G\n"
        assert runner.state is JobState.DONE, messages
        assert pen_down_moves(harness) == EXPECTED, messages  # none twice, none skipped
    finally:
        runner.deleteLater()
        harness.close()
