"""G-code job files: read once into arrays, checked against the machine that will run them.

The loader is split by what each part holds: :mod:`app.jobs.formats.gcode.program`
(the array-backed program a file becomes), :mod:`app.jobs.formats.gcode.words`
(comments, ``N`` numbers, checksums, words), :mod:`app.jobs.formats.gcode.pen` (the
pen conventions), :mod:`app.jobs.formats.gcode.plain_moves` (the fast path for plain
moves), :mod:`app.jobs.formats.gcode.parser` (the modal state, line by line),
:mod:`app.jobs.formats.gcode.arcs` (arcs flattened) and :mod:`app.jobs.formats.gcode.columns`
(the parsed operations in compact columns).  This module reads the file and
is what the rest of the station imports.

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
lines.  Malformed text (``X1..2``, non-UTF-8 bytes) and every line GRBL 1.1
would answer with an error (the pre-flight, :mod:`app.jobs.formats.gcode.parser`)
are refused at load with file:line, like the other loaders; the file is read
through :mod:`app.jobs.reading` (regular files only, a size cap).
"""

from __future__ import annotations

import gc
import re
from collections.abc import Sequence
from pathlib import Path

from PySide6.QtCore import QCoreApplication

from app.jobs.formats.gcode.arcs import ARC_TOLERANCE_MM, MAX_ARC_SEGMENTS, MIN_ARC_SEGMENTS
from app.jobs.formats.gcode.parser import AXIS_LETTERS, INCH_MM, PARAMETER_REASON, Parser
from app.jobs.formats.gcode.pen import DOWN, UP
from app.jobs.formats.gcode.program import (
    CCW_ARC,
    CW_ARC,
    HOME,
    KIND_CODE,
    KINDS,
    LINEAR,
    NO_MOTION,
    RAPID,
    GcodeData,
    GcodeOperations,
    GcodeProblem,
    GcodeProgram,
)
from app.jobs.formats.gcode.words import MAX_LINE_CHARS
from app.jobs.program import JobFileError
from app.jobs.reading import read_job_text
from app.profiles import GcodeSettings
from protocol.gcode.words import split_comment

__all__ = [
    "ARC_TOLERANCE_MM",
    "AXIS_LETTERS",
    "CCW_ARC",
    "CW_ARC",
    "DOWN",
    "HOME",
    "INCH_MM",
    "KINDS",
    "KIND_CODE",
    "LINEAR",
    "MAX_ARC_SEGMENTS",
    "MAX_LINE_CHARS",
    "MIN_ARC_SEGMENTS",
    "NO_MOTION",
    "PARAMETER_REASON",
    "RAPID",
    "UP",
    "GcodeData",
    "GcodeOperations",
    "GcodeProblem",
    "GcodeProgram",
    "load_gcode",
    "sniff_gcode",
]


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
    parser = Parser(
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
        # The text is the parser's alone, so it can let it go once split into lines.
        parser.parse(_lines_text(path))
        data = parser.data()
    finally:
        if collecting:
            gc.enable()
    if not data.sent.any():
        raise JobFileError(
            path.name, 0, QCoreApplication.translate("JobFile", "no G-code to send in the file")
        )
    problems = tuple(sorted(parser.problems, key=lambda p: p.line))
    return GcodeProgram(
        path.stem,
        GcodeOperations(data),
        path,
        parser.notes(data),
        unsupported=problems,
        data=data,
        start_relative=tuple(parser.columns[c] for c in sorted(parser.start_relative)),
    )


def _lines_text(path: Path) -> str:
    """The file's text with its line ends made ``\n``."""
    text = read_job_text(path)
    if "\r" in text:
        return text.replace("\r\n", "\n").replace("\r", "\n")
    return text


#: A G-code line: a G/M word (optionally numbered), a GRBL ``$`` command or bare coordinates.
_SNIFF_LINE = re.compile(r"(?:N\d+\s*)?(?:[GM]\d|\$[A-Z$#]|[XYZ]\s*[-+.\d])", re.IGNORECASE)


def sniff_gcode(head: str) -> bool:
    """Most code lines of the head are G/M words, and it is no Excellon file (``M48``)."""
    codes: list[str] = []
    for raw in head.splitlines()[:200]:
        code = split_comment(raw)[0].strip()
        if code and not code.startswith("%"):
            codes.append(code)
    if not codes or any(code.upper() == "M48" for code in codes):
        return False
    hits = sum(1 for code in codes if _SNIFF_LINE.match(code))
    motion = any(re.match(r"(?:N\d+\s*)?G0*[0-3](?!\d)", c, re.IGNORECASE) for c in codes)
    return motion and hits >= 0.6 * len(codes)
