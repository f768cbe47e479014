"""A macro read into a program by the job parser, from where the machine stands.

The text goes through :class:`~app.jobs.formats.gcode.parser.Parser`, the
G-code files' own reader and pre-flight, with the macro's name as the file
name, so every refusal reads ``macro "Park":2: reason``.  One difference
from a file: a job is checked from the origin (and refused to start anywhere
else when it moves relative to its start), while a macro runs from wherever
the machine stands — ``G91 G0 Z5`` is what macros are for.  So the parser
starts from the machine's work position on every axis, and a relative move
is checked against the travel from there, as the board will execute it.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from PySide6.QtCore import QCoreApplication

from app.jobs.formats.gcode.loader import GcodeOperations, GcodeProgram
from app.jobs.formats.gcode.parser import Parser
from app.jobs.formats.gcode.state import State
from app.jobs.program import JobFileError, LimitViolation
from app.macros.store import Macro
from app.profiles import GcodeSettings, MachineProfile


def macro_file(name: str) -> str:
    """What refusals call the macro in place of a file name: ``macro "Park"``."""
    return f'macro "{name}"'


def macro_program(
    macro: Macro, profile: MachineProfile, start: Mapping[str, float]
) -> GcodeProgram:
    """``macro`` for ``profile``'s machine standing at ``start`` (work position per axis name).

    Raises JobFileError (``macro "Name":line: reason``) where the text is not
    G-code this machine would accept; lines beyond its repertoire are in the
    program's ``unsupported`` for the runner's check, as a file's are.
    """
    file = macro_file(macro.name)
    axis_names = [axis.name for axis in profile.axes]
    parser = Parser(
        file, axis_names, profile.gcode or GcodeSettings(), True, False, profile.shown_title
    )
    # X and Y are the parser's first two columns (its fast path's); the others follow.
    columns = ["X", "Y", *(name.upper() for name in axis_names if name.upper() not in "XY")]
    parser.columns = columns
    parser.state = State(
        [float(start.get(name, math.nan)) for name in columns], [0.0] * len(columns)
    )
    parser.parse(macro.code)
    data = parser.data()
    if not data.sent.any():
        raise JobFileError(
            file, 0, QCoreApplication.translate("Macros", "no G-code to send in the macro")
        )
    return GcodeProgram(
        file,
        GcodeOperations(data),
        None,
        parser.notes(data),
        unsupported=tuple(sorted(parser.problems, key=lambda p: p.line)),
        data=data,
        start_relative=tuple(parser.columns[c] for c in sorted(parser.start_relative)),
    )


def refusal_text(violation: LimitViolation) -> str:
    """One refused operation, as the macro bar lists it: ``macro "Park":2: X 900 is outside
    the travel 0…300`` (an axis it lacks, a word it cannot run: as the jobs dock says it)."""
    if type(violation) is not LimitViolation or not (
        math.isfinite(violation.low) and math.isfinite(violation.high)
    ):
        return str(violation)
    return QCoreApplication.translate(
        "Macros", "{0}: {1} {2:g} is outside the travel {3:g}…{4:g}"
    ).format(
        violation.operation.source,
        violation.axis,
        violation.value,
        violation.low,
        violation.high,
    )


def file_error_text(error: JobFileError) -> str:
    """The parser's refusal with every further bad line it found."""
    return "\n".join(str(e) for e in (error, *error.more))
