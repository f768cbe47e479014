"""The connection panel: choosing a link, remembering it, scanning, and what it reports."""

from __future__ import annotations

import threading
from collections.abc import Callable
from pathlib import Path
from typing import Any

import pytest
from PySide6.QtCore import QSettings, Qt
from pytestqt.qtbot import QtBot

import app.discovery
import widgets.panels.connection as panel_module
from app.discovery import BleDevice, PortInfo
from app.machine import LinkState
from app.settings import StationSettings
from tests.helpers.harness import StationHarness
from widgets.panels.connection import ConnectionPanel

LEFT = Qt.MouseButton.LeftButton
PORTS = [
    PortInfo("/dev/ttyACM0", "XY stage (CDC)", "USB VID:PID=0483:5740"),
    PortInfo("/dev/ttyUSB0", "FT232R USB UART", "USB VID:PID=0403:6001"),
]


@pytest.fixture
def store(tmp_path: Path) -> QSettings:
    return QSettings(str(tmp_path / "stepdeck.ini"), QSettings.Format.IniFormat)


@pytest.fixture
def make_panel(
    qtbot: QtBot, harness: StationHarness, store: QSettings, monkeypatch: pytest.MonkeyPatch
) -> Callable[[], ConnectionPanel]:
    monkeypatch.setattr(panel_module, "serial_ports", lambda: list(PORTS))

    def make() -> ConnectionPanel:
        panel = ConnectionPanel(harness.station, StationSettings(store))
        qtbot.addWidget(panel)
        panel.show()
        return panel

    return make


def test_ports_are_listed_with_their_description(make_panel: Callable[[], ConnectionPanel]) -> None:
    panel = make_panel()
    texts = [panel.port_combo.itemText(i) for i in range(panel.port_combo.count())]
    assert texts == ["/dev/ttyACM0 — XY stage (CDC)", "/dev/ttyUSB0 — FT232R USB UART"]


def test_serial_choice_connects_and_is_remembered(
    qtbot: QtBot,
    make_panel: Callable[[], ConnectionPanel],
    harness: StationHarness,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    calls: list[tuple[str, int | None]] = []
    monkeypatch.setattr(
        harness.station, "connect_serial", lambda port, baud=None: calls.append((port, baud))
    )
    panel = make_panel()
    qtbot.mouseClick(panel.transport_buttons["serial"], LEFT)
    assert panel.serial_box.isVisible() and not panel.ble_box.isVisible()
    panel.port_combo.setCurrentIndex(1)
    panel.baud_combo.setCurrentIndex(panel.baud_combo.findData(19200))
    qtbot.mouseClick(panel.connect_button, LEFT)
    assert calls == [("/dev/ttyUSB0", 19200)]

    again = make_panel()  # the next start offers the same choice
    assert again.transport == "serial"
    assert again.selected_port() == "/dev/ttyUSB0"
    assert again.baud_combo.currentData() == 19200


def test_a_typed_port_that_is_not_listed_is_used_as_typed(
    qtbot: QtBot,
    make_panel: Callable[[], ConnectionPanel],
    harness: StationHarness,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    calls: list[str] = []
    monkeypatch.setattr(
        harness.station, "connect_serial", lambda port, baud=None: calls.append(port)
    )
    panel = make_panel()
    panel.select_transport("serial")
    panel.port_combo.setEditText("/tmp/stage-link")
    qtbot.mouseClick(panel.connect_button, LEFT)
    assert calls == ["/tmp/stage-link"]


def test_emulator_choice_connects_the_built_in_stage(
    qtbot: QtBot, make_panel: Callable[[], ConnectionPanel], harness: StationHarness
) -> None:
    panel = make_panel()
    panel.select_transport("emulator")
    qtbot.mouseClick(panel.connect_button, LEFT)
    # Open, then connected once the emulated stage has answered (its first echo).
    harness.run_until(lambda: harness.station.model.link_state is LinkState.CONNECTED)
    assert panel.state_label.text().startswith("connected")
    qtbot.mouseClick(panel.disconnect_button, LEFT)
    assert harness.station.model.link_state is LinkState.DISCONNECTED
    assert not panel.disconnect_button.isEnabled()


def test_scan_results_list_name_address_and_signal_with_the_last_device_chosen(
    qtbot: QtBot,
    make_panel: Callable[[], ConnectionPanel],
    store: QSettings,
    harness: StationHarness,
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    StationSettings(store).machine(harness.station.profile.name).device = "C0:FF:EE:00:00:02"
    found = [
        BleDevice("XY-STAGE-1", "C0:FF:EE:00:00:01", -48),
        BleDevice("XY-STAGE-2", "C0:FF:EE:00:00:02", -71),
    ]

    def fake_scan(_loop: object, *, on_done: Callable[[Any], None], **_kw: object) -> None:
        # The real scan answers from the BLE thread; so does this one.
        worker = threading.Thread(target=on_done, args=(found,))
        worker.start()
        worker.join()

    monkeypatch.setattr(app.discovery, "scan", fake_scan)
    calls: list[str | None] = []
    monkeypatch.setattr(harness.station, "connect_ble", calls.append)
    panel = make_panel()
    panel.select_transport("ble")
    qtbot.mouseClick(panel.scan_button, LEFT)
    qtbot.waitUntil(lambda: panel.ble_list.count() == 2, timeout=2000)
    assert panel.ble_list.item(0).text().split() == [
        "XY-STAGE-1",
        "C0:FF:EE:00:00:01",
        "-48",
        "dBm",
    ]
    assert panel.selected_ble_address() == "C0:FF:EE:00:00:02"  # the last used one
    qtbot.mouseClick(panel.connect_button, LEFT)
    assert calls == ["C0:FF:EE:00:00:02"]


def test_no_bluetooth_adapter_is_said_in_the_panel(
    qtbot: QtBot,
    make_panel: Callable[[], ConnectionPanel],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    message = "No Bluetooth adapter found"

    def failing_scan(_loop: object, *, on_done: Callable[[Any], None], **_kw: object) -> None:
        on_done(message)

    monkeypatch.setattr(app.discovery, "scan", failing_scan)
    panel = make_panel()
    panel.select_transport("ble")
    qtbot.mouseClick(panel.scan_button, LEFT)
    qtbot.waitUntil(lambda: panel.ble_note.text() == message, timeout=2000)
    assert panel.scan_button.isEnabled()


def test_choosing_another_machine_asks_for_it(
    make_panel: Callable[[], ConnectionPanel], qtbot: QtBot
) -> None:
    panel = make_panel()
    assert panel.profile_combo.currentData() == "xy-stage"
    requested: list[str] = []
    panel.profileRequested.connect(requested.append)
    panel.profile_combo.activated.emit(panel.profile_combo.currentIndex())
    assert requested == []  # the same machine is no switch
