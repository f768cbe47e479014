"""End to end on the emulated winder: every nail drilled once, a wait, then the file's order.

The station runs the string-art profile against the in-process G-code
emulator on the harness's manual clock, through the job runner as the dock
does.  The emulator's event log is the judge, never the program: where the
drill went down, whether anything moved while the operator was asked to
insert the nails, and which nail each wrap of the needle went round.

Time: the profile's speeds are kept as they are (a 10 mm plunge at
3.75 mm/s² takes 3.3 s each way, a half turn of the base 6.2 s), so the
hexagon's 120 nails take about 950 emulated seconds to drill and its 300
connections another 3300; the cardioid's 200 nails and 400 connections take
longer still.  The drill phase runs whole (it is the same whatever the
sequence); the winding check winds the sample's first ``CONNECTIONS``
connections only — the program of a shortened job built from the same file
— so that each sample stays within seconds of wall time.
"""

from __future__ import annotations

import time
from collections import Counter
from collections.abc import Callable, Iterator
from dataclasses import dataclass, replace
from itertools import pairwise
from pathlib import Path

import numpy as np
import pytest
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.geometry import along_drill_axis_mm, shortest_turn
from app.jobs.formats.string_art.program import StringArtProgram, build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams, read_string_art
from app.jobs.program import OpKind
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from protocol.emulator.gcode_firmware import GcodeEvent
from tests.helpers.harness import StationHarness

#: Connections wound of each sample's sequence (see the module notes).
CONNECTIONS = 30
#: Emulated seconds the station is left alone while it waits (or is paused).
LEFT_ALONE_S = 20.0
ANGLE_TOLERANCE_DEG = 0.01
RADIUS_TOLERANCE_MM = 0.01
#: Generous bounds on emulated time, so that a hang fails instead of spinning.
DRILL_TIMEOUT_S = 2500.0
#: Z at a hole's bottom: 1 cm above the board plus 1 cm deep, along the 74.333° axis (S0-15).
DRILL_BOTTOM_Z = along_drill_axis_mm(20.0)
#: Z resolution: 133.3 microsteps a mm.
Z_STEP = 1 / 133.3
WIND_TIMEOUT_S = 1500.0

Position = dict[str, float]


@pytest.fixture
def winder(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("string-art"))
    harness.connect()
    harness.run_until(lambda: harness.gcode_session.planner_size > 0, timeout=1)
    yield harness
    harness.close()


@pytest.fixture
def runner(winder: StationHarness, tmp_path: Path) -> Iterator[JobRunner]:
    built = JobRunner(winder.station, tmp_path / "checkpoints")
    yield built
    built.deleteLater()


# --- reading the emulator's log --------------------------------------------------------------


def shortened(job: StringArtJob, connections: int) -> StringArtJob:
    """The same board and file, winding only the first ``connections`` connections."""
    return replace(
        job,
        sequence=job.sequence[: connections + 1],
        entry_lines=job.entry_lines[: connections + 1],
    )


def moves(winder: StationHarness, since: int = 0) -> list[GcodeEvent]:
    """The moves the emulator finished, from log entry ``since`` on."""
    return [e for e in winder.gcode_emulator.event_log[since:] if e["event"] == "move"]


def track(winder: StationHarness, since: int = 0) -> list[Position]:
    """Every place the tool stood: the end of each finished move and where a stop left it."""
    return [
        e["pos"] for e in winder.gcode_emulator.event_log[since:] if e["event"] in ("move", "reset")
    ]


def angle_off(a: float, b: float) -> float:
    """How far apart two angles are, whole turns ignored (0…180°)."""
    return abs(shortest_turn(b, a))


@dataclass
class Board:
    """The nails as the program places them, to name the nail at a place of the log."""

    angles: np.ndarray
    radii: np.ndarray

    @classmethod
    def of(cls, job: StringArtJob) -> Board:
        angles, radii = job.nail_polar()
        return cls(angles, radii)

    @property
    def count(self) -> int:
        return len(self.angles)

    def at(self, a: float, x: float) -> list[int]:
        """The nails at base angle ``a`` (any turn) and radius ``x``, within the tolerances."""
        return [
            k
            for k in range(self.count)
            if angle_off(a, float(self.angles[k])) <= ANGLE_TOLERANCE_DEG
            and abs(x - float(self.radii[k])) <= RADIUS_TOLERANCE_MM
        ]

    def inside(self, start: float, end: float) -> list[int]:
        """The nails strictly inside the turn from ``start`` to ``end`` (unwrapped degrees)."""
        low, high = min(start, end), max(start, end)
        middle = (low + high) / 2
        found = []
        for k, angle in enumerate(self.angles):
            nearest = middle + shortest_turn(middle, float(angle))  # the turn nearest the arc
            if low < nearest < high:
                found.append(k)
        return found

    def side(self, x: float) -> str:
        """Where a needle at radius ``x`` is: inside every nail, outside every nail, or among."""
        if x < float(self.radii.min()):
            return "in"
        if x > float(self.radii.max()):
            return "out"
        return "ring"


def drilled(log: list[GcodeEvent], board: Board) -> list[int]:
    """Each plunge (Z down to the hole's bottom, then straight back to 0) as the nail it made.

    FIDELITY S0-15/S0-16: the bottom is 20 mm / sin 74.333° from Z 0 (1 cm above the board).
    """
    found: list[int] = []
    previous: Position = {"A": 0.0, "X": 0.0, "Z": 0.0}
    for n, event in enumerate(log):
        pos = event["pos"]
        if pos["Z"] != previous["Z"]:
            # Z moves on its own, only down to the depth and straight back.
            assert (pos["A"], pos["X"]) == (previous["A"], previous["X"]), event
            if pos["Z"] != 0.0:
                assert pos["Z"] == pytest.approx(DRILL_BOTTOM_Z, abs=Z_STEP), event
                assert previous["Z"] == 0.0, event
                assert log[n + 1]["pos"] == {**pos, "Z": 0.0}, "no straight way back out"
                at = board.at(pos["A"], pos["X"])
                assert len(at) == 1, f"a plunge at A {pos['A']} X {pos['X']} is at nails {at}"
                found.append(at[0])
        previous = pos
    return found


def wound(places: list[Position], board: Board) -> list[int]:
    """The nails the needle went round, in order, from where it stood.

    The base turns only with the needle inside every nail or outside every
    nail; the needle crosses the ring only radially.  Between going out (at
    one angle) and coming back in (at another) it turns across exactly one
    nail: the one the thread wraps.  Out and back in at the same angle
    wraps nothing (a resumed job may do that), and the first move in — the
    start, beside the first nail, out and in at different angles — wraps
    nothing either.
    """
    out_at: float | None = None
    started = False
    side = board.side(places[0]["X"])
    visited: list[int] = []
    for previous, pos in pairwise(places):
        assert pos["Z"] == 0.0, f"the tool went down while winding, at {pos}"
        if pos["A"] != previous["A"]:
            assert pos["X"] == previous["X"], f"turned while moving radially: {previous}→{pos}"
            assert board.side(pos["X"]) != "ring", f"turned among the nails: {previous}→{pos}"
            continue
        now = board.side(pos["X"])
        if now == "ring" or now == side:
            continue
        if now == "out":
            out_at = pos["A"]
        elif not started:
            started = True
        elif out_at is not None and abs(out_at - pos["A"]) > 1e-6:
            across = board.inside(out_at, pos["A"])
            assert len(across) == 1, f"a wrap from A {out_at} to {pos['A']} crosses {across}"
            visited.append(across[0])
        side = now
    return visited


def first_gap(places: list[Position], board: Board) -> tuple[int, int]:
    """The two nails either side of where the needle first went in."""
    a = next(p for p in places if board.side(p["X"]) == "in")["A"]
    # The nail just clockwise of it (the least turn back to a nail) and the next one.
    before = min(range(board.count), key=lambda k: (a - float(board.angles[k])) % 360.0)
    return before, (before + 1) % board.count


def assert_no_turn_over_half(log: list[GcodeEvent]) -> None:
    previous = 0.0  # homed: the base starts at A = 0
    for event in log:
        a = event["pos"]["A"]
        assert abs(a - previous) <= 180.0 + 1e-6, f"a turn of {a - previous}° at t={event['t']}"
        previous = a


def run_to_end(winder: StationHarness, runner: JobRunner) -> None:
    winder.run_until(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED),
        timeout=WIND_TIMEOUT_S,
    )


# --- the samples -----------------------------------------------------------------------------


@pytest.mark.parametrize("sample", ["hexagon", "cardioid"])
def test_every_nail_is_drilled_once_then_it_waits_then_winds_in_file_order(
    winder: StationHarness, runner: JobRunner, data_dir: Path, sample: str
) -> None:
    """Drill every nail, wait untouched, wind the first connections with a pause half way.

    On the emulated winder, as its firmware (FIDELITY S0-15, S0-16, S0-18, S0-25): each
    plunge to 20 mm / sin 74.333°, the wait at nail 0 with every driver off, the drill's
    driver off after the winding.
    """
    wall = time.perf_counter()
    begun = winder.clock.now()
    full = read_string_art(data_dir / "samples" / f"string-art-{sample}" / "poradi.txt")
    job = shortened(full, CONNECTIONS)
    program = build_program(job, winder.station.profile)
    board = Board.of(job)
    asked: list[str] = []
    runner.waitingForOperator.connect(asked.append)

    assert runner.load(program) == []
    runner.start()
    winder.run_until(lambda: runner.state is not JobState.RUNNING, timeout=DRILL_TIMEOUT_S)

    # The drill phase: every nail once, in index order, at its angle and radius.
    assert runner.state is JobState.WAITING
    assert asked == [f"Insert the nails, tie the thread to nail {job.sequence[0]}"]
    drill_log = moves(winder)
    holes = drilled(drill_log, board)
    assert holes == list(range(job.params.nails))
    assert Counter(holes).most_common(1)[0][1] == 1

    # Waiting (FIDELITY S0-18, S0-25): the machine stands idle at nail 0, its drivers off,
    # and nothing moves, however long.
    assert winder.gcode_emulator.state == "Idle"
    standing = winder.gcode_emulator.position()
    assert standing["A"] % 360 == pytest.approx(0.0, abs=1e-3)
    assert standing["X"] == pytest.approx(float(board.radii[0]), abs=1e-3)
    assert standing["Z"] == pytest.approx(0.0, abs=1e-6)
    assert winder.gcode_emulator.drivers_off == {"A", "X", "Z"}
    logged = len(winder.gcode_emulator.event_log)
    winder.run(LEFT_ALONE_S)
    assert runner.state is JobState.WAITING
    assert moves(winder, logged) == []
    assert winder.gcode_emulator.position() == standing

    # The operator confirms: the winding, paused half way and resumed.
    confirmed_at = len(winder.gcode_emulator.event_log)
    runner.confirm()
    half_way = int(np.flatnonzero(program.entry_of_op == CONNECTIONS // 2)[0])
    winder.run_until(lambda: runner.done > half_way, timeout=WIND_TIMEOUT_S)
    runner.pause()
    # A pause lets the lines already sent be planned, then the machine runs them out.
    winder.run_until(lambda: runner.state is JobState.PAUSED, timeout=WIND_TIMEOUT_S)
    winder.run_until(lambda: winder.gcode_emulator.state == "Idle", timeout=WIND_TIMEOUT_S)
    paused_at = len(winder.gcode_emulator.event_log)
    winder.run(LEFT_ALONE_S)
    assert moves(winder, paused_at) == [], "it moved while paused"
    assert runner.done < len(program)
    runner.resume()
    run_to_end(winder, runner)
    assert runner.state is JobState.DONE
    assert winder.gcode_emulator.state == "Idle"
    assert winder.gcode_emulator.drivers_off == {"Z"}  # the drill's, off while winding

    # The winding starts beside the first nail, then goes round the nails in file order.
    places = [drill_log[-1]["pos"], *track(winder, confirmed_at)]
    first = job.sequence[0]
    assert first_gap(places, board) == (first, (first + 1) % job.params.nails)
    assert wound(places, board) == list(job.sequence[1:])

    # And no turn of the whole job was longer than half a turn.
    assert_no_turn_over_half(moves(winder))
    print(
        f"\n{sample}: {job.params.nails} nails drilled, {CONNECTIONS} connections wound in "
        f"{winder.clock.now() - begun:.0f} emulated s, {time.perf_counter() - wall:.1f} s wall"
    )


# --- stopped and resumed from the checkpoint ---------------------------------------------------

#: A small board, so that drilling it is short: 8 nails on a circle, every one wound.
SMALL = StringArtJob(StringArtParams(tvar=0, nails=8, radius_cm=8.0), (0, 3, 6, 1, 4, 7, 2, 5, 0))
#: The connection under way when the job is stopped.
STOPPED_AT = 4


@dataclass(frozen=True)
class Connection:
    """Where the needle goes for one connection: turn in, out, round the nail, back in."""

    before: float  # the base's angle before it
    gap: float  # the gap it turns to (inside) and goes out at
    beyond: float  # the gap on the nail's other side, where it comes back in
    nail_angle: float
    r_in: float
    r_out: float

    @classmethod
    def of(cls, program: StringArtProgram, entry: int) -> Connection:
        moving = program.indices_of(OpKind.MOVE)
        ops = moving[program.entry_of_op[moving] == entry]
        turn, out, wrap, _in = program.axis_positions(ops)
        before = program.axis_positions(ops[:1] - 1)[0][0]
        angles, _radii = program.job.nail_polar()
        nail = program.job.sequence[entry]
        target = float(turn[0]) + shortest_turn(float(turn[0]), float(angles[nail]))
        return cls(
            float(before),
            float(turn[0]),
            float(wrap[0]),
            target,
            program.needle_in_radius_mm,
            float(out[1]),  # this nail's out radius (the winding's start goes farther)
        )


def _between(value: float, a: float, b: float) -> bool:
    return min(a, b) < value < max(a, b)


#: Where the needle is when the job is stopped, as a test of the emulator's live position.
#: "round the nail, just begun" stops within a status report of the needle's going out:
#: the checkpoint still holds the move out as not run, so the way back must retrace the
#: path (turn back outside the ring, then in) rather than cut across the nails.
STOP_POINTS = [
    pytest.param(
        lambda p, c: abs(p["X"] - c.r_out) < 1e-6 and _between(p["A"], c.gap, c.nail_angle),
        id="round the nail, just begun",
    ),
    pytest.param(
        lambda p, c: (
            abs(p["X"] - c.r_in) < 1e-6 and _between(p["A"], (c.before + c.gap) / 2, c.gap)
        ),
        id="turning inside",
    ),
    pytest.param(
        lambda p, c: (
            abs(p["A"] - c.gap) < 1e-6 and _between(p["X"], (c.r_in + c.r_out) / 2, c.r_out)
        ),
        id="going out",
    ),
    pytest.param(
        lambda p, c: abs(p["X"] - c.r_out) < 1e-6 and _between(p["A"], c.nail_angle, c.beyond),
        id="round the nail, past it",
    ),
    pytest.param(
        lambda p, c: (
            abs(p["A"] - c.beyond) < 1e-6 and _between(p["X"], c.r_in, (c.r_in + c.r_out) / 2)
        ),
        id="coming in",
    ),
]


@pytest.mark.parametrize("stop", STOP_POINTS)
def test_stopped_while_winding_and_resumed_from_the_checkpoint_no_nail_twice_or_missed(
    winder: StationHarness, runner: JobRunner, stop: Callable[[Position, Connection], bool]
) -> None:
    """Abort in the middle of a move, resume from the checkpoint: still the file's order."""
    program = build_program(SMALL, winder.station.profile)
    board = Board.of(SMALL)
    connection = Connection.of(program, STOPPED_AT)
    assert runner.load(program) == []
    runner.start()
    winder.run_until(lambda: runner.state is JobState.WAITING, timeout=DRILL_TIMEOUT_S)
    confirmed_at = len(winder.gcode_emulator.event_log)
    standing = winder.gcode_emulator.position()
    runner.confirm()
    winder.run_until(
        lambda: stop(winder.gcode_emulator.position(), connection), timeout=WIND_TIMEOUT_S
    )
    assert winder.gcode_emulator.state == "Run"
    runner.abort()
    # A feed hold brakes at the winder's acceleration (seconds from top speed); the reset
    # that drops the buffered lines follows once the hold is complete.
    winder.run_until(lambda: winder.gcode_emulator.state == "Idle", timeout=10)
    assert runner.state is JobState.ABORTED
    assert not winder.gcode_session.stopping
    assert runner.resume_available is not None

    runner.resume_from_checkpoint()
    run_to_end(winder, runner)
    assert runner.state is JobState.DONE
    places = [standing, *track(winder, confirmed_at)]
    assert wound(places, board) == list(SMALL.sequence[1:])
    assert_no_turn_over_half(moves(winder))


def test_the_log_readers_name_the_right_nails() -> None:
    """The helpers that judge the log: a wrap names the one nail strictly inside the turn."""
    board = Board(np.array([0.0, 90.0, 180.0, 270.0]), np.full(4, 100.0))
    assert board.inside(-45.0, 45.0) == [0]
    assert board.inside(45.0, -45.0) == [0]
    assert board.inside(315.0, 405.0) == [0]
    assert board.inside(100.0, 170.0) == []
    assert board.inside(80.0, 190.0) == [1, 2]
    assert board.at(720.0 + 0.005, 100.0) == [0]
    assert board.at(90.0, 100.02) == []
    places = [
        {"A": 45.0, "X": 110.0, "Z": 0.0},
        {"A": 45.0, "X": 90.0, "Z": 0.0},  # the start: in beside nail 0
        {"A": 135.0, "X": 90.0, "Z": 0.0},
        {"A": 135.0, "X": 110.0, "Z": 0.0},
        {"A": 225.0, "X": 110.0, "Z": 0.0},  # round nail 2
        {"A": 225.0, "X": 90.0, "Z": 0.0},
    ]
    assert first_gap(places, board) == (0, 1)
    assert wound(places, board) == [2]
    with pytest.raises(AssertionError, match="turned while moving radially"):
        wound([*places[:3], {"A": 140.0, "X": 110.0, "Z": 0.0}], board)
    with pytest.raises(AssertionError, match="turned among the nails"):
        wound(
            [*places[:3], {"A": 135.0, "X": 100.0, "Z": 0.0}, {"A": 150.0, "X": 100.0, "Z": 0.0}],
            board,
        )
