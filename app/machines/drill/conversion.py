"""Millimetres to the drill's microsteps, as the host does it (docs/protocols.md §3).

The drill knows only microsteps: the host converts with the profile's
constants (steps per revolution x microsteps ÷ lead: 19.8 a mm on X, 19.7 on
Y) and does all the rounding, half away from zero, in decimal, so that
12.5 mm x 19.8 is 247.5 exactly and becomes 248.  One place for the rule: the
session, the step-through and the teaching constants all count with it.
"""

from __future__ import annotations

from decimal import ROUND_HALF_UP, Decimal

from app.profiles import AxisProfile


def profile_microsteps_per_mm(axis: AxisProfile) -> Decimal:
    """The profile's microsteps a millimetre for ``axis``, exact in decimal."""
    return Decimal(axis.steps_per_rev) * Decimal(axis.microsteps) / Decimal(str(axis.lead))


def mm_to_microsteps(mm: float, per_mm: Decimal) -> int:
    """Nearest microstep to ``mm``, half away from zero, computed in decimal."""
    exact = Decimal(str(mm)) * per_mm
    steps = int(exact.copy_abs().quantize(Decimal(1), rounding=ROUND_HALF_UP))
    return -steps if exact < 0 else steps
