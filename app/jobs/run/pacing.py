"""Pacing on the station's clock: something done at most so often, whatever calls it.

A streaming driver hears of answers a thousand times a second; a checkpoint
is an fsync and an announcement a redraw, so each goes at most every so
often of the station's clock (a manual clock in tests, so the pacing is exact).
"""

from __future__ import annotations


class Every:
    """At most once every ``seconds`` of a clock (the first time at once), unless forced."""

    def __init__(self, seconds: float) -> None:
        self.seconds = seconds
        self._last = -1.0

    def due(self, now: float, *, force: bool = False) -> bool:
        """Whether it is time (then the next is ``seconds`` from ``now``)."""
        if not force and self._last >= 0 and now - self._last < self.seconds:
            return False
        self._last = now
        return True
