"""Millimetres to the drill's microsteps, as the host does it (docs/protocols.md §3).

The drill knows only microsteps: the host converts with the profile's
constants (steps per revolution x microsteps ÷ lead: 19.8 a mm on X, 19.7 on
Y) and does all the rounding, half away from zero, in decimal, so that
12.5 mm x 19.8 is 247.5 exactly and becomes 248.  One place for the rule: the
session, the step-through and the teaching constants all count with it.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Sequence
from dataclasses import dataclass
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


#: The Excellon step the original's "Krok excelon" starts from: 1/10000 inch a count.
PROFILE_EXCELLON_STEP_INCH = 1e-4
#: What the teacher may set (FIDELITY S2-42): the Excellon step in inches a count, and the
#: microsteps a millimetre of each axis.  Wide enough to show what a wrong constant does,
#: narrow enough that nothing is divided by nothing.
EXCELLON_STEP_BOUNDS = (1e-6, 1e-2)
MICROSTEPS_PER_MM_BOUNDS = (1.0, 400.0)


@dataclass(frozen=True)
class DrillConversion:
    """The drill's conversion constants as the teacher set them (FIDELITY S2-42).

    The original let a teacher change "Krok excelon" and "Mikrokroky X 19,8 /
    Y 19,7 na mm" "to show what happens when these important parameters
    change".  The profile's values are the machine's truth: the travel, the
    gate and the position shown count with them.  Edited ones change how a
    job's file becomes microsteps, so the job lands where the edited constants
    send it; :meth:`scale` says how far from where the file means.
    """

    excellon_step_inch: float
    #: Per axis, in the profile's order.
    microsteps_per_mm: tuple[float, ...]
    #: The profile's, to measure the edited ones against.
    profile_microsteps_per_mm: tuple[float, ...]

    def __post_init__(self) -> None:
        low, high = EXCELLON_STEP_BOUNDS
        if not low <= self.excellon_step_inch <= high:
            raise ValueError(f"the Excellon step must be within {low:g}…{high:g} inch")
        low, high = MICROSTEPS_PER_MM_BOUNDS
        if len(self.microsteps_per_mm) != len(self.profile_microsteps_per_mm):
            raise ValueError("one microsteps-a-mm constant per axis")
        for value, profiles in zip(
            self.microsteps_per_mm, self.profile_microsteps_per_mm, strict=True
        ):
            # The profile's own value stands whatever it is (a stage's 3200 a mm).
            if value != profiles and not low <= value <= high:
                raise ValueError(f"microsteps a mm must be within {low:g}…{high:g}")

    @classmethod
    def of_profile(cls, axes: Sequence[AxisProfile]) -> DrillConversion:
        per_mm = tuple(float(profile_microsteps_per_mm(axis)) for axis in axes)
        return cls(PROFILE_EXCELLON_STEP_INCH, per_mm, per_mm)

    @property
    def is_profiles(self) -> bool:
        return self == dataclasses.replace(
            self,
            excellon_step_inch=PROFILE_EXCELLON_STEP_INCH,
            microsteps_per_mm=self.profile_microsteps_per_mm,
        )

    @property
    def excellon_scale(self) -> float:
        """How much larger an Excellon file's coordinates come out than with 1/10000 inch."""
        return self.excellon_step_inch / PROFILE_EXCELLON_STEP_INCH

    def axis_scale(self, axis: int) -> float:
        """Where a millimetre of the job lands, in the machine's millimetres, on ``axis``."""
        return self.microsteps_per_mm[axis] / self.profile_microsteps_per_mm[axis]
