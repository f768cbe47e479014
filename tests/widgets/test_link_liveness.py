"""A silent link on every dialect: amber ("no reply for N s") first, red after, green when back.

Silence is made on the emulator's link with the loopback manipulator, as a
pulled RS232 cable would: the port stays open and the bytes are dropped.
The lamp and the status bar are the window's own, read after each step.
"""

from __future__ import annotations

from collections.abc import Iterator

import pytest
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.profiles import load_profile
from protocol.transport.loopback import Direction
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.info import LINK_COLOURS

PROFILES = ("xy-stage", "usb3", "pcb-drill", "grbl-plotter", "corexy-plotter", "string-art")


@pytest.fixture(params=PROFILES)
def unit(request: pytest.FixtureRequest) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile(request.param))
    harness.connect()
    yield harness
    harness.close()


@pytest.fixture
def window(qtbot: QtBot, unit: StationHarness) -> MainWindow:
    shown = MainWindow(unit.station)
    qtbot.addWidget(shown)
    return shown


class Seen:
    """Every link state the window showed, with its lamp colour and status bar text."""

    def __init__(self, window: MainWindow) -> None:
        self.window = window
        self.states: list[tuple[LinkState, str, str, str]] = []
        # Connected after the window's own slots, so it reads what they just showed.
        window.model.linkStateChanged.connect(self._record)

    def _record(self, state: LinkState) -> None:
        lamp = self.window.info_panel.link_lamp.styleSheet()
        colour = next(c for c in LINK_COLOURS.values() if c in lamp)
        self.states.append(
            (state, self.window.model.link_detail, colour, self.window.link_status.text())
        )

    def kinds(self) -> list[LinkState]:
        kinds: list[LinkState] = []
        for state, *_ in self.states:
            if not kinds or kinds[-1] is not state:
                kinds.append(state)
        return kinds

    def first(self, state: LinkState) -> tuple[LinkState, str, str, str]:
        return next(entry for entry in self.states if entry[0] is state)


def _drop(*directions: Direction) -> object:
    def manipulate(direction: Direction, data: bytes) -> bytes:
        return b"" if direction in directions else data

    return manipulate


def _busy_drill(unit: StationHarness, mm: float) -> None:
    """The drill is asked nothing while idle: its liveness is timed on a command in flight."""
    if unit.station.drill_session is not None:
        # Not while it homes by itself after power-on (FIDELITY S2-19): the D would wait.
        unit.run_until(lambda: not unit.drill_emulator.busy, timeout=10)
        assert unit.drill_session.move_absolute(0, mm)


def test_a_silent_link_shows_amber_then_red_and_green_again_when_it_answers(
    unit: StationHarness, window: MainWindow
) -> None:
    station = unit.station
    seen = Seen(window)
    _busy_drill(unit, 60.0)  # a move of seconds
    unit.loopback.set_manipulator(_drop(Direction.TO_DEVICE, Direction.TO_HOST))  # type: ignore[arg-type]
    unit.run_until(lambda: station.model.link_state is LinkState.LOST, timeout=15)

    kinds = seen.kinds()
    assert kinds[:2] == [LinkState.STALE, LinkState.LOST]
    _, detail, colour, status = seen.first(LinkState.STALE)
    assert detail.startswith("no reply for ")
    assert colour == LINK_COLOURS[LinkState.STALE]
    assert status.startswith("Link stale — no reply for ")
    _, _, colour, status = seen.first(LinkState.LOST)
    assert colour == LINK_COLOURS[LinkState.LOST]
    assert status.startswith("Link lost")
    assert station.model.motion_lock_reason() == "link lost"

    # The cable is back: the device, asked on every second with the port open, answers.
    unit.loopback.set_manipulator(None)
    unit.run_until(lambda: station.model.link_state is LinkState.CONNECTED, timeout=15)
    assert window.info_panel.link_text.text().startswith("connected")
    assert LINK_COLOURS[LinkState.CONNECTED] in window.info_panel.link_lamp.styleSheet()
    assert station.model.motion_lock_reason() is None


def test_replies_back_before_the_link_is_lost_turn_it_green_without_reopening(
    unit: StationHarness, window: MainWindow
) -> None:
    station = unit.station
    link = station.link
    assert link is not None
    reopened: list[object] = []
    link.disconnected.connect(reopened.append)
    seen = Seen(window)
    # The drill takes its command but its R is lost: late (amber) at half a second, and
    # the move's D, after some 0.8 s, is the reply that comes back.
    _busy_drill(unit, 31.0)
    unit.loopback.set_manipulator(_drop(Direction.TO_HOST))  # type: ignore[arg-type]
    unit.run_until(lambda: station.model.link_state is LinkState.STALE, timeout=5)
    unit.loopback.set_manipulator(None)
    unit.run_until(lambda: station.model.link_state is LinkState.CONNECTED, timeout=5)

    assert seen.kinds() == [LinkState.STALE, LinkState.CONNECTED]
    assert reopened == [] and station.link is link  # nobody closed or reopened anything
    _, _, colour, _ = seen.states[-1]
    assert colour == LINK_COLOURS[LinkState.CONNECTED]
    assert window.link_status.text().startswith("Link connected")


def test_a_device_that_answers_is_never_shown_stale(unit: StationHarness) -> None:
    """Idle and at work, a device that answers keeps the lamp green, the drill's slow
    procedures included (the D is late only a second past the procedure's expected time)."""
    states: list[LinkState] = []
    unit.station.model.linkStateChanged.connect(states.append)
    unit.run(5.0)
    session = unit.station.session
    assert session is not None
    if unit.station.drill_session is not None:
        assert unit.drill_session.home(0)
        assert unit.drill_session.move_absolute(1, 40.0)
        assert unit.drill_session.drill()
        unit.run_until(lambda: not unit.drill_session.busy, timeout=120)
    else:
        session.move_relative(0, 2.0)
        unit.run(5.0)
    unit.run(3.0)
    assert states == []
    assert unit.station.model.link_state is LinkState.CONNECTED


def test_a_drill_procedure_whose_end_is_late_is_amber_before_it_is_red() -> None:
    """After the R, the D is due at the procedure's expected end: late a second after it
    (amber), given up at twice the expected time plus 3 s (red)."""
    from app.machines.drill.session import DONE_FACTOR, DONE_LATE_S, DONE_MARGIN_S

    unit = StationHarness(load_profile("pcb-drill"))
    try:
        unit.connect()
        session = unit.drill_session
        model = unit.station.model
        assert session.move_absolute(0, 60.0)
        command = session.in_flight
        assert command is not None
        takes = session.expected_s(command)
        received: list[str] = []
        session.commandReceived.connect(received.append)  # nothing that holds the harness
        unit.run_until(lambda: bool(received), timeout=1)
        received_at = unit.clock.now()  # within one harness step of the R
        unit.loopback.set_manipulator(_drop(Direction.TO_HOST))  # type: ignore[arg-type]
        stale_at = received_at + takes + DONE_LATE_S
        unit.run_until(lambda: unit.clock.now() >= stale_at - 0.05)
        assert model.link_state is LinkState.CONNECTED  # on time so far
        unit.run_until(lambda: model.link_state is not LinkState.CONNECTED, timeout=1)
        assert model.link_state is LinkState.STALE
        assert model.link_detail.startswith("no reply for ")
        assert "the end of its procedure" in model.link_detail
        lost_at = received_at + DONE_FACTOR * takes + DONE_MARGIN_S
        unit.run_until(lambda: model.link_state is LinkState.LOST, timeout=2 * takes + 5)
        assert unit.clock.now() == pytest.approx(lost_at, abs=0.15)
    finally:
        unit.close()
