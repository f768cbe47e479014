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
import subprocess
import sys
import time
from collections.abc import Callable
from dataclasses import dataclass
from itertools import pairwise
from pathlib import Path
from typing import Any

from tests.helpers.emulator_process import ROOT, device_path, start_emulator, stop
from tests.helpers.fault_bridge import Direction
from tests.helpers.fault_relay import Fault, FaultKind, FaultRelay, random_fault
from tests.helpers.relay_judge import (
    Judgement,
    Track,
    corexy_stroke_part_of,
    drill_holes,
    gcode_strokes,
    in_box,
    judge,
    last_words,
    same_stroke,
    stage_targets,
    stroke_part_of,
    usb3_same,
    usb3_targets,
)

#: G-code's real-time bytes: never part of a line.
GCODE_REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))
#: A station that has not ended this long after the fault's effect ended is hung.
HANG_AFTER_S = float(os.environ.get("STEPDECK_RELAY_HANG_S", "20"))
#: A job whose fault was never reached has this long more (a clean run takes a few seconds).
NOT_REACHED_S = 20.0
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
    return {
        f"axis {name}": Track(
            expected[axis][1:], early.get(name, []), late.get(name, []), same=usb3_same
        )
        for axis, name in enumerate("XY")
    }


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
    fault = random_fault(seed, dialect.traffic, dialect.profile) if seed is not None else None
    log = workdir / "emulator.log"
    job = dialect.write_job(workdir)
    started = time.monotonic()
    emulator = start_emulator(
        "--profile", dialect.profile, "--time-scale", str(dialect.time_scale), "--log", str(log)
    )
    relay: FaultRelay | None = None
    station: subprocess.Popen[bytes] | None = None
    status: int | None = None
    fired, traffic = False, {}
    try:
        relay = FaultRelay(
            device_path(emulator),
            workdir / "port",
            fault,
            to_device_end=dialect.to_device_end,
            to_host_end=dialect.to_host_end,
            ignored_to_device=dialect.ignored_to_device,
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
            status = _wait(station, relay, fault)
        at_exit = _read(log)
        (workdir / "emulator-at-exit.log").write_text(at_exit, encoding="utf-8")
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
        stop(emulator)
    final = _read(log)
    said = _read(workdir / "station.err") + _read(workdir / "station.out")
    judgement = judge(dialect.tracks(at_exit, final), status, said)
    return RunResult(
        dialect.profile,
        seed if seed is not None else -1,
        fault,
        fault is not None and fired,
        judgement,
        status,
        time.monotonic() - started,
        traffic,
        last_words(said),
    )


_fired = False
_traffic: dict[Direction, int] = {}


def _wait(station: subprocess.Popen[bytes], relay: FaultRelay, fault: Fault | None) -> int | None:
    """The station's exit status, or None when it is hung.

    Hung: still running HANG_AFTER_S after the fault's effect ended (a hold,
    a silence or a pulled port lasts its time; the others are over at once),
    or, when the fault was never reached, HANG_AFTER_S plus NOT_REACHED_S
    after the start.
    """
    begun = time.monotonic()
    while True:
        status = station.poll()
        if status is not None:
            return status
        fired = relay.fired_at
        if fired is None or fault is None:
            quiet_since = begun + NOT_REACHED_S
        elif fault.kind in TIMED:
            quiet_since = fired + fault.amount
        else:
            quiet_since = fired
        if time.monotonic() - quiet_since > HANG_AFTER_S:
            return None
        time.sleep(0.05)
