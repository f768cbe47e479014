"""How long a program takes on the PCB drill, in closed form, from :mod:`protocol.drill.timing`.

The drill has no ramps and runs one procedure at a time: every axis steps at
one constant period per microstep, X and Y move one after the other, a pen
movement takes a fixed time, and each command costs a little more for the
round trip (sent after the previous ``D``, started at the device's next
control cycle).  A drill cycle is long the first time (the drill comes down
from the top of Z) and short afterwards (it hovers where the original's
39-full-step return leaves it); the station cannot ask where Z is, so the
first way down of every job (a ``V`` or a ``K``) is counted long: a second
job on the same power-on is estimated about 2.5 s long.  ``K`` and ``Z``
are the halves of ``V`` (FIDELITY S2-24): ``K`` its way down, ``Z`` its way
back.  Every constant is the profile's (``[timing]``, S2-06).  The homing
before the job (when the station has not seen one on this link) and the park
after it are counted too.
"""

from __future__ import annotations

from collections.abc import Mapping
from decimal import ROUND_HALF_UP, Decimal

from app.jobs.estimate.model import Estimate
from app.jobs.program import OpKind, Program
from app.profiles import MachineProfile
from protocol.drill.timing import DRILL_CYCLE_S, FIRST_DRILL_CYCLE_S

__all__ = ["DRILL_CYCLE_S", "FIRST_DRILL_CYCLE_S", "estimate_drill"]

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
    home_first: bool = False,
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
    timing = profile.drill_timing
    periods = timing.step_periods
    where = {name: _microsteps((start or {}).get(name, 0.0), k) for name, k in per_mm.items()}
    elapsed = 0.0
    if home_first and OpKind.MOVE in program.kinds():
        # N: X, then Y, to the switch and on to the zero (the station's first send).
        elapsed += sum(timing.home_s(name, steps) for name, steps in where.items()) + overhead_s
        where = dict.fromkeys(where, 0)

    def go(target_mm: Mapping[str, float]) -> float:
        took = 0.0
        for name, mm in target_mm.items():
            if name not in per_mm:
                continue
            target = _microsteps(mm, per_mm[name])
            took += abs(target - where[name]) * periods.get(name, 0.0) + overhead_s
            where[name] = target
        return took

    cumulative: list[float] = []
    # Microsteps Z has to go down to the bottom of the stroke: from the top at first.
    above = timing.first_down_microsteps
    for op in program:
        if op.kind is OpKind.MOVE:
            elapsed += go(op.target)
        elif op.kind is OpKind.DRILL:
            elapsed += timing.stroke_s(above) + overhead_s
            above = timing.return_microsteps
        elif op.kind is OpKind.PEN_DOWN:
            elapsed += timing.down_s(above) + overhead_s
            above = 0
        elif op.kind is OpKind.PEN_UP:
            elapsed += timing.up_s() + overhead_s
            above = min(above + timing.return_microsteps, timing.first_down_microsteps)
        cumulative.append(elapsed)
    if profile.park and len(program):
        # The park after the last operation (and P, which moves nothing more, when it
        # is P's own place): in the total, after every operation.
        elapsed += go(profile.park) + overhead_s
    return Estimate(elapsed, tuple(cumulative))
