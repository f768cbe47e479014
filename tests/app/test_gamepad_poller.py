"""The gamepad poller (app/gamepad/poller.py) on a stand-in device, for every dialect that jogs:
a stick pushed with enable held jogs through the same state machine and gate as the keys."""

from __future__ import annotations

import threading
from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.gamepad.mapping import PadReading
from app.gamepad.poller import GamepadJog, PadState
from app.gamepad.source import PadDevice, PadUnavailable
from app.jog_state import JogState
from app.profiles import available_profiles, load_profile
from app.station import Station
from protocol.clock import ManualClock
from tests.helpers.harness import StationHarness

PUSHED_RIGHT = PadReading(x=1.0, enable=True)


class FakePad:
    """A :class:`PadSource` whose one device the test plugs, unplugs and pushes."""

    def __init__(self, name: str = "Test Pad") -> None:
        self.name = name
        self.plugged = True
        self.reading = PadReading()
        self.opened: PadDevice | None = None

    def devices(self) -> list[PadDevice]:
        return [PadDevice(0, self.name)] if self.plugged else []

    def open(self, device: PadDevice) -> bool:
        self.opened = device if self.plugged else None
        return self.opened is not None

    def read(self) -> PadReading | None:
        if not self.plugged or self.opened is None:
            return None
        return self.reading

    def close(self) -> None:
        self.opened = None


def jogging_profiles() -> list[str]:
    return [
        name
        for name in available_profiles()
        if Station(load_profile(name), ManualClock(), realtime=False).dialect.jogs
    ]


@pytest.fixture(params=jogging_profiles())
def machine(request: pytest.FixtureRequest, qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile(request.param))
    harness.connect()
    harness.run(1.0)
    if harness.station.drill_emulator is not None:  # it homes by itself at power-on
        drill = harness.drill_emulator
        harness.run_until(lambda: drill.homed and not drill.busy, 30)
    yield harness
    harness.close()


def pad_on(harness: StationHarness, pad: FakePad) -> tuple[GamepadJog, JogState]:
    jog = JogState(harness.station, {})
    poller = GamepadJog(harness.station, jog, source_factory=lambda: pad, poll_ms=None)
    poller.set_enabled(True)
    assert poller.state is PadState.CONNECTED and poller.device is not None
    return poller, jog


def hold(harness: StationHarness, poller: GamepadJog, seconds: float) -> None:
    """Time passes with the poller looking at the pad as its timer would (every 40 ms)."""
    for _ in range(round(seconds / 0.04)):
        harness.run(0.04)
        poller.poll()


def test_every_jogging_machine_jogs_on_the_stick_and_stops_on_its_release(
    machine: StationHarness,
) -> None:
    pad = FakePad()
    poller, _jog = pad_on(machine, pad)
    session = machine.station.session
    assert session is not None
    ended: list[str] = []
    session.jogEnded.connect(ended.append)
    x = machine.station.model.axes[0]
    start = x.position
    pad.reading = PUSHED_RIGHT
    poller.poll()
    assert session.jog_vector[0] == 1
    hold(machine, poller, 2.0)  # longer than the dead-man: each look is its sign
    assert not ended and session.jog_vector[0] == 1
    assert x.position > start
    pad.reading = PadReading(x=1.0, enable=False)  # the enable button let go: the release
    poller.poll()
    assert session.jog_vector == (0,) * session.axis_count
    machine.run_until(lambda: session.motion_stopped(), timeout=5)
    machine.run(2.0)  # braked, the last report in
    stopped = x.position
    machine.run(1.0)
    assert x.position == pytest.approx(stopped, abs=1e-6)


@pytest.fixture
def grbl(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    harness.connect()
    harness.run(1.0)
    yield harness
    harness.close()


def test_unplugged_mid_jog_stops_at_once_and_says_so(grbl: StationHarness) -> None:
    pad = FakePad("Wireless Pad")
    poller, _jog = pad_on(grbl, pad)
    said: list[str] = []
    grbl.station.model.message.connect(said.append)
    pad.reading = PUSHED_RIGHT
    poller.poll()
    hold(grbl, poller, 0.5)
    before = len(grbl.written)
    pad.plugged = False
    poller.poll()
    session = grbl.gcode_session
    assert session.jog_vector == (0, 0)
    assert b"\x85" in b"".join(grbl.written[before:])  # the jog cancel, on this very look
    assert "Gamepad Wireless Pad unplugged: jog stopped" in said
    assert poller.state is PadState.SEARCHING and poller.device is None
    # Plugged back in with the stick still pushed: nothing until it is let go.
    pad.plugged = True
    poller.poll()
    assert poller.state is PadState.CONNECTED
    hold(grbl, poller, 0.2)
    assert session.jog_vector == (0, 0)
    pad.reading = PadReading(enable=True)
    poller.poll()
    pad.reading = PUSHED_RIGHT
    poller.poll()
    assert session.jog_vector == (1, 0)


def test_a_stalled_poller_is_ended_by_the_dead_man_and_must_be_let_go(
    grbl: StationHarness,
) -> None:
    pad = FakePad()
    poller, _jog = pad_on(grbl, pad)
    session = grbl.gcode_session
    ended: list[str] = []
    session.jogEnded.connect(ended.append)
    pad.reading = PUSHED_RIGHT
    poller.poll()
    grbl.run_until(lambda: bool(ended), timeout=5)  # nobody looks at the pad any more
    assert session.jog_vector == (0, 0)
    hold(grbl, poller, 0.5)  # looking again, the stick still pushed: no new jog
    assert session.jog_vector == (0, 0)
    pad.reading = PadReading()
    poller.poll()
    pad.reading = PUSHED_RIGHT
    poller.poll()
    assert session.jog_vector == (1, 0)


def test_half_a_push_jogs_slower_than_a_full_one(grbl: StationHarness) -> None:
    pad = FakePad()
    poller, _jog = pad_on(grbl, pad)

    def feed_of_first_jog(push: float) -> float:
        before = len(grbl.written)
        pad.reading = PadReading(x=push, enable=True)
        hold(grbl, poller, 0.3)
        lines = [w for w in grbl.written[before:] if w.startswith(b"$J=")]
        pad.reading = PadReading()
        poller.poll()
        grbl.run_until(lambda: grbl.gcode_session.machine_state == "Idle", timeout=5)
        grbl.run(0.5)
        assert lines, "no jog on the wire"
        return float(lines[0].split(b"F")[-1])

    full = feed_of_first_jog(1.0)
    half = feed_of_first_jog(0.6)
    assert 0 < half < full / 2
    assert grbl.gcode_session.jog_speed_share == 1.0  # let go: the keys jog as before


def test_a_locked_jog_refuses_the_pad_once_and_waits_for_it_to_be_let_go(
    grbl: StationHarness,
) -> None:
    pad = FakePad()
    poller, jog = pad_on(grbl, pad)
    said: list[str] = []
    grbl.station.model.message.connect(said.append)
    jog.set_enabled(False, "a job is running")
    before = len(grbl.written)
    pad.reading = PUSHED_RIGHT
    hold(grbl, poller, 0.5)
    assert said.count("Jog refused: a job is running") == 1
    assert not [w for w in grbl.written[before:] if w.startswith(b"$J=")]
    jog.set_enabled(True)
    hold(grbl, poller, 0.2)  # the lock lifted with the stick still pushed: still nothing
    assert grbl.gcode_session.jog_vector == (0, 0)


def test_stop_lets_go_of_the_pad_until_it_is_released(grbl: StationHarness) -> None:
    pad = FakePad()
    poller, jog = pad_on(grbl, pad)
    pad.reading = PUSHED_RIGHT
    poller.poll()
    jog.stop_all()
    hold(grbl, poller, 0.3)
    assert grbl.gcode_session.jog_vector == (0, 0)


def test_an_inactive_window_lets_go(grbl: StationHarness) -> None:
    pad = FakePad()
    active = [True]
    jog = JogState(grbl.station, {})
    poller = GamepadJog(
        grbl.station, jog, source_factory=lambda: pad, active=lambda: active[0], poll_ms=None
    )
    poller.set_enabled(True)
    pad.reading = PUSHED_RIGHT
    poller.poll()
    assert grbl.gcode_session.jog_vector == (1, 0)
    active[0] = False
    poller.poll()
    assert grbl.gcode_session.jog_vector == (0, 0)


def test_a_pad_already_pushed_when_found_does_not_jog(grbl: StationHarness) -> None:
    pad = FakePad()
    pad.reading = PUSHED_RIGHT
    poller, _jog = pad_on(grbl, pad)
    hold(grbl, poller, 0.3)
    assert grbl.gcode_session.jog_vector == (0, 0)


def test_the_device_chosen_is_waited_for_and_another_is_not_read(grbl: StationHarness) -> None:
    pad = FakePad("Other Pad")
    jog = JogState(grbl.station, {})
    poller = GamepadJog(grbl.station, jog, source_factory=lambda: pad, poll_ms=None)
    poller.set_device("My Pad")
    poller.set_enabled(True)
    assert poller.state is PadState.SEARCHING and poller.device_names() == ["Other Pad"]
    pad.name = "My Pad"
    poller.poll()
    assert poller.state is PadState.CONNECTED and poller.device == PadDevice(0, "My Pad")
    poller.set_enabled(False)
    assert poller.state is PadState.OFF and pad.opened is None


def test_without_the_library_the_pad_says_it_is_unavailable(grbl: StationHarness) -> None:
    def missing() -> FakePad:
        raise PadUnavailable("pysdl2 is not installed")

    jog = JogState(grbl.station, {})
    poller = GamepadJog(grbl.station, jog, source_factory=missing, poll_ms=None)
    poller.set_enabled(True)
    assert poller.state is PadState.UNAVAILABLE
    assert poller.unavailable == "pysdl2 is not installed"
    poller.poll()  # nothing to look at, nothing breaks
    assert poller.device_names() == []


def test_the_library_is_imported_off_the_gui_thread_then_the_pad_is_read(
    grbl: StationHarness, qtbot: QtBot
) -> None:
    pad = FakePad()
    imported_on: list[str] = []
    gate = threading.Event()

    def slow_import() -> None:
        imported_on.append(threading.current_thread().name)
        gate.wait(5)

    jog = JogState(grbl.station, {})
    poller = GamepadJog(
        grbl.station, jog, source_factory=lambda: pad, preload=slow_import, poll_ms=None
    )
    poller.set_enabled(True)
    assert poller.state is PadState.LOADING  # returned at once: the import is elsewhere
    poller.poll()  # nothing to read yet, nothing breaks
    gate.set()
    qtbot.waitUntil(lambda: poller.state is PadState.CONNECTED)
    assert imported_on and imported_on[0] != threading.main_thread().name
    pad.reading = PUSHED_RIGHT
    poller.set_enabled(False)
    poller.set_enabled(True)  # loaded now: at once
    assert poller.state is PadState.CONNECTED


def test_turned_off_while_loading_stays_off(grbl: StationHarness, qtbot: QtBot) -> None:
    loaded = threading.Event()
    jog = JogState(grbl.station, {})
    poller = GamepadJog(grbl.station, jog, source_factory=FakePad, preload=loaded.set, poll_ms=None)
    changed: list[PadState] = []
    poller.stateChanged.connect(lambda: changed.append(poller.state))
    poller.set_enabled(True)
    poller.set_enabled(False)
    qtbot.waitUntil(lambda: len(changed) >= 3)  # loading, off, then the import's end
    assert loaded.is_set() and poller.state is PadState.OFF
    assert poller.device_names() == ["Test Pad"]  # the dialog can list devices now
