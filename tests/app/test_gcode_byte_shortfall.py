"""Bytes lost inside a line still waiting in the CoreXY plotter's buffer: stopped before it runs.

Relay corexy-plotter seeds 6, 18, 42, 72, 174: bytes dropped inside a line on
its way turned it into a shorter valid line, which drew a wrong stroke.  The
board's ``Bf:`` shows fewer bytes than the lines written before the ``?`` must
leave in it (app/machines/gcode/byte_shortfall.py); the station stops then.
"""

from __future__ import annotations

from pathlib import Path

from hypothesis import given, settings
from hypothesis import strategies as st
from pytestqt.qtbot import QtBot

from app.jobs.run.runner import JobRunner, JobState
from app.machines.gcode.byte_shortfall import Held, QueryMarks, ShortfallWatch
from app.profiles import load_profile
from protocol.gcode.codec import StatusReport, decode
from protocol.transport.loopback import Direction
from tests.app.test_gcode_resume_proof import EXPECTED, pen_down_moves, run_as_the_api_does, zigzag
from tests.helpers.harness import StationHarness
from tests.helpers.wire_as_written import as_written


def _run_zigzag(qtbot: QtBot, tmp_path: Path, manipulator: object) -> tuple[JobState, list[str]]:
    profile = as_written(load_profile("corexy-plotter"))
    harness = StationHarness(profile)
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        if manipulator is not None:
            harness.loopback.set_manipulator(manipulator)  # type: ignore[arg-type]
        assert runner.load(zigzag(profile, tmp_path)) == []
        runner.start()
        run_as_the_api_does(harness, runner)
        harness.run(2.0)  # the board settles
        drawn = pen_down_moves(harness)
        whole = [d for d in drawn if d in EXPECTED]
        assert whole == EXPECTED[: len(whole)], drawn  # whole strokes of the job, in order
        for x, y in drawn[len(whole) :]:  # then at most the next one, cut short on its line
            assert y == EXPECTED[len(whole)][1] and 10.0 <= x <= 60.0, drawn
        if runner.state is JobState.DONE:
            assert pen_down_moves(harness) == EXPECTED, messages
        return runner.state, messages
    finally:
        runner.deleteLater()
        harness.close()


def test_a_line_that_lost_bytes_in_the_buffer_stops_the_plotter_before_it_runs(
    qtbot: QtBot, tmp_path: Path
) -> None:
    count = [0]

    def drop(direction: Direction, data: bytes) -> bytes:
        if direction is not Direction.TO_DEVICE or count[0] < 0:
            return data
        count[0] += data.lower().count(b"g1 ")
        if count[0] < 12:
            return data
        count[0] = -1  # once: the middle of the last G1 line written loses 5 bytes
        at = data.lower().rfind(b"g1 ")
        return data[: at + 4] + data[at + 9 :]

    state, messages = _run_zigzag(qtbot, tmp_path, drop)
    assert count[0] == -1
    assert state is JobState.FAILED, messages
    assert any("lost on the way inside a line" in m for m in messages), messages


def test_a_healthy_job_on_the_plotter_is_never_stopped_by_the_comparison(
    qtbot: QtBot, tmp_path: Path
) -> None:
    state, messages = _run_zigzag(qtbot, tmp_path, None)
    assert state is JobState.DONE, messages
    assert not any("lost on the way inside a line" in m for m in messages), messages


def _report(held: int, state: str = "Run") -> StatusReport:
    text = f"<{state}|MPos:0.000,0.000,0.000|FS:0,0|Bf:1,{128 - held}>\r\n".encode()
    report = decode(text)[1]
    assert isinstance(report, StatusReport)
    return report


def test_a_buffer_short_of_the_lines_it_must_hold_is_a_loss_a_tail_of_them_is_not() -> None:
    watch = ShortfallWatch(128)
    held = Held([20, 25, 30], 0)  # the oldest may be running: at least 55 bytes held
    assert watch.judge(_report(55), held) is None
    assert watch.judge(_report(75), held) is None
    assert watch.judge(_report(30), held) is None  # an OK lost on the way: whole lines gone
    assert watch.judge(_report(50), held) == 5
    assert Held([20, 25, 30], 12).short(42) is None  # a lost OK, 12 bytes written after the ?
    assert Held([20, 25, 30], 12).short(20) == 35
    assert Held([20], 40).short(0) is None  # one line only: it may be the one running
    assert watch.judge(_report(50), None) is None  # no ? to match: not judged


@settings(max_examples=400, deadline=None)
@given(
    lines=st.lists(st.integers(min_value=4, max_value=40), min_size=1, max_size=20),
    steps=st.lists(
        st.tuples(st.sampled_from("www??aaappddssrrr"), st.integers(1, 50)),
        min_size=60,
        max_size=300,
    ),
)
def test_a_healthy_board_is_never_short_wherever_the_query_falls(
    lines: list[int], steps: list[tuple[str, int]]
) -> None:
    """A model of the wire and of the CoreXY firmware's buffer: the station writes lines and
    ``?`` in any order; they arrive in order, any number of bytes at a time; the board parses
    a line once it is whole and the one before was answered, answers it once it ran, and
    reports its buffer at any time after a ``?`` arrived.  No single report is ever short."""
    marks = QueryMarks()
    sent = acked = 0  # the station's lines written and answered
    wire: list[str] = []  # on the way to the board: "b" a byte of a line, "?" a query
    received = parsed = 0  # the board's line bytes received, lines taken from its buffer
    running = wanted = False
    back: list[int | None] = []  # on the way back: None an OK, an int a report's held bytes
    judged = 0
    for kind, n in steps:
        if kind == "w" and sent < len(lines) and sum(lines[acked : sent + 1]) <= 127:
            wire.extend("b" * lines[sent])
            sent += 1
            marks.wrote(1)
        elif kind == "?":
            wire.append("?")
            marks.asked()
        elif kind == "a":
            for token in wire[:n]:
                wanted = wanted or token == "?"
                received += token == "b"
            del wire[:n]
        elif kind == "p" and not running and parsed < sent and received >= sum(lines[: parsed + 1]):
            parsed += 1
            running = True
        elif kind == "d" and running:
            running = False
            back.append(None)
        elif kind == "s" and wanted:
            wanted = False
            back.append(received - sum(lines[:parsed]))
        elif kind == "r" and back:
            item = back.pop(0)
            if item is None:
                acked += 1
                continue
            held = marks.seen(lines[acked:sent])
            if held is not None:
                judged += 1
                assert held.short(item) is None, (lines[acked:sent], item, held.before)
