"""End to end over a real serial device: the station, the serial transport, the emulator process.

The emulator runs as its own process on a pseudo-terminal behind a fixed
``--link`` path, in real time, exactly as the operator would run it; the
station talks to it through ``connect_serial``.  Nothing is faked, so every
wait is bounded by a timeout and polls the model — no fixed sleeps.
"""

from __future__ import annotations

import selectors
import signal
import subprocess
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState, ParameterState
from app.profiles import load_profile
from app.station import Station
from protocol.stage.codec import PARAMETERS, EchoType

ROOT = Path(__file__).resolve().parents[2]
STARTUP_TIMEOUT = 15.0
AXES = (0, 1)
EVERY_PARAMETER = {(axis, int(parameter)) for axis in AXES for parameter in PARAMETERS}
DEFAULT_FAST_SPEED = 10000  # µm/s, table 1.4


class EmulatorProcesses:
    """The emulator on one ``--link`` path, started, killed and restarted by a test."""

    def __init__(self, link: Path) -> None:
        self.link = link
        self._started: list[subprocess.Popen[bytes]] = []

    def start(self) -> str:
        """Start an emulator and return its device path once it has printed it (it is ready)."""
        command = [
            sys.executable,
            "-m",
            "protocol.emulator",
            "--profile",
            "xy-stage",
            "--pty",
            "--link",
            str(self.link),
        ]
        process = subprocess.Popen(
            command, cwd=ROOT, stdout=subprocess.PIPE, stderr=subprocess.PIPE
        )
        self._started.append(process)
        assert process.stdout is not None
        with selectors.DefaultSelector() as selector:
            selector.register(process.stdout, selectors.EVENT_READ)
            assert selector.select(STARTUP_TIMEOUT), "the emulator printed no device path"
        return process.stdout.readline().decode().strip()

    def kill(self) -> None:
        """SIGKILL the running emulator: no clean-up, as when a cable is yanked."""
        process = self._started[-1]
        process.send_signal(signal.SIGKILL)
        process.wait(timeout=5)

    def stop_all(self) -> None:
        for process in self._started:
            if process.poll() is None:
                process.terminate()
            try:
                process.wait(timeout=5)
            except subprocess.TimeoutExpired:
                process.kill()
                process.wait()
            for pipe in (process.stdout, process.stderr):
                if pipe is not None:
                    pipe.close()


@pytest.fixture
def emulators(tmp_path: Path) -> Iterator[EmulatorProcesses]:
    processes = EmulatorProcesses(tmp_path / "stage")
    yield processes
    processes.stop_all()


@pytest.fixture
def station(qtbot: QtBot) -> Iterator[Station]:
    built = Station(load_profile("xy-stage"))
    yield built
    built.shutdown()


def echo_counter(station: Station) -> list[int]:
    """A one-element list counting the echoes the session decodes from now on."""
    count = [0]
    assert station.session is not None
    station.session.frameReceived.connect(lambda *_: count.__setitem__(0, count[0] + 1))
    return count


def read_since(station: Station) -> set[tuple[int, int]]:
    """Every (axis, parameter) the model records as READ from now on."""
    seen: set[tuple[int, int]] = set()

    def record(axis: int, parameter: int) -> None:
        if station.model.parameter(axis, parameter).state is ParameterState.READ:
            seen.add((axis, parameter))

    station.model.parameterChanged.connect(record)
    return seen


def connect(qtbot: QtBot, station: Station, emulators: EmulatorProcesses) -> None:
    """Connect over the link and wait until the session has read every parameter."""
    emulators.start()
    read = read_since(station)
    station.connect_serial(str(emulators.link), 115200)
    qtbot.waitUntil(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5000)
    qtbot.waitUntil(lambda: read >= EVERY_PARAMETER, timeout=10_000)
    assert station.model.parameter(0, EchoType.FAST_SPEED).value == DEFAULT_FAST_SPEED


def test_jog_release_and_absolute_move_over_the_serial_link(
    qtbot: QtBot, station: Station, emulators: EmulatorProcesses
) -> None:
    connect(qtbot, station, emulators)
    session, x = station.session, station.model.axes[0]
    assert session is not None
    start = x.position

    session.set_jog([1, 0])  # → held
    qtbot.waitUntil(lambda: x.position > start + 0.5, timeout=5000)
    assert x.moving

    session.set_jog([0, 0])  # → released
    qtbot.waitUntil(lambda: not x.moving, timeout=5000)
    stopped_at = x.position
    echoes = echo_counter(station)
    qtbot.waitUntil(lambda: echoes[0] >= 5, timeout=5000)
    assert x.position == stopped_at

    target = round(stopped_at) + 2.5
    assert session.move_absolute(0, target)
    qtbot.waitUntil(lambda: x.status_text == "target reached", timeout=10_000)
    assert x.position == pytest.approx(target, abs=0.001)


def test_a_killed_emulator_is_lost_and_a_restarted_one_reconnected_and_re_read(
    qtbot: QtBot, station: Station, emulators: EmulatorProcesses
) -> None:
    connect(qtbot, station, emulators)
    session, model = station.session, station.model
    assert session is not None
    # Something only the old device holds: seeing the default again proves a fresh read.
    session.write_parameter(0, EchoType.FAST_SPEED, 12345)
    fast = model.parameter(0, EchoType.FAST_SPEED)
    qtbot.waitUntil(lambda: fast.state is ParameterState.CONFIRMED, timeout=5000)
    session.set_jog([1, 0])
    qtbot.waitUntil(lambda: model.axes[0].moving, timeout=5000)

    emulators.kill()
    qtbot.waitUntil(lambda: model.link_state is LinkState.LOST, timeout=2000)
    assert "disappeared" in model.link_detail

    read = read_since(station)
    emulators.start()
    qtbot.waitUntil(lambda: model.link_state is LinkState.CONNECTED, timeout=5000)
    qtbot.waitUntil(lambda: read >= EVERY_PARAMETER, timeout=10_000)
    assert model.parameter(0, EchoType.FAST_SPEED).value == DEFAULT_FAST_SPEED
    assert session is station.session  # the same session, reconnected underneath
    assert not model.axes[0].moving  # the jog held before the loss was not resumed


def test_a_port_that_does_not_exist_is_explained_and_leaves_no_thread(
    qtbot: QtBot, station: Station, tmp_path: Path
) -> None:
    station.reconnect_delays = (60.0,)  # one attempt is enough to look at
    messages: list[str] = []
    station.model.message.connect(messages.append)
    missing = str(tmp_path / "ttyUSB7")

    station.connect_serial(missing, 115200)

    expected = f"{missing} not found — is it plugged in?"
    qtbot.waitUntil(lambda: expected in station.model.link_detail, timeout=5000)
    assert station.model.link_state is LinkState.LOST
    assert any(expected in message for message in messages)
    assert "Traceback" not in station.model.link_detail
    qtbot.waitUntil(lambda: not _serial_threads(), timeout=5000)
    station.shutdown()
    assert station.model.link_state is LinkState.DISCONNECTED


def _serial_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name.startswith("serial-")]
