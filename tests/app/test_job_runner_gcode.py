"""Jobs on the emulated CoreXY plotter: streamed, judged from ok and status, never skipped.

The emulator's event log is the judge: where it moved, with the pen up or
down, in which order.  The station runs on the harness's manual clock.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.gcode_stream import GcodeStream
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode.session import SentLine
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness

SQUARE = [(10.0, 10.0), (110.0, 10.0), (110.0, 110.0), (10.0, 110.0), (10.0, 10.0)]


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("corexy-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    yield harness
    harness.close()


@pytest.fixture
def runner(plotter: StationHarness, tmp_path: Path) -> Iterator[JobRunner]:
    built = JobRunner(plotter.station, tmp_path / "checkpoints")
    yield built
    built.deleteLater()


def at(line: int) -> SourceRef:
    return SourceRef("square", line)


def square_program(wait: bool = False) -> Program:
    """Pen up, to the first corner, pen down, round the square, pen up, home."""
    ops: list[Operation] = [Operation(OpKind.PEN_UP, at(1))]
    ops.append(move(at(2), X=SQUARE[0][0], Y=SQUARE[0][1]))
    ops.append(Operation(OpKind.PEN_DOWN, at(3)))
    for n, (x, y) in enumerate(SQUARE[1:], start=4):
        ops.append(move(at(n), X=x, Y=y))
    ops.append(Operation(OpKind.PEN_UP, at(8)))
    if wait:
        ops.append(Operation(OpKind.WAIT, at(9), message="change the pen"))
    ops.append(Operation(OpKind.COMMENT, at(10), message="back home"))
    ops.append(move(at(11), X=0.0, Y=0.0))
    return Program("square", tuple(ops))


def drawn(plotter: StationHarness) -> list[tuple[float, float, bool]]:
    """Every move the emulator finished: (x, y, pen down)."""
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3), bool(e["pen"]))
        for e in plotter.gcode_emulator.event_log
        if e["event"] == "move"
    ]


EXPECTED = [
    (10.0, 10.0, False),
    (110.0, 10.0, True),
    (110.0, 110.0, True),
    (10.0, 110.0, True),
    (10.0, 10.0, True),
    (0.0, 0.0, False),
]


def next_move_after(runner: JobRunner, moves_done: int) -> int:
    """The program's operation that makes move number ``moves_done`` (counted from 0)."""
    program = runner.program
    assert program is not None
    moves = [i for i, op in enumerate(program) if op.kind is OpKind.MOVE]
    return moves[moves_done]


def run_to_end(plotter: StationHarness, runner: JobRunner, timeout: float = 60.0) -> None:
    plotter.run_until(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), timeout
    )


def state_of(runner: JobRunner) -> JobState:
    return runner.state


def test_a_program_draws_in_order_with_the_pen_where_it_says(
    plotter: StationHarness, runner: JobRunner
) -> None:
    program = square_program()
    assert runner.load(program) == []
    runner.start()
    run_to_end(plotter, runner)
    assert runner.state is JobState.DONE
    assert drawn(plotter) == EXPECTED
    # Done means drawn: the machine stands at the last target, idle.
    assert plotter.gcode_emulator.state == "Idle"
    assert runner.done == len(program)
    written = b"".join(plotter.written)
    assert written.count(b"M4\n") == 1 and written.count(b"M3\n") == 2  # the plotter's pen


def test_a_long_program_streams_within_the_buffer_and_ends_when_drawn(
    plotter: StationHarness, runner: JobRunner
) -> None:
    ops = [Operation(OpKind.PEN_DOWN, at(1))]
    ops += [move(at(n + 2), X=10 + (n % 20) * 0.5, Y=10 + (n // 20) * 0.5) for n in range(300)]
    program = Program("zigzag", tuple(ops))
    assert runner.load(program) == []
    started: list[int] = []
    runner.operationStarted.connect(started.append)
    runner.start()
    most_in_flight = 0
    while runner.state is JobState.RUNNING:
        session = plotter.gcode_session
        most_in_flight = max(most_in_flight, session.streamer.in_flight)
        plotter.step()
    assert runner.state is JobState.DONE
    assert most_in_flight > 3  # several lines in the device at once: not ping-pong
    assert plotter.gcode_emulator.max_unacknowledged <= 127
    assert len(drawn(plotter)) == 300
    assert drawn(plotter)[-1] == (10 + 19 * 0.5, 10 + 14 * 0.5, True)
    # The dock is told the operation under way as the job goes (a few a second, in order).
    assert len(started) > 5 and started == sorted(started) and started[-1] > 250


def test_an_error_reply_stops_the_job_and_names_the_line(
    plotter: StationHarness, runner: JobRunner
) -> None:
    def spoil(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data.replace(b"G1 X110.000 Y110.000", b"G7 X110.000 Y110.000")
        return data

    plotter.loopback.set_manipulator(spoil)
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(square_program()) == []
    runner.start()
    run_to_end(plotter, runner)
    assert runner.state is JobState.FAILED
    failure = messages[-1]
    assert "square:5" in failure and "error:20" in failure, failure
    plotter.run(3.0)
    # Stopped there: the corner after it may have begun, the way home never ran.
    assert (0.0, 0.0, False) not in drawn(plotter)
    assert plotter.gcode_emulator.state in ("Idle", "Hold")
    assert runner.resume_available is not None and runner.resume_available <= 4


def test_a_cut_link_resumes_after_the_last_line_that_ran_nothing_twice(
    plotter: StationHarness, runner: JobRunner
) -> None:
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(square_program()) == []
    runner.start()
    plotter.run_until(lambda: len(drawn(plotter)) >= 2, timeout=20)  # drawing the square
    plotter.loopback.sever("cable pulled")
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
    plotter.run(8.0)  # the machine runs what it had planned, alone
    plotter.loopback.set_manipulator(None)
    plotter.run_until(lambda: plotter.station.model.link_state is LinkState.CONNECTED, timeout=30)
    runner.resume()
    run_to_end(plotter, runner)
    assert state_of(runner) is JobState.DONE
    assert any("every answered line ran" in m for m in messages), messages
    moves = drawn(plotter)
    # The way back to where it stopped is a pen-up travel; the drawing itself is exact.
    assert [m for m in moves if m[2]] == [m for m in EXPECTED if m[2]]
    assert moves[-1] == EXPECTED[-1]


@pytest.mark.parametrize("name", ["grbl-plotter", "corexy-plotter"])
def test_a_machine_that_lost_its_planner_unseen_lets_the_operator_pick_nothing_redrawn(
    qtbot: QtBot, tmp_path: Path, name: str
) -> None:
    """A reset while the cable is out (its banner lost): the board stopped mid-stroke and
    forgot what it had planned.  Where it stands fits no end of the lines sent, so what
    ran is not proven: the operator picks the line, the stroke it stopped in is offered,
    and resuming there draws every stroke once, none skipped."""
    plotter = StationHarness(load_profile(name))
    plotter.connect()
    plotter.run_until(lambda: plotter.gcode_session.planner_size > 0, timeout=1)
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program()) == []
        runner.start()
        emulator = plotter.gcode_emulator
        # Halfway up the square's second side.
        plotter.run_until(lambda: 30.0 < emulator.position()["Y"] < 90.0, timeout=20)
        plotter.loopback.sever("cable pulled")
        emulator.soft_reset()  # its banner goes nowhere
        plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        plotter.run_until(
            lambda: plotter.station.model.link_state is LinkState.CONNECTED, timeout=30
        )
        moves_before = len(drawn(plotter))
        runner.resume()
        plotter.run_until(lambda: runner.resume_choice is not None, timeout=10)
        assert runner.state is JobState.PAUSED
        assert len(drawn(plotter)) == moves_before  # nothing moved before the pick
        choice = runner.resume_choice
        assert choice is not None and choice.default is None  # strokes among the candidates
        # The stroke it stopped in (towards 110, 110) is one of them.
        program = runner.program
        assert program is not None
        in_progress = next(
            i for i, op in enumerate(program) if op.target == {"X": 110.0, "Y": 110.0}
        )
        assert in_progress in choice.candidates
        runner.resume()  # Resume alone does not pick for the operator
        assert runner.state is JobState.PAUSED
        runner.resume_at(in_progress)
        run_to_end(plotter, runner)
        assert state_of(runner) is JobState.DONE, messages
        strokes = [m for m in drawn(plotter) if m[2]]
        assert strokes == [m for m in EXPECTED if m[2]]  # each once, in order
    finally:
        runner.deleteLater()
        plotter.close()


def test_a_wait_asks_the_operator_only_once_the_machine_stands(
    plotter: StationHarness, runner: JobRunner
) -> None:
    asked: list[str] = []
    runner.waitingForOperator.connect(asked.append)
    assert runner.load(square_program(wait=True)) == []
    runner.start()
    plotter.run_until(lambda: runner.state is JobState.WAITING, timeout=30)
    assert asked == ["change the pen"]
    assert plotter.gcode_emulator.state == "Idle"
    assert drawn(plotter) == EXPECTED[:-1]  # the square is finished, home not begun
    plotter.run(1.0)
    assert drawn(plotter) == EXPECTED[:-1]
    runner.confirm()
    run_to_end(plotter, runner)
    assert runner.state is JobState.DONE
    assert drawn(plotter) == EXPECTED


def test_pause_lets_the_lines_out_finish_and_resume_carries_on(
    plotter: StationHarness, runner: JobRunner
) -> None:
    assert runner.load(square_program()) == []
    runner.start()
    plotter.run_until(lambda: runner.done >= 3, timeout=20)
    runner.pause()
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=20)
    paused_at = runner.done
    plotter.run(5.0)
    assert runner.done == paused_at
    runner.resume()
    run_to_end(plotter, runner)
    assert state_of(runner) is JobState.DONE
    assert drawn(plotter) == EXPECTED


def test_pause_stops_after_the_lines_the_device_has_not_the_ones_queued(
    plotter: StationHarness, runner: JobRunner
) -> None:
    ops = [Operation(OpKind.PEN_DOWN, at(1))]
    ops += [move(at(n + 2), X=10 + (n % 2) * 20, Y=10 + n * 0.5) for n in range(200)]
    program = Program("long", tuple(ops))
    assert runner.load(program) == []
    runner.start()
    plotter.run_until(lambda: runner.done >= 20, timeout=60)
    received = len([e for e in plotter.gcode_emulator.event_log if e["event"] == "line"])
    runner.pause()
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=20)
    # Only what the device held (its 128-byte buffer and its planner) ran: no line left
    # the station after the pause.
    plotter.run(5.0)
    lines = [e for e in plotter.gcode_emulator.event_log if e["event"] == "line"]
    assert len(lines) == received
    paused_at = runner.done
    assert paused_at <= received
    runner.resume()
    run_to_end(plotter, runner, timeout=400)
    assert state_of(runner) is JobState.DONE
    # Every move once, in order, across the pause.
    moves = drawn(plotter)
    assert [(x, y) for x, y, _ in moves] == [
        (10 + (n % 2) * 20, round(10 + n * 0.5, 3)) for n in range(200)
    ]


def test_the_winder_goes_back_one_axis_at_a_time_tool_radius_then_turn() -> None:
    from app.jobs.run.gcode_stream import ResumeState, preamble

    winder = load_profile("string-art").gcode
    plotter = load_profile("corexy-plotter").gcode
    assert winder is not None and plotter is not None
    state = ResumeState({"A": 370.0, "X": 120.0, "Z": 0.0}, pen_down=False)
    assert preamble(state, winder)[-3:] == ["G0 Z0.000", "G0 X120.000", "G0 A370.000"]
    drawing = ResumeState({"X": 10.0, "Y": 20.0}, pen_down=True, relative=True, feed=1200.0)
    assert preamble(drawing, plotter) == [
        "M3",
        "G90",
        "G0 X10.000 Y20.000",
        "M4",
        "G91",
        "F1200",
    ]


def test_the_way_back_retraces_the_path_from_where_the_machine_stopped() -> None:
    from app.jobs.run.gcode_stream import retrace

    # In at 10°, out, round to 30°, in: a winder's wrap in (A, X).
    ops = (
        move(at(1), A=10.0, X=60.0),
        move(at(2), X=70.0),
        move(at(3), A=30.0),
        move(at(4), X=60.0),
    )
    program = Program("wrap", ops)
    axes = ("A", "X")
    # Stopped half way round, the checkpoint at the move out: back round, then in.
    assert retrace(program, axes, 1, 4, (20.0, 70.0)) == [
        {"A": 10.0, "X": 70.0},
        {"A": 10.0, "X": 60.0},
    ]
    # Just past the corner: the turn has begun, so the way back is a turn first.
    assert retrace(program, axes, 1, 4, (10.00001, 70.0))[0] == {"A": 10.0, "X": 70.0}
    # Nowhere on that stretch (the machine was moved by hand): no way back is made up.
    assert retrace(program, axes, 1, 4, (50.0, 0.0)) == []


def test_step_sends_one_line_at_a_time(plotter: StationHarness, runner: JobRunner) -> None:
    assert runner.load(square_program()) == []
    runner.step()
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
    assert runner.done == 1  # the pen lifted, nothing moved
    assert drawn(plotter) == []
    runner.step()
    plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
    assert runner.done == 2
    plotter.run_until(lambda: plotter.gcode_emulator.state == "Idle", timeout=5)
    assert drawn(plotter) == EXPECTED[:1]  # to the first corner, pen up; no further
    plotter.run(2.0)
    assert drawn(plotter) == EXPECTED[:1]
    runner.resume()
    run_to_end(plotter, runner)
    assert state_of(runner) is JobState.DONE and drawn(plotter) == EXPECTED


@pytest.mark.parametrize("lost", [2, 6])  # an answer lost mid-job, and the last one
def test_a_lost_ok_does_not_stall_the_job_and_nothing_is_drawn_twice(
    qtbot: QtBot, tmp_path: Path, lost: int
) -> None:
    grbl = StationHarness(load_profile("grbl-plotter"))
    grbl.connect()
    grbl.run_until(lambda: grbl.gcode_session.planner_size > 0, timeout=2)
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    grbl.station.model.message.connect(messages.append)
    oks = [0]

    def lose_one_ok(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_HOST and b"ok" in data:
            oks[0] += data.count(b"ok")
            if oks[0] >= lost and data.count(b"ok\r\n") and oks[0] - data.count(b"ok") < lost:
                return data.replace(b"ok\r\n", b"", 1)
        return data

    try:
        program = square_program()
        assert runner.load(program) == []
        grbl.loopback.set_manipulator(lose_one_ok)
        runner.start()
        grbl.run_until(lambda: runner.state is not JobState.RUNNING, timeout=60)
        assert runner.state is JobState.DONE
        assert any("lost on the way" in m for m in messages)
        assert drawn(grbl) == EXPECTED
    finally:
        grbl.close()


def _stream_through(text: str, tmp_path: Path, answered: int) -> GcodeStream:
    """A GRBL job whose first ``answered`` lines went out and came back ok."""
    profile = load_profile("grbl-plotter")
    source = tmp_path / "job.gcode"
    source.write_text(text, encoding="utf-8")
    program = load_job(source, ["X", "Y"], JobOptions(gcode=profile.gcode))
    stream = GcodeStream(program, profile, 0)
    for index in range(answered):
        stream.pending.append(index)
        stream.next_index = index + 1
        assert stream.acknowledge(SentLine(index + 1, program[index].line, "job", index))
    stream.status("Run", None, 0, (0.0, 0.0))  # the answers are before the next report
    return stream


def test_without_bf_the_executed_boundary_follows_where_the_board_stands(
    tmp_path: Path,
) -> None:
    """G8-02: a board reporting no ``Bf:`` (``$10=1``) still shows what has run.

    Without it the boundary stayed at the start until the board stood idle, so a
    resume after a lost link redrew everything since (313 pen-down moves on the
    Unicorn file).
    """
    lines = ["G90 G21", *(f"G1 X{10 * k} Y0 F3000" for k in range(1, 9))]
    stream = _stream_through("\n".join(lines) + "\n", tmp_path, 9)
    assert stream.executed == 0
    stream.status("Run", None, 0, (45.0, 0.0))  # halfway along X40 → X50: line 6
    assert stream.executed == 5  # operations 0-4 ran; the one under way has not
    stream.status("Run", None, 0, (41.0, 3.0))  # off the path: proves nothing more
    assert stream.executed == 5
    stream.status("Run", None, 0, (75.0, 0.0))
    assert stream.executed == 8


def test_without_bf_a_path_that_comes_back_makes_the_boundary_lag_never_lead(
    tmp_path: Path,
) -> None:
    lines = ["G90 G21", "G0 X0 Y0", "G1 X20 Y0 F3000", "G1 X0 Y0", "G1 X20 Y0", "G1 X20 Y10"]
    stream = _stream_through("\n".join(lines) + "\n", tmp_path, 6)
    stream.status("Run", None, 0, (10.0, 0.0))  # on the way out, back, or out again
    assert stream.executed == 2  # the earliest: nothing it cannot prove


@pytest.mark.parametrize("name", ["grbl-plotter", "corexy-plotter"])
def test_a_board_that_resets_itself_mid_job_pauses_until_the_operator_resumes(
    qtbot: QtBot, tmp_path: Path, name: str
) -> None:
    """A reset nobody here sent (the board's reset button, how many GRBL machines are
    stopped by hand, or a power dip) must not be followed by the station moving the
    machine again on its own: the job pauses; Resume looks and carries on, nothing skipped."""
    plotter = StationHarness(load_profile(name))
    plotter.connect()
    plotter.run_until(lambda: plotter.gcode_session.planner_size > 0, timeout=1)
    runner = JobRunner(plotter.station, tmp_path / "checkpoints")
    try:
        messages: list[str] = []
        runner.message.connect(messages.append)
        assert runner.load(square_program()) == []
        runner.start()
        plotter.run_until(lambda: len(drawn(plotter)) >= 2, timeout=20)  # drawing the square
        plotter.gcode_emulator.soft_reset()  # its own reset: the link stays up
        plotter.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
        plotter.run(1.0)
        assert len(messages) == 1 and "restarted" in messages[0], messages  # said once
        assert runner.needs_operator
        assert plotter.station.model.link_state is LinkState.CONNECTED
        moves_when_paused = len(drawn(plotter))
        sent_when_paused = len(plotter.written)
        plotter.run(3.0)
        assert len(drawn(plotter)) == moves_when_paused  # nothing moved on its own
        job_lines = [w for w in plotter.written[sent_when_paused:] if w.strip() not in (b"?", b"")]
        assert job_lines == []  # and nothing but status questions went out
        runner.resume()  # not without a pick: the operator homed it or checked it, and picks
        assert runner.state is JobState.PAUSED
        choice = runner.resume_choice
        assert choice is not None and choice.position_lost
        assert len(drawn(plotter)) == moves_when_paused
        # The operator looks at the paper: the strokes drawn so far are there.
        pick = next_move_after(runner, len(drawn(plotter)))
        assert pick in choice.candidates
        runner.resume_at(pick)
        run_to_end(plotter, runner)
        assert runner.state is JobState.DONE
        strokes = [m for m in drawn(plotter) if m[2]]
        assert strokes == [m for m in EXPECTED if m[2]]  # each once, none skipped
    finally:
        runner.deleteLater()
        plotter.close()
