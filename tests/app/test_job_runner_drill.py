"""Excellon jobs on the emulated PCB drill: every hole once, where the file says, in time.

The station runs on the harness's manual clock against the drill firmware
emulator, so the emulator's logs are the judge: each hole of the sample EAGLE
board drilled exactly once at the microsteps the host computes (mm x 19.8 / 19.7,
half away from zero), also when the link is cut in the middle of the job.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.estimate.drill import DRILL_CYCLE_S, FIRST_DRILL_CYCLE_S, estimate_drill
from app.jobs.formats.excellon.reader import DrillMode, build_drill_program, read_drill_file
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.registration import Registration, register, registered
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from protocol.drill.codec import DRILL, Command
from protocol.transport.loopback import Direction, Manipulator
from tests.helpers.harness import StationHarness

X, Y = 0, 1
SAMPLE_HOLES = 36  # the sample EAGLE board: T01 20 holes, then the larger tools


@pytest.fixture
def drill(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("pcb-drill"))
    harness.connect()
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)
    # Home first, so the step counters count from the machine's zero as the model does.
    assert harness.drill_session.home(X)
    harness.run_until(lambda: not harness.drill_session.busy, timeout=60)
    assert harness.drill_emulator.positions[:2] == (0, 0)
    yield harness
    harness.close()


@pytest.fixture
def runner(drill: StationHarness, tmp_path: Path) -> Iterator[JobRunner]:
    built = JobRunner(drill.station, tmp_path / "checkpoints")
    yield built
    built.deleteLater()


def sample_program(data_dir: Path, mode: DrillMode = "drill") -> Program:
    job = read_drill_file(data_dir / "samples/pcb-driver/driver")
    return build_drill_program(job, mode=mode)


def expected_holes(drill: StationHarness, program: Program) -> Counter[tuple[int, int]]:
    """Microsteps of the MOVE before each DRILL, as the host rounds them."""
    session = drill.drill_session
    holes: Counter[tuple[int, int]] = Counter()
    for before, op in zip(program.operations, program.operations[1:], strict=False):
        if op.kind is OpKind.DRILL:
            assert before.kind is OpKind.MOVE
            holes[
                (
                    session.to_microsteps(X, before.target["X"]),
                    session.to_microsteps(Y, before.target["Y"]),
                )
            ] += 1
    return holes


def drilled(drill: StationHarness) -> Counter[tuple[int, int]]:
    return Counter((hole.x, hole.y) for hole in drill.drill_emulator.drill_log)


def auto_confirm(runner: JobRunner) -> list[str]:
    """Record every WAIT message; the test confirms it at its next step."""
    asked: list[str] = []
    runner.waitingForOperator.connect(asked.append)
    return asked


def run_to_end(drill: StationHarness, runner: JobRunner, timeout: float = 400.0) -> None:
    def over() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED, JobState.PAUSED)

    drill.run_until(over, timeout=timeout)


def test_the_sample_board_is_drilled_every_hole_once_where_the_file_says_within_the_eta(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir)
    assert runner.load(program) == []
    assert runner.progress.estimate is not None
    eta = runner.progress.estimate.total_s
    asked = auto_confirm(runner)
    runner.start()
    run_to_end(drill, runner)

    assert runner.state is JobState.DONE
    assert runner.done == len(program)
    waits = [op.message for op in program if op.kind is OpKind.WAIT]
    assert asked == waits and asked[0].startswith("insert T01, 0.80 mm")
    expected = expected_holes(drill, program)
    assert sum(expected.values()) == SAMPLE_HOLES
    assert drilled(drill) == expected
    assert all(count == 1 for count in drilled(drill).values())
    # The first hole of the file: X 25.654 mm, Y 11.684 mm.
    assert (round(25.654 * 19.8), round(11.684 * 19.7)) in expected
    # At least the drill cycles themselves, and the model's time within 5 % of the run's.
    assert eta > SAMPLE_HOLES * DRILL_CYCLE_S
    print(f"drill: ETA {eta:.2f} s, emulated {runner.progress.running_s:.2f} s")
    assert runner.progress.running_s == pytest.approx(eta, rel=0.05)


def test_s2_12_a_drawn_job_draws_on_the_machine_what_its_preview_shows(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir, "draw")
    assert runner.load(program) == []
    assert runner.progress.estimate is not None
    eta = runner.progress.estimate.total_s
    auto_confirm(runner)
    runner.start()
    run_to_end(drill, runner)

    assert runner.state is JobState.DONE
    session = drill.drill_session
    bits = sum(op.kind is OpKind.WAIT for op in program)
    pen = drill.drill_emulator.pen_log
    assert [e.down for e in pen] == [True, False] * bits  # Kresli, Zvedni per bit
    # The preview's pen-down segments (the program's path), in the machine's microsteps ...
    path = program.preview_path("X", "Y")
    steps = [(session.to_microsteps(X, x), session.to_microsteps(Y, y)) for x, y in path.coords]
    previewed = [(*steps[i - 1], *steps[i]) for i in range(1, len(steps)) if path.pen[i]]
    # ... are the strokes the pen drew on the machine, one for one, in order.
    drawn = [(s.x0, s.y0, s.x1, s.y1) for s in drill.drill_emulator.drawing]
    assert len(drawn) > SAMPLE_HOLES - 2 * bits
    assert drawn == [seg for seg in previewed if seg[:2] != seg[2:]]
    assert drill.drill_emulator.drill_log == ()
    assert not drill.drill_emulator.pen_down
    print(f"draw: ETA {eta:.2f} s, emulated {runner.progress.running_s:.2f} s")
    assert runner.progress.running_s == pytest.approx(eta, rel=0.05)


def test_cross_mode_puts_the_pen_down_at_both_arms_of_every_cross(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir, "cross")
    assert runner.load(program) == []
    assert runner.progress.estimate is not None
    eta = runner.progress.estimate.total_s
    auto_confirm(runner)
    runner.start()
    run_to_end(drill, runner)

    assert runner.state is JobState.DONE
    session = drill.drill_session
    expected = Counter(
        (session.to_microsteps(X, before.target["X"]), session.to_microsteps(Y, before.target["Y"]))
        for before, op in zip(program.operations, program.operations[1:], strict=False)
        if op.kind is OpKind.PEN_DOWN
    )
    downs = Counter((e.x, e.y) for e in drill.drill_emulator.pen_log if e.down)
    ups = [e for e in drill.drill_emulator.pen_log if not e.down]
    assert sum(downs.values()) == 2 * SAMPLE_HOLES and len(ups) == 2 * SAMPLE_HOLES
    assert downs == expected
    assert drill.drill_emulator.drill_log == ()
    assert not drill.drill_emulator.pen_down
    print(f"draw: ETA {eta:.2f} s, emulated {runner.progress.running_s:.2f} s")
    assert runner.progress.running_s == pytest.approx(eta, rel=0.05)


def test_the_dry_run_times_moves_axis_after_axis_at_the_step_periods() -> None:
    profile = load_profile("pcb-drill")
    where = SourceRef("t.drl", 1)
    program = Program(
        "t",
        (
            move(where, X=10.0, Y=20.0),  # 198 X microsteps, 394 Y microsteps
            Operation(OpKind.DRILL, where),
            Operation(OpKind.DRILL, where),
            Operation(OpKind.PEN_DOWN, where),
            Operation(OpKind.WAIT, where, message="tool"),
        ),
    )
    estimate = estimate_drill(program, profile, overhead_s=0.0)
    assert estimate.cumulative_s[0] == pytest.approx(198 * 0.0013 + 394 * 0.0015)
    # FIDELITY S2-22/S2-23, by hand: the first V comes 412 microsteps down from the top at
    # 2.5 ms with 10 ms after every second one (1.03 + 2.06 s), waits 0.1 s, returns 39
    # full steps (0.0975 s) and waits 0.1 s: 3.3875 s.  Later ones start 78 microsteps up:
    # 0.195 + 0.39 + 0.1 + 0.0975 + 0.1 = 0.8825 s.
    assert estimate.cumulative_s[1] - estimate.cumulative_s[0] == pytest.approx(3.3875)
    assert estimate.cumulative_s[2] - estimate.cumulative_s[1] == pytest.approx(0.8825)
    # K is V's way down (S2-24), from the hover: 0.195 + 0.39 + 0.1 s.
    assert estimate.cumulative_s[3] - estimate.cumulative_s[2] == pytest.approx(0.685)
    # Then the park at X 0, Y 150 mm (the profile's): X back 198, Y on 2955 - 394 microsteps.
    park = 198 * 0.0013 + (2955 - 394) * 0.0015
    assert estimate.total_s == pytest.approx(estimate.cumulative_s[3] + park)
    homing = estimate_drill(program, profile, overhead_s=0.0, home_first=True)
    # From 0: to each switch (offset + 1), off it (1) and the offset again.
    home = (3 + 1 + 1 + 3) * 0.0013 + (86 + 1 + 1 + 86) * 0.0015
    assert homing.total_s == pytest.approx(estimate.total_s + home)


def test_s2_24_the_estimate_times_kresli_and_zvedni_as_the_halves_of_vrtat() -> None:
    profile = load_profile("pcb-drill")
    where = SourceRef("t.drl", 1)
    pen = [Operation(OpKind.PEN_DOWN, where), Operation(OpKind.PEN_UP, where)]
    program = Program("t", (*pen, *pen, Operation(OpKind.DRILL, where)))
    steps = estimate_drill(program, profile, overhead_s=0.0).cumulative_s
    times = [b - a for a, b in zip((0.0, *steps), steps, strict=False)]
    # The first K from the top of Z: 412 microsteps at 2.5 ms, 206 pauses of 10 ms, 0.1 s.
    # Z: 39 full steps at 2.5 ms and 0.1 s.  Then K from the hover (78 microsteps), and a
    # V from where Z left the pen: a later stroke.
    assert times == pytest.approx([3.19, 0.1975, 0.685, 0.1975, 0.8825])
    assert times[2] + times[3] == pytest.approx(times[4])


def state_of(runner: JobRunner) -> JobState:
    """The state now (a call, so a type checker does not keep an earlier assertion's value)."""
    return runner.state


def reconnect(drill: StationHarness) -> None:
    drill.loopback.set_manipulator(None)
    drill.run_until(lambda: drill.station.model.link_state is LinkState.CONNECTED, timeout=60)


def test_a_link_cut_during_a_received_drill_cycle_resumes_without_drilling_it_again(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir)
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(program) == []
    runner.start()

    fifth_drill = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL][4]

    def in_fifth_drill() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return (
            runner.current_index == fifth_drill
            and len(drill.drill_emulator.drill_log) == 4
            and drill.drill_emulator.positions[2] > 0  # Z is on its way down: RV is out
        )

    drill.run_until(in_fifth_drill, timeout=200)
    index = fifth_drill
    drill.run(0.01)  # the RV reaches the station
    drill.loopback.sever("cable pulled")
    drill.run_until(lambda: runner.state is JobState.PAUSED)
    assert runner.done == index and runner.current_index == index
    reconnect(drill)
    drill.run(2.0)  # the machine finishes the cycle it had received on its own
    assert len(drill.drill_emulator.drill_log) == 5
    assert runner.state is JobState.PAUSED  # nothing resumes without the operator

    runner.resume()
    run_to_end(drill, runner)
    assert state_of(runner) is JobState.DONE
    assert any("counted as done" in m for m in messages)
    assert drilled(drill) == expected_holes(drill, program)
    assert len(drill.drill_emulator.drill_log) == SAMPLE_HOLES


def test_a_drill_command_lost_with_the_link_is_the_operators_call_and_a_move_is_repeated(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """A V that went out unacknowledged may have drilled: the operator, not the runner, decides."""
    program = sample_program(data_dir)
    drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]
    moves = [i for i, op in enumerate(program) if op.kind is OpKind.MOVE]
    cut_at = {drills[3], moves[10]}  # a V that never arrives, then an X/Y that may not

    def cable_gone(direction: Direction, data: bytes) -> bytes:
        return b""

    def cut(index: int) -> None:
        if index in cut_at:
            cut_at.discard(index)
            drill.loopback.set_manipulator(cable_gone)

    runner.operationStarted.connect(cut)
    asked: list[tuple[int | None, str]] = []
    runner.decisionNeeded.connect(lambda question, *_: asked.append((runner.question, question)))
    assert runner.load(program) == []
    runner.start()
    paused: list[int] = []
    for _ in range(2):

        def cut_made() -> bool:
            if runner.state is JobState.WAITING:
                runner.confirm()
            return drill.loopback._manipulator is not None

        drill.run_until(cut_made, timeout=200)
        drill.run(0.05)
        drill.loopback.sever("cable pulled")
        drill.run_until(lambda: runner.state is JobState.PAUSED)
        paused_at = runner.current_index
        assert paused_at is not None and runner.done == paused_at
        paused.append(paused_at)
        reconnect(drill)
        runner.resume()
        if asked and runner.question is not None:
            runner.resume()  # refused: the question stands
            assert runner.state is JobState.PAUSED
            runner.decide(again=True)  # the operator sees no hole there
    run_to_end(drill, runner)
    assert paused == [drills[3], moves[10]]
    assert [index for index, _ in asked] == [drills[3]]  # the move was simply sent again
    assert str(program[drills[3]].source) in asked[0][1]
    assert runner.state is JobState.DONE
    assert drilled(drill) == expected_holes(drill, program)
    assert len(drill.drill_emulator.drill_log) == SAMPLE_HOLES
    sent_v = [c for c in drill.drill_emulator.command_log if c.command == Command("V")]
    assert len(sent_v) == SAMPLE_HOLES  # the lost V never reached the machine


def test_a_lost_receipt_is_not_a_reason_to_drill_twice(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """The drill took the V, but its RV and DV never came back: asked, then counted as drilled."""
    program = sample_program(data_dir)
    drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]
    target = drills[6]

    def replies_lost(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_HOST else data

    def lose_replies(index: int) -> None:
        if index == target:
            drill.loopback.set_manipulator(replies_lost)

    runner.operationStarted.connect(lose_replies)
    asked: list[int | None] = []
    runner.decisionNeeded.connect(lambda *_: asked.append(runner.question))
    assert runner.load(program) == []
    runner.start()

    def v_taken() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return len(drill.drill_emulator.drill_log) == 7

    drill.run_until(v_taken, timeout=300)
    drill.loopback.sever("cable pulled")
    drill.run_until(lambda: runner.state is JobState.PAUSED)
    reconnect(drill)
    drill.run(2.0)
    runner.resume()
    assert asked == [target] and runner.state is JobState.PAUSED
    assert len(drill.drill_emulator.drill_log) == 7  # nothing sent while the question stands

    runner.decide(again=False)  # the operator sees the hole
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert drilled(drill) == expected_holes(drill, program)
    assert len(drill.drill_emulator.drill_log) == SAMPLE_HOLES


def test_a_restarted_station_asks_about_the_checkpoints_next_hole(
    drill: StationHarness, data_dir: Path, tmp_path: Path
) -> None:
    """After a crash nothing is known of the last V: the operator is asked, nothing is sent."""
    program = sample_program(data_dir)
    drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]
    first = JobRunner(drill.station, tmp_path / "checkpoints")
    assert first.load(program) == []
    first.start()

    def at_third_drill() -> bool:
        if first.state is JobState.WAITING:
            first.confirm()
        return first.done == drills[2]

    drill.run_until(at_third_drill, timeout=300)
    first.deleteLater()  # the station died here, its V perhaps on the wire
    sent: list[object] = []
    drill.drill_session.frameSent.connect(lambda command, _raw: sent.append(command))

    again = JobRunner(drill.station, tmp_path / "checkpoints")
    asked: list[str] = []
    again.decisionNeeded.connect(lambda question, *_: asked.append(question))
    assert again.load(program) == [] and again.resume_available == drills[2]
    again.resume_from_checkpoint()
    assert again.state is JobState.PAUSED and again.question == drills[2] and asked
    drill.run(1.0)
    assert DRILL not in sent  # (the V perhaps on the wire still runs to its end)
    again.decide(again=False)
    assert again.done == drills[2] + 1


def test_a_refused_command_fails_the_job_at_its_line(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir)
    messages: list[str] = []
    runner.message.connect(messages.append)
    first_drill = next(i for i, op in enumerate(program) if op.kind is OpKind.DRILL)

    def spoil(direction: Direction, data: bytes) -> bytes:
        return b"Q\r" if direction is Direction.TO_DEVICE and data == b"V\r" else data

    drill.loopback.set_manipulator(spoil)
    assert runner.load(program) == []
    runner.start()
    run_to_end(drill, runner)
    assert runner.state is JobState.FAILED
    assert runner.done == first_drill
    assert any(f"Job failed at {program[first_drill].source}" in m for m in messages)
    assert drill.drill_emulator.drill_log == ()


def test_a_silent_link_mid_drill_is_noticed_paused_and_recovered_without_reconnecting(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """The port stays open but no byte passes (a pulled RS232 cable): no reply, no hang."""
    program = sample_program(data_dir)
    drills = [i for i, op in enumerate(program) if op.kind is OpKind.DRILL]
    states: list[LinkState] = []
    drill.station.model.linkStateChanged.connect(states.append)
    assert runner.load(program) == []
    runner.start()

    def received_third_drill() -> bool:
        if runner.state is JobState.WAITING:
            runner.confirm()
        return runner.current_index == drills[2] and drill.drill_emulator.positions[2] > 0

    drill.run_until(received_third_drill, timeout=200)
    drill.run(0.01)  # its RV reaches the station

    def silence(_direction: Direction, _data: bytes) -> bytes:
        return b""

    drill.loopback.set_manipulator(silence)
    waited = drill.run_until(lambda: runner.state is JobState.PAUSED, timeout=30)
    assert waited < 2 * FIRST_DRILL_CYCLE_S + 3.0 + 0.5  # the D's deadline, not forever
    assert LinkState.LOST in states

    drill.loopback.set_manipulator(None)
    drill.run_until(lambda: drill.station.model.link_state is LinkState.CONNECTED, timeout=60)
    runner.resume()  # no Disconnect/Connect (and the job may have gone on by itself already)
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert drilled(drill) == expected_holes(drill, program)
    assert len(drill.drill_emulator.drill_log) == SAMPLE_HOLES


def test_a_registered_board_is_drilled_every_hole_once_at_its_transformed_position(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """Jogged points → registration → the runner's travel check → holes where the board is."""
    program = sample_program(data_dir)
    # The board lies 1.5° askew, 20 mm right and 15 mm up; the operator "jogs" over two holes.
    truth = Registration(math.radians(1.5), (20.0, 15.0))
    moves = [op.target for op in program if op.kind is OpKind.MOVE]
    refs = [(moves[0]["X"], moves[0]["Y"]), (moves[-1]["X"], moves[-1]["Y"])]
    fit = register(refs, [truth.apply(*p) for p in refs])
    board = registered(program, fit)

    assert runner.load(board) == []
    auto_confirm(runner)
    runner.start()
    run_to_end(drill, runner)

    assert runner.state is JobState.DONE
    expected = expected_holes(drill, board)
    assert sum(expected.values()) == SAMPLE_HOLES
    assert drilled(drill) == expected
    assert expected != expected_holes(drill, program)
    session = drill.drill_session
    first = truth.apply(25.654, 11.684)
    assert (session.to_microsteps(X, first[0]), session.to_microsteps(Y, first[1])) in expected


def test_a_registration_that_puts_holes_off_the_bed_is_refused_by_the_travel_check(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    program = sample_program(data_dir)
    off_bed = registered(program, Registration(0.0, (-30.0, 0.0)))
    refused = runner.load(off_bed)
    assert refused and all(v.axis == "X" and v.value < 0 for v in refused)
    assert runner.program is None


def _once(wanted: bytes, direction: Direction, change: Callable[[bytes], bytes]) -> Manipulator:
    """A manipulator that changes the first message equal to ``wanted`` going ``direction``."""
    fired: list[bool] = []

    def manipulate(going: Direction, data: bytes) -> bytes:
        if going is direction and data == wanted and not fired:
            fired.append(True)
            return change(data)
        return data

    return manipulate


def test_a_drill_cycle_repeated_on_the_way_fails_the_job_instead_of_saying_done(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """The relay's pcb-drill seed 55: ``V`` arrives twice, the drill says ``RV`` twice.

    The drill has no checksum and no stop, so the second hole is drilled; but
    the station heard the second acknowledgement and must not call the job done.
    """
    program = sample_program(data_dir)
    messages: list[str] = []
    runner.message.connect(messages.append)
    first_drill = next(i for i, op in enumerate(program) if op.kind is OpKind.DRILL)
    drill.loopback.set_manipulator(_once(b"V\r", Direction.TO_DEVICE, lambda d: d + d))
    assert runner.load(program) == []
    runner.start()
    run_to_end(drill, runner)
    assert runner.state is JobState.FAILED
    assert runner.done <= first_drill + 1
    assert any(
        f"Job failed at {program[first_drill].source}" in m and "did not send" in m
        for m in messages
    )


def test_a_move_repeated_on_the_way_or_a_reply_repeated_back_changes_nothing(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """An absolute move run twice ends where once does; a repeated ``D`` is only a message."""
    program = sample_program(data_dir)
    first_move = next(op for op in program if op.kind is OpKind.MOVE)
    x = drill.drill_session.to_microsteps(X, first_move.target["X"])
    twice_x = _once(f"X{x}\r".encode(), Direction.TO_DEVICE, lambda d: d + d)
    twice_dv = _once(b"DV\r\n", Direction.TO_HOST, lambda d: d + d)
    drill.loopback.set_manipulator(lambda going, data: twice_dv(going, twice_x(going, data)))
    assert runner.load(program) == []
    runner.start()
    run_to_end(drill, runner)
    assert runner.state is JobState.DONE
    assert drilled(drill) == expected_holes(drill, program)


def test_a_letter_changed_on_the_way_fails_the_job(
    drill: StationHarness, runner: JobRunner, data_dir: Path
) -> None:
    """``Y197`` arriving as ``X197``: the drill answers ``RX`` while ``Y`` is awaited."""
    program = sample_program(data_dir)
    first_move = next(op for op in program if op.kind is OpKind.MOVE)
    y = drill.drill_session.to_microsteps(Y, first_move.target["Y"])
    drill.loopback.set_manipulator(
        _once(f"Y{y}\r".encode(), Direction.TO_DEVICE, lambda d: b"X" + d[1:])
    )
    assert runner.load(program) == []
    runner.start()
    run_to_end(drill, runner)
    assert runner.state is JobState.FAILED
    assert drill.drill_emulator.drill_log == ()
