"""The operator's jog input in the window: Qt's keys and the mouse, fed to the state machine.

What is held and what the session is told is :class:`app.jog_state.JogState`;
this adds what only a GUI knows: which Qt keys jog which axis, and whether
the mouse still holds an on-screen button (a held button sends no repeats,
so the mouse's state is looked at instead).
"""

from __future__ import annotations

from collections.abc import Hashable, Sequence

from PySide6.QtCore import QObject, Qt, QTimer
from PySide6.QtGui import QGuiApplication

from app.jog_state import JogState
from app.station import Station

#: Key → (axis index, direction).  PageUp/PageDown only act on a machine with a Z axis.
JOG_KEYS: dict[int, tuple[int, int]] = {
    Qt.Key.Key_Right: (0, +1),
    Qt.Key.Key_Left: (0, -1),
    Qt.Key.Key_Up: (1, +1),
    Qt.Key.Key_Down: (1, -1),
    Qt.Key.Key_PageUp: (2, +1),
    Qt.Key.Key_PageDown: (2, -1),
}
#: How often a held on-screen button is checked for still being held (the dead-man's sign).
BUTTON_POLL_MS = 200


class JogInput(JogState):
    """The jog state machine on Qt's arrow keys, with the mouse watched for held buttons."""

    def __init__(self, station: Station, parent: QObject | None = None) -> None:
        super().__init__(station, JOG_KEYS, parent)
        self._button_poll = QTimer(self)
        self._button_poll.setInterval(BUTTON_POLL_MS)
        self._button_poll.timeout.connect(self._poll_buttons)

    def button_press(self, source: Hashable, directions: Sequence[int]) -> bool:
        """An on-screen jog button went down; the mouse is watched while it is held."""
        taken = super().button_press(source, directions)
        if taken:
            self._button_poll.start()
        return taken

    def _poll_buttons(self) -> None:
        held = bool(QGuiApplication.mouseButtons() & Qt.MouseButton.LeftButton)
        if not self.poll_buttons(held):
            self._button_poll.stop()
