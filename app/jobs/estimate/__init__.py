"""How long a program takes on a machine, each machine timed its own way (picked here).

:data:`ESTIMATORS` is the estimate's half of the dialect registry
(:mod:`app.machines.registry` lists the dialects; a test holds the tables
together): each dialect's timing takes the one :class:`EstimateInputs` and
reads what it needs, so :func:`estimate` asks no profile its dialect.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

from app.jobs.estimate.drill import estimate_drill
from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.estimate.model import Estimate, Parameters, parameters_from_model
from app.jobs.estimate.stage import CONTROL_CYCLE_S, estimate_stage
from app.jobs.estimate.usb3 import estimate_usb3
from app.jobs.program import Program
from app.profiles import MachineProfile

__all__ = [
    "CONTROL_CYCLE_S",
    "ESTIMATORS",
    "Estimate",
    "EstimateInputs",
    "Estimator",
    "estimate",
    "parameters_from_model",
]


@dataclass(frozen=True)
class EstimateInputs:
    """What any machine's timing may read besides the program and the profile."""

    parameters: Parameters
    period_s: float
    fast: bool = True
    start: Mapping[str, float] | None = None
    control_cycle_s: float = CONTROL_CYCLE_S
    speeds_mm_s: Mapping[str, float] | None = None
    home_first: bool = False


Estimator = Callable[[Program, MachineProfile, EstimateInputs], Estimate]


def _drill(program: Program, profile: MachineProfile, inputs: EstimateInputs) -> Estimate:
    return estimate_drill(program, profile, start=inputs.start, home_first=inputs.home_first)


def _gcode(program: Program, profile: MachineProfile, inputs: EstimateInputs) -> Estimate:
    return estimate_gcode(program, profile, start=inputs.start)


def _usb3(program: Program, profile: MachineProfile, inputs: EstimateInputs) -> Estimate:
    return estimate_usb3(program, profile, start=inputs.start, speeds_mm_s=inputs.speeds_mm_s)


def _stage(program: Program, profile: MachineProfile, inputs: EstimateInputs) -> Estimate:
    return estimate_stage(
        program,
        profile,
        inputs.parameters,
        inputs.period_s,
        fast=inputs.fast,
        start=inputs.start,
        control_cycle_s=inputs.control_cycle_s,
    )


#: Dialect name (a profile's ``dialect``) → how a program is timed on it.
ESTIMATORS: Mapping[str, Estimator] = {
    "stage": _stage,
    "usb3": _usb3,
    "drill": _drill,
    "gcode": _gcode,
}


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
    inputs = EstimateInputs(
        parameters,
        period_s,
        fast=fast,
        start=start,
        control_cycle_s=control_cycle_s,
        speeds_mm_s=speeds_mm_s,
        home_first=home_first,
    )
    return ESTIMATORS[profile.dialect](program, profile, inputs)
