"""Whether a G-code board stands, with nothing left of what it was sent: a resume's first gate.

After a fault the board may still hold lines sent before it: in its planner,
and in its receive buffer, parsed only as the planner takes them.  A board
that has just finished a line and not yet parsed the next reports ``Idle``
for that instant (GRBL between two lines; the CoreXY plotter, which parses
the next line only after the ``OK`` of the last, for one control cycle).
Taking that report for "standing" sent the way back while old lines were
still to run: a stroke drawn twice, or supervision stopping the job.

So a report proves the board stands only when it also shows nothing left:

* with ``Bf:`` (GRBL ``$10`` bit 1, the CoreXY plotter): the planner as
  free as when idle, and the receive buffer empty;
* without it: the same ``Idle`` place in a second report, asked for once the
  first was read — a line left in the buffer would have been parsed between
  them (the board parses whenever it has room), and would show as ``Run`` or
  as another place.

Never a fixed wait: each verdict comes from a report the board made.
"""

from __future__ import annotations

import enum
from collections.abc import Sequence

from protocol.gcode.codec import StatusReport

#: Positions closer than this (mm) are the same place (GRBL reports three decimals).
SAME_PLACE_MM = 0.0005


class Standing(enum.Enum):
    """What one status report says of a board that should stand before a resume."""

    STANDS = "stands"  # nothing left of what it was sent
    BUSY = "busy"  # running, holding, or something left: the next report decides
    ASK_AGAIN = "ask again"  # idle, but only a second report can prove nothing is left


class StandingProof:
    """Judges the reports of one wait for a standing board (:meth:`forget` starts another)."""

    def __init__(self) -> None:
        self._idle_at: tuple[float, ...] | None = None

    def forget(self) -> None:
        """A new wait: an idle report seen before it proves nothing now."""
        self._idle_at = None

    def judge(self, report: StatusReport, planner_size: int, rx_buffer: int) -> Standing:
        """``planner_size``: the free blocks of the idle board (0: not known)."""
        if report.state != "Idle":
            self._idle_at = None
            return Standing.BUSY
        if report.rx_free is not None:
            planner_empty = (
                report.planner_free is None
                or not planner_size
                or report.planner_free >= planner_size
            )
            # GRBL counts its ring buffer's free bytes as 128 or 127 when empty.
            if planner_empty and report.rx_free >= rx_buffer - 1:
                return Standing.STANDS
            self._idle_at = None
            return Standing.BUSY
        before, self._idle_at = self._idle_at, tuple(report.mpos)
        if before is not None and _same_place(before, report.mpos):
            return Standing.STANDS
        return Standing.ASK_AGAIN


def _same_place(a: Sequence[float], b: Sequence[float]) -> bool:
    return len(a) == len(b) and all(abs(x - y) <= SAME_PLACE_MM for x, y in zip(a, b, strict=True))
