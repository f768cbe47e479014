"""The developer pane on a G-code machine: inject a reply, press the emulated board's buttons."""

from __future__ import annotations

from PySide6.QtWidgets import (
    QGridLayout,
    QGroupBox,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.developer.gcode import QUICK_REPLIES, GcodeEmulatorButtons, inject_reply
from app.machines.gcode.session import zeroes_by_hand
from app.station import Station
from widgets.history_entry import HistoryLineEdit
from widgets.number_field import FieldGate, NumberField
from widgets.retranslate import Texts
from widgets.style import MINUS, compact

_ERROR_STYLE = "color: #b00020;"


class GcodeReplyBox(QGroupBox):
    """Type what the device "says"; it reaches the session as the device's bytes would."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Inject a reply (as if the device sent it)"))
        self._station = station
        self.entry = HistoryLineEdit()
        self.entry.setObjectName("gcode_inject_entry")
        self.entry.setPlaceholderText("ok, error:9, ALARM:1, <Hold:0|MPos:1,2,0|FS:0,0>…")
        self.entry.returnPressed.connect(self.inject)
        self.inject_button = t.button(lambda: self.tr("Inject"))
        self.inject_button.clicked.connect(self.inject)
        self.error = QLabel()
        self.error.setStyleSheet(_ERROR_STYLE)
        self.error.setWordWrap(True)
        self.error.hide()
        row = QHBoxLayout()
        row.addWidget(self.entry, 1)
        row.addWidget(self.inject_button)
        quick = QHBoxLayout()
        self.quick_buttons: dict[str, QPushButton] = {}
        for caption, text in QUICK_REPLIES:
            button = QPushButton(caption)
            # The reply's name; the wire's own words (ok, ALARM:1, Hold) are not in the list.
            t.set(button.setText, lambda c=caption: self.tr(c))
            t.set(button.setToolTip, lambda r=text: self.tr("Inject {0}").format(repr(r)))
            button.clicked.connect(lambda _=False, t=text: self.inject_text(t))
            quick.addWidget(compact(button))
            self.quick_buttons[caption] = button
        layout = QVBoxLayout(self)
        layout.addLayout(row)
        layout.addLayout(quick)
        layout.addWidget(self.error)

    def inject(self) -> bool:
        return self.inject_text(self.entry.take())

    def inject_text(self, text: str) -> bool:
        try:
            inject_reply(self._station, text)
        except ValueError as exc:
            self.error.setText(self.tr("Not injected: {0}").format(exc))
            self.error.show()
            return False
        self.error.hide()
        return True


class GcodeEmulatorBox(QGroupBox):
    """The emulated board's own hold / resume buttons and an alarm, as a switch would raise."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        t = self.texts = Texts(self)
        t.set(self.setTitle, lambda: self.tr("Emulated board"))
        self.buttons = GcodeEmulatorButtons(station, self)
        self.hold_button = t.button(
            lambda: self.tr("Hold"), lambda: self.tr("The board's feed-hold button")
        )
        self.resume_button = t.button(
            lambda: self.tr("Cycle start"), lambda: self.tr("The board's cycle-start button")
        )
        self.alarm_code = NumberField(
            1,
            9,
            decimals=0,
            value=1,
            name="alarm_code",
        )
        t.set(
            self.alarm_code.set_description,
            lambda: self.tr("ALARM code (1: hard limit, 2: soft limit, 3: reset in motion…)"),
        )
        self.alarm_code.setMinimumWidth(60)
        self.alarm_button = t.button(lambda: self.tr("Raise alarm"))
        self.note = QLabel()
        self.gate = FieldGate(self.note, self)
        self.gate.watch(self.alarm_code, lambda: self.tr("ALARM code"))

        self.gate.bind(self.alarm_button, self.alarm_code)
        self.hold_button.clicked.connect(self.buttons.hold)
        self.resume_button.clicked.connect(self.buttons.resume)
        self.alarm_button.clicked.connect(self._alarm)
        grid = QGridLayout(self)
        grid.addWidget(self.hold_button, 0, 0)
        grid.addWidget(self.resume_button, 0, 1)
        grid.addWidget(self.alarm_code, 1, 0)
        grid.addWidget(self.alarm_button, 1, 1)
        grid.addWidget(self.note, 2, 0, 1, 2)
        self.white_button = t.button(
            lambda: self.tr("White button"),
            lambda: self.tr(
                "The winder's white button: the first press switches the holding current off "
                "(turn the axes by hand), the second sets the zero there (X = board radius)"
            ),
        )
        self.white_button.clicked.connect(self._white)
        self.white_note = QLabel()
        self.hand_buttons: dict[tuple[str, int], QPushButton] = {}
        hand = QHBoxLayout()
        for axis in station.profile.axes:
            step = 5.0 if axis.kind == "rotary" else 1.0
            for sign in (-1, 1):
                button = QPushButton(f"{axis.name} {MINUS if sign < 0 else '+'}{step:g}")
                t.set(
                    button.setToolTip,
                    lambda n=axis.name: self.tr("Turn {0} by hand (its driver must be off)").format(
                        n
                    ),
                )
                button.clicked.connect(lambda _=False, n=axis.name, d=sign * step: self._turn(n, d))
                # As wide as their captions: six at the style's 80 px made the pane wider than
                # the room under the pages beside the jobs dock on a 1280 px screen.
                hand.addWidget(compact(button))
                self.hand_buttons[(axis.name, sign)] = button
        self.winder_widgets: list[QWidget] = [self.white_button, self.white_note]
        self.winder_widgets += list(self.hand_buttons.values())
        grid.addWidget(self.white_button, 3, 0)
        grid.addWidget(self.white_note, 3, 1)
        grid.addLayout(hand, 4, 0, 1, 2)
        settings = station.profile.gcode
        winder = settings is not None and zeroes_by_hand(settings)
        for widget in self.winder_widgets:
            widget.setVisible(winder)

    def _white(self) -> None:
        done = self.buttons.white_button()
        texts = {
            "drivers off": self.tr("drivers off: turn the axes by hand, then press again"),
            "zero set": self.tr("zero set here (X = board radius)"),
        }
        self.white_note.setText(texts.get(done, self.tr("ignored: the machine is busy")))

    def _turn(self, axis: str, delta: float) -> None:
        if not self.buttons.turn_by_hand(axis, delta):
            self.white_note.setText(self.tr("{0} holds: its driver is on").format(axis))

    def _alarm(self) -> None:
        code = self.alarm_code.value()
        if code is None:
            self.gate.refusal(self.alarm_code)
            return
        self.buttons.alarm(round(code))

    def sync(self, *_args: object) -> None:
        enabled = self.buttons.available
        for widget in (self.hold_button, self.resume_button, self.alarm_code):
            widget.setEnabled(enabled)
        for winder_widget in self.winder_widgets:
            winder_widget.setEnabled(enabled)
        self.gate.set_enabled(enabled)
