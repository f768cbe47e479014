"""String-art jobs: the SD-card pair ``param.txt`` + ``poradi.txt``, read and checked.

The winder's original firmware read two files from its SD card:

* ``param.txt``: ``key = value`` lines — ``tvar`` (0 = circle, n ≥ 3 = a
  regular n-gon), ``pocet_hrebiku`` (the nail count) and ``polomer_matrice``
  (the board radius in cm);
* ``poradi.txt``: comma-separated integers — the number of nail indices
  that follow, then the nail indices in winding order (0-based).

The operator may open either file: the other one is looked for in the same
directory under its usual name (case ignored, as on a FAT SD card).
Public generators write the nail sequence alone, without the count and
without a ``param.txt``; such a file loads with :func:`load_string_art` and
parameters the operator supplies, and the job loader raises
:class:`NeedsNailCount` so the dock can ask for them.

What is tolerated: blank lines, ``#``/``;``/``//`` comment lines and
``# comments`` after a value in ``param.txt``, ``key=value`` with or without
spaces (``key: value`` too), keys in any case, a UTF-8 byte-order mark, CRLF
line ends, a trailing comma, and in ``poradi.txt`` commas, semicolons,
spaces and line breaks alike as separators (empty fields between two commas
are skipped).  A decimal comma
is accepted in ``param.txt`` values (``polomer_matrice = 14,5``), where a
comma cannot be a separator; nail indices must be whole numbers.

Whether a nail list starts with its count: a file named ``poradi.txt``
always does (it is the firmware's format, so a count that disagrees is an
error on its line); any other file does when its first number equals the
number of numbers after it, and is a bare list otherwise.

Every number is bounded before it sizes anything: at most
:data:`MAX_NAILS` nails, a polygon of at most :data:`MAX_TVAR` sides, a
radius of at most :data:`MAX_RADIUS_CM`, nail indices of at most
:data:`MAX_INDEX_DIGITS` digits (a longer one is out of range however many
nails the board has) and at most :data:`MAX_ENTRIES` entries.

Every refusal is a :class:`~app.jobs.program.JobFileError` naming the file
and the line; a missing ``param.txt`` key is reported on line 0.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from types import MappingProxyType
from typing import Any

import numpy as np

from app.jobs.formats.string_art.geometry import NAIL_INSET_MM, nail_polar, nail_positions
from app.jobs.names import quoted
from app.jobs.program import JobFileError, SourceRef
from app.jobs.reading import decode_job_text, read_job_bytes, read_job_text
from app.jobs.texts import translate

PARAM_NAME = "param.txt"
PORADI_NAME = "poradi.txt"
PARAM_KEYS = ("tvar", "pocet_hrebiku", "polomer_matrice")
MIN_NAILS = 3
#: The most nails a board may have (boards are wound with a few hundred).
MAX_NAILS = 10_000
#: The most sides of a polygonal board.
MAX_TVAR = 1_000
#: The largest board radius, in cm (no winder turns a board of 10 m).
MAX_RADIUS_CM = 500.0
#: The most nail indices in a sequence.
MAX_ENTRIES = 5_000_000
#: A nail index with more digits is out of range on any board (MAX_NAILS has five).
MAX_INDEX_DIGITS = 9

_SEPARATORS = re.compile(r"[,;\s]+")
_INTEGER = re.compile(r"[+-]?\d+")
_PARAM_LINE = re.compile(r"^\s*(tvar|pocet_hrebiku|polomer_matrice)\s*[=:]", re.I | re.M)


@dataclass(frozen=True)
class StringArtParams:
    """The board: its shape, nail count and radius (what ``param.txt`` holds)."""

    tvar: int  # 0: circle; n ≥ 3: a regular n-gon
    nails: int
    radius_cm: float

    @property
    def shape(self) -> str:
        if self.tvar == 0:
            return translate("JobFile", "circle")
        return translate("JobFile", "{0}-gon").format(self.tvar)

    def check(self) -> str | None:
        """Why these parameters cannot make a board, or None when they can."""
        return _check_tvar(self.tvar) or _check_nails(self.nails) or _check_radius(self.radius_cm)


@dataclass(frozen=True)
class StringArtJob:
    """A checked board and nail sequence; equal jobs wind the same picture.

    The source paths and line numbers are where it came from (for messages),
    not part of the job: an exported and re-read job equals the original.
    """

    params: StringArtParams
    sequence: tuple[int, ...]
    poradi_path: Path | None = field(default=None, compare=False)
    param_path: Path | None = field(default=None, compare=False)
    #: The line of each sequence entry in ``poradi_path`` (1-based; int32 for long lists).
    entry_lines: Sequence[int] | np.ndarray = field(default=(), compare=False)
    #: The line of each ``param.txt`` key (absent: supplied by the operator).
    param_lines: Mapping[str, int] = field(
        default_factory=lambda: MappingProxyType({}), compare=False
    )

    @property
    def name(self) -> str:
        path = self.poradi_path
        if path is None:
            return "string art"
        if path.name.lower() == PORADI_NAME and path.parent.name:
            return path.parent.name
        return path.stem

    def nail_positions(self) -> np.ndarray:
        """(nails, 2) in mm on the board, nail 0 on +X, counter-clockwise."""
        p = self.params
        return nail_positions(p.tvar, p.nails, p.radius_cm)

    def nail_polar(self) -> tuple[np.ndarray, np.ndarray]:
        """(angle in degrees within 0…360, radius in mm) per nail."""
        p = self.params
        return nail_polar(p.tvar, p.nails, p.radius_cm)

    def thread_length_mm(self) -> float:
        """Straight nail-to-nail thread from the first entry to the last (centres, no wraps)."""
        return self._thread_length_mm

    @cached_property
    def _thread_length_mm(self) -> float:
        # Once per job: a generator's list has millions of entries, and summaries repeat it.
        # Chunk by chunk (each overlapping the next by one entry): the points of a whole
        # 2-million-entry list at once were 80 MB of temporaries at the load's peak.
        positions = self.nail_positions()
        indices = self.indices
        total = 0.0
        for first in range(0, max(len(indices) - 1, 0), CONVERT_CHUNK):
            points = positions[indices[first : first + CONVERT_CHUNK + 1]]
            total += float(np.hypot(*np.diff(points, axis=0).T).sum())
        return total

    @cached_property
    def indices(self) -> np.ndarray:
        """The sequence as a read-only int64 array, made once per job.

        A job read from a file has it already (:meth:`read`).  Converting two
        million Python ints in one numpy call holds the interpreter lock for a
        tenth of a second, a stall of the window while the dock's worker
        loads, and the loader, the preview and the summary each needed it.
        """
        return int_array(self.sequence)

    @classmethod
    def read(cls, indices: np.ndarray, **fields: Any) -> StringArtJob:
        """A job read from a file whose numbers are already the array ``indices``."""
        job = cls(**fields)
        indices.flags.writeable = False
        job.__dict__["indices"] = indices  # the cached property's value (the class is frozen)
        return job

    def entry_source(self, entry: int) -> SourceRef:
        """Where sequence entry ``entry`` (0-based) is written."""
        name = self.poradi_path.name if self.poradi_path is not None else PORADI_NAME
        line = int(self.entry_lines[entry]) if entry < len(self.entry_lines) else 0
        return SourceRef(name, line)

    def param_source(self, key: str = "pocet_hrebiku") -> SourceRef:
        """Where ``key`` is written; line 0 of "parameters entered" when the operator gave it."""
        if self.param_path is None or key not in self.param_lines:
            return SourceRef("parameters entered", 0)
        return SourceRef(self.param_path.name, self.param_lines[key])

    @property
    def connections(self) -> int:
        """Threads from nail to nail: one fewer than the nails visited (the generator's count)."""
        return max(0, len(self.sequence) - 1)

    def summary(self, estimate_s: float | None = None) -> str:
        """Totals for the operator: nails, connections, thread length, estimated time."""
        p = self.params
        text = translate(
            "JobFile", "{0} nails on a {1} of {2:g} cm radius, {3} connections, thread {4:.1f} m"
        ).format(p.nails, p.shape, p.radius_cm, self.connections, self.thread_length_mm() / 1000)
        if estimate_s is not None and math.isfinite(estimate_s):
            text += translate("JobFile", ", about {0}").format(_clock(estimate_s))
        return text


class NeedsNailCount(JobFileError):
    """A bare nail list with no ``param.txt``: the operator must give the board.

    ``min_nails`` is the least nail count the list allows (its largest index
    plus one); ``entries`` the number of nail indices read.
    """

    def __init__(self, path: Path, min_nails: int, entries: int) -> None:
        super().__init__(
            path.name,
            0,
            translate(
                "JobFile",
                "a nail list without {0}: give the board (shape, at least {1} nails, radius) "
                "to load its {2} entries",
            ).format(PARAM_NAME, min_nails, entries),
        )
        self.path = path
        self.min_nails = min_nails
        self.entries = entries


# --- reading ---------------------------------------------------------------------------------


def read_text(path: Path) -> str:
    return read_job_text(path)


def _number(text: str) -> float | None:
    try:
        return float(text.replace(",", "."))
    except ValueError:
        return None


def read_params(path: Path) -> tuple[StringArtParams, dict[str, int]]:
    """``param.txt`` as parameters and the line of each key; JobFileError names the line."""
    found: dict[str, tuple[float, int, str]] = {}
    for number, raw in enumerate(read_text(path).splitlines(), start=1):
        line = raw.strip()
        if not line or line.startswith(("#", ";", "//")):
            continue
        key, sep, value = line.replace(":", "=", 1).partition("=")
        key = key.strip().lower()
        value = value.partition("#")[0].strip().rstrip(";").strip()
        if not sep or not key:
            raise JobFileError(
                path.name,
                number,
                translate("JobFile", "expected 'key = value', found {0}").format(quoted(line)),
            )
        if key not in PARAM_KEYS:
            continue  # the firmware ignores keys it does not know; so does the station
        if key in found:
            first = found[key][1]
            raise JobFileError(
                path.name,
                number,
                translate("JobFile", "{0} given twice (first on line {1})").format(key, first),
            )
        parsed = _number(value)
        if parsed is None or math.isnan(parsed):
            raise JobFileError(
                path.name,
                number,
                translate("JobFile", "{0} = {1} is not a number").format(key, repr(value[:40])),
            )
        if not math.isfinite(parsed):
            raise JobFileError(
                path.name,
                number,
                translate("JobFile", "{0} = {1} is too large").format(key, repr(value[:40])),
            )
        if key != "polomer_matrice" and parsed != int(parsed):
            raise JobFileError(
                path.name,
                number,
                translate("JobFile", "{0} = {1} is not a whole number").format(key, value),
            )
        found[key] = (parsed, number, value)
    for key in PARAM_KEYS:
        if key not in found:
            raise JobFileError(
                path.name,
                0,
                translate("JobFile", "no '{0} = …' line (line 0: missing, not wrong)").format(key),
            )
    lines = {key: found[key][1] for key in PARAM_KEYS}
    params = StringArtParams(
        tvar=int(found["tvar"][0]),
        nails=int(found["pocet_hrebiku"][0]),
        radius_cm=found["polomer_matrice"][0],
    )
    for key, reason in (
        ("tvar", _check_tvar(params.tvar)),
        ("pocet_hrebiku", _check_nails(params.nails)),
        ("polomer_matrice", _check_radius(params.radius_cm)),
    ):
        if reason is not None:
            raise JobFileError(path.name, lines[key], reason)
    return params, lines


def _check_tvar(tvar: int) -> str | None:
    if tvar == 0 or 3 <= tvar <= MAX_TVAR:
        return None
    if tvar > MAX_TVAR:
        return translate("JobFile", "tvar = {0}: a polygon has at most {1} sides").format(
            _short(tvar), MAX_TVAR
        )
    return translate(
        "JobFile", "tvar = {0}: the shape must be 0 (a circle) or 3 or more (a regular polygon)"
    ).format(tvar)


def _check_nails(nails: int) -> str | None:
    if MIN_NAILS <= nails <= MAX_NAILS:
        return None
    if nails > MAX_NAILS:
        return translate("JobFile", "pocet_hrebiku = {0}: a board has at most {1} nails").format(
            _short(nails), MAX_NAILS
        )
    return translate("JobFile", "pocet_hrebiku = {0}: a board needs at least {1} nails").format(
        nails, MIN_NAILS
    )


def _short(value: int) -> str:
    """A whole number as a message shows it: a huge one by its size, not its 4000 digits."""
    text = str(value) if abs(value) < 10**30 else f"{float(value):.3g}"
    return text


def _check_radius(radius_cm: float) -> str | None:
    if math.isfinite(radius_cm) and NAIL_INSET_MM / 10 < radius_cm <= MAX_RADIUS_CM:
        return None
    if math.isfinite(radius_cm) and radius_cm > MAX_RADIUS_CM:
        limit = f"{MAX_RADIUS_CM:g} cm"
        return translate(
            "JobFile", "polomer_matrice = {0:g} cm: a board's radius is at most {1}"
        ).format(radius_cm, limit)
    return translate(
        "JobFile",
        "polomer_matrice = {0:g} cm: the nails sit {1:g} cm inside the edge, so the radius "
        "must be larger than {1:g} cm",
    ).format(radius_cm, NAIL_INSET_MM / 10)


@dataclass(frozen=True)
class NailList:
    """The integers of a nail-order file: the sequence, its lines, and the count if written."""

    sequence: tuple[int, ...]
    lines: np.ndarray  # int32, the line of each entry
    count: int | None
    count_line: int
    #: The sequence as int64 (what numpy reads; the tuple is made from it).
    array: np.ndarray = field(default_factory=lambda: np.zeros(0, np.int64), compare=False)


#: Values converted between numpy and Python at a time: one conversion of millions holds the
#: interpreter lock throughout (a tenth of a second), and the GUI thread waits for it.
CONVERT_CHUNK = 65_536


def int_tuple(values: np.ndarray) -> tuple[int, ...]:
    """``tuple(values.tolist())`` in pieces, so the GUI thread gets the lock between them."""
    out: list[int] = [0] * len(values)  # its full size at once: growing it copied it over
    for start in range(0, len(values), CONVERT_CHUNK):
        out[start : start + CONVERT_CHUNK] = values[start : start + CONVERT_CHUNK].tolist()
    return tuple(out)


def int_array(values: Sequence[int]) -> np.ndarray:
    """``np.asarray(values, dtype=np.int64)`` in pieces (see :func:`int_tuple`)."""
    out = np.empty(len(values), dtype=np.int64)
    for start in range(0, len(values), CONVERT_CHUNK):
        out[start : start + CONVERT_CHUNK] = values[start : start + CONVERT_CHUNK]
    return out


#: Byte classes of a nail list: separators, digits, signs, anything else.
_SEPARATOR, _DIGIT, _SIGN, _OTHER = 0, 1, 2, 3
_CLASSES = np.full(256, _OTHER, dtype=np.uint8)
_CLASSES[list(b" ,;\t\r\n\v\f")] = _SEPARATOR
_CLASSES[list(b"0123456789")] = _DIGIT
_CLASSES[list(b"+-")] = _SIGN
_TO_SPACES = bytes.maketrans(b",;\t\r\n\v\f", b"       ")


def read_nail_list(path: Path) -> NailList:
    """The integers of ``path`` (see the module notes for separators and the count).

    Read with numpy in a few passes over the bytes (a generator's list can
    hold millions of entries): each byte's class, where each number starts
    and ends and on which line, the first number that is not a whole number
    or is too long for any board, then every value at once.
    """
    raw = read_job_bytes(path)
    if not raw.isascii() or b"\x00" in raw:
        decode_job_text(raw, path.name)  # UTF-16, binary data, malformed UTF-8: named as such
    raw = raw.removeprefix(b"\xef\xbb\xbf")
    classes = _CLASSES[np.frombuffer(raw, dtype=np.uint8)]
    separator = (classes == _SEPARATOR).view(np.int8)
    change = np.diff(separator, prepend=np.int8(1), append=np.int8(1))
    del separator
    starts = np.flatnonzero(change == -1)  # first byte of each number
    ends = np.flatnonzero(change == 1)  # one past its last byte
    del change
    newlines = np.flatnonzero(np.frombuffer(raw, dtype=np.uint8) == ord("\n"))
    lines = (np.searchsorted(newlines, starts) + 1).astype(np.int32)
    del newlines
    # A number is an optional sign at its start, then digits only: any other byte, or a sign
    # further in, spoils the number it is in.
    bad = np.zeros(len(starts), dtype=bool)
    other = np.flatnonzero(classes == _OTHER)
    bad[np.searchsorted(starts, other, side="right") - 1] = True
    signs = np.flatnonzero(classes == _SIGN)
    owner = np.searchsorted(starts, signs, side="right") - 1
    bad[owner[signs != starts[owner]]] = True
    del other, signs, owner
    signed = classes[starts] == _SIGN if len(starts) else np.zeros(0, dtype=bool)
    bad |= signed & (ends - starts == 1)  # a sign alone
    del classes
    if bad.any():
        k = int(np.flatnonzero(bad)[0])
        text = raw[starts[k] : min(ends[k], starts[k] + 40)].decode("utf-8", "replace")
        raise JobFileError(
            path.name,
            int(lines[k]),
            translate("JobFile", "number {0} of the file: {1} is not a whole number").format(
                k + 1, repr(text)
            ),
        )
    if not len(starts):
        raise JobFileError(path.name, 0, translate("JobFile", "no nail indices in the file"))
    digits = ends - starts - signed
    long = np.flatnonzero(digits > MAX_INDEX_DIGITS)
    if len(long):
        k = int(long[0])
        text = (
            translate(
                "JobFile",
                "the count of the file has {1} digits: out of range on any board "
                "(at most {2} nails, {3} entries)",
            )
            if k == 0 and path.name.lower() == PORADI_NAME
            else translate(
                "JobFile",
                "number {0} of the file has {1} digits: out of range on any board "
                "(at most {2} nails, {3} entries)",
            )
        )
        raise JobFileError(
            path.name,
            int(lines[k]),
            text.format(k + 1, int(digits[k]), MAX_NAILS, MAX_ENTRIES),
        )
    if len(starts) > MAX_ENTRIES + 1:
        raise JobFileError(
            path.name,
            int(lines[MAX_ENTRIES + 1]),
            translate("JobFile", "more than {0} nail indices").format(MAX_ENTRIES),
        )
    del starts, ends, digits, signed
    values = np.fromstring(raw.translate(_TO_SPACES), dtype=np.int64, sep=" ")
    if len(values) != len(lines):  # cannot happen: every number was checked above
        raise JobFileError(path.name, 0, translate("JobFile", "could not read the nail indices"))
    counted = path.name.lower() == PORADI_NAME or int(values[0]) == len(values) - 1
    if not counted:
        return NailList(int_tuple(values), lines, None, 0, values)
    entries = values[1:]
    return NailList(int_tuple(entries), lines[1:], int(values[0]), int(lines[0]), entries)


def check_sequence(path: Path, nails: NailList, params: StringArtParams) -> None:
    """Count, range and repeats; the first problem as a JobFileError on its line."""
    name = path.name
    sequence = nails.sequence
    if nails.count is not None and nails.count != len(sequence):
        raise JobFileError(
            name,
            nails.count_line,
            translate("JobFile", "the count says {0} nail indices, but {1} follow").format(
                nails.count, len(sequence)
            ),
        )
    if len(sequence) < 2:
        raise JobFileError(
            name,
            nails.count_line or 1,
            translate("JobFile", "fewer than two nails: nothing to wind"),
        )
    array = nails.array
    bad = np.flatnonzero((array < 0) | (array >= params.nails))
    if len(bad):
        i = int(bad[0])
        more = (
            translate("JobFile", " ({0} more out of range)").format(len(bad) - 1)
            if len(bad) > 1
            else ""
        )
        raise JobFileError(
            name,
            int(nails.lines[i]),
            translate("JobFile", "entry {0}: nail {1} is out of range 0…{2}{3}").format(
                i + 1, sequence[i], params.nails - 1, more
            ),
        )
    repeats = np.flatnonzero(array[1:] == array[:-1])
    if len(repeats):
        i = int(repeats[0]) + 1
        raise JobFileError(
            name,
            int(nails.lines[i]),
            translate(
                "JobFile", "entries {0} and {1}: nail {2} twice in a row (a thread to itself)"
            ).format(i, i + 1, sequence[i]),
        )


def _partner(path: Path, name: str) -> Path | None:
    """``name`` beside ``path``, in any letter case."""
    try:
        for candidate in path.parent.iterdir():
            if candidate.name.lower() == name and candidate.is_file():
                return candidate
    except OSError:
        return None
    return None


def load_string_art(poradi: Path, param: StringArtParams | None = None) -> StringArtJob:
    """The job of nail-order file ``poradi`` and the board ``param``.

    Without ``param`` the board comes from ``param.txt`` beside a
    ``poradi.txt``; for any other file (a bare generator list) it must be
    given, else :class:`NeedsNailCount` says what the list needs.
    """
    nails = read_nail_list(poradi)
    param_path: Path | None = None
    lines: dict[str, int] = {}
    if param is None:
        if poradi.name.lower() == PORADI_NAME:
            param_path = _partner(poradi, PARAM_NAME)
        if param_path is None:
            # What no board can take is refused before the operator is asked for one.
            check_sequence(poradi, nails, StringArtParams(0, MAX_NAILS, MAX_RADIUS_CM))
            raise NeedsNailCount(poradi, int(nails.array.max()) + 1, len(nails.sequence))
        param, lines = read_params(param_path)
    else:
        reason = param.check()
        if reason is not None:
            raise JobFileError(
                poradi.name,
                0,
                translate("JobFile", "the board entered: {0}").format(reason),
            )
    return _job(poradi, nails, param, param_path, lines)


def read_string_art(path: Path, param: StringArtParams | None = None) -> StringArtJob:
    """Either file of the pair (``param.txt`` finds its ``poradi.txt``), or a nail list."""
    if path.name.lower() == PARAM_NAME or (_looks_like_params(path) and param is None):
        params, lines = read_params(path)  # its errors first: the file the operator chose
        poradi = _partner(path, PORADI_NAME)
        if poradi is None:
            raise JobFileError(
                path.name,
                0,
                translate("JobFile", "no {0} beside it (the nail order)").format(PORADI_NAME),
            )
        return _job(poradi, read_nail_list(poradi), params, path, lines)
    return load_string_art(path, param)


def _job(
    poradi: Path,
    nails: NailList,
    params: StringArtParams,
    param_path: Path | None,
    lines: dict[str, int],
) -> StringArtJob:
    """The job of a nail list read from ``poradi`` on the board ``params``, once it fits."""
    check_sequence(poradi, nails, params)
    return StringArtJob.read(
        nails.array,
        params=params,
        sequence=nails.sequence,
        poradi_path=poradi,
        param_path=param_path,
        entry_lines=nails.lines,
        param_lines=MappingProxyType(lines),
    )


def _looks_like_params(path: Path) -> bool:
    try:
        with path.open(encoding="utf-8", errors="replace") as handle:
            return sniff_params(handle.read(4096))
    except OSError:
        return False


# --- sniffing --------------------------------------------------------------------------------


def sniff_params(head: str) -> bool:
    """A ``param.txt``: a ``tvar``, ``pocet_hrebiku`` or ``polomer_matrice`` line."""
    return bool(_PARAM_LINE.search(head))


def sniff_nail_list(head: str) -> bool:
    """A nail list: nothing but integers, at least four, and not shaped like a point list.

    A point list (2-3 numbers a line on several lines) is left to its own
    loader even when its numbers are whole.
    """
    tokens = [t for t in _SEPARATORS.split(head.strip()) if t]
    if len(tokens) < 4 or not all(_INTEGER.fullmatch(t) for t in tokens):
        return False
    rows = [line for line in head.splitlines() if line.strip()]
    widths = {len([t for t in _SEPARATORS.split(line.strip()) if t]) for line in rows}
    return not (len(rows) >= 2 and widths <= {2, 3})


def sniff_string_art(head: str) -> bool:
    return sniff_params(head) or sniff_nail_list(head)


def _clock(seconds: float) -> str:
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes:02d}:{secs:02d}"
