"""The control loop every emulated firmware runs: fixed cycles on an injected clock.

Each firmware decides what one cycle does; when cycles happen, where the
replies go and the lock that keeps the loopback's ticker thread and the GUI
thread apart are the same for all of them, so they live here once.
"""

from __future__ import annotations

import threading
from abc import ABC, abstractmethod
from collections.abc import Callable

from protocol.clock import Clock

#: Seconds: a cycle that ends within this of the asked time has been reached.
_EPS = 1e-9


class ControlCycles(ABC):
    """Base of the firmwares: ``set_output`` and ``run_until`` of the EmulatedDevice face.

    Subclasses implement ``_run_cycle`` (one control cycle ending at
    ``_cycle_time(_cycles + 1)``; it must increment ``_cycles``) and
    ``receive``; they send replies with ``_send_to_host``.
    """

    def __init__(self, clock: Clock, control_cycle: float) -> None:
        self._lock = threading.RLock()
        self._sink: Callable[[bytes], None] | None = None
        self._start = clock.now()
        self._cycles = 0
        self._control_cycle = control_cycle

    def set_output(self, sink: Callable[[bytes], None] | None) -> None:
        with self._lock:
            self._sink = sink

    def run_until(self, t: float) -> None:
        with self._lock:
            while self._cycle_time(self._cycles + 1) <= t + _EPS:
                self._run_cycle()

    def next_cycle_at(self) -> float:
        """Clock time at which the next control cycle is due (a serving loop sleeps till then)."""
        with self._lock:
            return self._cycle_time(self._cycles + 1)

    @property
    def time(self) -> float:
        """Clock time at the end of the last control cycle run."""
        with self._lock:
            return self._cycle_time(self._cycles)

    def _cycle_time(self, cycles: int) -> float:
        return self._start + cycles * self._control_cycle

    @abstractmethod
    def receive(self, data: bytes) -> None:
        """Bytes from the host, handled in the next control cycle."""

    @abstractmethod
    def _run_cycle(self) -> None:
        """One control cycle; ends by counting it in ``_cycles``."""

    def _send_to_host(self, data: bytes) -> None:
        if self._sink is not None:
            self._sink(data)
