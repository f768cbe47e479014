"""An operation as the operator reads it, in the operator's language.

``Operation.describe()`` is the job's own wording (the runner's messages, the
command line); the jobs dock shows this instead, in the window's language and
with its decimal separator ("najet na X10,000" in Czech).  Only the text shown
changes: what goes on the wire and into files is written elsewhere, with points.
"""

from __future__ import annotations

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.jobs.program import Operation, OpKind
from app.local_numbers import local_number

_KINDS = {
    OpKind.MOVE: QT_TRANSLATE_NOOP("Operation", "move"),
    OpKind.DRILL: QT_TRANSLATE_NOOP("Operation", "drill"),
    OpKind.PEN_UP: QT_TRANSLATE_NOOP("Operation", "pen up"),
    OpKind.PEN_DOWN: QT_TRANSLATE_NOOP("Operation", "pen down"),
    OpKind.WAIT: QT_TRANSLATE_NOOP("Operation", "wait"),
    OpKind.COMMENT: QT_TRANSLATE_NOOP("Operation", "comment"),
    OpKind.GCODE: QT_TRANSLATE_NOOP("Operation", "gcode"),
}


def kind_text(kind: OpKind) -> str:
    return QCoreApplication.translate("Operation", str(_KINDS.get(kind, kind.value)))


def operation_text(op: Operation) -> str:
    """What ``op`` does: "move to X40.000 Y5.000", "najet na X40,000 Y5,000"…"""
    if op.kind is OpKind.MOVE:
        where = " ".join(f"{axis}{local_number(value, '.3f')}" for axis, value in op.target.items())
        return QCoreApplication.translate("Operation", "move to {0}").format(where)
    if op.kind in (OpKind.WAIT, OpKind.COMMENT) and op.message:
        return f"{kind_text(op.kind)}: {op.message}"
    if op.kind is OpKind.GCODE and op.line:
        return op.describe()
    return kind_text(op.kind)
