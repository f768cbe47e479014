"""Answers lost on the wire: an ``ok`` that never came would stall the stream for ever.

GRBL answers every line once it has parsed it, so when its reports show the
receive buffer empty (``Bf:…,<all free>``), the planner empty and the machine
idle, reports in a row and some time apart, every line sent was taken and
answered: the missing answers were lost, and the lines count as answered.  A
line that pauses the board is waited for as long as it may (a dwell its
time, a program stop for ever); a board that reports no ``Bf:`` cannot show
this: the operator is told the stream waits, and a board still idle a while
later is reset (it stands: its position stays) and the job goes on from proof.

Plain Python: the watch only judges; the session acts on its verdict (it
acknowledges the lines, or says the stream waits).  It runs on the GUI thread,
from the status reports the session applies.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from app.machines.gcode.lines import SentLine
from protocol.gcode.codec import StatusReport

#: After the operator is told the stream waits, a board without ``Bf:`` still idle this much
#: longer (plus every dwell unanswered) is reset: nothing it could say would show more.
UNSEEN_RESET_AFTER_S = 2.0
#: Reports in a row, at least this far apart, that show every sent byte consumed and the
#: machine idle with an empty planner while lines are unanswered: their answers were lost.
LOST_ANSWER_REPORTS = 2
LOST_ANSWER_AFTER_S = 0.5
_COMMENT = re.compile(r"\([^)]*\)|;.*")
_WORD = re.compile(r"([GM])\s*([-+]?\d+(?:\.\d*)?)")


@dataclass(frozen=True)
class AnswersLost:
    """The board has taken and run these lines: their answers were lost (oldest first)."""

    lines: list[SentLine]


@dataclass(frozen=True)
class Unaccounted:
    """A board without ``Bf:`` has stood idle so long with lines unanswered that none can
    still be on its way: lost on the wire, answers or lines, or a fragment in its buffer."""

    count: int


@dataclass(frozen=True)
class StreamWaits:
    """Lines stay unanswered while the board stands idle, and nothing shows it has them."""

    count: int


class LostAnswerWatch:
    """Follows drained reports while lines stay unanswered; says when their answers are lost."""

    def __init__(self, rx_buffer: int) -> None:
        self._rx_buffer = rx_buffer
        #: Since when (station clock) reports show the board done with everything sent, while
        #: lines are unanswered, and how many reports in a row have.
        self._drained_since: float | None = None
        self._drained_reports = 0
        #: The lines unanswered through every drained report so far.
        self._candidates: list[SentLine] = []
        self._stall_told = False

    def forget(self) -> None:
        """The run of drained reports ends (the board is reset and looked at again)."""
        self._drained_since, self._drained_reports = None, 0

    def answer_heard(self) -> None:
        """A reply came: a stall is told again if the stream stalls again."""
        self._stall_told = False

    def judge(
        self,
        report: StatusReport,
        unanswered: list[SentLine],
        planner_size: int,
        planner_empty: bool,
        now: float,
        stall_after_s: float,
    ) -> AnswersLost | Unaccounted | StreamWaits | None:
        """The verdict of one status report.

        ``stall_after_s``: unanswered this long with nothing to show the board has the
        lines, the operator is told (once until an answer comes).

        ``unanswered``: the lines unanswered when the report was read (the feeder's
        snapshot on the reader thread; lines written since went after the report).
        Only lines unanswered through every report of the run count as lost.
        """
        if self._drained_since is not None:
            unanswered = [sent for sent in unanswered if sent in self._candidates]
        if not unanswered or report.state != "Idle":
            self._drained_since, self._drained_reports = None, 0
            return None
        self._candidates = unanswered
        drained = (
            report.rx_free is not None
            and report.rx_free >= self._rx_buffer - 1
            and report.planner_free is not None
            and planner_size > 0
            and planner_empty
        )
        if self._drained_since is None:
            self._drained_since, self._drained_reports = now, 0
        self._drained_reports += 1
        waited = now - self._drained_since
        # A dwell keeps the board idle before its answer, but only as long as it lasts
        # (relay string-art seed 34: a G4 S0.25 among the lines a silence took kept the
        # job waiting for ever); a program stop, for as long as the operator takes.
        paused = paused_s(unanswered)
        if (
            drained
            and self._drained_reports >= LOST_ANSWER_REPORTS
            and (waited >= LOST_ANSWER_AFTER_S + paused)
        ):
            self._drained_since, self._drained_reports = None, 0
            return AnswersLost(unanswered)
        if (
            report.rx_free is None
            and self._drained_reports >= LOST_ANSWER_REPORTS
            and waited >= stall_after_s + UNSEEN_RESET_AFTER_S + paused
        ):
            # Without Bf: nothing shows whether the lines are in its buffer, on the wire
            # or run with their answers lost; idle this long, none is on its way (relay
            # string-art seed 34: a silence took lines whole, the job waited for ever).
            self._drained_since, self._drained_reports = None, 0
            return Unaccounted(len(unanswered))
        if (not drained or math.isinf(paused)) and waited >= stall_after_s and not self._stall_told:
            self._stall_told = True
            return StreamWaits(len(unanswered))
        return None


_DWELL = re.compile(r"([PS])\s*([-+]?\d+(?:\.\d*)?)")


def paused_s(lines: list[SentLine]) -> float:
    """How long ``lines`` may keep a board idle on their own: their dwells (a ``P`` taken as
    seconds, the longest reading), for ever with a program stop."""
    total = 0.0
    for sent in lines:
        code = _COMMENT.sub("", sent.text).upper()
        words = _WORD.findall(code)
        if any(letter == "M" and float(n) in (0, 1, 2, 30) for letter, n in words):
            return math.inf
        if any(letter == "G" and float(n) == 4 for letter, n in words):
            total += sum(float(v) for _, v in _DWELL.findall(code))
    return total
