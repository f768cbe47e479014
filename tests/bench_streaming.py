"""G-code streaming rate over a pty paced at 115200 baud: character counting vs ping-pong.

A pty has no speed, so the emulator runs with ``--baud 115200`` (10 bits a
byte, 11 520 bytes/s each way) in real time, parsing lines once per 5 ms
control cycle as the firmware does.  The lines are moves to where the pen
already stands, so motion is never the bottleneck: the question is how well
the sender keeps the wire busy.
The station's G-code session streams the same short lines both ways; the
figure is line bytes delivered per second as a share of the wire's rate.
Run by ``tests/benchmark.py``.
"""

from __future__ import annotations

import selectors
import subprocess
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BAUD = 115200
WIRE_BYTES_PER_S = BAUD / 10


def _lines(count: int) -> list[str]:
    """Short lines, as a drawing's polylines are (~17 bytes), that need no motion."""
    return ["G1 X12.34 Y56.78"] * count


def _stream(mode: str, lines: list[str]) -> tuple[float, int]:
    """Seconds to get every line answered, and the line bytes sent, in ``mode``."""
    from PySide6.QtCore import QEventLoop
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station

    app = QApplication.instance() or QApplication([])
    profile = load_profile("corexy-plotter")
    assert profile.gcode is not None
    profile = replace(profile, gcode=replace(profile.gcode, streaming=mode))
    command = [
        sys.executable, "-m", "protocol.emulator", "--profile", "corexy-plotter", "--pty",
        "--baud", str(BAUD),
    ]  # fmt: skip
    with subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL
    ) as process:
        try:
            assert process.stdout is not None
            with selectors.DefaultSelector() as selector:
                selector.register(process.stdout, selectors.EVENT_READ)
                if not selector.select(15):
                    raise RuntimeError("the emulator printed no device path")
            path = process.stdout.readline().decode().strip()
            station = Station(profile)
            try:
                station.connect_serial(path)
                deadline = time.monotonic() + 10
                session = station.gcode_session
                while session is None or session.planner_size == 0:
                    app.processEvents(QEventLoop.ProcessEventsFlag.AllEvents, 20)
                    session = station.gcode_session
                    if time.monotonic() > deadline:
                        raise RuntimeError("the plotter did not answer")
                answered = [0]
                session.lineAcknowledged.connect(
                    lambda _sent: answered.__setitem__(0, answered[0] + 1)
                )
                session.send_line(lines[0], "console")  # get there; the rest move nothing
                while answered[0] < 1 or not session.settled:
                    app.processEvents(QEventLoop.ProcessEventsFlag.AllEvents, 5)
                answered[0] = 0
                start = time.perf_counter()
                for line in lines:
                    session.send_line(line, "console")
                while answered[0] < len(lines):
                    app.processEvents(QEventLoop.ProcessEventsFlag.AllEvents, 5)
                    if time.perf_counter() - start > 300:
                        raise RuntimeError(f"only {answered[0]} of {len(lines)} answered")
                elapsed = time.perf_counter() - start
            finally:
                station.shutdown()
        finally:
            process.terminate()
            process.wait(timeout=5)
    return elapsed, sum(len(line) + 1 for line in lines)


def bench_gcode_streaming() -> list[str]:
    lines = _lines(2000)
    results: dict[str, float] = {}
    for mode in ("counting", "ping-pong"):
        elapsed, sent = _stream(mode, lines)
        results[mode] = sent / elapsed
    counting, ping_pong = results["counting"], results["ping-pong"]
    return [
        f"G-code streaming over a pty paced at {BAUD} baud ({WIRE_BYTES_PER_S:.0f} bytes/s), "
        f"{len(lines)} lines of ~{sum(len(x) + 1 for x in lines) / len(lines):.0f} bytes:",
        f"  character counting {counting:,.0f} bytes/s = {counting / WIRE_BYTES_PER_S:.0%} "
        "of the wire (goal >= 90 %)",
        f"  ping-pong {ping_pong:,.0f} bytes/s = {ping_pong / WIRE_BYTES_PER_S:.0%} of the wire; "
        f"counting is {counting / ping_pong:.1f}x ping-pong (goal >= 2x)",
    ]


if __name__ == "__main__":
    sys.path.insert(0, str(ROOT))
    for text in bench_gcode_streaming():
        print(text)
