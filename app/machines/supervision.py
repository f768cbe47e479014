"""What the station says and does when a reported position leaves the envelope of its moves.

The geometry is :mod:`app.machines.envelope`; this is the operator's side of
it: the message (the move the machine was on, what was seen against what was
expected, in the operator's language) and the fault a running job hears of
(:class:`MotionFault`, with the job's operation where the move was one).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.machines.envelope import Deviation, Fault


@dataclass(frozen=True)
class MotionFault:
    """The machine was stopped because it went where nothing sent it: why, and for which job
    operation (None: not a job's move, or not known)."""

    text: str
    op_index: int | None = None


def _fault_words(fault: Fault) -> str:
    if fault is Fault.OUTSIDE_TRAVEL:
        return QCoreApplication.translate("Supervision", "outside the travel")
    if fault is Fault.PAST_TARGET:
        return QCoreApplication.translate("Supervision", "past the target")
    if fault is Fault.MOVED_AT_REST:
        return QCoreApplication.translate("Supervision", "moved while nothing was sent")
    return QCoreApplication.translate("Supervision", "off the path of the moves sent")


def where(names: Sequence[str], point: Sequence[float]) -> str:
    """``X 3.000 Y 18.000``: a position as the operator reads it."""
    return " ".join(
        f"{name} {local_number(value, '.3f')}" for name, value in zip(names, point, strict=False)
    )


def fault_text(deviation: Deviation, names: Sequence[str], *, scale: float = 1.0) -> str:
    """The message of a stop: the move, what was seen, what was expected, how far apart.

    ``scale`` turns the envelope's units into millimetres (the usb3 unit judges counts).
    """
    seen = [value * scale for value in deviation.seen]
    expected = [value * scale for value in deviation.expected]
    move = deviation.label or QCoreApplication.translate("Supervision", "no move")
    return QCoreApplication.translate(
        "Supervision",
        "Machine stopped: it reported {0}, {1} ({2}); expected {3}, {4} mm away",
    ).format(
        where(names, seen),
        _fault_words(deviation.fault),
        move,
        where(names, expected),
        local_number(deviation.distance * scale, ".3f"),
    )
