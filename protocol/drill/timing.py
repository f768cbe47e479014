"""How long the reference PCB drill takes for each procedure (PROTOCOLS.md section 3).

The one timing table of the drill: the emulator's defaults are built from it,
the job estimate sums it, and the session's reply timeouts wait as long as it
says a procedure takes (plus a margin), and no longer.

``V`` (the original's ``Vrtat``, FIDELITY S2-22/S2-23): Z goes down one
microstep (a half step: the Z motor runs in half-step drive) per period until
the optical sensor sees the board, and :data:`DRILL_OVERTRAVEL` more, pausing
10 ms after every second microstep; it waits 100 ms at the bottom, comes back
39 full steps (two microsteps per period) and waits 100 ms more.  Coming back
39 full steps is 78 microsteps, so the drill then hovers 66 microsteps above
the board, and every later stroke goes down those 78 microsteps only.  The
first stroke after power-on starts from the top of Z, :data:`SENSOR_DEPTH`
microsteps above the board: it alone is long.
"""

from __future__ import annotations

from collections.abc import Mapping

#: Seconds per microstep, per axis name.
STEP_PERIODS_S: Mapping[str, float] = {"X": 0.0013, "Y": 0.0015, "Z": 0.0025}
#: Microsteps from where each end switch opens to the machine's zero (``N`` steps them).
ZERO_OFFSETS: Mapping[str, int] = {"X": 50, "Y": 40}
#: Microsteps an end switch needs to open again once hit (``N`` backs off that far).
SWITCH_HYSTERESIS = 1

#: Z microsteps from the top (power-on) to where the optical sensor sees the board.
SENSOR_DEPTH = 400
#: Microsteps the drill goes on after the optical sensor sees the board.
DRILL_OVERTRAVEL = 12
#: Going down, a pause of :data:`DOWN_PAUSE_S` after every this many microsteps.
DOWN_PAUSE_EVERY = 2
DOWN_PAUSE_S = 0.010
#: The waits at the bottom of the stroke and after the return.
BOTTOM_WAIT_S = 0.100
AFTER_WAIT_S = 0.100
#: The return: this many full steps of Z, each this many microsteps in one period.
RETURN_FULL_STEPS = 39
Z_MICROSTEPS_PER_FULL_STEP = 2
#: Microsteps the return climbs: where the drill hovers is this far above the bottom.
RETURN_MICROSTEPS = RETURN_FULL_STEPS * Z_MICROSTEPS_PER_FULL_STEP

#: One ``K`` or ``Z``: the pen's solenoid settling.
PEN_TIME_S = 0.15


def stroke_s(down_microsteps: int) -> float:
    """One ``V`` whose drill starts ``down_microsteps`` above the bottom of the stroke."""
    z = STEP_PERIODS_S["Z"]
    down = down_microsteps * z + (down_microsteps // DOWN_PAUSE_EVERY) * DOWN_PAUSE_S
    return down + BOTTOM_WAIT_S + RETURN_FULL_STEPS * z + AFTER_WAIT_S


#: The first ``V`` after power-on, from the top of Z (the audit's "about 3.3 s"): 3.3875 s.
FIRST_DRILL_CYCLE_S = stroke_s(SENSOR_DEPTH + DRILL_OVERTRAVEL)
#: Every later ``V``, from where the previous one left the drill hovering: 0.8825 s.
DRILL_CYCLE_S = stroke_s(RETURN_MICROSTEPS)


def home_s(axis: str, start_microsteps: int) -> float:
    """``N`` on one axis from ``start_microsteps`` off the zero (of a homed machine).

    To the switch (the zero lies offset + hysteresis off it), off it until
    it opens, then the offset to the zero.
    """
    offset = ZERO_OFFSETS.get(axis, 0)
    steps = abs(start_microsteps + offset + SWITCH_HYSTERESIS) + SWITCH_HYSTERESIS + offset
    return steps * STEP_PERIODS_S.get(axis, 0.0)
