"""The pen of a GRBL servo plotter, supervised from the spindle state its reports show.

No wire here carries a checksum: an ``M3 S1000`` lost on the way draws nothing
of the row after it, an ``M5`` changed into ``M4`` draws the travel after it.
The positions a board reports cannot show that (the pen is where it should
be, only not down), but GRBL 1.1 reports its spindle — the servo — in the
``A:`` field of the reports that carry ``Ov:``
(:mod:`protocol.gcode.accessories` has what GRBL does, to the line of its
source).  So the watch follows every line written as GRBL would run it, and
judges a report only where the lines imply one state for it:

* the state is the one left by the lines answered ``ok`` (GRBL synchronises
  before a spindle change, so the ``ok`` of a pen line means the pen moved); a
  pen line written and not yet answered may or may not have run, so no report
  is judged while one is on its way (a refused line runs not);
* until a pen line or a reset is proven the state is not known (a board
  found running, a link that dropped lines): nothing is judged;
* a report without ``Ov:`` says nothing of the spindle; a board whose
  reports never carry it (other firmware) is never judged;
* GRBL 1.1 writes ``Ov:`` (and ``A:``) in the first report after a spindle
  change — the second when the first carries ``WCO:``.  So once a pen line
  that changes the spindle is answered, on a board that has said it is
  GRBL 1.1 and shown ``Ov:``, two reports without ``Ov:`` after it say the
  change never happened: the line that came was not the line sent.

A report against the lines stops the machine as the motion supervision does
(:meth:`stop_for_fault`: feed hold, then the soft reset), naming the line.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.machines.gcode.lines import SentLine
from app.profiles import GcodeSettings
from protocol.gcode.accessories import (
    AT_RESET,
    UNKNOWN,
    Spindle,
    SpindleWords,
    reported_spindle,
    spindle_words,
)
from protocol.gcode.codec import StatusReport


def _pen(state: str) -> str:
    if state == "":
        return QCoreApplication.translate("PenWatch", "up")
    return QCoreApplication.translate("PenWatch", "down")


def _board(state: str) -> str:
    if state == "S":
        return QCoreApplication.translate(
            "PenWatch", "the spindle (the pen servo) on, clockwise (A:S)"
        )
    if state == "C":
        return QCoreApplication.translate(
            "PenWatch", "the spindle (the pen servo) on, counter-clockwise (A:C)"
        )
    return QCoreApplication.translate("PenWatch", "the spindle (the pen servo) off")


def mismatch_text(expected: str, seen: str, line: str | None, *, unreported: bool = False) -> str:
    """The stop's message: the pen as it is, the line run (None: the board's reset), what
    the board reports."""
    ran = (
        repr(line)
        if line is not None
        else QCoreApplication.translate("PenWatch", "the board's reset")
    )
    if unreported:
        return QCoreApplication.translate(
            "PenWatch",
            "Machine stopped: the pen is {0} after {1} ran (pen {2} sent), but the board did "
            "not report the change it makes; the line it got was not the line sent",
        ).format(_pen(seen), ran, _pen(expected))
    return QCoreApplication.translate(
        "PenWatch",
        "Machine stopped: the pen is {0} after {1} ran (pen {2} sent): the board reports {3}",
    ).format(_pen(seen), ran, _pen(expected), _board(seen))


def sync_text(line: SentLine) -> str:
    """What a report short of a proven pen line says (the motion supervision's stop)."""
    return QCoreApplication.translate(
        "PenWatch",
        "{0} counted as answered while the moves before it still ran (GRBL answers a pen "
        "line only once they are done): a line or an answer was lost, changed or repeated "
        "on the way.",
    ).format(repr(line.text))


#: Reports in which GRBL's spindle reports nothing to compare (it is stopped or not running).
_NOT_JUDGED = ("Alarm", "Door", "Sleep", "Check", "Home")


def pen_is_spindle(settings: GcodeSettings) -> bool:
    """The profile's pen is the spindle: ``pen_down`` turns it on, ``pen_up`` off."""
    down = AT_RESET.after(spindle_words(settings.pen_down))
    return down.seen in ("S", "C") and down.after(spindle_words(settings.pen_up)).seen == ""


@dataclass(frozen=True)
class PenMismatch:
    """A report against the lines: what was expected, what the board said, and the line."""

    expected: str
    seen: str
    line: SentLine | None
    #: The board did not report a change at all (no ``Ov:`` where GRBL must send it).
    unreported: bool = False

    @property
    def op_index(self) -> int | None:
        return None if self.line is None else self.line.op_index

    def text(self) -> str:
        """The operator's message: the pen, the line, what the board reports."""
        line = None if self.line is None else self.line.text
        return mismatch_text(self.expected, self.seen, line, unreported=self.unreported)


class PenWatch:
    """The spindle state the lines written imply, against the board's ``A:`` (GUI thread)."""

    def __init__(self, settings: GcodeSettings, next_leg: Callable[[], int] | None = None) -> None:
        #: Only a profile whose pen is the spindle is watched.
        self.enabled = pen_is_spindle(settings)
        #: The serial of the next leg of the motion supervision's path (Envelope.next_serial).
        self._next_leg = next_leg
        #: Pen changes proven since the last report, each with the first leg after it: GRBL
        #: ran every move before it first (spindle_sync), so the machine is past them.
        self.synced: list[tuple[SentLine, int]] = []
        #: The state the lines answered leave (UNKNOWN until a pen line or reset is proven).
        self._settled: Spindle = UNKNOWN
        #: The last line answered that set what ``A:`` shows, for the message.
        self._settled_by: SentLine | None = None
        #: Lines written and not yet answered, in the order they went, with their words.
        self._in_flight: deque[tuple[SentLine, SpindleWords, int]] = deque()
        #: Answers heard before their line's note of writing (the two threads' order).
        self._early: set[SentLine] = set()
        #: A board that said it is GRBL 1.1 and has shown Ov: (the refresh rule holds).
        self._grbl11 = False
        self._ov_seen = False
        #: A pen line answered whose change GRBL must report: the line, the reports since,
        #: and what ``A:`` showed before it.
        self._refresh_due: tuple[SentLine, int, str] | None = None

    # --- the lines --------------------------------------------------------------------

    def written(self, raw: bytes, sent: SentLine) -> None:
        """A line gone on the wire (its bytes as written), before its path is added."""
        if not self.enabled:
            return
        words = spindle_words(raw.decode("ascii", errors="replace"))
        mark = 0 if self._next_leg is None else self._next_leg()
        if sent in self._early:
            self._early.discard(sent)
            self._ran(sent, words, mark)
            return
        self._in_flight.append((sent, words, mark))

    def answered(self, sent: SentLine, ok: bool) -> None:
        """The board's answer to ``sent``: ``ok`` ran it, an ``error:`` did not."""
        if not self.enabled:
            return
        if all(entry[0] != sent for entry in self._in_flight):
            if ok:
                self._early.add(sent)
            return
        while self._in_flight:
            line, words, mark = self._in_flight.popleft()
            if line == sent and not ok:
                return  # refused: it runs not
            self._ran(line, words, mark)  # an earlier one whose answer was not told here: ran
            if line == sent:
                return

    def _ran(self, line: SentLine, words: SpindleWords, mark: int) -> None:
        if not words.touches:
            return
        before = self._settled
        self._settled = before.after(words)
        if self._settled.seen != before.seen or self._settled_by is None:
            self._settled_by = line
        if before.refreshes(words):
            self._refresh_due = (line, 0, before.seen or "")
            if self._next_leg is not None:
                self.synced.append((line, mark))

    def reset(self) -> None:
        """The board is being reset: the lines unanswered are gone; its state is known again
        from its banner."""
        self.synced.clear()
        self._settled = UNKNOWN
        self._settled_by = None
        self._in_flight.clear()
        self._early.clear()
        self._refresh_due = None

    def restarted(self, banner: str) -> None:
        """A banner: the board (re)started, its spindle off and S0 (GRBL's ``gc_init``).

        The lines before it were forgotten with the reset (:meth:`reset`); those noted as
        written since (the reader thread sends what waited for the banner as it reads it)
        went after it and stay on their way."""
        self._settled = AT_RESET
        self._settled_by = None
        self._refresh_due = None
        self.synced.clear()
        self._grbl11 = banner.startswith("Grbl 1.1")

    def alarmed(self) -> None:
        """An alarm stops the spindle (``mc_reset``); the lines on their way are refused."""
        self.reset()
        self._settled = AT_RESET if self.enabled else UNKNOWN

    def lines_lost(self) -> None:
        """The link dropped lines that may or may not have run: nothing is known."""
        self.reset()

    # --- the reports ------------------------------------------------------------------

    def judge(
        self, report: StatusReport, reached: Callable[[int], bool] | None = None
    ) -> PenMismatch | None:
        """A report against what the lines answered leave, where they leave one state.

        ``reached(mark)``: whether the report, placed on the path, may be past every move
        before the leg numbered ``mark`` (None: not placed).  A pen line on its way runs
        only once the moves before it are done, so one the machine has not reached cannot
        have run, nor anything after it."""
        if not self.enabled or report.state in _NOT_JUDGED:
            return None
        fields = report.fields
        self._ov_seen = self._ov_seen or "Ov" in fields
        unreported = self._unreported(fields)
        if unreported is not None:
            return unreported
        expected = self._settled.seen
        if expected is None:
            return None
        state = self._settled
        for _line, words, mark in self._in_flight:
            if words.touches and reached is not None and not reached(mark):
                break  # a move before this pen line is still ahead: it (and what follows) waits
            state = state.after(words)
            if state.seen != expected:
                return None  # a pen line on its way: it may have run or not
        seen = reported_spindle(fields)
        if seen is None or seen == expected:
            return None
        mismatch = PenMismatch(expected, seen, self._settled_by)
        self._settled = UNKNOWN  # one stop, one message: known again after the reset
        return mismatch

    def _unreported(self, fields: Mapping[str, str]) -> PenMismatch | None:
        """No ``Ov:`` in the first report after a spindle change (the second after WCO:).

        Every report read after the line's ``ok`` was made after the change, whatever
        lines are on their way since (GRBL answers a pen line straight after the change)."""
        due = self._refresh_due
        if due is None:
            return None
        line, reports, before = due
        if "Ov" in fields:
            self._refresh_due = None
            return None
        if "WCO" in fields and reports == 0:
            self._refresh_due = (line, 1, before)
            return None
        self._refresh_due = None
        expected = self._settled.seen
        if not (self._grbl11 and self._ov_seen) or expected is None or expected == before:
            return None
        # Nothing changed on the board: it still shows what the lines before left.
        mismatch = PenMismatch(expected, before, line, unreported=True)
        self._settled = UNKNOWN
        return mismatch
