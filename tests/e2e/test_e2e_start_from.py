"""``stepdeck run square.gcode --from-line N`` on the emulator and on real GRBL (grbl-sim).

The issue's check: started at line N, the plotter draws exactly the strokes
of lines N and after, in the modal state the file had there.  The file below
changes that state on the way: millimetres, then a G91 stretch, a G92 that
moves the origin, then inches; the feed is set once.  A start inside the
G91 stretch (line 9) must draw line 9's stroke relative to where line 8
left the pen; a start inside the inch stretch (line 19) must read its
numbers as inches, from the G92 origin, at the file's feed.

Judged on each board's own record, never on what the station says: the
emulator's ``--log`` (its pen-down moves, on its own clock) and grbl-sim's
step report (where the motors stood, with the servo's PWM, on the
simulator's clock).  The feed is judged by the time a stroke took on that
clock: 50 mm at the file's F3000 (50 mm/s) takes a little over a second; a
rapid would take 0.6 s, an F read as inches per minute far longer.
"""

from __future__ import annotations

import json
import os
import re
import select
import subprocess
import sys
import time
import tty
from pathlib import Path

import pytest

from tests.conftest import ROOT
from tests.helpers import grbl_sim
from tests.helpers.emulator_process import device_path, start_emulator, stop
from tests.helpers.relay_judge import (
    GRBL_SIM_EPS_MM,
    gcode_strokes,
    grbl_sim_strokes,
)

INCH = 25.4
#: The file, and each line's stroke (machine mm), where it draws one.
SQUARE: list[tuple[str, tuple[tuple[float, float], tuple[float, float]] | None]] = [
    ("G21 G90", None),  # 1
    ("M5", None),  # 2
    ("G0 X10 Y10", None),  # 3
    ("M3 S1000", None),  # 4
    ("G1 X60 Y10 F3000", ((10, 10), (60, 10))),  # 5
    ("X60 Y60", ((60, 10), (60, 60))),  # 6
    ("G91", None),  # 7
    ("X-50 Y0", ((60, 60), (10, 60))),  # 8
    ("X0 Y-50", ((10, 60), (10, 10))),  # 9
    ("G90", None),  # 10
    ("M5", None),  # 11
    ("G92 X0 Y0", None),  # 12: the origin is now at machine 10, 10
    ("G0 X70 Y0", None),  # 13
    ("M3 S1000", None),  # 14
    ("G1 X120 Y0", ((80, 10), (130, 10))),  # 15
    ("X120 Y50", ((130, 10), (130, 60))),  # 16
    ("(inches from here)", None),  # 17
    ("G20", None),  # 18
    ("X2 Y2", ((130, 60), (10 + 2 * INCH, 10 + 2 * INCH))),  # 19
    ("X2 Y0", ((10 + 2 * INCH, 10 + 2 * INCH), (10 + 2 * INCH, 10))),  # 20
    ("G21", None),  # 21
    ("M5", None),  # 22
    ("G0 X0 Y0", None),  # 23
]
#: mm/s of the file's F3000.
FEED_MM_S = 50.0
#: The profile's acceleration (mm/s²): a stroke from rest to rest takes length/feed + feed/a.
ACCEL = 1000.0
STROKE_EPS_MM = 0.01
CLI_TIMEOUT_S = 240


def write_square(directory: Path) -> Path:
    path = directory / "square.gcode"
    path.write_text("\n".join(text for text, _ in SQUARE) + "\n", encoding="utf-8")
    return path


def strokes_from(line: int) -> list[tuple[tuple[float, float], tuple[float, float]]]:
    return [stroke for n, (_, stroke) in enumerate(SQUARE, start=1) if stroke and n >= line]


def run_cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "app", "run", *args],
        cwd=ROOT,
        env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
        stdin=subprocess.DEVNULL,
        capture_output=True,
        text=True,
        timeout=CLI_TIMEOUT_S,
    )


def assert_same_strokes(
    drawn: list[tuple[tuple[float, float], tuple[float, float]]],
    expected: list[tuple[tuple[float, float], tuple[float, float]]],
    eps: float,
) -> None:
    assert len(drawn) == len(expected), f"drew {drawn}, expected {expected}"
    for got, want in zip(drawn, expected, strict=True):
        for point, aim in zip(got, want, strict=True):
            assert point == pytest.approx(aim, abs=eps), f"drew {drawn}, expected {expected}"


def assert_at_feed(seconds: float, length: float) -> None:
    """A stroke from rest to rest at the file's feed: no faster, and not much slower."""
    least = length / FEED_MM_S
    assert least * 0.98 <= seconds <= least + FEED_MM_S / ACCEL + 0.1, (
        f"{length:.1f} mm took {seconds:.3f} s; at F3000 it takes {least:.3f} s and a little"
    )


@pytest.mark.parametrize("line", [9, 19])
def test_from_line_on_the_emulator_draws_the_strokes_from_there_in_the_files_state(
    tmp_path: Path, line: int
) -> None:
    job = write_square(tmp_path)
    log = tmp_path / "emulator.log"
    process = start_emulator("--profile", "grbl-plotter", "--log", str(log))
    try:
        path = device_path(process)
        result = run_cli(
            str(job),
            "--profile",
            "grbl-plotter",
            "--port",
            path,
            "--from-line",
            str(line),
            "--no-progress",
            "--checkpoints",
            str(tmp_path / "ck"),
        )
    finally:
        stop(process)
    assert result.returncode == 0, result.stderr
    assert f"Starting at square.gcode:{line}" in result.stderr
    text = log.read_text(encoding="utf-8")
    assert_same_strokes(gcode_strokes(text), strokes_from(line), STROKE_EPS_MM)
    # The last stroke (line 20: 2 inches down, 50.8 mm) on the firmware's clock.
    events = [json.loads(e) for e in text.splitlines() if e.startswith("{")]
    moves = [e for e in events if e.get("event") == "move" and e.get("pen")]
    before = [e for e in events if e.get("event") in ("move", "pen")]
    last = moves[-1]
    start = before[before.index(last) - 1]
    assert_at_feed(last["t"] - start["t"], 2 * INCH)


def test_from_line_beyond_the_end_is_refused_before_a_byte_moves(tmp_path: Path) -> None:
    job = write_square(tmp_path)
    log = tmp_path / "emulator.log"
    process = start_emulator("--profile", "grbl-plotter", "--log", str(log))
    try:
        path = device_path(process)
        result = run_cli(str(job), "--profile", "grbl-plotter", "--port", path, "--from-line", "99")
    finally:
        stop(process)
    assert result.returncode == 2, result.stderr
    assert "square.gcode:99: beyond the end" in result.stderr
    moved = [e for e in log.read_text(encoding="utf-8").splitlines() if '"move"' in e]
    assert moved == []


# --- real GRBL ------------------------------------------------------------------------------

#: A new board's steps a mm ($100, $101), and the profile's speeds set as an operator would.
GRBL_STEPS_PER_MM = 250.0
GRBL_SETUP = b"$110=6000\n$111=6000\n$120=1000\n$121=1000\n"
GRBL_SIM_START_S = 60.0
_STEP = re.compile(r"^\s*([\d.]+)\s+(-?\d+),\s*(-?\d+),\s*(-?\d+),\s*(\d+)\s*$")


def set_up_board(path: str) -> None:
    """The profile's speeds to the board, each line answered (bounded)."""
    fd = os.open(path, os.O_RDWR | os.O_NOCTTY)
    try:
        tty.setraw(fd)
        os.write(fd, GRBL_SETUP)
        heard = b""
        deadline = time.monotonic() + GRBL_SIM_START_S
        while heard.count(b"ok") + heard.count(b"error") < GRBL_SETUP.count(b"\n"):
            assert time.monotonic() < deadline, f"the board did not take its set-up: {heard!r}"
            if select.select([fd], [], [], 0.1)[0]:
                heard += os.read(fd, 4096)
        assert b"error" not in heard, heard
    finally:
        os.close(fd)


def block_times(steps: str, end: tuple[float, float]) -> float:
    """Simulated seconds the pen-down block ending at ``end`` ran, from grbl-sim's report."""
    blocks: list[list[tuple[float, float, float, int]]] = [[]]
    for row in steps.splitlines():
        if row.startswith("# block number"):
            blocks.append([])
        elif (match := _STEP.match(row)) is not None:
            t, x, y = float(match.group(1)), int(match.group(2)), int(match.group(3))
            blocks[-1].append(
                (t, x / GRBL_STEPS_PER_MM, y / GRBL_STEPS_PER_MM, int(match.group(5)))
            )
    previous_end: float | None = None
    for block in blocks:
        if not block:
            continue
        t, x, y, _pwm = block[-1]
        if (
            previous_end is not None
            and abs(x - end[0]) <= GRBL_SIM_EPS_MM
            and abs(y - end[1]) <= GRBL_SIM_EPS_MM
            and block[0][3] > 0
        ):
            return t - previous_end
        previous_end = t
    raise AssertionError(f"no pen-down block ends at {end}")


def test_from_line_on_grbl_sim_draws_the_strokes_from_there_in_the_files_state(
    tmp_path: Path,
) -> None:
    if grbl_sim.compiler() is None:
        pytest.skip("no C compiler and make: grbl-sim cannot be built (.ci/run installs them)")
    exe = grbl_sim.build(ROOT / "tests" / "third_party" / "grbl")
    job = write_square(tmp_path)
    workdir = tmp_path / "board"
    workdir.mkdir()
    steps = tmp_path / "steps.log"
    process = grbl_sim.start(exe, workdir, steps=steps)
    try:
        path = device_path(process, GRBL_SIM_START_S)
        set_up_board(path)
        result = run_cli(
            str(job),
            "--profile",
            "grbl-plotter",
            "--port",
            path,
            "--from-line",
            "19",
            "--no-progress",
            "--checkpoints",
            str(tmp_path / "ck"),
        )
    finally:
        stop(process)
    assert result.returncode == 0, result.stderr
    report = steps.read_text(encoding="utf-8")
    assert_same_strokes(
        grbl_sim_strokes(report, GRBL_STEPS_PER_MM), strokes_from(19), GRBL_SIM_EPS_MM
    )
    end = SQUARE[19][1]
    assert end is not None
    assert_at_feed(block_times(report, end[1]), 2 * INCH)
