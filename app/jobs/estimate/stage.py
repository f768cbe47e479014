"""How long a program takes on the XY stage, found by replaying it on the emulator's mechanism.

Rather than a second, simpler motion model that would drift from the device,
the program is replayed on the same :class:`~protocol.mechanism.Axis`
the firmware emulator runs: trapezoids, start-speed jumps and triangular
short moves come out exactly as the device does them, at the speed its step
timer's whole PSC/ARR really give.  Each move is one
``time_to_idle`` and one ``advance`` in closed form, never small time steps,
so a long job is estimated in a blink.

What the mechanism does not know is the host: the runner sends the next move
as soon as it sees the previous one finished, and it sees that only in the
echo to the next periodic frame, i.e. on average half a period after arrival,
plus the control cycle the echo waits for.  That overhead is added per move;
WAIT and COMMENT operations cost nothing here (the operator's time is not the
machine's).
"""

from __future__ import annotations

import math
from collections.abc import Mapping

from app.jobs.estimate.model import Estimate, Parameters
from app.jobs.program import OpKind, Program
from app.profiles import MachineProfile
from protocol.mechanism import Axis, AxisLimits
from protocol.stage.codec import EchoType
from protocol.stage.driver import quantised_speed

#: The stage's control cycle (s): an echo leaves at the end of the cycle its frame arrived in.
CONTROL_CYCLE_S = 0.005

#: What the XY stage holds until the station has read otherwise (docs/protocols.md §1.4).
DEFAULT_PARAMETERS: Mapping[int, int] = {
    EchoType.FAST_SPEED: 10_000,
    EchoType.SLOW_SPEED: 2_000,
    EchoType.ACCELERATION: 20_000,
    EchoType.START_SPEED: 500,
}


def estimate_stage(
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
    runner's pre-check refuses such programs before this matters.
    """
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
        # The speed the step timer really runs (FIDELITY S3-28), as the device does.
        speeds[axis_profile.name] = quantised_speed(
            value(EchoType.FAST_SPEED if fast else EchoType.SLOW_SPEED),
            lead_um / per_rev,
            profile.driver.step_clock_hz,
        )
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
