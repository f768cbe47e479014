"""StepDeck's performance figures: ``python tools/benchmark.py`` prints them.

Not part of the test run (pytest does not collect it): timings depend on the
machine, so they are measured and printed here, never asserted in tests.
Each later capability adds its figures as another function in ``BENCHMARKS``.
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from protocol.clock import ManualClock  # noqa: E402
from tools.bench_delivery_edges import bench_gcode_delivery_edges  # noqa: E402
from tools.bench_drill_order import bench_drill_order_50k, bench_drill_order_quality  # noqa: E402
from tools.bench_eta import bench_gcode_eta  # noqa: E402
from tools.bench_grbl_planner import bench_grbl_planner_vs_grbl_sim  # noqa: E402
from tools.bench_start_from import bench_start_from_1m  # noqa: E402
from tools.bench_streaming import (  # noqa: E402
    bench_gcode_delivery,
    bench_gcode_job_streaming,
    bench_gcode_streaming,
)
from tools.bench_string_art_generator import bench_string_art_generator  # noqa: E402
from tools.bench_string_art_peers import bench_string_art_peers  # noqa: E402
from tools.bench_work_offsets import bench_resume_file_offset  # noqa: E402

if TYPE_CHECKING:
    from app.jobs.program import Program
from protocol.stage.codec import (  # noqa: E402
    AxisStatus,
    CommandFrame,
    CommandId,
    CommandPacket,
    EchoFrame,
    EchoPacket,
    StageDecoder,
    encode_command,
    encode_echo,
)


def _percentile(samples: list[float], q: float) -> float:
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def bench_decode() -> list[str]:
    echo = encode_echo(
        EchoFrame((EchoPacket(0, AxisStatus.CONSTANT_SPEED, 12345), EchoPacket(0, 0, -42)), 5, 1234)
    )
    stream = echo * 20_000
    chunks = [stream[i : i + 20] for i in range(0, len(stream), 20)]  # BLE-sized pieces
    decoder = StageDecoder()
    start = time.perf_counter()
    for chunk in chunks:
        decoder.feed(chunk)
    elapsed = time.perf_counter() - start
    assert decoder.frames == 20_000 and decoder.rejected == 0
    return [f"stage frames decoded per second (20-byte chunks): {decoder.frames / elapsed:,.0f}"]


def bench_emulated_move() -> list[str]:
    from protocol.emulator.stage_firmware import StageFirmware

    clock = ManualClock()
    firmware = StageFirmware(clock)
    replies: list[bytes] = []
    firmware.set_output(replies.append)
    move = CommandFrame(
        (CommandPacket(CommandId.MOVE_ABS, 20_000), CommandPacket(CommandId.MOVE_ABS, 20_000))
    )
    nop = encode_command(CommandFrame((CommandPacket(CommandId.NOP),) * 2))
    firmware.receive(encode_command(move))
    start = time.perf_counter()
    emulated = 0.0
    while emulated < 1.0 or any(axis.moving for axis in firmware.axes):
        firmware.receive(nop)  # the host's 100 ms frames keep the data session alive
        clock.advance(0.1)
        firmware.run_until(clock.now())
        emulated += 0.1
    elapsed = time.perf_counter() - start
    return [
        f"two-axis 20 mm move: {emulated:.1f} emulated s in {elapsed * 1000:.1f} ms wall "
        f"= {emulated / elapsed:,.0f} emulated s per wall s"
    ]


def bench_key_to_frame() -> list[str]:
    from PySide6.QtCore import QEvent, Qt
    from PySide6.QtGui import QKeyEvent
    from PySide6.QtWidgets import QApplication

    from tests.helpers.harness import StationHarness
    from widgets.main_window import MainWindow

    app = QApplication.instance() or QApplication([])
    harness = StationHarness()
    harness.connect()
    window = MainWindow(harness.station)
    window.show()
    harness.run(1.0)
    sent_at: list[float] = []
    assert harness.station.link is not None
    harness.station.link.dataSent.connect(lambda _data: sent_at.append(time.perf_counter()))
    latencies: list[float] = []
    for i in range(1000):
        key = Qt.Key.Key_Right if i % 2 == 0 else Qt.Key.Key_Left
        for kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease):
            sent_at.clear()
            start = time.perf_counter()
            QApplication.sendEvent(window, QKeyEvent(kind, key, Qt.KeyboardModifier.NoModifier))
            if kind is QEvent.Type.KeyPress:
                assert sent_at, "key press did not reach the transport"
                latencies.append(sent_at[0] - start)
        harness.run(0.01)
    window.close()
    harness.close()
    app.processEvents()
    p50 = statistics.median(latencies) * 1000
    p99 = _percentile(latencies, 0.99) * 1000
    return [f"key press -> frame handed to the transport: p50 {p50:.3f} ms, p99 {p99:.3f} ms"]


def _paint_counter() -> Any:
    """An event filter counting the paints of the widgets it is installed on (``.paints``)."""
    from PySide6.QtCore import QEvent, QObject

    class PaintCounter(QObject):
        def __init__(self) -> None:
            super().__init__()
            self.paints = 0

        def eventFilter(self, _watched: QObject, event: QEvent) -> bool:
            if event.type() == QEvent.Type.Paint:
                self.paints += 1
            return False

    return PaintCounter()


def _load() -> str:
    """The load average (1 and 5 min) a figure was measured under."""
    one, five, _ = os.getloadavg()
    return f"[load {one:.2f}/{five:.2f}]"


#: Run in a child before the entry point: says "painted" on stdout at the first paint of a
#: main window (the moment the operator sees it), then ends the process at once.
_FIRST_PAINT = """
import os, sys
from PySide6.QtCore import QEvent, QObject
from PySide6.QtWidgets import QApplication, QMainWindow
app = QApplication(sys.argv[:1])
class FirstPaint(QObject):
    def eventFilter(self, watched, event):
        if event.type() == QEvent.Type.Paint and isinstance(watched, QMainWindow):
            print("painted", flush=True)
            os._exit(0)
        return False
first_paint = FirstPaint()
app.installEventFilter(first_paint)
"""
#: The entry point as the desktop starts it (``stepdeck`` is ``python -m app``).
_STEPDECK = _FIRST_PAINT + "import runpy; runpy.run_module('app', run_name='__main__')"
#: The floor: PySide6 and pyqtgraph imported, an empty main window shown.
_BARE = _FIRST_PAINT + "import pyqtgraph; w = QMainWindow(); w.show(); app.exec()"
#: A session that closed with every dock shown, its layout saved as the window saves it.
_REMEMBER_DOCKS = """
from PySide6.QtWidgets import QApplication
from app.profiles import load_profile
from app.settings import StationSettings, default_settings
from app.station import Station
from widgets.main_window import MainWindow
app = QApplication([])
app.setApplicationName("StepDeck"); app.setOrganizationName("StepDeck")
settings = StationSettings(default_settings())
station = Station(load_profile(settings.profile))
window = MainWindow(station, settings)
window.show()
for action in (window.jobs_action, window.telemetry_action, window.developer_action):
    action.trigger()
app.processEvents()
window.save_settings()
names = ",".join(d.objectName() for d in window.docks.built() if d.isVisible())
station.shutdown()
print(names)
"""


def _to_first_paint(source: str, env: dict[str, str]) -> tuple[float, float]:
    """Seconds from starting a Python process running ``source`` to its first paint, and the
    CPU seconds it used to get there (which a loaded machine stretches far less)."""
    import subprocess

    start = time.perf_counter()
    child = subprocess.Popen(
        [sys.executable, "-c", source],
        cwd=ROOT,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        text=True,
    )
    assert child.stdout is not None
    line = child.stdout.readline()
    elapsed = time.perf_counter() - start
    if line.strip() != "painted":
        child.kill()
        child.wait()
        child.stdout.close()
        raise RuntimeError(f"no first paint from the launch ({line!r})")
    # It ends itself at the paint (os._exit): reaped here, with what it used. Not killed
    # first: Popen.kill polls, and that would reap it and lose the figures.
    _, _, usage = os.wait4(child.pid, 0)
    child.returncode = 0
    child.stdout.close()
    return elapsed, usage.ru_utime + usage.ru_stime


def launch_env(home: Path, base: dict[str, str]) -> dict[str, str]:
    """The launches' environment: settings in ``home``, and a bytecode cache there too.

    An operator's station starts from compiled modules (Python writes them at the first
    start, pip at install); a caller with ``PYTHONDONTWRITEBYTECODE`` set would otherwise
    have every launch compile StepDeck's 200 modules from source while the bare window,
    all site-packages, loads compiled ones (1.6x instead of 1.1x on the same code).
    """
    env = dict(
        base,
        QT_QPA_PLATFORM=base.get("QT_QPA_PLATFORM", "offscreen"),
        XDG_CONFIG_HOME=str(home / "config"),
        XDG_CACHE_HOME=str(home / "cache"),
        XDG_DATA_HOME=str(home / "data"),
        PYTHONPYCACHEPREFIX=str(home / "bytecode"),
    )
    env.pop("PYTHONDONTWRITEBYTECODE", None)
    return env


def bench_launch() -> list[str]:
    """The real entry point to its first paint, with the docks a last session left shown.

    Settings live in a temporary XDG config folder, written by a session that
    showed the jobs, telemetry and developer docks, so the launch restores them
    as an operator's second start does; the modules are compiled by a first
    start of each, as on an operator's computer (:func:`launch_env`).  The bare
    window is measured in the same run, alternating, so both see the same disk
    cache and load.
    """
    import subprocess

    with tempfile.TemporaryDirectory() as home:
        env = launch_env(Path(home), dict(os.environ))
        remembered = subprocess.run(
            [sys.executable, "-c", _REMEMBER_DOCKS],
            cwd=ROOT,
            env=env,
            capture_output=True,
            text=True,
            check=True,
        ).stdout.strip()
        _to_first_paint(_STEPDECK, env)  # the first starts compile, as an operator's first
        _to_first_paint(_BARE, env)
        launches: list[tuple[float, float]] = []
        bares: list[tuple[float, float]] = []
        before = _load()
        for _ in range(5):
            launches.append(_to_first_paint(_STEPDECK, env))
            bares.append(_to_first_paint(_BARE, env))
    total, baseline = min(t for t, _ in launches), min(t for t, _ in bares)
    cpu, cpu_bare = min(c for _, c in launches), min(c for _, c in bares)
    return [
        f"launch to first paint, `python -m app` with docks remembered ({remembered}): "
        f"{total * 1000:.0f} ms; bare PySide6 + pyqtgraph empty QMainWindow: "
        f"{baseline * 1000:.0f} ms; ratio {total / baseline:.2f}x (goal <= 1.4x; best of 5, "
        f"medians {statistics.median(t for t, _ in launches) * 1000:.0f} / "
        f"{statistics.median(t for t, _ in bares) * 1000:.0f} ms; CPU {cpu * 1000:.0f} / "
        f"{cpu_bare * 1000:.0f} ms, {cpu / cpu_bare:.2f}x) {before} -> {_load()}"
    ]


def _drain_frames(fd: int, frames: int, timeout: float = 1.0) -> None:
    """Read from ``fd`` until ``frames`` whole lines have come, so each sample starts clean."""
    import select

    seen = 0
    while seen < frames and select.select([fd], [], [], timeout)[0]:
        seen += os.read(fd, 4096).count(b"\n")


def _drain_quiet(fd: int, quiet: float = 0.3) -> None:
    """Read from ``fd`` until it has been silent for ``quiet`` seconds."""
    import select

    while select.select([fd], [], [], quiet)[0]:
        os.read(fd, 4096)


def bench_key_to_pty() -> list[str]:
    """A jog intent through the session and the serial transport to the device's side of a pty.

    Station-less: a Link and a StageSession over a SerialTransport on the pty's
    slave; the "device" is this function, watching the master with select().
    """
    import select
    import tty

    from PySide6.QtWidgets import QApplication

    from app.link import Link
    from app.machine import LinkState, MachineModel
    from app.machines.stage.session import StageSession
    from app.profiles import load_profile
    from protocol.clock import MonotonicClock
    from protocol.transport.serial_link import SerialTransport

    app = QApplication.instance() or QApplication([])
    master, slave = os.openpty()
    tty.setraw(slave)
    transport = SerialTransport(os.ttyname(slave))
    model = MachineModel(load_profile("xy-stage"))
    link = Link(transport)
    session = StageSession(model, link, MonotonicClock(), autotick=False)
    try:
        link.open()
        # The session waits for the device's first word before it takes motion: the "device"
        # speaks every 50 ms, as a stage does, until the session has heard it.
        echo = encode_echo(EchoFrame((EchoPacket(0, 0, 0), EchoPacket(0, 0, 0)), 0, 0))
        deadline = time.monotonic() + 5.0
        spoke = 0.0
        while model.link_state is not LinkState.CONNECTED and time.monotonic() < deadline:
            if time.monotonic() - spoke >= 0.05:
                os.write(master, echo)
                spoke = time.monotonic()
            app.processEvents()
        assert model.link_state is LinkState.CONNECTED, model.link_detail
        _drain_quiet(master)  # the connect burst: speed select and the first reads
        latencies: list[float] = []
        for i in range(1000):
            start = time.perf_counter()
            session.set_jog([1 if i % 2 == 0 else -1, 0])
            readable = select.select([master], [], [], 1.0)[0]
            latencies.append(time.perf_counter() - start)
            assert readable, "the frame never reached the pty"
            _drain_frames(master, 1)
            session.set_jog([0, 0])
            _drain_frames(master, 1)
    finally:
        session.shutdown()
        transport.close()
        app.processEvents()
        os.close(master)
        os.close(slave)
    p50 = statistics.median(latencies) * 1000
    p99 = _percentile(latencies, 0.99) * 1000
    return [
        "key press -> bytes readable on the device side of a pty "
        f"(session.set_jog -> SerialTransport -> select on the master): "
        f"p50 {p50:.3f} ms, p99 {p99:.3f} ms"
    ]


def bench_echo_round_trip() -> list[str]:
    """A command frame to the emulator process over a pty and its echo decoded back.

    No Qt: the transport's listener decodes on the reader thread, so the figure
    is the link and the emulator's control cycle (5 ms), not the GUI's event loop.
    """
    import selectors
    import subprocess
    import threading

    from protocol.transport.serial_link import SerialTransport

    class EchoWaiter:
        def __init__(self) -> None:
            self.decoder = StageDecoder(2)
            self.made = threading.Event()
            self.echo = threading.Event()

        def connection_made(self) -> None:
            self.made.set()

        def data_received(self, data: bytes) -> None:
            if any(isinstance(frame, EchoFrame) for frame in self.decoder.feed(data)):
                self.echo.set()

        def connection_lost(self, reason: str | None) -> None:
            if reason is not None:
                print(f"echo round-trip: link lost: {reason}", file=sys.stderr)

    command = [sys.executable, "-m", "protocol.emulator", "--profile", "xy-stage", "--pty"]
    nop = encode_command(CommandFrame((CommandPacket(CommandId.NOP),) * 2))
    with subprocess.Popen(
        command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL
    ) as emulator:
        assert emulator.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(emulator.stdout, selectors.EVENT_READ)
            assert selector.select(15.0), "the emulator printed no device path"
        transport = SerialTransport(emulator.stdout.readline().decode().strip())
        waiter = EchoWaiter()
        transport.set_listener(waiter)
        round_trips: list[float] = []
        try:
            transport.open()
            assert waiter.made.wait(5.0), "could not open the emulator's pty"
            for _ in range(500):
                waiter.echo.clear()
                start = time.perf_counter()
                transport.write(nop)
                assert waiter.echo.wait(1.0), "no echo within 1 s"
                round_trips.append(time.perf_counter() - start)
        finally:
            transport.close()
            emulator.terminate()
            emulator.wait(timeout=5)
    p50 = statistics.median(round_trips) * 1000
    p99 = _percentile(round_trips, 0.99) * 1000
    return [
        "echo round-trip over a pty to the emulator process (NOP frame written -> echo decoded, "
        f"5 ms control cycle): p50 {p50:.2f} ms, p99 {p99:.2f} ms over 500"
    ]


def _telemetry_run(
    throttle_ms: int | None, seconds: float = 5.0, axes: int = 2, window_s: float = 600.0
) -> tuple[float, float, int]:
    """Feed a shown telemetry dock ``2 * axes`` curves at 1 kHz over a full ``window_s``.

    Returns (frames painted per second, share of one core, samples per curve held).
    ``throttle_ms`` None keeps the recorder's default.  ``axes`` beyond the
    xy-stage's two are added to its profile (the curves are an axis's
    position and velocity).  The sine sweeps are computed before the clock
    starts, so the share is the station's and the dock's, not the test
    signal's.
    """
    import dataclasses
    import math

    import numpy as np
    from PySide6.QtCore import QEventLoop, Qt, QTimer
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station
    from app.telemetry import TelemetryRecorder
    from widgets.telemetry_dock import TelemetryDock

    def waves(t: np.ndarray, axis: int) -> tuple[np.ndarray, np.ndarray]:
        """Position and velocity of a sine sweep, a different period per axis."""
        omega = 2 * math.pi / (7.0 + 4 * axis)
        return 20.0 + 15.0 * np.sin(omega * t), 15.0 * omega * np.cos(omega * t)

    app = QApplication.instance() or QApplication([])
    clock = ManualClock()  # advanced sample by sample, in step with the wall clock
    profile = load_profile("xy-stage")
    extra = tuple(
        dataclasses.replace(profile.axes[0], name=name) for name in ("U", "V", "W")[: axes - 2]
    )
    profile = dataclasses.replace(profile, axes=profile.axes + extra)
    station = Station(profile, clock, realtime=False)
    model = station.model
    options = {} if throttle_ms is None else {"throttle_ms": throttle_ms}
    recorder = TelemetryRecorder(station, **options)
    dock = TelemetryDock(recorder)
    dock.resize(1200, 700)
    dock.show()
    dock.window_combo.setCurrentIndex(dock.window_combo.findData(window_s))
    rate = 1000
    t = np.arange(int(window_s * rate)) / rate
    names = [axis.name for axis in profile.axes]
    for axis, name in enumerate(names):
        position, velocity = waves(t, axis)
        recorder.extend(f"{name} position", t, position)
        recorder.extend(f"{name} velocity", t, velocity)
    del t, position, velocity
    clock.advance(window_s)
    ahead = window_s + (np.arange(int((seconds + 2) * rate)) + 1) / rate
    fed_values = [[v.tolist() for v in waves(ahead, axis)] for axis in range(len(names))]
    app.processEvents()

    counter = _paint_counter()
    dock.graphics.viewport().installEventFilter(counter)
    fed = 0
    wall_start = time.perf_counter()

    def feed() -> None:
        """Every sample due by the wall clock, each at its own millisecond."""
        nonlocal fed
        due = min(int((time.perf_counter() - wall_start) * rate), len(ahead))
        while fed < due:
            clock.advance(1 / rate)
            for axis in range(len(names)):
                positions, velocities = fed_values[axis]
                model.update_axis(axis, position=positions[fed], velocity=velocities[fed])
            fed += 1

    feeder = QTimer()
    feeder.setTimerType(Qt.TimerType.PreciseTimer)
    feeder.timeout.connect(feed)
    loop = QEventLoop()
    cpu_start = time.process_time()
    wall_start = time.perf_counter()
    feeder.start(2)
    QTimer.singleShot(round(seconds * 1000), loop.quit)
    loop.exec()
    feeder.stop()
    wall = time.perf_counter() - wall_start
    cpu = time.process_time() - cpu_start
    held = len(recorder.recorded(f"{names[0]} position")[0])
    dock.close()
    dock.deleteLater()
    recorder.deleteLater()
    station.shutdown()
    app.processEvents()
    return counter.paints / wall, cpu / wall, held


def _telemetry_idle(with_dock: bool, seconds: float = 10.0) -> tuple[float, float]:
    """An idle stage on the built-in emulator, in real time: (share of one core, frames/s).

    The station, the emulator's control loop and 10 frames a second run
    either way; with the dock, its plots scroll and hold every series.
    """
    from PySide6.QtCore import QEventLoop, QTimer
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station
    from app.telemetry import TelemetryRecorder
    from protocol.clock import MonotonicClock
    from protocol.stage.codec import Subscriber
    from widgets.telemetry_dock import TelemetryDock

    app = QApplication.instance() or QApplication([])
    station = Station(load_profile("xy-stage"), MonotonicClock(), realtime=True)
    station.connect_emulator()
    recorder = TelemetryRecorder(station)
    recorder.set_variable(Subscriber.BATTERY_VOLTAGE)
    dock = TelemetryDock(recorder)
    counter = _paint_counter()
    if with_dock:
        dock.resize(1200, 700)
        dock.show()
        dock.graphics.viewport().installEventFilter(counter)
    loop = QEventLoop()
    QTimer.singleShot(2000, loop.quit)  # connect and settle
    loop.exec()
    counter.paints = 0
    cpu_start, wall_start = time.process_time(), time.perf_counter()
    QTimer.singleShot(round(seconds * 1000), loop.quit)
    loop.exec()
    wall = time.perf_counter() - wall_start
    cpu = time.process_time() - cpu_start
    dock.close()
    dock.deleteLater()
    recorder.deleteLater()
    station.shutdown()
    app.processEvents()
    return cpu / wall, counter.paints / wall


def bench_telemetry_plots() -> list[str]:
    """Curves at 1 kHz each in a full window, drawn by the telemetry dock; and idle.

    The window is pre-filled (4 curves and 10 minutes, 600 000 samples a
    curve; 8 curves and 30 minutes, 1 800 000), then every axis's position
    and velocity are fed through the machine model at 1 kHz for about 5 s of
    wall time, with the dock shown offscreen.  With the recorder's default
    throttle the frame rate is the throttle's (about 60 Hz); a second run
    with a 10 ms throttle shows the headroom left.  The idle rows: a
    connected, standing stage, with and without the dock shown.  Each
    figure carries its goal and the load average (1 and 5 min) it was
    measured under.
    """
    lines = []
    cases = (
        (None, 2, 600.0, "default throttle", 15),
        (None, 4, 1800.0, "default throttle", 25),
        (10, 2, 600.0, "10 ms throttle", None),
    )
    for throttle_ms, axes, window_s, what, goal in cases:
        fps, core, held = _telemetry_run(throttle_ms, axes=axes, window_s=window_s)
        one, five, _ = os.getloadavg()
        target = f"goal >= 60 frames/s at <= {goal} %" if goal else "headroom, no goal"
        met = "" if goal is None else ("met" if fps >= 59 and 100 * core <= goal else "NOT met")
        lines.append(
            f"telemetry dock, {2 * axes} curves x 1 kHz, {window_s / 60:g}-minute window "
            f"({held:,} samples per curve), {what}: {fps:.1f} frames/s drawn, "
            f"{100 * core:.0f} % of one core ({target}{': ' + met if met else ''}), "
            f"{1000 * core / fps:.1f} ms of processor time per frame with the feeding "
            f"[load {one:.2f}/{five:.2f}]"
        )
    for with_dock in (False, True):
        core, fps = _telemetry_idle(with_dock)
        one, five, _ = os.getloadavg()
        what = f"dock shown, {fps:.1f} frames/s" if with_dock else "dock hidden"
        lines.append(
            f"telemetry idle, stage connected to the built-in emulator, standing, {what}: "
            f"{100 * core:.1f} % of one core (goal <= 10 % with the dock) "
            f"[load {one:.2f}/{five:.2f}]"
        )
    return lines


def _large_program(operations: int) -> Program:
    """A plotter-like program: pen-up travel, a pen-down stroke of 8 moves, a drill, repeated."""
    import math

    from app.jobs.program import Operation, OpKind, Program, SourceRef, move

    ops: list[Operation] = []
    line = 0
    while len(ops) < operations:
        line += 1
        k = len(ops)
        cx, cy = 5 + (k * 0.37) % 40, 5 + (k * 0.11) % 40
        ops.append(move(SourceRef("big.job", line), X=cx, Y=cy))
        ops.append(Operation(OpKind.PEN_DOWN, SourceRef("big.job", line)))
        for s in range(8):
            angle = 2 * math.pi * s / 8
            ops.append(
                move(SourceRef("big.job", line), X=cx + math.cos(angle), Y=cy + math.sin(angle))
            )
        ops.append(Operation(OpKind.PEN_UP, SourceRef("big.job", line)))
        ops.append(Operation(OpKind.DRILL, SourceRef("big.job", line)))
    return Program("big", tuple(ops[:operations]))


def bench_job_preview() -> list[str]:
    """Build time of the jobs preview for a 100 000-operation program, shown offscreen.

    ``build_seconds`` is what ``set_program`` takes (the path arrays and the
    curves' data); the first paint after it is timed separately, as the
    operator waits for both.
    """
    from PySide6.QtWidgets import QApplication

    from app.profiles import load_profile
    from app.station import Station
    from widgets.jobs.preview import JobPreview

    app = QApplication.instance() or QApplication([])
    program = _large_program(100_000)
    station = Station(load_profile("xy-stage"), ManualClock(), realtime=False)
    preview = JobPreview(station, confirm=lambda _text: False)
    preview.resize(900, 700)
    preview.show()
    app.processEvents()
    builds = []
    paints = []
    for _ in range(3):
        preview.set_program(None)
        app.processEvents()
        preview.set_program(program)
        builds.append(preview.build_seconds)
        start = time.perf_counter()
        preview.plot_widget.viewport().repaint()
        paints.append(time.perf_counter() - start)
    preview.close()
    preview.deleteLater()
    station.shutdown()
    app.processEvents()
    return [
        f"job preview, 100,000-operation program: build {min(builds):.3f} s "
        f"(median {statistics.median(builds):.3f} s), first paint {min(paints):.3f} s"
    ]


def bench_dry_run() -> list[str]:
    """Emulated seconds per wall second of the dry run on a 10,000-move, two-axis program."""
    import random

    from app.jobs.estimate import estimate
    from app.jobs.program import Program, SourceRef, move
    from app.profiles import load_profile

    rng = random.Random(1)
    program = Program(
        "bench",
        tuple(
            move(SourceRef("bench.txt", i + 1), X=rng.uniform(0, 50), Y=rng.uniform(0, 50))
            for i in range(10_000)
        ),
    )
    profile = load_profile("xy-stage")
    runs: list[tuple[float, float]] = []
    for _ in range(3):
        start = time.perf_counter()
        result = estimate(program, profile, {}, 0.1)
        runs.append((time.perf_counter() - start, result.total_s))
    wall, emulated = min(runs)
    return [
        f"dry run, 10,000 two-axis moves: {emulated:,.0f} emulated s in {wall:.3f} s wall "
        f"= {emulated / wall:,.0f}x real time (goal >= 500x)"
    ]


def bench_drill_eta() -> list[str]:
    """The drill's job estimate against the emulated run, per Excellon board (issue 19: 5 %).

    Each board on a fresh emulated drill, as after switching it on: the
    station has seen no homing, so the job homes, prompts per bit (confirmed
    at once), drills and parks; the estimate (``protocol/drill/timing.py``)
    against the emulator's time for the same job.
    """
    from PySide6.QtWidgets import QApplication

    from app.jobs.formats.excellon.reader import build_drill_program, read_drill_file
    from app.jobs.run.runner import JobRunner, JobState
    from app.profiles import load_profile
    from tests.helpers.harness import StationHarness

    app = QApplication.instance() or QApplication([])
    data = ROOT / "tests" / "data"
    boards = [data / "samples" / "pcb-driver" / "driver"]
    boards += sorted((data / "realdata" / "excellon").iterdir())
    lines = []
    with tempfile.TemporaryDirectory() as checkpoints:
        for path in boards:
            harness = StationHarness(load_profile("pcb-drill"))
            try:
                harness.connect()
                harness.run_until(lambda h=harness: h.drill_emulator.homed, timeout=10)
                runner = JobRunner(harness.station, Path(checkpoints))
                program = build_drill_program(read_drill_file(path))
                if runner.load(program) or runner.progress.estimate is None:
                    lines.append(f"drill ETA {path.name}: refused on this machine")
                    continue
                eta = runner.progress.estimate.total_s
                runner.waitingForOperator.connect(lambda _m, r=runner: r.confirm())
                runner.start()
                harness.run_until(
                    lambda r=runner: r.state not in (JobState.RUNNING, JobState.WAITING),
                    timeout=3600,
                )
                ran = runner.progress.elapsed_s
                lines.append(
                    f"drill ETA {path.name}: estimate {eta:.1f} s, emulated {ran:.1f} s, "
                    f"ratio {eta / ran:.3f} (goal 0.95…1.05), {runner.state.value}"
                )
            finally:
                harness.close()
    del app
    return lines


def bench_drill_order() -> list[str]:
    """Load + optimise time and travel (file order vs optimised) per real board and 50 000 holes."""
    import numpy as np

    from app.jobs.formats.excellon.hole_order import order_holes
    from app.jobs.formats.excellon.reader import plan_drilling, read_drill_file

    data = ROOT / "tests" / "data"
    boards = [data / "samples" / "pcb-driver" / "driver"]
    boards += sorted((data / "realdata" / "excellon").iterdir())
    lines = []
    for path in boards:
        start = time.perf_counter()
        job = read_drill_file(path)
        loaded = time.perf_counter()
        plan = plan_drilling(job)
        done = time.perf_counter()
        lines.append(
            f"drill {path.name}: {len(job.holes)} holes, {len(job.slots)} slots, "
            f"load {1000 * (loaded - start):.1f} ms + optimise {1000 * (done - loaded):.1f} ms, "
            f"travel {plan.file_travel_mm:,.1f} mm in file order -> {plan.travel_mm:,.1f} mm "
            f"({100 * (1 - plan.travel_mm / plan.file_travel_mm):.0f}% shorter)"
        )
    points = np.random.default_rng(1).uniform(0, 300, size=(50_000, 2))
    start = time.perf_counter()
    result = order_holes(points)
    elapsed = time.perf_counter() - start
    lines.append(
        f"drill synthetic 50,000 holes on 300x300 mm: optimise {elapsed:.2f} s, "
        f"travel {result.file_length:,.0f} mm in file order -> {result.length:,.0f} mm"
    )
    return lines


def bench_string_art() -> list[str]:
    """Load + preview and winding-program build for 300 nails and 10 000 connections.

    The job is written as an SD-card pair (random nail order, no nail twice in
    a row) and read the way the dock reads it: load = the files to a checked
    job and its program; preview = ``JobPreview.set_program`` (paths, nails,
    thread); build = ``build_program`` alone, on the string-art profile.
    """
    import random
    import tempfile

    from PySide6.QtWidgets import QApplication

    from app.jobs.formats.string_art.export import export_sd_files
    from app.jobs.formats.string_art.program import StringArtProgram, build_program
    from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
    from app.jobs.loaders import load_job
    from app.profiles import load_profile
    from app.station import Station
    from widgets.jobs.preview import JobPreview

    rng = random.Random(1)
    sequence = [0]
    for _ in range(10_000 - 1):
        sequence.append((sequence[-1] + rng.randrange(1, 300)) % 300)
    job = StringArtJob(StringArtParams(0, 300, 25.0), tuple(sequence))
    profile = load_profile("string-art")
    axes = [axis.name for axis in profile.axes]
    app = QApplication.instance() or QApplication([])
    station = Station(profile, ManualClock(), realtime=False)
    preview = JobPreview(station, confirm=lambda _text: False)
    preview.resize(900, 700)
    preview.show()
    app.processEvents()
    loads, previews, builds, paints = [], [], [], []
    with tempfile.TemporaryDirectory() as folder:
        param, _poradi = export_sd_files(job, Path(folder))
        for _ in range(3):
            preview.set_program(None)
            app.processEvents()
            start = time.perf_counter()
            program = load_job(param, axes)
            loaded = time.perf_counter()
            preview.set_program(program)
            shown = time.perf_counter()
            preview.plot_widget.viewport().repaint()
            painted = time.perf_counter()
            loads.append(loaded - start)
            previews.append(shown - loaded)
            paints.append(painted - shown)
            start = time.perf_counter()
            built = build_program(job, profile)
            builds.append(time.perf_counter() - start)
    assert isinstance(program, StringArtProgram)
    preview.close()
    preview.deleteLater()
    station.shutdown()
    app.processEvents()
    return [
        f"string art, 300 nails and 10,000 connections ({len(program):,} operations): "
        f"load {min(loads):.3f} s + preview {min(previews):.3f} s "
        f"(first paint {min(paints):.3f} s); winding-program build {min(builds):.3f} s; "
        f"estimated {(built.estimate_s or 0.0) / 3600:.1f} h on the winder"
    ]


def _write_plotter_gcode(path: Path, lines: int) -> None:
    """Typical plotter G-code: ``G1 X12.345 Y67.890 F3000`` strokes, the pen up/down every 50."""
    import random

    rng = random.Random(1)
    out = ["G21", "G90"]
    while len(out) < lines:
        out.append(f"G0 X{rng.uniform(0, 290):.3f} Y{rng.uniform(0, 190):.3f}")
        out.append("M3 S1000")
        out += [
            f"G1 X{rng.uniform(0, 290):.3f} Y{rng.uniform(0, 190):.3f} F3000" for _ in range(47)
        ]
        out.append("M5")
    path.write_text("\n".join(out[:lines]) + "\n", encoding="ascii")


#: Run in a fresh interpreter so its peak RSS is the load's own, not the benchmarks' before it.
_GCODE_CHILD = """
import json, resource, sys, time
from pathlib import Path
sys.path.insert(0, sys.argv[2])
from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.loaders import JobOptions, load_job
from app.profiles import load_profile
from widgets.jobs.preview import ProgramGeometry

def peak_mb():
    # VmHWM belongs to this process image; ru_maxrss survives exec and would report
    # the benchmark's own (large) parent process instead.
    try:
        with open("/proc/self/status") as status:
            for line in status:
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024
    except OSError:
        pass
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024

profile = load_profile("grbl-plotter")
options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
imports_mb = peak_mb()
start = time.perf_counter()
program = load_job(Path(sys.argv[1]), [axis.name for axis in profile.axes], options)
loaded = time.perf_counter()
geometry = ProgramGeometry(program, "X", "Y")
drawn = time.perf_counter()
peak = peak_mb()
estimate = estimate_gcode(program, profile)
timed = time.perf_counter()
print(json.dumps({
    "operations": len(program), "load": loaded - start, "geometry": drawn - loaded,
    "estimate": timed - drawn, "imports_mb": imports_mb, "peak_mb": peak,
    "work_points": int(len(geometry.work.x)), "model_hours": estimate.total_s / 3600,
}))
"""


def bench_gcode_load_1m() -> list[str]:
    """Load and preview geometry of a synthetic 1,000,000-line plotter file (goal: <= 5 s, 500 MB).

    The file is written to a temporary directory and read by a separate
    interpreter, whose peak RSS (``ru_maxrss``) covers the imports (Qt,
    pyqtgraph, numpy), the load and the preview geometry; the figure after
    the imports is given too, so the load's own share is plain.
    """
    import json
    import subprocess
    import tempfile

    lines = 1_000_000
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "synthetic-1m.gcode"
        _write_plotter_gcode(path, lines)
        size_mb = path.stat().st_size / 1e6
        runs = []
        for _ in range(3):
            child = subprocess.run(
                [sys.executable, "-c", _GCODE_CHILD, str(path), str(ROOT)],
                check=True,
                capture_output=True,
                text=True,
                env={**os.environ, "QT_QPA_PLATFORM": "offscreen"},
            )
            runs.append(json.loads(child.stdout.strip().splitlines()[-1]))
    best = min(runs, key=lambda r: r["load"] + r["geometry"])
    total = best["load"] + best["geometry"]
    peak = max(r["peak_mb"] for r in runs)
    return [
        f"gcode_load_1m: {lines:,} lines ({size_mb:.1f} MB, {best['operations']:,} operations): "
        f"load {best['load']:.2f} s + preview geometry {best['geometry']:.2f} s = {total:.2f} s "
        f"(goal <= 2.5 s: {_met(total <= 2.5)}; best of 3, median load "
        f"{statistics.median(r['load'] for r in runs):.2f} s); "
        f"peak RSS {peak:.0f} MB, the highest of the 3 ({best['imports_mb']:.0f} MB after "
        f"imports; goal <= 250 MB: {_met(peak <= 250)}; peer, from issue #36, not this run: "
        f"gcodeparser 8.9 s, 744 MiB); "
        f"estimate {best['estimate']:.2f} s ({best['model_hours']:.1f} h of plotting)"
    ]


def _met(ok: bool) -> str:
    return "met" if ok else "NOT met"


#: A 2-million-entry poradi.txt loaded in a fresh interpreter (its peak RSS is the load's own).
_PORADI_CHILD = """
import json, sys, time
from pathlib import Path
sys.path.insert(0, sys.argv[2])
from app.jobs.loaders import load_job
from app.jobs.program import check_limits
from app.profiles import load_profile

def peak_mb():
    with open("/proc/self/status") as status:
        for line in status:
            if line.startswith("VmHWM:"):
                return int(line.split()[1]) / 1024
    return 0.0

profile = load_profile("string-art")
imports_mb = peak_mb()
start = time.perf_counter()
program = load_job(Path(sys.argv[1]), [axis.name for axis in profile.axes])
loaded = time.perf_counter()
peak = peak_mb()
refused = check_limits(program, profile.travel_limits())
program.fingerprint()
checked = time.perf_counter()
print(json.dumps({
    "operations": len(program), "load": loaded - start, "check": checked - loaded,
    "imports_mb": imports_mb, "peak_mb": peak, "refused": len(refused),
}))
"""


def bench_string_art_2m() -> list[str]:
    """A generator's 2,000,000-entry poradi.txt (160 nails): goal <= 5 s and <= 500 MB.

    Read by a separate interpreter as the dock's worker reads it (``load_job``:
    the numbers, the checks, the winding program); the limit check and the
    checkpoint fingerprint the runner adds are timed apart.
    """
    import json
    import random
    import subprocess
    import tempfile

    entries = 2_000_000
    rng = random.Random(1)
    sequence = [0]
    for _ in range(entries - 1):
        sequence.append((sequence[-1] + rng.randrange(1, 160)) % 160)
    with tempfile.TemporaryDirectory() as directory:
        folder = Path(directory)
        (folder / "param.txt").write_text("tvar = 0\npocet_hrebiku = 160\npolomer_matrice = 12\n")
        poradi = folder / "poradi.txt"
        poradi.write_text(f"{entries}\n" + "\n".join(map(str, sequence)) + "\n")
        size_mb = poradi.stat().st_size / 1e6
        runs = [
            json.loads(
                subprocess.run(
                    [sys.executable, "-c", _PORADI_CHILD, str(poradi), str(ROOT)],
                    check=True,
                    capture_output=True,
                    text=True,
                )
                .stdout.strip()
                .splitlines()[-1]
            )
            for _ in range(3)
        ]
    best = min(runs, key=lambda r: r["load"])
    peak = max(r["peak_mb"] for r in runs)
    return [
        f"string_art_2m: poradi.txt of {entries:,} entries ({size_mb:.1f} MB, "
        f"{best['operations']:,} operations): load {best['load']:.2f} s (goal <= 1.5 s: "
        f"{_met(best['load'] <= 1.5)}; best of 3), peak RSS {peak:.0f} MB, the highest of "
        f"the 3 ({best['imports_mb']:.0f} MB after imports; goal <= 250 MB: {_met(peak <= 250)}); "
        f"limit check + fingerprint {best['check']:.2f} s"
    ]


def _poradi_2m(folder: Path, entries: int = 2_000_000, nails: int = 160) -> Path:
    """A generator's ``entries``-entry poradi.txt (with its param.txt) in ``folder``."""
    import random

    rng = random.Random(1)
    sequence = [0]
    for _ in range(entries - 1):
        sequence.append((sequence[-1] + rng.randrange(1, nails)) % nails)
    (folder / "param.txt").write_text(f"tvar = 0\npocet_hrebiku = {nails}\npolomer_matrice = 12\n")
    poradi = folder / "poradi.txt"
    poradi.write_text(f"{entries}\n" + "\n".join(map(str, sequence)) + "\n")
    return poradi


def _open_measuring_holds(app: Any, dock: Any, path: Path, settle_s: float) -> tuple[float, float]:
    """Open ``path`` in ``dock`` on its loading thread: seconds until loaded, longest GUI hold.

    A 5 ms timer on the GUI thread ticks throughout; the longest gap between
    its ticks is how long the GUI thread went unserved.  ``settle_s`` more of
    the event loop after the load takes in the first paint of the preview.
    """
    from PySide6.QtCore import QElapsedTimer, QTimer

    clock = QElapsedTimer()
    gaps: list[float] = []
    last = [0.0]

    def tick() -> None:
        now = clock.nsecsElapsed() / 1e9
        gaps.append(now - last[0])
        last[0] = now

    timer = QTimer()
    timer.timeout.connect(tick)
    timer.start(5)
    clock.start()
    dock.open_path(path, background=True)
    while dock._loading is not None:
        app.processEvents()
        time.sleep(0.001)
    loaded = clock.nsecsElapsed() / 1e9
    if settle_s > 0:
        dock.preview.plot_widget.viewport().update()
        settle = time.perf_counter() + settle_s
        while time.perf_counter() < settle:
            app.processEvents()
            time.sleep(0.001)
    timer.stop()
    return loaded, max(gaps, default=0.0)


def bench_string_art_2m_dock() -> list[str]:
    """The same 2,000,000-entry poradi.txt opened in a shown jobs dock (string-art winder).

    The dock reads it as the Open dialog does (its worker thread); a 5 ms timer
    measures the longest the GUI thread went unserved from Open to the job READY
    and its preview painted (goal <= 100 ms), and the time to READY.
    """
    import tempfile

    from PySide6.QtWidgets import QApplication

    from app.jobs.run.runner import JobRunner, JobState
    from app.profiles import load_profile
    from app.station import Station
    from widgets.jobs.dock import JobsDock

    app = QApplication.instance() or QApplication([])
    station = Station(load_profile("string-art"), ManualClock(), realtime=False)
    results: list[tuple[float, float, int]] = []
    with tempfile.TemporaryDirectory() as directory:
        poradi = _poradi_2m(Path(directory))
        for _ in range(2):
            runner = JobRunner(station, Path(directory) / "checkpoints")
            dock = JobsDock(station, runner, confirm=lambda _t: False, throttle_ms=0)
            dock.resize(900, 700)
            dock.show()
            app.processEvents()
            ready, hold = _open_measuring_holds(app, dock, poradi, settle_s=0.5)
            if runner.state is not JobState.READY or runner.program is None:
                raise RuntimeError(dock.messages.toPlainText())
            results.append((ready, hold, len(runner.program)))
            dock.close()
            dock.deleteLater()
            runner.deleteLater()
            app.processEvents()
    station.shutdown()
    return [
        f"string_art_2m_dock: 2,000,000-entry poradi.txt opened in the jobs dock "
        f"({results[0][2]:,} operations): ready in {min(r[0] for r in results):.2f} s, "
        f"longest GUI-thread hold {max(r[1] for r in results) * 1000:.0f} ms "
        f"(goal <= 100 ms: {_met(max(r[1] for r in results) <= 0.1)}; load, checks, estimate "
        f"and first paint of the preview)"
    ]


def bench_gcode_1m_dock() -> list[str]:
    """The 1,000,000-line plotter file opened in a shown jobs dock (grbl-plotter).

    The dock reads it as the Open dialog does (its worker thread); a 5 ms timer
    measures the longest the GUI thread went unserved from Open to the job READY
    and its preview painted (goal <= 100 ms), and the time to READY.
    """
    import tempfile

    from PySide6.QtWidgets import QApplication

    from app.jobs.run.runner import JobRunner, JobState
    from app.profiles import load_profile
    from app.station import Station
    from widgets.jobs.dock import JobsDock

    app = QApplication.instance() or QApplication([])
    station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    results: list[tuple[float, float, int]] = []
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "synthetic-1m.gcode"
        _write_plotter_gcode(path, 1_000_000)
        for _ in range(2):
            runner = JobRunner(station, Path(directory) / "checkpoints")
            dock = JobsDock(station, runner, confirm=lambda _t: False, throttle_ms=0)
            dock.resize(900, 700)
            dock.show()
            app.processEvents()
            ready, hold = _open_measuring_holds(app, dock, path, settle_s=0.5)
            if runner.state is not JobState.READY or runner.program is None:
                raise RuntimeError(dock.messages.toPlainText())
            results.append((ready, hold, len(runner.program)))
            dock.close()
            dock.deleteLater()
            runner.deleteLater()
            app.processEvents()
    station.shutdown()
    hold = max(r[1] for r in results)
    return [
        f"gcode_1m_dock: 1,000,000-line G-code file opened in the jobs dock "
        f"({results[0][2]:,} operations): ready in {min(r[0] for r in results):.2f} s, "
        f"longest GUI-thread hold {hold * 1000:.0f} ms (goal <= 100 ms: {_met(hold <= 0.1)}; "
        f"load, checks, estimate and first paint of the preview)"
    ]


def bench_huge_arcs() -> list[str]:
    """2000 huge G2 arcs (44 KB) opened in the jobs dock: refused in <= 1 s, stall <= 100 ms.

    Before the pre-flight each arc became 20,000 vertices and the window froze
    for 30-45 s.  The dock reads it as the Open dialog does (on its worker
    thread); a 5 ms timer measures the longest the event loop went unserved.
    """
    import tempfile

    from PySide6.QtWidgets import QApplication

    from app.jobs.run.runner import JobRunner
    from app.profiles import load_profile
    from app.station import Station
    from widgets.jobs.dock import JobsDock

    app = QApplication.instance() or QApplication([])
    station = Station(load_profile("grbl-plotter"), ManualClock(), realtime=False)
    results = []
    with tempfile.TemporaryDirectory() as directory:
        path = Path(directory) / "huge-arcs.gcode"
        path.write_text("G0 X10 Y10 F600\n" + "G2 X10 Y10 I-900000 J0\n" * 2000)
        size_kb = path.stat().st_size / 1000
        for _ in range(3):
            runner = JobRunner(station, Path(directory) / "checkpoints")
            dock = JobsDock(station, runner, confirm=lambda _t: False, throttle_ms=0)
            dock.show()
            app.processEvents()
            refused, hold = _open_measuring_holds(app, dock, path, settle_s=0.0)
            text = dock.messages.toPlainText()
            assert "arc too long" in text and runner.program is None, text
            results.append((refused, hold))
            dock.close()
            dock.deleteLater()
            app.processEvents()
    station.shutdown()
    refused = min(r for r, _ in results)
    return [
        f"huge_arcs: {size_kb:.0f} KB of 2000 huge arcs refused in {refused * 1000:.0f} ms "
        f"(goal <= 1 s; best of 3), longest event-loop stall "
        f"{max(s for _, s in results) * 1000:.0f} ms (goal <= 100 ms)"
    ]


BENCHMARKS: list[Callable[[], list[str]]] = [
    bench_decode,
    bench_emulated_move,
    bench_key_to_frame,
    bench_launch,
    bench_key_to_pty,
    bench_echo_round_trip,
    bench_telemetry_plots,
    bench_job_preview,
    bench_dry_run,
    bench_drill_order,
    bench_drill_eta,
    bench_drill_order_50k,
    bench_drill_order_quality,
    bench_string_art,
    bench_gcode_load_1m,
    bench_string_art_2m,
    bench_string_art_2m_dock,
    bench_gcode_1m_dock,
    bench_huge_arcs,
    bench_gcode_streaming,
    bench_gcode_job_streaming,
    bench_gcode_delivery,
    bench_gcode_delivery_edges,
    bench_string_art_generator,
    bench_string_art_peers,
    bench_gcode_eta,
    bench_grbl_planner_vs_grbl_sim,
    bench_resume_file_offset,
    bench_start_from_1m,
]


def _busy_core() -> Any:
    """A separate process spinning on one core, for ``--loaded`` (killed by the caller)."""
    import subprocess

    return subprocess.Popen([sys.executable, "-c", "while True: pass"])


def _name(bench: Callable[[], list[str]]) -> str:
    return bench.__name__.removeprefix("bench_")


def main(argv: list[str] | None = None) -> None:
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument(
        "--loaded",
        action="store_true",
        help="keep one core busy with a separate process (a busy loop) while measuring",
    )
    parser.add_argument(
        "--only",
        metavar="NAME[,NAME]",
        help="run only these rows: " + ", ".join(_name(b) for b in BENCHMARKS),
    )
    args = parser.parse_args(argv)
    chosen = BENCHMARKS
    if args.only:
        wanted = [name.strip().removeprefix("bench_") for name in args.only.split(",")]
        known = {_name(b): b for b in BENCHMARKS}
        unknown = [name for name in wanted if name not in known]
        if unknown:
            parser.error(f"no such row: {', '.join(unknown)} (rows: {', '.join(known)})")
        chosen = [known[name] for name in wanted]
    busy = _busy_core() if args.loaded else None
    try:
        if busy is not None:
            time.sleep(1.0)  # let it take its core before the first figure
            print(f"--loaded: one core kept busy by process {busy.pid} {_load()}", flush=True)
        for bench in chosen:
            for line in bench():
                # Every figure with the load it was measured under (rows that measure it
                # themselves, before and after, say so already).
                print(line if "[load" in line else f"{line} {_load()}", flush=True)
    finally:
        if busy is not None:
            busy.kill()
            busy.wait()


if __name__ == "__main__":
    main()
