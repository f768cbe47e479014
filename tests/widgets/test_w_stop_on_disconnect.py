"""Disconnect and closing the window stop every axis first (issue 15, symptoms 8 and 9).

Driven as the operator drives it — a click on Disconnect, closing the window —
against the emulators on a manual clock; asserting the stop on the wire, that
the link closes only once the device confirms it (within the bounded wait),
and that the emulated axis then stands instead of running on with nobody
left to stop it.
"""

from __future__ import annotations

from collections.abc import Iterator
from pathlib import Path

import pytest
from PySide6.QtCore import QSettings, Qt
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.profiles import load_profile
from app.settings import StationSettings
from app.station import STOP_CONFIRM_S, Station
from protocol.stage.codec import CommandFrame, CommandId, decode
from tests.helpers.harness import StationHarness
from widgets.main_window import MainWindow
from widgets.panels.connection import ConnectionPanel

LEFT = Qt.MouseButton.LeftButton
TARGET_UM = 50_000


def stop_frames(harness: StationHarness, since: int) -> list[CommandFrame]:
    frames = []
    for raw in harness.written[since:]:
        _, frame = decode(raw)
        assert isinstance(frame, CommandFrame)
        if all(p.command == CommandId.STOP for p in frame.packets):
            frames.append(frame)
    return frames


def start_long_move(harness: StationHarness) -> None:
    harness.connect()
    harness.run(1.0)
    assert harness.session.move_absolute(0, TARGET_UM / 1000)
    harness.run_until(lambda: harness.station.model.axes[0].moving, timeout=1)
    harness.run(0.5)
    assert harness.emulator.axes[0].moving


@pytest.fixture
def panel(qtbot: QtBot, harness: StationHarness, tmp_path: Path) -> ConnectionPanel:
    store = QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)
    built = ConnectionPanel(harness.station, StationSettings(store))
    qtbot.addWidget(built)
    built.show()
    return built


def test_disconnect_during_an_absolute_move_stops_the_axis_before_closing(
    qtbot: QtBot, harness: StationHarness, panel: ConnectionPanel
) -> None:
    """Symptom 8: an absolute move ran on for 4.5 s after Disconnect."""
    start_long_move(harness)
    emulator = harness.emulator
    messages: list[str] = []
    harness.station.model.message.connect(messages.append)
    mark = len(harness.written)

    qtbot.mouseClick(panel.disconnect_button, LEFT)
    assert len(stop_frames(harness, mark)) == 1  # the stop went out at once, every axis
    assert harness.station.stopping_to_close and harness.station.link is not None

    waited = harness.run_until(lambda: harness.station.link is None, timeout=2 * STOP_CONFIRM_S)
    assert waited <= STOP_CONFIRM_S
    assert messages[-1] == "Every axis stopped; link closed"  # confirmed, not timed out
    assert harness.station.model.link_state is LinkState.DISCONNECTED
    assert not emulator.axes[0].moving
    stood_at = emulator.axes[0].position_um
    emulator.run_until(harness.clock.now() + 6.0)  # the device alone, nobody connected
    assert emulator.axes[0].position_um == stood_at < TARGET_UM / 2


def test_disconnect_with_nothing_moving_closes_at_once(
    qtbot: QtBot, harness: StationHarness, panel: ConnectionPanel
) -> None:
    harness.connect()
    harness.run(1.0)
    qtbot.mouseClick(panel.disconnect_button, LEFT)
    assert harness.station.link is None
    assert harness.station.model.link_state is LinkState.DISCONNECTED


def test_a_stop_the_device_never_confirms_closes_after_the_bounded_wait(
    qtbot: QtBot, harness: StationHarness, panel: ConnectionPanel
) -> None:
    start_long_move(harness)
    messages: list[str] = []
    harness.station.model.message.connect(messages.append)
    harness.loopback.set_manipulator(lambda _direction, _data: b"")  # the cable goes deaf
    qtbot.mouseClick(panel.disconnect_button, LEFT)
    waited = harness.run_until(lambda: harness.station.link is None, timeout=2 * STOP_CONFIRM_S)
    assert STOP_CONFIRM_S <= waited <= STOP_CONFIRM_S + 0.01
    assert "did not confirm the stop within 1 s" in messages[-1]


def test_closing_the_window_during_a_move_stops_it_then_closes(
    qtbot: QtBot, harness: StationHarness
) -> None:
    window = MainWindow(harness.station)
    qtbot.addWidget(window)
    window.show()
    start_long_move(harness)
    emulator = harness.emulator
    mark = len(harness.written)

    window.close()
    assert window.isVisible()  # waiting for the machine, not blocking the event loop
    assert len(stop_frames(harness, mark)) == 1
    harness.run_until(lambda: not window.isVisible(), timeout=2 * STOP_CONFIRM_S)
    assert harness.station.link is None
    assert not emulator.axes[0].moving
    stood_at = emulator.axes[0].position_um
    emulator.run_until(harness.clock.now() + 6.0)
    assert emulator.axes[0].position_um == stood_at < TARGET_UM / 2


@pytest.fixture
def plotter(qtbot: QtBot) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("grbl-plotter"))
    yield harness
    harness.close()


def test_disconnect_on_a_gcode_machine_holds_resets_and_then_closes(
    qtbot: QtBot, plotter: StationHarness
) -> None:
    plotter.connect()
    plotter.run(0.5)
    session = plotter.gcode_session
    assert session.send_line("G1 X200 F600", "console")
    plotter.run_until(lambda: plotter.gcode_emulator.state == "Run", timeout=2)
    plotter.run(0.5)
    moving_at = plotter.gcode_emulator.position()["X"]
    mark = len(plotter.written)
    messages: list[str] = []
    plotter.station.model.message.connect(messages.append)

    assert plotter.station.stop_and_close() is False  # waits for the hold to complete
    assert plotter.written[mark] == b"!"
    plotter.run_until(lambda: plotter.station.link is None, timeout=2 * STOP_CONFIRM_S)
    assert messages[-1] == "Every axis stopped; link closed"
    assert b"\x18" in plotter.written[mark:]  # the reset went out once the machine stood
    emulator = plotter.gcode_emulator
    stood_at = emulator.position()["X"]
    emulator.run_until(plotter.clock.now() + 10.0)
    assert emulator.position()["X"] == pytest.approx(stood_at)
    assert stood_at < moving_at + 10 < 200


def test_in_real_time_the_wait_runs_on_the_event_loop(qtbot: QtBot) -> None:
    """The station's own timer, not a test clock, ends the wait; the GUI thread never sleeps."""
    station = Station(load_profile("xy-stage"))  # real clock, emulator on its ticker thread
    try:
        station.connect_emulator()
        session = station.session
        assert session is not None
        qtbot.waitUntil(lambda: session.device_answered, timeout=5000)
        assert session.move_absolute(0, 50.0)
        qtbot.waitUntil(lambda: station.model.axes[0].moving, timeout=5000)
        emulator = station.stage_emulator
        assert emulator is not None
        with qtbot.waitSignal(station.linkClosed, timeout=5000):
            assert station.stop_and_close() is False
        assert not emulator.axes[0].moving
        assert emulator.axes[0].position_um < 50_000
    finally:
        station.shutdown()
