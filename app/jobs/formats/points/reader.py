"""Point lists: ``x, y`` (or ``x, y, z``) per line, ``# comments`` and ``wait: message`` lines.

The plainest job an XY stage runs (a scan, an inspection route); a line
``wait: <message>`` makes the runner stop for the operator there.  The
column count of the first position line decides the axes: a 2-column list
on a 3-axis machine moves X and Y only.  Numbers must be finite (``1e999``
and ``nan`` are refused on their line): a position sizes the preview and is
checked against the travel.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from pathlib import Path
from types import MappingProxyType

from PySide6.QtCore import QCoreApplication

from app.jobs.program import JobFileError, Operation, OpKind, Program, SourceRef
from app.jobs.reading import read_job_text


def _is_wait(line: str) -> bool:
    return line.lower().startswith("wait")


def _data_lines(text: str) -> list[str]:
    """Lines that are neither blank, comments nor operator waits: the positions."""
    lines = (line.strip() for line in text.splitlines())
    return [line for line in lines if line and not line.startswith("#") and not _is_wait(line)]


def _fields(line: str) -> list[str]:
    return [f.strip() for f in line.replace(";", ",").split(",")]


def _numbers(line: str) -> bool:
    try:
        [float(f) for f in _fields(line)]
    except ValueError:
        return False
    return True


def sniff_point_list(head: str) -> bool:
    """Two or three comma/semicolon-separated numbers per line, the first few lines agreeing."""
    lines = _data_lines(head)[:5]
    if not lines:
        return False
    counts = {len(_fields(line)) for line in lines}
    return len(counts) == 1 and counts <= {2, 3} and all(_numbers(line) for line in lines)


def parse_point_list(text: str, name: str, axis_names: Sequence[str], stem: str) -> Program:
    """The operations of point-list ``text`` (file ``name``) on ``axis_names``, in order."""
    ops: list[Operation] = []
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        where = SourceRef(name, number)
        if not line:
            continue
        if line.startswith("#"):
            ops.append(Operation(OpKind.COMMENT, where, message=line.lstrip("# ")))
            continue
        if _is_wait(line):
            message = line.partition(":")[2].strip() or QCoreApplication.translate(
                "JobFile", "continue when ready"
            )
            ops.append(Operation(OpKind.WAIT, where, message=message))
            continue
        fields = _fields(line)
        if len(fields) != len(axis_names):
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate("JobFile", "expected {0} numbers, found {1}").format(
                    len(axis_names), len(fields)
                ),
            )
        try:
            values = [float(f) for f in fields]
        except ValueError:
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate("JobFile", "not a number in {0}").format(
                    repr(line[:80])
                ),
            ) from None
        if not all(math.isfinite(v) for v in values):
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate("JobFile", "not a finite number in {0}").format(
                    repr(line[:80])
                ),
            )
        target = MappingProxyType(dict(zip(axis_names, values, strict=True)))
        ops.append(Operation(OpKind.MOVE, where, target))
    if not any(op.kind is OpKind.MOVE for op in ops):
        raise JobFileError(
            name, 0, QCoreApplication.translate("JobFile", "no positions in the file")
        )
    return Program(stem, tuple(ops))


def load_point_list(path: Path, axis_names: Sequence[str] = ("X", "Y")) -> Program:
    """The point list ``path`` with exactly one number per axis of ``axis_names`` a line."""
    program = parse_point_list(read_job_text(path), path.name, axis_names, path.stem)
    return Program(program.name, program.operations, path)


def load_points(path: Path, axis_names: Sequence[str]) -> Program:
    """A point list for this machine: as many axes as the first position line has numbers.

    A column count the machine cannot take is refused on the line that has it.
    """
    text = read_job_text(path)
    lines = _data_lines(text)
    columns = len(_fields(lines[0])) if lines else len(axis_names)
    axes = tuple(axis_names[:columns]) if columns <= len(axis_names) else tuple(axis_names)
    program = parse_point_list(text, path.name, axes, path.stem)
    return Program(program.name, program.operations, path)
