"""The stage's parameters: table 1.4's defaults and ranges, kept in the FRAM, and what
each does to its axis as it is written (docs/protocols.md §1).

The firmware's control loop hands a written parameter and a READ here; the
mechanism takes a new acceleration, start speed or geometry at once (speeds
are read per move).  Not thread-safe by itself: the firmware calls it under
its lock.
"""

from __future__ import annotations

from collections.abc import Mapping
from types import MappingProxyType

from protocol.emulator.fram import Fram
from protocol.emulator.stage_commands import UNKNOWN, Reply
from protocol.mechanism import Axis, AxisLimits
from protocol.stage.codec import AxisStatus, EchoType

#: Table 1.4 defaults of the XY stage.
XY_STAGE_PARAMETERS: Mapping[EchoType, int] = MappingProxyType(
    {
        EchoType.FAST_SPEED: 10_000,
        EchoType.SLOW_SPEED: 2_000,
        EchoType.ACCELERATION: 20_000,
        EchoType.START_SPEED: 500,
        EchoType.IRUN: 16,
        EchoType.IHOLD: 8,
        EchoType.MICROSTEPS: 16,
        EchoType.LEAD: 1_000,
        EchoType.STEPS_PER_REV: 200,
        EchoType.TRAVEL: 50_000,
    }
)

#: Table 1.4 ranges; microsteps are further restricted to powers of two.
PARAMETER_RANGES: Mapping[EchoType, tuple[int, int]] = MappingProxyType(
    {
        EchoType.FAST_SPEED: (1, 999_999),
        EchoType.SLOW_SPEED: (1, 999_999),
        EchoType.ACCELERATION: (1, 999_999),
        EchoType.START_SPEED: (0, 99_999),
        EchoType.IRUN: (0, 31),
        EchoType.IHOLD: (0, 31),
        EchoType.MICROSTEPS: (1, 256),
        EchoType.LEAD: (1, 99_999),
        EchoType.STEPS_PER_REV: (1, 9_999),
        EchoType.TRAVEL: (1, 999_999),
    }
)


def parameter_in_range(parameter: EchoType, value: int) -> bool:
    """Whether the device accepts ``value`` for ``parameter`` (table 1.4)."""
    low, high = PARAMETER_RANGES[parameter]
    if not low <= value <= high:
        return False
    return parameter != EchoType.MICROSTEPS or value & (value - 1) == 0


class StageParameters:
    """The parameters of every axis of one stage firmware, in its FRAM."""

    def __init__(self, fram: Fram) -> None:
        self.fram = fram
        #: The axes the parameters drive (set once they are made from them).
        self.axes: tuple[Axis, ...] = ()

    def store_defaults(self, defaults: Mapping[EchoType, int], axes: int) -> None:
        """The power-on values of every axis, each checked against its range."""
        for index in range(axes):
            for parameter, value in defaults.items():
                if not parameter_in_range(parameter, value):
                    raise ValueError(f"default {parameter.name} = {value} is out of range")
                self.fram.write(index, parameter, value)

    def make_axis(self, index: int, where: float) -> Axis:
        """Axis ``index`` as its stored parameters make it, its encoder at ``where`` µm."""
        limits = self.limits(index)
        if not 0.0 <= where <= limits.travel_um:
            raise ValueError(f"encoder position {where} µm of axis {index} is off its travel")
        return Axis(
            limits,
            acceleration=self.fram.read(index, EchoType.ACCELERATION),
            start_speed=self.fram.read(index, EchoType.START_SPEED),
            position_um=where,
        )

    def limits(self, index: int) -> AxisLimits:
        read = self.fram.read
        microsteps_per_rev = read(index, EchoType.STEPS_PER_REV) * read(index, EchoType.MICROSTEPS)
        return AxisLimits(
            travel_um=read(index, EchoType.TRAVEL),
            microstep_um=read(index, EchoType.LEAD) / microsteps_per_rev,
        )

    def value(self, index: int, parameter: int) -> int:
        if parameter == EchoType.ENCODER:
            return round(self.axes[index].position_um)
        return self.fram.read(index, parameter)

    def apply(self, index: int, parameter: EchoType) -> None:
        """Make a stored parameter take effect on the mechanism (speeds are read per move)."""
        axis = self.axes[index]
        if parameter == EchoType.ACCELERATION:
            axis.acceleration = self.fram.read(index, parameter)
        elif parameter == EchoType.START_SPEED:
            axis.start_speed = self.fram.read(index, parameter)
        elif parameter in (
            EchoType.MICROSTEPS,
            EchoType.LEAD,
            EchoType.STEPS_PER_REV,
            EchoType.TRAVEL,
        ):
            axis.limits = self.limits(index)

    def write(self, index: int, parameter: EchoType, value: int) -> Reply:
        if parameter_in_range(parameter, value) and self.fram.write(index, parameter, value):
            self.apply(index, parameter)
            return Reply(type=parameter, data=value)
        kept = self.fram.read(index, parameter)
        return Reply(parameter, AxisStatus.PARAMETER_REJECTED, kept, accepted=False)

    def read(self, index: int, data: int, now: float) -> Reply:
        if not EchoType.FAST_SPEED <= data <= EchoType.ENCODER:
            return UNKNOWN
        return Reply(type=data, data=self.value(index, data))
