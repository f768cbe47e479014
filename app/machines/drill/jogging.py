"""The drill's jog: absolute steps in whole microsteps, inside the travel.

Split from :class:`~app.machines.drill.session.DrillSession`, which is built
on :class:`DrillJogging`: a tap is one step; a held jog is a chain of short
steps, each queued only when the one before is done and the holding still
shows signs of life (the session's module docstring says why).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from decimal import ROUND_CEILING, ROUND_FLOOR, Decimal

from PySide6.QtCore import QCoreApplication

from app.machines.drill.queue import MAX_POSITION, DrillQueue
from protocol.drill.codec import POSITION_LETTERS, Command

#: Seconds of motion in one step of a held jog: what may still run after a release.
JOG_STEP_S = 0.1
#: With Shift (the other speed) a held jog's steps are this share as long: fine positioning.
JOG_SLOW_SHARE = 0.1


class DrillJogging(DrillQueue):
    """The jogging half of the drill's session (its state is set by its init)."""

    _slow: bool
    _jog_turn: int
    _jog_told_end: bool

    # --- jogging: absolute steps in whole microsteps, inside the travel ---------------

    def step_jog(self, axis: int, direction: int, step: float) -> bool:
        """One tap of an arrow key in step mode: ``step`` (at least one microstep) that way.

        Taps made while a move is under way queue and count from where the
        moves before them end, so three taps go three steps.
        """
        if not 0 <= axis < self.axis_count or direction not in (-1, 1) or not step > 0:
            return False
        if self._refuse_jog():
            return False
        name = self.model.profile.axes[axis].name
        if name not in POSITION_LETTERS:
            return self._unsupported(
                QCoreApplication.translate("DrillSession", "moves of {0}").format(name)
            )
        microsteps = max(1, self.to_microsteps(axis, step))
        target = self._jog_target(axis, direction, microsteps)
        if target is None:
            self.model.message.emit(
                QCoreApplication.translate(
                    "DrillSession", "{0} is at the end of its travel"
                ).format(name)
            )
            return False
        return self._enqueue(Command(name, target))

    def set_jog(self, directions: Sequence[int]) -> None:
        """Held arrows or pad buttons: short steps while the holding shows signs of life."""
        wanted = self._jog_wanted(directions)
        if wanted == self._jog:
            return
        self._jog = wanted
        self._jog_started()
        self._jog_told_end = False
        self._feed_jog()

    def set_shift(self, held: bool) -> None:
        """Shift makes the held jog's steps short (the drill has one speed)."""
        self._slow = held

    def jog_step_microsteps(self, axis: int) -> int:
        """How far one step of a held jog goes on ``axis``: a short time's motion."""
        name = self.model.profile.axes[axis].name
        period = self.model.profile.drill_timing.step_periods.get(name, 0.0)
        seconds = JOG_STEP_S * (JOG_SLOW_SHARE if self._slow else 1.0)
        return max(1, round(seconds / period)) if period > 0 else 1

    def travel_microsteps(self, axis: int) -> tuple[int, int]:
        """The whole microsteps inside the travel: a position the gate can never refuse."""
        low, high = self.gate.limits(axis)
        per_mm = self._per_mm[axis]
        first = 0
        if math.isfinite(low):
            first = max(0, int((Decimal(str(low)) * per_mm).to_integral_value(ROUND_CEILING)))
        last = MAX_POSITION
        if math.isfinite(high):
            last = int((Decimal(str(high)) * per_mm).to_integral_value(ROUND_FLOOR))
        return first, min(last, MAX_POSITION)

    def _planned_microsteps(self, axis: int) -> int:
        """Where ``axis`` will stand once the commands out and queued are done."""
        name = self.model.profile.axes[axis].name
        pending = [c for c in (self._in_flight, *self._queue) if c is not None]
        for command in reversed(pending):
            if command.letter == name and command.value is not None:
                return command.value
            if command.letter == "N":
                return 0
            if command.letter == "P":
                travel = self.model.profile.axes[axis].travel
                return 0 if name == "X" else self.to_microsteps(axis, travel)
        return self.to_microsteps(axis, self.model.axes[axis].position)

    def _jog_target(self, axis: int, direction: int, microsteps: int) -> int | None:
        """``microsteps`` from the planned position, clamped inside the travel; None: no room."""
        here = self._planned_microsteps(axis)
        first, last = self.travel_microsteps(axis)
        target = min(last, max(first, here + direction * microsteps))
        if (target - here) * direction <= 0:
            return None  # at the end already (or outside it: never moved further out)
        return target

    def _feed_jog(self) -> bool:
        """The next step of a held jog, when the drill is free; whether one was sent."""
        self._check_deadman()  # no step goes for a holding that shows no sign of life
        if not any(self._jog) or self.busy or not self.link.is_open:
            return False
        if self.model.jog_lock_reason is not None or self.model.motion_lock_reason() is not None:
            self._end_held_jog("locked")
            return False
        held = [axis for axis, d in enumerate(self._jog) if d]
        for k in range(len(held)):
            axis = held[(self._jog_turn + k) % len(held)]
            name = self.model.profile.axes[axis].name
            if name not in POSITION_LETTERS:
                continue
            target = self._jog_target(axis, self._jog[axis], self.jog_step_microsteps(axis))
            if target is None:
                continue
            self._jog_turn = (self._jog_turn + k + 1) % len(held)
            return self._enqueue(Command(name, target))
        if not self._jog_told_end:
            self._jog_told_end = True
            self.model.message.emit(
                QCoreApplication.translate("DrillSession", "Jog ends: the end of the travel")
            )
        return False

    def _end_held_jog(self, reason: str) -> None:
        """The held jog is over without a release: whoever holds it forgets it."""
        if any(self._jog):
            self._jog = [0] * self.axis_count
            self._jog_started()
            self.jogEnded.emit(reason)
