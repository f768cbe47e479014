"""How long a program takes on a machine, each machine timed its own way (picked here)."""

from __future__ import annotations

from collections.abc import Mapping

from app.jobs.estimate.drill import estimate_drill
from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.estimate.model import Estimate, Parameters, parameters_from_model
from app.jobs.estimate.stage import CONTROL_CYCLE_S, estimate_stage
from app.jobs.estimate.usb3 import estimate_usb3
from app.jobs.program import Program
from app.profiles import MachineProfile

__all__ = ["CONTROL_CYCLE_S", "Estimate", "estimate", "parameters_from_model"]


def estimate(
    program: Program,
    profile: MachineProfile,
    parameters: Parameters,
    period_s: float,
    *,
    fast: bool = True,
    start: Mapping[str, float] | None = None,
    control_cycle_s: float = CONTROL_CYCLE_S,
    speeds_mm_s: Mapping[str, float] | None = None,
    home_first: bool = False,
) -> Estimate:
    """Time ``program`` on ``profile`` from ``start`` (mm per axis name; 0 when unknown).

    ``parameters``, ``period_s``, ``fast`` and ``control_cycle_s`` are the
    stage's (its device parameters and frame pacing); ``speeds_mm_s`` the usb3
    unit's axis speeds at its present step sizes and threads; ``home_first``
    that the job will home the machine before its first operation (the
    drill).  The drill and G-code machines take what they need from the profile.
    """
    if profile.dialect == "drill":
        return estimate_drill(program, profile, start=start, home_first=home_first)
    if profile.dialect == "gcode":
        return estimate_gcode(program, profile, start=start)
    if profile.dialect == "usb3":
        return estimate_usb3(program, profile, start=start, speeds_mm_s=speeds_mm_s)
    return estimate_stage(
        program,
        profile,
        parameters,
        period_s,
        fast=fast,
        start=start,
        control_cycle_s=control_cycle_s,
    )
