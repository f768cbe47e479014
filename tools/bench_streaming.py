"""G-code streaming rate over a pty paced at 115200 baud: the station against grbl's method.

A pty has no speed, so the emulator runs with ``--baud 115200`` (10 bits a
byte, 11 520 bytes/s each way) in real time, parsing lines once per 5 ms
control cycle as the firmware does.  The lines are moves to where the pen
already stands, so motion is never the bottleneck: the question is how well
the sender keeps the wire busy.

Two rows (``tools/benchmark.py --only gcode_streaming,gcode_job_streaming``):

* ``gcode_streaming`` — the station's G-code session alone streams short lines
  with character counting and with ping-pong;
* ``gcode_job_streaming`` — 10 000 such lines run as a job (runner + jobs dock in
  the window's own event loop, until the machine is seen idle), and in the same
  run the peer: grbl's ``stream.py`` character counting, reimplemented here
  (:func:`stream_counting`), as a separate plain process on the same emulator,
  also timed until it has seen the machine idle after its last line.
  Beside each rate: processor time per line of the sender's process (the
  station: every thread of this process; the peer: its own process) and of the
  emulator's process, measured apart (``/proc/<pid>/stat``), and the load average.

Run by ``tools/benchmark.py``; ``python tools/bench_streaming.py --peer-counting PATH
COUNT RX`` is the peer's own process.
"""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
import time
from collections import deque
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, replace
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from tests.helpers.emulator_process import device_path, start_emulator, stop  # noqa: E402

BAUD = 115200
WIRE_BYTES_PER_S = BAUD / 10
PROFILE = "corexy-plotter"
#: The GRBL plotter, whose lines go compact (issue #33's delivery row).
GRBL_PROFILE = "grbl-plotter"
#: Lines of the job row (the issue's figure).
JOB_LINES = 10_000


def _lines(count: int) -> list[str]:
    """Short lines, as a drawing's polylines are (~17 bytes), that need no motion."""
    return ["G1 X12.34 Y56.78"] * count


def _load() -> str:
    one, five, _ = os.getloadavg()
    return f"[load {one:.2f}/{five:.2f}]"


def process_cpu_s(pid: int) -> float:
    """User + system processor seconds of process ``pid`` so far (Linux ``/proc``)."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


@dataclass(frozen=True)
class Run:
    """One streaming run: wall seconds, line bytes, and processor seconds on each side."""

    elapsed: float
    sent: int
    lines: int
    sender_cpu: float
    emulator_cpu: float
    load: str

    @property
    def cpu_per_line_ms(self) -> float:
        return self.sender_cpu / self.lines * 1000

    @property
    def share(self) -> float:
        return self.sent / self.elapsed / WIRE_BYTES_PER_S

    def describe(self, who: str) -> str:
        return (
            f"{who}: {self.sent / self.elapsed:,.0f} bytes/s = {self.share:.1%} of the wire, "
            f"{self.elapsed:.2f} s; processor per line "
            f"{self.sender_cpu / self.lines * 1000:.3f} ms "
            f"(emulator {self.emulator_cpu / self.lines * 1000:.3f} ms) {self.load}"
        )


@contextmanager
def _emulator(profile: str = PROFILE) -> Iterator[tuple[str, int]]:
    """A paced emulator of the plotter: its device path and process id."""
    process = start_emulator("--profile", profile, "--baud", str(BAUD))
    try:
        yield device_path(process), process.pid
    finally:
        stop(process)


def _stream(
    mode: str, lines: list[str], *, as_job: bool = False, profile_name: str = PROFILE
) -> Run:
    """Stream ``lines`` through the station in ``mode`` until every one is answered.

    ``as_job``: the lines are a G-code file run by the job runner with the jobs dock
    showing it (progress, preview, the operation under way), as an operator runs it.
    """
    from PySide6.QtCore import QEventLoop, QTimer
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station

    app = QApplication.instance() or QApplication([])
    profile = load_profile(profile_name)
    assert profile.gcode is not None
    profile = replace(profile, gcode=replace(profile.gcode, streaming=mode))
    with _emulator(profile_name) as (path, pid):
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
                elapsed, cpu, emulator_cpu = _run_as_job(app, station, lines, pid)
            else:
                # Waited for in an event loop, not a spinning one: the processor time is then
                # the station's, not this loop's.
                loop = QEventLoop()
                session.lineAcknowledged.connect(
                    lambda _sent: loop.quit() if answered[0] >= len(lines) else None
                )
                QTimer.singleShot(300_000, loop.quit)
                cpu, emulator_cpu = time.process_time(), process_cpu_s(pid)
                start = time.perf_counter()
                for line in lines:
                    session.send_line(line, "console")
                loop.exec()
                if answered[0] < len(lines):
                    raise RuntimeError(f"only {answered[0]} of {len(lines)} answered")
                elapsed = time.perf_counter() - start
                cpu, emulator_cpu = time.process_time() - cpu, process_cpu_s(pid) - emulator_cpu
        finally:
            station.shutdown()
    sent = sum(len(line) + 1 for line in lines)
    return Run(elapsed, sent, len(lines), cpu, emulator_cpu, _load())


def job_run(lines: list[str], profile_name: str = PROFILE) -> Run:
    """``lines`` run as a job, counting, as the job rows run them (for rows elsewhere)."""
    return _stream("counting", lines, as_job=True, profile_name=profile_name)


def _run_as_job(
    app: object, station: object, lines: list[str], emulator_pid: int
) -> tuple[float, float, float]:
    """Seconds from Run to the job done (all answered and the machine seen idle), and the
    processor seconds this process and the emulator's spent meanwhile."""
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
        said: list[str] = []
        station.model.message.connect(said.append)
        runner.message.connect(said.append)
        model = station.model
        model.linkStateChanged.connect(
            lambda state: said.append(f"link {state.name.lower()} {model.link_detail}".strip())
        )
        loop = QEventLoop()
        runner.stateChanged.connect(
            lambda state: loop.quit() if state is not JobState.RUNNING else None
        )
        QTimer.singleShot(300_000, loop.quit)
        cpu, emulator_cpu = time.process_time(), process_cpu_s(emulator_pid)
        start = time.perf_counter()
        runner.start()
        if runner.state is JobState.RUNNING:
            loop.exec()
        if runner.state is JobState.RUNNING:
            raise RuntimeError(f"job stuck at {runner.done} of {len(lines)}")
        elapsed = time.perf_counter() - start
        cpu, emulator_cpu = time.process_time() - cpu, process_cpu_s(emulator_pid) - emulator_cpu
        if runner.state is not JobState.DONE:
            raise RuntimeError(f"job ended {runner.state}: {' / '.join(said)}")
        dock.close()
        dock.deleteLater()
        runner.deleteLater()
    return elapsed, cpu, emulator_cpu


# --- the peer: grbl's stream.py, character counting --------------------------------------


def stream_py_line(line: str) -> str:
    """A line as grbl's ``stream.py`` sends it: spaces and comments dropped, upper case."""
    return re.sub(r"\s|\(.*?\)", "", line).upper()


def stream_counting(
    path: str, lines: list[str], rx_buffer: int, *, compact: bool = False
) -> tuple[float, float]:
    """Stream ``lines`` as grbl's ``stream.py`` does by character counting; (wall, processor) s.

    Written here from the method (GRBL wiki, "Streaming a G-code program"), not
    copied: remember the length of every line sent and not yet answered, and
    before each line read replies (a blocking ``readline`` each) while the line
    would overfill the board's receive buffer or a reply is waiting; each ``ok``
    or ``error`` frees its line's bytes.  One thread, pyserial, nothing else.
    The window is the station's (``rx_buffer - 1`` bytes unanswered at most), so
    the two differ in how they send, not in how much they may.
    The first line takes the pen there and is waited out (``?`` until Idle),
    as the station's run does before it is timed.  ``compact``: each line as
    ``stream.py`` itself sends it (:func:`stream_py_line`: no spaces, no
    comments, upper case), the figure the station's delivery is held to.

    The time ends where the station's job ends: the machine seen idle after the
    last line (GRBL answers a line once it is planned, not run).  ``stream.py``
    itself stops its clock at the last ``ok`` and tells the operator to wait for
    the machine; here ``?`` goes the moment that ``ok`` is read, and again after
    each report until one says Idle: the least wait a sender can have.
    """
    import serial

    port = serial.Serial(path, BAUD, timeout=2.0)
    try:
        port.readline()  # the board's banner (it answers nothing before it)
        time.sleep(0.05)
        port.reset_input_buffer()

        def answered(reply: bytes) -> bool:
            text = reply.strip().lower()
            return text.startswith(b"ok") or text.startswith(b"error")

        shape = stream_py_line if compact else str.strip
        port.write(shape(lines[0]).encode() + b"\n")
        while not answered(port.readline()):
            pass
        while True:
            port.write(b"?")
            if port.readline().startswith(b"<Idle"):
                break
            time.sleep(0.05)
        time.sleep(0.05)
        port.reset_input_buffer()

        in_flight: deque[int] = deque()
        cpu = time.process_time()
        start = time.perf_counter()
        for line in lines:
            block = shape(line).encode() + b"\n"
            while in_flight and (sum(in_flight) + len(block) >= rx_buffer or port.in_waiting):
                reply = port.readline()
                if not reply:
                    raise RuntimeError("the board stopped answering")
                if answered(reply):
                    in_flight.popleft()
            port.write(block)
            in_flight.append(len(block))
        while in_flight:
            reply = port.readline()
            if not reply:
                raise RuntimeError("the board stopped answering")
            if answered(reply):
                in_flight.popleft()
        port.write(b"?")
        while True:
            reply = port.readline()
            if not reply:
                raise RuntimeError("the board stopped answering")
            if reply.startswith(b"<Idle"):
                break
            if reply.startswith(b"<"):
                port.write(b"?")
        return time.perf_counter() - start, time.process_time() - cpu
    finally:
        port.close()


def _peer(lines: list[str], profile: str = PROFILE, *, compact: bool = False) -> Run:
    """The peer in a process of its own against a fresh emulator, as it would be run."""
    from app.profiles import load_profile

    gcode = load_profile(profile).gcode
    assert gcode is not None
    with _emulator(profile) as (path, pid):
        emulator_cpu = process_cpu_s(pid)
        command = [sys.executable, str(Path(__file__)), "--peer-counting", path]
        child = subprocess.run(
            [*command, str(len(lines)), str(gcode.rx_buffer), "compact" if compact else "as-is"],
            cwd=ROOT,
            check=True,
            capture_output=True,
            text=True,
        )
        emulator_cpu = process_cpu_s(pid) - emulator_cpu
    result = json.loads(child.stdout.strip().splitlines()[-1])
    sent = sum(len(line) + 1 for line in lines)
    return Run(result["elapsed"], sent, len(lines), result["cpu"], emulator_cpu, _load())


def bench_gcode_streaming() -> list[str]:
    """The session alone: character counting against ping-pong, 2000 short lines."""
    lines = _lines(2000)
    counting = _stream("counting", lines)
    ping_pong = _stream("ping-pong", lines)
    return [
        f"G-code streaming over a pty paced at {BAUD} baud ({WIRE_BYTES_PER_S:.0f} bytes/s), "
        f"{len(lines)} lines of ~{sum(len(x) + 1 for x in lines) / len(lines):.0f} bytes, "
        "the session alone:",
        "  " + counting.describe("character counting") + " (goal >= 90 %)",
        "  "
        + ping_pong.describe("ping-pong")
        + f"; counting is {counting.share / ping_pong.share:.1f}x ping-pong (goal >= 2x)",
    ]


def bench_gcode_job_streaming() -> list[str]:
    """10 000 short lines as a job, and grbl's stream.py method on the same lines, same run."""
    lines = _lines(JOB_LINES)
    job = _stream("counting", lines, as_job=True)
    peer = _peer(lines)
    return [
        f"{len(lines):,} short lines over a pty paced at {BAUD} baud, as a G-code job "
        "(runner + jobs dock, counting; until the machine is seen idle) beside grbl's "
        "stream.py character counting (reimplemented, its own process; also until idle):",
        "  " + job.describe("job") + " (goals >= 95 % quiet, >= 85 % loaded)",
        "  "
        + peer.describe("stream.py counting")
        + f"; the job is {job.share / peer.share:.0%} of it (goal >= 95 % loaded)",
        f"  processor per line: job {job.cpu_per_line_ms:.3f} ms = "
        f"{job.cpu_per_line_ms / peer.cpu_per_line_ms:.1f}x stream.py's "
        f"{peer.cpu_per_line_ms:.3f} ms (goals <= 0.10 ms and <= 1.5x)",
    ]


def grbl_lines(count: int) -> list[str]:
    """The same short lines for the GRBL plotter: the first sets the feed GRBL requires."""
    return [f"{_lines(1)[0]} F3000", *_lines(count - 1)]


def bench_gcode_delivery() -> list[str]:
    """Issue #33: a 10 000-line job on the GRBL plotter beside grbl's own ``stream.py``.

    Both on a paced emulator of the GRBL plotter, same lines as written; the
    station sends them compact, as ``stream.py`` does (goal: delivered in at
    most 1.00 times its time).  Both timed from the same start (the operator's
    Run; the script's first line) to the same end: the machine seen idle after
    the last line, each by its own status query (:func:`stream_counting`).
    """
    lines = grbl_lines(JOB_LINES)
    job = _stream("counting", lines, as_job=True, profile_name=GRBL_PROFILE)
    peer = _peer(lines, GRBL_PROFILE, compact=True)
    written = sum(len(line) + 1 for line in lines)
    wire = sum(len(stream_py_line(line)) + 1 for line in lines)
    return [
        f"{len(lines):,} lines of ~{written / len(lines):.0f} bytes as written, "
        f"~{wire / len(lines):.0f} compact, on the GRBL plotter over a pty paced at {BAUD} "
        "baud: the station's job beside grbl's stream.py (compact lines, its own process), "
        "each timed from its start (Run; the script's first line) to the machine seen idle "
        "after the last line (stream.py: '?' as its last ok is read, until Idle):",
        f"  job: {job.elapsed:.2f} s; stream.py: {peer.elapsed:.2f} s; delivery ratio "
        f"{job.elapsed / peer.elapsed:.2f}x stream.py's time (goal <= 1.00) {job.load}",
    ]


def main(argv: list[str]) -> None:
    if argv[:1] == ["--peer-counting"]:
        path, count, rx_buffer = argv[1], int(argv[2]), int(argv[3])
        compact = argv[4:5] == ["compact"]
        lines = grbl_lines(count) if compact else _lines(count)
        elapsed, cpu = stream_counting(path, lines, rx_buffer, compact=compact)
        print(json.dumps({"elapsed": elapsed, "cpu": cpu}))
        return
    for text in bench_gcode_streaming() + bench_gcode_job_streaming():
        print(text)


if __name__ == "__main__":
    main(sys.argv[1:])
