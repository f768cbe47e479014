"""The motion gate: every motion the station is asked for is judged here before a byte goes out.

Every dialect's session hands its motion intents (jog, absolute, relative,
home, a job's moves, a console line that moves) to the same gate, which knows
the machine's position (from the model the device's replies keep current)
and its travel (from the profile).  A motion that would leave the travel is
refused with the reason, in words the operator can act on; a jog is never
refused but told how far it may go, so it ends at the limit.

The gate is pure logic over the model: no wire, no timers, so the property
tests can ask it anything.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.machine import MachineModel

#: Targets this close past a limit are rounding (a move to exactly the travel end).
EPSILON = 1e-6


@dataclass(frozen=True)
class Refusal:
    """Why a motion is not sent: shown where the operator acted."""

    reason: str

    def __str__(self) -> str:
        return self.reason


class MotionGate:
    """Travel limits and position of one machine, asked by its session before any motion."""

    def __init__(self, model: MachineModel) -> None:
        self.model = model

    # --- what the gate knows ------------------------------------------------------

    def limits(self, axis: int) -> tuple[float, float]:
        """Where the axis may go: 0…travel, a rotary axis anywhere."""
        profile = self.model.profile.axes[axis]
        if profile.kind == "rotary":
            return (-math.inf, math.inf)
        return (0.0, profile.travel)

    def position(self, axis: int) -> float:
        return self.model.axes[axis].position

    def _name(self, axis: int) -> str:
        axis_profile = self.model.profile.axes[axis]
        return axis_profile.name

    def _unit(self, axis: int) -> str:
        return self.model.profile.axes[axis].unit

    # --- judgements ---------------------------------------------------------------

    def refuse_target(self, axis: int, target: float) -> Refusal | None:
        """An absolute target outside the travel (or not a number) is refused."""
        if not 0 <= axis < len(self.model.axes):
            return Refusal(
                QCoreApplication.translate("MotionGate", "there is no axis {0}").format(axis + 1)
            )
        name, unit = self._name(axis), self._unit(axis)
        if not math.isfinite(target):
            return Refusal(
                QCoreApplication.translate("MotionGate", "{0} {1} is not a position").format(
                    name, target
                )
            )
        low, high = self.limits(axis)
        if target < low - EPSILON or target > high + EPSILON:
            return Refusal(
                QCoreApplication.translate(
                    "MotionGate", "{0} {1} {2} is outside the travel {3}…{4} {2}"
                ).format(
                    name,
                    local_number(target, ".3f"),
                    unit,
                    local_number(low),
                    local_number(high),
                )
            )
        return None

    def refuse_relative(
        self, axis: int, delta: float, start: float | None = None
    ) -> Refusal | None:
        """A relative move is judged by where it ends, from where the axis stands now.

        ``start`` is where the caller knows the axis stands when the model lags
        (a job judging each report as it is decoded).
        """
        if not 0 <= axis < len(self.model.axes):
            return Refusal(
                QCoreApplication.translate("MotionGate", "there is no axis {0}").format(axis + 1)
            )
        if not math.isfinite(delta):
            return Refusal(
                QCoreApplication.translate("MotionGate", "{0} {1} is not a distance").format(
                    self._name(axis), delta
                )
            )
        here = self.position(axis) if start is None else start
        refusal = self.refuse_target(axis, here + delta)
        if refusal is None:
            return None
        unit = self._unit(axis)
        return Refusal(
            QCoreApplication.translate("MotionGate", "{0} {1} from {2}: {3}").format(
                local_number(delta, "+.3f"), unit, local_number(here, ".3f"), refusal
            )
        )

    def room(self, axis: int, direction: int) -> float:
        """How far the axis may still go in ``direction`` (+1/-1) before leaving the travel."""
        low, high = self.limits(axis)
        here = self.position(axis)
        if direction > 0:
            return max(0.0, high - here)
        if direction < 0:
            return max(0.0, here - low)
        return 0.0

    def clamp(self, axis: int, target: float) -> float:
        """The nearest position inside the travel (a jog's end)."""
        low, high = self.limits(axis)
        return min(high, max(low, target))

    def refuse_release(self, busy: str | None = None) -> Refusal | None:
        """Drivers off, the axes free to turn by hand (zeroing by hand), only at rest.

        No motion is sent, but a machine whose drivers let go while it moves
        loses its position and drops what it carries, and a job under way
        (waiting or paused included) would go on from a position that is no
        longer true.  ``busy`` is the session's own reason the machine is not
        at rest (lines still to run, a stop under way), if any.
        """
        reason = self.model.motion_lock_reason() or self.model.jog_lock_reason
        if reason is None and self.model.any_moving:
            reason = "the machine is moving"
        reason = reason or busy
        if reason is None:
            return None
        return Refusal(
            QCoreApplication.translate("MotionGate", "the motors are not released: {0}").format(
                reason
            )
        )

    def refuse_new_zero(self, busy: str | None = None) -> Refusal | None:
        """A work zero set or another coordinate system chosen (``G10``, ``G54``…), only at
        rest: nothing moves, but every position a job or a queued line names would then
        mean another place on the machine.  ``busy`` as for :meth:`refuse_release`."""
        reason = self.model.motion_lock_reason() or self.model.jog_lock_reason
        if reason is None and self.model.any_moving:
            reason = "the machine is moving"
        reason = reason or busy
        if reason is None:
            return None
        return Refusal(
            QCoreApplication.translate("MotionGate", "the work zero stays: {0}").format(reason)
        )

    def refuse(self, refusal: Refusal | None) -> bool:
        """Tell the operator (status bar) when refused; True when the motion must not go."""
        if refusal is None:
            return False
        self.model.message.emit(
            QCoreApplication.translate("MotionGate", "Motion refused: {0}").format(refusal)
        )
        return True
