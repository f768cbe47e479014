"""The board's receive buffer against the bytes the station counts unanswered.

Character counting keeps at most ``rx_buffer - 1`` bytes unanswered, so the
board's buffer never overflows — as long as the board gets exactly what was
sent and each ``ok`` answers one line.  A line that arrives twice (a
repeating USB adapter, a relay), or an answer that arrives twice, breaks that
silently: the next lines overflow the buffer, bytes are dropped, and a line
glued from two halves is refused or, worse, runs.  The board went straight
on to the lines behind a refused one before the station could hold it: a
few tenths of a mm of a stroke not in the job (relay corexy-plotter, a
duplicated line).

A board that reports its buffer (``Bf:``) shows it before that happens: its
buffer holds only lines not yet parsed, all of them unanswered, so it can
never hold more than the station counts unanswered.  When it does, the count
is wrong, and the machine is stopped before the damaged line is reached.

Only once the board was seen with its buffer empty since the station last
forgot its lines (a reconnect, a silence, a reset): before that the buffer
may hold lines sent on an earlier link, which the station no longer counts.
"""

from __future__ import annotations

from protocol.gcode.codec import StatusReport

#: GRBL counts an empty buffer as 128 or 127 free (its ring buffer): a byte of slack.
SLACK_BYTES = 1


class ByteCount:
    """Compares each report's buffer with the bytes counted unanswered when it was read."""

    def __init__(self, rx_buffer: int) -> None:
        self._rx_buffer = rx_buffer
        self._known = False

    def forget(self) -> None:
        """The station forgot its lines (the board may still hold some): not comparable."""
        self._known = False

    def excess(self, report: StatusReport, unanswered_bytes: int | None) -> int | None:
        """Bytes the board holds beyond those counted unanswered (None: none, or unknown)."""
        if report.rx_free is None:
            return None
        held = self._rx_buffer - report.rx_free
        if held <= SLACK_BYTES:
            self._known = True  # empty: from here on it holds only what is counted
            return None
        if not self._known or unanswered_bytes is None:
            return None
        extra = held - unanswered_bytes - SLACK_BYTES
        return extra if extra > 0 else None
