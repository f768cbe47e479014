"""A library's import, off the GUI thread: pysdl2 binds SDL's whole API through ctypes at
import, a tenth of a second on an idle computer and half a second on a busy one.

Only the import runs on the worker thread; what then uses the library (SDL's joystick
start-up, every read) stays on the GUI thread, where SDL expects its joystick calls.
"""

from __future__ import annotations

import threading
from collections.abc import Callable

from PySide6.QtCore import QObject, Signal


class BackgroundImport(QObject):
    """Runs ``work`` (an import) once on a short-lived thread; :attr:`done` on the GUI thread."""

    #: The work ended (whether it worked is for the caller to find out: importing again
    #: is then immediate, or fails again at once with its reason).
    done = Signal()

    def __init__(self, work: Callable[[], None], parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._work = work
        self._thread: threading.Thread | None = None
        #: Whether ``done`` has reached the GUI thread (set there, before the other slots).
        self.finished = False
        self.done.connect(self._mark_finished)

    @property
    def started(self) -> bool:
        return self._thread is not None

    def start(self) -> None:
        """Start the work unless it has started already."""
        if self._thread is not None:
            return
        self._thread = threading.Thread(target=self._run, name="gamepad-import", daemon=True)
        self._thread.start()

    def _mark_finished(self) -> None:
        self.finished = True

    def _run(self) -> None:
        try:
            self._work()
        except Exception:  # said on the GUI thread, where the import is tried again
            pass
        self._finish()

    def _finish(self) -> None:
        try:
            self.done.emit()  # queued to the GUI thread: this object lives there
        except RuntimeError:  # the window, and this object with it, is gone
            pass
