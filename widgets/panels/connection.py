"""Connection panel: which machine, over which link, and the link's state.

It remembers the last choice (transport, port, baud, BLE address) so the
next start offers the same device first, and it never blocks: listing ports
is instant, and a BLE scan reports back through a signal.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, Qt, Signal
from PySide6.QtWidgets import (
    QButtonGroup,
    QComboBox,
    QFormLayout,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QRadioButton,
    QVBoxLayout,
    QWidget,
)

from app.discovery import BAUD_RATES, BleScan, serial_ports
from app.machine import LinkState
from app.profiles import available_profiles
from app.settings import StationSettings
from app.station import Station
from widgets.link_text import link_detail_text, link_state_text
from widgets.retranslate import Texts

if TYPE_CHECKING:
    from app.discovery import BleDevice

TRANSPORTS = (
    ("emulator", QT_TRANSLATE_NOOP("ConnectionPanel", "Built-in emulator")),
    ("serial", QT_TRANSLATE_NOOP("ConnectionPanel", "Serial port")),
    ("ble", QT_TRANSLATE_NOOP("ConnectionPanel", "Bluetooth LE")),
)


class ConnectionPanel(QWidget):
    profileRequested = Signal(str)

    def __init__(
        self, station: Station, settings: StationSettings, parent: QWidget | None = None
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._settings = settings
        #: The link is remembered per machine: the drill's port is not the stage's.
        self._machine = settings.machine(station.profile.name)
        self._scan: BleScan | None = None
        self._scan_note: tuple[str, int] | None = None
        t = self.texts = Texts(self)

        self.profile_combo = QComboBox()
        for name in available_profiles():
            self.profile_combo.addItem(name, name)
        self.profile_combo.setCurrentIndex(self.profile_combo.findData(station.profile.name))
        t.set(
            self.profile_combo.setToolTip,
            lambda: self.tr("Switching machine closes this link and opens the new one"),
        )
        self.profile_combo.activated.connect(self._profile_chosen)
        self.transport_buttons: dict[str, QRadioButton] = {}
        self._transport_group = QButtonGroup(self)
        transport_row = QHBoxLayout()
        for key, title in TRANSPORTS:
            button = QRadioButton()
            t.set(
                button.setText,
                lambda title=title: QCoreApplication.translate("ConnectionPanel", title),
            )
            self.transport_buttons[key] = button
            self._transport_group.addButton(button)
            transport_row.addWidget(button)
            button.toggled.connect(self._show_transport)
        transport_row.addStretch(1)

        self.port_combo = QComboBox()
        self.port_combo.setEditable(True)  # a port that is not plugged in yet can be typed
        self.port_combo.setMinimumWidth(280)
        self.refresh_button = t.button(lambda: self.tr("Refresh"))
        self.refresh_button.clicked.connect(self.refresh_ports)
        self.baud_combo = QComboBox()
        for baud in BAUD_RATES:
            self.baud_combo.addItem(str(baud), baud)
        port_row = QHBoxLayout()
        port_row.addWidget(self.port_combo, 1)
        port_row.addWidget(self.refresh_button)
        self.serial_box = t.group(lambda: self.tr("Serial"))
        serial_form = QFormLayout(self.serial_box)
        serial_form.addRow(t.label(lambda: self.tr("Port")), port_row)
        serial_form.addRow(t.label(lambda: self.tr("Baud rate")), self.baud_combo)

        self.scan_button = t.button(lambda: self.tr("Scan"))
        self.scan_button.clicked.connect(self.start_scan)
        self.ble_list = QListWidget()
        self.ble_list.setMinimumHeight(90)
        self.ble_note = QLabel("")
        self.ble_note.setWordWrap(True)
        self.ble_box = t.group(lambda: self.tr("Bluetooth LE"))
        ble_layout = QVBoxLayout(self.ble_box)
        scan_row = QHBoxLayout()
        scan_row.addWidget(self.scan_button)
        scan_row.addWidget(self.ble_note, 1)
        ble_layout.addLayout(scan_row)
        ble_layout.addWidget(self.ble_list)

        self.connect_button = t.button(lambda: self.tr("Connect"))
        self.connect_button.clicked.connect(self.connect_selected)
        self.disconnect_button = t.button(
            lambda: self.tr("Disconnect"),
            lambda: self.tr(
                "Stop every axis, wait briefly for the machine to confirm, then close the link"
            ),
        )
        self.disconnect_button.clicked.connect(self._station.stop_and_close)
        buttons = QHBoxLayout()
        buttons.addWidget(self.connect_button)
        buttons.addWidget(self.disconnect_button)
        buttons.addStretch(1)
        self.state_label = QLabel()
        self.state_label.setWordWrap(True)
        self.state_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)

        layout = QVBoxLayout(self)
        form = QFormLayout()
        form.addRow(t.label(lambda: self.tr("Machine")), self.profile_combo)
        form.addRow(t.label(lambda: self.tr("Link")), transport_row)
        layout.addLayout(form)
        layout.addWidget(self.serial_box)
        layout.addWidget(self.ble_box)
        layout.addLayout(buttons)
        layout.addWidget(self.state_label)
        layout.addStretch(1)

        station.model.linkStateChanged.connect(self._show_state)
        self._restore()
        self._show_state()
        t.also(self._show_state)
        t.also(self._show_scan_note)

    # --- choices -------------------------------------------------------------

    def _profile_chosen(self, _index: int) -> None:
        name = str(self.profile_combo.currentData())
        if name != self._station.profile.name:
            self.profileRequested.emit(name)

    @property
    def transport(self) -> str:
        for key, button in self.transport_buttons.items():
            if button.isChecked():
                return key
        return "emulator"

    def select_transport(self, key: str) -> None:
        self.transport_buttons.get(key, self.transport_buttons["emulator"]).setChecked(True)

    def refresh_ports(self) -> None:
        current = self.port_combo.currentText()
        self.port_combo.clear()
        for port in serial_ports():
            self.port_combo.addItem(f"{port.device} — {port.description}", port.device)
        self._select_port(current or self._machine.device)

    def _select_port(self, device: str) -> None:
        index = self.port_combo.findData(device)
        if index >= 0:
            self.port_combo.setCurrentIndex(index)
        elif device:
            self.port_combo.setEditText(device)

    def selected_port(self) -> str:
        index = self.port_combo.currentIndex()
        if index >= 0 and self.port_combo.itemText(index) == self.port_combo.currentText():
            return str(self.port_combo.itemData(index))
        return self.port_combo.currentText().split(" — ")[0].strip()

    def start_scan(self) -> None:
        if self._scan is None:
            self._scan = BleScan(self._station.ble_loop(), self._station.profile, self)
            self._scan.finished.connect(self.show_devices)
            self._scan.failed.connect(self._scan_failed)
        self.scan_button.setEnabled(False)
        self._set_scan_note("scanning")
        self._scan.start()

    def show_devices(self, devices: list[BleDevice]) -> None:
        self.scan_button.setEnabled(True)
        self.ble_list.clear()
        last = self._machine.device
        for device in devices:
            rssi = f"{device.rssi} dBm" if device.rssi is not None else "—"
            name = device.name or self.tr("(no name)")
            item = QListWidgetItem(f"{name}   {device.address}   {rssi}")
            item.setData(Qt.ItemDataRole.UserRole, device.address)
            self.ble_list.addItem(item)
            if device.address == last:
                self.ble_list.setCurrentItem(item)
        if self.ble_list.currentItem() is None and self.ble_list.count():
            self.ble_list.setCurrentRow(0)
        self._set_scan_note("found", len(devices))

    def _scan_failed(self, message: str) -> None:
        self.scan_button.setEnabled(True)
        self._scan_note = None
        self.ble_note.setText(message)

    def _set_scan_note(self, what: str, count: int = 0) -> None:
        self._scan_note = (what, count)
        self._show_scan_note()

    def _show_scan_note(self) -> None:
        """The scan's note in the current language (made again after a switch)."""
        if self._scan_note is None:
            return
        what, count = self._scan_note
        if what == "scanning":
            self.ble_note.setText(self.tr("Scanning…"))
        elif count:
            self.ble_note.setText(self.tr("%n found", "", count))
        else:
            self.ble_note.setText(self.tr("No stage found"))

    def selected_ble_address(self) -> str | None:
        item = self.ble_list.currentItem()
        if item is not None:
            return str(item.data(Qt.ItemDataRole.UserRole))
        return self._machine.device or None  # the last used stage, found again by the transport

    # --- connecting ----------------------------------------------------------

    def connect_selected(self) -> None:
        transport = self.transport
        self._machine.transport = transport
        if transport == "serial":
            port = self.selected_port()
            if not port:
                self.state_label.setText(
                    self.tr("Choose a serial port first (Refresh lists them).")
                )
                return
            baud = int(self.baud_combo.currentData())
            self._machine.device = port
            self._machine.baud = baud
            self._station.connect_serial(port, baud)
        elif transport == "ble":
            address = self.selected_ble_address()
            if address:
                self._machine.device = address
            self._station.connect_ble(address)
        else:
            self._station.connect_emulator()
        self._settings.sync()

    def _restore(self) -> None:
        self.refresh_ports()
        baud = self._machine.baud or self._station.profile.link.baud
        index = self.baud_combo.findData(baud)
        self.baud_combo.setCurrentIndex(index if index >= 0 else self.baud_combo.count() - 4)
        self.select_transport(self._machine.transport)
        self._show_transport()

    def _show_transport(self) -> None:
        self.serial_box.setVisible(self.transport == "serial")
        self.ble_box.setVisible(self.transport == "ble")

    def _show_state(self, _state: object = None) -> None:
        model = self._station.model
        text = link_state_text(model.link_state)

        if model.link_detail:
            text += f" — {link_detail_text(model.link_detail)}"
        self.state_label.setText(text)
        linked = model.link_state is not LinkState.DISCONNECTED
        self.disconnect_button.setEnabled(linked)
        if model.link_state is not LinkState.CONNECTED:
            return
        remembered = False
        kind = self._station.transport_kind
        if kind is not None and kind != self.transport:
            # The page shows the link in use (a bare launch or a machine switch opens the
            # emulator), never the one remembered from before; and it is the last one now.
            self.select_transport(kind)
        if kind is not None and kind != self._machine.transport:
            self._machine.transport = kind
            remembered = True
        device = self._station.device_id
        if device and device != self._machine.device:
            # A scan-found stage becomes "the last used" one, tried first next time.
            self._machine.device = device
            remembered = True
        if device and kind == "serial":
            self._select_port(device)
        if remembered:
            self._settings.sync()
