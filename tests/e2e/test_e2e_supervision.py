"""End to end: a command corrupted on the wire makes the machine leave the path, and is stopped.

No dialect's wire has a checksum.  A :class:`~tests.helpers.tamper_relay.TamperRelay`
between a real-clock station and the emulator's process (its pty) changes one
command on its way, as a noisy cable would; the station cannot see that, but
it sees the machine's reports leave the path of what it sent, stops the
machine and fails the job with a message.  What the machine did is judged
from the emulator's own ``--log``, not from what the station says.
"""

from __future__ import annotations

import json
import os
import re
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import Program, SourceRef, move
from app.jobs.run.runner import JobRunner, JobState
from app.machine import LinkState
from app.profiles import load_profile
from app.station import Station
from protocol.usb3.codec import Position, StepSize, decode_reply
from tests.helpers.emulator_process import device_path, start_emulator, stop
from tests.helpers.tamper_relay import TO_DEVICE, TO_HOST, TamperRelay

# The relay and the emulator sit on pseudo-terminals, which only POSIX systems have
# (Windows: see docs/manual/windows-macos.md); every Linux CI run has them.
pytestmark = pytest.mark.skipif(not hasattr(os, "openpty"), reason="no pseudo-terminals here")

STEP_TIMEOUT_MS = 20_000
X = 0
#: M6 thread (the unit's default): 1 mm a turn, 6400 counts a millimetre.
COUNTS_PER_MM = 6400
#: Full steps (32 counts a pulse) at the top pulse rate: 300 * 32 / 6400 mm/s.
FULL_STEP_MM_S = 1.5
_MOVE = re.compile(r"^(\d+\.\d+) .*Move\(axis=<AxisId\.X: 0>, count=(\d+)\)")
_STOP = re.compile(r"^(\d+\.\d+) .*StopAll")


def _run(
    qtbot: QtBot,
    station: Station,
    program: Program,
    tmp_path: Path,
    messages: list[str],
) -> JobRunner:
    runner = JobRunner(station, tmp_path / "checkpoints")
    runner.message.connect(messages.append)
    assert runner.load(program) == []
    runner.start()
    try:
        qtbot.waitUntil(
            lambda: runner.state in (JobState.DONE, JobState.FAILED), timeout=STEP_TIMEOUT_MS
        )
    except Exception:
        raise AssertionError(f"the job never ended: {messages[-8:]}") from None
    return runner


def _connected(qtbot: QtBot, station: Station, link: Path, messages: list[str]) -> None:
    station.model.message.connect(messages.append)
    station.connect_serial(str(link))
    qtbot.waitUntil(
        lambda: station.model.link_state is LinkState.CONNECTED, timeout=STEP_TIMEOUT_MS
    )


# --- the usb3 unit: one corrupted digit ---------------------------------------------------


def test_a_corrupted_usb3_count_stops_the_unit_within_a_report_of_leaving_the_path(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """``X000000000006400;`` (1 mm) arrives as ``X000001000006400;`` (156 km).

    The unit runs at full steps, 1.5 mm/s in real time: the station must stop
    it about a report (0.1 s, 0.15 mm) after it passes the target by more
    than the profile's tolerance, not 29 hours later.
    """
    log = tmp_path / "usb3.log"
    process = start_emulator("--profile", "usb3", "--log", str(log))
    corrupted: list[bytes] = []

    def tamper(message: bytes) -> bytes:
        if message == b"X000000000006400;" and not corrupted:
            corrupted.append(message)
            return b"X000001000006400;"
        return message

    relay = None
    station = Station(load_profile("usb3"))
    messages: list[str] = []
    try:
        relay = TamperRelay(
            device_path(process), tmp_path / "port", end=b";", host_end=b";", tamper=tamper
        )
        _connected(qtbot, station, relay.link, messages)
        session = station.usb3_session
        assert session is not None
        session.set_step_size(X, StepSize.FULL)
        session.zero_all()
        qtbot.waitUntil(
            lambda: all(a.position == 0.0 and a.status_text == "idle" for a in station.model.axes),
            timeout=STEP_TIMEOUT_MS,
        )
        program = Program("route", [move(SourceRef("route.txt", 1), X=1.0)])
        runner = _run(qtbot, station, program, tmp_path, messages)
        assert corrupted, "the move never went out"
        assert runner.state is JobState.FAILED, messages[-5:]
        failed = next(m for m in messages if m.startswith("Job failed at route.txt:1"))
        assert "Machine stopped: it reported X " in failed
        assert "past the target (X +1.000 mm, +6400 counts); expected X 1.000" in failed

        # The unit, by its own log: the corrupted move, then S; soon after.
        qtbot.waitUntil(lambda: any(_STOP.match(line) for line in _lines(log)), timeout=5000)
        lines = _lines(log)
        moved = [(float(m[1]), int(m[2])) for line in lines if (m := _MOVE.match(line))]
        started = next(t for t, count in moved if count == 1_000_006_400)
        stopped = next(float(m[1]) for line in lines if (m := _STOP.match(line)))
        assert stopped > started
        # Travel before the stop, at most: at full speed all the way (it accelerates first).
        ran_mm = FULL_STEP_MM_S * (stopped - started)
        tolerance = station.profile.supervision_tolerance_mm
        reports_beyond = _x_reports_beyond(relay.messages(), (1.0 + tolerance) * COUNTS_PER_MM)
        print(
            f"\nSUPERVISION | usb3 | S; {stopped - started:.3f} s after the corrupted move, "
            f"≤ {ran_mm:.3f} mm run for 1 mm sent; {reports_beyond} report(s) beyond the "
            "tolerance reached the station before S; went out"
        )
        # 1 mm sent, the tolerance, one report's travel (0.15 mm), and the station's and the
        # relay's latency on a loaded machine (0.5 s at 1.5 mm/s).
        assert ran_mm <= 1.0 + tolerance + 0.15 + 0.75
        assert 1 <= reports_beyond <= 3
    finally:
        station.shutdown()
        if relay is not None:
            relay.close()
        stop(process)


def _lines(log: Path) -> list[str]:
    return log.read_text(encoding="utf-8").splitlines() if log.exists() else []


def _x_reports_beyond(record: list[tuple[str, bytes]], limit: float) -> int:
    """Position reports of X past ``limit`` counts that reached the station before ``S;``."""
    beyond = 0
    for direction, message in record:
        if direction == TO_DEVICE and message.strip() == b"S;":
            return beyond
        if direction == TO_HOST:
            _, reply = decode_reply(message)
            if isinstance(reply, Position) and reply.axis == X and reply.count > limit:
                beyond += 1
    raise AssertionError("S; never went out")


# --- G-code: a line that lost bytes and is still valid --------------------------------------

#: G-code's real-time bytes go on at once: no line holds them.
GCODE_REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))
PLOT = [
    "G0 X5.000 Y5.000",
    "{pen_down}",
    "G1 X18.000 Y18.000 F3000",
    "G1 X30.000 Y18.000 F600",  # slow: off the path for a good second, several reports
    "G1 X30.000 Y5.000",
    "{pen_up}",
    "G0 X0.000 Y0.000",
]


def _events(log: Path) -> list[dict[str, object]]:
    found = []
    for line in _lines(log):
        try:
            found.append(json.loads(line))
        except ValueError:
            continue
    return found


@pytest.mark.parametrize("profile_name", ["grbl-plotter", "corexy-plotter"])
def test_a_gcode_line_that_lost_bytes_is_stopped_when_the_plotter_leaves_the_path(
    qtbot: QtBot, tmp_path: Path, profile_name: str
) -> None:
    """``G1 X18.000 Y18.000 F3000`` arrives as ``G1 X18.F3000`` (12 bytes lost), a valid line.

    The board draws along Y = 5 instead of to (18, 18): its reports leave the
    path sent, the station holds and resets it, and the job fails naming a
    line of the file.  By the board's log: the stroke after the mangled one is
    never finished, and the job's last move (home to 0, 0) never runs.
    """
    log = tmp_path / "board.log"
    process = start_emulator("--profile", profile_name, "--log", str(log))
    mangled: list[bytes] = []

    def tamper(message: bytes) -> bytes:
        # As written to the CoreXY plotter, compact to GRBL (the failure names it as written).
        lost = {
            b"G1 X18.000 Y18.000 F3000": b"G1 X18.F3000\n",
            b"G1X18.000Y18.000F3000": b"G1X18.F3000\n",
        }
        if message.strip() in lost and not mangled:
            mangled.append(message)
            return lost[message.strip()]
        return message

    profile = load_profile(profile_name)
    settings = profile.gcode
    assert settings is not None
    source = tmp_path / "plot.gcode"
    text = "\n".join(PLOT).format(pen_down=settings.pen_down, pen_up=settings.pen_up)
    source.write_text(text + "\n", encoding="utf-8")
    program = load_job(source, ["X", "Y"], JobOptions(gcode=settings))
    relay = None
    station = Station(profile)
    messages: list[str] = []
    try:
        relay = TamperRelay(
            device_path(process),
            tmp_path / "port",
            end=b"\n",
            host_end=b"\n",
            tamper=tamper,
            passthrough=GCODE_REALTIME,
        )
        _connected(qtbot, station, relay.link, messages)
        session = station.gcode_session
        assert session is not None
        qtbot.waitUntil(lambda: session.planner_size > 0, timeout=STEP_TIMEOUT_MS)
        runner = _run(qtbot, station, program, tmp_path, messages)
        assert mangled, "the line never went out"
        assert runner.state is JobState.FAILED, messages[-5:]
        failed = next(m for m in messages if m.startswith("Job failed at plot.gcode:"))
        assert "Machine stopped: it reported X " in failed
        assert "expected X " in failed
        # The line it was on: the mangled one, or the one it drew from the wrong place.
        assert "(G1 X18.000 Y18.000 F3000)" in failed or "(G1 X30.000 Y18.000 F600)" in failed
        assert failed.startswith(("Job failed at plot.gcode:3", "Job failed at plot.gcode:4"))

        qtbot.waitUntil(
            lambda: any(e["event"] == "reset" for e in _events(log)), timeout=STEP_TIMEOUT_MS
        )
        events = _events(log)
        lines = [e["text"] for e in events if e["event"] == "line"]
        assert mangled[0].strip().replace(b" ", b"") == b"G1X18.000Y18.000F3000"
        assert {"G1 X18.F3000", "G1X18.F3000"} & set(lines)  # the board got the mangled line
        moves = [e for e in events if e["event"] == "move"]
        ends = [(round(m["pos"]["X"], 3), round(m["pos"]["Y"], 3)) for m in moves]  # type: ignore[index]
        # Held on the wrong stroke or the one after it: nothing further ran, and the job never
        # went home as if it were done.
        assert (30.0, 5.0) not in ends
        assert ends[-1] != (0.0, 0.0)
        held = next(i for i, e in enumerate(events) if e["event"] == "hold")
        after = [e for e in events[held:] if e["event"] == "line"]
        assert after == [], after  # no line of the job reached the board after the hold
        print(f"\nSUPERVISION | {profile_name} | moves ended before the hold: {ends}; {failed}")
    finally:
        station.shutdown()
        if relay is not None:
            relay.close()
        stop(process)
