"""The developer pane (Shift+V): inject echoes, simulate the device, watch the wire.

It mirrors the developer extension of the stage's original tool — fake a
received echo, let a timer answer the tool's own commands — and adds the
frame log and the emulator's knobs, so every state the operator panels can
show is one click away.  The pane is a view: parsing, logging and the
emulator live in :mod:`app.developer`, and the pane never touches a
transport or the emulator itself.

The log view redraws on a timer, in batches, never per frame: at a 1 kHz
frame rate a redraw per frame would stall the GUI the operator is using.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from contextlib import contextmanager

from PySide6.QtCore import QCoreApplication, Qt, QTimer
from PySide6.QtGui import QShowEvent
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDockWidget,
    QFileDialog,
    QFormLayout,
    QFrame,
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QPlainTextEdit,
    QPushButton,
    QScrollArea,
    QSizePolicy,
    QSlider,
    QSplitter,
    QVBoxLayout,
    QWidget,
)

from app.developer.emulator_controls import (
    END_SWITCHES,
    EmulatorControls,
    SimulationRefused,
    SwitchName,
)
from app.developer.frame_log import LOG_CAPACITY, FrameLog
from app.developer.stage import (
    SUBSCRIBER_TEXT,
    TYPE_TEXT,
    AxisFields,
    EchoFields,
    InjectError,
    inject_echo,
    raw_echo_text,
    status_text,
    subscriber_text,
    type_text,
)
from app.machines.stage.echoes import STATUS_TEXT
from app.station import Station
from widgets.developer.gcode_box import GcodeEmulatorBox, GcodeReplyBox
from widgets.dialects import DeveloperBox, window_dialect
from widgets.number_field import FieldGate, NumberField
from widgets.retranslate import Texts
from widgets.style import MINUS, monospace_font

#: How often the log view takes in what arrived: fast enough to feel live, slow
#: enough that a 1 kHz stream costs ten redraws a second.
REDRAW_MS = 100
#: Lines the view keeps; the log itself keeps :data:`LOG_CAPACITY` entries (saved in full).
VIEW_LINES = 5_000

_ERROR_STYLE = "color: #c62828;"
_NOTE_STYLE = "color: #6a6a6a;"


@contextmanager
def _quiet(*widgets: QWidget) -> Iterator[None]:
    """Set widgets from the model without their change signals writing it back."""
    for widget in widgets:
        widget.blockSignals(True)
    try:
        yield
    finally:
        for widget in widgets:
            widget.blockSignals(False)


def _end_switch_button(
    texts: Texts, controls: EmulatorControls, index: int, name: str, which: SwitchName
) -> QPushButton:
    """A button closing an emulated axis' low or high end switch where the axis stands.

    The stage's box and the usb3 unit's joystick box have the same ones; the
    texts are the emulator box's.
    """
    translate = QCoreApplication.translate
    if which == END_SWITCHES[0]:
        button = texts.button(
            lambda: translate("EmulatorBox", "{0} end switch").format(
                translate("EmulatorBox", "Low")
            ),
            lambda: translate(
                "EmulatorBox", "Close {0}'s low end switch where the axis is now"
            ).format(name),
        )
    else:
        button = texts.button(
            lambda: translate("EmulatorBox", "{0} end switch").format(
                translate("EmulatorBox", "High")
            ),
            lambda: translate(
                "EmulatorBox", "Close {0}'s high end switch where the axis is now"
            ).format(name),
        )
    button.clicked.connect(lambda _=False: controls.press_end_switch(index, which))
    return button


class EchoComposer(QGroupBox):
    """Compose an echo field by field and inject it as if the device had sent it."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Inject echo"))
        self._station = station
        self.type_combos: list[QComboBox] = []
        self.status_combos: list[QComboBox] = []
        self.data_edits: list[QLineEdit] = []

        grid = QGridLayout()
        grid.setHorizontalSpacing(6)
        # The wire's field names (TYPE, STATUS, DATA), said in the operator's language.
        headings = (
            lambda: self.tr("type"),
            lambda: self.tr("status"),
            lambda: self.tr("value"),
        )
        for column, heading in enumerate(headings, start=1):
            label = QLabel()
            t.set(label.setText, lambda h=heading: f"<small>{h()}</small>")
            grid.addWidget(label, 0, column)
        for row, axis in enumerate(station.model.axes, start=1):
            grid.addWidget(QLabel(f"<b>{axis.name}</b>"), row, 0)
            grid.addWidget(self._add_combo(self.type_combos, TYPE_TEXT, type_text), row, 1)
            grid.addWidget(self._add_combo(self.status_combos, STATUS_TEXT, status_text), row, 2)
            edit = self._add_data_edit(self.data_edits, "")
            t.set(edit.setPlaceholderText, lambda: self.tr("µm, µm/s or value"))
            grid.addWidget(edit, row, 3)
        ss_row = len(station.model.axes) + 1
        self.subscriber_combo = QComboBox()
        self.subscriber_combo.setEditable(True)  # any ID 00…FF, to try unknown ones
        t.set(
            self.subscriber_combo.setToolTip,
            lambda: self.tr("Subscriber ID: pick one, or type any hex ID 00…FF"),
        )
        for index, code in enumerate(SUBSCRIBER_TEXT):
            self.subscriber_combo.addItem("", code)
            t.item(self.subscriber_combo, index, lambda c=code: f"{c:02X} {subscriber_text(c)}")
        self.subscriber_data = self._add_data_edit([], "")
        t.set(self.subscriber_data.setPlaceholderText, lambda: self.tr("subscriber value"))
        grid.addWidget(QLabel("<b>SS</b>"), ss_row, 0)
        grid.addWidget(self.subscriber_combo, ss_row, 1, 1, 2)
        grid.addWidget(self.subscriber_data, ss_row, 3)
        grid.setColumnStretch(1, 1)
        grid.setColumnStretch(2, 1)

        self.inject_button = t.button(
            lambda: self.tr("Inject"),
            lambda: self.tr("Fold this echo into the model as if the device had sent it"),
        )
        self.inject_button.clicked.connect(self.inject)
        self.result_label = QLabel()
        self.result_label.setWordWrap(True)
        self.result_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        buttons = QHBoxLayout()
        buttons.addWidget(self.inject_button)
        buttons.addWidget(self.result_label, 1)

        layout = QVBoxLayout(self)
        layout.addLayout(grid)
        layout.addLayout(buttons)

    def _add_combo(
        self, into: list[QComboBox], names: dict[int, str], words: Callable[[int], str]
    ) -> QComboBox:
        combo = QComboBox()
        for index, code in enumerate(names):
            combo.addItem("", code)
            # The hex digit first, as on the wire; the words in the operator's language.
            self.texts.item(combo, index, lambda c=code: f"{c:X} {words(c)}")
        combo.setSizeAdjustPolicy(QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon)
        combo.setMinimumContentsLength(10)
        into.append(combo)
        return combo

    def _add_data_edit(self, into: list[QLineEdit], tip: str) -> QLineEdit:
        # No validator on purpose: a malformed value gets a message that says why,
        # instead of keys that silently do nothing.
        edit = QLineEdit("0")
        self.texts.set(
            edit.setToolTip,
            lambda: self.tr("A whole number, {0}").format(f"{MINUS}99999…999999"),
        )
        edit.setMaximumWidth(90)
        edit.returnPressed.connect(self.inject)
        into.append(edit)
        return edit

    def fields(self) -> EchoFields:
        axes = [
            AxisFields(int(t.currentData()), int(s.currentData()), d.text())
            for t, s, d in zip(self.type_combos, self.status_combos, self.data_edits, strict=True)
        ]
        return EchoFields(axes, self.subscriber_combo.currentText(), self.subscriber_data.text())

    def inject(self) -> None:
        """Inject the composed echo, or say which field is wrong (then nothing is injected)."""
        try:
            echo = inject_echo(self._station, self.fields())
        except InjectError as error:
            self.result_label.setStyleSheet(_ERROR_STYLE)
            self.result_label.setText(error.message)
            return
        self.result_label.setStyleSheet(_NOTE_STYLE)
        self.result_label.setText(self.tr("Injected {0}").format(raw_echo_text(echo)))


class EmulatorBox(QGroupBox):
    """The built-in emulator's environment and faults; disabled while there is none."""

    def __init__(self, controls: EmulatorControls, axis_names: list[str]) -> None:
        super().__init__()
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Emulator"))
        self._controls = controls
        self.note = t.label(
            lambda: self.tr(
                "No emulator connected: these controls act on the built-in emulator. "
                "Turn Simulation on, or connect it on the Link page."
            )
        )
        self.note.setWordWrap(True)
        self.note.setStyleSheet(_NOTE_STYLE)
        self.body = QWidget()

        self.charger = QCheckBox()
        t.set(self.charger.setText, lambda: self.tr("Charger connected"))
        self.usb = QCheckBox()
        t.set(self.usb.setText, lambda: self.tr("USB connected"))
        self.verification_fault = QCheckBox()
        t.set(
            self.verification_fault.setText,
            lambda: self.tr("FRAM verification fault (writes refused)"),
        )
        self.charger.toggled.connect(controls.set_charger)
        self.usb.toggled.connect(controls.set_usb)
        self.verification_fault.toggled.connect(controls.set_verification_fault)

        form = self._build_fields(t, controls)
        axes = self._build_axes(t, controls, axis_names)
        link = self._build_link(t, controls)
        # The fields' own note (what is wrong with a value typed), under them; ``note``
        # above is the box's "no emulator" line.
        self.field_note = QLabel()
        self.gate = FieldGate(self.field_note, self)
        self.gate.watch(self.battery, lambda: self.tr("Battery"))
        self.gate.watch(self.temperature, lambda: self.tr("Temperature"))
        self.gate.watch(self.rotation, lambda: self.tr("Rotation rate"))
        self.gate.watch(self.corrupt_count, lambda: self.tr("Corrupt"))
        self.gate.bind(self.corrupt_button, self.corrupt_count)

        body = QVBoxLayout(self.body)
        body.setContentsMargins(0, 0, 0, 0)
        for box in (self.charger, self.usb, self.verification_fault):
            body.addWidget(box)
        body.addLayout(form)
        body.addLayout(axes)
        body.addLayout(link)
        body.addWidget(self.field_note)
        layout = QVBoxLayout(self)
        layout.addWidget(self.note)
        layout.addWidget(self.body)

        controls.availabilityChanged.connect(self.sync)
        self.sync()

    def _build_fields(self, t: Texts, controls: EmulatorControls) -> QFormLayout:
        """The battery, the temperature and the rotation rate."""
        # Applied on Enter, focus out or an arrow step (committed), not at every keystroke
        # of "12.5"; a value outside the range stays red and is not applied.
        self.battery = NumberField(
            0,
            100,
            decimals=0,
            unit="%",
        )
        t.set(
            self.battery.set_description,
            lambda: self.tr("State of charge; below 5 % the stage blocks motion"),
        )
        self.temperature = NumberField(-40.0, 125.0, decimals=2, unit="°C")
        t.set(self.temperature.set_description, lambda: self.tr("Board temperature"))
        self.rotation = NumberField(-720.0, 720.0, decimals=2, unit="°/s")
        t.set(
            self.rotation.set_description,
            lambda: self.tr("Platform rotation rate; the IMU's yaw integrates it"),
        )
        self.battery.committed.connect(lambda value: controls.set_battery(round(value)))
        self.temperature.committed.connect(controls.set_temperature)
        self.rotation.committed.connect(controls.set_rotation_rate)
        form = QFormLayout()
        form.setFieldGrowthPolicy(QFormLayout.FieldGrowthPolicy.FieldsStayAtSizeHint)
        form.addRow(t.label(lambda: self.tr("Battery")), self.battery)
        form.addRow(t.label(lambda: self.tr("Temperature")), self.temperature)
        form.addRow(t.label(lambda: self.tr("Rotation rate")), self.rotation)
        return form

    def _build_axes(
        self, t: Texts, controls: EmulatorControls, axis_names: list[str]
    ) -> QGridLayout:
        """Per axis: its end switches to close, and a driver fault."""
        self.switch_buttons: dict[tuple[int, str], QPushButton] = {}
        self.driver_faults: list[QCheckBox] = []
        axes = QGridLayout()
        for index, name in enumerate(axis_names):
            axes.addWidget(QLabel(f"<b>{name}</b>"), index, 0)
            for column, which in enumerate(END_SWITCHES, start=1):
                button = _end_switch_button(t, controls, index, name, which)
                self.switch_buttons[(index, which)] = button
                axes.addWidget(button, index, column)
            fault = QCheckBox()
            t.set(fault.setText, lambda: self.tr("Driver fault"))
            t.set(
                fault.setToolTip,
                lambda n=name: self.tr(
                    "Over-temperature or stall on {0}'s driver: the axis stops dead"
                ).format(n),
            )
            fault.toggled.connect(lambda on, a=index: controls.set_driver_fault(a, on))
            self.driver_faults.append(fault)
            axes.addWidget(fault, index, 3)
        return axes

    def _build_link(self, t: Texts, controls: EmulatorControls) -> QHBoxLayout:
        """Drop the link; corrupt the next frames."""
        self.drop_button = t.button(
            lambda: self.tr("Drop link"),
            lambda: self.tr("Cut the emulated cable; the station reconnects with back-off"),
        )
        self.drop_button.clicked.connect(controls.drop_link)
        self.corrupt_count = NumberField(
            1, 999, decimals=0, unit="frames", value=3, name="corrupt_count"
        )
        self.corrupt_button = t.button(
            lambda: self.tr("Corrupt"),
            lambda: self.tr("Flip a byte in each of the next frames from the device"),
        )
        self.corrupt_button.clicked.connect(self._corrupt)
        link = QHBoxLayout()
        link.addWidget(self.drop_button)
        link.addSpacing(12)
        link.addWidget(self.corrupt_button)
        link.addWidget(self.corrupt_count)
        link.addStretch(1)
        return link

    def sync(self, *_args: object) -> None:
        """Show the emulator's present state, or disable everything when there is none."""
        state = self._controls.state()
        self.note.setVisible(state is None)
        self.body.setEnabled(state is not None)
        if state is None:
            return
        checks = (self.charger, self.usb, self.verification_fault, *self.driver_faults)
        with _quiet(*checks, self.battery, self.temperature, self.rotation):
            self.charger.setChecked(state.charger)
            self.usb.setChecked(state.usb)
            self.verification_fault.setChecked(state.verification_fault)
            for box, fault in zip(self.driver_faults, state.driver_faults, strict=True):
                box.setChecked(fault)
            self.battery.setValue(round(state.battery_percent))
            self.temperature.setValue(state.temperature_c)
            self.rotation.setValue(state.rotation_dps)

    def _corrupt(self) -> None:
        count = self.corrupt_count.value()
        if count is None:
            self.gate.refusal(self.corrupt_count)
            return
        self._controls.corrupt_next(round(count))


JOYSTICK_CENTRE = 512


class JoystickBox(QGroupBox):
    """The usb3 unit's joystick as three sliders that spring back to the centre like the stick."""

    def __init__(self, controls: EmulatorControls, axis_names: list[str]) -> None:
        super().__init__()
        self.texts = Texts(self)
        self.texts.set(self.setTitle, lambda: self.tr("Joystick (usb3 unit)"))
        self._controls = controls
        self.sliders: list[QSlider] = []
        #: The unit's end switches (FIDELITY S4-18), closed where the axis is now.
        self.switch_buttons: dict[tuple[int, str], QPushButton] = {}
        grid = QGridLayout(self)
        for index, name in enumerate(axis_names):
            slider = QSlider(Qt.Orientation.Horizontal)
            slider.setRange(0, 1023)
            slider.setValue(JOYSTICK_CENTRE)
            self.texts.set(
                slider.setToolTip,
                lambda n=name: self.tr(
                    "{0} stick: 500…524 is the dead zone; let go to centre it"
                ).format(n),
            )
            slider.valueChanged.connect(lambda value, a=index: controls.set_joystick(a, value))
            slider.sliderReleased.connect(lambda s=slider: s.setValue(JOYSTICK_CENTRE))
            grid.addWidget(QLabel(name), index, 0)
            grid.addWidget(slider, index, 1)
            self.sliders.append(slider)
            for column, which in enumerate(END_SWITCHES, start=2):
                button = _end_switch_button(self.texts, controls, index, name, which)
                self.switch_buttons[(index, which)] = button
                grid.addWidget(button, index, column)
        controls.availabilityChanged.connect(self.setEnabled)
        self.setEnabled(controls.available)


class FrameLogView(QWidget):
    """The TX/RX log: filter, Pause, Clear, Save…, and a view redrawn in batches."""

    def __init__(self, log: FrameLog, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._log = log
        self._shown_seq = log.last_seq
        self._rebuild_due = True

        t = self.texts = Texts(self)
        self.filter_edit = QLineEdit()
        t.set(
            self.filter_edit.setPlaceholderText,
            lambda: self.tr("Filter: words that must all occur, e.g. rx charger"),
        )
        self.filter_edit.setClearButtonEnabled(True)
        self.filter_edit.textChanged.connect(self._request_rebuild)
        self.pause_button = QPushButton(self.tr("Pause"))
        self.pause_button.setCheckable(True)
        t.set(
            self.pause_button.setToolTip,
            lambda: self.tr("Freeze the view; frames are still recorded and appear on Resume"),
        )
        self.pause_button.toggled.connect(log.set_paused)
        self.clear_button = t.button(lambda: self.tr("Clear"))
        self.clear_button.clicked.connect(log.clear)
        self.save_button = t.button(
            lambda: self.tr("Save…"),
            lambda: self.tr("Save the entries that pass the filter (all when empty)"),
        )
        self.save_button.clicked.connect(self.save)
        bar = QHBoxLayout()
        bar.addWidget(self.filter_edit, 1)
        for button in (self.pause_button, self.clear_button, self.save_button):
            bar.addWidget(button)

        self.view = QPlainTextEdit()
        self.view.setReadOnly(True)
        self.view.setLineWrapMode(QPlainTextEdit.LineWrapMode.NoWrap)
        self.view.setMaximumBlockCount(VIEW_LINES)
        self.view.setFont(monospace_font())
        t.set(
            self.view.setPlaceholderText,
            lambda: self.tr("Frames sent (TX), received (RX), injected (INJ), rejected (BAD)"),
        )
        self.status_label = QLabel()
        self.status_label.setStyleSheet(_NOTE_STYLE)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addLayout(bar)
        layout.addWidget(self.view, 1)
        layout.addWidget(self.status_label)

        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(REDRAW_MS)
        self._timer.timeout.connect(self.flush)
        log.entriesAdded.connect(self._schedule)
        log.cleared.connect(self._on_cleared)
        log.pausedChanged.connect(self._on_paused)
        self._schedule()
        t.also(lambda: self._on_paused(self._log.paused))

    @property
    def text(self) -> str:
        return self.view.toPlainText()

    def _schedule(self) -> None:
        if not self._timer.isActive():
            self._timer.start()

    def _request_rebuild(self) -> None:
        self._rebuild_due = True
        self._schedule()

    def flush(self) -> None:
        """Take in what the log recorded since the last redraw (the timer calls this).

        While paused only a new filter is applied (to what was shown when the
        pause began) and the count of held entries refreshed.
        """
        if not self.isVisible():
            return
        if self._rebuild_due:
            self._rebuild()
        elif not self._log.paused:
            self._append_new()
        self._show_status()
        if self._log.paused:
            self._timer.start()  # the log holds its signal while paused: keep the count live

    def _rebuild(self) -> None:
        self._rebuild_due = False
        chosen = self._log.filtered(self.filter_edit.text())
        if self._log.paused:
            chosen = [entry for entry in chosen if entry.seq <= self._shown_seq]
        else:
            self._shown_seq = self._log.last_seq
        self.view.setPlainText("\n".join(entry.line for entry in chosen[-VIEW_LINES:]))
        self.view.verticalScrollBar().setValue(self.view.verticalScrollBar().maximum())

    def _append_new(self) -> None:
        new = self._log.entries_since(self._shown_seq)
        if not new:
            return
        lines = []
        lost = new[0].seq - self._shown_seq - 1
        if lost > 0:
            kept = self._log.capacity
            lines.append(
                self.tr("… %n entries not shown: the log keeps the last {0}", "", lost).format(kept)
            )
        self._shown_seq = new[-1].seq
        lines += [entry.line for entry in self._log.filtered(self.filter_edit.text(), new)]
        if lines:
            self.view.appendPlainText("\n".join(lines))

    def _on_cleared(self) -> None:
        self.view.clear()
        self._shown_seq = self._log.last_seq
        self._show_status()

    def _on_paused(self, paused: bool) -> None:
        self.pause_button.setChecked(paused)
        self.pause_button.setText(self.tr("Resume") if paused else self.tr("Pause"))
        self._show_status()
        self._schedule()

    def _show_status(self) -> None:
        text = self.tr("%n entries", "", len(self._log))
        if self._log.paused:
            waiting = self._log.last_seq - self._shown_seq
            text += self.tr(" — paused, %n new not shown", "", waiting)
        self.status_label.setText(text)

    def save(self) -> None:
        """Ask where, then write the entries that pass the filter (all when it is empty)."""
        path, _ = QFileDialog.getSaveFileName(
            self,
            self.tr("Save frame log"),
            "stepdeck-frames.log",
            self.tr("Log files (*.log *.txt);;All files (*)"),
        )
        if not path:
            return
        try:
            count = self._log.save(path, self.filter_edit.text())
        except OSError as error:
            self.status_label.setText(
                self.tr("Could not save: {0}").format(error.strerror or error)
            )
            return
        self.status_label.setText(self.tr("Saved %n entries to {0}", "", count).format(path))

    def showEvent(self, event: QShowEvent) -> None:
        # Hidden, the view skipped its redraws; shown again, it starts from the log.
        self._request_rebuild()
        super().showEvent(event)


class DeveloperPane(QDockWidget):
    """Echo composer, simulation switch, emulator controls and the frame log, in one dock.

    The main window adds it and gives its ``toggleViewAction()`` the Shift+V
    shortcut; the pane itself owns no window-wide keys.
    """

    def __init__(
        self,
        station: Station,
        parent: QWidget | None = None,
        *,
        log_capacity: int = LOG_CAPACITY,
        frame_log: FrameLog | None = None,
    ) -> None:
        """``frame_log``: one already recording (the window keeps one from its start, and
        builds the pane when first shown); by default the pane starts its own."""
        super().__init__(parent)
        t = self.texts = Texts(self)
        t.set(self.setWindowTitle, lambda: self.tr("Developer"))
        self.setObjectName("developer_pane")  # for QMainWindow.saveState
        if frame_log is None:
            frame_log = FrameLog(station, log_capacity, parent=self)
        self.frame_log = frame_log
        self.emulator_controls = EmulatorControls(station, self)

        self.simulation = QCheckBox()
        t.set(
            self.simulation.setText,
            lambda: self.tr("Simulation: the built-in emulator answers the commands"),
        )
        t.set(
            self.simulation.setToolTip,
            lambda: self.tr(
                "On: connect the emulated stage (when no device is connected). Off: disconnect it."
            ),
        )
        self.simulation.toggled.connect(self._set_simulation)
        self.simulation_note = QLabel()
        self.simulation_note.setWordWrap(True)
        self.simulation_note.setStyleSheet(_ERROR_STYLE)
        self.simulation_note.hide()
        axis_names = [axis.name for axis in station.model.axes]
        # The echo composer and the stage's environment only mean something on a stage;
        # the usb3 unit's developer controls are its joystick (widgets.dialects says which).
        self.composer = EchoComposer(station)
        self.emulator_box = EmulatorBox(self.emulator_controls, axis_names)
        self.joystick_box = JoystickBox(self.emulator_controls, axis_names)
        self.reply_box = GcodeReplyBox(station)
        self.board_box = GcodeEmulatorBox(station)
        shown = window_dialect(station.profile).developer_boxes
        boxes: dict[DeveloperBox, QWidget] = {
            DeveloperBox.ECHO_COMPOSER: self.composer,
            DeveloperBox.STAGE_EMULATOR: self.emulator_box,
            DeveloperBox.JOYSTICK: self.joystick_box,
            DeveloperBox.GCODE_REPLIES: self.reply_box,
            DeveloperBox.GCODE_BOARD: self.board_box,
        }
        for box, widget in boxes.items():
            if box not in shown:
                # Only hidden: shown before the pane holds it, a box flashed up as a window
                # of its own and took the keyboard from the main window.
                widget.hide()
        self.log_view = FrameLogView(self.frame_log)

        self.setWidget(self._build(self._controls_column()))
        self.emulator_controls.availabilityChanged.connect(self._show_simulation)
        self.emulator_controls.availabilityChanged.connect(self.board_box.sync)
        self._show_simulation()
        self.board_box.sync()

    def _controls_column(self) -> QScrollArea:
        column = QWidget()
        layout = QVBoxLayout(column)
        layout.setContentsMargins(0, 0, 6, 0)
        layout.addWidget(self.simulation)
        layout.addWidget(self.simulation_note)
        layout.addWidget(self.composer)
        layout.addWidget(self.emulator_box)
        layout.addWidget(self.joystick_box)
        layout.addWidget(self.reply_box)
        layout.addWidget(self.board_box)
        layout.addStretch(1)
        scroll = QScrollArea()
        scroll.setWidget(column)
        scroll.setWidgetResizable(True)
        scroll.setFrameShape(QFrame.Shape.NoFrame)
        scroll.setHorizontalScrollBarPolicy(Qt.ScrollBarPolicy.ScrollBarAlwaysOff)
        # Its least width, not its preferred: the pane must fit under the pages beside the
        # jobs dock on a 1280 px screen; the splitter gives the column more where there is room.
        scroll.setMinimumWidth(column.minimumSizeHint().width() + 12)
        scroll.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Expanding)
        return scroll

    def _build(self, controls: QScrollArea) -> QWidget:
        splitter = QSplitter(Qt.Orientation.Horizontal)
        splitter.addWidget(controls)
        splitter.addWidget(self.log_view)
        splitter.setStretchFactor(0, 0)
        splitter.setStretchFactor(1, 1)
        splitter.setChildrenCollapsible(False)
        # The controls at their least width to begin with, the log the rest: under the pages
        # beside the jobs dock the log had only what its toolbar needs.
        splitter.setSizes([controls.minimumWidth(), 10 * controls.minimumWidth()])
        content = QWidget()
        layout = QVBoxLayout(content)
        layout.setContentsMargins(6, 4, 6, 4)
        layout.addWidget(splitter)
        return content

    def _set_simulation(self, on: bool) -> None:
        try:
            self.emulator_controls.set_simulation(on)
        except SimulationRefused as refused:
            self.simulation_note.setText(self.tr("Simulation refused: {0}").format(refused))

            self.simulation_note.show()
        else:
            self.simulation_note.hide()
        self._show_simulation()

    def _show_simulation(self, *_args: object) -> None:
        self.simulation.blockSignals(True)
        self.simulation.setChecked(self.emulator_controls.simulating)
        self.simulation.blockSignals(False)
