"""End to end: the sample EAGLE drill job over a real pseudo-terminal to the emulator process.

The emulator runs as ``python -m protocol.emulator --profile pcb-drill --pty``
with its clock 20 times faster than real time and every event appended to
``--log``; a real-clock station connects with ``connect_serial`` and the job
runner drives the board, the test confirming each tool change.  The log is
the judge: every hole drilled once, at the microsteps the host computed.

Every wait is bounded; the process is killed and the station shut down
whatever happens.
"""

from __future__ import annotations

import re
import time
from collections import Counter
from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QTimer
from pytestqt.qtbot import QtBot

from app.jobs.formats.excellon.reader import build_drill_program, read_drill_file
from app.jobs.program import OpKind
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station
from tests.helpers.emulator_process import emulator_on_pty

JOB_TIMEOUT_MS = 45_000  # the whole test stays under a minute
TIME_SCALE = 20
SAMPLE_HOLES = 36
HOLE_LINE = re.compile(r"^\d+\.\d+ hole X(-?\d+) Y(-?\d+)$")


@pytest.fixture
def emulator(tmp_path: Path) -> Iterator[tuple[str, Path]]:
    """The drill emulator on a pty: (device path, log path); always terminated."""
    log = tmp_path / "drill.log"
    args = ("--profile", "pcb-drill", "--link", str(tmp_path / "drill"))
    with emulator_on_pty(*args, "--time-scale", str(TIME_SCALE), "--log", str(log)) as path:
        yield path, log


@pytest.fixture
def station(qtbot: QtBot) -> Iterator[Station]:
    built = Station(load_profile("pcb-drill"))
    try:
        yield built
    finally:
        built.shutdown()


def logged_holes(log: Path) -> Counter[tuple[int, int]]:
    if not log.exists():
        return Counter()
    found: Counter[tuple[int, int]] = Counter()
    for line in log.read_text(encoding="utf-8").splitlines():
        match = HOLE_LINE.match(line.strip())
        if match:
            found[(int(match.group(1)), int(match.group(2)))] += 1
    return found


def test_the_sample_job_drills_every_hole_once_over_a_real_pty(
    qtbot: QtBot,
    emulator: tuple[str, Path],
    station: Station,
    shared_dir: Path,
    tmp_path: Path,
) -> None:
    began = time.monotonic()
    path, log = emulator
    station.connect_serial(path)
    qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5000)
    session = station.drill_session
    assert session is not None
    assert session.home(0)
    qtbot.waitUntil(lambda: not session.busy, timeout=10_000)

    program = build_drill_program(read_drill_file(shared_dir / "samples/pcb-driver/driver"))
    runner = JobRunner(station, tmp_path / "checkpoints")
    asked: list[str] = []

    def confirm_later(message: str) -> None:
        asked.append(message)
        QTimer.singleShot(0, runner.confirm)

    runner.waitingForOperator.connect(confirm_later)
    assert runner.load(program) == []
    runner.start()
    qtbot.waitUntil(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.PAUSED),
        timeout=JOB_TIMEOUT_MS,
    )
    assert runner.state is JobState.DONE
    assert asked == [op.message for op in program if op.kind is OpKind.WAIT]

    expected: Counter[tuple[int, int]] = Counter()
    for before, op in zip(program.operations, program.operations[1:], strict=False):
        if op.kind is OpKind.DRILL:
            expected[
                (
                    session.to_microsteps(0, before.target["X"]),
                    session.to_microsteps(1, before.target["Y"]),
                )
            ] += 1
    assert sum(expected.values()) == SAMPLE_HOLES
    # The log is flushed as the emulator runs; give its loop a moment for the last lines.
    qtbot.waitUntil(lambda: sum(logged_holes(log).values()) >= SAMPLE_HOLES, timeout=5000)
    holes = logged_holes(log)
    assert holes == expected
    assert set(holes.values()) == {1}
    assert (round(25.654 * 19.8), round(11.684 * 19.7)) in holes  # the file's first hole
    assert time.monotonic() - began < 60
