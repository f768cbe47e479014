"""The CoreXY plotter's pen servo PWM, as the RP2040 firmware sets it up (FIDELITY S1-11).

The original drives the pen servo from one RP2040 PWM slice: the 125 MHz
system clock divided by 40 (``clkdiv``) counts 0…62499 (``wrap``) and
starts over, so one period is 62 500 ticks of 0.32 µs, 20 ms, 50 Hz.  The
``M99 <pwm>`` level is the channel's compare value: the output is high while
the counter is below it, so the pulse is ``level`` ticks long.  Its Tab. 2
("Vztah střídy a polohy serva") gives the servo's range: 0.5 ms = 1562 …
2.5 ms = 7812.

Pure functions, no state: the emulator shows the pulse a level gives, and a
test checks the original's figures against them.
"""

from __future__ import annotations

import math

#: The RP2040's system clock the firmware runs at, Hz.
SYSTEM_CLOCK_HZ = 125_000_000
#: The PWM slice's clock divider and counter top ("clkdiv 40, wrap 62499").
PWM_CLKDIV = 40
PWM_WRAP = 62_499
#: One counter tick, seconds: 40 / 125 MHz = 0.32 µs.
PWM_TICK_S = PWM_CLKDIV / SYSTEM_CLOCK_HZ
#: The PWM period's frequency: 125 MHz / 40 / 62 500 = 50 Hz.
PWM_FREQUENCY_HZ = SYSTEM_CLOCK_HZ / PWM_CLKDIV / (PWM_WRAP + 1)
#: The servo's range in the original's Tab. 2: 0.5 ms … 2.5 ms is 1562 … 7812.
SERVO_MIN_PULSE_S = 0.0005
SERVO_MAX_PULSE_S = 0.0025


def compare_value(level: float) -> int:
    """The channel compare value the firmware writes for an ``M99`` level.

    The level is written as it is, a whole number of ticks; the counter
    never exceeds the wrap, so anything above ``wrap + 1`` is high the whole
    period, as on the chip.
    """
    if level < 0:
        raise ValueError(f"a PWM level cannot be negative, got {level!r}")
    return min(int(level), PWM_WRAP + 1)


def pulse_width_s(level: float) -> float:
    """Seconds the servo pulse lasts at an ``M99`` level: the compare value in ticks."""
    return compare_value(level) * PWM_TICK_S


def level_for_pulse(pulse_s: float) -> int:
    """The compare value for a pulse of ``pulse_s`` seconds, truncated to whole ticks.

    Truncated as the original's table is: 0.5 ms is 1562.5 ticks, listed as 1562.
    """
    if not 0 <= pulse_s <= (PWM_WRAP + 1) * PWM_TICK_S:
        raise ValueError(f"a pulse of {pulse_s!r} s does not fit one 20 ms period")
    return math.floor(pulse_s / PWM_TICK_S + 1e-9)
