"""The stage's stored parameters (docs/protocols.md §1.4) as the operator sees them.

The wire carries integers in µm, µm/s and raw register values; the dynamics
panel shows millimetres.  One table holds labels, units, scales and ranges so
the panel, the session and the tests agree on conversions and limits.
"""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.profiles import AxisProfile
from protocol.stage.codec import EchoType


@dataclass(frozen=True)
class StageParameter:
    type: EchoType
    label: str
    unit: str
    scale: int  # wire units per displayed unit
    wire_min: int
    wire_max: int
    decimals: int
    writable: bool = True
    power_of_two: bool = False

    def to_wire(self, shown: float) -> int:
        return round(shown * self.scale)

    def to_shown(self, wire: int) -> float:
        return wire / self.scale

    def check(self, wire: int) -> str | None:
        """Why the device would refuse ``wire``, or None when it is acceptable."""
        if not self.wire_min <= wire <= self.wire_max:
            low, high = self.to_shown(self.wire_min), self.to_shown(self.wire_max)
            return (
                QCoreApplication.translate("StageParameter", "{0} must be within {1}…{2} {3}")
                .format(
                    QCoreApplication.translate("StageParameter", self.label),
                    local_number(low),
                    local_number(high),
                    self.unit,
                )
                .rstrip()
            )
        if self.power_of_two and wire & (wire - 1):
            return QCoreApplication.translate(
                "StageParameter", "{0} must be a power of two"
            ).format(QCoreApplication.translate("StageParameter", self.label))
        return None


STAGE_PARAMETERS: tuple[StageParameter, ...] = (
    StageParameter(EchoType.FAST_SPEED, "Fast speed", "mm/s", 1000, 1, 999_999, 3),
    StageParameter(EchoType.SLOW_SPEED, "Slow speed", "mm/s", 1000, 1, 999_999, 3),
    StageParameter(EchoType.ACCELERATION, "Acceleration", "mm/s²", 1000, 1, 999_999, 3),
    StageParameter(EchoType.START_SPEED, "Start speed", "mm/s", 1000, 0, 99_999, 3),
    StageParameter(EchoType.IRUN, "Run current (IRUN)", "", 1, 0, 31, 0),
    StageParameter(EchoType.IHOLD, "Hold current (IHOLD)", "", 1, 0, 31, 0),
    StageParameter(EchoType.MICROSTEPS, "Microsteps per step", "", 1, 1, 256, 0, power_of_two=True),
    StageParameter(EchoType.LEAD, "Screw lead", "mm/rev", 1000, 1, 99_999, 3),
    StageParameter(EchoType.STEPS_PER_REV, "Full steps per rev", "steps", 1, 1, 9_999, 0),
    StageParameter(EchoType.TRAVEL, "Travel (soft limit)", "mm", 1000, 1, 999_999, 3),
    StageParameter(
        EchoType.ENCODER, "Encoder position", "mm", 1000, -99_999, 999_999, 3, writable=False
    ),
)

BY_TYPE: dict[int, StageParameter] = {p.type: p for p in STAGE_PARAMETERS}


def wire_limits(parameter: StageParameter, axis: AxisProfile) -> tuple[int, int]:
    """The wire range this machine may be given: the device's own, and for the travel
    (the soft limit) no more than the profile's mechanical travel — beyond it the
    device would drive into its end switch believing it has room."""
    if parameter.type == EchoType.TRAVEL:
        return parameter.wire_min, min(parameter.wire_max, round(axis.travel * parameter.scale))
    return parameter.wire_min, parameter.wire_max


def check_for_axis(parameter: StageParameter, wire: int, axis: AxisProfile) -> str | None:
    """Why ``wire`` must not be written to ``axis``, or None: the device's rules, then the
    machine's mechanical travel."""
    return parameter.check(wire) or beyond_mechanics(parameter, wire, axis)


def beyond_mechanics(parameter: StageParameter, wire: int, axis: AxisProfile) -> str | None:
    """Why ``wire`` would let the axis past its mechanical travel, or None.

    The device checks its own ranges (and says so when it refuses); it cannot
    know the machine it is built into, so this one the station checks.
    """
    if parameter.type != EchoType.TRAVEL:
        return None
    _low, high = wire_limits(parameter, axis)
    if wire > high:
        return (
            f"{parameter.label} must not exceed the mechanical travel, "
            f"{parameter.to_shown(high):g} {parameter.unit}"
        )
    return None
