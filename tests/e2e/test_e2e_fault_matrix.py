"""End to end: the link cut at every phase of an operation, pulled and silent, on every dialect.

Each runnable dialect's emulator runs as its own process on a pty
(``python -m protocol.emulator --pty --log``), one per profile for the whole
module; a :class:`~tests.helpers.fault_bridge.FaultBridge` stands between it
and a real-clock station as the cable.  Each job has a WAIT (the operator
changing a bit, say) just before the operation under test, ``k``; when the
runner reaches it the fault is set up, then the operator confirms:

* **before** — the link is cut during the WAIT, so ``k`` is not on the wire yet
  (the operator, not knowing, confirms: a pulled port refuses it, a silent
  link swallows it — on the drill that is then a ``V`` that went out
  unacknowledged, and the station asks);
* **sent** — ``k``'s bytes are dropped (the first message of ``k`` and all after);
* **received** — ``k`` arrives whole, then the link goes (the device runs it;
  whatever it answers is lost);
* **done** — the reply that says ``k`` is done is the first thing lost.

The cut is either *pulled* (the station's port vanishes, and reappears at the
same path) or *silent* (the port stays, nothing passes either way; only the
station's liveness can tell).  The station must notice (link lost, job
paused), and once the cable is back the operator resumes as the manual
(docs/manual/jobs.md) says: nothing but Resume, and for the drill's lost-receipt
case the answer to the question the station asks, given from what the board
shows (the emulator's own log: was the hole drilled?).  A second test answers that question both
ways, right and wrong, and the log follows the answer.

The emulator's log is the judge: every operation ran exactly once (holes,
absolute moves, relative moves, pen-down strokes), and the job ends DONE.
G-code pen-up travel may be retraced by the resume's own set-up move; a
pen-down stroke never is.

The liveness timeouts and the reconnection back-off are shortened (monkeypatched
module constants and the station's delays) so the whole matrix stays short.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pytest
from PySide6.QtCore import QTimer
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station
from protocol.stage.codec import MOVING_STATUSES as STAGE_MOVING
from protocol.stage.codec import CommandFrame, CommandId, EchoFrame, EchoType, parse_line
from protocol.usb3.codec import Move, Position, decode_command, decode_reply
from tests.helpers.emulator_process import device_path, start_emulator, stop
from tests.helpers.fault_bridge import Action, Cut, Direction, FaultBridge, Watch

pytestmark = pytest.mark.skipif(not hasattr(os, "openpty"), reason="no pseudo-terminals here")

PHASES = ("before", "sent", "received", "done")
#: Each step of a case (connect, notice the cut, reconnect, finish) is bounded by this.
STEP_TIMEOUT_MS = 15_000
#: How long the emulator's log may take to show the job's last operation once it is DONE.
LOG_SETTLE_MS = 3000
#: G-code's real-time bytes: never part of a line.
GCODE_REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))


@dataclass
class Dialect:
    """What the matrix needs to know of one profile: its job, its wire, its log."""

    profile: str
    time_scale: float
    to_device_end: bytes
    to_host_end: bytes
    job: Callable[[Path], Program]
    #: The watch of a phase (sent, received, done) for the program's operation ``k``.
    watch: Callable[[str, Program, int, Station], Watch]
    #: Asserts from the emulator's log lines of this case that every operation ran once.
    check: Callable[[list[str], Program, Station], None]
    #: Whether the board shows operation ``k`` done (the operator's look, for a question).
    ran: Callable[[list[str], Program, int, Station], bool]
    ignored_to_device: frozenset[int] = frozenset()
    prepare: Callable[[QtBot, Station], None] = lambda qtbot, station: None
    #: The stage's command period (``--period``): the station judges a move by its echoes.
    period_ms: int | None = None


def _k(program: Program) -> int:
    """The operation under test: the first one after the job's WAIT."""
    return next(i for i, op in enumerate(program) if op.kind is OpKind.WAIT) + 1


# --- the drill ------------------------------------------------------------------------

_HOLE = re.compile(r"^\d+\.\d+ hole X(-?\d+) Y(-?\d+)$")


def _drill_job(tmp_path: Path) -> Program:
    src = SourceRef("holes.drl", 0)

    def at(line: int) -> SourceRef:
        return SourceRef(src.file, line)

    ops = [
        move(at(1), X=10.0, Y=10.0),
        Operation(OpKind.DRILL, at(2)),
        move(at(3), X=20.0, Y=12.0),
        Operation(OpKind.WAIT, at(4), message="Check the bit"),
        Operation(OpKind.DRILL, at(5)),
        move(at(6), X=30.0, Y=14.0),
        Operation(OpKind.DRILL, at(7)),
    ]
    return Program("holes", ops)


def _drill_holes(lines: list[str]) -> Counter[tuple[int, int]]:
    found: Counter[tuple[int, int]] = Counter()
    for line in lines:
        if match := _HOLE.match(line.strip()):
            found[(int(match.group(1)), int(match.group(2)))] += 1
    return found


def _drill_hole_of(program: Program, index: int, station: Station) -> tuple[int, int]:
    session = station.drill_session
    assert session is not None
    last = next(op for op in reversed(program.operations[:index]) if op.kind is OpKind.MOVE)
    return session.to_microsteps(0, last.target["X"]), session.to_microsteps(1, last.target["Y"])


def _drill_watch(phase: str, program: Program, k: int, station: Station) -> Watch:
    def watch(direction: Direction, message: bytes) -> Action | None:
        if phase in ("sent", "received") and direction is Direction.TO_DEVICE:
            if message.strip() == b"V":
                return Action.DROP if phase == "sent" else Action.PASS
        if phase == "done" and direction is Direction.TO_HOST and message.strip() == b"DV":
            return Action.DROP
        return None

    return watch


def _drill_check(lines: list[str], program: Program, station: Station) -> None:
    expected = Counter(
        _drill_hole_of(program, i, station)
        for i, op in enumerate(program)
        if op.kind is OpKind.DRILL
    )
    assert _drill_holes(lines) == expected


def _drill_ran(lines: list[str], program: Program, k: int, station: Station) -> bool:
    return _drill_holes(lines)[_drill_hole_of(program, k, station)] > 0


DRILL = Dialect("pcb-drill", 50, b"\r", b"\n", _drill_job, _drill_watch, _drill_check, _drill_ran)


# --- G-code -----------------------------------------------------------------------------


def _gcode_job(profile: str) -> Callable[[Path], Program]:
    def build(tmp_path: Path) -> Program:
        settings = load_profile(profile).gcode
        source = tmp_path / "square.gcode"
        source.write_text(
            "\n".join(
                [
                    "G0 X5 Y5",
                    settings.pen_down,
                    "G1 X15 Y5 F3000",
                    "M0",
                    "G1 X15 Y15",
                    "G1 X5 Y15",
                    "G1 X5 Y5",
                    settings.pen_up,
                    "G0 X0 Y0",
                ]
            )
            + "\n",
            encoding="utf-8",
        )
        return load_job(source, ["X", "Y"], JobOptions(gcode=settings))

    return build


def _is_k(message: bytes) -> bool:
    return message.startswith(b"G1") and b"X15" in message and b"Y15" in message


def _gcode_watch(phase: str, program: Program, k: int, station: Station) -> Watch:
    unanswered: list[bytes] = []

    def watch(direction: Direction, message: bytes) -> Action | None:
        text = message.strip()
        if direction is Direction.TO_DEVICE:
            if not text:
                return None
            if phase in ("sent", "received") and _is_k(text):
                return Action.DROP if phase == "sent" else Action.PASS
            unanswered.append(text)
            return None
        low = text.lower()
        if (low == b"ok" or low.startswith(b"error:")) and unanswered:
            line = unanswered.pop(0)
            if phase == "done" and _is_k(line):
                return Action.DROP
        elif low.startswith(b"grbl"):
            unanswered.clear()
        return None

    return watch


def _gcode_events(lines: list[str]) -> list[dict[str, Any]]:
    found = []
    for line in lines:
        try:
            found.append(json.loads(line))
        except ValueError:
            continue
    return found


def _strokes(program: Program) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    path = program.path(("X", "Y"))
    strokes = []
    for row in range(1, len(path.coords)):
        if path.pen[row]:
            a, b = path.coords[row - 1], path.coords[row]
            strokes.append(((round(a[0], 3), round(a[1], 3)), (round(b[0], 3), round(b[1], 3))))
    return strokes


def _gcode_check(lines: list[str], program: Program, station: Station) -> None:
    moves = [e for e in _gcode_events(lines) if e["event"] == "move"]
    drawn = []
    where: tuple[float, float] | None = None
    for event in moves:
        end = (round(event["pos"]["X"], 3), round(event["pos"]["Y"], 3))
        if event["pen"] and where is not None:
            drawn.append((where, end))
        where = end
    # Every pen-down stroke of the file exactly once, in order; nothing else drawn.
    assert drawn == _strokes(program)
    assert where == (0.0, 0.0)


def _gcode_ran(lines: list[str], program: Program, k: int, station: Station) -> bool:
    raise AssertionError("the G-code rule never asks the operator")


def _gcode_prepare(qtbot: QtBot, station: Station) -> None:
    session = station.gcode_session
    assert session is not None
    try:
        qtbot.waitUntil(lambda: session.planner_size > 0, timeout=STEP_TIMEOUT_MS)
    except Exception:
        status = session.status
        if status is None or status.state != "Hold":
            raise AssertionError(f"no idle report (last: {status})") from None
        # The previous case's cable went between the station's hold and its reset (the stop
        # on closing): the board still holds, as a real one would. The operator resets it.
        session.soft_reset()
        try:
            qtbot.waitUntil(lambda: session.planner_size > 0, timeout=STEP_TIMEOUT_MS)
        except Exception:
            raise AssertionError(f"no idle report after a reset (last: {session.status})") from None


def _gcode(profile: str) -> Dialect:
    return Dialect(
        profile,
        20,
        b"\n",
        b"\n",
        _gcode_job(profile),
        _gcode_watch,
        _gcode_check,
        _gcode_ran,
        GCODE_REALTIME,
        _gcode_prepare,
    )


# --- the XY stage ------------------------------------------------------------------------

STAGE_TARGETS = [(10.0, 10.0), None, (30.0, 15.0), (5.0, 25.0)]
USB3_TARGETS = [(0.25, 0.5), (0.75, 0.25), None, (0.5, 1.0), (0.25, 0.75)]


def _points_job(targets: list[tuple[float, float] | None]) -> Callable[[Path], Program]:
    def build(tmp_path: Path) -> Program:
        ops: list[Operation] = []
        for line, target in enumerate(targets, start=1):
            where = SourceRef("route.txt", line)
            if target is None:
                ops.append(Operation(OpKind.WAIT, where, message="Check the sample"))
            else:
                ops.append(move(where, X=target[0], Y=target[1]))
        return Program("route", ops)

    return build


def _um(mm: float) -> int:
    return round(mm * 1000)


def _stage_watch(phase: str, program: Program, k: int, station: Station) -> Watch:
    target = program[k].target
    wanted = {0: _um(target["X"]), 1: _um(target["Y"])}
    seen = {0: False, 1: False}
    where: dict[int, int] = {}
    still = {0: False, 1: False}

    def watch(direction: Direction, message: bytes) -> Action | None:
        frame = parse_line(message + b"\n", 2)
        if direction is Direction.TO_DEVICE:
            if not isinstance(frame, CommandFrame):
                return None
            for axis, packet in enumerate(frame.packets):
                if packet.command == CommandId.MOVE_ABS and packet.data == wanted.get(axis):
                    first = not any(seen.values())
                    seen[axis] = True
                    if phase == "sent" and first:
                        return Action.DROP
                    if phase == "received" and all(seen.values()):
                        return Action.PASS
            return None
        if phase == "done" and isinstance(frame, EchoFrame) and all(seen.values()):
            # A packet is a position only every few frames (the others carry parameters),
            # but every packet tells its axis's status.
            for axis, packet in enumerate(frame.packets[:2]):
                if packet.type == EchoType.POSITION:
                    where[axis] = packet.data
                still[axis] = packet.status not in STAGE_MOVING
            if where == wanted and all(still.values()):
                return Action.DROP
        return None

    return watch


def _stage_moves(lines: list[str]) -> list[tuple[int, int]]:
    return [
        (int(fields[1]), int(fields[3]))
        for fields in (line.split() for line in lines)
        if len(fields) == 5 and fields[2] == "MOVE_ABS" and fields[4] == "1"
    ]


def _stage_check(lines: list[str], program: Program, station: Station) -> None:
    expected = [
        (axis, _um(op.target[name]))
        for op in program
        if op.kind is OpKind.MOVE
        for axis, name in enumerate("XY")
    ]
    assert _stage_moves(lines) == expected


STAGE = Dialect(
    "xy-stage",
    40,
    b"\n",
    b"\n",
    _points_job(STAGE_TARGETS),
    _stage_watch,
    _stage_check,
    lambda lines, program, k, station: pytest.fail("the stage rule never asks the operator"),
    period_ms=40,
)


# --- the usb3 unit ------------------------------------------------------------------------

USB3_COUNTS_PER_MM = 6400  # M6 thread (1 mm a turn), the unit's default
_USB3_DIRECTION = re.compile(r"SetDirection\(signs=\((-?1), (-?1), (-?1)\)\)")
_USB3_MOVE = re.compile(r"Move\(axis=<AxisId\.(\w): \d>, count=(\d+)\)")


def _usb3_watch(phase: str, program: Program, k: int, station: Station) -> Watch:
    target = program[k].target
    ends = {
        "X": round(target["X"] * USB3_COUNTS_PER_MM),
        "Y": round(target["Y"] * USB3_COUNTS_PER_MM),
    }
    at: dict[str, int] = {}
    sent: list[str] = []

    def watch(direction: Direction, message: bytes) -> Action | None:
        if direction is Direction.TO_DEVICE:
            _, command = decode_command(message + b";")
            if isinstance(command, Move) and command.count:
                sent.append(command.axis.name)
                if phase == "sent" and len(sent) == 1:
                    return Action.DROP
                if phase == "received" and len(sent) == 2:
                    return Action.PASS
            return None
        _, reply = decode_reply(message + b";")
        if isinstance(reply, Position) and reply.axis.name in ends:
            at[reply.axis.name] = reply.count
            if phase == "done" and len(sent) == 2 and at == ends:
                return Action.DROP
        return None

    return watch


def _usb3_moves(lines: list[str]) -> list[tuple[str, int]]:
    signs = {"X": 1, "Y": 1, "Z": 1}
    moves: list[tuple[str, int]] = []
    for line in lines:
        if (direction := _USB3_DIRECTION.search(line)) is not None:
            signs = dict(zip("XYZ", (int(s) for s in direction.groups()), strict=True))
        elif (found := _USB3_MOVE.search(line)) is not None and int(found.group(2)):
            axis = found.group(1)
            moves.append((axis, signs[axis] * int(found.group(2))))
    return moves


def _usb3_check(lines: list[str], program: Program, station: Station) -> None:
    # Every line after the unit was zeroed for this case.
    start = max(i for i, line in enumerate(lines) if "ZeroAll" in line)
    expected: list[tuple[str, int]] = []
    where = {"X": 0.0, "Y": 0.0}
    for op in program:
        if op.kind is not OpKind.MOVE:
            continue
        for axis in "XY":
            if op.target[axis] != where[axis]:
                delta = round((op.target[axis] - where[axis]) * USB3_COUNTS_PER_MM)
                expected.append((axis, delta))
            where[axis] = op.target[axis]
    assert _usb3_moves(lines[start:]) == expected


def _usb3_prepare(qtbot: QtBot, station: Station) -> None:
    session = station.usb3_session
    assert session is not None
    qtbot.waitUntil(lambda: len(session.threads) == 3, timeout=STEP_TIMEOUT_MS)
    session.zero_all()
    qtbot.waitUntil(
        lambda: all(a.position == 0.0 and a.status_text == "idle" for a in station.model.axes),
        timeout=STEP_TIMEOUT_MS,
    )


USB3 = Dialect(
    "usb3",
    40,
    b";",
    b";",
    _points_job(USB3_TARGETS),
    _usb3_watch,
    _usb3_check,
    lambda lines, program, k, station: pytest.fail("the usb3 rule never asks the operator"),
    prepare=_usb3_prepare,
)


DIALECTS = {
    "pcb-drill": DRILL,
    "grbl-plotter": _gcode("grbl-plotter"),
    "corexy-plotter": _gcode("corexy-plotter"),
    "xy-stage": STAGE,
    "usb3": USB3,
}


# --- fixtures -------------------------------------------------------------------------------


class Emulators:
    """One emulator process per profile for the module: (device path, log path)."""

    def __init__(self, directory: Path) -> None:
        self.directory = directory
        self.running: dict[str, tuple[Any, str, Path]] = {}

    def get(self, dialect: Dialect) -> tuple[str, Path]:
        if dialect.profile not in self.running:
            log = self.directory / f"{dialect.profile}.log"
            process = start_emulator(
                "--profile",
                dialect.profile,
                "--time-scale",
                str(dialect.time_scale),
                "--log",
                str(log),
            )
            try:
                path = device_path(process)
            except AssertionError:
                stop(process)
                raise
            self.running[dialect.profile] = (process, path, log)
        _, path, log = self.running[dialect.profile]
        return path, log

    def stop_all(self) -> None:
        for process, _, _ in self.running.values():
            stop(process)


@pytest.fixture(scope="module")
def emulators(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Emulators]:
    running = Emulators(tmp_path_factory.mktemp("emulators"))
    try:
        yield running
    finally:
        running.stop_all()


@pytest.fixture
def short_timeouts(monkeypatch: pytest.MonkeyPatch) -> None:
    """Liveness in about a second instead of several: the matrix has many silences to sit out.

    Not much shorter: on a loaded machine a shorter silence is sometimes a false loss
    before the fault is set up (seen at 0.8 s on the usb3 unit at a load of 14 on 2 cores).
    """
    monkeypatch.setattr("app.machines.drill.queue.RECEIPT_TIMEOUT_S", 0.8)  # read there
    # The drill's emulator runs 50 times faster than the station's timing table expects.
    monkeypatch.setattr("app.machines.drill.session.DONE_FACTOR", 0.2)
    monkeypatch.setattr("app.machines.drill.session.DONE_MARGIN_S", 0.8)
    monkeypatch.setattr("app.machines.gcode.timing.SILENCE_S", 1.2)
    monkeypatch.setattr("app.machines.stage.session.LOST_AFTER_S", 1.2)
    monkeypatch.setattr("app.machines.usb3.session.POLL_AFTER_S", 0.5)
    monkeypatch.setattr("app.machines.usb3.session.STALE_AFTER_S", 0.9)
    monkeypatch.setattr("app.machines.usb3.session.LOST_AFTER_S", 1.5)


def _log_since(log: Path, offset: int) -> list[str]:
    if not log.exists():
        return []
    with log.open("rb") as handle:
        handle.seek(offset)
        return handle.read().decode("utf-8", "replace").splitlines()


# --- the matrix ---------------------------------------------------------------------------


#: The operator's answer to the drill's question: (log lines, program, operation, station) →
#: drill it again.
Answer = Callable[[list[str], Program, int, Station], bool]
#: Asserts, from the emulator's log lines of the case, what the machine did.
Judge = Callable[[list[str], Program, Station], None]


@dataclass
class Outcome:
    """How a case went, for its MATRIX line."""

    resumes: int
    decided: list[bool]

    def __str__(self) -> str:
        answers = ", ".join(
            "drill again" if again else "count as drilled" for again in self.decided
        )
        return f"{self.resumes} resume(s)" + (f"; asked: {answers}" if answers else "")


def run_case(
    qtbot: QtBot,
    emulators: Emulators,
    tmp_path: Path,
    dialect: Dialect,
    phase: str,
    cut: Cut,
    answer: Answer,
    judge: Judge,
) -> Outcome:
    """Run the dialect's job with the link cut at ``phase`` of operation k; judge the log."""
    device, log = emulators.get(dialect)
    offset = log.stat().st_size if log.exists() else 0
    bridge = FaultBridge(
        device,
        tmp_path / "port",
        to_device_end=dialect.to_device_end,
        to_host_end=dialect.to_host_end,
        ignored_to_device=dialect.ignored_to_device,
    )
    station = Station(load_profile(dialect.profile))
    station.reconnect_delays = (0.1, 0.2, 0.4)
    if dialect.period_ms is not None:
        station.set_period_ms(dialect.period_ms)
    messages: list[str] = []

    def until(condition: Callable[[], bool], what: str) -> None:
        try:
            qtbot.waitUntil(condition, timeout=STEP_TIMEOUT_MS)
        except Exception:
            raise AssertionError(f"{what}: {messages[-8:]}") from None

    try:
        station.model.message.connect(messages.append)
        station.connect_serial(str(bridge.link))
        until(lambda: station.model.link_state is LinkState.CONNECTED, "never connected")
        dialect.prepare(qtbot, station)
        program = dialect.job(tmp_path)
        k = _k(program)
        runner = JobRunner(station, tmp_path / "checkpoints")
        runner.message.connect(messages.append)
        questions: list[str] = []
        runner.decisionNeeded.connect(lambda question, *_: questions.append(question))
        states: list[JobState] = []
        runner.stateChanged.connect(states.append)

        def at_the_wait(_: str) -> None:
            if phase == "before":
                bridge.cut(cut)
            else:
                bridge.arm(dialect.watch(phase, program, k, station), cut)
            QTimer.singleShot(0, runner.confirm)

        runner.waitingForOperator.connect(at_the_wait)
        assert runner.load(program) == []
        runner.start()
        # A hiccup before the fault (a loaded machine can miss a liveness deadline) pauses
        # the job for the link like any loss: the operator resumes, and the case goes on.
        for _ in range(3):
            until(
                lambda: (
                    bridge.fired.is_set()
                    or (
                        runner.state is JobState.PAUSED
                        and runner.question is None
                        and station.model.link_state is LinkState.CONNECTED
                    )
                ),
                "the fault was never set up",
            )
            if bridge.fired.is_set():
                break
            runner.resume()
        # The station notices by itself: the port gone, or no reply in time.
        until(lambda: station.model.link_state is LinkState.LOST, "the loss went unnoticed")
        until(lambda: runner.state is JobState.PAUSED, "the job did not pause")
        # Paused for the link, and saying so (not, say, "the unit stopped short").
        assert any(m.startswith("Job paused") and "link lost" in m for m in messages), messages
        bridge.restore()

        # The operator: Resume once the machine is back; a question answered by ``answer``.
        outcome = Outcome(0, [])
        for _ in range(6):
            until(
                lambda: (
                    runner.state in (JobState.DONE, JobState.FAILED)
                    or (
                        runner.state is JobState.PAUSED
                        and station.model.link_state is LinkState.CONNECTED
                    )
                ),
                "the machine never came back, or the job never ended",
            )
            if runner.state in (JobState.DONE, JobState.FAILED):
                break
            changes = len(states)
            if runner.question is not None:
                assert runner.question == k, (runner.question, k)
                again = answer(_log_since(log, offset), program, runner.question, station)
                outcome.decided.append(again)
                runner.decide(again=again)
            else:
                outcome.resumes += 1
                runner.resume()
            if len(states) == changes:
                raise AssertionError(f"the operator's answer did not take: {messages[-6:]}")
        assert runner.state is JobState.DONE, messages[-5:]
        if questions:
            # Only the drill asks, and only when its V may or may not have run.
            assert dialect is DRILL and phase in ("received", "before", "sent"), questions

        # The last operation's trace is in the log once the device is done with it.
        def judged() -> bool:
            try:
                judge(_log_since(log, offset), program, station)
            except AssertionError:
                return False
            return True

        with contextlib.suppress(Exception):
            qtbot.waitUntil(judged, timeout=LOG_SETTLE_MS)
        judge(_log_since(log, offset), program, station)
        return outcome
    finally:
        station.shutdown()
        bridge.close()


@pytest.mark.parametrize("cut", [Cut.PULLED, Cut.SILENT], ids=lambda c: c.value)
@pytest.mark.parametrize("phase", PHASES)
@pytest.mark.parametrize("profile", list(DIALECTS))
def test_a_link_cut_at_any_phase_of_an_operation_runs_every_operation_once(
    qtbot: QtBot,
    emulators: Emulators,
    short_timeouts: None,
    tmp_path: Path,
    profile: str,
    phase: str,
    cut: Cut,
) -> None:
    """The operator answers the drill's question from the board: every operation once."""
    dialect = DIALECTS[profile]

    def from_the_board(lines: list[str], program: Program, index: int, station: Station) -> bool:
        return not dialect.ran(lines, program, index, station)

    outcome = run_case(
        qtbot, emulators, tmp_path, dialect, phase, cut, from_the_board, dialect.check
    )
    print(f"\nMATRIX | {profile} | {phase} | {cut.value} | DONE, each op once; {outcome}")


@pytest.mark.parametrize("again", [True, False], ids=["drill-again", "count-as-drilled"])
@pytest.mark.parametrize("phase", ["sent", "received"])
def test_the_drills_question_is_answered_as_the_operator_says_either_way(
    qtbot: QtBot,
    emulators: Emulators,
    short_timeouts: None,
    tmp_path: Path,
    phase: str,
    again: bool,
) -> None:
    """Where the rule asks, the log follows the operator's answer, right or wrong.

    ``V`` dropped (sent): the hole is not drilled, so *count it* leaves it out and
    *again* drills it once; ``V`` delivered with its ``RV`` lost (received): the
    hole is drilled, so *again* drills it a second time.  Every other hole once.
    """
    drilled_before = phase == "received"

    def judge(lines: list[str], program: Program, station: Station) -> None:
        expected = Counter(
            _drill_hole_of(program, i, station)
            for i, op in enumerate(program)
            if op.kind is OpKind.DRILL
        )
        expected[_drill_hole_of(program, _k(program), station)] = int(drilled_before) + int(again)
        assert _drill_holes(lines) == +expected

    outcome = run_case(
        qtbot,
        emulators,
        tmp_path,
        DRILL,
        phase,
        Cut.SILENT,
        lambda lines, program, index, station: again,
        judge,
    )
    assert outcome.decided == [again]
