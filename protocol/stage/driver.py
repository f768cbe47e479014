"""What the stage's driver settings become on the motor: current and step rate.

Two formulas of the original (FIDELITY S3-18 and S3-28), kept here, pure and
Qt-free, so that the emulator, the station's estimate and its panels compute
the same numbers from the same wire values:

* the TMC2130's RMS motor current for a current-scale setting CS (IRUN,
  IHOLD, 0…31), equation (7-1) of the original::

      IRMS = (CS + 1) / 32 · VFS / (Rsense + 20 mΩ) · 1 / √2

* the step rate a 16-bit STM32 timer at 80 MHz really produces for a
  requested one, ``fSTEP = fclock / ((PSC + 1) · (ARR + 1))``: only whole
  PSC and ARR exist, so the rate is quantised, noticeably at high rates
  (few timer ticks per step).

The original gives neither VFS and Rsense nor how it picks PSC and ARR; the
values and the rule used are documented where they are defined.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

#: Resistance the TMC2130 datasheet adds to Rsense in the current formula (20 mΩ).
INTERNAL_RESISTANCE_OHM = 0.020
#: Full-scale sense voltage with VSENSE = 0 (the TMC2130's power-on setting), volts.
#: The original does not give it; the datasheet's value.
DEFAULT_VFS_V = 0.32
#: Sense resistor of the usual TMC2130 boards (0.11 Ω); the original does not give it.
DEFAULT_RSENSE_OHM = 0.11
#: The STM32's timer clock and timer width the original names.
STEP_CLOCK_HZ = 80_000_000
TIMER_BITS = 16
CS_MAX = 31


def rms_current_a(
    cs: int, vfs_v: float = DEFAULT_VFS_V, rsense_ohm: float = DEFAULT_RSENSE_OHM
) -> float:
    """The motor's RMS current (A) for current scale ``cs`` (0…31), equation (7-1)."""
    if not 0 <= cs <= CS_MAX:
        raise ValueError(f"current scale must be within 0…{CS_MAX}, got {cs}")
    if vfs_v <= 0 or rsense_ohm < 0:
        raise ValueError(f"VFS must be positive and Rsense not negative ({vfs_v}, {rsense_ohm})")
    return (cs + 1) / 32 * vfs_v / (rsense_ohm + INTERNAL_RESISTANCE_OHM) / math.sqrt(2)


def format_current(amperes: float) -> str:
    """A current as the station shows it: mA below 1 A, else A with two decimals."""
    if amperes < 1.0:
        return f"{amperes * 1000:.0f} mA"
    return f"{amperes:.2f} A"


@dataclass(frozen=True, slots=True)
class StepTimer:
    """The prescaler and auto-reload a step rate is set with, and the rate they give."""

    psc: int
    arr: int
    clock_hz: int = STEP_CLOCK_HZ

    @property
    def rate_hz(self) -> float:
        return self.clock_hz / ((self.psc + 1) * (self.arr + 1))


def step_timer(rate_hz: float, clock_hz: int = STEP_CLOCK_HZ, bits: int = TIMER_BITS) -> StepTimer:
    """PSC and ARR for a requested step rate, as the firmware computes them.

    The original gives only the formula; this is the usual STM32 rule: the
    smallest prescaler that lets the period fit the 16-bit ARR (the finest
    resolution), then ARR from the period truncated to whole ticks, as C's
    integer conversion does (so the real rate is never slower than asked).
    Rates beyond the timer's reach are clamped to its fastest (2 ticks) and
    slowest (both registers full) periods.
    """
    if not (math.isfinite(rate_hz) and rate_hz > 0):
        raise ValueError(f"step rate must be positive, got {rate_hz!r}")
    top = 1 << bits
    ticks = clock_hz / rate_hz
    prescale = max(1, math.ceil(ticks / top))
    if prescale > top:
        return StepTimer(top - 1, top - 1, clock_hz)
    # The epsilon keeps an exact period (2500 ticks) from truncating to 2499 by rounding.
    reload = min(top, max(2, int(ticks / prescale + 1e-9)))
    return StepTimer(prescale - 1, reload - 1, clock_hz)


def quantised_speed(
    speed_um_s: float, microstep_um: float, clock_hz: int = STEP_CLOCK_HZ, bits: int = TIMER_BITS
) -> float:
    """The speed (µm/s) the axis really runs when ``speed_um_s`` is asked for.

    0 stays 0 (no timer runs).
    """
    if speed_um_s <= 0:
        return 0.0
    timer = step_timer(speed_um_s / microstep_um, clock_hz, bits)
    return timer.rate_hz * microstep_um
