"""Work that waits for a window's first paint: the docks a last session left shown.

The jobs dock (job formats, their readers, pyqtgraph), the telemetry plots and
the developer pane were built before the window first painted, which made a
second start 2.7 times as slow as a bare window (issue 32).  The operator sees
the window first; the docks follow within the same start, placed where they
were.  A window that closes before it ever painted still runs the work, so the
layout it saves is the one it restored.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QEvent, QObject, QTimer
from PySide6.QtWidgets import QWidget


class AfterFirstPaint(QObject):
    """Runs ``work`` once, on the event loop after ``window``'s first paint (or on ``now()``)."""

    def __init__(self, window: QWidget, work: Callable[[], None]) -> None:
        super().__init__(window)
        self._window = window
        self._work: Callable[[], None] | None = work
        window.installEventFilter(self)

    @property
    def pending(self) -> bool:
        return self._work is not None

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        if watched is self._window and event.type() == QEvent.Type.Paint:
            self._window.removeEventFilter(self)
            # After this paint has reached the screen, not within it.
            QTimer.singleShot(0, self, self.now)
        return False

    def now(self) -> None:
        """Run the work if it has not run yet (closing, saving, or a test that needs it)."""
        work, self._work = self._work, None
        self._window.removeEventFilter(self)
        if work is not None:
            work()
