"""How the job runner feeds a program to a G-code machine, and what counts as done there.

A G-code device answers a line when it has *planned* it, not when it has
moved: with character counting a dozen answered lines may still wait in its
planner.  So two boundaries are kept:

* **answered** — operations whose line got its ``ok``: the progress bar;
* **executed** — operations known to have run: every answered line except as
  many lines, counted back from the last answered one, as the status report
  says blocks are still planned (``Bf:`` free blocks against the idle figure).
  Any line may hold a block (the plotter plans its pen changes too; GRBL
  answers a spindle change only once the planner has drained, and an arc is
  one line but many blocks), so counting every line as one block can make the
  boundary lag, never lead.  A device that does not report its planner (GRBL's
  default ``$10=1`` leaves ``Bf:`` out) is read by where it stands instead:
  the first answered operation whose stretch of path holds the reported
  position is the one under way, so every one before it has run (the first,
  so a path that comes back over itself can only make the boundary lag; the
  file's first move, whose start is wherever the machine stood, counts only
  from its end).

The checkpoint holds the executed boundary.  When the link comes back (or the
station restarts) the runner first looks at the machine: standing idle where
the last answered operation ends means every answered line ran, and the job
carries on after it — nothing repeated, nothing skipped; anywhere else (the
device was reset and lost its planner) it carries on after the executed
boundary, re-sending the few lines that may not have run.  Before the first
line goes again the machine is put back into the state the program had
there: pen up, absolute move to the position, then the pen, distance mode and
feed of that point.
"""

from __future__ import annotations

import math
import re
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from app.jobs.program import Operation, OpKind, Program, ProgramPath
from app.jobs.render.gcode import feed_for, render_operation
from app.machines.gcode.session import SentLine
from app.profiles import GcodeSettings, MachineProfile
from protocol.gcode.words import scan_words


@dataclass(frozen=True)
class AtReport:
    """The stream as a status report was read: the answered boundary, and lines pending."""

    answered: int
    pending: bool


#: Position agreement (mm) for "the machine stands where the last answered line ends".
AT_POSITION_MM = 0.01


@dataclass(frozen=True)
class ResumeState:
    """The machine state the program expects just before an operation."""

    position: dict[str, float]
    pen_down: bool
    relative: bool = False
    feed: float | None = None


def resume_state(program: Program, index: int, axes: Sequence[str]) -> ResumeState:
    """Where the machine should be, and how set up, before operation ``index`` runs.

    Programs that know their modal state (G-code files: distance mode, feed)
    say so through ``resume_state``; for the others it is read from the path.
    """
    own = getattr(program, "resume_state", None)
    if callable(own):
        state = own(index)
        if isinstance(state, ResumeState):
            return state
    path = program.path(axes)
    upto = int(np.searchsorted(path.ops, index, side="left"))
    position: dict[str, float] = {}
    if upto:
        row = path.coords[upto - 1]
        position = {a: float(v) for a, v in zip(axes, row, strict=True) if not math.isnan(v)}
    downs = program.indices_of(OpKind.PEN_DOWN)
    ups = program.indices_of(OpKind.PEN_UP)
    last_down = downs[np.searchsorted(downs, index) - 1] if np.searchsorted(downs, index) else -1
    last_up = ups[np.searchsorted(ups, index) - 1] if np.searchsorted(ups, index) else -1
    return ResumeState(position, pen_down=bool(last_down > last_up))


#: What a G92 line has (searched from its literal ``G``, as the unit words are: a bare
#: ``92`` also found every coordinate ending in 92, 30 000 lines of a million-line plotter
#: file, each then made a string and read), or a unit word (G20/G21: a G92 under G20 is in
#: inches); a hit in a comment is told apart by its words.
_G92_TEXT = (
    re.compile(r"G[ \t0]*92(?![0-9])"),
    re.compile(r"g[ \t0]*92(?![0-9])"),
    re.compile(r"G[ \t0]*2[01](?![0-9])"),
    re.compile(r"g[ \t0]*2[01](?![0-9])"),
)
#: Millimetres an inch; the axes G20 scales (A B C are degrees).
_INCH_MM = 25.4
_LINEAR = frozenset("XYZUVW")


def _position_before(
    program: Program, path: ProgramPath | None, index: int, axes: Sequence[str]
) -> np.ndarray:
    """Where the program stands before operation ``index`` (NaN where it is not known)."""
    data = getattr(program, "data", None)
    if path is None and data is not None and index > 0:
        row: np.ndarray = data.column_values(data.positions[index - 1 : index], axes)[0]
        return row
    if path is None:
        return np.full(len(axes), np.nan)
    first = int(np.searchsorted(path.ops, index, side="left"))
    return path.coords[first - 1] if first else np.full(len(axes), np.nan)


def texts_matching(
    texts: Sequence[str], patterns: Sequence[re.Pattern[str]], stop: int
) -> list[int]:
    """Indices before ``stop`` of the texts any of ``patterns`` finds something in, in order.

    A resume or a start part-way on a file of a million lines must not hold
    the GUI thread: a G-code file's texts are searched in its bytes at once
    (:meth:`~app.jobs.formats.gcode.sent_texts.SentTexts.matching`), others in
    one regex pass a pattern over their joined text.
    """
    find = getattr(texts, "matching", None)
    if callable(find):
        found: list[int] = find(patterns, stop)
        return found
    joined = "\n".join(texts[:stop])
    hits: set[int] = set()
    for pattern in patterns:
        line, at = 0, 0
        for hit in pattern.finditer(joined):
            line += joined.count("\n", at, hit.start())
            at = hit.start()
            hits.add(line)
    return sorted(hits)


def file_offset(program: Program, index: int, axes: Sequence[str]) -> dict[str, float]:
    """The file's own ``G92`` offset in force before operation ``index``, per axis.

    As the loader applies it (GRBL's rule: program position minus the value
    given; ``G92.1`` clears it; a bare ``G92``, where the machine takes it, calls
    here 0), in the program's coordinates, so that program position minus it
    is the file's work position.  0 for programs that are not G-code files.
    A ``G92`` under ``G20`` is read in inches, as the loader reads it.
    """
    offset = dict.fromkeys(axes, 0.0)
    data = getattr(program, "data", None)
    texts = getattr(data, "sent", None)  # the texts made as read (not all kept as str)
    if not isinstance(texts, Sequence) or isinstance(texts, str) or index <= 0:
        return offset
    candidates = texts_matching(texts, _G92_TEXT, index)
    if not candidates:
        return offset
    path = None if hasattr(data, "positions") else program.path(axes)
    scale = 1.0
    for k in candidates:
        words = scan_words(texts[k])
        codes = {v for w, v in words if w == "G"}
        if 20.0 in codes or 21.0 in codes:
            scale = _INCH_MM if 20.0 in codes else 1.0
        if 92.1 in codes:
            offset = dict.fromkeys(axes, 0.0)
            continue
        if 92.0 not in codes:
            continue
        here = _position_before(program, path, k, axes)
        given = {w: v for w, v in words if w in offset}
        for i, axis in enumerate(axes):
            where = 0.0 if math.isnan(here[i]) else float(here[i])
            if axis in given:
                offset[axis] = where - given[axis] * (scale if axis in _LINEAR else 1.0)
            elif not given:
                offset[axis] = where  # a bare G92: here is the origin
    return offset


#: On a cylindrical machine (the string-art winder) axes go back one at a time: the tool
#: out of the board first, then the radius, then the turn — so a needle stopped between
#: two nails retraces its way instead of turning through the nail ring.
CYLINDRICAL_ORDER = ("Z", "X", "A")


#: How far (mm or degrees, in axis space) the machine may stand off the program's path for
#: the way back to follow it.
ON_PATH = 0.05
#: Operations after the resume point the machine may have run when nobody knows what was
#: sent (a checkpoint after an abort or a restart): the session's queue and the device's.
RETRACE_WINDOW = 64


def retrace(
    program: Program, axes: Sequence[str], start: int, upto: int, mpos: Sequence[float]
) -> list[dict[str, float]]:
    """The program's own path back from where the machine stands to where ``start`` begins.

    The machine stopped somewhere on the segments of operations ``start … upto - 1``
    (they may have run without their answers getting back; after a restart, when what
    was sent is unknown, ``upto`` is a window of :data:`RETRACE_WINDOW` operations).
    Going back along them, vertex by vertex, only travels where the machine has just
    been: on the winder that never turns the base with the needle among the nails.
    Empty when the machine is
    not on that stretch of path (then the caller goes straight, axis by axis).
    """
    path = program.path(axes)
    first = int(np.searchsorted(path.ops, start, side="left"))
    last = int(np.searchsorted(path.ops, upto, side="left"))
    if first == 0 or last <= first - 1:
        return []
    vertices = path.coords[first - 1 : last]  # the position before ``start``, then each end
    here = np.array([mpos[i] if i < len(mpos) else np.nan for i in range(len(axes))])
    known = ~np.isnan(here) & ~np.isnan(vertices).any(axis=0)

    def on(k: int) -> bool:
        a, b = vertices[k][known], vertices[k + 1][known]
        span = b - a
        length2 = float(span @ span)
        t = 0.0 if length2 == 0 else min(max(float((here[known] - a) @ span) / length2, 0.0), 1.0)
        return float(np.linalg.norm(a + t * span - here[known])) <= ON_PATH

    # The first stretch of segments the machine stands on (it cannot have gone further
    # than it must), to its far end: standing at a corner is standing on the next segment.
    best = next((k for k in range(len(vertices) - 1) if on(k)), -1)
    if best < 0:
        return []
    while best + 1 < len(vertices) - 1 and on(best + 1):
        best += 1
    return [
        {axis: float(v) for axis, v in zip(axes, vertices[k], strict=True) if not np.isnan(v)}
        for k in range(best, -1, -1)
    ]


def preamble(
    state: ResumeState,
    settings: GcodeSettings,
    way_back: Sequence[dict[str, float]] = (),
    restore: Sequence[str] = (),
) -> list[str]:
    """Lines that put the machine into ``state`` without drawing or crossing on the way.

    ``way_back`` (see :func:`retrace`) is followed when given; otherwise the machine
    goes straight there — on the winder one axis at a time.  ``restore`` goes out
    once it is there (the work offset a reset took, set again).
    """
    # In millimetres where the machine has G21: the way back's numbers are (a file's G20
    # would have them read as inches); the file's own units follow (start_point.py).
    lines = [settings.pen_up, "G90 G21" if "G21" in settings.words else "G90"]
    if way_back:
        lines += ["G0 " + " ".join(f"{a}{v:.3f}" for a, v in point.items()) for point in way_back]
    elif state.position and settings.kinematics == "cylindrical":
        ordered = [a for a in CYLINDRICAL_ORDER if a in state.position]
        ordered += [a for a in state.position if a not in ordered]
        lines += [f"G0 {a}{state.position[a]:.3f}" for a in ordered]
    elif state.position:
        lines.append("G0 " + " ".join(f"{a}{v:.3f}" for a, v in state.position.items()))
    lines += restore
    if state.pen_down:
        lines.append(settings.pen_down)
    if state.relative:
        lines.append("G91")
    if state.feed is not None:
        lines.append(f"F{state.feed:g}")  # the feed alone: the motion mode is the file's
    return lines


class GcodeStream:
    """The runner's view of a program being streamed: what to send next, what is done.

    Plain Python on purpose: the runner owns the Qt signals and the job state;
    this object only keeps the bookkeeping between the session's lines and the
    program's operations.  It is the running job's line source
    (:class:`~app.machines.gcode.job_feed.JobSource`): the job's feed takes its
    lines (:meth:`next_lines`) and counts their answers (:meth:`count_answer`),
    on the transport's reader thread while the job is pulled, so every use
    holds the feed's lock (:meth:`~app.machines.gcode.job_feed.JobFeed.locked`).
    """

    def __init__(self, program: Program, profile: MachineProfile, start: int) -> None:
        if profile.gcode is None:
            raise ValueError(f"{profile.title} is not a G-code machine")
        self.program = program
        self.profile = profile
        self.settings: GcodeSettings = profile.gcode
        self._axis_order = tuple(axis.name for axis in profile.axes)
        self.next_index = start  # the next operation to hand to the session
        self.answered = start  # operations [0, answered) have their ok
        self.executed = start  # operations [0, executed) are known to have run
        self.written = start  # operations [0, written) went out on the wire
        #: Operations sent and not yet answered, in order.
        self.pending: deque[int] = deque()
        #: Answered lines' operations not known executed, in order (the planner's share).
        self._planned: deque[int] = deque()
        self._answered_at_last_report = start
        #: The operation whose line could not go, and why (the job fails there).
        self.refused: tuple[int, str] | None = None
        #: A start part-way in an arc mode: the operation whose line gets that motion word in
        #: front (see :mod:`app.jobs.run.start_point`).
        self.lead: tuple[int, str] | None = None

    # --- what to send --------------------------------------------------------

    def line_for(self, index: int, op: Operation | None = None) -> str | None:
        """The text of operation ``index`` (``op``, when the caller has it) for this machine,
        None when nothing is sent.

        A G-code file's line goes as written; other programs' moves are rendered at
        their slowest axis's top speed, in the profile's axis order.
        """
        if op is None:
            op = self.program[index]
        if op.line:
            return render_operation(op, self.settings)
        return render_operation(
            op, self.settings, feed_for(op.target, self.profile), axis_order=self._axis_order
        )

    def next_lines(self, count: int) -> list[tuple[int, str]]:
        """The next lines to send, at most ``count``, each with its operation's index: taken
        (pending their answer).  The pulled job and a single step both take them here.

        Stops before a WAIT (:attr:`waiting_at`), at the end, and after a line that
        could not go (:attr:`refused`: nothing is taken from there on).  Operations
        that send nothing are done when everything before them is.
        """
        out: list[tuple[int, str]] = []
        if self.refused is not None:
            return out
        program, pending = self.program, self.pending
        while len(out) < count and self.next_index < len(program):
            index = self.next_index
            kind, line = program.kind_and_line(index)
            if kind is OpKind.WAIT:
                break
            # A line as written goes as it is (render_operation's first answer); only the
            # others are rendered, from an operation built for them.
            text = line if line and kind is not OpKind.COMMENT else self.line_for(index)
            if self.lead is not None and self.lead[0] == index and text is not None:
                text = f"{self.lead[1]} {text}"
            self.next_index += 1
            if text is None:
                if not pending:
                    self.answered = self.executed = index + 1
                continue
            pending.append(index)
            out.append((index, text))
        return out

    def refuse(self, index: int, why: str) -> None:
        """Operation ``index``'s line, taken, cannot be sent: the job fails there once every
        line before it is answered (it and the lines taken after it go back)."""
        self.take_back(index)
        self.refused = (index, why)

    @property
    def waiting_at(self) -> int | None:
        """The WAIT the stream has come to (nothing after it goes before the operator)."""
        index = self.next_index
        if index < len(self.program) and self.program[index].kind is OpKind.WAIT:
            return index
        return None

    # --- replies -------------------------------------------------------------

    def count_answer(self, sent: SentLine) -> bool:
        """An ``ok`` read for ``sent``: counted when it is this job's line (the feeder asks)."""
        return sent.origin == "job" and self.acknowledge(sent)

    def reported(self) -> AtReport:
        """The stream as a status report is read (the feeder's snapshot for :meth:`status`)."""
        return AtReport(self.answered, bool(self.pending))

    def acknowledge(self, sent: SentLine) -> bool:
        """An ``ok`` for a job line; False when it is not the one expected (not ours)."""
        if sent.op_index is None or not self.pending or self.pending[0] != sent.op_index:
            return False
        index = self.pending.popleft()
        # Everything up to the next pending line is answered: comments between count too.
        upto = self.pending[0] if self.pending else self.next_index
        self.answered = upto
        self._planned.append(index)
        return True

    def status(
        self,
        state: str,
        planner_free: int | None,
        planner_size: int,
        mpos: Sequence[float] | None = None,
        seen: AtReport | None = None,
    ) -> None:
        """A status report: advance the executed boundary as far as it proves.

        ``planner_size`` is what the device reported free when idle (0: unknown,
        then only an idle machine with nothing pending, or ``mpos`` on the path
        of an answered operation, proves anything).  ``seen``: the stream as the
        report was read (:meth:`reported`; None: now) — lines answered after it
        was read may not have run, whatever it says.
        """
        if seen is None:
            seen = self.reported()
        if state == "Idle" and not seen.pending:
            while self._planned and self._planned[0] < seen.answered:
                self._planned.popleft()
            self.executed = max(self.executed, seen.answered)
        elif (planner_free is None or not planner_size) and mpos is not None:
            answered = self._answered_at_last_report
            for k, index in enumerate(self._planned):
                if index >= answered:
                    break
                if self._stands_on(index, mpos):
                    for _ in range(k):
                        self._planned.popleft()
                    self.executed = index
                    break
        elif planner_free is not None and planner_size:
            in_planner = max(planner_size - planner_free, 0)
            answered = self._answered_at_last_report
            # Lines answered before this report was asked for, minus what is still planned.
            ran = [i for i in self._planned if i < answered]
            finished = len(ran) - in_planner
            for _ in range(max(finished, 0)):
                self._planned.popleft()
            self.executed = self._planned[0] if self._planned else self.answered
        self._answered_at_last_report = seen.answered

    def _stands_on(self, index: int, mpos: Sequence[float]) -> bool:
        """Whether ``mpos`` lies on operation ``index``'s stretch of path (or its point)."""
        path = self.program.path(self._axis_order)
        first = int(np.searchsorted(path.ops, index, side="left"))
        last = int(np.searchsorted(path.ops, index, side="right"))
        # The file's first move starts wherever the machine stood: only its end is known.
        vertices = path.coords[max(first - 1, 0) : max(last, first)]
        if len(vertices) == 0:
            return False  # a line before any move holds no position
        count = min(len(mpos), vertices.shape[1])
        here = np.array([float(mpos[i]) for i in range(count)])
        for k in range(len(vertices)):
            a = vertices[k][:count]
            b = vertices[min(k + 1, len(vertices) - 1)][:count]
            known = ~(np.isnan(a) | np.isnan(b))
            if not known.any():
                continue
            a, b, point = a[known], b[known], here[known]
            span = b - a
            length2 = float(span @ span)
            t = 0.0 if length2 == 0 else min(max(float((point - a) @ span) / length2, 0.0), 1.0)
            if float(np.linalg.norm(a + t * span - point)) <= ON_PATH:
                return True
        return False

    @property
    def in_flight(self) -> bool:
        return bool(self.pending)

    @property
    def sent_all(self) -> bool:
        return self.next_index >= len(self.program) and not self.pending

    def take_back(self, index: int) -> None:
        """Lines from operation ``index`` on were taken back unsent: send them again later."""
        while self.pending and self.pending[-1] >= index:
            self.pending.pop()
        self.next_index = min(self.next_index, index)

    def note_written(self, index: int) -> None:
        """Operation ``index``'s line left for the device (it may run without an answer back)."""
        self.written = max(self.written, index + 1)

    def stands_after(
        self,
        mpos: Sequence[float],
        lo: int,
        hi: int,
        start: Sequence[float] | None = None,
    ) -> int | None:
        """For an idle machine at ``mpos`` that ran operations in order, at most ``[0, hi)``
        and at least ``[0, lo)``: the first operation it cannot have run, when its position
        proves it; None when it does not.

        The device runs what it received in order, so an idle machine stands
        where the last operation it ran leaves it.  Only a place known for
        certain counts (before the file's first move the machine stood wherever
        it was), and only one place: a path that passes the same point twice
        among the candidates leaves it open whether the loop between ran (the
        lines may have been lost on the wire), so it proves nothing.  Operations
        that do not move (a pen change) share the place of the move before them:
        the earliest is taken, so one is sent again rather than skipped (the way
        back sets the pen anyway).  ``start`` is where the machine stood when the
        job began, when known: standing there again fits "nothing moved yet" too,
        so a file that ends where it began (a plot back home) proves nothing there.
        """
        path = self.program.path(self._axis_order)
        count = min(len(mpos), path.coords.shape[1]) if len(path) else 0
        here = np.array([float(mpos[i]) for i in range(count)])
        places: set[int] = set()
        first: int | None = None
        for end in range(lo, hi + 1):
            # Vertices before operation ``end``: its place is the last of them.
            vertex = int(np.searchsorted(path.ops, end, side="left"))
            if vertex == 0:
                # Before any move the machine stands where the job found it.
                if start is not None and _near(start, here, count):
                    places.add(0)
                    first = end if first is None else first
                continue
            expected = path.coords[vertex - 1][:count]
            known = ~np.isnan(expected)
            if not known.any() or float(np.max(np.abs(expected[known] - here[known]))) > (
                AT_POSITION_MM
            ):
                continue
            # Moves in a row that end at the same point (a move of nothing, one of another
            # axis) are one place: standing there the machine has not gone away and back.
            while vertex > 1 and np.array_equal(
                path.coords[vertex - 2][:count], path.coords[vertex - 1][:count], equal_nan=True
            ):
                vertex -= 1
            places.add(vertex)
            first = end if first is None else first
        return first if len(places) == 1 else None

    def draws_between(self, lo: int, hi: int) -> bool:
        """Whether any operation in ``[lo, hi)`` moves with the pen down (a stroke).

        Pen changes and pen-up travel sent again draw nothing; a stroke may.
        """
        if hi <= lo:
            return False
        works = self.program.works_between(lo, hi)
        if works is not None:
            return works
        path = self.program.path(self._axis_order)
        first = int(np.searchsorted(path.ops, lo, side="left"))
        last = int(np.searchsorted(path.ops, hi, side="left"))
        return bool(path.pen[first:last].any())

    def rewind(self, index: int) -> None:
        """Forget everything unanswered; the next line sent is operation ``index``."""
        self.pending.clear()
        self._planned.clear()
        self.written = index
        self.next_index = self.answered = self.executed = index
        self._answered_at_last_report = index


def _near(start: Sequence[float], here: np.ndarray, count: int) -> bool:
    """Whether ``here`` is the place ``start`` (the axes both know, within AT_POSITION_MM)."""
    axes = min(count, len(start))
    return axes > 0 and all(
        abs(float(start[i]) - float(here[i])) <= AT_POSITION_MM for i in range(axes)
    )
