"""One fault-relay run: emulator process, relay, ``stepdeck run`` process, and the verdict.

Everything is a separate process but the relay (a thread of the caller):
the emulator on its own pty with ``--log``, and the station as an operator
would start it, ``stepdeck run JOB --profile P --port PORT --yes``, with no
one at its terminal (a question it asks ends the job, cleanly).  The
station's port is the relay's, behind a symlink in the run's own
directory, so runs in parallel never share anything.

The verdict comes from :mod:`tests.helpers.relay_judge`: the operations in
the emulator's log when the station ended, and once the device settled.
"""

from __future__ import annotations

import os
import select
import subprocess
import sys
import time
import tty
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path
from typing import Any, Protocol

from app.jobs.formats.string_art.geometry import along_drill_axis_mm, nail_polar
from tests.helpers import grbl_sim
from tests.helpers.emulator_process import ROOT, device_path, start_emulator, stop
from tests.helpers.fault_bridge import Direction
from tests.helpers.fault_relay import Fault, FaultKind, FaultRelay, random_fault
from tests.helpers.relay_judge import (
    BOOT_MARK,
    Judgement,
    NailBoard,
    Track,
    corexy_stroke_part_of,
    drill_holes,
    gcode_strokes,
    grbl_sim_part_of,
    grbl_sim_same_stroke,
    grbl_sim_strokes,
    in_box,
    judge,
    last_words,
    same_stroke,
    stage_targets,
    string_art_ops,
    stroke_part_of,
    usb3_joined,
    usb3_part_of,
    usb3_same,
    usb3_targets,
)

#: G-code's real-time bytes: never part of a line.
GCODE_REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))
#: A station that has not ended this long after the fault's effect ended is hung.
HANG_AFTER_S = float(os.environ.get("STEPDECK_RELAY_HANG_S", "20"))
#: A job whose fault was never reached has this long more (a clean run takes a few seconds).
NOT_REACHED_S = 20.0
#: However it goes on moving, a run is given up this long after its start.
GIVE_UP_S = 240.0
#: Faults that last a while: the station has HANG_AFTER_S once they are over.
TIMED = frozenset({FaultKind.DELAY, FaultKind.SILENCE, FaultKind.REOPEN})
#: How long the device is left to finish what it was doing once the station ended.
SETTLE_S = 1.0


@dataclass(frozen=True)
class RelayDialect:
    """What a run needs of one profile: its job, its wire, its log."""

    profile: str
    time_scale: float
    to_device_end: bytes
    to_host_end: bytes
    #: Writes the job file into a directory; returns its path.
    write_job: Callable[[Path], Path]
    #: The job's operations, and the log's, as the judge's tracks.
    tracks: Callable[[str, str], dict[str, Track[Any, Any]]]
    #: Bytes a clean run carries each way (measured; it sizes where a fault falls).
    traffic: dict[Direction, int]
    ignored_to_device: frozenset[int] = frozenset()
    #: The device at the cable's far end (the emulator, unless grbl-sim).
    board: Callable[[RelayDialect, Path], Board] = lambda dialect, workdir: EmulatorBoard(
        dialect, workdir
    )
    #: The name runs are known by (the profile, unless another board runs it).
    name: str = ""

    @property
    def key(self) -> str:
        return self.name or self.profile


class Board(Protocol):
    """A device process on a pty, its log, and what happens when its port reopens."""

    #: Whether :meth:`reopened` waits for the station to open its port again (an Arduino's
    #: DTR restarts the board then) rather than running as the port comes back.
    restarts_on_open: bool

    def start(self) -> str:
        """Started: its device path."""

    def reopened(self) -> str | None:
        """The station's port came back: a board that restarts then gives its new path."""

    def log(self) -> str:
        """What the machine did so far (the text the dialect's tracks read)."""

    def progress(self) -> int:
        """A number that changes only as the machine moves (constant if it cannot tell)."""

    def stop(self) -> None: ...


class EmulatorBoard:
    """``stepdeck-emulator --pty --log``: the emulated firmware, untouched by a reopen."""

    restarts_on_open = False

    def __init__(self, dialect: RelayDialect, workdir: Path) -> None:
        self.dialect = dialect
        self.path = workdir / "emulator.log"
        self.process: subprocess.Popen[bytes] | None = None

    def start(self) -> str:
        scale = str(self.dialect.time_scale)
        self.process = start_emulator(
            "--profile", self.dialect.profile, "--time-scale", scale, "--log", str(self.path)
        )
        return device_path(self.process)

    def reopened(self) -> str | None:
        return None

    def log(self) -> str:
        return _read(self.path)

    def progress(self) -> int:
        return 0  # the log also grows with every query: no sign of motion

    def stop(self) -> None:
        if self.process is not None:
            stop(self.process)


#: Real GRBL's speeds for the plotter's job (mm/min, mm/s²): a new board's are far slower.
GRBL_SETUP = b"$110=6000\n$111=6000\n$120=1000\n$121=1000\n"
#: grbl-sim shares one core with every other simulator on the machine: it may start slowly.
GRBL_SIM_START_S = 60.0
#: A new board's steps a mm ($100, $101).
GRBL_STEPS_PER_MM = 250.0


class GrblSimBoard:
    """Real GRBL 1.1h (grbl-sim) that restarts when its port reopens, as an Arduino does.

    A restart ends the simulator and starts a new one on the same EEPROM
    (the board keeps its settings, loses its position); the step log goes on,
    marked where the board came back.  It happens when the station opens the
    port again after it was pulled (the relay waits for that open), so the
    banner is the first thing the station reads, as from a real board; the
    old board runs on, unheard, while the port is gone.
    """

    restarts_on_open = True

    def __init__(self, dialect: RelayDialect, workdir: Path) -> None:
        self.workdir = workdir / "board"
        self.workdir.mkdir(parents=True, exist_ok=True)
        self.steps = workdir / "steps.log"
        self.process: subprocess.Popen[bytes] | None = None
        self.restarts = 0

    def start(self) -> str:
        exe = grbl_sim.build(ROOT / "tests" / "third_party" / "grbl")
        self.process = grbl_sim.start(exe, self.workdir, steps=self.steps)
        path = device_path(self.process, GRBL_SIM_START_S)
        _set_up(path, GRBL_SETUP)
        return path

    def reopened(self) -> str | None:
        assert self.process is not None
        stop(self.process)
        self.restarts += 1
        with self.steps.open("a", encoding="utf-8") as steps:
            steps.write(f"{BOOT_MARK} {self.restarts}\n")
        exe = grbl_sim.build(ROOT / "tests" / "third_party" / "grbl")
        self.process = grbl_sim.start(exe, self.workdir, steps=self.steps, fresh=False)
        return device_path(self.process, GRBL_SIM_START_S)

    def log(self) -> str:
        return _read(self.steps)

    def progress(self) -> int:
        """The step log grows only while blocks run (grbl-sim is slow on a busy machine)."""
        try:
            return self.steps.stat().st_size
        except FileNotFoundError:
            return 0

    def stop(self) -> None:
        if self.process is not None:
            stop(self.process)


def _set_up(path: str, lines: bytes) -> None:
    """Write set-up lines to a board and wait for an answer to each (bounded)."""
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    try:
        tty.setraw(fd)
        os.write(fd, lines)
        heard = b""
        deadline = time.monotonic() + GRBL_SIM_START_S
        while heard.count(b"ok") + heard.count(b"error") < lines.count(b"\n"):
            if time.monotonic() > deadline:
                raise AssertionError(f"the board did not take its set-up: {heard!r}")
            if select.select([fd], [], [], 0.1)[0]:
                heard += os.read(fd, 4096)
    finally:
        os.close(fd)


# --- the pen plotters ----------------------------------------------------------------------


ROWS = (0.0, 10.0)


def zigzag() -> list[tuple[float, float]]:
    """One row of ten strokes, each turning from the last (so none merges with the next)."""
    return [(5.0 + 3.0 * i, 5.0 + 2.0 * (i % 2)) for i in range(11)]


def plot_strokes() -> list[tuple[tuple[float, float], tuple[float, float]]]:
    """The job's pen-down strokes: the zig-zag once per row, the pen lifted between rows."""
    strokes = []
    for dy in ROWS:
        points = [(x, y + dy) for x, y in zigzag()]
        strokes += list(pairwise(points))
    return strokes


def gcode_job(pen_up: str, pen_down: str) -> Callable[[Path], Path]:
    def write(directory: Path) -> Path:
        lines = ["G21", "G90", pen_up]
        for dy in ROWS:
            points = [(x, y + dy) for x, y in zigzag()]
            lines.append(f"G0 X{points[0][0]:.3f} Y{points[0][1]:.3f}")
            lines.append(pen_down)
            lines += [f"G1 X{x:.3f} Y{y:.3f} F3000" for x, y in points[1:]]
            lines.append(pen_up)
        lines.append("G0 X0 Y0")
        path = directory / "plot.gcode"
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        return path

    return write


def gcode_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    return {
        "strokes": Track(
            plot_strokes(),
            gcode_strokes(at_exit),
            gcode_strokes(final),
            same=same_stroke,
            part_of=stroke_part_of,
        )
    }


def corexy_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    """As :func:`gcode_tracks`, a stroke caught midway anywhere on its way (see in_box)."""
    return {
        "strokes": Track(
            plot_strokes(),
            gcode_strokes(at_exit, in_box),
            gcode_strokes(final, in_box),
            same=same_stroke,
            part_of=corexy_stroke_part_of,
        )
    }


# --- the drill -----------------------------------------------------------------------------

#: Whole centimetres, so the drill's 19.8 and 19.7 microsteps a mm are exact; in a row, so
#: any hole-order optimisation keeps the file's order.
HOLES_MM = [(10, 10), (30, 10), (50, 20), (70, 20), (90, 30)]


def drill_job(directory: Path) -> Path:
    lines = ["M48", "METRIC", "T1C0.8", "%", "T1"]
    lines += [f"X{x:.1f}Y{y:.1f}" for x, y in HOLES_MM]
    lines.append("M30")
    path = directory / "holes.drl"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def drill_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    expected = [(198 * x // 10, 197 * y // 10) for x, y in HOLES_MM]
    return {"holes": Track(expected, drill_holes(at_exit), drill_holes(final))}


# --- the move machines ---------------------------------------------------------------------

STAGE_ROUTE = [(10.0, 10.0), (20.0, 15.0), (5.0, 25.0), (30.0, 30.0), (12.0, 4.0)]
USB3_ROUTE = [(0.25, 0.5), (0.75, 0.25), (0.5, 1.0), (0.25, 0.75), (1.0, 0.5)]
USB3_COUNTS_PER_MM = 6400  # M6 thread, the unit's default


def route_job(route: list[tuple[float, float]]) -> Callable[[Path], Path]:
    def write(directory: Path) -> Path:
        path = directory / "route.txt"
        path.write_text("".join(f"{x}, {y}\n" for x, y in route), encoding="utf-8")
        return path

    return write


def _per_axis(route: list[tuple[float, float]], scale: float) -> dict[int, list[int]]:
    found: dict[int, list[int]] = {0: [], 1: []}
    for point in route:
        for axis in (0, 1):
            value = round(point[axis] * scale)
            if not found[axis] or found[axis][-1] != value:
                found[axis].append(value)
    return found


def stage_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    expected = _per_axis(STAGE_ROUTE, 1000)
    early, late = stage_targets(at_exit), stage_targets(final)
    return {
        f"axis {'XY'[axis]}": Track(expected[axis], early.get(axis, []), late.get(axis, []))
        for axis in (0, 1)
    }


def usb3_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    expected = _per_axis([(0.0, 0.0), *USB3_ROUTE], USB3_COUNTS_PER_MM)
    early, late = usb3_targets(at_exit), usb3_targets(final)
    for found in (early, late):
        for axis in (0, 1):
            name = "XY"[axis]
            start, *targets = expected[axis]
            found[name] = usb3_joined(found.get(name, []), targets, start)
    return {
        f"axis {name}": Track(
            expected[axis][1:],
            early.get(name, []),
            late.get(name, []),
            same=usb3_same,
            part_of=usb3_part_of,
        )
        for axis, name in enumerate("XY")
    }


# --- the string-art winder ----------------------------------------------------------------

#: A small board (8 nails on a circle, every one wound), so a run is a few seconds.
SA_NAILS, SA_RADIUS_CM = 8, 8.0
SA_SEQUENCE = (0, 3, 6, 1, 4, 7, 2, 5, 0)


def string_art_job(directory: Path) -> Path:
    (directory / "param.txt").write_text(
        f"tvar = 0\npocet_hrebiku = {SA_NAILS}\npolomer_matrice = {SA_RADIUS_CM}\n",
        encoding="utf-8",
    )
    path = directory / "poradi.txt"
    path.write_text(",".join(map(str, (len(SA_SEQUENCE), *SA_SEQUENCE))) + "\n", encoding="utf-8")
    return path


def string_art_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    """Every nail drilled once in index order, then wound round in the file's order."""
    angles, radii = nail_polar(0, SA_NAILS, SA_RADIUS_CM)
    board = NailBoard(
        [float(a) for a in angles], [float(r) for r in radii], along_drill_axis_mm(20.0)
    )
    expected: list[tuple[str, int | str]] = [("nail", k) for k in range(SA_NAILS)]
    expected += [("wrap", k) for k in SA_SEQUENCE[1:]]
    return {"nails": Track(expected, string_art_ops(at_exit, board), string_art_ops(final, board))}


def grbl_sim_tracks(at_exit: str, final: str) -> dict[str, Track[Any, Any]]:
    """As :func:`gcode_tracks`, from grbl-sim's step reports (see grbl_sim_strokes)."""
    return {
        "strokes": Track(
            plot_strokes(),
            grbl_sim_strokes(at_exit, GRBL_STEPS_PER_MM),
            grbl_sim_strokes(final, GRBL_STEPS_PER_MM),
            same=grbl_sim_same_stroke,
            part_of=grbl_sim_part_of,
        )
    }


#: Real GRBL on grbl-sim, restarting when its port reopens: only in the slow mode.
GRBL_SIM = RelayDialect(
    "grbl-plotter",
    1,
    b"\n",
    b"\n",
    gcode_job("M5", "M3 S1000"),
    grbl_sim_tracks,
    {Direction.TO_DEVICE: 617, Direction.TO_HOST: 2022},
    GCODE_REALTIME,
    board=lambda dialect, workdir: GrblSimBoard(dialect, workdir),
    name="grbl-sim",
)


DIALECTS: dict[str, RelayDialect] = {
    "grbl-plotter": RelayDialect(
        "grbl-plotter",
        5,
        b"\n",
        b"\n",
        gcode_job("M5", "M3 S1000"),
        gcode_tracks,
        {Direction.TO_DEVICE: 590, Direction.TO_HOST: 525},
        GCODE_REALTIME,
    ),
    "corexy-plotter": RelayDialect(
        "corexy-plotter",
        5,
        b"\n",
        b"\n",
        gcode_job("M3", "M4"),
        corexy_tracks,
        {Direction.TO_DEVICE: 562, Direction.TO_HOST: 413},
        GCODE_REALTIME,
    ),
    "pcb-drill": RelayDialect(
        "pcb-drill",
        50,
        b"\r",
        b"\n",
        drill_job,
        drill_tracks,
        {Direction.TO_DEVICE: 77, Direction.TO_HOST: 156},
    ),
    "usb3": RelayDialect(
        "usb3",
        40,
        b";",
        b";",
        route_job(USB3_ROUTE),
        usb3_tracks,
        {Direction.TO_DEVICE: 319, Direction.TO_HOST: 1615},
    ),
    "string-art": RelayDialect(
        "string-art",
        50,
        b"\n",
        b"\n",
        string_art_job,
        string_art_tracks,
        {Direction.TO_DEVICE: 1328, Direction.TO_HOST: 1730},
        GCODE_REALTIME,
    ),
    "xy-stage": RelayDialect(
        "xy-stage",
        20,
        b"\n",
        b"\n",
        route_job(STAGE_ROUTE),
        stage_tracks,
        {Direction.TO_DEVICE: 759, Direction.TO_HOST: 957},
    ),
}


# --- a run ------------------------------------------------------------------------------------


@dataclass(frozen=True)
class RunResult:
    profile: str
    seed: int
    fault: Fault | None
    fired: bool
    judgement: Judgement
    status: int | None
    wall_s: float
    traffic: dict[Direction, int]
    said: str

    @property
    def kind(self) -> str:
        return self.fault.kind.value if self.fault is not None else "none"

    def line(self) -> str:
        fault = str(self.fault) if self.fault is not None else "no fault"
        fired = "" if self.fired or self.fault is None else " (never reached)"
        return (
            f"RELAY | {self.profile} | seed {self.seed} | {fault}{fired} | {self.judgement} "
            f"| {self.wall_s:.1f} s"
        )


def _read(path: Path) -> str:
    try:
        return path.read_text(encoding="utf-8", errors="replace")
    except FileNotFoundError:
        return ""


def station_command(job: Path, profile: str, port: Path, checkpoints: Path) -> list[str]:
    return [
        sys.executable,
        "-m",
        "app",
        "run",
        str(job),
        "--profile",
        profile,
        "--port",
        str(port),
        "--no-progress",
        "--yes",
        "--checkpoints",
        str(checkpoints),
    ]


def run_once(dialect: RelayDialect, seed: int | None, workdir: Path) -> RunResult:
    """The dialect's job through a relay with the fault of ``seed`` (None: no fault)."""
    workdir.mkdir(parents=True, exist_ok=True)
    fault = random_fault(seed, dialect.traffic, dialect.key) if seed is not None else None
    job = dialect.write_job(workdir)
    started = time.monotonic()
    board = dialect.board(dialect, workdir)
    relay: FaultRelay | None = None
    station: subprocess.Popen[bytes] | None = None
    status: int | None = None
    fired, traffic = False, {}
    try:
        relay = FaultRelay(
            board.start(),
            workdir / "port",
            fault,
            to_device_end=dialect.to_device_end,
            to_host_end=dialect.to_host_end,
            ignored_to_device=dialect.ignored_to_device,
            on_reopen=board.reopened,
            restart_on_open=board.restarts_on_open,
        )
        env = dict(os.environ, QT_QPA_PLATFORM="offscreen")
        with (
            (workdir / "station.out").open("wb") as out,
            (workdir / "station.err").open("wb") as err,
        ):
            station = subprocess.Popen(
                station_command(job, dialect.profile, workdir / "port", workdir / "checkpoints"),
                cwd=ROOT,
                stdin=subprocess.DEVNULL,
                stdout=out,
                stderr=err,
                env=env,
            )
            status = _wait(station, relay, fault, board)
        at_exit = board.log()
        (workdir / "log-at-exit.txt").write_text(at_exit, encoding="utf-8")
        fired, traffic = relay.fired_at is not None, relay.seen
        relay.close()
        relay = None
        time.sleep(SETTLE_S)  # the device finishes what it was doing (it is not told more)
    finally:
        if station is not None and station.poll() is None:
            station.kill()
            station.wait()
        if relay is not None:
            relay.close()
        board.stop()
    final = board.log()
    said = _read(workdir / "station.err") + _read(workdir / "station.out")
    judgement = judge(dialect.tracks(at_exit, final), status, said)
    return RunResult(
        dialect.key,
        seed if seed is not None else -1,
        fault,
        fault is not None and fired,
        judgement,
        status,
        time.monotonic() - started,
        traffic,
        last_words(said),
    )


def _wait(
    station: subprocess.Popen[bytes], relay: FaultRelay, fault: Fault | None, board: Board
) -> int | None:
    """The station's exit status, or None when it is hung.

    Hung: still running HANG_AFTER_S after the fault's effect ended (a hold,
    a silence or a pulled port lasts its time; the others are over at once)
    and after the machine last moved (as far as the board can tell), or,
    when the fault was never reached, HANG_AFTER_S plus NOT_REACHED_S after
    the start; and never later than GIVE_UP_S after the start.
    """
    begun = time.monotonic()
    moved_at, progress = begun, board.progress()
    while True:
        status = station.poll()
        if status is not None:
            return status
        now = time.monotonic()
        if (seen := board.progress()) != progress:
            moved_at, progress = now, seen
        fired = relay.fired_at
        if fired is None or fault is None:
            quiet_since = begun + NOT_REACHED_S
        elif fault.kind in TIMED:
            quiet_since = fired + fault.amount
        else:
            quiet_since = fired
        if now - max(quiet_since, moved_at) > HANG_AFTER_S or now - begun > GIVE_UP_S:
            return None
        time.sleep(0.05)
