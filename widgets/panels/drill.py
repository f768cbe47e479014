"""The PCB drill's page, as its Visual Basic tool had it.

Command buttons for the procedures that take no value (N V K Z P), X and Y
each with a target in microsteps and a send button, a terminal (a line
entry with Send and Clear, the lines sent kept in a history walked with
Up/Down, the device's replies shown), and the tool's two columns: "command
received" and "command done", filled as the device says ``R`` and ``D``.

The drill has no stop command: once a procedure starts it runs to its end.
So an X or Y move expected to take longer than :data:`LONG_MOVE_S` (from the
button or the terminal) is not sent at once; the page says how long it will
run unstoppable and sends it only on "Send anyway".
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication
from PySide6.QtWidgets import (
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QPlainTextEdit,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.machines.drill.session import DrillSession
from app.station import Station
from widgets.history_entry import HistoryLineEdit
from widgets.number_field import FieldGate, NumberField, localized
from widgets.panels.drill_conversion import DrillConversionBox
from widgets.panels.drill_step import DrillStepBox
from widgets.panels.drill_timing import DrillTimingBox
from widgets.retranslate import Texts, bold
from widgets.style import compact, monospace_font
from widgets.units import shown_unit

#: A move expected to run longer than this (seconds) asks first: it cannot be stopped.
LONG_MOVE_S = 2.0

#: Buttons of the procedures that take no value: letter, caption, tooltip.
COMMAND_BUTTONS = (
    (
        "N",
        QT_TRANSLATE_NOOP("DrillPanel", "N  home"),
        QT_TRANSLATE_NOOP("DrillPanel", "Home X then Y to the switches and the zero offsets"),
    ),
    (
        "V",
        QT_TRANSLATE_NOOP("DrillPanel", "V  drill"),
        QT_TRANSLATE_NOOP("DrillPanel", "Drill one hole where the head stands"),
    ),
    (
        "K",
        QT_TRANSLATE_NOOP("DrillPanel", "K  pen down"),
        QT_TRANSLATE_NOOP("DrillPanel", "Lower the pen"),
    ),
    (
        "Z",
        QT_TRANSLATE_NOOP("DrillPanel", "Z  pen up"),
        QT_TRANSLATE_NOOP("DrillPanel", "Raise the pen"),
    ),
    (
        "P",
        QT_TRANSLATE_NOOP("DrillPanel", "P  park"),
        QT_TRANSLATE_NOOP("DrillPanel", "Park at the back and switch the motors off"),
    ),
)


# Command buttons to a row (the Timing… toggle takes the last cell).
COMMAND_COLUMNS = 3


def _tr(text: str) -> str:
    """A text marked with QT_TRANSLATE_NOOP above, in the current language."""
    return QCoreApplication.translate("DrillPanel", text)


class DrillPanel(QWidget):
    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._watched: DrillSession | None = None
        self.command_buttons: dict[str, QPushButton] = {}
        self.targets: list[NumberField] = []
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self._pending_line: str | None = None
        self._mm_labels: list[QLabel] = []
        self.send_buttons: list[QPushButton] = []
        self._pending_s = 0.0
        t = self.texts = Texts(self)

        commands = self._build_commands(t, station)
        axes = self._build_targets(t, station)

        # Shown instead of sending a long move: it cannot be stopped once it runs.
        self.long_move = QGroupBox()
        self.long_move.setObjectName("long_move_warning")
        self.long_move.setStyleSheet(
            "QGroupBox#long_move_warning { background: #fff3cd; border: 1px solid #e0c060; }"
            " QGroupBox#long_move_warning QLabel { color: #1d1d1d; }"
        )
        self.long_move_label = QLabel()
        self.long_move_label.setWordWrap(True)
        self.long_move_send = t.button(lambda: self.tr("Send anyway"))
        self.long_move_send.clicked.connect(self.confirm_long_move)
        self.long_move_cancel = t.button(lambda: self.tr("Cancel"))
        self.long_move_cancel.clicked.connect(self.cancel_long_move)
        warning_row = QHBoxLayout(self.long_move)
        warning_row.addWidget(self.long_move_label, 1)
        warning_row.addWidget(self.long_move_send)
        warning_row.addWidget(self.long_move_cancel)
        self.long_move.hide()

        lower = self._build_terminal(t)
        layout = QVBoxLayout(self)
        layout.addWidget(commands)
        layout.addWidget(axes)
        layout.addWidget(self.timing_box)
        layout.addWidget(self.conversion_box)
        layout.addWidget(self.step_box)
        layout.addWidget(self.long_move)
        layout.addLayout(lower, 1)

        self._show_every_mm()
        station.sessionChanged.connect(self._watch_session)
        self._watch_session()
        t.also(self._show_long_move)
        t.also(self._show_every_mm)

    def _build_commands(self, t: Texts, station: Station) -> QGroupBox:
        """The command buttons, and the toggles of the boxes folded away until asked for."""
        commands = t.group(lambda: self.tr("Commands"))
        # Two rows of three: in one row (even with each button as wide as its caption) the
        # commands made the page, beside the jobs dock, wider than a 1280 px screen.
        row = QGridLayout(commands)
        for index, (letter, caption, tip) in enumerate(COMMAND_BUTTONS):
            button = t.button(lambda c=caption: _tr(c), lambda tp=tip, c=letter: f"{_tr(tp)} ({c})")
            button.setObjectName(f"command_{letter}")
            button.clicked.connect(lambda _=False, c=letter: self.send_command(c))
            row.addWidget(compact(button), index // COMMAND_COLUMNS, index % COMMAND_COLUMNS)
            self.command_buttons[letter] = button

        # The timing constants (FIDELITY S2-06), folded away until asked for.
        self.timing_box = DrillTimingBox(station, station.profile.drill_timing)
        self.timing_box.hide()
        self.timing_toggle = t.button(
            lambda: self.tr("Timing…"),
            lambda: self.tr("Show the drill's timing constants, to change them"),
        )
        self.timing_toggle.setObjectName("timing_toggle")
        self.timing_toggle.setCheckable(True)
        self.timing_toggle.toggled.connect(self.timing_box.setVisible)
        last = len(COMMAND_BUTTONS)
        row.addWidget(compact(self.timing_toggle), last // COMMAND_COLUMNS, last % COMMAND_COLUMNS)
        # VRTACKA's step-through (FIDELITY S2-41), folded away until asked for.
        self.step_box = DrillStepBox(station)
        self.step_box.hide()
        self.step_toggle = t.button(
            lambda: self.tr("Step through…"),
            lambda: self.tr("Walk the loaded job line by line and send its procedures by hand"),
        )
        self.step_toggle.setObjectName("step_toggle")
        self.step_toggle.setCheckable(True)
        self.step_toggle.toggled.connect(self.step_box.setVisible)
        last += 1
        row.addWidget(compact(self.step_toggle), last // COMMAND_COLUMNS, last % COMMAND_COLUMNS)
        # The conversion constants (FIDELITY S2-42), folded away until asked for.
        self.conversion_box = DrillConversionBox(station)
        self.conversion_box.hide()
        self.conversion_toggle = t.button(
            lambda: self.tr("Constants…"),
            lambda: self.tr("Show the Excellon step and microsteps a mm, to change them"),
        )
        self.conversion_toggle.setObjectName("conversion_toggle")
        self.conversion_toggle.setCheckable(True)
        self.conversion_toggle.toggled.connect(self.conversion_box.setVisible)
        last += 1
        row.addWidget(
            compact(self.conversion_toggle), last // COMMAND_COLUMNS, last % COMMAND_COLUMNS
        )
        row.setColumnStretch(COMMAND_COLUMNS, 1)
        return commands

    def _build_targets(self, t: Texts, station: Station) -> QGroupBox:
        """Per axis: a target in microsteps, what it is in mm, and Send."""
        axes = t.group(lambda: self.tr("Move to (microsteps from zero)"))
        grid = QGridLayout(axes)
        for index, axis in enumerate(station.profile.axes):
            per_mm = axis.steps_per_rev * axis.microsteps / axis.lead
            target = NumberField(
                0,
                round(axis.travel * per_mm),
                decimals=0,
                unit="µsteps",
                name=f"target_{axis.name}",
            )
            t.set(
                target.set_description,
                lambda a=axis.name, p=per_mm: self.tr("{0} target; {1} microsteps a mm").format(
                    a, localized(f"{p:g}")
                ),
            )
            target.textChanged.connect(lambda _t="", i=index: self._show_mm(i))
            mm = QLabel()
            mm.setFont(monospace_font())
            send = t.button(lambda a=axis.name: self.tr("Send {0}").format(a))
            send.clicked.connect(lambda _=False, i=index: self.send_axis(i))
            for column, widget in enumerate((QLabel(axis.name), target, mm, send)):
                grid.addWidget(widget, index, column)
            self.targets.append(target)
            self._mm_labels.append(mm)
            self.send_buttons.append(send)
            self.gate.watch(target, lambda a=axis.name: self.tr("{0} target").format(a))
            self.gate.bind(send, target)
        grid.addWidget(self.note, len(self.targets), 0, 1, 4)
        return axes

    def _build_terminal(self, t: Texts) -> QHBoxLayout:
        """The terminal (output, entry, Send, Clear) beside the received and done columns."""
        terminal = t.group(lambda: self.tr("Terminal"))
        box = QVBoxLayout(terminal)
        self.output = QPlainTextEdit()
        self.output.setReadOnly(True)
        self.output.setFont(monospace_font())
        self.output.setMaximumBlockCount(2000)
        self.entry = HistoryLineEdit()
        self.entry.setObjectName("terminal_entry")
        self.entry.setPlaceholderText("N, X1234, Y567, V, K, Z, P")
        self.entry.setMinimumWidth(80)  # the page must fit beside the jobs dock on 1280 px
        self.entry.returnPressed.connect(self.send_line)
        self.send_button = t.button(lambda: self.tr("Send"))
        self.send_button.clicked.connect(self.send_line)
        self.clear_button = t.button(
            lambda: self.tr("Clear"), lambda: self.tr("Clear the terminal and the columns")
        )
        self.clear_button.clicked.connect(self.clear)
        line = QHBoxLayout()
        line.addWidget(self.entry, 1)
        line.addWidget(self.send_button)
        line.addWidget(self.clear_button)
        box.addWidget(self.output, 1)
        box.addLayout(line)

        self.received_list = QListWidget()
        self.received_list.setObjectName("command_received")
        self.done_list = QListWidget()
        self.done_list.setObjectName("command_done")
        for listing in (self.received_list, self.done_list):
            # Commands are a few characters: narrow columns leave the terminal its width.
            listing.setMaximumWidth(150)
            listing.setFont(monospace_font())
        columns = QGridLayout()
        titles = (lambda: bold(self.tr("command received")), lambda: bold(self.tr("command done")))
        for column, title in enumerate(titles):
            header = t.label(title)
            header.setWordWrap(True)  # two short lines rather than a page too wide
            columns.addWidget(header, 0, column)
        columns.addWidget(self.received_list, 1, 0)
        columns.addWidget(self.done_list, 1, 1)

        lower = QHBoxLayout()
        lower.addWidget(terminal, 2)
        lower.addLayout(columns, 1)
        return lower

    @property
    def session(self) -> DrillSession | None:
        return self._station.session_as(DrillSession)

    # --- what the buttons do -----------------------------------------------------

    def send_command(self, letter: str) -> bool:
        session = self.session
        if session is None:
            return False
        return session.send_line(letter)

    def send_axis(self, axis: int) -> bool:
        """Send the axis to its target; a long move waits for "Send anyway" (False then)."""
        session = self.session
        if session is None:
            return False
        target = self.targets[axis].value()
        if target is None:
            self.gate.refusal(self.targets[axis])
            return False
        name = self._station.profile.axes[axis].name
        return self._send_or_ask(f"{name}{round(target)}")

    def send_line(self) -> bool:
        text = self.entry.take()
        if not text:
            return False
        if self.session is None:
            self.output.appendPlainText(self.tr("! {0}: not sent").format(text))
            return False
        return self._send_or_ask(text)

    def long_move_s(self, text: str) -> float:
        """How long the X or Y move ``text`` is expected to run (0 for anything else)."""
        session = self.session
        return 0.0 if session is None else session.line_expected_s(text)

    def _send_or_ask(self, text: str) -> bool:
        seconds = self.long_move_s(text)
        if seconds <= LONG_MOVE_S:
            return self._send_now(text)
        self._pending_line = text.strip()
        self._pending_s = seconds
        self._show_long_move()
        self.long_move.show()
        self.long_move_send.setFocus()
        return False

    def _show_long_move(self) -> None:
        if self._pending_line is None:
            return
        self.long_move_label.setText(
            self.tr(
                "<b>{0}</b> runs about {1} s, and the drill has no "
                "stop command: once it starts, STOP and Esc only drop what is queued after it. "
                "Send it?"
            ).format(self._pending_line, f"{self._pending_s:.0f}")
        )

    def confirm_long_move(self) -> bool:
        """Send anyway: the operator has read that the move cannot be stopped."""
        text, self._pending_line = self._pending_line, None
        self.long_move.hide()
        return text is not None and self._send_now(text)

    def cancel_long_move(self) -> None:
        self._pending_line = None
        self.long_move.hide()

    def _send_now(self, text: str) -> bool:
        session = self.session
        sent = session is not None and session.send_line(text)
        if not sent:
            self.output.appendPlainText(self.tr("! {0}: not sent").format(text))
        return sent

    def clear(self) -> None:
        self.output.clear()
        self.received_list.clear()
        self.done_list.clear()

    @property
    def history(self) -> tuple[str, ...]:
        return self.entry.history

    def set_motion_enabled(self, enabled: bool) -> None:
        for button in self.command_buttons.values():
            button.setEnabled(enabled)
        self.gate.set_enabled(enabled)
        self.long_move_send.setEnabled(enabled)
        self.step_box.set_motion_enabled(enabled)

    # --- the session's news ----------------------------------------------------------

    def _watch_session(self) -> None:
        session = self.session
        if session is self._watched:
            return
        self._watched = session
        if session is not None:
            # Bound methods, not lambdas: Qt drops a bound slot when the panel is destroyed,
            # while a lambda would keep calling into deleted list widgets.
            session.commandReceived.connect(self._show_received_command)
            session.commandDone.connect(self._show_done_command)
            session.terminalLine.connect(self.output.appendPlainText)
            session.commandFailed.connect(self._show_failed)

    def _show_received_command(self, text: str) -> None:
        _append(self.received_list, text)

    def _show_done_command(self, text: str) -> None:
        _append(self.done_list, text)

    def _show_failed(self, text: str) -> None:
        self.output.appendPlainText(
            self.tr("! {0} refused by the drill; queue cleared").format(text)
        )

    def _show_every_mm(self) -> None:
        for index in range(len(self.targets)):
            self._show_mm(index)

    def _show_mm(self, axis: int) -> None:
        label = self._mm_labels[axis]
        profile_axis = self._station.profile.axes[axis]
        per_mm = profile_axis.steps_per_rev * profile_axis.microsteps / profile_axis.lead
        target = self.targets[axis].value()
        if target is None:
            label.setText("—")
            return
        label.setText(localized(f"{target / per_mm:8.3f} {shown_unit(profile_axis.unit)}"))


COLUMN_ROWS = 1000


def _append(column: QListWidget, text: str) -> None:
    """Newest at the bottom and in view, like the original tool's lists; old rows drop off."""
    column.addItem(text)
    while column.count() > COLUMN_ROWS:
        column.takeItem(0)
    column.scrollToBottom()
