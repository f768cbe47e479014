"""A line cut on the wire, its start stuck in the board's receive buffer: the stream stalls.

A G-code board parses a line only once its end arrives.  When the bytes after
a line's start are lost (a silent cable, dropped bytes), the start waits in
the board's buffer for good: the board stands idle, the station waits for the
answers of that line and of the lines behind it, and nothing moves again.
Nothing the station sends can end that fragment safely — a line end would
make it a line (``G1 X17.0`` is valid, and wrong) — so the station resets the
board: standing idle, it keeps its position, and the resume looks at it and
goes on from what is proven run.

Only a board that reports its buffer (``Bf:``) shows it: idle, planner empty,
the same few bytes in its buffer report after report — whether the station
still waits for answers, or forgot its lines when the cable went silent.
Between two lines a board is idle with a whole line in its buffer for a
moment only; a dwell or a program stop (``G4``, ``M0``) holds lines on
purpose, and is never taken for this.
"""

from __future__ import annotations

import math

from protocol.clock import Clock
from protocol.gcode.codec import StatusReport

#: Reports in a row, spanning at least this long, that show the same bytes stuck.
STUCK_REPORTS = 3
STUCK_AFTER_S = 1.0


class StuckLineWatch:
    """Watches the status reports for a fragment stuck in the board's receive buffer."""

    def __init__(self, clock: Clock, rx_buffer: int) -> None:
        self._clock = clock
        self._rx_buffer = rx_buffer
        self._since: float | None = None
        self._reports = 0
        self._free: int | None = None

    def forget(self) -> None:
        self._since, self._reports, self._free = None, 0, None

    def stuck(self, report: StatusReport, *, planner_empty: bool, paused_s: float) -> int | None:
        """The bytes stuck when this report makes it certain (then it starts over), else None.

        ``paused_s``: how long the lines unanswered may hold the board on purpose (their
        dwells; for ever with ``M0``).  A dwell bounds the wait, it does not end it: relay
        string-art seed 34, a fragment behind a ``G4 S0.25`` kept the job waiting for ever.
        """
        free = report.rx_free
        held = None if free is None else self._rx_buffer - free
        if (
            report.state != "Idle"
            or not planner_empty
            or math.isinf(paused_s)
            or held is None
            or held <= 1  # GRBL counts an empty buffer as 127 or 128 free
        ):
            self.forget()
            return None
        now = self._clock.now()
        if self._since is None or free != self._free:
            self._since, self._reports, self._free = now, 0, free
        self._reports += 1
        if self._reports >= STUCK_REPORTS and now - self._since >= STUCK_AFTER_S + paused_s:
            self.forget()
            return held
        return None
