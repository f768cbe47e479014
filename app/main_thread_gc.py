"""Python's cyclic garbage collector, run on the GUI thread only.

The collector runs in whichever thread allocates when a generation fills: a
transport thread, the BLE asyncio loop, a file-loading worker.  A cycle freed
there may hold Qt objects that belong to the GUI thread, and deleting them from
another thread while the GUI thread delivers their events crashes the process.
The suite showed it: a station dropped by one test, its cycle collected later
from the asyncio thread of another, and a segmentation fault in the event loop.
So the automatic collector is switched off and the GUI thread collects on a
timer, by the collector's own thresholds (the pattern qutebrowser uses).
"""

from __future__ import annotations

import gc

from PySide6.QtCore import QObject, QTimer

#: How often the GUI thread looks at the collector's counts.
INTERVAL_MS = 500


def collect_due() -> int | None:
    """Collect the oldest generation whose count passed its threshold (as the automatic
    collector would have); the generation collected, or None when nothing was due."""
    counts = gc.get_count()
    thresholds = gc.get_threshold()
    for generation in (2, 1, 0):
        if thresholds[generation] and counts[generation] > thresholds[generation]:
            gc.collect(generation)
            return generation
    return None


class MainThreadCollector(QObject):
    """Switches automatic collection off and collects on the thread it lives in."""

    def __init__(self, parent: QObject | None = None, interval_ms: int = INTERVAL_MS) -> None:
        super().__init__(parent)
        self._timer = QTimer(self)
        self._timer.setInterval(interval_ms)
        self._timer.timeout.connect(collect_due)

    def start(self) -> None:
        gc.disable()
        self._timer.start()

    def stop(self) -> None:
        """Automatic collection back on (the process goes on without an event loop)."""
        self._timer.stop()
        gc.enable()
