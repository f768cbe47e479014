"""Dynamics panel: the device's stored parameters per axis, read, edited and written back.

The device verifies every write by reading its FRAM back, so the panel never
assumes a write worked: each value shows what the device answered — confirmed,
or refused together with the value the device kept.  Only values the operator
actually edited are written, so Apply cannot overwrite a parameter with a
field that was never filled from the device.

Snapshots save every stored parameter to a TOML file (machine, firmware,
date); loading one shows what differs from the device and writes only that,
after the operator confirms (and confirms again for another machine's file).
Undo writes back what the last Apply or load replaced.

Beside the raw current scales (IRUN, IHOLD: 0…31) the fields show the RMS
current they give the motor (FIDELITY S3-18, from the profile's VFS and
Rsense), and beside a speed the speed the step timer really runs when its
whole PSC/ARR cannot give the one typed (S3-28), both as the value is typed.

A value outside what the machine may take is framed red as it is typed and
is not sent; the travel (the device's soft limit) may not exceed the
profile's mechanical travel, since beyond it the device would drive into its
end switch believing it had room.
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QSize
from PySide6.QtGui import QResizeEvent
from PySide6.QtWidgets import (
    QFileDialog,
    QGridLayout,
    QLabel,
    QMessageBox,
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
from app.machines.stage.session import StageSession
from app.scripting.errors import StepdeckError
from app.scripting.parameters import (
    BY_NAME,
    Difference,
    check_machine,
    diff,
    load_snapshot,
    save_snapshot,
    values_of,
)
from app.station import Station
from protocol.stage.codec import EchoType
from protocol.stage.driver import format_current, quantised_speed, rms_current_a
from widgets.number_field import NumberField, localized
from widgets.retranslate import Texts, bold
from widgets.units import shown_unit

_Key = tuple[int, int]  # (axis, parameter type)

#: The parameters' labels as app.machines.stage.parameters names them, for lupdate.
PARAMETER_LABELS = (
    QT_TRANSLATE_NOOP("StageParameter", "Fast speed"),
    QT_TRANSLATE_NOOP("StageParameter", "Slow speed"),
    QT_TRANSLATE_NOOP("StageParameter", "Acceleration"),
    QT_TRANSLATE_NOOP("StageParameter", "Start speed"),
    QT_TRANSLATE_NOOP("StageParameter", "Run current (IRUN)"),
    QT_TRANSLATE_NOOP("StageParameter", "Hold current (IHOLD)"),
    QT_TRANSLATE_NOOP("StageParameter", "Microsteps per step"),
    QT_TRANSLATE_NOOP("StageParameter", "Screw lead"),
    QT_TRANSLATE_NOOP("StageParameter", "Full steps per rev"),
    QT_TRANSLATE_NOOP("StageParameter", "Travel (soft limit)"),
    QT_TRANSLATE_NOOP("StageParameter", "Encoder position"),
)


def parameter_label(parameter: StageParameter) -> str:
    """The parameter's name in the current language."""
    return QCoreApplication.translate("StageParameter", parameter.label)


def _bracketed(unit: str) -> str:
    """`` [mm/ot]``: the unit after a parameter's name, in the operator's language."""
    return f" [{shown_unit(unit)}]" if unit else ""


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
        #: What the last Apply or snapshot load replaced: (axis, parameter type, wire value).
        self._undo: list[tuple[int, int, int]] = []
        #: The open "write these differences?" question, while it is asked.
        self.confirm_box: QMessageBox | None = None
        t = self.texts = Texts(self)

        self._headers = [QLabel(f"<b>{axis.name}</b>") for axis in self._model.axes]
        self._parameter_header = t.label(lambda: bold(self.tr("Parameter")))
        #: Each axis has its own column of parameter names: side by side only the first
        #: axis's is shown, stacked each axis block has its own.
        self._names: list[list[QLabel]] = []
        for axis_index in range(len(self._model.axes)):
            names = []
            for parameter in STAGE_PARAMETERS:
                names.append(t.label(lambda p=parameter: parameter_label(p) + _bracketed(p.unit)))
                key = (axis_index, int(parameter.type))
                state = QLabel()
                state.setMinimumWidth(state.fontMetrics().horizontalAdvance(_WIDEST_STATE))
                # "✗ refused, kept 12.500" wraps under itself rather than widening the page.
                state.setWordWrap(True)
                self.fields[key] = self._field(parameter, key)
                self.states[key] = state
            self._names.append(names)
        self.grid = QGridLayout()
        self.grid.setHorizontalSpacing(10)
        self.grid.setVerticalSpacing(4)

        self.read_button = t.button(
            lambda: self.tr("Read"),
            lambda: self.tr("Read every parameter from the device into the fields"),
        )
        self.read_button.clicked.connect(self.read)
        self.apply_button = t.button(
            lambda: self.tr("Apply"),
            lambda: self.tr("Write the edited values to the device; it confirms each one"),
        )
        self.apply_button.clicked.connect(self.apply)
        self.save_button = t.button(
            lambda: self.tr("Save snapshot…"),
            lambda: self.tr("Save every stored parameter to a TOML file"),
        )
        self.save_button.clicked.connect(self._ask_save)
        self.load_button = t.button(
            lambda: self.tr("Load snapshot…"),
            lambda: self.tr("Show what a snapshot changes, then write only that"),
        )
        self.load_button.clicked.connect(self._ask_load)
        self.undo_button = t.button(
            lambda: self.tr("Undo last write"),
            lambda: self.tr("Write back what the last Apply or load replaced"),
        )
        self.undo_button.clicked.connect(self.undo)
        self.summary = QLabel()
        self.summary.setWordWrap(True)
        self.buttons = QGridLayout()
        self.buttons.setHorizontalSpacing(6)

        layout = QVBoxLayout(self)
        layout.addLayout(self.grid)
        layout.addSpacing(6)
        layout.addLayout(self.buttons)
        layout.addStretch(1)
        # The widths each arrangement needs, measured once laid out; the page picks the
        # side-by-side one only where it fits, so it never scrolls sideways.
        self.stacked = True
        self._arrange(stacked=True)
        self._stacked_width = layout.minimumSize().width()
        self._arrange(stacked=False)
        self._wide_width = layout.minimumSize().width()

        self._model.parameterChanged.connect(self._show_parameter)
        self._model.linkStateChanged.connect(self._update_enabled)
        for axis_index, type_ in self.fields:
            self._show_parameter(axis_index, type_)
        self._update_enabled()
        t.also(self._retranslate_states)
        for (axis_index, _type), number in self.fields.items():
            number.textChanged.connect(lambda _text, a=axis_index: self._show_notes(a))
        for axis_index in range(len(self._model.axes)):
            self._show_notes(axis_index)

    # --- reflow ------------------------------------------------------------------

    def _arrange(self, *, stacked: bool) -> None:
        """Axes side by side where the page is wide enough, else one axis block under another.

        At 1280 px with the jobs dock open the page is a third of the window: side by side
        the second axis's column ran off its edge and the page scrolled sideways.
        """
        self.stacked = stacked
        for layout in (self.grid, self.buttons):
            while layout.count():
                layout.takeAt(0)
        grid = self.grid
        axes = range(len(self._model.axes))
        if stacked:
            self._parameter_header.hide()
            row = 0
            for axis in axes:
                grid.addWidget(self._headers[axis], row, 0, 1, 3)
                row += 1
                for parameter, name in zip(STAGE_PARAMETERS, self._names[axis], strict=True):
                    key = (axis, int(parameter.type))
                    name.show()
                    grid.addWidget(name, row, 0)
                    grid.addWidget(self.fields[key], row, 1)
                    grid.addWidget(self.states[key], row, 2)
                    row += 1
            columns = 3
        else:
            self._parameter_header.show()
            grid.addWidget(self._parameter_header, 0, 0)
            for axis in axes:
                grid.addWidget(self._headers[axis], 0, 1 + 2 * axis, 1, 2)
                for row, (parameter, name) in enumerate(
                    zip(STAGE_PARAMETERS, self._names[axis], strict=True), start=1
                ):
                    key = (axis, int(parameter.type))
                    if axis == 0:
                        grid.addWidget(name, row, 0)
                    name.setVisible(axis == 0)
                    grid.addWidget(self.fields[key], row, 1 + 2 * axis)
                    grid.addWidget(self.states[key], row, 2 + 2 * axis)
            columns = 1 + 2 * len(axes)
        for column in range(grid.columnCount()):
            grid.setColumnStretch(column, 0)
        grid.setColumnStretch(columns, 1)
        # The buttons: one row beside the summary, or two rows with the summary under them.
        buttons = self.buttons
        if stacked:
            for column, button in enumerate((self.read_button, self.apply_button)):
                buttons.addWidget(button, 0, column)
            buttons.addWidget(self.undo_button, 0, 2)
            buttons.addWidget(self.save_button, 1, 0, 1, 2)
            buttons.addWidget(self.load_button, 1, 2)
            buttons.addWidget(self.summary, 2, 0, 1, 4)
            for column in range(6):
                buttons.setColumnStretch(column, 1 if column == 3 else 0)
        else:
            for column, button in enumerate(
                (
                    self.read_button,
                    self.apply_button,
                    self.save_button,
                    self.load_button,
                    self.undo_button,
                )
            ):
                buttons.addWidget(button, 0, column)
            buttons.addWidget(self.summary, 0, 5)
            for column in range(6):
                buttons.setColumnStretch(column, 1 if column == 5 else 0)
        self.grid.invalidate()
        self.buttons.invalidate()

    def minimumSizeHint(self) -> QSize:
        """As narrow as the stacked arrangement: the page reflows rather than scroll."""
        hint = super().minimumSizeHint()
        if not hasattr(self, "_stacked_width"):
            return hint
        return QSize(self._stacked_width, hint.height())

    def resizeEvent(self, event: QResizeEvent) -> None:
        stacked = event.size().width() < self._wide_width
        if stacked != self.stacked:
            self._arrange(stacked=stacked)
            self.updateGeometry()  # the height differs: a scroll area around it follows
        super().resizeEvent(event)

    # --- what the values mean on the motor -----------------------------------------

    def _show_notes(self, axis: int) -> None:
        """The currents the scales give and the speeds the step timer runs, as typed."""
        driver = self._station.profile.driver
        for type_ in (EchoType.IRUN, EchoType.IHOLD):
            number = self.fields.get((axis, int(type_)))
            if number is None:
                continue
            cs = number.value()
            note = ""
            if cs is not None and cs == int(cs):
                amperes = rms_current_a(int(cs), driver.vfs_v, driver.rsense_ohm)
                note = "= " + localized(format_current(amperes))
            number.set_note(note)
        microstep = self._microstep_um(axis)
        for type_ in (EchoType.FAST_SPEED, EchoType.SLOW_SPEED):
            number = self.fields.get((axis, int(type_)))
            if number is None:
                continue
            shown = number.value()
            note = ""
            if shown is not None and microstep is not None and shown > 0:
                wire = BY_TYPE[type_].to_wire(shown)
                real = quantised_speed(wire, microstep, driver.step_clock_hz) / 1000
                if abs(real - shown) >= 0.0005:
                    note = "→ " + localized(f"{real:.3f}")
            number.set_note(note)

    def _microstep_um(self, axis: int) -> float | None:
        """One microstep (µm) as the fields hold lead, steps and microsteps, or None."""
        values = [
            self.fields[(axis, int(t))].value()
            for t in (EchoType.LEAD, EchoType.STEPS_PER_REV, EchoType.MICROSTEPS)
        ]
        lead, steps, microsteps = values
        if lead is None or not steps or not microsteps or lead <= 0:
            return None
        return lead * 1000 / (steps * microsteps)

    def _field(self, parameter: StageParameter, key: _Key) -> NumberField:
        low, high = wire_limits(parameter, self._station.profile.axes[key[0]])

        def tip() -> str:
            if not parameter.writable:
                return self.tr("Read only: measured by the device")
            text = parameter_label(parameter)
            if parameter.type == EchoType.TRAVEL:
                travel = localized(f"{parameter.to_shown(high):g}")
                text += self.tr("; at most the mechanical travel, {0} mm").format(travel)
            elif parameter.type in (EchoType.IRUN, EchoType.IHOLD):
                driver = self._station.profile.driver
                text += self.tr(
                    "; current scale CS, the motor gets IRMS = (CS+1)/32 · VFS/(Rsense+20 mΩ)/√2"
                    " (VFS {0} V, Rsense {1} Ω)"
                ).format(localized(f"{driver.vfs_v:g}"), localized(f"{driver.rsense_ohm:g}"))
            elif parameter.type in (EchoType.FAST_SPEED, EchoType.SLOW_SPEED):
                text += self.tr(
                    "; → the speed the step timer really runs, where its whole prescaler and"
                    " reload values cannot give this one"
                )
            return text

        field = NumberField(
            parameter.to_shown(low),
            parameter.to_shown(high),
            decimals=parameter.decimals,
            unit=parameter.unit,
        )
        self.texts.set(field.set_description, tip)
        if parameter.writable:
            field.textChanged.connect(lambda _text: self._mark_edited(key))
        else:
            field.setReadOnly(True)
        return field

    # --- operator actions ----------------------------------------------------

    def read(self) -> None:
        """Ask the device for every parameter; the answers replace the fields."""
        session = self._station.session_as(StageSession)
        if session is None:
            return
        self._edited.clear()
        session.read_all_parameters()
        self.summary.setText(self.tr("Reading from the device…"))

    def apply(self) -> int:
        """Write every edited, locally valid value; returns how many were sent."""
        session = self._station.session_as(StageSession)
        if session is None:
            return 0
        sent = 0
        reasons: list[str] = []
        replaced: list[tuple[int, int, int]] = []
        for key in sorted(self._edited):
            axis, type_ = key
            parameter = BY_TYPE[type_]
            shown = self.fields[key].value()
            if shown is None:
                problem = self.fields[key].problem() or self.tr("not a number")
                self._set_state(key, self.tr("✗ not sent"), _RED, problem)
                label = parameter_label(parameter)
                reasons.append(f"{self._model.axes[axis].name} {label}: {problem}")
                continue
            wire = parameter.to_wire(shown)
            if wire == self._model.parameter(axis, type_).value:
                self._edited.discard(key)
                self._set_state(key, "", _GREY)
                continue
            refused = check_for_axis(parameter, wire, self._station.profile.axes[axis])
            if refused is not None:
                self._set_state(key, self.tr("✗ not sent"), _RED, refused)
                reasons.append(f"{self._model.axes[axis].name} {refused}")
                continue
            previous = self._model.parameter(axis, type_).value
            if session.write_parameter(axis, parameter.type, wire):
                sent += 1
                if previous is not None:
                    replaced.append((axis, type_, previous))
        if replaced:
            self._undo = replaced
        self._update_enabled()
        parts = [self.tr("%n value(s) written", "", sent)] if sent else []
        parts += [self.tr("not sent: {0}").format(reason) for reason in reasons]
        self.summary.setText("; ".join(parts) or self.tr("Nothing changed"))
        return sent

    # --- snapshots ------------------------------------------------------------

    def _ask_save(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self,
            self.tr("Save parameter snapshot"),
            "",
            self.tr("Parameter snapshots (*.toml)"),
        )
        if path:
            self.save_snapshot(Path(path))

    def _ask_load(self) -> None:
        path, _ = QFileDialog.getOpenFileName(
            self,
            self.tr("Load parameter snapshot"),
            "",
            self.tr("Parameter snapshots (*.toml)"),
        )
        if path:
            self.load_snapshot(Path(path))

    def save_snapshot(self, path: Path) -> bool:
        """Save what the device answered (the fields' last reads and confirmed writes)."""
        values = values_of(self._model)
        missing = [
            f"{axis} {name}"
            for axis, row in values.items()
            for name in BY_NAME
            if BY_NAME[name].writable and name not in row
        ]
        if missing:
            self.summary.setText(
                self.tr("Not saved: not read yet: {0} — press Read").format(", ".join(missing[:4]))
            )
            return False
        try:
            save_snapshot(path, self._station, values)
        except OSError as exc:
            self.summary.setText(self.tr("Not saved: {0}").format(exc))
            return False
        self.summary.setText(self.tr("Snapshot saved to {0}").format(path.name))
        return True

    def load_snapshot(self, path: Path) -> list[Difference]:
        """Show what ``path`` changes and ask before writing it; returns the differences."""
        try:
            snapshot = load_snapshot(path)
            other = False
            try:
                check_machine(snapshot, self._station.profile, other_machine=False)
            except StepdeckError:
                other = True
            differences = [d for d in diff(snapshot, values_of(self._model)) if d.writable]
        except StepdeckError as exc:
            self.summary.setText(self.tr("Not loaded: {0}").format(exc))
            return []
        if not differences:
            self.summary.setText(
                self.tr("{0}: the device already holds every value").format(path.name)
            )
            return []
        box = QMessageBox(self)
        box.setObjectName("snapshot_confirm")
        box.setWindowTitle(self.tr("Load parameter snapshot"))
        lines = "\n".join(str(d) for d in differences)
        count = len(differences)
        text = self.tr("%n value(s) of {0} differ from the device:", "", count).format(path.name)
        text += f"\n\n{lines}"
        if other:
            box.setIcon(QMessageBox.Icon.Warning)
            text = (
                self.tr(
                    "This snapshot is of another machine ({0}, firmware {1}, {2}), not {3}."
                ).format(
                    snapshot.title or snapshot.profile,
                    snapshot.firmware,
                    snapshot.date,
                    self._station.profile.shown_title,
                )
                + "\n\n"
                + text
            )
        box.setText(text)
        write = box.addButton(
            self.tr("Write anyway") if other else self.tr("Write %n", "", count),
            QMessageBox.ButtonRole.AcceptRole,
        )
        box.addButton(QMessageBox.StandardButton.Cancel)
        box.setModal(True)

        def answered() -> None:
            if box.clickedButton() is write:
                self._write_differences(differences)
            else:
                self.summary.setText(self.tr("Snapshot not loaded"))
            self.confirm_box = None
            box.deleteLater()

        box.finished.connect(lambda _result: answered())
        self.confirm_box = box
        box.open()  # never blocks: the answer arrives as a click
        return differences

    def _write_differences(self, differences: list[Difference]) -> None:
        session = self._station.session_as(StageSession)
        if session is None:
            self.summary.setText(self.tr("Not written: not connected"))
            return
        names = [axis.name for axis in self._model.axes]
        replaced: list[tuple[int, int, int]] = []
        sent = 0
        for difference in differences:
            axis = names.index(difference.axis)
            parameter = BY_NAME[difference.name]
            previous = self._model.parameter(axis, int(parameter.type)).value
            if session.write_parameter(axis, parameter.type, parameter.to_wire(difference.wanted)):
                sent += 1
                if previous is not None:
                    replaced.append((axis, int(parameter.type), previous))
        if replaced:
            self._undo = replaced
        self._update_enabled()
        self.summary.setText(
            self.tr("%n value(s) written from the snapshot; the device confirms each", "", sent)
        )

    def undo(self) -> int:
        """Write back what the last Apply or load replaced; returns how many were sent."""
        session = self._station.session_as(StageSession)
        if session is None or not self._undo:
            return 0
        undo, self._undo = self._undo, []
        sent = sum(
            1 for axis, type_, wire in undo if session.write_parameter(axis, EchoType(type_), wire)
        )
        self._update_enabled()
        self.summary.setText(self.tr("%n value(s) written back", "", sent))
        return sent

    # --- model → fields ------------------------------------------------------

    def _mark_edited(self, key: _Key) -> None:
        if self._filling:
            return
        self._edited.add(key)
        self._set_state(key, self.tr("• edited"), _AMBER)

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
            self._set_state(key, self.tr("… writing"), _GREY)
        elif entry.state is ParameterState.CONFIRMED:
            self._set_state(key, self.tr("✓ confirmed"), _GREEN)
        elif entry.state is ParameterState.REFUSED:
            asked = "" if entry.requested is None else self._format(parameter, entry.requested)
            self._set_state(
                key,
                self.tr("✗ refused, kept {0}").format(shown),
                _RED,
                self.tr("Asked for {0}").format(asked),
            )
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

    def _retranslate_states(self) -> None:
        """The states the device answered, said again; "edited" stays edited."""
        for axis, type_ in self.fields:
            if (axis, type_) in self._edited:
                self._set_state((axis, type_), self.tr("• edited"), _AMBER)
            else:
                self._show_parameter(axis, type_)

    def _set_state(self, key: _Key, text: str, colour: str, tooltip: str = "") -> None:
        label = self.states[key]
        label.setText(text)
        label.setStyleSheet(f"color: {colour};")
        label.setToolTip(tooltip)

    @staticmethod
    def _format(parameter: StageParameter, wire: int) -> str:
        return localized(f"{parameter.to_shown(wire):.{parameter.decimals}f}")

    def _update_enabled(self, _state: object = None) -> None:
        """Read/Apply need a live link; motion locks do not matter for parameters."""
        live = self._model.link_state in (LinkState.CONNECTED, LinkState.STALE)
        self.read_button.setEnabled(live)
        self.apply_button.setEnabled(live)
        self.load_button.setEnabled(live)
        self.save_button.setEnabled(live)
        self.undo_button.setEnabled(live and bool(self._undo))
