"""Clocks the emulator and the station's link-health logic run on.

Everything time-dependent takes a clock instead of calling ``time`` itself, so
that tests and dry runs advance time deterministically and faster than real
time, while the app runs on the monotonic clock.
"""

from __future__ import annotations

import threading
import time
from typing import Protocol


class Clock(Protocol):
    """A source of monotonic time in seconds."""

    def now(self) -> float: ...


class MonotonicClock:
    """Real time, for the running station and the emulator on a pty."""

    def now(self) -> float:
        return time.monotonic()


class ManualClock:
    """Time that moves only when a test (or a dry run) advances it."""

    def __init__(self, start: float = 0.0) -> None:
        self._now = start
        self._lock = threading.Lock()

    def now(self) -> float:
        with self._lock:
            return self._now

    def advance(self, seconds: float) -> float:
        if seconds < 0:
            raise ValueError("time cannot run backwards")
        with self._lock:
            self._now += seconds
            return self._now
