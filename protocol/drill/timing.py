"""How long the reference PCB drill takes for each procedure (docs/protocols.md §3).

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

``K`` and ``Z`` (``Kresli``/``Zvedni``, FIDELITY S2-24) are the two halves of
``Vrtat``: ``K`` is its way down (to the sensor and the overtravel, the pauses,
the 100 ms at the bottom), ``Z`` its way back (39 full steps, the 100 ms
after).  So ``K`` then ``Z`` takes exactly one ``V``, the first ``K`` after
power-on is long like the first ``V``, and the pen goes down where the drill
would and comes back up to where it hovers.

The constants below are the reference machine's; :class:`DrillTiming` holds
one machine's set (FIDELITY S2-06: the original tool let the teacher change
them, to show what they do).  A profile's ``[timing]`` table overrides them,
within :data:`TIMING_BOUNDS`; the emulator, the estimate and the session's
timeouts all take them from there.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, fields
from typing import Any

#: Seconds per microstep, per axis name.
STEP_PERIODS_S: Mapping[str, float] = {"X": 0.0013, "Y": 0.0015, "Z": 0.0025}
#: Microsteps from where each end switch opens to the machine's zero (``N`` steps them):
#: the original's ``Const Nulax = 3`` and ``Const Nulay = 86`` (FIDELITY S2-18; read from
#: an OCR'd listing, the only source there is).  They only place the zero off the
#: switches and fit the machine: X 3 microsteps (0.15 mm) past its switch, Y 86 (4.4 mm),
#: the travel (an A5 board, S2-27) counted from there.
ZERO_OFFSETS: Mapping[str, int] = {"X": 3, "Y": 86}
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


@dataclass(frozen=True)
class DrillTiming:
    """One machine's timing constants; the defaults are the reference machine's.

    Times in seconds, lengths in microsteps.  Built from a profile's
    ``[timing]`` table by :meth:`from_table`, which checks every value
    against :data:`TIMING_BOUNDS`.
    """

    x_period_s: float = STEP_PERIODS_S["X"]
    y_period_s: float = STEP_PERIODS_S["Y"]
    z_period_s: float = STEP_PERIODS_S["Z"]
    down_pause_s: float = DOWN_PAUSE_S
    down_pause_every: int = DOWN_PAUSE_EVERY
    bottom_wait_s: float = BOTTOM_WAIT_S
    after_wait_s: float = AFTER_WAIT_S
    return_full_steps: int = RETURN_FULL_STEPS

    def __post_init__(self) -> None:
        for name, (low, high) in TIMING_BOUNDS.items():
            value = getattr(self, name)
            if isinstance(value, bool) or not low <= value <= high:
                raise ValueError(f"{name} must be within {low:g}…{high:g}, got {value!r}")

    @classmethod
    def from_table(cls, table: Mapping[str, Any]) -> DrillTiming:
        """From ``key = value`` pairs (a profile's ``[timing]``); ValueError names the bad one."""
        known = {f.name: f for f in fields(cls)}
        values: dict[str, Any] = {}
        for key, value in table.items():
            if key not in known:
                raise ValueError(f"unknown timing constant {key!r} (known: {', '.join(known)})")
            whole = key in INTEGER_CONSTANTS
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise ValueError(f"{key} must be a number, not {value!r}")
            if whole and value != int(value):
                raise ValueError(f"{key} must be a whole number, not {value!r}")
            values[key] = int(value) if whole else float(value)
        return cls(**values)

    @property
    def step_periods(self) -> Mapping[str, float]:
        """Seconds per microstep, per axis name."""
        return {"X": self.x_period_s, "Y": self.y_period_s, "Z": self.z_period_s}

    @property
    def return_microsteps(self) -> int:
        """Microsteps the return climbs (full steps in half-step drive)."""
        return self.return_full_steps * Z_MICROSTEPS_PER_FULL_STEP

    def down_s(self, down_microsteps: int) -> float:
        """The way down (``Vrtat``'s first half, ``Kresli``) from ``down_microsteps`` above."""
        steps = max(down_microsteps, 0)
        pauses = steps // self.down_pause_every
        return steps * self.z_period_s + pauses * self.down_pause_s + self.bottom_wait_s

    def up_s(self) -> float:
        """The way back up (``Vrtat``'s second half, ``Zvedni``)."""
        return self.return_full_steps * self.z_period_s + self.after_wait_s

    def stroke_s(self, down_microsteps: int) -> float:
        """One ``V`` whose drill starts ``down_microsteps`` above the bottom of the stroke."""
        return self.down_s(down_microsteps) + self.up_s()

    @property
    def first_down_microsteps(self) -> int:
        """The first way down after power-on: from the top of Z."""
        return SENSOR_DEPTH + DRILL_OVERTRAVEL

    @property
    def first_cycle_s(self) -> float:
        return self.stroke_s(self.first_down_microsteps)

    @property
    def cycle_s(self) -> float:
        return self.stroke_s(self.return_microsteps)

    def home_s(self, axis: str, start_microsteps: int) -> float:
        """``N`` on one axis from ``start_microsteps`` off the zero (of a homed machine).

        To the switch (the zero lies offset + hysteresis off it), off it until
        it opens, then the offset to the zero.
        """
        offset = ZERO_OFFSETS.get(axis, 0)
        steps = abs(start_microsteps + offset + SWITCH_HYSTERESIS) + SWITCH_HYSTERESIS + offset
        return steps * self.step_periods.get(axis, 0.0)


#: Each editable constant's bounds (inclusive): wide enough to show what a change does,
#: narrow enough that no value stalls the emulator or reads as a typing slip.
TIMING_BOUNDS: Mapping[str, tuple[float, float]] = {
    "x_period_s": (0.0002, 0.05),
    "y_period_s": (0.0002, 0.05),
    "z_period_s": (0.0002, 0.05),
    "down_pause_s": (0.0, 1.0),
    "down_pause_every": (1, 100),
    "bottom_wait_s": (0.0, 5.0),
    "after_wait_s": (0.0, 5.0),
    "return_full_steps": (1, 200),
}
#: The constants that count microsteps or steps, not seconds.
INTEGER_CONSTANTS = frozenset({"down_pause_every", "return_full_steps"})
#: The reference machine's timing.
REFERENCE = DrillTiming()


def stroke_s(down_microsteps: int) -> float:
    """One ``V`` of the reference machine from ``down_microsteps`` above the bottom."""
    return REFERENCE.stroke_s(down_microsteps)


#: The first ``V`` after power-on, from the top of Z (the audit's "about 3.3 s"): 3.3875 s.
FIRST_DRILL_CYCLE_S = stroke_s(SENSOR_DEPTH + DRILL_OVERTRAVEL)
#: Every later ``V``, from where the previous one left the drill hovering: 0.8825 s.
DRILL_CYCLE_S = stroke_s(RETURN_MICROSTEPS)
#: The first ``K`` after power-on (from the top of Z): 3.19 s; every later one 0.685 s.
FIRST_PEN_DOWN_S = REFERENCE.down_s(SENSOR_DEPTH + DRILL_OVERTRAVEL)
PEN_DOWN_S = REFERENCE.down_s(RETURN_MICROSTEPS)
#: One ``Z``: 0.1975 s.  ``PEN_DOWN_S + PEN_UP_S == DRILL_CYCLE_S``.
PEN_UP_S = REFERENCE.up_s()


def home_s(axis: str, start_microsteps: int) -> float:
    """``N`` of the reference machine on one axis (see :meth:`DrillTiming.home_s`)."""
    return REFERENCE.home_s(axis, start_microsteps)
