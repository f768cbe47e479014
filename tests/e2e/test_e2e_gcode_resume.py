"""End to end: both plotters' emulators on a pty, the cable faulted mid-job, every stroke once.

The emulator runs as its own process (``python -m protocol.emulator --pty
--controls --log``); a :class:`~tests.helpers.fault_bridge.FaultBridge` is the
cable to a real-clock station.  Mid-job the cable is pulled or falls silent
until the station notices, the board may be reset meanwhile (its reset
button, through ``--controls``: it stops at once, mid-stroke perhaps, and
its banner goes nowhere), and the cable comes back.  The job is then resumed
as the scripting API does it, and where the station asks the operator to
pick the resume line, the operator looks at the paper: the emulator's own
log of finished strokes.

The emulator's log is the judge: each of the file's 24 pen-down strokes
exactly once, in order (the issue saw 48).
"""

from __future__ import annotations

import json
import selectors
import subprocess
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Program
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station
from tests.helpers.emulator_process import ROOT, STARTUP_TIMEOUT_S, stop
from tests.helpers.fault_bridge import Cut, FaultBridge

STROKES = 24
TIME_SCALE = 5
STEP_TIMEOUT_MS = 60_000
GCODE_REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))


class Board:
    """The emulator process: its device path, its log, and its own controls on stdin."""

    def __init__(self, profile: str, log: Path) -> None:
        self.profile = profile
        self.log = log
        self.process = subprocess.Popen(
            [
                sys.executable,
                "-m",
                "protocol.emulator",
                "--profile",
                profile,
                "--pty",
                "--controls",
                "--time-scale",
                str(TIME_SCALE),
                "--log",
                str(log),
            ],
            cwd=ROOT,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.DEVNULL,
        )
        assert self.process.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(self.process.stdout, selectors.EVENT_READ)
            assert selector.select(STARTUP_TIMEOUT_S), "the emulator printed no device path"
        self.path = self.process.stdout.readline().decode().strip()
        assert self.path.startswith("/dev/"), self.path

    def control(self, line: str) -> None:
        assert self.process.stdin is not None
        self.process.stdin.write(line.encode() + b"\n")
        self.process.stdin.flush()

    def events(self) -> list[dict[str, object]]:
        if not self.log.exists():
            return []
        found = []
        for line in self.log.read_text(encoding="utf-8").splitlines():
            try:
                found.append(json.loads(line))
            except ValueError:
                continue
        return found

    def strokes(self) -> list[tuple[float, float]]:
        """Pen-down moves the board finished, as their ends."""
        return [
            (round(e["pos"]["X"], 3), round(e["pos"]["Y"], 3))  # type: ignore[index]
            for e in self.events()
            if e.get("event") == "move" and e.get("pen")
        ]

    def close(self) -> None:
        if self.process.stdin is not None:
            self.process.stdin.close()
        stop(self.process)


def zigzag(profile: str, tmp_path: Path) -> Program:
    settings = load_profile(profile).gcode
    assert settings is not None
    lines = ["G21 G90"]
    for k in range(STROKES):
        y = 5 + 3 * k
        lines += [settings.pen_up, f"G0 X10 Y{y}", settings.pen_down, f"G1 X60 Y{y} F3000"]
    lines.append(settings.pen_up)
    source = tmp_path / "plot.gcode"
    source.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return load_job(source, ["X", "Y"], JobOptions(gcode=settings))


EXPECTED = [(60.0, 5.0 + 3 * k) for k in range(STROKES)]


def operator_pick(program: Program, drawn: int) -> int:
    """The line the operator picks from the paper: the travel to the first stroke not there."""
    travels = [i for i, op in enumerate(program) if op.line.startswith("G0")]
    return travels[drawn] if drawn < len(travels) else len(program)


@pytest.fixture(params=["grbl-plotter", "corexy-plotter"])
def board(request: pytest.FixtureRequest, tmp_path: Path) -> Iterator[Board]:
    running = Board(request.param, tmp_path / "emulator.log")
    try:
        yield running
    finally:
        running.close()


@pytest.fixture
def short_timeouts(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr("app.machines.gcode.timing.SILENCE_S", 1.2)


def run_with_fault(
    qtbot: QtBot,
    board: Board,
    tmp_path: Path,
    fault: Callable[[FaultBridge, Station], None],
) -> tuple[list[str], int]:
    """The zig-zag with ``fault`` mid-job; returns the runner's messages and the picks made."""
    profile = load_profile(board.profile)
    bridge = FaultBridge(
        board.path,
        tmp_path / "port",
        to_device_end=b"\n",
        to_host_end=b"\n",
        ignored_to_device=GCODE_REALTIME,
    )
    station = Station(profile)
    station.reconnect_delays = (0.1, 0.2, 0.4)
    messages: list[str] = []
    picks = 0
    try:
        station.connect_serial(str(bridge.link))
        qtbot.waitUntil(
            lambda: station.model.link_state is LinkState.CONNECTED, timeout=STEP_TIMEOUT_MS
        )
        session = station.gcode_session
        assert session is not None
        qtbot.waitUntil(lambda: session.planner_size > 0, timeout=STEP_TIMEOUT_MS)
        program = zigzag(profile.name, tmp_path)
        runner = JobRunner(station, tmp_path / "checkpoints")
        runner.message.connect(messages.append)
        assert runner.load(program) == []
        runner.start()
        qtbot.waitUntil(lambda: len(board.strokes()) >= 6, timeout=STEP_TIMEOUT_MS)
        fault(bridge, station)
        # As the scripting API: Resume when the link is back; the operator picks from the paper.
        for _ in range(20):
            qtbot.waitUntil(
                lambda: (
                    runner.state in (JobState.DONE, JobState.FAILED)
                    or (
                        runner.state is JobState.PAUSED
                        and station.model.link_state is LinkState.CONNECTED
                        and (runner.resume_choice is not None or not runner.needs_operator)
                    )
                ),
                timeout=STEP_TIMEOUT_MS,
            )
            if runner.state in (JobState.DONE, JobState.FAILED):
                break
            choice = runner.resume_choice
            if choice is not None:
                picks += 1
                pick = max(operator_pick(program, len(board.strokes())), choice.first)
                assert pick in choice.candidates, (pick, choice)
                runner.resume_at(pick)
            else:
                runner.resume()
        assert runner.state is JobState.DONE, messages[-5:]
        qtbot.waitUntil(lambda: len(board.strokes()) >= STROKES, timeout=STEP_TIMEOUT_MS)
        assert board.strokes() == EXPECTED, messages  # every stroke once, in order
        return messages, picks
    finally:
        station.shutdown()
        bridge.close()


def cut_until_noticed(
    qtbot: QtBot, board: Board, mode: Cut, *, reset: bool = False
) -> Callable[[FaultBridge, Station], None]:
    """The cable cut until the station notices (and the board reset meanwhile), then back."""

    def fault(bridge: FaultBridge, station: Station) -> None:
        bridge.cut(mode)
        if reset:
            board.control("reset")  # its reset button while the cable is out
        qtbot.waitUntil(
            lambda: station.model.link_state is not LinkState.CONNECTED, timeout=STEP_TIMEOUT_MS
        )
        bridge.restore()

    return fault


@pytest.mark.parametrize("mode", [Cut.PULLED, Cut.SILENT], ids=lambda m: m.value)
def test_a_cable_fault_mid_job_draws_each_stroke_once(
    qtbot: QtBot, board: Board, tmp_path: Path, short_timeouts: None, mode: Cut
) -> None:
    messages, picks = run_with_fault(qtbot, board, tmp_path, cut_until_noticed(qtbot, board, mode))
    # The board ran what it had and stands where the last line it got leaves it: proven.
    assert picks == 0, messages
    assert not any("sent again" in m for m in messages), messages


def test_a_board_reset_while_the_cable_is_out_never_redraws(
    qtbot: QtBot, board: Board, tmp_path: Path, short_timeouts: None
) -> None:
    """Its banner is lost with the cable: where it stands says how far it got, or, mid-stroke,
    the operator picks."""
    run_with_fault(qtbot, board, tmp_path, cut_until_noticed(qtbot, board, Cut.PULLED, reset=True))


def test_a_board_that_resets_itself_with_the_cable_in_says_so_once_and_waits_for_the_pick(
    qtbot: QtBot, board: Board, tmp_path: Path
) -> None:
    def reset(_bridge: FaultBridge, station: Station) -> None:
        board.control("reset")

    messages, picks = run_with_fault(qtbot, board, tmp_path, reset)
    assert picks == 1
    assert len([m for m in messages if "restarted" in m]) == 1, messages
