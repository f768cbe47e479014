"""The G-code page's overrides: feed 10…200 % and rapid 25/50/100 % on a GRBL board.

Buttons, not a slider: a slider with focus takes the arrow keys, which jog
everywhere else in the window.  What is shown is what the board reports in
its ``Ov:`` field, with what was asked while the board has not shown it yet;
the window's keys (:data:`OVERRIDE_KEYS`, listed in Help → Keys) press the
same buttons.  Hidden on a machine whose firmware has no overrides (the dialect
registry's word, :mod:`app.machines.registry`).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QAction, QKeySequence
from PySide6.QtWidgets import QGridLayout, QLabel, QPushButton, QWidget

from app.machines.gcode.session import GcodeSession
from app.machines.registry import dialect_for
from app.station import Station
from widgets.retranslate import Maker, Texts
from widgets.style import monospace_font

# The window's override keys: (key, button attribute); Help → Keys lists them.
OVERRIDE_KEYS: tuple[tuple[str, str], ...] = (
    ("F5", "feed_minus_10"),
    ("F6", "feed_plus_10"),
    ("Shift+F5", "feed_minus_1"),
    ("Shift+F6", "feed_plus_1"),
    ("F7", "feed_reset"),
    ("F8", "rapid_next"),
)
# F8 steps the rapid override round: 100 → 50 → 25 → 100 %.
_RAPID_NEXT = {100: 50, 50: 25, 25: 100}

# The narrow buttons' width (px): "G54", "+10", "100 %" fit; six to a row fit the page.
SMALL_BUTTON = 64


class OverrideBox(QWidget):
    """Feed and rapid overrides of the session's GRBL board."""

    def __init__(self, station: Station, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._watched: GcodeSession | None = None
        t = self.texts = Texts(self)
        self.setObjectName("override_box")
        group = t.group(lambda: self.tr("Overrides"))
        self.feed_label = QLabel("—")
        self.feed_label.setObjectName("override_feed")
        self.feed_label.setFont(monospace_font())
        self.rapid_label = QLabel("—")
        self.rapid_label.setObjectName("override_rapid")
        self.rapid_label.setFont(monospace_font())
        self.feed_minus_10 = self._button("-10", lambda: self.tr("Feed override -10 %"), -10)
        self.feed_minus_1 = self._button("-1", lambda: self.tr("Feed override -1 %"), -1)
        self.feed_plus_1 = self._button("+1", lambda: self.tr("Feed override +1 %"), 1)
        self.feed_plus_10 = self._button("+10", lambda: self.tr("Feed override +10 %"), 10)
        self.feed_reset = t.button(
            lambda: self.tr("100 %"), lambda: self.tr("Feed override back to 100 %")
        )
        self.feed_reset.clicked.connect(lambda: self.set_feed(100))
        self.rapid_buttons: dict[int, QPushButton] = {}
        for level in (25, 50, 100):
            button = t.button(
                lambda level=level: self.tr("{0} %").format(level),
                lambda level=level: self.tr("Rapid (G0) at {0} %").format(level),
            )
            button.setCheckable(True)
            button.clicked.connect(lambda _=False, level=level: self.set_rapid(level))
            self.rapid_buttons[level] = button
        # F8's button: not shown, pressed by its key (and the menu).
        self.rapid_next = QPushButton(self)
        self.rapid_next.hide()
        self.rapid_next.clicked.connect(self._next_rapid)
        # Narrow buttons, the value on its own row: the page fits beside the jobs dock.
        grid = QGridLayout(group)
        grid.addWidget(t.label(lambda: self.tr("Feed")), 0, 0)
        grid.addWidget(self.feed_label, 0, 1, 1, 4)
        feed = (self.feed_minus_10, self.feed_minus_1, self.feed_plus_1, self.feed_plus_10)
        for column, button in enumerate((*feed, self.feed_reset)):
            button.setMaximumWidth(SMALL_BUTTON)
            grid.addWidget(button, 1, column)
        grid.addWidget(t.label(lambda: self.tr("Rapid")), 2, 0)
        grid.addWidget(self.rapid_label, 2, 1, 1, 4)
        for column, level in enumerate((25, 50, 100)):
            self.rapid_buttons[level].setMaximumWidth(SMALL_BUTTON)
            grid.addWidget(self.rapid_buttons[level], 3, column)
        layout = QGridLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.addWidget(group)
        self.setVisible(dialect_for(station.profile).overrides(station.profile))
        station.sessionChanged.connect(self._watch_session)
        self._watch_session()
        self._show()

    def _button(self, caption: str, tip: Maker, step: int) -> QPushButton:
        button = self.texts.button(lambda: caption, tip)
        button.clicked.connect(lambda: self.step_feed(step))
        return button

    @property
    def session(self) -> GcodeSession | None:
        return self._station.session_as(GcodeSession)

    # --- what the buttons do -----------------------------------------------------------

    def _current(self) -> tuple[int, int]:
        session = self.session
        if session is None:
            return 100, 100
        control = session.overrides
        if control.wanted is not None:
            return control.wanted
        reported = control.reported
        return (100, 100) if reported is None else (reported.feed, reported.rapid)

    def step_feed(self, step: int) -> bool:
        """From what is asked (or shown) by ``step`` %, kept within GRBL's 10…200 %."""
        feed, _ = self._current()
        return self.set_feed(min(max(feed + step, 10), 200))

    def set_feed(self, percent: int) -> bool:
        session = self.session
        done = session is not None and session.overrides.set(feed=percent)
        self._show()
        return done

    def set_rapid(self, percent: int) -> bool:
        session = self.session
        done = session is not None and session.overrides.set(rapid=percent)
        self._show()
        return done

    def _next_rapid(self) -> None:
        _, rapid = self._current()
        self.set_rapid(_RAPID_NEXT.get(rapid, 100))

    def actions_for(self, window: QWidget, texts: Texts) -> list[QAction]:
        """The override keys as the window's actions (Machine → Overrides)."""
        made: list[QAction] = []
        for key, name in OVERRIDE_KEYS:
            button: QPushButton = getattr(self, name)
            action = QAction(window)
            texts.set(action.setText, lambda name=name: override_menu_text(name))
            action.setShortcut(QKeySequence(key))
            action.setShortcutContext(Qt.ShortcutContext.WindowShortcut)
            action.triggered.connect(button.click)
            action.setObjectName(f"override_{name}")
            made.append(action)
        return made

    # --- the session's news ------------------------------------------------------------

    def _watch_session(self) -> None:
        session = self.session
        if session is self._watched:
            return
        self._watched = session
        if session is not None:
            session.statusChanged.connect(self._show)

    def _show(self, *_args: object) -> None:
        session = self.session
        reported = session.overrides.reported if session is not None else None
        wanted = session.overrides.wanted if session is not None else None
        feed = "—" if reported is None else f"{reported.feed:3d} %"
        rapid = "—" if reported is None else f"{reported.rapid:3d} %"
        if wanted is not None:
            feed += f" → {wanted[0]} %" if reported is None or wanted[0] != reported.feed else ""
            rapid += f" → {wanted[1]} %" if reported is None or wanted[1] != reported.rapid else ""
        self.feed_label.setText(feed)
        self.rapid_label.setText(rapid)
        shown_rapid = wanted[1] if wanted is not None else (reported.rapid if reported else 100)
        for level, button in self.rapid_buttons.items():
            button.setChecked(level == shown_rapid)


def override_menu_text(name: str) -> str:
    """The Machine → Overrides entries, by button name (for the menu's captions)."""
    return {
        "feed_minus_10": QCoreApplication.translate("OverrideBox", "Feed override -10 %"),
        "feed_plus_10": QCoreApplication.translate("OverrideBox", "Feed override +10 %"),
        "feed_minus_1": QCoreApplication.translate("OverrideBox", "Feed override -1 %"),
        "feed_plus_1": QCoreApplication.translate("OverrideBox", "Feed override +1 %"),
        "feed_reset": QCoreApplication.translate("OverrideBox", "Feed override back to 100 %"),
        "rapid_next": QCoreApplication.translate("OverrideBox", "Rapid override 100 → 50 → 25 %"),
    }[name]
