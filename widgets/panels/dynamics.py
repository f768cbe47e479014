"""Dynamics panel: the device's stored parameters per axis, read, edited and written back.

The device verifies every write by reading its FRAM back, so the panel never
assumes a write worked: each value shows what the device answered — confirmed,
or refused together with the value the device kept.  Only values the operator
actually edited are written, so Apply cannot overwrite a parameter with a
field that was never filled from the device.

A value outside what the machine may take is framed red as it is typed and
is not sent; the travel (the device's soft limit) may not exceed the
profile's mechanical travel, since beyond it the device would drive into its
end switch believing it had room.
"""

from __future__ import annotations

from PySide6.QtWidgets import (
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.machine import LinkState, ParameterState
from app.machines.stage.parameters import (
    BY_TYPE,
    STAGE_PARAMETERS,
    StageParameter,
    check_for_axis,
    wire_limits,
)
from app.station import Station
from protocol.stage.codec import EchoType
from widgets.number_field import NumberField

_Key = tuple[int, int]  # (axis, parameter type)

_WIDEST_STATE = "✓ confirmed"
_GREY, _GREEN, _RED, _AMBER = "#707070", "#2e9e44", "#d03030", "#b07000"


class DynamicsPanel(QWidget):
    """A grid of every STAGE_PARAMETERS entry per axis, with Read and Apply."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._model = station.model
        self.fields: dict[_Key, NumberField] = {}
        self.states: dict[_Key, QLabel] = {}
        self._edited: set[_Key] = set()
        self._filling = False

        grid = QGridLayout()
        grid.setHorizontalSpacing(10)
        grid.setVerticalSpacing(4)
        grid.addWidget(QLabel("<b>Parameter</b>"), 0, 0)
        for axis_index, axis in enumerate(self._model.axes):
            grid.addWidget(QLabel(f"<b>{axis.name}</b>"), 0, 1 + 2 * axis_index, 1, 2)
        for row, parameter in enumerate(STAGE_PARAMETERS, start=1):
            unit = f" [{parameter.unit}]" if parameter.unit else ""
            grid.addWidget(QLabel(parameter.label + unit), row, 0)
            for axis_index in range(len(self._model.axes)):
                key = (axis_index, int(parameter.type))
                field = self._field(parameter, key)
                state = QLabel()
                state.setMinimumWidth(state.fontMetrics().horizontalAdvance(_WIDEST_STATE))
                grid.addWidget(field, row, 1 + 2 * axis_index)
                grid.addWidget(state, row, 2 + 2 * axis_index)
                self.fields[key] = field
                self.states[key] = state
        grid.setColumnStretch(grid.columnCount(), 1)

        self.read_button = QPushButton("Read")
        self.read_button.setToolTip("Read every parameter from the device into the fields")
        self.read_button.clicked.connect(self.read)
        self.apply_button = QPushButton("Apply")
        self.apply_button.setToolTip("Write the edited values to the device; it confirms each one")
        self.apply_button.clicked.connect(self.apply)
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        buttons = QHBoxLayout()
        buttons.addWidget(self.read_button)
        buttons.addWidget(self.apply_button)
        buttons.addWidget(self.summary, 1)

        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addSpacing(6)
        layout.addLayout(buttons)
        layout.addStretch(1)

        self._model.parameterChanged.connect(self._show_parameter)
        self._model.linkStateChanged.connect(self._update_enabled)
        for axis_index, type_ in self.fields:
            self._show_parameter(axis_index, type_)
        self._update_enabled()

    def _field(self, parameter: StageParameter, key: _Key) -> NumberField:
        low, high = wire_limits(parameter, self._station.profile.axes[key[0]])
        tip = "Read only: measured by the device" if not parameter.writable else parameter.label
        if parameter.type == EchoType.TRAVEL:
            tip += f"; at most the mechanical travel, {parameter.to_shown(high):g} mm"
        field = NumberField(
            parameter.to_shown(low),
            parameter.to_shown(high),
            decimals=parameter.decimals,
            unit=parameter.unit,
            tooltip=tip,
        )
        if parameter.writable:
            field.textChanged.connect(lambda _text: self._mark_edited(key))
        else:
            field.setReadOnly(True)
        return field

    # --- operator actions ----------------------------------------------------

    def read(self) -> None:
        """Ask the device for every parameter; the answers replace the fields."""
        session = self._station.stage_session
        if session is None:
            return
        self._edited.clear()
        session.read_all_parameters()
        self.summary.setText("Reading from the device…")

    def apply(self) -> int:
        """Write every edited, locally valid value; returns how many were sent."""
        session = self._station.stage_session
        if session is None:
            return 0
        sent = 0
        reasons: list[str] = []
        for key in sorted(self._edited):
            axis, type_ = key
            parameter = BY_TYPE[type_]
            shown = self.fields[key].value()
            if shown is None:
                problem = self.fields[key].problem() or "not a number"
                self._set_state(key, "✗ not sent", _RED, problem)
                reasons.append(f"{self._model.axes[axis].name} {parameter.label}: {problem}")
                continue
            wire = parameter.to_wire(shown)
            if wire == self._model.parameter(axis, type_).value:
                self._edited.discard(key)
                self._set_state(key, "", _GREY)
                continue
            refused = check_for_axis(parameter, wire, self._station.profile.axes[axis])
            if refused is not None:
                self._set_state(key, "✗ not sent", _RED, refused)
                reasons.append(f"{self._model.axes[axis].name} {refused}")
                continue
            if session.write_parameter(axis, parameter.type, wire):
                sent += 1
        parts = [f"{sent} value(s) written"] if sent else []
        parts += [f"not sent: {reason}" for reason in reasons]
        self.summary.setText("; ".join(parts) or "Nothing changed")
        return sent

    # --- model → fields ------------------------------------------------------

    def _mark_edited(self, key: _Key) -> None:
        if self._filling:
            return
        self._edited.add(key)
        self._set_state(key, "• edited", _AMBER)

    def _show_parameter(self, axis: int, type_: int) -> None:
        key = (axis, type_)
        if key not in self.fields:
            return
        parameter = BY_TYPE[type_]
        entry = self._model.parameter(axis, type_)
        answered = entry.state in (ParameterState.CONFIRMED, ParameterState.REFUSED)
        if entry.value is not None and (answered or key not in self._edited):
            self._fill(key, parameter.to_shown(entry.value))
        shown = "—" if entry.value is None else self._format(parameter, entry.value)
        if entry.state is ParameterState.PENDING:
            self._set_state(key, "… writing", _GREY)
        elif entry.state is ParameterState.CONFIRMED:
            self._set_state(key, "✓ confirmed", _GREEN)
        elif entry.state is ParameterState.REFUSED:
            asked = "" if entry.requested is None else self._format(parameter, entry.requested)
            self._set_state(key, f"✗ refused, kept {shown}", _RED, f"Asked for {asked}")
        elif entry.state is ParameterState.READ and key not in self._edited:
            self._set_state(key, "", _GREY)

    def _fill(self, key: _Key, value: float) -> None:
        # Not blockSignals: the field must still judge what the device holds (a travel
        # beyond the mechanics shows red), only the panel must not count it an edit.
        self._filling = True
        try:
            self.fields[key].setValue(value)
        finally:
            self._filling = False
        self._edited.discard(key)

    def _set_state(self, key: _Key, text: str, colour: str, tooltip: str = "") -> None:
        label = self.states[key]
        label.setText(text)
        label.setStyleSheet(f"color: {colour};")
        label.setToolTip(tooltip)

    @staticmethod
    def _format(parameter: StageParameter, wire: int) -> str:
        return f"{parameter.to_shown(wire):.{parameter.decimals}f}"

    def _update_enabled(self, _state: object = None) -> None:
        """Read/Apply need a live link; motion locks do not matter for parameters."""
        live = self._model.link_state in (LinkState.CONNECTED, LinkState.STALE)
        self.read_button.setEnabled(live)
        self.apply_button.setEnabled(live)
