"""G-code job files: read once into arrays, checked against the machine that will run them.

Why arrays: a plotter file of a million lines would be a million Operation
objects (and seconds of garbage collection) if built the plain way, yet the
preview, the limit check and the estimate only ever need columns of numbers.
:class:`GcodeProgram` therefore keeps one numpy array per property of an
operation (kind, source line, motion, feed, pen, end position) plus the text
each operation sends, and builds an :class:`Operation` only when one is asked
for (the runner's current line, a refusal message).

Why a fast path: most lines of a large file are plain ``G1 X… Y… F…``.  One
compiled pattern over the whole text picks those out and their numbers are
parsed by numpy in one call; only the other lines (pen commands, modal words,
arcs, comments) go through the full per-line parser, and runs of plain lines
between them are placed with numpy (scale, G92 offset, or a cumulative sum
under G91).

The model is kept in machine coordinates and millimetres, as the limit check
and the preview need it: G20 inch coordinates are scaled, G92 offsets added,
G91 distances accumulated, arcs flattened for the preview.  The machine is
assumed to start at its origin (where homing leaves it) for G91 and G92.

What a line becomes on the machine (``Operation.line``) is the line as
written without comments, ``N`` numbers, checksums and surrounding spaces,
except where the machine would not understand it:

* pen commands of another flavour become the profile's own pen commands
  (``translate_pen``), e.g. Unicorn's ``M300 S30`` becomes the CoreXY
  plotter's ``M4``;
* G21 is not sent to a machine that has no G21 (it works in mm anyway);
* Z heights on a machine whose profile says Z is the pen become pen commands.

Everything else a machine cannot execute (a word outside the profile's
repertoire, an axis it lacks, a named parameter) is listed in
:attr:`GcodeProgram.unsupported` with its line, so the runner refuses the job
before it starts, or becomes a comment when the operator chose to skip such
lines.  Malformed text (``X1..2``, non-UTF-8 bytes) is refused at load with
file:line, like the other loaders.

Pen rules, in order: the profile's own pen_up/pen_down (command word, and S
value where the profile gives one); the GRBL servo convention (``M3``/``M4``
with S > 0 down, ``M5`` up) unless the profile gives M3/M4/M5 another meaning
(the CoreXY plotter lifts with M3); servo flavours ``M300 S<n>`` (Unicorn)
and ``M280 P0 S<n>`` (Makelangelo), where of the two S values the file uses
most the smaller lowers the pen (Unicorn S30 down / S50 up, Makelangelo S25 /
S90; any other value, like Unicorn's ``S255`` servo off, is not a pen move, and
a file using a single value does not say which way it moves the pen, so its
servo lines are sent as written);
and on a ``z_is_pen`` machine Z > 0 up, Z ≤ 0 down, but only in a file whose
Z moves go both above and down to 0 (a file that keeps Z at 0 throughout
does not use Z for its pen).  A file without any pen command is previewed
with G0 as travel and G1/G2/G3 as work.
"""

from __future__ import annotations

import gc
import hashlib
import math
import operator
import re
from array import array
from collections import Counter
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, NamedTuple, overload

import numpy as np
import numpy.typing as npt

from app.jobs.program import (
    JobFileError,
    LimitViolation,
    Operation,
    OpKind,
    Program,
    ProgramPath,
    SourceRef,
)
from app.profiles import GcodeSettings

#: The longest line a board takes, without its line end (PROTOCOLS.md section 4: 80 bytes).
MAX_LINE_CHARS = 79
#: Largest chord error of a flattened arc (mm) and the fewest segments one gets.
ARC_TOLERANCE_MM = 0.02
MIN_ARC_SEGMENTS = 4
MAX_ARC_SEGMENTS = 20_000
INCH_MM = 25.4

PARAMETER_REASON = "named parameters/expressions are not G-code this machine runs"

#: Operation kinds by code (the uint8 stored per operation).
KINDS: tuple[OpKind, ...] = tuple(OpKind)
KIND_CODE: Mapping[OpKind, int] = MappingProxyType({kind: i for i, kind in enumerate(KINDS)})
_MOVE = KIND_CODE[OpKind.MOVE]
_GCODE = KIND_CODE[OpKind.GCODE]
_COMMENT = KIND_CODE[OpKind.COMMENT]
_WAIT = KIND_CODE[OpKind.WAIT]
_PEN_UP = KIND_CODE[OpKind.PEN_UP]
_PEN_DOWN = KIND_CODE[OpKind.PEN_DOWN]

#: Motion per operation (uint8): the modal motion a MOVE ran with.
RAPID, LINEAR, CW_ARC, CCW_ARC, HOME = 0, 1, 2, 3, 4
NO_MOTION = 255
_MOTION_WORDS = {"G0": RAPID, "G1": LINEAR, "G2": CW_ARC, "G3": CCW_ARC}
_MOTION_NAMES = {code: word for word, code in _MOTION_WORDS.items()}

UP, DOWN = 0, 1
AXIS_LETTERS = "XYZABCUVWE"
_LINEAR_AXES = frozenset("XYZUVWE")  # scaled by G20; A B C are degrees

_NUM = r"[-+]?(?:\d+\.?\d*|\.\d+)"
#: One record per line: group 1 is the G0/G1 digit of a plain move (a comment may follow),
#: empty for any other line.
_FAST_LINE = re.compile(
    rf"[ \t]*(?:G0?([01])[ \t]*X[ \t]*{_NUM}[ \t]*Y[ \t]*{_NUM}(?:[ \t]*F[ \t]*{_NUM})?"
    rf"[ \t]*(?:;[^\n]*|\([^()\n]*\)[ \t]*)?\r?\n|[^\n]*\n)"
)
_FAST_LETTERS = bytes.maketrans(b"GXYF\t\r", b"      ")
_WORD = re.compile(rf"[ \t]*([A-Za-z])[ \t]*({_NUM})(?![\d.])")
_WORDS = re.compile(rf"(?:[ \t]*[A-Za-z][ \t]*{_NUM}(?![\d.]))*[ \t]*")
#: A line that may hold a servo pen command (the prescan reads only those).
_SERVO_HINT = re.compile(r"[Mm]0*(?:300|280)(?![\d.])")
_COMMENT_RE = re.compile(r"\(([^)]*)\)?|;(.*)")
_LINE_NUMBER = re.compile(r"[Nn][ \t]*\d+[ \t]*")
_CHECKSUM = re.compile(r"\*[ \t]*\d*[ \t]*\Z")
_SYSTEM = re.compile(r"\$([A-Za-z]+|\$|#|\d+)?")
_WAIT_RE = re.compile(r"[Mm]0*([01])(?![\d.])[ \t]*")
_MESSAGE_RE = re.compile(r"[Mm]0*(11[78])(?![\d.])")
_PARAMETERS = re.compile(
    r"[#\[\]]|^[Oo]|[Gg]0*6[5-7](?![\d.])|\b(?:IF|WHILE|GOTO|DO|END)\b", re.IGNORECASE
)
_SPACES = re.compile(r"[ \t]{2,}")
#: ``M98 800`` / ``M99 90``: the CoreXY plotter's step interval and servo level (PROTOCOLS §4).
_BARE_VALUE = re.compile(r"[ \t]*[Mm]0*(9[89])[ \t]+(\d+(?:\.\d*)?)[ \t]*")
_REALTIME = {"?": "status query", "!": "feed hold", "~": "cycle start", "\x18": "soft reset"}
#: The cached tokenisations (per distinct line text) stop growing here: repeated lines
#: (pen commands, dwells) are what the cache is for.
_TOKEN_CACHE_SIZE = 20_000


@dataclass(frozen=True)
class GcodeProblem:
    """A line this machine cannot execute: the runner refuses the job and lists these."""

    line: int
    text: str
    reason: str

    def __str__(self) -> str:
        return f"line {self.line}: {self.text} — {self.reason}"


class _Word(NamedTuple):
    letter: str  # upper case
    text: str  # the number as written
    value: float


def _normal(letter: str, value: float) -> str:
    """A command word spelled one way: G00 == G0, M03 == M3, G92.1 stays G92.1."""
    if value.is_integer():
        return f"{letter}{int(value)}"
    return f"{letter}{value:g}"


def _split_comment(raw: str) -> tuple[str, str]:
    """The code of a line and its first comment (``( … )`` or ``; …``)."""
    if "(" not in raw and ";" not in raw:
        return raw, ""
    comments: list[str] = []

    def drop(match: re.Match[str]) -> str:
        text = match.group(1) if match.group(1) is not None else match.group(2)
        comments.append((text or "").strip())
        return ""

    code = _SPACES.sub(" ", _COMMENT_RE.sub(drop, raw))  # no double space where one was
    return code, next((c for c in comments if c), "")


def _plain_code(line: str) -> str:
    """A plain move's text as sent: without its trailing comment and surrounding spaces."""
    if ";" in line or "(" in line:
        return _split_comment(line)[0].strip()
    return line.strip()


def _render(code: str, removed: set[int]) -> str:
    """The code with its words number ``removed`` cut out, spacing otherwise as written."""
    spans = [(m.start(1), m.end()) for m in _WORD.finditer(code)]
    parts: list[str] = []
    at = 0
    for index in sorted(removed):
        start, end = spans[index]
        parts.append(code[at:start])
        at = end
    parts.append(code[at:])
    return _SPACES.sub(" ", "".join(parts)).strip()


# --- the program ---------------------------------------------------------------------


class GcodeData:
    """The arrays a :class:`GcodeProgram` is made of (one entry per operation unless noted)."""

    def __init__(
        self,
        file: str,
        columns: tuple[str, ...],
        kinds: npt.NDArray[np.uint8],
        lines: npt.NDArray[np.int32],
        motion: npt.NDArray[np.uint8],
        feed: npt.NDArray[np.float64],
        pen: npt.NDArray[np.bool_],
        pen_info: bool,
        positions: npt.NDArray[np.float64],
        named: npt.NDArray[np.uint16],
        texts: list[str],
        messages: dict[int, str],
        dwell_ops: npt.NDArray[np.int64],
        dwell_s: npt.NDArray[np.float64],
        arc_ops: npt.NDArray[np.int64],
        arc_points: npt.NDArray[np.float64],
    ) -> None:
        self.file = file
        #: The axis of each column of ``positions`` (and of ``arc_points``).
        self.columns = columns
        self.kinds = kinds
        self.lines = lines
        #: RAPID, LINEAR, CW_ARC, CCW_ARC or HOME for a MOVE, NO_MOTION otherwise.
        self.motion = motion
        #: The modal feed (mm/min) in force at each operation; NaN until a file sets one.
        self.feed = feed
        #: Pen down while the operation runs (from the file's pen commands; without any,
        #: G1/G2/G3 moves count as work).
        self.pen = pen
        self.pen_info = pen_info
        #: Machine position (mm; degrees for A B C) after each operation; NaN until set.
        self.positions = positions
        #: Bit ``c`` set: the operation (a MOVE) moves column ``c``.
        self.named = named
        #: What each operation sends (empty: not sent).
        self.texts = texts
        self.messages = messages
        #: G4 dwells: the operations and their seconds (sparse).
        self.dwell_ops = dwell_ops
        self.dwell_s = dwell_s
        #: Flattened arcs: inner vertices (before each arc's end) and their operations.
        self.arc_ops = arc_ops
        self.arc_points = arc_points

    def __len__(self) -> int:
        return len(self.kinds)

    def operation(self, index: int) -> Operation:
        kind = KINDS[int(self.kinds[index])]
        target: Mapping[str, float] = MappingProxyType({})
        if kind is OpKind.MOVE:
            bits = int(self.named[index])
            row = self.positions[index]
            target = MappingProxyType(
                {axis: float(row[c]) for c, axis in enumerate(self.columns) if bits & (1 << c)}
            )
        return Operation(
            kind,
            SourceRef(self.file, int(self.lines[index])),
            target,
            self.messages.get(index, ""),
            self.texts[index],
        )

    def column_values(self, rows: npt.NDArray[np.float64], axes: Sequence[str]) -> np.ndarray:
        """``rows`` (n, columns) rearranged to ``axes``; NaN for axes the file never moves."""
        out = np.full((len(rows), len(axes)), np.nan)
        for i, axis in enumerate(axes):
            if axis in self.columns:
                out[:, i] = rows[:, self.columns.index(axis)]
        return out


class GcodeOperations(Sequence[Operation]):
    """The operations of a G-code program, each built when asked for (never all at once)."""

    def __init__(self, data: GcodeData) -> None:
        self._data = data

    def __len__(self) -> int:
        return len(self._data)

    @overload
    def __getitem__(self, index: int) -> Operation: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[Operation]: ...

    def __getitem__(self, index: int | slice) -> Operation | Sequence[Operation]:
        if isinstance(index, slice):
            return [self._data.operation(i) for i in range(*index.indices(len(self)))]
        i = operator.index(index)
        if i < 0:
            i += len(self)
        if not 0 <= i < len(self):
            raise IndexError(index)
        return self._data.operation(i)

    def __iter__(self) -> Iterator[Operation]:
        for i in range(len(self)):
            yield self._data.operation(i)


@dataclass(frozen=True, eq=False, kw_only=True)
class GcodeProgram(Program):
    """A G-code file as the station runs it, answered from arrays (see the module doc)."""

    #: Lines this machine cannot execute, by line; the runner refuses the job while any remain.
    unsupported: tuple[GcodeProblem, ...] = ()
    data: GcodeData = field(repr=False)

    @property
    def axes(self) -> tuple[str, ...]:
        d = self.data
        first: list[tuple[int, str]] = []
        for c, axis in enumerate(d.columns):
            hits = np.flatnonzero(d.named & (1 << c))
            if len(hits):
                first.append((int(hits[0]), axis))
        return tuple(axis for _, axis in sorted(first))

    def fingerprint(self) -> str:
        """Hash of what is sent and of the kinds: the same file for the same machine."""
        d = self.data
        digest = hashlib.sha256()
        digest.update(d.kinds.tobytes())
        digest.update("\n".join(d.texts).encode("utf-8", "surrogatepass"))
        digest.update(repr(sorted(d.messages.items())).encode("utf-8", "surrogatepass"))
        return digest.hexdigest()[:16]

    def positions(self) -> Iterator[tuple[int, Mapping[str, float], bool]]:
        d = self.data
        for index in np.flatnonzero(d.kinds == _MOVE).tolist():
            row = d.positions[index]
            where = {a: float(row[c]) for c, a in enumerate(d.columns) if not math.isnan(row[c])}
            yield index, where, bool(d.pen[index])

    def path(self, axes: Sequence[str]) -> ProgramPath:
        """Every move's end on ``axes``, with each arc's inner vertices before its end."""
        d = self.data
        ops = np.flatnonzero(d.kinds == _MOVE).astype(np.int64)
        coords = d.column_values(d.positions[ops], axes)
        pen = d.pen[ops]
        if len(d.arc_ops):
            at = np.searchsorted(ops, d.arc_ops)
            coords = np.insert(coords, at, d.column_values(d.arc_points, axes), axis=0)
            pen = np.insert(pen, at, d.pen[d.arc_ops])
            ops = np.insert(ops, at, d.arc_ops)
        return ProgramPath(coords, ops, pen)

    def kinds(self) -> frozenset[OpKind]:
        counts = np.bincount(self.data.kinds, minlength=len(KINDS))
        return frozenset(KINDS[i] for i in np.flatnonzero(counts))

    def indices_of(self, kind: OpKind) -> np.ndarray:
        return np.flatnonzero(self.data.kinds == KIND_CODE[kind]).astype(np.int64)

    def limit_violations(self, limits: Mapping[str, tuple[float, float]]) -> list[LimitViolation]:
        """One entry per move and axis outside the travel; arcs are judged by their vertices."""
        d = self.data
        found: dict[tuple[int, int], float] = {}
        nan_range = (math.nan, math.nan)
        arc_named = d.named[d.arc_ops] if len(d.arc_ops) else d.named[:0]
        for c, axis in enumerate(d.columns):
            low, high = limits.get(axis, nan_range)
            bit = 1 << c
            values = d.positions[:, c]
            with np.errstate(invalid="ignore"):
                bad = ((d.named & bit) != 0) & ~((values >= low) & (values <= high))
            for index in np.flatnonzero(bad).tolist():
                found[(index, c)] = float(values[index])
            if len(d.arc_ops):
                inner = d.arc_points[:, c]
                with np.errstate(invalid="ignore"):
                    out = ((arc_named & bit) != 0) & ~((inner >= low) & (inner <= high))
                for k in np.flatnonzero(out).tolist():
                    key = (int(d.arc_ops[k]), c)
                    value = float(inner[k])
                    if key not in found or _beyond(value, low, high) > _beyond(
                        found[key], low, high
                    ):
                        found[key] = value
        violations: list[LimitViolation] = []
        built: dict[int, Operation] = {}
        for index, c in sorted(found):
            op = built.get(index) or built.setdefault(index, d.operation(index))
            low, high = limits.get(d.columns[c], nan_range)
            violations.append(LimitViolation(index, op, d.columns[c], found[(index, c)], low, high))
        return violations


def _beyond(value: float, low: float, high: float) -> float:
    """How far ``value`` lies outside low…high (unknown limits: infinitely)."""
    if math.isnan(low) or math.isnan(high):
        return math.inf
    return max(low - value, value - high)


# --- pen conventions ------------------------------------------------------------------


@dataclass(frozen=True)
class _PenCommand:
    word: str
    s: float | None
    state: int
    text: str


def _profile_pen(text: str, state: int) -> _PenCommand:
    """A profile's pen command: its command word and the S value it names, if any."""
    code = text.strip()
    word, s = "", None
    for match in _WORD.finditer(code.upper()):
        letter, value = match.group(1), float(match.group(2))
        if letter in "GM" and not word:
            word = _normal(letter, value)
        elif letter == "S":
            s = value
    return _PenCommand(word, s, state, code)


def _servo_levels(values: Counter[float]) -> tuple[float, float] | None:
    """(down, up) of a servo pen: of the two S values used most, the smaller lowers it."""
    common = [value for value, _ in values.most_common(2)]
    if len(common) < 2:
        return None
    return min(common), max(common)


# --- the parser -------------------------------------------------------------------------


@dataclass
class _State:
    """The modal state of the file as the machine will see it."""

    position: list[float]
    offset: list[float]
    scale: float = 1.0
    relative: bool = False
    motion: int = RAPID
    plane: int = 17
    z_work: float = math.nan
    pen: int = -1  # unknown, shown as up

    def copy(self) -> _State:
        return _State(
            list(self.position),
            list(self.offset),
            self.scale,
            self.relative,
            self.motion,
            self.plane,
            self.z_work,
            self.pen,
        )


@dataclass
class _Pending:
    """One operation a line makes, before the line is known to be acceptable."""

    kind: int
    text: str
    sent: Sequence[_Word] = ()  # the words it sends (checked against the machine)
    motion: int = NO_MOTION
    feed: float = math.nan
    pen: int = -1  # pen state set by this operation (-1: unchanged)
    target: dict[int, float] = field(default_factory=dict)
    arc: np.ndarray | None = None
    dwell: float = 0.0
    message: str = ""
    translated: bool = False  # a pen line sent as the profile's command
    checked: bool = False  # ``text`` is the profile's own, already checked


class _Parser:
    def __init__(
        self,
        file: str,
        axis_names: Sequence[str],
        settings: GcodeSettings,
        translate_pen: bool,
        skip_unsupported: bool,
        machine_title: str,
    ) -> None:
        self.file = file
        self.machine_axes = frozenset(a.upper() for a in axis_names)
        self.words = frozenset(w.upper() for w in settings.words)
        self.translate = translate_pen
        self.skip = skip_unsupported
        self.who = f"the {machine_title}" if machine_title else "this machine"
        self.title = machine_title or "machine"
        self.z_is_pen = settings.z_is_pen
        self.pen_up = _profile_pen(settings.pen_up, UP)
        self.pen_down = _profile_pen(settings.pen_down, DOWN)
        # Entries naming an S value first, so "M3 S0" / "M3 S1000" pairs resolve exactly.
        self.pen_map = sorted((self.pen_up, self.pen_down), key=lambda p: p.s is None)
        profile_words = {self.pen_up.word, self.pen_down.word}
        self.grbl_pen = not profile_words & {"M3", "M4", "M5"} or (
            self.pen_up.word == "M5" and self.pen_down.word in ("M3", "M4")
        )
        self.servo: dict[str, tuple[float, float]] = {}
        self.z_pen = False

        self.columns: list[str] = ["X", "Y"]
        self.state = _State([math.nan, math.nan], [0.0, 0.0])
        self.token_cache: dict[str, tuple[_Word, ...]] = {}
        #: Lines whose operations depend on nothing but their text (pen commands, dwells):
        #: the pen state they set, their operations and the machine's objections.
        self.memo: dict[str, tuple[int | None, list[_Pending], tuple[str, ...]]] = {}

        # Output, in operation order.
        self.texts: list[str] = []
        self.messages: dict[int, str] = {}
        # Compact columns (array, not list: a million lines of them must stay small).
        self.s_op = array("q")
        self.s_kind = array("B")
        self.s_line = array("i")
        self.s_motion = array("B")
        self.s_feed = array("d")
        self.s_named = array("H")
        self.pos_op = array("q")
        self.pos_col = array("q")
        self.pos_val = array("d")
        self.pen_ops = array("q")
        self.pen_states = array("B")
        self.dwell_ops = array("q")
        self.dwell_s = array("d")
        self.arc_ops = array("q")
        self.arc_blocks: list[np.ndarray] = []
        self.problems: list[GcodeProblem] = []
        self.skipped: list[tuple[int, str, tuple[str, ...]]] = []
        self.translated = 0
        self.g21_dropped = 0
        self.realtime_dropped = 0
        self.z_dropped = 0
        self.checked_texts: dict[str, tuple[str, ...]] = {}

        # Plain moves (the fast path): numbers per plain line and the runs placed so far.
        self.fast_texts: list[str] = []
        self.fast_g = np.empty(0)
        self.fast_x = np.empty(0)
        self.fast_y = np.empty(0)
        self.fast_f = np.empty(0)
        self.runs: list[tuple[int, int, int]] = []  # (first plain line, end, first operation)
        self.plain_lines = np.empty(0, dtype=np.int32)  # source line of each plain move

    # --- driving -------------------------------------------------------------------

    def fast_path_allowed(self) -> bool:
        """Plain moves need no checks only where G0, G1, X and Y are all the machine's."""
        return {"G0", "G1"} <= self.words and {"X", "Y"} <= self.machine_axes

    def parse(self, text: str) -> None:
        if not text.endswith("\n"):
            text += "\n"
        lines = text.split("\n")
        count = len(lines) - 1
        if self.fast_path_allowed():
            kinds = np.array(_FAST_LINE.findall(text), dtype="<U1")
            plain = kinds != ""
        else:
            kinds = np.empty(0, dtype="<U1")
            plain = np.zeros(count, dtype=bool)
        if len(plain) != count:  # cannot happen: one record per line
            raise JobFileError(self.file, 0, "could not split the file into lines")
        plain_index = np.flatnonzero(plain)
        texts = [_plain_code(lines[i]) for i in plain_index.tolist()]
        lengths = np.fromiter(map(len, texts), dtype=np.int64, count=len(texts))
        if len(texts) and int(lengths.max()) > MAX_LINE_CHARS:  # left to the full parser
            plain[plain_index[lengths > MAX_LINE_CHARS]] = False
            keep = lengths <= MAX_LINE_CHARS
            texts = [t for t, k in zip(texts, keep.tolist(), strict=True) if k]
            plain_index = plain_index[keep]
        self._plain_numbers(texts)
        self.plain_lines = (plain_index + 1).astype(np.int32)
        slow = np.flatnonzero(~plain)
        self._prescan([lines[i] for i in slow.tolist()])
        plain_before = (np.cumsum(plain) - plain)[slow].tolist()
        done = 0
        for i, before in zip(slow.tolist(), plain_before, strict=True):
            if before > done:
                self._plain_run(done, before)
                done = before
            self._line(i + 1, lines[i])
        if done < len(self.fast_texts):
            self._plain_run(done, len(self.fast_texts))

    def _plain_numbers(self, texts: list[str]) -> None:
        """Every plain line's G, X, Y and F in one numpy parse (F NaN where not given)."""
        self.fast_texts = texts
        n = len(texts)
        has_f = np.fromiter(("F" in t for t in texts), dtype=bool, count=n)
        blob = " ".join(texts).encode("ascii").translate(_FAST_LETTERS)
        numbers = np.fromstring(blob, dtype=np.float64, sep=" ") if n else np.empty(0)
        per_line = 3 + has_f.astype(np.int64)
        starts = np.cumsum(per_line) - per_line
        if len(numbers) != int(per_line.sum()):  # cannot happen: the pattern admits numbers only
            raise JobFileError(self.file, 0, "could not read the coordinates")
        self.fast_g = numbers[starts]
        self.fast_x = numbers[starts + 1]
        self.fast_y = numbers[starts + 2]
        self.fast_f = np.full(n, np.nan)
        self.fast_f[has_f] = numbers[starts[has_f] + 3]

    def _prescan(self, lines: list[str]) -> None:
        """What needs the whole file: the servo S values in use, and whether Z is the pen."""
        servo: dict[str, Counter[float]] = {"M300": Counter(), "M280": Counter()}
        z_low, z_high = math.inf, -math.inf
        for raw in lines:
            has_servo = _SERVO_HINT.search(raw) is not None
            has_z = self.z_is_pen and ("Z" in raw or "z" in raw)
            if not (has_servo or has_z):
                continue
            code = self._code(raw)
            if not code or code[0] in "$%" or _PARAMETERS.search(code):
                continue
            words = self._tokens_or_none(code)
            if words is None:
                continue
            commands = {_normal(w.letter, w.value) for w in words if w.letter in "GM"}
            values = {w.letter: w.value for w in words}
            if "M300" in commands and "S" in values:
                servo["M300"][values["S"]] += 1
            if "M280" in commands and values.get("P") == 0 and "S" in values:
                servo["M280"][values["S"]] += 1
            if "Z" in values and not commands & {"G92", "G28", "G10", "G53"}:
                z_low, z_high = min(z_low, values["Z"]), max(z_high, values["Z"])
        for word, counts in servo.items():
            levels = _servo_levels(counts)
            if levels is not None:
                self.servo[word] = levels
        self.z_pen = self.z_is_pen and z_low <= 0 < z_high

    @staticmethod
    def _code(raw: str) -> str:
        code = _split_comment(raw)[0].strip()
        match = _LINE_NUMBER.match(code)
        if match:
            code = code[match.end() :]
        return _CHECKSUM.sub("", code).strip()

    # --- plain moves ---------------------------------------------------------------

    def _plain_run(self, k0: int, k1: int) -> None:
        """Plain moves k0…k1-1 as MOVE operations, placed by the modal state in force."""
        st = self.state
        self.runs.append((k0, k1, len(self.texts)))
        self.texts.extend(self.fast_texts[k0:k1])
        scale = st.scale
        if st.relative:
            for column, values in ((0, self.fast_x), (1, self.fast_y)):
                start = st.position[column]
                steps = np.concatenate(
                    ([0.0 if math.isnan(start) else start], values[k0:k1] * scale)
                )
                values[k0:k1] = np.cumsum(steps)[1:]  # added in order, as line by line
        else:
            for column, values in ((0, self.fast_x), (1, self.fast_y)):
                if scale != 1.0 or st.offset[column] != 0.0:
                    values[k0:k1] = values[k0:k1] * scale + st.offset[column]
        if scale != 1.0:
            self.fast_f[k0:k1] *= scale
        st.position[0] = float(self.fast_x[k1 - 1])
        st.position[1] = float(self.fast_y[k1 - 1])
        st.motion = int(self.fast_g[k1 - 1])

    # --- one line ------------------------------------------------------------------

    def _tokens_or_none(self, code: str) -> tuple[_Word, ...] | None:
        cached = self.token_cache.get(code)
        if cached is not None:
            return cached
        if not _WORDS.fullmatch(code):
            return None
        result = tuple(
            _Word(letter.upper(), number, float(number)) for letter, number in _WORD.findall(code)
        )
        if len(self.token_cache) < _TOKEN_CACHE_SIZE:
            self.token_cache[code] = result
        return result

    def _tokens(self, code: str, number: int) -> tuple[_Word, ...]:
        words = self._tokens_or_none(code)
        if words is None and (bare := _BARE_VALUE.fullmatch(code)) is not None:
            # The CoreXY plotter's own M98 <µs> / M99 <pwm>: a value with no letter.
            value = bare.group(2)
            words = (
                _Word("M", bare.group(1), float(bare.group(1))),
                _Word("P", value, float(value)),
            )
        if words is None:
            at = 0
            upper = code.upper()
            while (match := _WORD.match(upper, at)) is not None:
                at = match.end()
            rest = code[at:].strip()
            raise JobFileError(self.file, number, f"malformed G-code at {rest[:20]!r} in {code!r}")
        return words

    def _column(self, letter: str) -> int:
        if letter not in self.columns:
            self.columns.append(letter)
            self.state.position.append(math.nan)
            self.state.offset.append(0.0)
        return self.columns.index(letter)

    def _line(self, number: int, raw: str) -> None:
        code, comment = _split_comment(raw)
        code = code.strip()
        if not code:
            if comment:
                self._commit(number, "", [_Pending(_COMMENT, "", message=comment)], ())
            return
        if code.startswith("%"):
            return
        match = _LINE_NUMBER.match(code)
        if match:
            code = code[match.end() :]
        code = _CHECKSUM.sub("", code).strip()
        if not code:
            return
        replay = self.memo.get(code)
        if replay is not None:
            pen, pending, reasons = replay
            if pen is not None:
                self.state.pen = pen
            self._commit(number, code, pending, reasons)
        elif code[0] == "$":
            self._system(number, code)
        elif code in _REALTIME:
            self._realtime(number, code)
        elif _PARAMETERS.search(code):
            self._commit(number, code, [_Pending(_GCODE, code)], (PARAMETER_REASON,))
        elif wait := _WAIT_RE.match(code):
            message = comment or code[wait.end() :].strip() or f"M{wait.group(1)}: paused"
            self._commit(number, code, [_Pending(_WAIT, "", message=message)], ())
        elif display := _MESSAGE_RE.match(code):
            word = f"M{display.group(1)}"
            reasons = () if word in self.words else (f"{self.who} cannot execute {word}",)
            self._commit(number, code, [_Pending(_GCODE, code, checked=True)], reasons)
        else:
            self._words(number, code, self._tokens(code, number))

    def _system(self, number: int, code: str) -> None:
        """A GRBL ``$`` command: sent as written where the machine knows it."""
        match = _SYSTEM.match(code)
        word = "$" + (match.group(1) or "").upper() if match else "$"
        reasons = () if word in self.words else (f"{self.who} cannot execute {word}",)
        self._commit(number, code, [_Pending(_GCODE, code, checked=True)], reasons)

    def _realtime(self, number: int, code: str) -> None:
        """A real-time byte on a line: the station sends ``?`` itself; the others never belong."""
        what = _REALTIME[code]
        if code == "?":
            self.realtime_dropped += 1
            message = "? not sent: the station asks for the status itself"
            self._commit(number, code, [_Pending(_COMMENT, "", message=message)], ())
            return
        reason = f"{what} ({code!r}) is a real-time command, not a line of a job"
        self._commit(number, code, [_Pending(_GCODE, code, checked=True)], (reason,))

    def _words(self, number: int, code: str, words: tuple[_Word, ...]) -> None:
        """A line of words: modal changes, pen commands, then what remains as one operation."""
        st = self.state
        saved = st.copy()
        commands: dict[str, int] = {}
        params: dict[str, int] = {}
        for index, word in enumerate(words):
            if word.letter in "GM":
                commands.setdefault(_normal(word.letter, word.value), index)
            else:
                params[word.letter] = index
        removed: set[int] = set()
        pending: list[_Pending] = []
        notes: list[str] = []
        extra: list[str] = []
        previous_motion = st.motion

        def value(letter: str) -> float:
            return words[params[letter]].value

        if "G20" in commands:
            st.scale = INCH_MM
        if "G21" in commands:
            st.scale = 1.0
            if "G21" not in self.words:
                removed.add(commands["G21"])
                notes.append("g21")
        if "G90" in commands:
            st.relative = False
        if "G91" in commands:
            st.relative = True
        for plane in (17, 18, 19):
            if f"G{plane}" in commands:
                st.plane = plane
        for name, motion in _MOTION_WORDS.items():
            if name in commands:
                st.motion = motion
        for end in ("M2", "M30"):
            if end in commands:
                removed.add(commands[end])
        if "M0" in commands or "M1" in commands:
            extra.append("M0/M1 must stand on a line of its own (the station asks the operator)")
        non_modal = {"G92", "G28", "G10", "G4"} & commands.keys()

        # The pen: a pen command word, or a Z height on a machine whose pen Z is.
        pen, pen_words = self._pen_command(commands, params, words)
        z_index = params.get("Z")
        z_only = False
        if z_index is not None and self.z_is_pen:
            if "G92" in commands:
                st.z_work = value("Z") * st.scale
                if self.translate:
                    removed.add(z_index)
            elif not non_modal:
                if self.z_pen:
                    z = value("Z") * st.scale
                    base = 0.0 if math.isnan(st.z_work) else st.z_work
                    st.z_work = base + z if st.relative else z
                    if pen is None:
                        pen = UP if st.z_work > 0 else DOWN
                        pen_words = {z_index}
                        z_only = not (set(params) & set(AXIS_LETTERS)) - {"Z"}
                if self.translate:
                    removed.add(z_index)
                    if not self.z_pen:
                        notes.append("z")
        split = False
        if pen is not None:
            changed = pen != st.pen or z_only or pen_words != {z_index}
            if self.translate:
                removed |= pen_words
                if changed:
                    pending.append(self._pen_pending(code, words, pen_words, pen))
                    split = True
            st.pen = pen
        whole = pen is not None and not self.translate  # the pen line goes out as written

        rest = (
            list(range(len(words))) if whole else [i for i in range(len(words)) if i not in removed]
        )
        if rest:
            text = code if whole or not removed else _render(code, removed)
            sent = [words[i] for i in rest]
            op = _Pending(_GCODE, text, sent)
            if "F" in params and params["F"] in rest:
                op.feed = value("F") * st.scale
            axes = [i for i in rest if self._is_axis(words[i].letter)]
            if "G92" in commands or "G92.1" in commands:
                self._set_offsets(commands, words, axes)
            elif "G28" in commands:
                op.kind, op.motion = _MOVE, HOME
                op.target = dict.fromkeys(range(len(self.columns)), 0.0)
                for c in op.target:
                    st.position[c] = 0.0
            elif "G4" in commands:
                # PROTOCOLS.md section 4: P in milliseconds, S in seconds.
                op.dwell = (
                    value("P") / 1000 if "P" in params else value("S") if "S" in params else 0.0
                )
            elif axes and not non_modal:
                self._motion(number, code, words, params, commands, op, axes)
            if whole:
                op.pen = pen if pen is not None else -1
                if op.kind != _MOVE:
                    op.kind = _PEN_DOWN if pen == DOWN else _PEN_UP
            if not (split and op.kind == _GCODE and self._redundant(sent, previous_motion)):
                pending.append(op)
        if not pending and ("M2" in commands or "M30" in commands):
            pending.append(_Pending(_COMMENT, "", message="program end"))
        elif not pending and "g21" in notes:
            message = "G21 not sent: the machine works in mm"
            pending.append(_Pending(_COMMENT, "", message=message))
        reasons = self._check(pending) + tuple(extra)
        # F is read in the units in force, axes move from where the machine is: not pure.
        pure = not any(letter in AXIS_LETTERS or letter == "F" for letter in params) and all(
            name == "G4" or (name[0] == "M" and name not in ("M0", "M1", "M2", "M30"))
            for name in commands
        )
        if pure and not (reasons and self.skip) and len(self.memo) < _TOKEN_CACHE_SIZE:
            self.memo[code] = (pen, pending, reasons)
        if reasons and self.skip:
            while len(saved.position) < len(self.columns):
                saved.position.append(math.nan)
                saved.offset.append(0.0)
            self.state = saved
        else:
            self.g21_dropped += notes.count("g21")
            self.z_dropped += notes.count("z")
        self._commit(number, code, pending, reasons)

    def _is_axis(self, letter: str) -> bool:
        """An axis of the model (on a machine whose pen Z is, Z is no axis)."""
        return letter in AXIS_LETTERS and not (self.z_is_pen and letter == "Z")

    def _redundant(self, sent: Sequence[_Word], previous_motion: int) -> bool:
        """What is left of a pen line is only the motion word already in force."""
        if len(sent) != 1 or sent[0].letter != "G":
            return False
        return _MOTION_WORDS.get(_normal("G", sent[0].value)) == previous_motion

    def _pen_command(
        self, commands: Mapping[str, int], params: Mapping[str, int], words: Sequence[_Word]
    ) -> tuple[int | None, set[int]]:
        """The pen state a command word of the line sets, and the words that say so."""
        s = words[params["S"]].value if "S" in params else None
        for word, index in commands.items():
            if word[0] != "M":
                continue
            used = {index} | ({params["S"]} if "S" in params else set())
            for pen in self.pen_map:
                if word == pen.word and (pen.s is None or s == pen.s):
                    return pen.state, used
            if self.grbl_pen and word in ("M3", "M4") and s is not None and s > 0:
                return DOWN, used
            if self.grbl_pen and word == "M5":
                return UP, {index}
            if word in self.servo and s is not None:
                if word == "M280":
                    if "P" not in params or words[params["P"]].value != 0:
                        continue
                    used |= {params[k] for k in ("P", "T") if k in params}
                down, up = self.servo[word]
                if s == down:
                    return DOWN, used
                if s == up:
                    return UP, used
        return None, set()

    def _pen_pending(
        self, code: str, words: Sequence[_Word], pen_words: set[int], pen: int
    ) -> _Pending:
        """The pen part of a line: as written if it is the profile's own command, else that."""
        own = self.pen_down if pen == DOWN else self.pen_up
        kind = _PEN_DOWN if pen == DOWN else _PEN_UP
        written = [words[i] for i in sorted(pen_words)]
        commands = [_normal(w.letter, w.value) for w in written if w.letter in "GM"]
        s_values = [w.value for w in written if w.letter == "S"]
        if (
            commands == [own.word]
            and len(written) == len(commands) + len(s_values)
            and (s_values == ([own.s] if own.s is not None else []))
        ):
            text = _render(code, set(range(len(words))) - pen_words)
            return _Pending(kind, text, written)
        return _Pending(kind, own.text, translated=True, checked=False)

    def _set_offsets(
        self, commands: Mapping[str, int], words: Sequence[_Word], axes: Sequence[int]
    ) -> None:
        """G92: the current machine position is called the given values from now on."""
        st = self.state
        if "G92.1" in commands:
            st.offset = [0.0] * len(st.offset)
            return
        for index in axes:
            word = words[index]
            if self.z_is_pen and word.letter == "Z":
                continue
            c = self._column(word.letter)
            scale = st.scale if word.letter in _LINEAR_AXES else 1.0
            here = st.position[c]
            st.offset[c] = (0.0 if math.isnan(here) else here) - word.value * scale

    def _motion(
        self,
        number: int,
        code: str,
        words: Sequence[_Word],
        params: Mapping[str, int],
        commands: Mapping[str, int],
        op: _Pending,
        axes: Sequence[int],
    ) -> None:
        """A move: its machine target, and the arc's inner vertices when it is one."""
        st = self.state
        op.kind = _MOVE
        op.motion = st.motion
        machine = "G53" in commands
        start = list(st.position)
        for index in axes:
            word = words[index]
            c = self._column(word.letter)
            scale = st.scale if word.letter in _LINEAR_AXES else 1.0
            if machine:
                target = word.value * scale
            elif st.relative:
                here = st.position[c]
                target = (0.0 if math.isnan(here) else here) + word.value * scale
            else:
                target = word.value * scale + st.offset[c]
            op.target[c] = target
        while len(start) < len(self.columns):
            start.append(math.nan)
        if op.motion in (CW_ARC, CCW_ARC) and st.plane == 17:
            op.target.setdefault(0, 0.0 if math.isnan(start[0]) else start[0])
            op.target.setdefault(1, 0.0 if math.isnan(start[1]) else start[1])
            offsets = {k: words[params[k]].value * st.scale for k in "IJR" if k in params}
            op.arc = self._arc(number, code, start, op.target, offsets, op.motion == CW_ARC)
        for c, target in op.target.items():
            st.position[c] = target

    def _arc(
        self,
        number: int,
        code: str,
        start: list[float],
        target: Mapping[int, float],
        offsets: Mapping[str, float],
        clockwise: bool,
    ) -> np.ndarray:
        """The inner vertices of an XY arc, chord error at most ARC_TOLERANCE_MM."""
        sx = 0.0 if math.isnan(start[0]) else start[0]
        sy = 0.0 if math.isnan(start[1]) else start[1]
        ex, ey = target[0], target[1]
        if "R" in offsets:
            radius = offsets["R"]
            dx, dy = ex - sx, ey - sy
            chord = math.hypot(dx, dy)
            if chord == 0.0:
                raise JobFileError(self.file, number, f"an R arc needs distinct ends: {code!r}")
            h2 = 4 * radius * radius - dx * dx - dy * dy
            if h2 < -1e-6 * max(1.0, radius * radius):
                raise JobFileError(self.file, number, f"arc radius too small: {code!r}")
            h = -math.sqrt(max(h2, 0.0)) / chord
            if not clockwise:
                h = -h
            if radius < 0:
                h = -h
            cx, cy = sx + 0.5 * (dx - dy * h), sy + 0.5 * (dy + dx * h)
        elif "I" in offsets or "J" in offsets:
            cx, cy = sx + offsets.get("I", 0.0), sy + offsets.get("J", 0.0)
        else:
            raise JobFileError(self.file, number, f"an arc needs I/J or R: {code!r}")
        r0 = math.hypot(sx - cx, sy - cy)
        r1 = math.hypot(ex - cx, ey - cy)
        a0 = math.atan2(sy - cy, sx - cx)
        a1 = math.atan2(ey - cy, ex - cx)
        if clockwise:
            sweep = (a0 - a1) % math.tau
        else:
            sweep = (a1 - a0) % math.tau
        if sweep < 1e-12 and "R" not in offsets:
            sweep = math.tau  # same start and end with a centre: a full circle
        radius = max(r0, r1)
        if radius > ARC_TOLERANCE_MM:
            step = 2 * math.acos(1 - ARC_TOLERANCE_MM / radius)
            segments = math.ceil(sweep / step)
        else:
            segments = 1
        segments = min(max(segments, MIN_ARC_SEGMENTS), MAX_ARC_SEGMENTS)
        t = np.arange(1, segments) / segments
        angles = a0 + (-sweep if clockwise else sweep) * t
        radii = r0 + (r1 - r0) * t
        points = np.empty((len(t), len(self.columns)))
        for c in range(len(self.columns)):
            a = start[c] if c < len(start) else math.nan
            b = target.get(c, a)
            points[:, c] = a + (b - a) * t if not math.isnan(a) else b
        points[:, 0] = cx + radii * np.cos(angles)
        points[:, 1] = cy + radii * np.sin(angles)
        return points

    # --- checks and output -----------------------------------------------------------

    def _check(self, pending: Sequence[_Pending]) -> tuple[str, ...]:
        """Why the machine could not execute what this line sends (empty: it can)."""
        reasons: list[str] = []
        for op in pending:
            if op.kind in (_COMMENT, _WAIT) or not op.text:
                continue
            if op.translated or op.checked:
                found = self._check_text(op.text) if op.translated else ()
            else:
                found = self._check_words(op)
            if not op.text.isascii():
                found += (f"{op.text!r} is not ASCII",)
            if len(op.text) > MAX_LINE_CHARS:
                found += (f"{len(op.text)} characters; a line holds at most {MAX_LINE_CHARS}",)
            reasons += [r for r in found if r not in reasons]
        return tuple(reasons)

    def _check_words(self, op: _Pending) -> tuple[str, ...]:
        found: list[str] = []
        explicit_motion = False
        for word in op.sent:
            if word.letter in "GM":
                name = _normal(word.letter, word.value)
                explicit_motion |= name in _MOTION_WORDS
                if name not in self.words:
                    found.append(f"{self.who} cannot execute {name}")
            elif word.letter in AXIS_LETTERS and word.letter not in self.machine_axes:
                found.append(f"{self.who} has no {word.letter} axis")
        if op.kind == _MOVE and op.motion in _MOTION_NAMES and not explicit_motion:
            name = _MOTION_NAMES[op.motion]
            if name not in self.words:
                found.append(f"{self.who} cannot execute {name}")
        return tuple(found)

    def _check_text(self, text: str) -> tuple[str, ...]:
        """The profile's own pen command, checked once like any line."""
        if text not in self.checked_texts:
            words = self._tokens_or_none(text) or ()
            self.checked_texts[text] = self._check_words(_Pending(_GCODE, text, words))
        return self.checked_texts[text]

    def _commit(
        self, number: int, code: str, pending: Sequence[_Pending], reasons: Sequence[str]
    ) -> None:
        if reasons and self.skip:
            reason_text = "; ".join(reasons)
            message = f"not sent: {code} ({reason_text})"
            pending = [_Pending(_COMMENT, "", message=message)]
            self.skipped.append((number, code, tuple(reasons)))
        else:
            self.problems += [GcodeProblem(number, code, reason) for reason in reasons]
        for op in pending:
            index = len(self.texts)
            self.texts.append(op.text)
            self.s_op.append(index)
            self.s_kind.append(op.kind)
            self.s_line.append(number)
            self.s_motion.append(op.motion if op.kind == _MOVE else NO_MOTION)
            self.s_feed.append(op.feed)
            named = 0
            for c, value in op.target.items():
                named |= 1 << c
                self.pos_op.append(index)
                self.pos_col.append(c)
                self.pos_val.append(value)
            self.s_named.append(named)
            pen = op.pen
            if op.kind in (_PEN_UP, _PEN_DOWN):
                pen = DOWN if op.kind == _PEN_DOWN else UP
            if pen >= 0:
                self.pen_ops.append(index)
                self.pen_states.append(pen)
            if op.dwell:
                self.dwell_ops.append(index)
                self.dwell_s.append(op.dwell)
            if op.arc is not None and len(op.arc):
                self.arc_ops.extend([index] * len(op.arc))
                self.arc_blocks.append(op.arc)
            if op.message:
                self.messages[index] = op.message
            self.translated += op.translated

    # --- the result ------------------------------------------------------------------

    def data(self) -> GcodeData:
        n = len(self.texts)
        k = len(self.columns)
        if k > 16:
            raise JobFileError(self.file, 0, "more than 16 axes")
        kinds = np.full(n, _MOVE, dtype=np.uint8)
        lines = np.zeros(n, dtype=np.int32)
        motion = np.full(n, NO_MOTION, dtype=np.uint8)
        feed = np.full(n, np.nan)
        named = np.zeros(n, dtype=np.uint16)
        positions = np.full((n, k), np.nan)

        # Plain moves, placed run by run.
        if self.runs:
            # The runs cover the plain moves in order, so plain move r is operation r + shift.
            k0s, k1s, op0s = (np.array(v, dtype=np.int64) for v in zip(*self.runs, strict=True))
            ranks = np.arange(int(k1s[-1]))
            ops = ranks + np.repeat(op0s - k0s, k1s - k0s)
            lines[ops] = self.plain_lines[ranks]
            motion[ops] = self.fast_g[ranks].astype(np.uint8)
            feed[ops] = self.fast_f[ranks]
            named[ops] = 0b11
            positions[ops, 0] = self.fast_x[ranks]
            positions[ops, 1] = self.fast_y[ranks]

        # Everything else.
        slow = _numbers(self.s_op, np.int64)
        kinds[slow] = _numbers(self.s_kind, np.uint8)
        lines[slow] = _numbers(self.s_line, np.int32)
        motion[slow] = _numbers(self.s_motion, np.uint8)
        feed[slow] = _numbers(self.s_feed, np.float64)
        named[slow] = _numbers(self.s_named, np.uint16)
        positions[_numbers(self.pos_op, np.int64), _numbers(self.pos_col, np.int64)] = _numbers(
            self.pos_val, np.float64
        )

        # Modal values carry forward: positions per axis, the feed.
        steps = np.arange(n)
        for c in range(k):
            valid = (named & (1 << c)) != 0
            positions[:, c] = positions[np.maximum.accumulate(np.where(valid, steps, 0)), c]
        if n:
            given = ~np.isnan(feed)
            feed = feed[np.maximum.accumulate(np.where(given, steps, 0))]

        # The pen: from the pen operations, or G1/G2/G3 as work when the file has none.
        pen_info = bool(self.pen_ops)
        if pen_info:
            events = _numbers(self.pen_ops, np.int64)
            states = _numbers(self.pen_states, np.uint8).astype(bool)
            last = np.searchsorted(events, steps, side="right") - 1
            pen = np.where(last >= 0, states[np.maximum(last, 0)], False)
        else:
            pen = (motion == LINEAR) | (motion == CW_ARC) | (motion == CCW_ARC)

        arc_points = np.full((len(self.arc_ops), k), np.nan)
        row = 0
        for block in self.arc_blocks:
            arc_points[row : row + len(block), : block.shape[1]] = block
            row += len(block)
        return GcodeData(
            self.file,
            tuple(self.columns),
            kinds,
            lines,
            motion,
            feed,
            pen,
            pen_info,
            positions,
            named,
            self.texts,
            self.messages,
            _numbers(self.dwell_ops, np.int64),
            _numbers(self.dwell_s, np.float64),
            _numbers(self.arc_ops, np.int64),
            arc_points,
        )

    def notes(self, data: GcodeData) -> tuple[str, ...]:
        """What the operator should know about how the file was taken."""
        notes: list[str] = []
        if self.translated:
            plural = "line" if self.translated == 1 else "lines"
            notes.append(
                f"{self.translated} pen {plural} sent as the {self.title}'s "
                f"{self.pen_up.text}/{self.pen_down.text}"
            )
        for word, (down, up) in sorted(self.servo.items()):
            notes.append(f"pen servo {word}: S{down:g} lowers the pen, S{up:g} lifts it")
        if self.z_pen:
            notes.append("Z heights are the pen: above 0 up, 0 or below down")
        if self.z_dropped:
            notes.append(
                f"Z not sent on {self.z_dropped} line(s): Z is the {self.title}'s pen and this "
                "file's Z never lifts it"
            )
        if self.g21_dropped:
            plural = "line" if self.g21_dropped == 1 else "lines"
            notes.append(f"{self.g21_dropped} G21 {plural} not sent: the machine works in mm")
        if self.realtime_dropped:
            notes.append("? not sent: the station asks for the status itself")
        if not data.pen_info and (data.kinds == _MOVE).any():
            notes.append("no pen commands: G0 moves are shown as travel, G1/G2/G3 as work")
        by_reason: dict[str, list[int]] = {}
        for number, _code, reasons in self.skipped:
            for reason in reasons:
                by_reason.setdefault(reason, []).append(number)
        for reason, numbers in by_reason.items():
            shown = ", ".join(str(n) for n in numbers[:10])
            more = f" and {len(numbers) - 10} more" if len(numbers) > 10 else ""
            notes.append(f"skipped {len(numbers)} line(s): {reason} (lines {shown}{more})")
        return tuple(notes)


def _numbers(column: array[Any], dtype: type[np.generic]) -> np.ndarray:
    """An array column as numpy, without a copy through Python objects."""
    return np.frombuffer(column, dtype=dtype) if len(column) else np.zeros(0, dtype=dtype)


def load_gcode(
    path: Path,
    axis_names: Sequence[str],
    settings: GcodeSettings | None = None,
    *,
    translate_pen: bool = True,
    skip_unsupported: bool = False,
    machine_title: str = "",
) -> GcodeProgram:
    """Read a G-code file for a machine with ``axis_names`` and ``settings`` (None: GRBL).

    Raises JobFileError (file:line) for text that is not G-code at all; what
    is G-code but beyond this machine is returned in ``unsupported`` (or, with
    ``skip_unsupported``, as comments listed in the notes).
    """
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise JobFileError(path.name, 0, f"cannot read: {exc}") from exc
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise JobFileError(
            path.name, line, f"not UTF-8 text (byte 0x{raw[exc.start]:02x})"
        ) from None
    del raw
    text = text.removeprefix("\ufeff")
    if "\r" in text:
        text = text.replace("\r\n", "\n").replace("\r", "\n")
    parser = _Parser(
        path.name,
        axis_names,
        settings or GcodeSettings(),
        translate_pen,
        skip_unsupported,
        machine_title,
    )
    collecting = gc.isenabled()
    gc.disable()  # millions of small objects, none cyclic: collections would only cost time
    try:
        parser.parse(text)
        del text
        data = parser.data()
    finally:
        if collecting:
            gc.enable()
    if not any(data.texts):
        raise JobFileError(path.name, 0, "no G-code to send in the file")
    problems = tuple(sorted(parser.problems, key=lambda p: p.line))
    return GcodeProgram(
        path.stem,
        GcodeOperations(data),
        path,
        parser.notes(data),
        unsupported=problems,
        data=data,
    )


#: A G-code line: a G/M word (optionally numbered), a GRBL ``$`` command or bare coordinates.
_SNIFF_LINE = re.compile(r"(?:N\d+\s*)?(?:[GM]\d|\$[A-Z$#]|[XYZ]\s*[-+.\d])", re.IGNORECASE)


def sniff_gcode(head: str) -> bool:
    """Most code lines of the head are G/M words, and it is no Excellon file (``M48``)."""
    codes: list[str] = []
    for raw in head.splitlines()[:200]:
        code = _split_comment(raw)[0].strip()
        if code and not code.startswith("%"):
            codes.append(code)
    if not codes or any(code.upper() == "M48" for code in codes):
        return False
    hits = sum(1 for code in codes if _SNIFF_LINE.match(code))
    motion = any(re.match(r"(?:N\d+\s*)?G0*[0-3](?!\d)", c, re.IGNORECASE) for c in codes)
    return motion and hits >= 0.6 * len(codes)
