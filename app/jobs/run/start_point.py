"""Starting a job part-way: the operation a chosen line starts at, and the machine state there.

Starting at a line the operator picks is a resume at a chosen point: the
operations before it count as run (the checkpoint says so from the first
answer on), and the machine must be put into the state the file had reached
there before the line goes, or the rest of the file runs in the wrong units,
the wrong distance mode, at the wrong feed, or with the pen up where it
should draw.  This module works that state out from the program alone, and
the lines that rebuild it; the G-code driver sends them after it has looked
at the machine, as a resume does (:mod:`app.jobs.run.gcode`).

What is rebuilt, from the file's own lines before the start:

* units (``G20``/``G21``), distance mode (``G90``/``G91``), plane
  (``G17``/``G18``/``G19``), feed (the last ``F``, in the units then in force);
* the motion mode (``G0``…``G3``): ``G0`` and ``G1`` are set on their own;
  ``G2``/``G3`` cannot be (GRBL refuses an arc without axis words, error:26),
  so the first move from the start that does not name its motion gets the
  arc's word in front of it — the same arc, now saying what it is;
* the file's own ``G92`` offset, set again once the machine stands at the
  start (``G92`` calling that place the file's work position there);
* the pen: lifted for the way there, lowered again at the start when the
  file had it down.

What is refused, with the line that makes it so (``file:line: reason``):

* a start beyond the end of the file, or at no operation;
* a coordinate system the file chose or changed (``G54``…``G59`` other than
  ``G54``, ``G10``), a stored position (``G28.1``/``G30.1``), a tool length
  offset (``G43.1``) or a probe (``G38.x``) before the start: the station's
  model of the file does not follow them, so where the machine should stand
  at the start is not known.  The operator starts before that line instead.

Pure: no wire, no Qt objects (only the translation of the reasons), so the
property tests can ask it anything.
"""

from __future__ import annotations

import math
import re
import threading
import weakref
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
from PySide6.QtCore import QCoreApplication

from app.jobs.program import OpKind, Program
from app.jobs.run.gcode_stream import (
    ResumeState,
    file_offset,
    preamble,
    resume_state,
    texts_matching,
)
from app.profiles import GcodeSettings
from protocol.gcode.words import scan_words

#: Lines that may change the modal state this module follows (a literal-ish search over
#: the text before the start; each hit is then read word by word).
_MODAL_CODES = r"[ \t0]*(?:1[789]|2[01]|9[01]|10|28\.1|30\.1|38|43|5[4-9])(?![0-9])"
MODAL_HINT = (re.compile("G" + _MODAL_CODES), re.compile("g" + _MODAL_CODES))
#: Motion words, and the codes they are.
_MOTION = {0.0: "G0", 1.0: "G1", 2.0: "G2", 3.0: "G3"}
#: Words that make the position at the start unknown to the station's model.
_UNFOLLOWED = {
    10.0: "G10",
    28.1: "G28.1",
    30.1: "G30.1",
    43.1: "G43.1",
    38.2: "G38.2",
    38.3: "G38.3",
    38.4: "G38.4",
    38.5: "G38.5",
    **{54.0 + k: f"G{54 + k}" for k in range(1, 6)},
    59.1: "G59.1",
    59.2: "G59.2",
    59.3: "G59.3",
}
INCH_MM = 25.4
#: File offsets smaller than this (mm) are none.
OFFSET_NONE_MM = 1e-9
#: Operations after the start looked at for the move that needs the arc's word.
LEAD_SCAN = 10_000


class StartRefused(ValueError):
    """The job cannot start there; the text says where (file:line) and why."""


@dataclass(frozen=True)
class ModalState:
    """The state the file has reached just before its start operation."""

    #: Where the machine stands (program coordinates, mm), and whether the pen is down.
    resume: ResumeState
    inches: bool = False
    relative: bool = False
    plane: int = 17
    #: The motion mode in force (``G0``…``G3``), None when the file set none yet.
    motion: str | None = None
    #: The feed in force, in the file's units per minute at the start (None: never set).
    feed: float | None = None
    #: The file's own G92 offset per axis (mm), as :func:`file_offset` gives it.
    offset: dict[str, float] = field(default_factory=dict)
    #: The last operator prompt before the start (a pen or bit change), if any.
    prompt: str = ""


@dataclass(frozen=True)
class StartPlan:
    """Where a chosen start begins, the state to rebuild, and the lines that rebuild it."""

    index: int
    state: ModalState
    #: The operation that gets the arc's motion word in front (see the module doc).
    lead: tuple[int, str] | None = None
    #: The program is a G-code file whose own modal state is rebuilt (else only the
    #: position and the pen, as a resume does: its lines carry their own words).
    from_file: bool = True

    def lines(self, settings: GcodeSettings, shift: dict[str, float] | None = None) -> list[str]:
        """What goes before the start line; ``shift`` per axis: board offset changes since
        the program's coordinates were taken (added to the travel target)."""
        shift = shift or {}
        state = self.state
        position = {a: v + shift.get(a, 0.0) for a, v in state.resume.position.items()}
        words = settings.words
        # Millimetres, absolute, the XY plane for the way there (the file's own follow).
        base = [w for w in ("G90", "G21", "G17") if w in words]
        out = [settings.pen_up]
        if base:
            out.append(" ".join(base))
        if not self.from_file:
            travel = ResumeState(position, state.resume.pen_down, state.resume.relative)
            return out + preamble(travel, settings)[1:]  # its pen_up is sent already
        if settings.kinematics == "cylindrical":
            out += preamble(ResumeState(position, False), settings)[2:]  # axis by axis
        elif position:
            out.append("G0 " + " ".join(f"{a}{v:.3f}" for a, v in position.items()))
        own = {a: v for a, v in state.offset.items() if a in position}
        if any(abs(v) > OFFSET_NONE_MM for v in own.values()):
            # The machine stands at the start: call it the file's work position there.
            out.append(
                "G92 " + " ".join(f"{a}{state.resume.position[a] - own[a]:.3f}" for a in own)
            )
        out += self.modes(settings)
        if state.resume.pen_down:
            out.append(settings.pen_down)
        return out

    def modes(self, settings: GcodeSettings) -> list[str]:
        """The file's units, plane, distance mode, motion mode and feed, set once the machine
        stands at the start (also after a resume's way back, which travels in mm, G90)."""
        state, words = self.state, settings.words
        if not self.from_file:
            return []
        modes = []
        if state.inches and "G20" in words:
            modes.append("G20")
        if state.plane != 17 and f"G{state.plane}" in words:
            modes.append(f"G{state.plane}")
        if state.relative and "G91" in words:
            modes.append("G91")
        out = [" ".join(modes)] if modes else []
        feed = f"F{_number(state.feed)}" if state.feed is not None else ""
        if state.motion in ("G0", "G1"):
            out.append(f"{state.motion} {feed}".strip())
        elif feed:
            out.append(feed)
        return out

    def summary(self, program: Program) -> str:
        """One line for the operator: where, and in what state."""
        state = self.state
        parts = [
            "inch" if state.inches else "mm",
            "G91" if state.relative else "G90",
        ]
        if state.plane != 17:
            parts.append(f"G{state.plane}")
        if state.motion is not None:
            parts.append(state.motion)
        if state.feed is not None:
            parts.append(f"F{_number(state.feed)}")
        if any(abs(v) > OFFSET_NONE_MM for v in state.offset.values()):
            parts.append("G92 " + " ".join(f"{a}{v:g}" for a, v in state.offset.items() if v))
        parts.append("pen down" if state.resume.pen_down else "pen up")
        text = QCoreApplication.translate(
            "JobRunner",
            "Starting at {0}: the machine goes there with the pen up, set as the file had it ({1})",
        ).format(program[self.index].source, ", ".join(parts))
        if state.prompt:
            text += QCoreApplication.translate(
                "JobRunner", "; the file's last prompt before it was: {0}"
            ).format(state.prompt)
        return text


def _number(value: float) -> str:
    return f"{value:.4f}".rstrip("0").rstrip(".")


def _refuse(program: Program, line: int | str, reason: str) -> StartRefused:
    name = program.source.name if program.source is not None else program.name
    return StartRefused(f"{name}:{line}: {reason}")


# --- where a start is ---------------------------------------------------------------


def operation_at_line(program: Program, line: int) -> int:
    """The first operation of file line ``line`` or, when that line makes none (a comment, a
    blank line), of the next line that does.  Only for programs read in file order (G-code)."""
    if not program_in_file_order(program):
        raise _refuse(
            program,
            line,
            QCoreApplication.translate(
                "JobRunner",
                "this job does not run in the order of its file's lines: start from an "
                "operation number instead",
            ),
        )
    lines = _source_lines(program)
    if line < 1:
        raise _refuse(program, line, QCoreApplication.translate("JobRunner", "lines count from 1"))
    index = int(np.searchsorted(lines, line, side="left"))
    if index >= len(program):
        last = int(lines[-1]) if len(lines) else 0
        raise _refuse(
            program,
            line,
            QCoreApplication.translate(
                "JobRunner", "beyond the end: nothing runs after line {0}"
            ).format(last),
        )
    return index


def operation_numbered(program: Program, number: int) -> int:
    """Operation ``number`` as the jobs dock counts them (from 1), as an index; a drill
    cycle starts with the move to its hole (the move and the cycle are one hole)."""
    if not 1 <= number <= len(program):
        raise _refuse(
            program,
            f"op {number}",
            QCoreApplication.translate("JobRunner", "the job has operations 1 to {0}").format(
                len(program)
            ),
        )
    index = number - 1
    if index > 0 and program[index].kind is OpKind.DRILL:
        if program[index - 1].kind is OpKind.MOVE:
            index -= 1
    return index


def program_in_file_order(program: Program) -> bool:
    """Whether the operations follow the file's lines (a drill job is reordered by hole)."""
    lines = _source_lines(program)
    return bool(len(lines) == 0 or np.all(np.diff(lines) >= 0))


def _source_lines(program: Program) -> np.ndarray:
    data = getattr(program, "data", None)
    lines = getattr(data, "lines", None)
    if isinstance(lines, np.ndarray):
        return lines
    return np.fromiter((op.source.line for op in program), dtype=np.int64, count=len(program))


# --- the state there ----------------------------------------------------------------


# The last plan worked out, or its refusal: the window works it out on a worker thread
# (a million-line file's state before its last lines is read in a fraction of a second,
# too long for the GUI thread), then starts, and the driver's own call finds it here.
_last: tuple[weakref.ref[Program], int, tuple[str, ...], StartPlan | StartRefused] | None = None
_last_lock = threading.Lock()


def plan_start(program: Program, index: int, axes: Sequence[str]) -> StartPlan:
    """The plan for starting ``program`` at operation ``index``; StartRefused says why not.

    Remembered for the last program and start asked (a program does not change once
    loaded), so that a plan worked out on a worker thread costs the GUI thread nothing.
    """
    global _last
    key = (index, tuple(axes))
    with _last_lock:
        last = _last
    if last is not None and last[0]() is program and last[1:3] == key:
        if isinstance(last[3], StartRefused):
            raise StartRefused(str(last[3]))
        return last[3]
    outcome: StartPlan | StartRefused
    try:
        outcome = _plan_start(program, index, axes)
    except StartRefused as exc:
        outcome = exc
    with _last_lock:
        _last = (weakref.ref(program), index, key[1], outcome)
    if isinstance(outcome, StartRefused):
        raise outcome
    return outcome


def _plan_start(program: Program, index: int, axes: Sequence[str]) -> StartPlan:
    if not 0 <= index < len(program):
        raise _refuse(
            program,
            f"op {index + 1}",
            QCoreApplication.translate("JobRunner", "the job has operations 1 to {0}").format(
                len(program)
            ),
        )
    resume = resume_state(program, index, axes)
    prompt = _last_prompt(program, index)
    data = getattr(program, "data", None)
    texts = getattr(data, "sent", None)
    if data is None or texts is None:
        # Not a G-code file: each line it sends says its own motion and feed.
        return StartPlan(index, ModalState(resume, prompt=prompt), from_file=False)
    inches, relative, plane = _file_modes(program, texts, index)
    motion = _motion_before(program, data, texts, index)
    feed_mm = float(data.feed[index - 1]) if index > 0 else math.nan
    scale = INCH_MM if inches else 1.0
    modal = ModalState(
        resume,
        inches=inches,
        relative=relative,
        plane=plane,
        motion=motion,
        feed=None if math.isnan(feed_mm) else feed_mm / scale,
        offset=file_offset(program, index, axes),
        prompt=prompt,
    )
    lead = _arc_lead(texts, index, motion)
    return StartPlan(index, modal, lead)


def _file_modes(program: Program, texts: Sequence[str], index: int) -> tuple[bool, bool, int]:
    """Units (inches), distance mode (relative) and plane before ``index``; refused on a word
    it cannot follow."""
    inches, relative, plane = False, False, 17
    if index <= 0:
        return inches, relative, plane
    seen = texts_matching(texts, MODAL_HINT, index)
    for k in seen:
        for letter, value in scan_words(texts[k]):
            if letter != "G":
                continue
            code = round(value, 1)
            if code in _UNFOLLOWED:
                raise _refuse(
                    program,
                    program[k].source.line,
                    QCoreApplication.translate(
                        "JobRunner",
                        "{0} before the start changes where the file's coordinates are, "
                        "which the station does not follow: start before this line",
                    ).format(_UNFOLLOWED[code]),
                )
            if code in (20.0, 21.0):
                inches = code == 20.0
            elif code in (90.0, 91.0):
                relative = code == 91.0
            elif code in (17.0, 18.0, 19.0):
                plane = int(code)
    return inches, relative, plane


def _motion_words(text: str) -> list[str]:
    return [_MOTION[v] for letter, v in scan_words(text) if letter == "G" and v in _MOTION]


def _motion_before(program: Program, data: object, texts: Sequence[str], index: int) -> str | None:
    """The motion mode in force before ``index``: the last move's, or a word said since."""
    motion_codes = getattr(data, "motion", None)
    last_move = -1
    motion: str | None = None
    if isinstance(motion_codes, np.ndarray):
        # G28 (HOME) leaves the motion mode as it was: only G0…G3 moves say it.
        moves = np.flatnonzero(motion_codes[:index] <= max(_MOTION))
        if len(moves):
            last_move = int(moves[-1])
            motion = _MOTION.get(float(motion_codes[last_move]))
    for text in texts[last_move + 1 : index]:
        said = _motion_words(text)
        if said:
            motion = said[-1]
    return motion


def _arc_lead(texts: Sequence[str], index: int, motion: str | None) -> tuple[int, str] | None:
    """The first line from the start that moves in the arc mode without saying so."""
    if motion not in ("G2", "G3"):
        return None
    for k in range(index, min(len(texts), index + LEAD_SCAN)):
        text = texts[k]
        words = scan_words(text)
        if any(letter == "G" and v in _MOTION for letter, v in words):
            return None  # it says its motion: the mode is set from there on
        if any(letter in "XYZABC" for letter, _ in words):
            return (k, motion)
    return None


def _last_prompt(program: Program, index: int) -> str:
    waits = program.indices_of(OpKind.WAIT)
    before = int(np.searchsorted(waits, index))
    return program[int(waits[before - 1])].message if before else ""
