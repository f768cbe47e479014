"""How long a point list takes on the three-axis USB unit.

The unit runs every axis of a move at once at its top pulse rate, which is
fixed whatever the step size, so an axis covers ``rate / pulses per mm``
millimetres a second; finer steps and finer threads are slower.  Its speed
table ramps up and down in a few tenths of a second, small beside moves that
take seconds at these speeds, so a move is timed by its slowest axis plus
the last position report the driver waits for.
"""

from __future__ import annotations

from collections.abc import Mapping

from app.jobs.estimate.model import Estimate
from app.jobs.program import OpKind, Program
from app.machines.usb3.session import DEFAULT_STEP, DEFAULT_THREAD
from app.profiles import MachineProfile
from protocol.usb3.codec import top_speed_mm_s

#: The unit reports every 100 ms and once when it stops: the driver sees the end that late.
REPORT_LAG_S = 0.1


def estimate_usb3(
    program: Program,
    profile: MachineProfile,
    *,
    start: Mapping[str, float] | None = None,
    speeds_mm_s: Mapping[str, float] | None = None,
) -> Estimate:
    """Time ``program`` from ``start``; ``speeds_mm_s`` per axis (the unit's defaults if absent)."""
    default = top_speed_mm_s(DEFAULT_STEP, DEFAULT_THREAD)
    speeds = {axis.name: (speeds_mm_s or {}).get(axis.name, default) for axis in profile.axes}
    where = {name: (start or {}).get(name, 0.0) for name in speeds}
    elapsed = 0.0
    cumulative: list[float] = []
    for op in program:
        if op.kind is OpKind.MOVE:
            longest = 0.0
            for name, target in op.target.items():
                if name in speeds:
                    longest = max(longest, abs(target - where[name]) / speeds[name])
                    where[name] = target
            if longest > 0:
                elapsed += longest + REPORT_LAG_S
        cumulative.append(elapsed)
    return Estimate(elapsed, tuple(cumulative))
