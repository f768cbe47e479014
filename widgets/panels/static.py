"""Static panel: the controls that must be reachable whatever page is shown.

Speed choice, Sleep/Wake and Stop live outside the stacked pages so the
operator never has to switch pages to stop the machine or wake it up.  Sleep
is shown from the device's reports, not from what was asked, so the button
always offers what will actually change the machine's state.

On a machine that cannot stop a move (the PCB drill has no stop command) the
Stop button says on its face what it and Esc do instead — drop the queued
commands and let the running procedure finish — rather than promising a stop.
"""

from __future__ import annotations

from PySide6.QtWidgets import QButtonGroup, QLabel, QPushButton, QVBoxLayout, QWidget

from app.machine import LinkState
from app.station import Station
from widgets.jog_input import JogInput
from widgets.retranslate import Texts, bold
from widgets.stop_caption import stop_caption
from widgets.style import CHECKED_BUTTON_STYLE

_STOP_STYLE = (
    "QPushButton {{ background: #c62828; color: white; font-size: {size}pt;"
    " font-weight: bold; border-radius: 8px; padding: 6px; }}"
    "QPushButton:pressed {{ background: #8e1b1b; }}"
)


class StaticPanel(QWidget):
    """Fast/slow selector, Sleep/Wake toggle and a big Stop button."""

    def __init__(self, station: Station, jog: JogInput, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._model = station.model
        self._asleep = station.model.sleeping
        self._reported_sleeping = station.model.sleeping
        t = self.texts = Texts(self)

        self.fast_button = t.button(
            lambda: self.tr("Fast"),
            lambda: self.tr("Jog and move at the fast speed (hold Shift for slow)"),
        )
        self.slow_button = t.button(
            lambda: self.tr("Slow"),
            lambda: self.tr("Jog and move at the slow speed (hold Shift for fast)"),
        )
        speeds = QButtonGroup(self)
        for button in (self.fast_button, self.slow_button):
            button.setCheckable(True)
            button.setStyleSheet(CHECKED_BUTTON_STYLE)
            speeds.addButton(button)
        self.fast_button.setChecked(True)
        self.fast_button.toggled.connect(self._select_speed)
        self.shift_note = QLabel()
        self.shift_note.setStyleSheet("color: #b07000;")
        jog.shiftChanged.connect(self._show_shift)

        self.sleep_button = QPushButton()
        self.sleep_button.clicked.connect(self._toggle_sleep)
        self.sleep_button.setVisible(station.profile.capabilities.sleep)

        self.stop_button = QPushButton()
        t.set(self.stop_button.setText, lambda: stop_caption(station.profile)[0])
        t.set(self.stop_button.setToolTip, lambda: stop_caption(station.profile)[1])
        self.stop_button.setObjectName("stop_button")
        big = station.profile.capabilities.stop_command
        self.stop_button.setStyleSheet(_STOP_STYLE.format(size=18 if big else 11))
        # At least the big target it always was, and never narrower than its caption: a
        # fixed minimum cut the drill's three-line "DROP QUEUE" caption at both edges.
        self.stop_button.ensurePolished()
        hint = self.stop_button.sizeHint()
        self.stop_button.setMinimumSize(max(120, hint.width()), max(80, hint.height()))
        self.stop_button.clicked.connect(jog.stop_all)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(6)
        speed_title = t.label(lambda: bold(self.tr("Speed")))
        layout.addWidget(speed_title)
        layout.addWidget(self.fast_button)
        layout.addWidget(self.slow_button)
        layout.addWidget(self.shift_note)
        for widget in (speed_title, self.fast_button, self.slow_button, self.shift_note):
            widget.setVisible(station.profile.capabilities.speed_select)
        layout.addSpacing(10)
        layout.addWidget(self.sleep_button)
        layout.addStretch(1)
        layout.addWidget(self.stop_button)

        self._model.lockChanged.connect(self._on_lock)
        station.sessionChanged.connect(self._on_session)
        self._show_shift(False)
        self._show_sleep()
        t.also(self._show_sleep)
        t.also(lambda: self._show_shift(bool(self.shift_note.text())))

    @property
    def asleep(self) -> bool:
        """Whether the device reported itself asleep (or was sent to sleep and not woken)."""
        return self._asleep

    def _on_session(self) -> None:
        # A new session starts on the fast speed; keep the operator's choice instead.
        session = self._station.session
        if session is not None and session.fast_selected != self.fast_button.isChecked():
            session.select_speed(self.fast_button.isChecked())
        self._asleep = self._reported_sleeping = self._model.sleeping
        self._show_sleep()

    def _select_speed(self, fast: bool) -> None:
        session = self._station.session
        if session is not None:
            session.select_speed(fast)

    def _show_shift(self, held: bool) -> None:
        if not held:
            self.shift_note.setText("")
        elif self.fast_button.isChecked():
            self.shift_note.setText(self.tr("Shift held: slow"))
        else:
            self.shift_note.setText(self.tr("Shift held: fast"))

    def _toggle_sleep(self) -> None:
        session = self._station.session
        if session is None:
            return
        wake = self._asleep
        session.set_sleep(not wake)
        # Shown at once; the device's next reports confirm (or correct) it.
        self._asleep = not wake
        self._show_sleep()

    def _on_lock(self) -> None:
        # Follow the device's edges only, so a click shows at once and is not undone by
        # echoes sent before the device handled it.  A block (charger…) hides "sleeping"
        # in the axis status, so losing it while blocked does not mean awake.
        sleeping = self._model.sleeping
        if sleeping != self._reported_sleeping:
            self._reported_sleeping = sleeping
            if sleeping or self._model.block_reason is None:
                self._asleep = sleeping
        self._show_sleep()

    def _show_sleep(self) -> None:
        live = self._model.link_state in (LinkState.CONNECTED, LinkState.STALE)
        self.sleep_button.setEnabled(live)
        self.sleep_button.setText(self.tr("Wake") if self._asleep else self.tr("Sleep"))
        self.sleep_button.setToolTip(
            self.tr("Wake the machine: motors on, motion controls unlocked")
            if self._asleep
            else self.tr("Put the machine to sleep: motors off, motion controls locked until Wake")
        )
