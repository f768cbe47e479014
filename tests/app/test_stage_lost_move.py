"""A byte lost or flipped on the way to the stage: the move in that frame is not lost for good.

The stage drops a frame whose checksum fails and answers nothing (found by the
fault relay: the job waited for ever for a move the stage never got).  The
session sends such a move again only once an echo of a later frame shows the
axis standing off its target; a move whose *echo* was lost has run and is never
sent twice.  Judged from the emulator's command log, on the manual clock.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from protocol.stage.codec import CommandId
from protocol.transport.loopback import Direction
from tests.app.test_job_runner import expected_moves, random_program
from tests.helpers.harness import StationHarness

Fault = Callable[[bytes], bytes]


def _drop_four(frame: bytes) -> bytes:
    return frame[:5] + frame[9:]  # four DATA digits of the first packet gone


def _flip_bit(frame: bytes) -> bytes:
    mangled = bytearray(frame)
    mangled[3] ^= 0x04  # one bit of the first packet's DATA
    return bytes(mangled)


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


def _per_axis(moves: list[tuple[int, int]]) -> dict[int, list[int]]:
    return {axis: [um for a, um in moves if a == axis] for axis in (0, 1)}


def _executed(harness: StationHarness) -> list[tuple[int, int]]:
    log = harness.emulator.command_log
    return [(c.axis, c.data) for c in log if c.command == CommandId.MOVE_ABS]


def _mangle_move(
    harness: StationHarness, direction: Direction, fault: Fault, nth: int
) -> list[bytes]:
    """Apply ``fault`` once, to the ``nth`` frame going ``direction`` after an X MOVE_ABS left."""
    hit: list[bytes] = []
    armed: list[int] = []

    def manipulate(way: Direction, data: bytes) -> bytes:
        if hit:
            return data
        if way is Direction.TO_DEVICE and data.startswith(b">03"):
            armed.append(0)
        if armed and way is direction:
            armed[0] += 1
            if armed[0] == nth:
                hit.append(data)
                return fault(data)
        return data

    harness.loopback.set_manipulator(manipulate)
    return hit


@pytest.mark.parametrize("fault", [_drop_four, _flip_bit], ids=["drop", "flip"])
def test_a_move_mangled_on_the_way_to_the_stage_runs_once_and_the_job_ends(
    connected: StationHarness, runner: JobRunner, fault: Fault
) -> None:
    prog = random_program(5)
    runner.load(prog)
    hit = _mangle_move(connected, Direction.TO_DEVICE, fault, nth=1)
    runner.start()
    connected.run_until(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), timeout=60
    )
    assert hit and hit[0].startswith(b">03")  # the fault did hit a move's frame
    assert connected.session.rejected == 0  # nothing mangled came back to the station
    assert connected.emulator.snapshot().rejected_frames >= 1  # the stage refused the mangled frame
    assert runner.state is JobState.DONE
    assert _per_axis(_executed(connected)) == _per_axis(expected_moves(prog))


def test_a_move_whose_echo_is_lost_has_run_and_is_not_sent_again(
    connected: StationHarness, runner: JobRunner
) -> None:
    prog = random_program(5, seed=3)
    runner.load(prog)
    hit = _mangle_move(connected, Direction.TO_HOST, _drop_four, nth=1)
    runner.start()
    connected.run_until(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED), timeout=60
    )
    assert hit and hit[0].startswith(b"<")  # the move's own echo was the one mangled
    assert connected.session.rejected == 1
    assert runner.state is JobState.DONE
    assert _per_axis(_executed(connected)) == _per_axis(expected_moves(prog))
