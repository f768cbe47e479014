"""How long a program takes on the machine, found by replaying it on the emulator's mechanism.

The runner's progress bar needs a total before anything moves, and the
operator wants a time they can plan around.  Rather than a second, simpler
motion model that would drift from the device, the program is replayed on the
same :class:`~protocol.emulator.mechanism.Axis` the firmware emulator runs:
trapezoids, start-speed jumps and triangular short moves come out exactly as
the device does them.  Each move is one ``time_to_idle`` and one ``advance``
in closed form, never small time steps, so a long job is estimated in a blink.

What the mechanism does not know is the host: the runner sends the next move
as soon as it sees the previous one finished, and it sees that only in the
echo to the next periodic frame, i.e. on average half a period after arrival,
plus the control cycle the echo waits for.  That overhead is added per move;
WAIT and COMMENT operations cost nothing here (the operator's time is not the
machine's).

G-code machines (``gcode`` dialect) plan their own moves from feeds and
accelerations, and their files can be a million lines long, so they are
timed by :func:`app.jobs.estimate.gcode.estimate_gcode` from numpy columns.

The PCB drill (``drill`` dialect) has no ramps and runs one procedure at a
time, so it is timed in closed form instead (:func:`estimate_drill`): every
axis steps at one constant period per microstep, X and Y move one after the
other, a drill cycle and a pen movement take fixed times, and each command
costs a little more for the round trip (sent after the previous ``D``,
started at the device's next control cycle).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from decimal import ROUND_HALF_UP, Decimal

import numpy as np
import numpy.typing as npt

from app.jobs.program import OpKind, Program
from app.machine import MachineModel, ParameterState
from app.profiles import MachineProfile
from protocol.emulator.mechanism import Axis, AxisLimits
from protocol.stage.codec import EchoType

#: The stage's control cycle (s): an echo leaves at the end of the cycle its frame arrived in.
CONTROL_CYCLE_S = 0.005

#: What the XY stage holds until the station has read otherwise (PROTOCOLS.md table 1.4).
DEFAULT_PARAMETERS: Mapping[int, int] = {
    EchoType.FAST_SPEED: 10_000,
    EchoType.SLOW_SPEED: 2_000,
    EchoType.ACCELERATION: 20_000,
    EchoType.START_SPEED: 500,
}

#: The PCB drill's seconds per microstep, per axis name (PROTOCOLS.md section 3).
DRILL_STEP_PERIODS_S: Mapping[str, float] = {"X": 0.0013, "Y": 0.0015}
#: One ``V``: Z down to the sensor and 12 microsteps more at 2.5 ms, 0.2 s dwell, up in full steps.
DRILL_CYCLE_S = 1.35875
#: One ``K`` or ``Z``: the pen's solenoid settling.
PEN_TIME_S = 0.15
#: Per drill command: its ``D`` leaves at the end of the control cycle in which the procedure
#: ends, half a 5 ms cycle late on average; the host's next command starts at the cycle after.
#: (A real 19200-baud line adds about half a millisecond per byte on top.)
DRILL_COMMAND_OVERHEAD_S = 0.0025

#: Per axis name: parameter TYPE → value in wire units (µm, µm/s, µm/s²).
Parameters = Mapping[str, Mapping[int, int]]


@dataclass(frozen=True)
class Estimate:
    """Model times of a program: ``cumulative_s[i]`` is when operation ``i`` ends."""

    total_s: float
    #: A tuple, or a numpy array for G-code programs (a million floats as objects would not do).
    cumulative_s: Sequence[float] | npt.NDArray[np.float64]

    def remaining_after(self, done: int) -> float:
        """Model time still to go once the first ``done`` operations are complete."""
        if done <= 0 or len(self.cumulative_s) == 0:
            return self.total_s
        ended = float(self.cumulative_s[min(done, len(self.cumulative_s)) - 1])
        return max(self.total_s - ended, 0.0)


def parameters_from_model(model: MachineModel) -> dict[str, dict[int, int]]:
    """The dynamics the device reported (read or confirmed); unknown ones are left out."""
    found: dict[str, dict[int, int]] = {}
    for axis in model.axes:
        values: dict[int, int] = {}
        for parameter, entry in axis.parameters.items():
            known = entry.state in (ParameterState.READ, ParameterState.CONFIRMED)
            if known and entry.value is not None:
                values[parameter] = entry.value
        found[axis.name] = values
    return found


def estimate(
    program: Program,
    profile: MachineProfile,
    parameters: Parameters,
    period_s: float,
    *,
    fast: bool = True,
    start: Mapping[str, float] | None = None,
    control_cycle_s: float = CONTROL_CYCLE_S,
) -> Estimate:
    """Replay ``program`` from ``start`` (mm per axis name; 0 when unknown) and time it.

    ``parameters`` are the device's, as read into the model; whatever is
    missing falls back to the XY stage's defaults.  ``fast`` is the speed the
    session has selected.  Axes the profile lacks are ignored here: the
    runner's pre-check refuses such programs before this matters.  A drill
    profile is timed by :func:`estimate_drill` (``parameters``, ``period_s``
    and ``fast`` do not apply to it), a G-code profile by
    :func:`~app.jobs.estimate.gcode.estimate_gcode`.
    """
    if profile.dialect == "drill":
        return estimate_drill(program, profile, start=start)
    if profile.dialect == "gcode":
        # Imported here: gcode_estimate builds on this module's Estimate.
        from app.jobs.estimate.gcode import estimate_gcode

        return estimate_gcode(program, profile, start=start)
    axes: dict[str, Axis] = {}
    speeds: dict[str, float] = {}
    for axis_profile in profile.axes:
        given = parameters.get(axis_profile.name, {})

        def value(parameter: int, given: Mapping[int, int] = given) -> int:
            return given.get(parameter, DEFAULT_PARAMETERS[parameter])

        travel_um = given.get(EchoType.TRAVEL, round(axis_profile.travel * 1000))
        lead_um = given.get(EchoType.LEAD, round(axis_profile.lead * 1000))
        per_rev = given.get(EchoType.STEPS_PER_REV, axis_profile.steps_per_rev) * given.get(
            EchoType.MICROSTEPS, axis_profile.microsteps
        )
        where = (start or {}).get(axis_profile.name, 0.0) * 1000
        axes[axis_profile.name] = Axis(
            AxisLimits(travel_um=travel_um, microstep_um=lead_um / per_rev),
            acceleration=value(EchoType.ACCELERATION),
            start_speed=value(EchoType.START_SPEED),
            position_um=min(max(where, 0.0), travel_um),
        )
        speeds[axis_profile.name] = value(EchoType.FAST_SPEED if fast else EchoType.SLOW_SPEED)
    overhead = period_s / 2 + control_cycle_s
    elapsed = 0.0
    cumulative: list[float] = []
    for op in program:
        if op.kind is OpKind.MOVE:
            longest = 0.0
            for name, target_mm in op.target.items():
                axis = axes.get(name)
                if axis is None:
                    continue
                axis.move_to(round(target_mm * 1000), speeds[name])
                longest = max(longest, axis.time_to_idle() or 0.0)
            if math.isfinite(longest) and longest > 0:
                for axis in axes.values():
                    axis.advance(longest)
            elapsed += longest + overhead
        cumulative.append(elapsed)
    return Estimate(elapsed, tuple(cumulative))


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
                period = DRILL_STEP_PERIODS_S.get(name, 0.0)
                elapsed += abs(target - where[name]) * period + overhead_s
                where[name] = target
        elif op.kind is OpKind.DRILL:
            elapsed += DRILL_CYCLE_S + overhead_s
        elif op.kind in (OpKind.PEN_DOWN, OpKind.PEN_UP):
            elapsed += PEN_TIME_S + overhead_s
        cumulative.append(elapsed)
    return Estimate(elapsed, tuple(cumulative))
