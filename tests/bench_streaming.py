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

import os
import sys
import time
from dataclasses import replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from tests.helpers.emulator_process import emulator_on_pty  # noqa: E402

BAUD = 115200
WIRE_BYTES_PER_S = BAUD / 10


def _lines(count: int) -> list[str]:
    """Short lines, as a drawing's polylines are (~17 bytes), that need no motion."""
    return ["G1 X12.34 Y56.78"] * count


def _stream(mode: str, lines: list[str], *, as_job: bool = False) -> tuple[float, int]:
    """Seconds to get every line answered, and the line bytes sent, in ``mode``.

    ``as_job``: the lines are a G-code file run by the job runner with the jobs dock
    showing it (progress, preview, the operation under way), as an operator runs it.
    """
    from PySide6.QtCore import QEventLoop
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station

    app = QApplication.instance() or QApplication([])
    profile = load_profile("corexy-plotter")
    assert profile.gcode is not None
    profile = replace(profile, gcode=replace(profile.gcode, streaming=mode))
    with emulator_on_pty("--profile", "corexy-plotter", "--baud", str(BAUD)) as path:
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
            session.lineAcknowledged.connect(lambda _sent: answered.__setitem__(0, answered[0] + 1))
            session.send_line(lines[0], "console")  # get there; the rest move nothing
            while answered[0] < 1 or not session.settled:
                app.processEvents(QEventLoop.ProcessEventsFlag.AllEvents, 5)
            answered[0] = 0
            if as_job:
                elapsed = _run_as_job(app, station, lines)
            else:
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
    return elapsed, sum(len(line) + 1 for line in lines)


def _run_as_job(app: object, station: object, lines: list[str]) -> float:
    """Seconds from Run to the job done (all answered and the machine seen idle)."""
    import tempfile

    from PySide6.QtCore import QEventLoop, QTimer
    from PySide6.QtWidgets import QApplication

    from app.jobs.run.runner import JobRunner, JobState
    from app.station import Station
    from widgets.jobs.dock import JobsDock

    assert isinstance(app, QApplication) and isinstance(station, Station)
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "short-lines.gcode"
        path.write_text("\n".join(lines) + "\n", encoding="ascii")
        runner = JobRunner(station, Path(directory) / "checkpoints")
        dock = JobsDock(station, runner)
        dock.resize(800, 600)
        dock.show()
        if not dock.open_path(path):
            raise RuntimeError(dock.messages.toPlainText())
        # The window's own event loop, waiting in the system as the application's does
        # (a loop of processEvents would spin, holding the interpreter lock the port's
        # reader thread needs for every reply).
        loop = QEventLoop()
        runner.stateChanged.connect(
            lambda state: loop.quit() if state is not JobState.RUNNING else None
        )
        QTimer.singleShot(300_000, loop.quit)
        start = time.perf_counter()
        runner.start()
        if runner.state is JobState.RUNNING:
            loop.exec()
        if runner.state is JobState.RUNNING:
            raise RuntimeError(f"job stuck at {runner.done} of {len(lines)}")
        elapsed = time.perf_counter() - start
        if runner.state is not JobState.DONE:
            raise RuntimeError(f"job ended {runner.state}: {dock.messages.toPlainText()}")
        dock.close()
        dock.deleteLater()
        runner.deleteLater()
    return elapsed


def bench_gcode_streaming() -> list[str]:
    lines = _lines(2000)
    results: dict[str, float] = {}
    for mode in ("counting", "ping-pong"):
        elapsed, sent = _stream(mode, lines)
        results[mode] = sent / elapsed
    # The figure: 10 000 short lines as a job, with the load beside it (another
    # process busy slows the window's thread, which no longer paces the stream).
    job_lines = _lines(10_000)
    load_before = os.getloadavg()[0]
    job_elapsed, job_sent = _stream("counting", job_lines, as_job=True)
    load_after = os.getloadavg()[0]
    job = job_sent / job_elapsed
    counting, ping_pong = results["counting"], results["ping-pong"]
    return [
        f"G-code streaming over a pty paced at {BAUD} baud ({WIRE_BYTES_PER_S:.0f} bytes/s), "
        f"{len(lines)} lines of ~{sum(len(x) + 1 for x in lines) / len(lines):.0f} bytes:",
        f"  character counting {counting:,.0f} bytes/s = {counting / WIRE_BYTES_PER_S:.0%} "
        "of the wire (goal >= 90 %)",
        f"  ping-pong {ping_pong:,.0f} bytes/s = {ping_pong / WIRE_BYTES_PER_S:.0%} of the wire; "
        f"counting is {counting / ping_pong:.1f}x ping-pong (goal >= 2x)",
        f"  {len(job_lines)} such lines as a G-code job (runner + jobs dock, counting; until "
        f"the machine is seen idle): {job:,.0f} bytes/s = {job / WIRE_BYTES_PER_S:.0%} of the "
        f"wire, {job_elapsed:.1f} s (load average {load_before:.1f} -> {load_after:.1f}; "
        "goal >= 95 % quiet, >= 85 % loaded)",
    ]


if __name__ == "__main__":
    for text in bench_gcode_streaming():
        print(text)
