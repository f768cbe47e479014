"""The stage's RGB LED ring (the original's table 7-4), from the device flags.

The ring shows one state at a time.  The table lists the states, not their
precedence; this reading takes the first that applies: the charger (red on),
a low battery (red, fast blink), asleep (standby: green on), a host talking
(a data session: blue on), else advertising for a host (pairing: blue, slow
blink).  The device flags (docs/protocols.md §1.5, SS 07) carry every one of those
conditions, so the emulator lights its ring and the station draws it from
the same function.
"""

from __future__ import annotations

import enum

from protocol.stage.codec import DeviceFlag


class LedRing(enum.Enum):
    """The ring's states; the values say what the ring looks like."""

    OFF = "off"
    CHARGING = "red on"
    LOW_BATTERY = "red, fast blink"
    STANDBY = "green on"
    PAIRING = "blue, slow blink"
    TALKING = "blue on"


def led_ring(flags: DeviceFlag | int) -> LedRing:
    """The state a powered ring shows for ``flags`` (an off board shows nothing)."""
    flags = DeviceFlag(int(flags))
    if DeviceFlag.CHARGER in flags:
        return LedRing.CHARGING
    if DeviceFlag.LOW_BATTERY in flags:
        return LedRing.LOW_BATTERY
    if DeviceFlag.SLEEPING in flags:
        return LedRing.STANDBY
    if DeviceFlag.DATA_SESSION in flags:
        return LedRing.TALKING
    return LedRing.PAIRING
