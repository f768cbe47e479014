"""Manual panel: press-and-hold jog buttons in a 3x3 cross, Stop in the middle, Home per axis.

A jog lasts exactly as long as the button is held: press hands the button's
direction to the shared :class:`JogInput`, release (or Qt's cancel, e.g.
dragging off the button) takes it back.  Going through the shared input keeps
buttons and arrow keys from cancelling each other.
"""

from __future__ import annotations

from PySide6.QtCore import QSize, Qt, Signal
from PySide6.QtWidgets import (
    QComboBox,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.profiles import AxisProfile
from app.settings import JOG_STEPS
from app.station import Station
from widgets.jog_input import JogInput
from widgets.number_field import localized
from widgets.retranslate import Texts
from widgets.stop_caption import pad_stop_caption, stop_caption
from widgets.style import MINUS
from widgets.units import shown_unit

#: (row, column) in the cross → (dx, dy, label, key hint); ``{0}``/``{1}`` are the
#: profile's first two axes (X and Y on a plotter, A and X on the string-art winder).
_CROSS: dict[tuple[int, int], tuple[int, int, str, str]] = {
    (0, 0): (-1, +1, "↖", "← + ↑"),
    (0, 1): (0, +1, "{1}+ ↑", "↑"),
    (0, 2): (+1, +1, "↗", "→ + ↑"),
    (1, 0): (-1, 0, "← {0}" + MINUS, "←"),
    (1, 2): (+1, 0, "{0}+ →", "→"),
    (2, 0): (-1, -1, "↙", "← + ↓"),
    (2, 1): (0, -1, "{1}" + MINUS + " ↓", "↓"),
    (2, 2): (+1, -1, "↘", "→ + ↓"),
}


_BUTTON_SIZE = QSize(96, 64)


def _describe(dx: int, dy: int, names: tuple[str, str]) -> str:
    parts = [
        f"{'+' if d > 0 else MINUS}{name}" for name, d in zip(names, (dx, dy), strict=True) if d
    ]
    return " ".join(parts)


class ManualPanel(QWidget):
    """Hold-to-jog buttons and Home; all motion goes through ``jog`` or the session."""

    #: The arrow keys' step was chosen (0: continuous): the window stores it.
    keyStepChanged = Signal(float)

    def __init__(self, station: Station, jog: JogInput, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._jog = jog
        self.jog_buttons: dict[tuple[int, ...], QPushButton] = {}
        self.home_buttons: list[QPushButton] = []
        t = self.texts = Texts(self)

        grid = QGridLayout()
        grid.setSpacing(6)
        axes = station.profile.axes
        names = (axes[0].name, axes[1].name if len(axes) > 1 else "")
        for (row, column), (dx, dy, label, keys) in _CROSS.items():
            if dy and len(axes) < 2:
                continue  # a one-axis machine: left and right only
            button = self._jog_button(label.format(*names), (dx, dy))
            described = _describe(dx, dy, names)
            t.set(
                button.setToolTip,
                lambda d=described, k=keys: self.tr(
                    "Hold to jog {0}  (keys: {1}; Shift = other speed)"
                ).format(d, k),
            )
            grid.addWidget(button, row, column)
            self.jog_buttons[(dx, dy)] = button

        self.stop_button = QPushButton()
        t.set(self.stop_button.setText, lambda: pad_stop_caption(station.profile))
        t.set(self.stop_button.setToolTip, lambda: stop_caption(station.profile)[1])
        self.stop_button.setFixedSize(_BUTTON_SIZE)
        self.stop_button.setStyleSheet("font-weight: bold; color: #b02020;")
        self.stop_button.clicked.connect(jog.stop_all)
        if jog.jogs:
            grid.addWidget(self.stop_button, 1, 1)

        steps = self._build_key_step(t, axes[0])
        homes = self._build_homes(t, station, jog)

        cross = QHBoxLayout()
        cross.addLayout(grid)
        if len(station.profile.axes) >= 3:
            cross.addSpacing(18)
            cross.addLayout(self._z_column(station.profile.axes[2].name))
        cross.addStretch(1)
        #: Why the jog buttons are off while the machine itself may move (a job under way).
        self.jog_note = QLabel()
        self.jog_note.setObjectName("jog_lock_note")
        self.jog_note.setWordWrap(True)
        self.jog_note.setStyleSheet("color: #a05a00; font-weight: bold;")
        self.jog_note.hide()
        self._jog_lock: str | None = None
        #: Buttons shown pressed for a held arrow key (never one the mouse holds).
        self._key_lit: set[QPushButton] = set()
        jog.keysChanged.connect(self._show_keys)

        layout = QVBoxLayout(self)
        layout.setContentsMargins(12, 12, 12, 12)
        #: The pad and the arrow-key choice, left out on a machine that cannot jog.
        self.jog_pad = QWidget()
        self.jog_pad.setObjectName("jog_pad")
        pad = QVBoxLayout(self.jog_pad)
        pad.setContentsMargins(0, 0, 0, 0)
        pad.addLayout(cross)
        pad.addWidget(self.jog_note)
        pad.addSpacing(12)
        pad.addLayout(steps)
        layout.addWidget(self.jog_pad)
        layout.addLayout(homes)
        layout.addStretch(1)
        self.jog_pad.setVisible(jog.jogs)

    def _build_key_step(self, t: Texts, first: AxisProfile) -> QHBoxLayout:
        """What a tap of an arrow key does: jog while held, or one step of the first axis's unit."""
        self.key_step = QComboBox()
        self.key_step.setObjectName("key_step")
        self.key_step.setFocusPolicy(Qt.FocusPolicy.NoFocus)  # arrows stay the machine's
        for step in JOG_STEPS:
            self.key_step.addItem("", step)
            t.item(
                self.key_step,
                self.key_step.count() - 1,
                lambda s=step, u=first.unit: (
                    self.tr("continuous (hold)")
                    if s == 0
                    else self.tr("{0} {1} per tap").format(localized(f"{s:g}"), shown_unit(u))
                ),
            )
        t.set(
            self.key_step.setToolTip,
            lambda: self.tr(
                "What a tap of an arrow key does: jog while held, or move one step "
                "(never past the travel)"
            ),
        )
        self.key_step.currentIndexChanged.connect(self._key_step_chosen)
        steps = QHBoxLayout()
        steps.addWidget(t.label(lambda: self.tr("Arrow keys:")))
        steps.addWidget(self.key_step)
        steps.addStretch(1)
        return steps

    def _build_homes(self, t: Texts, station: Station, jog: JogInput) -> QHBoxLayout:
        """Home all (one command homes every axis), or a button per axis; Stop when no pad."""
        homes = QHBoxLayout()
        homes.setSpacing(6)
        if station.profile.capabilities.home and station.dialect.homes_all_axes:
            # One command homes every axis here: per-axis buttons that all did the same
            # thing promised what the machine cannot do.
            button = t.button(
                lambda: self.tr("Home all"),
                lambda: self.tr("Home every axis: the machine's home command does them all"),
            )
            button.clicked.connect(lambda _=False: self._home(0))
            homes.addWidget(button)
            self.home_buttons.append(button)
        elif station.profile.capabilities.home:
            for index, axis in enumerate(station.profile.axes):
                button = t.button(
                    lambda a=axis: self.tr("Home {0}").format(a.name),
                    lambda a=axis: self.tr("Seek the {0} home switch and set {0} = 0").format(
                        a.name
                    ),
                )
                button.clicked.connect(lambda _=False, i=index: self._home(i))
                homes.addWidget(button)
                self.home_buttons.append(button)
        if not jog.jogs:
            homes.insertWidget(0, self.stop_button)  # no pad to sit in: Stop stays in sight
        homes.addStretch(1)
        return homes

    def _z_column(self, name: str) -> QVBoxLayout:
        """Up and down for the third axis, beside the cross (PageUp / PageDown)."""
        column = QVBoxLayout()
        column.setSpacing(6)
        for sign, direction, key in (("+", +1, "PageUp"), (MINUS, -1, "PageDown")):
            button = self._jog_button(f"{name}{sign}", (0, 0, direction))
            self.texts.set(
                button.setToolTip,
                lambda up=direction > 0, k=key: (
                    self.tr("Hold to jog {0} up  (key: {1})")
                    if up
                    else self.tr("Hold to jog {0} down  (key: {1})")
                ).format(name, k),
            )

            column.addWidget(button)
            self.jog_buttons[(0, 0, direction)] = button
        column.addStretch(1)
        return column

    def _jog_button(self, label: str, directions: tuple[int, ...]) -> QPushButton:
        button = QPushButton(label)
        button.setFixedSize(_BUTTON_SIZE)
        font = button.font()
        font.setPointSizeF(font.pointSizeF() * 1.25)
        button.setFont(font)
        # A hold-to-move button must not take keyboard focus: Space would "hold" it
        # and arrows pressed afterwards would land on it instead of jogging.
        button.setFocusPolicy(Qt.FocusPolicy.NoFocus)
        button.setAutoRepeat(False)
        # pressed/released also fire when the pointer leaves and re-enters while held,
        # and released fires when the button is disabled while down.
        button.pressed.connect(lambda: self._jog.button_press(button, directions))
        button.released.connect(lambda: self._jog.button_release(button))
        return button

    def set_key_step(self, step: float) -> None:
        """Show (and use) a stored choice; one the list lacks means continuous."""
        index = self.key_step.findData(step)
        self.key_step.setCurrentIndex(max(0, index))
        self._key_step_chosen()

    def _key_step_chosen(self) -> None:
        self._jog.set_key_step(float(self.key_step.currentData()))
        self.keyStepChanged.emit(self._jog.key_step)

    def _home(self, axis: int) -> None:
        session = self._station.session
        if session is not None:
            session.home(axis)

    def set_motion_enabled(self, enabled: bool) -> None:
        """Jog and Home follow the motion lock; Stop never does."""
        for button in self.home_buttons:
            button.setEnabled(enabled)
        self._motion_enabled = enabled
        self._update_jog_buttons()

    def set_jog_lock(self, reason: str | None) -> None:
        """A job under way: the jog buttons go off and the page says why (Home stays with
        the motion lock; the job refuses what would disturb it)."""
        self._jog_lock = reason
        self._update_jog_buttons()

    def _update_jog_buttons(self) -> None:
        enabled = getattr(self, "_motion_enabled", True) and self._jog_lock is None
        for button in self.jog_buttons.values():
            button.setEnabled(enabled)
        if self._jog_lock is None:
            self.jog_note.hide()
            return
        self.jog_note.setText(self.tr("Jogging locked: {0}").format(self._jog_lock))
        self.jog_note.show()

    def _show_keys(self, vector: tuple[int, ...]) -> None:
        """Show the button of the held arrow keys' direction pressed, as if held by the mouse."""
        xy = tuple(vector[:2]) + (0,) * (2 - len(vector[:2]))
        lit: set[QPushButton] = set()
        for directions, button in self.jog_buttons.items():
            if len(directions) == 3:
                on = len(vector) > 2 and vector[2] == directions[2]
            else:
                on = any(xy) and tuple(directions[:2]) == xy
            if on:
                lit.add(button)
        for button in self._key_lit - lit:
            button.setDown(False)
        kept = self._key_lit & lit
        for button in lit - self._key_lit:
            if button.isDown():
                continue  # the mouse holds it: only the mouse may let it up again
            button.setDown(True)
            kept.add(button)
        self._key_lit = kept
