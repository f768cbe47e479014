"""What an estimate is: the model time at which each operation of a program ends.

The runner's progress bar needs a total before anything moves, and the
operator wants a time they can plan around; each machine's module times a
program its own way (:mod:`app.jobs.estimate` picks it by dialect).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from app.machine import MachineModel, ParameterState

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
