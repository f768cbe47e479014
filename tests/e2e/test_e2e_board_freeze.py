"""End to end: a GRBL board that stops answering for 2.5 s mid-job does not pause the job.

Issue 30: freezing the emulator 2.5 s paused a streaming job every time ("link
lost"), although the board lost nothing and the operator then had to resume
by hand.  Here the emulated ``grbl-plotter`` runs as its own process on a pty
(``python -m protocol.emulator --pty --log``); mid-job the whole process is
frozen with SIGSTOP and let go with SIGCONT 2.5 s later, as a board whose USB
bridge or host hiccups would be.  The emulator's own log is the judge: every
pen-down stroke of the file drawn once, in order, and the job done without a
pause.  The station's real-time event loop runs throughout (the freeze is the
fault's own length; every other wait is on a condition).
"""

from __future__ import annotations

import json
import os
import signal
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station
from tests.helpers.emulator_process import device_path, start_emulator, stop

PROFILE = load_profile("grbl-plotter")
FREEZE_MS = 2500
JOB_TIMEOUT_MS = 180_000
#: 24 pen-down strokes of 40 mm with pen-up returns: some seconds of drawing at time scale 2.
STROKES = 24


def _job_text() -> str:
    lines = ["G21 G90", "M5"]
    for k in range(STROKES):
        y = 5 + 4 * k
        lines += [f"G0 X10 Y{y}", "M3 S1000", f"G1 X50 Y{y} F6000", "M5"]
    lines.append("G0 X0 Y0")
    return "\n".join(lines) + "\n"


def _strokes(log: Path) -> list[tuple[float, float]]:
    """Where every pen-down move the emulator finished ended."""
    found: list[tuple[float, float]] = []
    for line in log.read_text(encoding="utf-8").splitlines():
        try:
            event: dict[str, Any] = json.loads(line)
        except ValueError:
            continue
        if event.get("event") == "move" and event.get("pen"):
            found.append((round(event["pos"]["X"], 3), round(event["pos"]["Y"], 3)))
    return found


@pytest.fixture
def board(tmp_path: Path) -> Iterator[tuple[int, str, Path]]:
    """(pid, device path, log) of the emulated GRBL plotter; always let go and stopped."""
    log = tmp_path / "plotter.log"
    process = start_emulator("--profile", "grbl-plotter", "--time-scale", "2", "--log", str(log))
    try:
        yield process.pid, device_path(process), log
    finally:
        if process.poll() is None:
            os.kill(process.pid, signal.SIGCONT)
        stop(process)


@pytest.fixture
def station(qtbot: QtBot) -> Iterator[Station]:
    built = Station(PROFILE)
    try:
        yield built
    finally:
        built.shutdown()


def test_a_board_frozen_2_5_s_mid_job_does_not_pause_it_and_draws_every_stroke_once(
    qtbot: QtBot, board: tuple[int, str, Path], station: Station, tmp_path: Path
) -> None:
    pid, path, log = board
    station.connect_serial(path)
    qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=15_000)
    session = station.gcode_session
    assert session is not None
    qtbot.waitUntil(lambda: session.planner_size > 0, timeout=15_000)
    links: list[LinkState] = []
    station.model.linkStateChanged.connect(links.append)

    source = tmp_path / "zigzag.gcode"
    source.write_text(_job_text(), encoding="utf-8")
    options = JobOptions(gcode=PROFILE.gcode, machine_title=PROFILE.title)
    program = load_job(source, ["X", "Y"], options)
    runner = JobRunner(station, tmp_path / "checkpoints")
    states: list[JobState] = []
    runner.stateChanged.connect(states.append)
    assert runner.load(program) == []
    runner.start()
    # Mid-job: some strokes drawn, more of the file still to stream.
    qtbot.waitUntil(lambda: log.exists() and len(_strokes(log)) >= 3, timeout=JOB_TIMEOUT_MS)
    assert runner.state is JobState.RUNNING

    os.kill(pid, signal.SIGSTOP)
    try:
        qtbot.wait(FREEZE_MS)  # the station runs on meanwhile: only the board is frozen
    finally:
        os.kill(pid, signal.SIGCONT)
    qtbot.waitUntil(
        lambda: runner.state in (JobState.DONE, JobState.FAILED, JobState.ABORTED),
        timeout=JOB_TIMEOUT_MS,
    )

    assert runner.state is JobState.DONE
    assert JobState.PAUSED not in states  # never paused: nothing was lost
    assert LinkState.STALE in links and LinkState.LOST not in links  # amber, never red
    expected = [(50.0, float(5 + 4 * k)) for k in range(STROKES)]
    assert _strokes(log) == expected  # every stroke once, in order
