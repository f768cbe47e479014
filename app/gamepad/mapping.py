"""What a gamepad's sticks and buttons ask of the jog: directions per axis and a speed share.

Pure functions over a :class:`PadReading`, so the mapping is tested without SDL or Qt.
The mapping (also in the manual and Help → Keys):

* the left stick jogs X (right +) and Y (pushed away from the operator +), the right
  stick's vertical jogs Z (up +), on machines that have those axes;
* nothing jogs unless the **enable** button is held too (a shoulder button on a gamepad,
  the trigger on a joystick): a pad dropped on its stick, a worn stick drifting or a
  throttle left open moves nothing — the same rule as an industrial pendant's enable
  switch.  Letting go of the button, or of the stick, is the key's release;
* each axis has a dead zone, and a hysteresis: an axis starts jogging past
  :data:`DEAD_ZONE` and stops only back under :data:`RELEASE_ZONE`, so a stick resting
  on the edge does not chatter start/stop on the wire;
* how far the stick is pushed past the dead zone sets the speed share (of the speed a held
  key jogs at): slowly at first, as the usb3 unit's own joystick grows its speed slowly at
  small deflections, then to the key's full speed.  Never faster than the keys.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Deflection (0…1) past which an axis jogs: worn sticks rest up to about 0.15 off centre.
DEAD_ZONE = 0.25
#: Deflection under which a jogging axis stops (hysteresis against chatter at the edge).
RELEASE_ZONE = 0.20
#: The speed share just past the dead zone; full deflection is 1 (a held key's speed).
MIN_SPEED_SHARE = 0.1
#: Axes the mapping drives: X, Y, Z.
PAD_AXES = 3


@dataclass(frozen=True)
class PadReading:
    """One look at the device, in StepDeck's senses: each stick axis in -1…1.

    ``x`` + is right, ``y`` + is the stick pushed away from the operator (SDL's up is
    negative: the source turns it), ``z`` + is the right stick pushed up.
    """

    x: float = 0.0
    y: float = 0.0
    z: float = 0.0
    enable: bool = False

    @property
    def sticks(self) -> tuple[float, float, float]:
        return (self.x, self.y, self.z)


@dataclass(frozen=True)
class PadIntent:
    """What the pad asks: one -1/0/+1 per axis (X, Y, Z) and the speed share (0…1]."""

    directions: tuple[int, ...] = (0,) * PAD_AXES
    speed: float = 1.0

    @property
    def jogs(self) -> bool:
        return any(self.directions)


#: Nothing asked (stick centred or enable let go).
IDLE = PadIntent()


def _clean(value: float) -> float:
    """A reading as a number in -1…1; anything else (NaN, inf) is centred: it moves nothing."""
    if not math.isfinite(value):
        return 0.0
    return max(-1.0, min(1.0, value))


def axis_direction(value: float, held: int) -> int:
    """-1, 0 or +1 for one stick axis, given the direction it jogged at the last look.

    Past the dead zone it jogs; an axis already jogging that way goes on down to the
    release zone; a stick flicked to the other side jogs that way only past the dead zone.
    """
    value = _clean(value)
    sign = 1 if value > 0 else -1 if value < 0 else 0
    threshold = RELEASE_ZONE if held and sign == held else DEAD_ZONE
    return sign if abs(value) > threshold else 0


def speed_share(deflection: float) -> float:
    """The jog speed share for a deflection (0…1): slow just past the dead zone, then faster.

    Quadratic past the dead zone, from :data:`MIN_SPEED_SHARE` to 1 at full deflection.
    """
    magnitude = abs(_clean(deflection))
    beyond = max(0.0, (magnitude - DEAD_ZONE) / (1.0 - DEAD_ZONE))
    return MIN_SPEED_SHARE + (1.0 - MIN_SPEED_SHARE) * min(1.0, beyond) ** 2


def intent(reading: PadReading, held: tuple[int, ...] = IDLE.directions) -> PadIntent:
    """What ``reading`` asks, given the directions the pad held at the last look.

    Without the enable button nothing jogs, whatever the sticks say.
    """
    if not reading.enable:
        return IDLE
    previous = (*held, *(0,) * PAD_AXES)[:PAD_AXES]
    directions = tuple(
        axis_direction(value, was) for value, was in zip(reading.sticks, previous, strict=True)
    )
    if not any(directions):
        return IDLE
    pushed = zip(reading.sticks, directions, strict=True)
    deflection = max(abs(_clean(value)) for value, direction in pushed if direction)
    return PadIntent(directions, speed_share(deflection))
