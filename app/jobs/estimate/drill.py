"""How long a program takes on the PCB drill, in closed form.

The drill has no ramps and runs one procedure at a time: every axis steps at
one constant period per microstep, X and Y move one after the other, a drill
cycle and a pen movement take fixed times, and each command costs a little
more for the round trip (sent after the previous ``D``, started at the
device's next control cycle).
"""

from __future__ import annotations

from collections.abc import Mapping
from decimal import ROUND_HALF_UP, Decimal

from app.jobs.estimate.model import Estimate
from app.jobs.program import OpKind, Program
from app.profiles import MachineProfile
from protocol.drill.timing import DRILL_CYCLE_S, PEN_TIME_S, STEP_PERIODS_S

__all__ = ["DRILL_CYCLE_S", "PEN_TIME_S", "estimate_drill"]

#: Per drill command: its ``D`` leaves at the end of the control cycle in which the procedure
#: ends, half a 5 ms cycle late on average; the host's next command starts at the cycle after.
#: (A real 19200-baud line adds about half a millisecond per byte on top.)
DRILL_COMMAND_OVERHEAD_S = 0.0025


def _microsteps(mm: float, per_mm: Decimal) -> int:
    """Nearest microstep, half away from zero, in decimal (as the drill session rounds)."""
    exact = Decimal(str(mm)) * per_mm
    steps = int(exact.copy_abs().quantize(Decimal(1), rounding=ROUND_HALF_UP))
    return -steps if exact < 0 else steps


def estimate_drill(
    program: Program,
    profile: MachineProfile,
    *,
    start: Mapping[str, float] | None = None,
    overhead_s: float = DRILL_COMMAND_OVERHEAD_S,
) -> Estimate:
    """Time ``program`` on the PCB drill from ``start`` (mm per axis name; 0 when unknown).

    A MOVE sends one command per axis of its target, in order; each takes
    ``|Δ microsteps| x period``.  Positions are rounded to microsteps exactly
    as the session sends them, so the distances are the machine's.
    """
    per_mm = {
        axis.name: Decimal(axis.steps_per_rev) * Decimal(axis.microsteps) / Decimal(str(axis.lead))
        for axis in profile.axes
    }
    where = {name: _microsteps((start or {}).get(name, 0.0), k) for name, k in per_mm.items()}
    elapsed = 0.0
    cumulative: list[float] = []
    for op in program:
        if op.kind is OpKind.MOVE:
            for name, target_mm in op.target.items():
                if name not in per_mm:
                    continue
                target = _microsteps(target_mm, per_mm[name])
                period = STEP_PERIODS_S.get(name, 0.0)
                elapsed += abs(target - where[name]) * period + overhead_s
                where[name] = target
        elif op.kind is OpKind.DRILL:
            elapsed += DRILL_CYCLE_S + overhead_s
        elif op.kind in (OpKind.PEN_DOWN, OpKind.PEN_UP):
            elapsed += PEN_TIME_S + overhead_s
        cumulative.append(elapsed)
    return Estimate(elapsed, tuple(cumulative))
