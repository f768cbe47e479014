"""The job runner on the emulated stage, with time driven by the harness's test clock.

"Exactly once, in order" is checked on the emulator's own log of executed
commands: that is what the machine did, whatever the station believed.
"""

from __future__ import annotations

import json
import os
import random
from collections.abc import Iterator
from pathlib import Path

import pytest

from app.jobs.formats.points.reader import load_point_list
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.drivers import DRIVERS
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.registry import DIALECTS
from app.profiles import load_profile
from protocol.stage.codec import CommandId, StageDecoder
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness

TRAVEL_MM = 50.0


def random_program(count: int, seed: int = 7, name: str = "random") -> Program:
    rng = random.Random(seed)
    ops = tuple(
        move(
            SourceRef(f"{name}.txt", i + 1),
            X=round(rng.uniform(0, TRAVEL_MM), 3),
            Y=round(rng.uniform(0, TRAVEL_MM), 3),
        )
        for i in range(count)
    )
    return Program(name, ops)


def expected_moves(ops: Program | tuple[Operation, ...]) -> list[tuple[int, int]]:
    """(axis, target µm) of every MOVE_ABS the program should cause, in order."""
    return [
        (("X", "Y").index(axis), round(value * 1000))
        for op in ops
        if op.kind is OpKind.MOVE
        for axis, value in op.target.items()
    ]


def executed_moves(harness: StationHarness) -> list[tuple[int, int]]:
    return [
        (c.axis, c.data) for c in harness.emulator.command_log if c.command == CommandId.MOVE_ABS
    ]


def finished(runner: JobRunner) -> bool:
    return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED)


@pytest.fixture
def connected(harness: StationHarness) -> StationHarness:
    harness.connect()
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)
    harness.run(1.0)  # the parameter reads at connect
    return harness


@pytest.fixture
def runner(connected: StationHarness, tmp_path: Path) -> Iterator[JobRunner]:
    built = JobRunner(connected.station, tmp_path / "checkpoints")
    yield built
    built.deleteLater()


def test_200_random_moves_run_to_done_each_target_once_in_order_and_the_eta_holds(
    connected: StationHarness, runner: JobRunner, tmp_path: Path
) -> None:
    prog = random_program(200)
    states: list[JobState] = []
    runner.stateChanged.connect(states.append)
    assert runner.load(prog) == []
    assert runner.state is JobState.READY
    assert runner.progress.estimate is not None
    eta_at_start = runner.progress.remaining_s
    assert eta_at_start == runner.progress.estimate.total_s

    runner.start()
    took = connected.run_until(lambda: finished(runner), timeout=2000)

    assert runner.state is JobState.DONE, states
    assert runner.done == 200
    assert executed_moves(connected) == expected_moves(prog)
    assert abs(eta_at_start - took) <= 0.02 * took, (eta_at_start, took)
    assert runner.progress.remaining_s == 0.0
    assert runner.progress.elapsed_s == pytest.approx(took, abs=0.02)
    assert not list((tmp_path / "checkpoints").glob("*.json"))  # removed when done
    x, y = connected.station.model.axes
    assert (x.position, y.position) == pytest.approx(tuple(prog[-1].target.values()), abs=0.002)


def test_pause_lets_the_current_move_finish_and_nothing_starts_until_resume(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(8)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.current_index == 3 and connected.emulator.axes[0].moving)

    runner.pause()
    assert runner.state is JobState.PAUSING
    connected.run_until(lambda: runner.state is JobState.PAUSED)
    assert runner.done == 4  # the move under way was finished, not cut
    sent = executed_moves(connected)
    assert sent == expected_moves(prog.operations[:4])
    elapsed_at_pause, waiting_at_pause = runner.progress.elapsed_s, runner.progress.waiting_s
    connected.run(10.0)
    assert executed_moves(connected) == sent
    assert runner.state is JobState.PAUSED and runner.done == 4
    # The wall clock goes on while paused, and the pause is told apart as waiting.
    assert runner.progress.elapsed_s == pytest.approx(elapsed_at_pause + 10.0, abs=0.02)
    assert runner.progress.waiting_s == pytest.approx(waiting_at_pause + 10.0, abs=0.02)

    runner.resume()
    connected.run_until(lambda: finished(runner), timeout=120)
    assert runner.state is JobState.DONE
    assert executed_moves(connected) == expected_moves(prog)


def test_step_runs_exactly_one_operation_each_time(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(5)
    runner.load(prog)

    runner.step()
    connected.run_until(lambda: runner.state is JobState.PAUSED)
    assert runner.done == 1
    connected.run(10.0)
    assert executed_moves(connected) == expected_moves(prog.operations[:1])

    runner.step()
    connected.run_until(lambda: runner.state is JobState.PAUSED and runner.done == 2)
    connected.run(10.0)
    assert runner.done == 2
    assert executed_moves(connected) == expected_moves(prog.operations[:2])


def test_a_move_outside_the_travel_is_refused_before_any_motion_naming_its_line(
    connected: StationHarness, runner: JobRunner, tmp_path: Path
) -> None:
    job = tmp_path / "scan.txt"
    job.write_text("# a scan\n10, 10\n20, 60\n30, 30\n-1, 5\n", encoding="utf-8")
    messages: list[str] = []
    runner.message.connect(messages.append)

    refused = runner.load(load_point_list(job))

    assert [(v.index, v.operation.source.line, v.axis) for v in refused] == [
        (2, 3, "Y"),
        (4, 5, "X"),
    ]
    assert runner.state is JobState.IDLE and runner.program is None
    assert "scan.txt:3" in messages[-1] and "scan.txt:5" in messages[-1]
    assert "move to X20.000 Y60.000" in messages[-1]
    runner.start()
    connected.run(2.0)
    decoder = StageDecoder()
    frames = [f for chunk in connected.written for f in decoder.feed(chunk)]
    assert frames, "the session kept sending its periodic frames"
    assert not [
        p for f in frames for p in getattr(f, "packets", ()) if p.command == CommandId.MOVE_ABS
    ]


def test_a_drill_operation_is_refused_on_a_stage(runner: JobRunner) -> None:
    where = SourceRef("board.drl", 12)
    prog = Program(
        "board", (move(SourceRef("board.drl", 11), X=5, Y=5), Operation(OpKind.DRILL, where))
    )
    refused = runner.load(prog)
    assert [str(v.operation.source) for v in refused] == ["board.drl:12"]
    assert "cannot drill" in str(refused[0])
    assert runner.state is JobState.IDLE


def test_a_wait_holds_the_job_until_the_operator_confirms(
    connected: StationHarness, runner: JobRunner
) -> None:
    here = SourceRef("job.txt", 1)
    prog = Program(
        "job",
        (
            move(here, X=5.0, Y=5.0),
            Operation(OpKind.WAIT, SourceRef("job.txt", 2), message="load the sample"),
            Operation(OpKind.COMMENT, SourceRef("job.txt", 3), message="scanning"),
            move(here, X=10.0, Y=5.0),
        ),
    )
    asked: list[str] = []
    runner.waitingForOperator.connect(asked.append)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.state is JobState.WAITING)
    assert asked == ["load the sample"] and runner.done == 1
    elapsed, waiting = runner.progress.elapsed_s, runner.progress.waiting_s
    connected.run(20.0)
    assert runner.state is JobState.WAITING
    assert runner.progress.elapsed_s == pytest.approx(
        elapsed + 20.0, abs=0.02
    )  # the prompt's time counts
    assert runner.progress.waiting_s == pytest.approx(
        waiting + 20.0, abs=0.02
    )  # told apart as waiting
    assert executed_moves(connected) == expected_moves(prog.operations[:1])

    runner.confirm()
    connected.run_until(lambda: finished(runner))
    assert runner.state is JobState.DONE and runner.done == 4
    assert executed_moves(connected) == expected_moves(prog)


def test_a_checkpoint_is_written_after_every_operation(
    connected: StationHarness, runner: JobRunner, tmp_path: Path
) -> None:
    prog = random_program(6)
    seen: list[int] = []

    def record(index: int) -> None:
        path = tmp_path / "checkpoints" / f"{prog.fingerprint()}.json"
        record = json.loads(path.read_text(encoding="utf-8"))
        assert record["fingerprint"] == prog.fingerprint() and record["name"] == "random"
        seen.append(record["completed"])

    runner.operationDone.connect(record)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: finished(runner), timeout=120)
    assert seen == [0, 1, 2, 3, 4, 5]
    assert not list((tmp_path / "checkpoints").iterdir())  # no temp files left either


def cut_link(harness: StationHarness, *, replies_only: bool) -> None:
    def drop(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_HOST or not replies_only else data

    harness.loopback.set_manipulator(drop)


def restore_link(harness: StationHarness) -> None:
    harness.loopback.set_manipulator(None)
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)


def test_replies_cut_mid_move_then_restored_the_finished_move_is_not_sent_again(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(12)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.current_index == 5 and connected.emulator.axes[0].moving)

    cut_link(connected, replies_only=True)
    connected.run_until(lambda: runner.state is JobState.PAUSED)
    assert runner.done == 5  # the move in flight is not counted
    connected.run(6.0)  # the stage finishes the move on its own meanwhile
    restore_link(connected)
    assert runner.state is JobState.PAUSED  # nothing resumes without the operator

    runner.resume()
    connected.run_until(lambda: finished(runner), timeout=120)
    assert runner.state is JobState.DONE
    assert executed_moves(connected) == expected_moves(prog)


def test_a_move_lost_on_the_way_is_sent_again_after_the_link_returns(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(10, seed=11)

    def cut_before_op_4(index: int) -> None:
        if index == 4:
            cut_link(connected, replies_only=False)

    runner.operationStarted.connect(cut_before_op_4)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.state is JobState.PAUSED)
    assert runner.done == 4
    assert executed_moves(connected) == expected_moves(prog.operations[:4])

    restore_link(connected)
    runner.resume()
    connected.run_until(lambda: finished(runner), timeout=120)
    assert runner.state is JobState.DONE
    assert executed_moves(connected) == expected_moves(prog)


def test_a_severed_link_pauses_and_the_job_resumes_without_repeats(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(10, seed=3)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.current_index == 2 and connected.emulator.axes[1].moving)
    connected.loopback.sever()
    assert runner.state is JobState.PAUSED and runner.current_index == 2
    connected.run_until(lambda: connected.station.model.link_state is LinkState.CONNECTED)
    runner.resume()
    connected.run_until(lambda: finished(runner), timeout=120)
    assert runner.state is JobState.DONE
    assert executed_moves(connected) == expected_moves(prog)


def test_a_new_station_offers_the_checkpoint_and_finishes_the_job_without_repeats(
    qapp: object, tmp_path: Path
) -> None:
    prog = random_program(12, seed=5)
    checkpoints = tmp_path / "checkpoints"
    first = StationHarness()
    try:
        first.connect()
        first.run(1.0)
        runner = JobRunner(first.station, checkpoints)
        runner.load(prog)
        runner.start()
        first.run_until(lambda: runner.done == 7)
        runner.pause()  # PAUSING: op 7 is under way and finishes
        first.run_until(lambda: runner.state is JobState.PAUSED)
        before = executed_moves(first)
    finally:
        first.close()  # the station goes away with its job paused
    assert before == expected_moves(prog.operations[:8])

    second = StationHarness()
    try:
        second.connect()
        second.run(1.0)
        again = JobRunner(second.station, checkpoints)
        assert again.load(prog) == []
        assert again.resume_available == 8
        again.start()  # refused: the operator has to decide first
        second.run(1.0)
        assert again.state is JobState.READY and executed_moves(second) == []

        again.resume_from_checkpoint()
        second.run_until(lambda: finished(again), timeout=120)
        assert again.state is JobState.DONE and again.done == 12
        assert before + executed_moves(second) == expected_moves(prog)
        assert again.resume_available is None and not list(checkpoints.glob("*.json"))
    finally:
        second.close()


def test_abort_stops_the_machine_and_keeps_the_checkpoint_for_later(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(10, seed=9)
    runner.load(prog)
    runner.start()
    connected.run_until(lambda: runner.current_index == 3 and connected.emulator.axes[0].moving)
    runner.abort()
    assert runner.state is JobState.ABORTED
    connected.run_until(lambda: not any(a.moving for a in connected.emulator.axes))
    stops = [c for c in connected.emulator.command_log if c.command == CommandId.STOP]
    assert len(stops) == 2
    assert runner.resume_available == 3  # op 3 never completed
    assert executed_moves(connected) == expected_moves(prog.operations[:4])

    runner.resume_from_checkpoint()  # op 3 stopped short: it is sent again, then the rest
    connected.run_until(lambda: finished(runner), timeout=120)
    assert runner.state is JobState.DONE
    assert executed_moves(connected) == expected_moves(prog.operations[:4]) + expected_moves(
        prog.operations[3:]
    )


def test_a_changed_program_does_not_pick_up_another_programs_checkpoint(
    connected: StationHarness, runner: JobRunner, tmp_path: Path
) -> None:
    prog = random_program(6, seed=1)
    runner.load(prog)
    runner.step()
    connected.run_until(lambda: runner.state is JobState.PAUSED)
    runner.abort()
    assert runner.resume_available == 1
    other = random_program(6, seed=2)
    assert runner.load(other) == [] and runner.resume_available is None
    assert runner.load(prog) == [] and runner.resume_available == 1
    runner.discard_checkpoint()
    assert runner.resume_available is None
    assert not list((tmp_path / "checkpoints").glob("*.json"))


def test_every_dialect_a_profile_can_name_has_a_job_driver() -> None:
    """A machine whose jobs nobody can judge would hang; so every dialect gets a driver."""
    assert set(DRIVERS) == set(DIALECTS)
    for name in ("xy-stage", "usb3", "pcb-drill", "string-art", "corexy-plotter", "grbl-plotter"):
        assert load_profile(name).dialect in DRIVERS


def test_a_checkpoint_that_cannot_be_written_stops_the_job_as_failed_with_the_reason(
    connected: StationHarness, tmp_path: Path
) -> None:
    blocked = tmp_path / "not-a-folder"
    blocked.write_text("a file where the checkpoint folder should be", encoding="utf-8")
    runner = JobRunner(connected.station, blocked)
    messages: list[str] = []
    runner.message.connect(messages.append)
    prog = random_program(5, seed=4)
    assert runner.load(prog) == []
    runner.start()
    connected.run_until(lambda: finished(runner), timeout=60)
    assert runner.state is JobState.FAILED  # not running on, not "done" without a record
    assert runner.done == 1
    assert executed_moves(connected) == expected_moves(prog.operations[:1])  # nothing after it
    assert any("checkpoint could not be written" in m and str(blocked) in m for m in messages)


@pytest.mark.parametrize("kind", ["fifo", "device", "huge"])
def test_only_a_small_regular_file_is_read_as_a_checkpoint(
    runner: JobRunner, tmp_path: Path, kind: str
) -> None:
    """A FIFO would hang the load, /dev/zero would never end: both refused, with a word."""
    prog = random_program(4, seed=5)
    folder = tmp_path / "checkpoints"
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{prog.fingerprint()}.json"
    if kind == "fifo":
        os.mkfifo(path)
    elif kind == "device":
        path.symlink_to("/dev/zero")
    else:
        path.write_text(json.dumps({"pad": "x" * 100_000}), encoding="utf-8")
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(prog) == []
    assert runner.resume_available is None and runner.state is JobState.READY
    assert any("unreadable checkpoint" in m for m in messages)
