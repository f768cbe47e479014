"""When the recorder tells the views that the shown data changed: throttled, on a steady beat.

Samples may come at 1 kHz; the screen needs ~60 Hz.  ``updated`` fires at
once after a quiet spell, then at most once per ``throttle_ms`` (60 Hz by
default) while samples keep coming (the last change is never lost), on a
steady beat: each interval counts from when the previous one was due, not
from when the timer happened to fire, so timer latency does not drag 30 Hz
down to 29.  ``throttle_ms=0`` emits once per change, for tests.  While live,
a slow ``scroll_ms`` beat also fires it so that the time window keeps moving
when nothing changes.  Every ``updated`` restarts that beat, so it only fills
silences: an idle link's echoes and the beat do not each cost a frame.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable

from PySide6.QtCore import QObject, Qt, QTimer, SignalInstance

DEFAULT_THROTTLE_MS = 1000 / 60  # redraws per second at most: 60, a display's rate
#: Longer than the stage's 100 ms echo period, so a live link's frames alone move the window.
DEFAULT_SCROLL_MS = 150


class UpdatePacer(QObject):
    """Emits the recorder's ``updated``: coalesced while samples come, on a beat while live."""

    def __init__(
        self,
        updated: SignalInstance,
        live: Callable[[], bool],
        *,
        throttle_ms: float,
        scroll_ms: int,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._updated = updated
        self._live = live  # not paused: the window moves with time
        self.throttle_ms = throttle_ms
        self.throttle = QTimer(self)
        self.throttle.setSingleShot(True)
        self.throttle.setTimerType(Qt.TimerType.PreciseTimer)
        self.throttle.timeout.connect(self._throttle_done)
        self._pending = False
        self._due: float | None = None  # wall time the throttle's current interval ends
        self.scroll = QTimer(self)
        self.scroll.timeout.connect(self._on_scroll)
        if scroll_ms > 0:
            self.scroll.start(scroll_ms)

    def changed(self) -> None:
        """Emit ``updated`` now, or once when the throttle interval is over."""
        if self.throttle_ms <= 0:
            self._rearm_scroll()
            self._updated.emit()
        elif self.throttle.isActive():
            self._pending = True
        else:
            self.emit_now()

    def emit_now(self, *, on_beat: bool = False) -> None:
        """Emit, and start the next throttle interval.

        ``on_beat``: the throttle timer fired.  The next interval then counts
        from when this one was due, so the timer's lateness does not pile up;
        after a quiet spell a fresh interval counts from now.
        """
        self._pending = False
        if self.throttle_ms > 0:
            # Wall time, not the station clock: this paces the screen, not the machine.
            interval = self.throttle_ms / 1000
            now = time.perf_counter()
            if on_beat and self._due is not None and now - self._due < interval:
                self._due += interval
            else:
                self._due = now + interval
            self.throttle.start(max(1, math.ceil((self._due - now) * 1000)))
        self._rearm_scroll()
        self._updated.emit()

    def _throttle_done(self) -> None:
        if self._pending:
            self.emit_now(on_beat=True)

    def _rearm_scroll(self) -> None:
        """The beat counts from the last ``updated``: it only fills silences."""
        if self.scroll.isActive():
            self.scroll.start()

    def _on_scroll(self) -> None:
        if self._live():
            self.changed()
