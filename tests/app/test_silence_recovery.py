"""A silent line with the port open: asked on, back without Disconnect/Connect, a job goes on.

Issue 30: usb3 and the drill never came back from a silent line (they speak only when
asked, and nobody asked any more), and a GRBL job paused for a 2.5 s freeze of the
board's replies although nothing was lost.  Here every dialect is silenced on the
emulator's link (the loopback manipulator: the port stays open, bytes are dropped or
held back), on the harness's manual clock.  What the machine did is judged from the
emulator's own records (its command log, holes, moves), never from the station's account.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.machines.gcode.session import SILENCE_S
from app.machines.session import PROBE_EVERY_S
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from protocol.usb3.codec import AxisId, Move, StepSize, Thread, count_to_mm
from tests.helpers.harness import StationHarness

PROFILES = ("xy-stage", "usb3", "pcb-drill", "grbl-plotter", "corexy-plotter", "string-art")
#: Full steps on an M10 thread: the usb3 unit's moves take seconds, not minutes.
STEP = StepSize.FULL
THREAD = Thread.M10


def _silence(*directions: Direction) -> Callable[[Direction, bytes], bytes]:
    def manipulate(direction: Direction, data: bytes) -> bytes:
        return b"" if direction in directions else data

    return manipulate


class HeldReplies:
    """A relay that holds the device's replies back (a frozen board), then lets them all go."""

    def __init__(self) -> None:
        self.held = bytearray()
        self.holding = True

    def __call__(self, direction: Direction, data: bytes) -> bytes:
        if direction is Direction.TO_DEVICE:
            return data
        if self.holding:
            self.held += data
            return b""
        released, self.held = bytes(self.held) + data, bytearray()
        return released


def _finished(runner: JobRunner) -> bool:
    return runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED)


# --- every dialect: the link comes back by itself, the port never closed ----------------------


@pytest.fixture(params=PROFILES)
def unit(request: pytest.FixtureRequest) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile(request.param))
    harness.connect()
    yield harness
    harness.close()


def test_a_silence_that_outlasts_the_loss_ends_when_the_line_works_again(
    unit: StationHarness,
) -> None:
    station = unit.station
    link = station.link
    assert link is not None
    closed: list[object] = []
    link.disconnected.connect(closed.append)
    messages: list[str] = []
    station.model.message.connect(messages.append)
    if station.drill_session is not None:
        # An idle drill is asked nothing: its silence is noticed on a command in flight.
        unit.run_until(lambda: not unit.drill_emulator.busy, timeout=10)
        assert unit.drill_session.move_absolute(0, 60.0)
    unit.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
    unit.run_until(lambda: station.model.link_state is LinkState.LOST, timeout=15)
    assert station.model.motion_lock_reason() == "link lost"
    sent_when_lost = len(unit.written)
    unit.run(4.0)  # the line stays silent well past the loss
    assert station.model.link_state is LinkState.LOST
    # Asked on meanwhile (the stage's frames and GRBL's status queries ask every period).
    assert len(unit.written) - sent_when_lost >= 4.0 / PROBE_EVERY_S - 1

    unit.loopback.set_manipulator(None)
    waited = unit.run_until(lambda: station.model.link_state is LinkState.CONNECTED, timeout=10)
    assert waited <= PROBE_EVERY_S + 1.5  # the next question is answered; no back-off
    assert station.link is link and closed == []  # nothing closed, nothing reopened
    assert station.model.motion_lock_reason() is None
    assert sum("asking it every" in m for m in messages) == 1
    assert sum(m.startswith("The device answers again") for m in messages) == 1


def test_an_idle_usb3_unit_is_asked_g_while_silent_and_answers_it_afterwards() -> None:
    """The idle unit through the API in the issue: it only ever speaks when asked."""
    unit = StationHarness(load_profile("usb3"))
    try:
        unit.connect()
        model = unit.station.model
        unit.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
        unit.run_until(lambda: model.link_state is LinkState.LOST, timeout=10)
        asked_from = len(unit.written)
        unit.run(5.0)
        asked = [w for w in unit.written[asked_from:] if w == b"G;"]
        assert len(asked) >= 4  # one a second, into the silence
        unit.loopback.set_manipulator(None)
        unit.run_until(lambda: model.link_state is LinkState.CONNECTED, timeout=3)
        assert unit.usb3_session.silent_since is None
    finally:
        unit.close()


# --- usb3 mid-job ---------------------------------------------------------------------


@pytest.fixture
def usb3() -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("usb3"))
    harness.connect()
    session = harness.usb3_session
    for axis in range(3):
        session.set_step_size(axis, STEP)
        session.set_thread(axis, THREAD)
    harness.run(0.3)
    yield harness
    harness.close()


def _route(*targets: tuple[float, float]) -> Program:
    return Program(
        "route",
        tuple(move(SourceRef("route.csv", i + 1), X=x, Y=y) for i, (x, y) in enumerate(targets)),
    )


def _moves_executed(unit: StationHarness) -> list[tuple[AxisId, int]]:
    return [
        (entry.command.axis, entry.command.count)
        for entry in unit.usb3_emulator.command_log
        if isinstance(entry.command, Move) and entry.command.count
    ]


def _unit_at(unit: StationHarness) -> tuple[float, float]:
    positions = unit.usb3_emulator.positions
    return count_to_mm(positions[AxisId.X], THREAD), count_to_mm(positions[AxisId.Y], THREAD)


def test_a_usb3_job_silenced_mid_move_goes_on_by_itself_nothing_moved_twice(
    usb3: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(usb3.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    states: list[JobState] = []
    runner.stateChanged.connect(states.append)
    program = _route((2.25, 0.0), (6.75, 2.25), (0.0, 0.0))
    assert runner.load(program) == []
    runner.start()
    usb3.run_until(lambda: runner.current_index == 1 and usb3.usb3_emulator.moving(AxisId.X))
    usb3.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
    usb3.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
    usb3.run(5.0)  # the unit runs its move out while the line is silent
    assert not usb3.usb3_emulator.moving(AxisId.X)
    usb3.loopback.set_manipulator(None)  # no Resume, no Disconnect/Connect

    usb3.run_until(lambda: _finished(runner), timeout=60)
    assert runner.state is JobState.DONE
    assert _unit_at(usb3) == (0.0, 0.0)
    per_mm = 6400 / THREAD.pitch_mm
    # Each operation's moves once: the one under way was not sent again.
    assert _moves_executed(usb3) == [
        (AxisId.X, round(2.25 * per_mm)),
        (AxisId.X, round(4.5 * per_mm)),
        (AxisId.Y, round(2.25 * per_mm)),
        (AxisId.X, round(6.75 * per_mm)),
        (AxisId.Y, round(2.25 * per_mm)),
    ]
    assert sum("the job goes on" in m for m in messages) == 1
    assert states.count(JobState.PAUSED) == 1


def test_a_usb3_unit_moved_while_silent_does_not_match_and_waits_for_the_operator(
    usb3: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(usb3.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(_route((2.25, 0.0), (4.5, 0.0))) == []
    runner.start()
    usb3.run_until(lambda: runner.done == 1 and not usb3.usb3_emulator.moving(AxisId.X))
    usb3.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
    usb3.usb3_emulator.receive(b"D+++;Y000000000012800;")  # a hand on its menu: Y 3 mm
    usb3.run_until(lambda: runner.state is JobState.PAUSED, timeout=10)
    usb3.run(3.0)
    moves_before = len(_moves_executed(usb3))
    usb3.loopback.set_manipulator(None)
    usb3.run_until(lambda: usb3.station.model.link_state is LinkState.CONNECTED, timeout=5)
    usb3.run(2.0)
    assert runner.state is JobState.PAUSED  # Y is not where the books have it
    assert len(_moves_executed(usb3)) == moves_before  # nothing moved on its own
    told = [m for m in messages if "position does not match" in m]
    assert len(told) == 1 and "Y is at 3.000 mm" in told[0], messages

    runner.resume()  # the operator looked: go on from where it stands
    usb3.run_until(lambda: _finished(runner), timeout=60)
    assert runner.state is JobState.DONE and _unit_at(usb3)[0] == 4.5


# --- the drill mid-job ---------------------------------------------------------------------


def test_a_drill_job_silenced_mid_board_goes_on_by_itself_every_hole_once(
    qtbot: QtBot, tmp_path: Path
) -> None:
    drill = StationHarness(load_profile("pcb-drill"))
    runner = JobRunner(drill.station, tmp_path / "checkpoints")
    try:
        drill.connect()
        assert drill.drill_session.home(0)
        drill.run_until(lambda: not drill.drill_session.busy, timeout=60)
        ops: list[Operation] = []
        holes = [(10.0, 10.0), (20.0, 12.0), (30.0, 14.0), (40.0, 16.0)]
        for n, (x, y) in enumerate(holes):
            ops.append(move(SourceRef("board.drl", 2 * n + 1), X=x, Y=y))
            ops.append(Operation(OpKind.DRILL, SourceRef("board.drl", 2 * n + 2)))
        assert runner.load(Program("board", tuple(ops))) == []
        messages: list[str] = []
        runner.message.connect(messages.append)
        runner.start()
        # Mid-board: the second hole drilled, the move to the third under way.
        drill.run_until(lambda: len(drill.drill_emulator.drill_log) == 2, timeout=120)
        drill.run_until(lambda: runner.current_index == 4, timeout=30)
        drill.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
        drill.run_until(lambda: runner.state is JobState.PAUSED, timeout=60)
        drill.run(6.0)
        drill.loopback.set_manipulator(None)

        drill.run_until(lambda: _finished(runner), timeout=300)
        assert runner.state is JobState.DONE
        session = drill.drill_session
        expected = [(session.to_microsteps(0, x), session.to_microsteps(1, y)) for x, y in holes]
        assert [(hole.x, hole.y) for hole in drill.drill_emulator.drill_log] == expected
        assert sum("the job goes on" in m for m in messages) == 1, messages
    finally:
        runner.deleteLater()
        drill.close()


# --- GRBL ---------------------------------------------------------------------------------

SQUARE = [(10.0, 10.0), (110.0, 10.0), (110.0, 110.0), (10.0, 110.0), (10.0, 10.0)]


def _square() -> Program:
    at = lambda line: SourceRef("square", line)  # noqa: E731
    ops: list[Operation] = [Operation(OpKind.PEN_UP, at(1)), move(at(2), X=10.0, Y=10.0)]
    ops.append(Operation(OpKind.PEN_DOWN, at(3)))
    ops += [move(at(n), X=x, Y=y) for n, (x, y) in enumerate(SQUARE[1:], start=4)]
    ops += [Operation(OpKind.PEN_UP, at(8)), move(at(9), X=0.0, Y=0.0)]
    return Program("square", tuple(ops))


def _strokes(plotter: StationHarness) -> list[tuple[float, float]]:
    """Every pen-down move the emulator finished, where it ended."""
    return [
        (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))
        for e in plotter.gcode_emulator.event_log
        if e["event"] == "move" and e["pen"]
    ]


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=2)
    yield harness
    harness.close()


def test_a_grbl_board_whose_replies_freeze_2_5_s_mid_job_does_not_pause_it(
    grbl: StationHarness, tmp_path: Path
) -> None:
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    states: list[JobState] = []
    runner.stateChanged.connect(states.append)
    links: list[LinkState] = []
    grbl.station.model.linkStateChanged.connect(links.append)
    assert runner.load(_square()) == []
    runner.start()
    grbl.run_until(lambda: len(_strokes(grbl)) >= 1, timeout=20)
    relay = HeldReplies()
    grbl.loopback.set_manipulator(relay)
    grbl.run(2.5)
    assert relay.held  # its answers were there, held back
    relay.holding = False
    grbl.run_until(lambda: _finished(runner), timeout=60)

    assert runner.state is JobState.DONE
    assert JobState.PAUSED not in states
    assert LinkState.STALE in links and LinkState.LOST not in links  # amber, never red
    assert _strokes(grbl) == SQUARE[1:]  # every stroke once, in order


def _square_paused_by_silence(
    grbl: StationHarness, tmp_path: Path
) -> tuple[JobRunner, list[str], HeldReplies]:
    """The pen square under way, then the board's replies held until the job pauses."""
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    messages: list[str] = []
    runner.message.connect(messages.append)
    assert runner.load(_square()) == []
    runner.start()
    grbl.run_until(lambda: len(_strokes(grbl)) >= 1, timeout=20)
    relay = HeldReplies()
    grbl.loopback.set_manipulator(relay)
    grbl.run_until(lambda: runner.state is JobState.PAUSED, timeout=SILENCE_S + 1)
    return runner, messages, relay


def test_a_grbl_board_silent_past_the_loss_goes_on_by_itself_nothing_drawn_twice(
    grbl: StationHarness, tmp_path: Path
) -> None:
    runner, messages, relay = _square_paused_by_silence(grbl, tmp_path)
    grbl.run(2.0)
    relay.holding = False  # no Resume

    grbl.run_until(lambda: _finished(runner), timeout=60)
    assert runner.state is JobState.DONE
    assert _strokes(grbl) == SQUARE[1:]
    assert sum("the job goes on" in m for m in messages) == 1, messages


def test_a_grbl_board_that_restarted_while_silent_waits_for_the_operator(
    grbl: StationHarness, tmp_path: Path
) -> None:
    runner, messages, relay = _square_paused_by_silence(grbl, tmp_path)
    grbl.gcode_emulator.soft_reset()  # its reset button, while nobody heard it
    grbl.run(1.0)
    relay.holding = False
    grbl.run_until(lambda: grbl.station.model.link_state is LinkState.CONNECTED, timeout=5)
    strokes = len(_strokes(grbl))
    grbl.run(3.0)
    assert runner.state is JobState.PAUSED
    assert len(_strokes(grbl)) == strokes  # nothing moved on its own
    assert runner.needs_operator  # only the operator can say where the tool is now
    assert sum("restarted" in m for m in messages) == 1, messages  # said once


# --- a busy station is not a silent device ------------------------------------------------


def test_time_the_station_itself_was_not_running_is_not_the_devices_silence(
    grbl: StationHarness,
) -> None:
    """A real-time tick seconds late (the computer busy) finds the replies waiting unread."""
    session = grbl.gcode_session
    session.discounts_stalls = True  # as with its real-time timer
    model = grbl.station.model
    grbl.run(0.5)
    grbl.clock.advance(SILENCE_S + 1.0)  # nothing ran: no tick, no read
    session.tick()
    assert model.link_state is LinkState.CONNECTED
    # Without the station stalled, the same silence is one.
    grbl.loopback.set_manipulator(_silence(Direction.TO_HOST))
    grbl.run_until(lambda: model.link_state is LinkState.LOST, timeout=SILENCE_S + 1)


G92_JOB = """G21 G90
G0 X10 Y10
G92 X0 Y0
G91
G1 X5 F3000
G1 Y5
G1 X-5
G1 Y-5
G90
G0 X2 Y3
"""


def test_a_grbl_job_after_g92_silenced_mid_way_ends_at_the_same_machine_position(
    grbl: StationHarness, tmp_path: Path
) -> None:
    """The board kept its offset through the silence: the job goes on in the same frame."""
    from app.jobs.loaders import JobOptions, load_job

    profile = grbl.station.profile
    source = tmp_path / "g92.gcode"
    source.write_text(G92_JOB, encoding="utf-8")
    assert profile.gcode is not None
    options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
    program = load_job(source, ["X", "Y"], options)
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    assert runner.load(program) == []
    runner.start()
    grbl.run_until(lambda: grbl.gcode_emulator.work_offset()["X"] == 10.0, timeout=20)
    relay = HeldReplies()
    grbl.loopback.set_manipulator(relay)
    grbl.run_until(lambda: runner.state is JobState.PAUSED, timeout=SILENCE_S + 1)
    relay.holding = False
    grbl.run_until(lambda: _finished(runner), timeout=60)
    assert runner.state is JobState.DONE
    grbl.run_until(lambda: grbl.gcode_session.settled, timeout=10)
    position = grbl.gcode_emulator.position()
    assert (position["X"], position["Y"]) == pytest.approx((12.0, 13.0), abs=1e-3)
    assert grbl.gcode_emulator.work_offset()["X"] == pytest.approx(10.0)


def test_a_stop_asked_for_while_the_board_is_silent_is_carried_out_when_it_answers(
    grbl: StationHarness, tmp_path: Path
) -> None:
    """The operator's stop went into a silent line (hold and reset both lost): once the
    board is heard again it is held and reset, not left to run out the move it had."""
    from app.jobs.loaders import JobOptions, load_job

    profile = grbl.station.profile
    assert profile.gcode is not None
    source = tmp_path / "slow.gcode"
    source.write_text("G21 G90\nG0 X10 Y10\nG1 X290 F300\nG0 X0 Y0\n", encoding="utf-8")
    options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
    runner = JobRunner(grbl.station, tmp_path / "checkpoints")
    assert runner.load(load_job(source, ["X", "Y"], options)) == []
    runner.start()
    board = grbl.gcode_emulator
    grbl.run_until(lambda: board.position()["X"] > 12.0, timeout=20)  # on its 56 s move
    grbl.loopback.set_manipulator(_silence(Direction.TO_DEVICE, Direction.TO_HOST))
    runner.abort()  # its feed hold, and the reset after it, are lost on the way
    session = grbl.gcode_session
    grbl.run_until(lambda: grbl.station.model.link_state is LinkState.LOST, timeout=SILENCE_S + 1)
    assert board.state in ("Run", "Cycle") or board.position()["X"] < 290.0  # still moving
    grbl.loopback.set_manipulator(None)
    grbl.run_until(lambda: not session.stopping and session.machine_state == "Idle", timeout=10)
    stopped_at = board.position()["X"]
    assert stopped_at < 100.0  # held once heard again, far short of X 290
    grbl.run(3.0)
    assert board.position()["X"] == stopped_at  # and it stays there
