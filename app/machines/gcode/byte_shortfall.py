"""Bytes lost inside a line that still waits in the board's receive buffer (fewer than sent).

A line that lost bytes on the way sits in the board's buffer shorter than the
station counts, and runs when its turn comes: a wrong but valid line
(``G1 X18.000 Y18.000`` cut to ``G1 X18.0``) draws a wrong stroke (relay
corexy-plotter 6, 18, 42, 72, 174).  A board that reports its buffer (``Bf:``)
shows the loss while the line waits, but only against the bytes written
before the ``?`` that asked for the report, and only on a board that parses
one line at a time and answers it once it ran (``ok_when_done``, the CoreXY
plotter's firmware).  Why the comparison is exact there:

- Wire order: every byte written before a ``?`` reaches the board before it
  (one port, one order: the feeder notes each ``?`` under the lock its lines
  are written under, :class:`QueryMarks`).  Bytes in flight when the board
  makes its report were written after the ``?``: they can only add to what
  it holds, never be missing from it.
- The board's accounting (``protocol/emulator/gcode_firmware.py``): a line
  leaves the buffer when it is parsed, and it is answered only once it ran;
  the next line is parsed only after that answer.  Of the lines unanswered,
  only the oldest can be out of the buffer; every other one is in it whole,
  even one that came in several reads (its bytes count as they arrive).
- Answers and reports share one ordered stream: a line whose ``OK`` came
  before the report is answered when the report is read, one whose ``OK``
  came after is not, as on the board when it made the report.

So the board holds at least the bytes of the lines written before the ``?``
and unanswered, less the oldest of them, and at most that plus the lines
written after the ``?``.  An ``OK`` lost on the way (a healthy board) leaves
whole lines at the front counted that the board no longer holds: a buffer
that is exactly a tail of the lines counted is that, not a loss.  Anything
else short of it is bytes lost on the way: inside a line, or a line cut by
a silence shorter than the station waits (relay seed 10: it stops too,
where the stuck-line watch would have reset the board and resumed).  No
byte written before the ``?`` can be missing from a healthy board's count,
so one report decides: the damaged line may wait only a fraction of a
second (relay seeds 6, 18, 174 are stopped by the one report that fell
there).  What it cannot tell from a loss: a report whose ``Bf:`` digits were
damaged on the way back, and a report repeated on the way and read after
another ``?`` went (it is matched with that ``?``); either stops the job
cleanly, and neither moves the machine.
"""

from __future__ import annotations

from collections import deque

from protocol.gcode.codec import StatusReport

#: GRBL counts an empty buffer as 128 or 127 free (its ring buffer): a byte of slack.
SLACK_BYTES = 1


class QueryMarks:
    """Which lines were written before each ``?`` (kept under the feeder's lock)."""

    def __init__(self) -> None:
        self._written = 0
        self._marks: deque[int] = deque()

    def wrote(self, lines: int) -> None:
        self._written += lines

    def asked(self) -> None:
        """A ``?`` goes on the wire now, behind every line written so far."""
        self._marks.append(self._written)

    def seen(self, lengths: list[int]) -> Held | None:
        """A report read: what the board must hold, from the oldest ``?`` not yet matched.

        ``lengths``: the lines unanswered now, oldest first.  One mark a report, oldest
        first: the board makes one report for one or more ``?`` (several in one control
        cycle make one; one lost on the way makes none), so a report is never matched with
        a ``?`` later than the one it answers, only earlier (fewer lines written before
        it: a wider range).  Only a report the board never made for a ``?`` (a report
        repeated on the way) would shift the matches later.
        """
        if not self._marks:
            return None
        after = self._written - self._marks.popleft()
        before = lengths[: max(0, len(lengths) - after)]
        return Held(before, sum(lengths[len(before) :]))


class Held:
    """The lines a report's board must hold: ``before`` (unanswered, written before its
    ``?``, oldest first) and up to ``after_bytes`` of those written after it."""

    def __init__(self, before: list[int], after_bytes: int) -> None:
        self.before = before
        self.after_bytes = after_bytes

    def short(self, held: int) -> int | None:
        """Bytes missing from ``held`` (None: none, or only lines answered unheard)."""
        tails = [sum(self.before[k:]) for k in range(len(self.before) + 1)]
        if len(tails) < 3 or held >= tails[1] - SLACK_BYTES:
            return None  # at most the oldest line out of the buffer (parsed): healthy
        for tail in tails[2:]:  # OKs lost on the way back: whole lines gone from the front
            if tail - SLACK_BYTES <= held <= tail + self.after_bytes + SLACK_BYTES:
                return None
        return tails[1] - held


class ShortfallWatch:
    """Stops a board whose buffer holds fewer bytes than the lines it must hold."""

    def __init__(self, rx_buffer: int) -> None:
        self._rx_buffer = rx_buffer

    def judge(self, report: StatusReport, held_lines: Held | None) -> int | None:
        """The bytes missing from the board's buffer (None: none, or not known)."""
        if report.rx_free is None or held_lines is None:
            return None
        return held_lines.short(self._rx_buffer - report.rx_free)
