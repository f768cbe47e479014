"""Info panel: link lamp colours, battery gauge, temperature and the power note."""

from __future__ import annotations

import pytest
from PySide6.QtCore import Qt
from pytestqt.qtbot import QtBot

from app.machine import LinkState
from app.profiles import load_profile
from app.settings import StationSettings
from tests.helpers.harness import StationHarness
from widgets.panels.connection import ConnectionPanel
from widgets.panels.info import LINK_COLOURS, InfoPanel


@pytest.fixture
def info(qtbot: QtBot, harness: StationHarness) -> InfoPanel:
    panel = InfoPanel(harness.station.model)
    qtbot.addWidget(panel)
    return panel


def lamp_colour(info: InfoPanel) -> str:
    return next(c for c in LINK_COLOURS.values() if c in info.link_lamp.styleSheet())


def test_link_lamp_follows_the_link_state(harness: StationHarness, info: InfoPanel) -> None:
    assert lamp_colour(info) == LINK_COLOURS[LinkState.DISCONNECTED]
    assert info.link_text.text().startswith("disconnected")
    harness.connect()
    assert lamp_colour(info) == LINK_COLOURS[LinkState.CONNECTED]
    assert info.link_text.text() == "connected — built-in emulator"

    harness.loopback.set_manipulator(lambda _direction, _data: b"")  # the device goes silent
    harness.run_until(lambda: harness.station.model.link_state is LinkState.STALE, timeout=1)
    assert lamp_colour(info) == LINK_COLOURS[LinkState.STALE]
    assert info.link_text.text().startswith("stale")
    harness.run_until(lambda: harness.station.model.link_state is LinkState.LOST, timeout=3)
    assert lamp_colour(info) == LINK_COLOURS[LinkState.LOST]
    assert LINK_COLOURS[LinkState.LOST] != LINK_COLOURS[LinkState.STALE]


def test_the_dro_is_greyed_whenever_it_is_not_live(
    harness: StationHarness, info: InfoPanel
) -> None:
    assert not info.positions[0].isEnabled()  # nothing heard yet
    harness.connect()
    assert all(p.isEnabled() for p in info.positions) and info.positions[0].toolTip() == ""
    harness.loopback.set_manipulator(lambda _direction, _data: b"")  # the device goes silent
    harness.run_until(lambda: harness.station.model.link_state is LinkState.LOST, timeout=5)
    assert not any(p.isEnabled() for p in info.positions + info.statuses)
    assert info.positions[0].toolTip() == "Last known — the link is lost"
    assert "color" not in info.statuses[0].styleSheet()  # no live state colour either


def test_battery_and_temperature(harness: StationHarness, info: InfoPanel) -> None:
    assert info.battery.format() == info.battery_text.text() == "battery —"
    assert not info.battery.isTextVisible()  # the words beside the gauge, never over its edge
    harness.connect()
    harness.emulator.board_temperature_c = 31.25
    harness.run(1.5)
    assert info.battery.value() == 80
    assert info.battery_text.text() == "battery 80 % · 4.02 V"
    assert info.temperature.text() == "board 31.2 °C"


def test_power_note_names_the_charger_and_usb(harness: StationHarness, info: InfoPanel) -> None:
    harness.connect()
    harness.run(1.5)
    assert info.power_note.text() == ""
    harness.emulator.charger_connected = True
    harness.emulator.usb_connected = True
    harness.run(1.5)
    assert "charger connected (800 mA)" in info.power_note.text()
    assert "USB connected" in info.power_note.text()
    assert info.statuses[0].text() == "blocked: charger connected"
    harness.emulator.charger_connected = False
    harness.emulator.usb_connected = False
    harness.run(1.5)
    assert info.power_note.text() == ""


def test_positions_have_three_decimals(harness: StationHarness, info: InfoPanel) -> None:
    harness.connect()
    harness.session.move_absolute(1, 12.3456)
    harness.run_until(lambda: info.statuses[1].text() == "target reached", timeout=5)
    assert info.positions[1].text() == "12.346 mm"


def test_usb3_axes_show_their_state_right_after_connecting(qtbot: QtBot) -> None:
    """The unit reports an axis only when it moves: Connect asks, so none stays "unknown"."""
    usb3 = StationHarness(load_profile("usb3"))
    try:
        info = InfoPanel(usb3.station.model)
        connection = ConnectionPanel(usb3.station, StationSettings(None))
        for widget in (info, connection):
            qtbot.addWidget(widget)
            widget.show()
        assert [s.text() for s in info.statuses] == ["unknown"] * 3
        qtbot.mouseClick(connection.transport_buttons["emulator"], Qt.MouseButton.LeftButton)
        qtbot.mouseClick(connection.connect_button, Qt.MouseButton.LeftButton)
        usb3.run(0.2)
        assert [s.text() for s in info.statuses] == ["idle"] * 3
        assert all(p.isEnabled() for p in info.positions)  # live, not greyed
        assert [p.text() for p in info.positions] == ["0.000 mm"] * 3
        assert usb3.usb3_emulator.positions == (0, 0, 0)  # asking moved nothing
    finally:
        usb3.close()


def test_s3_33_the_led_ring_is_drawn_from_the_device_flags(
    harness: StationHarness, info: InfoPanel
) -> None:
    from protocol.stage.led import LedRing
    from widgets.panels.info import LED_COLOURS

    assert info.led_state() is None and info.led_text.text() == "LED ring: —"
    harness.connect()
    harness.run(1.5)  # the flags are asked at least once a second
    assert info.led_state() is LedRing.TALKING
    assert info.led_text.text() == "LED ring: blue"
    assert LED_COLOURS[LedRing.TALKING] in info.led_lamp.styleSheet()
    assert info.led_text.toolTip() == "Talking to this station"
    harness.emulator.battery_charge = 10.0
    harness.run(1.5)
    assert info.led_state() is LedRing.LOW_BATTERY is harness.emulator.snapshot().led
    assert info.led_text.text() == "LED ring: red, blinking fast"
    harness.emulator.charger_connected = True
    harness.run(1.5)
    assert info.led_state() is LedRing.CHARGING is harness.emulator.snapshot().led
    harness.emulator.charger_connected = False
    harness.emulator.battery_charge = 80.0
    harness.session.set_sleep(True)
    harness.run(1.5)
    assert info.led_state() is LedRing.STANDBY is harness.emulator.snapshot().led
    assert LED_COLOURS[LedRing.STANDBY] in info.led_lamp.styleSheet()
    # Silent stage: the station no longer knows how the ring is lit.
    harness.emulator.kill_switch()
    harness.run_until(lambda: harness.station.model.link_state is LinkState.LOST, timeout=3)
    assert info.led_state() is None and info.led_text.text() == "LED ring: —"


def test_s3_33_machines_without_device_flags_show_no_led_ring(qtbot: QtBot) -> None:
    harness = StationHarness(load_profile("usb3"))
    try:
        panel = InfoPanel(harness.station.model)
        qtbot.addWidget(panel)
        panel.show()
        assert not panel.led_text.isVisible() and not panel.led_lamp.isVisible()
    finally:
        harness.close()
