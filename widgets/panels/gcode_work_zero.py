"""The G-code page's work zero on a GRBL board: zero X / Y / all here, G54…G59, go to zero.

The DRO line above the buttons shows the system in use and its offset (the
board's ``WCO:``, and ``$G``/``$#`` when read).  Each button is the session's
intent (:mod:`app.machines.gcode.work_zero`), judged by the motion gate:
refused, with the reason on the status bar, while a job is under way or the
machine moves.  Hidden on a machine without work systems (the dialect
registry's word).
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QWidget

from app.machines.gcode.session import GcodeSession
from app.machines.gcode.work_zero import SYSTEMS
from app.machines.registry import dialect_for
from app.station import Station
from widgets.retranslate import Maker, Texts
from widgets.style import monospace_font

# The narrow buttons' width (px): "G54", "+10", "100 %" fit; six to a row fit the page.
SMALL_BUTTON = 64


class WorkZeroBox(QWidget):
    """Zeroing buttons, the system chooser and the work DRO line of a GRBL session."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._watched: GcodeSession | None = None
        t = self.texts = Texts(self)
        self.setObjectName("work_zero_box")
        group = t.group(lambda: self.tr("Work zero"))
        self.work_label = QLabel("—")
        self.work_label.setObjectName("work_offset")
        self.work_label.setFont(monospace_font())
        t.set(
            self.work_label.setToolTip,
            lambda: self.tr("The coordinate system in use and its offset from the machine zero"),
        )
        names = [a.name for a in station.profile.axes]
        self.zero_buttons: dict[str, QPushButton] = {}
        for name in names:
            self.zero_buttons[name] = self._button(
                lambda name=name: self.tr("Zero {0}").format(name),
                lambda name=name: self.tr(
                    "Here is {0} 0 in the system in use (G10 L20 P0 {0}0); nothing moves"
                ).format(name),
                partial(self.zero, [name]),
            )
        self.zero_all_button = self._button(
            lambda: self.tr("Zero all"),
            lambda: self.tr("Here is the work zero of every axis (G10 L20 P0); nothing moves"),
            lambda: self.zero(names),
        )
        self.go_button = self._button(
            lambda: self.tr("Go to work zero"),
            lambda: self.tr("Lift the pen, then travel to the work zero (G90 G0)"),
            self.go_to_zero,
        )
        self.read_button = self._button(
            lambda: self.tr("Read"),
            lambda: self.tr("Ask the board for its systems ($G, $#)"),
            self.read,
        )
        # Buttons, not a list: a focused list would take the arrow keys, which jog.
        self.system_buttons: dict[str, QPushButton] = {}
        for system in SYSTEMS:
            button = self._button(
                lambda system=system: system,
                lambda system=system: self.tr(
                    "Work in {0} from now on (its own zero); nothing moves"
                ).format(system),
                partial(self.select, system),
            )
            button.setCheckable(True)
            self.system_buttons[system] = button
        # Three to a row (six narrow system buttons to one), as the Machine box above, so the
        # page fits beside the jobs dock on a 1280 px screen.
        grid = QGridLayout(group)
        grid.addWidget(t.label(lambda: self.tr("In use")), 0, 0)
        grid.addWidget(self.work_label, 0, 1, 1, 5)
        for column, button in enumerate(self.system_buttons.values()):
            button.setMaximumWidth(SMALL_BUTTON)
            grid.addWidget(button, 1, column)
        row = [*self.zero_buttons.values(), self.zero_all_button, self.go_button, self.read_button]
        for number, button in enumerate(row):
            grid.addWidget(button, 2 + number // 3, (number % 3) * 2, 1, 2)
        layout = QGridLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(group)
        self.setVisible(dialect_for(station.profile).work_systems(station.profile))
        station.sessionChanged.connect(self._watch_session)
        self._watch_session()
        self._show()

    def _button(self, caption: Maker, tip: Maker, slot: Callable[[], object]) -> QPushButton:
        button = self.texts.button(caption, tip)
        button.clicked.connect(lambda _checked=False: slot())  # not the checked flag
        return button

    @property
    def session(self) -> GcodeSession | None:
        return self._station.session_as(GcodeSession)

    # --- what the buttons do -----------------------------------------------------------

    def zero(self, axes: list[str]) -> bool:
        return self.session is not None and self.session.work.zero(axes)

    def go_to_zero(self) -> bool:
        return self.session is not None and self.session.work.go_to_zero()

    def read(self) -> bool:
        return self.session is not None and self.session.work.read()

    def select(self, system: str) -> bool:
        session = self.session
        chosen = session is not None and session.work.select(system)
        self._show()  # refused or not yet answered: the buttons show the system in use
        return chosen

    def set_motion_enabled(self, enabled: bool) -> None:
        for button in (*self.zero_buttons.values(), self.zero_all_button, self.go_button):
            button.setEnabled(enabled)
        self.read_button.setEnabled(enabled)
        for button in self.system_buttons.values():
            button.setEnabled(enabled)

    # --- the session's news ------------------------------------------------------------

    def _watch_session(self) -> None:
        session = self.session
        if session is self._watched:
            return
        self._watched = session
        if session is not None:
            session.statusChanged.connect(self._show)
            session.replyText.connect(self._show)
            session.linesSent.connect(self._show)  # once a write, not once a line

    def _show(self, *_args: object) -> None:
        session = self.session
        if session is None:
            self.work_label.setText("—")
            return
        work = session.work
        self.work_label.setText(work.describe())
        for system, button in self.system_buttons.items():
            button.setChecked(system == work.system)
