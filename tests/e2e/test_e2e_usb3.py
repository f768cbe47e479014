"""End to end with the three-axis unit: the station, the serial transport, the emulator process.

The emulated unit runs as its own process on a pseudo-terminal
(``python -m protocol.emulator --profile usb3 --pty --controls``); the
station talks to it through ``connect_serial`` at the unit's 19200 baud, on
the real clock, and the test plays the unit's own menu through the
emulator's control lines on its standard input.  Nothing is faked, so every
wait is bounded and polls the model — no fixed sleeps.

The unit moves at most 300 pulses a second: 12.5 mm at 1/8 step is 20000
pulses, over a minute of real time.  The emulator's clock therefore runs
``TIME_SCALE`` times faster than real time; the wire, the pty and the station
are untouched by it, and the counts asserted are exact either way.
"""

from __future__ import annotations

import selectors
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.machines.usb3.session import Usb3Session
from app.profiles import load_profile
from app.station import Station
from protocol.usb3.codec import StepSize, Thread
from widgets.panels.usb3 import Usb3Panel

ROOT = Path(__file__).resolve().parents[2]
STARTUP_TIMEOUT = 15.0
#: How much faster than real time the emulated unit runs (1 for a real-time run).
TIME_SCALE = 20
#: 12.5 mm at 1/8 step: 20000 pulses at up to 300 a second, plus the ramps.
MOVE_TIMEOUT_MS = round(1000 * (20000 / 300 + 5) / TIME_SCALE) + 10_000
X = 0


class Usb3Emulator:
    """The emulator process: its device path, and its standard input for control lines."""

    def __init__(self) -> None:
        command = [
            sys.executable,
            "-m",
            "protocol.emulator",
            "--profile",
            "usb3",
            "--pty",
            "--controls",
            "--time-scale",
            str(TIME_SCALE),
        ]
        self.process = subprocess.Popen(
            command,
            cwd=ROOT,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
        )
        self.path = ""

    def wait_ready(self) -> str:
        """The device path, once the emulator has printed it (it is serving then)."""
        assert self.process.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(self.process.stdout, selectors.EVENT_READ)
            assert selector.select(STARTUP_TIMEOUT), "the emulator printed no device path"
        self.path = self.process.stdout.readline().decode().strip()
        assert self.path.startswith("/dev/"), self.path
        return self.path

    def control(self, line: str) -> None:
        """One line on the emulator's standard input: the unit's own controls."""
        assert self.process.stdin is not None
        self.process.stdin.write(line.encode() + b"\n")
        self.process.stdin.flush()

    def stop(self) -> bytes:
        """End the process (always, however the test went) and return what it said on stderr."""
        if self.process.poll() is None:
            self.process.terminate()
        try:
            _, errors = self.process.communicate(timeout=5)
        except subprocess.TimeoutExpired:
            self.process.kill()
            _, errors = self.process.communicate()
        return errors or b""


@pytest.fixture
def emulator() -> Iterator[Usb3Emulator]:
    started = Usb3Emulator()
    try:
        started.wait_ready()
        yield started
    finally:
        errors = started.stop()
        assert b"Traceback" not in errors, errors.decode(errors="replace")


@pytest.fixture
def station(qtbot: QtBot, emulator: Usb3Emulator) -> Iterator[Station]:
    """A real-clock station on the usb3 profile, connected over the pty, settings read."""
    built = Station(load_profile("usb3"))
    settings: list[None] = []

    def listen() -> None:
        # Hooked before the link opens: the reply to G; can beat any later hook.
        if built.usb3_session is not None:
            built.usb3_session.settingsChanged.connect(lambda: settings.append(None))

    built.sessionChanged.connect(listen)
    try:
        built.connect_serial(emulator.path, 19200)
        qtbot.waitUntil(lambda: built.model.link_state is LinkState.CONNECTED, timeout=5000)
        qtbot.waitUntil(lambda: len(settings) >= 2, timeout=5000)  # the M…; and T…; of G;
        yield built
    finally:
        built.shutdown()


def session_of(station: Station) -> Usb3Session:
    session = station.usb3_session
    assert session is not None
    return session


def test_move_zero_and_the_units_menu_over_a_real_serial_device(
    qtbot: QtBot, station: Station, emulator: Usb3Emulator
) -> None:
    session, model = session_of(station), station.model
    x = model.axes[X]

    # Move X by 12.5 mm with an M6 thread at 1/8 step: the position the unit reports
    # is exactly the reachable one.
    session.set_thread(X, Thread.M6)
    session.set_step_size(X, StepSize.EIGHTH)
    target = session.reachable(X, 12.5)
    assert target == 12.5  # 80000 counts: whole eighth steps on a 1 mm thread
    assert session.move_relative(X, 12.5)
    qtbot.waitUntil(lambda: x.moving and x.status_text == "moving", timeout=5000)
    qtbot.waitUntil(lambda: x.status_text == "idle", timeout=MOVE_TIMEOUT_MS)
    assert abs(x.position - target) <= 1e-9
    assert (model.axes[1].position, model.axes[2].position) == (0.0, 0.0)

    # Zero all: every axis reports 0 and none is shown moving.
    moved: list[int] = []
    model.axisChanged.connect(lambda axis: moved.extend([axis] if model.axes[axis].moving else []))
    session.zero_all()
    qtbot.waitUntil(
        lambda: all(a.position == 0.0 and a.status_text == "idle" for a in model.axes),
        timeout=5000,
    )
    assert not moved

    # The unit's own menu sets X to 1/32 step: the session and a panel follow.
    panel = Usb3Panel(station)
    qtbot.addWidget(panel)
    assert panel.step_combos[X].currentText() == "1/8"
    emulator.control("menu M5 3 3")
    qtbot.waitUntil(lambda: session.step_sizes[X] is StepSize.THIRTY_SECOND, timeout=5000)
    assert session.step_sizes == [StepSize.THIRTY_SECOND, StepSize.EIGHTH, StepSize.EIGHTH]
    assert session.threads == [Thread.M6] * 3  # the menu line left the threads alone
    assert panel.step_combos[X].currentText() == "1/32"
    assert panel.step_combos[X].currentData() == StepSize.THIRTY_SECOND
    # And a panel built now shows it as well.
    later = Usb3Panel(station)
    qtbot.addWidget(later)
    assert later.step_combos[X].currentText() == "1/32"
