"""The XY stage's motion commands, as its firmware handles them (docs/protocols.md §1).

Each handler takes the axis index, the packet's data and the cycle's time,
acts on the mechanism, and says what the echo will carry.  A motion command
is refused while the axis may not move (blocked, asleep, a driver fault);
every one takes the axis over from whatever the previous command left
pending (a jog's watchdog, a homing run's "homed").  The firmware owns the
lock, the queue and the cycle; it calls these from its cycle, under its lock.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

from protocol.emulator.fram import Fram
from protocol.mechanism import Axis
from protocol.stage.codec import AxisStatus, EchoType
from protocol.stage.driver import quantised_speed


@dataclass
class AxisControl:
    """Firmware-side state of one axis besides the mechanism itself."""

    fast: bool = False
    #: Direction of a jog in progress (0: not jogging), for the dead-man watchdog.
    jog_direction: int = 0
    last_jog: float = 0.0
    driver_fault: bool = False
    #: Set by HOME until the next motion command: a finished homing run reads as
    #: idle at the new zero, not as a target reached.
    homed: bool = False


@dataclass(frozen=True, slots=True)
class Reply:
    """What one echo packet will say; None fields are filled in at the end of the cycle."""

    type: int = EchoType.POSITION
    status: int | None = None
    data: int | None = None
    #: False when the command was refused (unknown, out of range, motion while disabled).
    accepted: bool = True


DEFAULT_REPLY = Reply()
REFUSED = Reply(accepted=False)
UNKNOWN = Reply(status=AxisStatus.UNKNOWN_COMMAND, accepted=False)

Handler = Callable[[int, int, float], Reply]


class StageCommands:
    """The motion commands over the firmware's axes (all called under its lock)."""

    def __init__(
        self,
        axes: Sequence[Axis],
        controls: Sequence[AxisControl],
        fram: Fram,
        step_clock_hz: int,
        may_move: Callable[[int], bool],
        set_sleeping: Callable[[bool], None],
    ) -> None:
        self._axes = axes
        self._controls = controls
        self._fram = fram
        self._step_clock_hz = step_clock_hz
        self._may_move = may_move
        self._set_sleeping = set_sleeping

    def speed_of(self, index: int) -> float:
        """The selected speed as the step timer runs it (FIDELITY S3-28)."""
        fast = self._controls[index].fast
        asked = self._fram.read(index, EchoType.FAST_SPEED if fast else EchoType.SLOW_SPEED)
        microstep = self._axes[index].limits.microstep_um
        return quantised_speed(asked, microstep, self._step_clock_hz)

    def _take_over(self, index: int) -> Axis:
        """The axis, with whatever the previous command left pending forgotten."""
        control = self._controls[index]
        control.jog_direction = 0
        control.homed = False
        return self._axes[index]

    def nop(self, index: int, data: int, now: float) -> Reply:
        return DEFAULT_REPLY

    def stop(self, index: int, data: int, now: float) -> Reply:
        self._take_over(index).stop()
        return DEFAULT_REPLY

    def estop(self, index: int, data: int, now: float) -> Reply:
        self._take_over(index).estop()
        return DEFAULT_REPLY

    def jog(self, index: int, data: int, now: float) -> Reply:
        if data not in (-1, 0, 1):
            return UNKNOWN
        if not self._may_move(index):
            return REFUSED
        control = self._controls[index]
        if data == 0:
            # Key released: that ends a jog, but a move in progress carries on.
            if control.jog_direction:
                self._take_over(index).stop()
            return DEFAULT_REPLY
        self._take_over(index).jog(data, self.speed_of(index))
        control.jog_direction = data
        control.last_jog = now
        return DEFAULT_REPLY

    def move_abs(self, index: int, data: int, now: float) -> Reply:
        if not self._may_move(index):
            return REFUSED
        self._take_over(index).move_to(data, self.speed_of(index))
        return DEFAULT_REPLY

    def move_rel(self, index: int, data: int, now: float) -> Reply:
        if not self._may_move(index):
            return REFUSED
        self._take_over(index).move_by(data, self.speed_of(index))
        return DEFAULT_REPLY

    def home(self, index: int, data: int, now: float) -> Reply:
        if not self._may_move(index):
            return REFUSED
        slow = self._fram.read(index, EchoType.SLOW_SPEED)
        microstep = self._axes[index].limits.microstep_um
        self._take_over(index).home(quantised_speed(slow, microstep, self._step_clock_hz))
        self._controls[index].homed = True
        return DEFAULT_REPLY

    def set_pos(self, index: int, data: int, now: float) -> Reply:
        self._axes[index].set_position(data)
        return DEFAULT_REPLY

    def speed(self, index: int, data: int, now: float) -> Reply:
        if data not in (0, 1):
            return UNKNOWN
        self._controls[index].fast = data == 1
        return DEFAULT_REPLY

    def sleep(self, index: int, data: int, now: float) -> Reply:
        if data not in (0, 1):
            return UNKNOWN
        self._set_sleeping(data == 1)
        return DEFAULT_REPLY
