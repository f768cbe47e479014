"""The always-visible info panel: where the machine is and whether it can be trusted.

Everything here is read from the machine model on its change signals, so the
panel shows exactly what the device last reported: positions and statuses
per axis (the work position; where a board keeps a work offset, GRBL's
G92, the machine position beside it as well, in small), the link state as
a coloured lamp, the battery, the board temperature, why the machine may
refuse to move (charger, USB), and the stage's LED ring as the device flags
say it is lit (FIDELITY S3-33).
"""

from __future__ import annotations

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QProgressBar,
    QVBoxLayout,
    QWidget,
)

from app.machine import LinkState, MachineModel
from protocol.stage.codec import DeviceFlag
from protocol.stage.led import LedRing, led_ring
from widgets.link_text import axis_status_text, link_detail_text, link_state_text
from widgets.number_field import localized
from widgets.retranslate import Texts
from widgets.style import monospace_font
from widgets.units import shown_unit

LINK_COLOURS: dict[LinkState, str] = {
    LinkState.CONNECTED: "#2e9e44",
    LinkState.CONNECTING: "#e0a000",
    LinkState.STALE: "#e0a000",
    LinkState.LOST: "#d03030",
    LinkState.DISCONNECTED: "#8a8a8a",
}

#: The LED ring's colours, as drawn beside its state; blinking states say so in words.
LED_COLOURS: dict[LedRing, str] = {
    LedRing.OFF: "#8a8a8a",
    LedRing.CHARGING: "#d03030",
    LedRing.LOW_BATTERY: "#d03030",
    LedRing.STANDBY: "#2e9e44",
    LedRing.PAIRING: "#1f6fc0",
    LedRing.TALKING: "#1f6fc0",
}

#: Status texts worth a colour; the rest stay in the normal text colour.
_STATUS_COLOURS: dict[str, str] = {
    "accelerating": "#1f6fc0",
    "constant speed": "#1f6fc0",
    "decelerating": "#1f6fc0",
    "homing": "#1f6fc0",
    "target reached": "#2e9e44",
    "end switch hit": "#c06000",
    "driver fault": "#d03030",
}


class InfoPanel(QFrame):
    """Positions, statuses, link lamp, battery gauge and temperature, from the model."""

    def __init__(self, model: MachineModel, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._model = model
        self.setFrameShape(QFrame.Shape.StyledPanel)
        self.positions: list[QLabel] = []
        #: The machine position, shown beside the work position while they differ.
        self.machine_positions: list[QLabel] = []
        self.statuses: list[QLabel] = []
        self.texts = Texts(self)

        layout = QHBoxLayout(self)
        layout.setContentsMargins(12, 8, 12, 8)
        layout.setSpacing(24)
        layout.addLayout(self._build_axes())
        layout.addStretch(1)
        layout.addLayout(self._build_device())

        model.axisChanged.connect(self._show_axis)
        model.linkStateChanged.connect(self._show_link)
        model.telemetryChanged.connect(self._show_telemetry)
        for index in range(len(model.axes)):
            self._show_axis(index)
        self._show_link()
        self._show_telemetry()
        self.texts.also(self._show_link)
        self.texts.also(self._show_telemetry)

    # --- building ------------------------------------------------------------

    def _build_axes(self) -> QGridLayout:
        grid = QGridLayout()
        grid.setHorizontalSpacing(14)
        grid.setVerticalSpacing(4)
        for row, axis in enumerate(self._model.axes):
            name = QLabel(axis.name)
            name.setFont(monospace_font(4, bold=True))
            position = QLabel()
            position.setObjectName(f"position_{axis.name}")
            position.setFont(monospace_font(4, bold=True))
            position.setAlignment(Qt.AlignmentFlag.AlignRight | Qt.AlignmentFlag.AlignVCenter)
            position.setMinimumWidth(position.fontMetrics().horizontalAdvance("-0000.000 mm"))
            status = QLabel()
            status.setObjectName(f"status_{axis.name}")
            status.setMinimumWidth(status.fontMetrics().horizontalAdvance("blocked: charger conn"))
            machine = QLabel()
            machine.setObjectName(f"machine_position_{axis.name}")
            machine.setVisible(False)
            grid.addWidget(name, row, 0)
            grid.addWidget(position, row, 1)
            grid.addWidget(status, row, 2)
            grid.addWidget(machine, row, 3)
            self.positions.append(position)
            self.machine_positions.append(machine)
            self.statuses.append(status)
        return grid

    def _build_device(self) -> QVBoxLayout:
        column = QVBoxLayout()
        column.setSpacing(4)

        link_row = QHBoxLayout()
        self.link_lamp = QLabel()
        self.link_lamp.setFixedSize(14, 14)
        self.link_text = QLabel()
        link_row.addWidget(self.link_lamp)
        link_row.addWidget(self.link_text, 1)
        column.addLayout(link_row)

        self.battery = QProgressBar()
        self.battery.setRange(0, 100)
        self.battery.setMinimumWidth(160)
        self.battery.setMaximumHeight(8)
        self.texts.set(self.battery.setToolTip, lambda: self.tr("Battery charge and voltage"))
        # The words beside a thin gauge, not on it: text over the fill's edge was split in
        # two colours and half unreadable.
        self.battery.setTextVisible(False)
        self.battery_text = QLabel()
        self.battery_text.setObjectName("battery_text")
        column.addWidget(self.battery_text)
        column.addWidget(self.battery)

        # The stage's LED ring, drawn from the device flags it reports (S3-33).
        led_row = QHBoxLayout()
        self.led_lamp = QLabel()
        self.led_lamp.setObjectName("led_ring_lamp")
        self.led_lamp.setFixedSize(12, 12)
        self.led_text = QLabel()
        self.led_text.setObjectName("led_ring_text")
        led_row.addWidget(self.led_lamp)
        led_row.addWidget(self.led_text, 1)
        column.addLayout(led_row)

        self.temperature = QLabel()
        self.power_note = QLabel()
        self.power_note.setStyleSheet("color: #c06000;")
        column.addWidget(self.temperature)
        column.addWidget(self.power_note)
        # Battery and temperature come from subscriber variables; machines without
        # them (mains-powered units) do not show empty gauges.
        has_telemetry = self._model.profile.capabilities.subscribers
        for widget in (
            self.battery,
            self.battery_text,
            self.temperature,
            self.power_note,
            self.led_lamp,
            self.led_text,
        ):
            widget.setVisible(has_telemetry)
        return column

    # --- showing -------------------------------------------------------------

    def _show_axis(self, index: int) -> None:
        axis = self._model.axes[index]
        self.positions[index].setText(
            localized(f"{axis.work_position:.3f} {shown_unit(axis.unit)}")
        )
        machine = self.machine_positions[index]
        machine.setVisible(axis.offset != 0.0)
        machine.setEnabled(self._model.link_state is LinkState.CONNECTED)
        machine.setText(
            self.tr("machine {0}").format(localized(f"{axis.position:.3f} {shown_unit(axis.unit)}"))
        )
        machine.setToolTip(
            self.tr(
                "Machine position; the figure on the left is the work position "
                "(G92 work offset {0})"
            ).format(localized(f"{axis.offset:.3f} {shown_unit(axis.unit)}"))
        )
        status = self.statuses[index]
        status.setText(axis_status_text(axis.status_text))
        colour = _STATUS_COLOURS.get(axis.status_text)
        if axis.status_text.startswith("blocked") or axis.status_text == "sleeping":
            colour = "#c06000"
        if self._model.link_state is not LinkState.CONNECTED:
            colour = None  # the disabled grey: not a live state
        status.setStyleSheet(f"color: {colour};" if colour else "")

    def _show_link(self, _state: object = None) -> None:
        state = self._model.link_state
        colour = LINK_COLOURS[state]
        self.link_lamp.setStyleSheet(
            f"background: {colour}; border-radius: 7px; border: 1px solid #00000040;"
        )
        detail = (
            f" — {link_detail_text(self._model.link_detail)}" if self._model.link_detail else ""
        )
        self.link_text.setText(f"{link_state_text(state)}{detail}")
        self.link_lamp.setToolTip(self.tr("Link {0}").format(link_state_text(state)))
        # Positions and states are live only while the device answers: otherwise they are
        # the last ones heard, greyed so that nobody reads them as where the machine is.
        live = state is LinkState.CONNECTED
        tip = "" if live else self.tr("Last known — the link is {0}").format(link_state_text(state))
        for index, (position, status) in enumerate(zip(self.positions, self.statuses, strict=True)):
            position.setEnabled(live)
            status.setEnabled(live)
            position.setToolTip(tip)
            self._show_axis(index)
        self._show_led()

    def _show_telemetry(self, _key: str = "") -> None:
        telemetry = self._model.telemetry
        charge = telemetry.get("battery_charge")
        voltage = telemetry.get("battery_voltage")
        if charge is None:
            self.battery.setValue(0)
            self.battery.setFormat(self.tr("battery —"))
        else:
            self.battery.setValue(round(charge))
            volts = localized(f" · {voltage:.2f} V") if voltage is not None else ""
            self.battery.setFormat(self.tr("battery {0} %").format(f"{charge:.0f}") + volts)
        self.battery_text.setText(self.battery.format())
        temperature = telemetry.get("board_temperature")
        self.temperature.setText(
            self.tr("board —")
            if temperature is None
            else self.tr("board {0} °C").format(localized(f"{temperature:.1f}"))
        )
        self.power_note.setText(self._power_note())
        self._show_led()

    def led_state(self) -> LedRing | None:
        """What the stage's ring shows now, or None while the station cannot know.

        The device flags carry every condition of the ring's table; the station sees
        them only over a live link, and while it talks the ring shows that (or what
        outranks it): never pairing.
        """
        flags = self._model.telemetry.get("device_flags")
        if flags is None or self._model.link_state is not LinkState.CONNECTED:
            return None
        return led_ring(int(flags))

    def _show_led(self) -> None:
        state = self.led_state()
        colour = "transparent" if state is None else LED_COLOURS[state]
        rim = LED_COLOURS[LedRing.OFF]
        self.led_lamp.setStyleSheet(
            f"background: {colour}; border-radius: 6px; border: 2px solid {rim};"
        )
        words = "—" if state is None else self._led_words(state)
        self.led_text.setText(self.tr("LED ring: {0}").format(words))
        self.led_text.setToolTip(
            self.tr("The stage's LED ring as its device flags say it is lit")
            if state is None
            else self._led_meaning(state)
        )

    def _led_words(self, state: LedRing) -> str:
        match state:
            case LedRing.CHARGING:
                return self.tr("red")
            case LedRing.LOW_BATTERY:
                return self.tr("red, blinking fast")
            case LedRing.STANDBY:
                return self.tr("green")
            case LedRing.PAIRING:
                return self.tr("blue, blinking slowly")
            case LedRing.TALKING:
                return self.tr("blue")
        return self.tr("off")

    def _led_meaning(self, state: LedRing) -> str:
        match state:
            case LedRing.CHARGING:
                return self.tr("Charger connected")
            case LedRing.LOW_BATTERY:
                return self.tr("Battery low")
            case LedRing.STANDBY:
                return self.tr("Standby: the stage is asleep")
            case LedRing.PAIRING:
                return self.tr("Pairing: waiting for a host")
            case LedRing.TALKING:
                return self.tr("Talking to this station")
        return self.tr("Off")

    def _power_note(self) -> str:
        """Charger, USB and low battery: the device's reasons to refuse motion."""
        flags = DeviceFlag(int(self._model.telemetry.get("device_flags", 0)))
        notes = []
        if DeviceFlag.CHARGER in flags:
            current = self._model.telemetry.get("charging_current")
            notes.append(
                self.tr("charger connected")
                + (f" ({current:.0f} mA)" if current is not None else "")
            )
        if DeviceFlag.USB in flags:
            notes.append(self.tr("USB connected"))
        if DeviceFlag.LOW_BATTERY in flags:
            notes.append(self.tr("battery low"))

        return "⚡ " + ", ".join(notes) if notes else ""
