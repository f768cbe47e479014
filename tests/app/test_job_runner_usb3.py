"""The job runner on the emulated three-axis USB unit, time driven by the test clock.

The unit moves only relative to where it stands, so a move sent twice goes
twice as far: "exactly once" is checked on the emulator's own log of the
moves it executed and on where the axes end up.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest

from app.jobs.program import Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.jobs.run.usb3 import ANSWER_TIMEOUT_S
from app.machine import LinkState
from app.machines.usb3.session import LOST_AFTER_S
from app.profiles import load_profile
from protocol.emulator.usb3_firmware import Usb3Config, Usb3Firmware
from protocol.transport.loopback import Direction, LoopbackTransport
from protocol.usb3.codec import AxisId, Move, StepSize, Thread, count_to_mm
from tests.helpers.harness import StationHarness

#: Full steps on an M10 thread: 2.25 mm/s, so a test's moves take seconds, not minutes.
STEP = StepSize.FULL
THREAD = Thread.M10


def route(*targets: tuple[float, float]) -> Program:
    return Program(
        "route",
        tuple(move(SourceRef("route.csv", i + 1), X=x, Y=y) for i, (x, y) in enumerate(targets)),
    )


def moves_executed(unit: StationHarness) -> list[tuple[AxisId, int]]:
    """(axis, count) of every move that moved something, as the unit executed them."""
    return [
        (entry.command.axis, entry.command.count)
        for entry in unit.usb3_emulator.command_log
        if isinstance(entry.command, Move) and entry.command.count
    ]


def unit_at(unit: StationHarness, axis: AxisId) -> float:
    return count_to_mm(unit.usb3_emulator.positions[axis], THREAD)


def finished(runner: JobRunner) -> bool:
    return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED)


@pytest.fixture
def unit() -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("usb3"))
    harness.connect()
    session = harness.usb3_session
    for axis in range(3):
        session.set_step_size(axis, STEP)
        session.set_thread(axis, THREAD)
    harness.run(0.3)
    yield harness
    harness.close()


@pytest.fixture
def runner(unit: StationHarness, tmp_path: Path) -> JobRunner:
    return JobRunner(unit.station, tmp_path / "checkpoints")


def test_a_point_list_runs_on_the_unit_each_target_reached_once_in_order(
    unit: StationHarness, runner: JobRunner
) -> None:
    # Targets on the step grid (0.0075 mm), so every one is reached exactly.
    program = route((3.0, 1.5), (0.75, 4.5), (0.75, 0.75), (6.0, 0.0))
    seen: list[tuple[float, float]] = []
    runner.operationDone.connect(
        lambda _i: seen.append((unit_at(unit, AxisId.X), unit_at(unit, AxisId.Y)))
    )
    assert runner.load(program) == []
    assert runner.progress.estimate is not None and runner.progress.estimate.total_s > 0
    runner.start()
    unit.run_until(lambda: finished(runner), timeout=60)

    assert runner.state is JobState.DONE
    assert seen == [(3.0, 1.5), (0.75, 4.5), (0.75, 0.75), (6.0, 0.0)]
    assert (unit_at(unit, AxisId.X), unit_at(unit, AxisId.Y)) == (6.0, 0.0)
    # One move per axis that changes, each by exactly the difference: nothing sent twice.
    per_mm = 6400 / THREAD.pitch_mm
    assert moves_executed(unit) == [
        (AxisId.X, round(3.0 * per_mm)),
        (AxisId.Y, round(1.5 * per_mm)),
        (AxisId.X, round(2.25 * per_mm)),
        (AxisId.Y, round(3.0 * per_mm)),
        (AxisId.Y, round(3.75 * per_mm)),
        (AxisId.X, round(5.25 * per_mm)),
        (AxisId.Y, round(0.75 * per_mm)),
    ]


def test_an_operation_counts_only_when_the_unit_reports_it_there(
    unit: StationHarness, runner: JobRunner
) -> None:
    runner.load(route((4.5, 0.0)))
    runner.start()
    unit.run_until(lambda: unit.usb3_emulator.moving(AxisId.X))
    unit.run(1.0)
    assert runner.done == 0 and runner.current_index == 0  # under way, not done
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE and unit_at(unit, AxisId.X) == 4.5


def test_a_link_pulled_mid_move_resumes_without_moving_twice(
    unit: StationHarness, runner: JobRunner
) -> None:
    program = route((2.25, 0.0), (6.75, 2.25), (0.0, 0.0))
    runner.load(program)
    runner.start()
    unit.run_until(lambda: runner.current_index == 1 and unit.usb3_emulator.moving(AxisId.X))
    unit.loopback.sever()
    assert runner.state is JobState.PAUSED and runner.done == 1
    unit.run(4.0)  # the unit runs its move out while nobody listens
    assert not unit.usb3_emulator.moving(AxisId.X)
    unit.run_until(lambda: unit.station.model.link_state is LinkState.CONNECTED)
    sent_before_resume = len(moves_executed(unit))

    runner.resume()
    unit.run_until(lambda: runner.done == 2, timeout=30)
    # The move had finished: the unit was asked where it stands, and nothing was sent again.
    assert len(moves_executed(unit)) == sent_before_resume
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE
    assert (unit_at(unit, AxisId.X), unit_at(unit, AxisId.Y)) == (0.0, 0.0)


def test_a_link_pulled_before_the_unit_got_there_sends_only_the_rest(
    unit: StationHarness, runner: JobRunner
) -> None:
    runner.load(route((9.0, 0.0)))
    runner.start()
    unit.run_until(lambda: unit_at(unit, AxisId.X) > 1.0)
    unit.loopback.sever()
    unit.usb3_emulator.receive(b"S;")  # the unit stopped while nobody listened (a hand, a menu)
    unit.run(1.0)
    stopped_at = unit_at(unit, AxisId.X)
    assert 1.0 < stopped_at < 9.0
    unit.run_until(lambda: unit.station.model.link_state is LinkState.CONNECTED)

    runner.resume()
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE and unit_at(unit, AxisId.X) == 9.0
    per_mm = 6400 / THREAD.pitch_mm
    first, rest = (count for axis, count in moves_executed(unit) if axis is AxisId.X)
    assert first == round(9.0 * per_mm)
    assert rest == round((9.0 - stopped_at) * per_mm)  # the rest, not the whole again


def test_esc_stops_the_move_and_resume_carries_on_to_the_same_target(
    unit: StationHarness, runner: JobRunner
) -> None:
    runner.load(route((0.0, 6.0)))
    runner.start()
    unit.run_until(lambda: unit_at(unit, AxisId.Y) > 2.0)
    unit.station.session.stop_all()  # type: ignore[union-attr]
    unit.run_until(lambda: runner.state is JobState.PAUSED, timeout=5)
    assert runner.done == 0 and unit_at(unit, AxisId.Y) < 6.0

    runner.resume()
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE and unit_at(unit, AxisId.Y) == 6.0


def test_a_unit_that_does_not_say_where_it_stands_is_never_sent_a_move_blind(
    unit: StationHarness, runner: JobRunner
) -> None:
    messages: list[str] = []
    runner.message.connect(messages.append)
    runner.load(route((4.5, 0.0), (0.0, 0.0)))
    runner.start()
    unit.run_until(lambda: unit.usb3_emulator.moving(AxisId.X))
    unit.loopback.sever()
    unit.run_until(lambda: unit.station.model.link_state is LinkState.CONNECTED)
    sent = len(moves_executed(unit))

    def mute(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_HOST else data

    unit.loopback.set_manipulator(mute)
    runner.resume()
    unit.run(max(ANSWER_TIMEOUT_S, LOST_AFTER_S) + 1.0)
    assert runner.state is JobState.PAUSED
    # Not a word, not even to G;: the link's silence, which its liveness judges.
    assert any("link lost" in m for m in messages)
    assert len(moves_executed(unit)) == sent  # the question moved nothing, no move followed

    unit.loopback.set_manipulator(None)  # asked again, and this time it hears
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE and unit_at(unit, AxisId.X) == 0.0


def test_a_unit_moved_while_nobody_listened_is_asked_before_the_first_move(
    unit: StationHarness, runner: JobRunner
) -> None:
    def mute(direction: Direction, data: bytes) -> bytes:
        return b"" if direction is Direction.TO_HOST else data

    unit.loopback.set_manipulator(mute)
    unit.usb3_emulator.receive(b"D+++;X000000000012800;")  # 3 mm by its own menu or a hand
    unit.run_until(lambda: not unit.usb3_emulator.moving(AxisId.X) and unit_at(unit, AxisId.X) > 0)
    unit.loopback.set_manipulator(None)
    assert unit.station.model.axes[0].position == 0.0  # the station has not heard of it

    runner.load(route((4.5, 0.0)))
    runner.start()
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE and unit_at(unit, AxisId.X) == 4.5
    assert moves_executed(unit)[-1] == (AxisId.X, round(1.5 * 6400 / THREAD.pitch_mm))


def test_s4_18_an_end_switch_mid_move_pauses_the_job_naming_the_axis_and_end(
    tmp_path: Path,
) -> None:
    """FIDELITY S4-18: the unit stops the motor at its switch and reports only where it
    stands; the job pauses with that news instead of going on (or on to the target) blindly."""
    unit = StationHarness(load_profile("usb3"))
    try:
        ends = ((1e6, 1e6), (1e6, 12_800.0), (1e6, 1e6))  # Y's high switch 3 mm on at M10
        firmware = Usb3Firmware(
            unit.clock,
            Usb3Config(step_sizes=(STEP,) * 3, threads=(THREAD,) * 3, end_switches=ends),
        )
        unit.station.connect_transport(LoopbackTransport(firmware, unit.clock, realtime=False))
        unit.station.emulator = firmware
        unit.run(0.3)
        runner = JobRunner(unit.station, tmp_path / "checkpoints")
        messages: list[str] = []
        runner.message.connect(messages.append)
        runner.load(route((0.0, 4.5), (1.5, 0.0)))
        runner.start()
        unit.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
        assert unit_at(unit, AxisId.Y) == 3.0 and runner.done == 0
        assert messages[-1].startswith("Y stopped at its high end switch at 3.000 mm during ")
        assert "route.csv:1" in messages[-1]
        sent = len(moves_executed(unit))
        unit.run(3.0)
        assert runner.state is JobState.PAUSED and len(moves_executed(unit)) == sent
    finally:
        unit.close()


def test_a_move_the_unit_could_not_read_pauses_saying_so_and_the_resume_moves_it_once(
    unit: StationHarness, runner: JobRunner
) -> None:
    """Relay usb3 seeds 26, 56…: a flipped bit made the X move unreadable; the unit answered
    ``?;`` and ran only Y.  The job stayed "running" (or paused "link lost") for good while
    the unit answered every question."""
    garbled: list[bytes] = []

    def garble_first_x_move(direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE and not garbled and data.startswith(b"X"):
            if data != b"X000000000000000;":  # the question "where are you?" passes
                garbled.append(data)
                return b"X0p" + data[3:]  # a digit flipped into a letter
        return data

    messages: list[str] = []
    runner.message.connect(messages.append)
    unit.loopback.set_manipulator(garble_first_x_move)
    assert runner.load(route((2.25, 0.75), (0.75, 1.5))) == []
    runner.start()
    unit.run_until(lambda: runner.state is JobState.PAUSED or finished(runner), timeout=20)
    assert garbled
    assert runner.state is JobState.PAUSED, messages
    assert unit.station.model.link_state is LinkState.CONNECTED
    assert "could not read the move of X" in messages[-1], messages
    assert not runner.needs_operator  # the API resumes it by itself
    runner.resume()
    unit.run_until(lambda: finished(runner), timeout=30)
    assert runner.state is JobState.DONE, messages
    per_mm = 6400 / THREAD.pitch_mm
    # Y once, X once (the garbled one never ran), then the second point: nothing twice.
    assert moves_executed(unit) == [
        (AxisId.Y, round(0.75 * per_mm)),
        (AxisId.X, round(2.25 * per_mm)),
        (AxisId.X, round(1.5 * per_mm)),
        (AxisId.Y, round(0.75 * per_mm)),
    ]
    assert (unit_at(unit, AxisId.X), unit_at(unit, AxisId.Y)) == (0.75, 1.5)
