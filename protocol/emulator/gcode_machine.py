"""The G-code machines the emulator knows: kinematics, travel, motors, replies, pen.

One firmware serves the CoreXY pen plotter, GRBL servo plotters and the
string-art winder (docs/protocols.md §4); what differs between them is
data, kept here so the interpreter, the planner and the firmware read one
description.

Decisions the contract leaves open, made here:

- Travel runs from 0 to the profile's length on X and Y (the CoreXY
  plotter's 300 by 210 mm holds the original's "at least A4"; the GRBL
  plotter keeps 300 by 200 mm); the plotters' Z, which only a job that does
  not map Z to the pen would use, may go 20 mm either way; the winder's A
  turns freely.
- Every motor shares one top step rate and one acceleration (infinite on
  the CoreXY plotter, which has no ramps); a move is
  timed on the motor that makes the most steps, so the others never exceed
  either.  A GRBL plotter plans as GRBL does instead (``junction_deviation``,
  its ``$11``): along the path, with each axis' own rate and acceleration.
  The CoreXY plotter's power-on step interval is 25 µs (40 000 steps/s,
  about 98 mm/s per motor); ``M98`` changes it.
- The CoreXY plotter ignores ``F`` and runs ``G0`` as ``G1`` (its firmware,
  FIDELITY S1-01): every move steps at the ``M98`` interval.  The winder
  moves at its top rate when a job never set ``F``; a GRBL plotter refuses
  ``G1`` without a feed rate (``error:22``) as GRBL does.
"""

from __future__ import annotations

import enum
import math
from dataclasses import dataclass
from typing import Literal

from protocol.gcode.codec import GRBL_BANNER, MAX_LINE_BYTES, PLOTTER_BANNER, RX_BUFFER

Kinematics = Literal["corexy", "cartesian", "cylindrical"]

#: Axis letters a machine may have.
AXIS_LETTERS = "XYZA"
#: The CoreXY plotter's resolution: 64 microsteps of a 200-step motor on a 10 mm pulley.
COREXY_MM_PER_STEP = 0.00245
#: The winder's base: 200 steps x 6 (gearing) x 8 microsteps per turn.
STRING_ART_STEPS_PER_TURN = 200 * 6 * 8
#: The board radius the emulated winder's white buttons set X to: the original reads its
#: ``polomer_matrice`` from the SD card (12 cm in the examples); the emulator has no card.
STRING_ART_BOARD_RADIUS_MM = 120.0


class PenMapping(enum.Enum):
    """Which M codes move the pen."""

    #: The CoreXY plotter: ``M3`` lifts, ``M4`` lowers (``M5`` lifts too).
    M3_UP_M4_DOWN = "m3-up-m4-down"
    #: GRBL servo plotters: the spindle is the servo, down while on with ``S`` > 0.
    SPINDLE = "spindle"


@dataclass(frozen=True)
class GcodeConfig:
    """One machine; lengths in its units (mm, degrees for A), times in seconds.

    ``travel`` is per axis ``(low, high)``, or None for an axis that turns
    freely.  ``max_rate`` (steps/s) and ``acceleration`` (steps/s²) bound
    every motor.
    """

    kinematics: Kinematics
    axes: tuple[str, ...]
    steps_per_unit: tuple[float, ...]
    travel: tuple[tuple[float, float] | None, ...]
    max_rate: float
    acceleration: float
    reply_ok: str = "ok"
    reply_error: str = "error"
    banner: str = GRBL_BANNER
    rx_buffer: int = RX_BUFFER
    planner_blocks: int = 16
    max_line: int = MAX_LINE_BYTES
    pen: PenMapping = PenMapping.SPINDLE
    #: Seconds the pen takes to go up or down; motion waits for it.
    pen_time: float = 0.0
    #: G2/G3 accepted and flattened into straight blocks.
    arcs: bool = False
    #: The plotter's ``M98 <µs>`` step interval and ``M99 <pwm>`` servo level.
    plotter_codes: bool = False
    #: GRBL 1.1's ``$J=`` jog lines and the 0x85 jog cancel.
    jogging: bool = False
    #: A bare ``G92`` makes the current position the origin (the CoreXY plotter's firmware:
    #: "G92 ; nastav aktuální pozici jako počátek"); GRBL refuses it (error:26).
    bare_g92: bool = False
    #: Answer a line only once its motion is done (the CoreXY plotter's firmware executes a
    #: line, then prints ``OK``); GRBL answers when the line is planned.
    ok_when_done: bool = False
    #: mm → steps by truncation (the CoreXY firmware's integer division), not rounding.
    truncate_steps: bool = False
    #: F words are read and ignored, and G0 is G1: every move steps at the ``M98`` interval
    #: (the CoreXY plotter's firmware: "Příkaz G0 a G1 je interpretován stejně", speed set
    #: only by M98, "nastav interval mezi kroky").
    feed_ignored: bool = False
    #: ``M18 [axes]`` switches drivers off (the winder while it waits, its drill while winding).
    drivers_off: bool = False
    #: The winder's white buttons (FIDELITY S0-24): the first press switches every driver's
    #: holding current off, the second declares the axes to stand at this position (A 0,
    #: X the board radius, Z 0).  None: the machine has no such buttons.
    hand_zero: tuple[float, ...] | None = None
    #: Units/min a G1 runs at before any F; None refuses it (``error:22``).
    default_feed: float | None = None
    #: Largest distance of an arc's chord from the arc (GRBL's $12).
    arc_tolerance: float = 0.002
    control_cycle: float = 0.005
    #: Seconds one unit of ``G4 P`` is: GRBL reads P as seconds, the plotters' firmwares as ms.
    dwell_p_seconds: float = 0.001
    #: Moves beyond the travel are refused (``error:15``); GRBL's ``$20``, off by default.
    soft_limits: bool = True
    #: GRBL 1.1's line handling and ``$`` settings: a lone CR ends a line, comments and
    #: spaces are dropped as they arrive (not counted towards the line limit), ``$N=v``,
    #: ``$C``, ``M8``/``M9`` and ``T`` words are taken.
    grbl: bool = False
    #: GRBL's ``$10`` status mask: 1 = MPos (0: WPos), 2 = ``Bf:`` in reports.
    status_mask: int = 3
    #: GRBL's ``$22``: with homing off ``$H`` is ``error:5``.
    homing: bool = True
    #: GRBL's ``$11`` (mm): moves join at their junction speed and are planned along the
    #: path with per-axis limits (GRBL's planner).  None: every move starts and ends at rest.
    junction_deviation: float | None = None
    #: Per-axis top speeds (units/s) and accelerations (units/s²), GRBL's ``$110…`` and
    #: ``$120…``; None: the shared step rate and acceleration over each axis' steps/unit.
    axis_rates: tuple[float, ...] | None = None
    axis_accelerations: tuple[float, ...] | None = None

    def __post_init__(self) -> None:
        count = len(self.axes)
        if (
            count == 0
            or len(set(self.axes)) != count
            or any(a not in AXIS_LETTERS for a in self.axes)
        ):
            raise ValueError(f"axes are distinct letters from {AXIS_LETTERS}, got {self.axes!r}")
        if len(self.steps_per_unit) != count or len(self.travel) != count:
            raise ValueError("steps_per_unit and travel need one entry per axis")
        if self.hand_zero is not None and len(self.hand_zero) != count:
            raise ValueError("the white buttons' zero needs one entry per axis")
        if any(not (math.isfinite(s) and s > 0) for s in self.steps_per_unit):
            raise ValueError(f"steps per unit must be positive, got {self.steps_per_unit!r}")
        for limits in self.travel:
            if limits is not None and not limits[0] < limits[1]:
                raise ValueError(f"travel runs from low to high, got {limits!r}")
        if self.kinematics == "corexy" and self.axes[:2] != ("X", "Y"):
            raise ValueError("a CoreXY machine's first two axes are X and Y")
        if self.arcs and not {"X", "Y"} <= set(self.axes):
            raise ValueError("arcs are traced in the XY plane: the machine needs X and Y")
        if not (self.max_rate > 0 and self.acceleration > 0):
            raise ValueError("the step rate and the acceleration must be positive")
        if self.planner_blocks < 2 or self.rx_buffer < 2 or self.max_line < 2:
            raise ValueError("the planner and the buffers need room for something")
        if self.pen_time < 0 or not self.control_cycle > 0 or not self.arc_tolerance > 0:
            raise ValueError("times and the arc tolerance must be positive")

    def rates(self) -> tuple[float, ...]:
        """Each axis' top speed in units/s."""
        if self.axis_rates is not None:
            return self.axis_rates
        return tuple(self.max_rate / s for s in self.steps_per_unit)

    def accelerations(self) -> tuple[float, ...]:
        """Each axis' acceleration in units/s²."""
        if self.axis_accelerations is not None:
            return self.axis_accelerations
        return tuple(self.acceleration / s for s in self.steps_per_unit)

    def index(self, axis: str) -> int:
        return self.axes.index(axis)

    def motor_counts(self, position: tuple[float, ...]) -> tuple[int, ...]:
        """Each motor's step counter at ``position``: CoreXY mixes X and Y, the others do not.

        With ``truncate_steps`` each axis is first made whole steps towards zero (the
        CoreXY firmware's integer division), and the motors mix those.
        """
        if self.truncate_steps:
            steps = [math.trunc(p * s) for p, s in zip(position, self.steps_per_unit, strict=True)]
            if self.kinematics == "corexy":
                sx, sy = steps[0], steps[1]
                steps[0], steps[1] = sx - sy, sx + sy
            return tuple(steps)
        counts = [round(p * s) for p, s in zip(position, self.steps_per_unit, strict=True)]
        if self.kinematics == "corexy":
            x, y = position[0], position[1]
            counts[0] = round((x - y) * self.steps_per_unit[0])
            counts[1] = round((x + y) * self.steps_per_unit[1])
        return tuple(counts)

    def within_travel(self, position: tuple[float, ...]) -> bool:
        if not self.soft_limits:
            return True
        # A hair of tolerance, so that a target computed in inches or along an
        # arc that should land on the edge is not refused for rounding.
        return all(
            limits is None or limits[0] - 1e-9 <= p <= limits[1] + 1e-9
            for p, limits in zip(position, self.travel, strict=True)
        )


def corexy_plotter_config() -> GcodeConfig:
    """The RP2040 CoreXY pen plotter as its own firmware, not GRBL.

    ``OK`` once a line's motion is done; G0 is G1 and F is ignored (the M98 step
    interval alone sets the speed); M3 lifts and M4 lowers the pen, M99 lifts
    it to a PWM level, M98 sets the step interval; one step interval from a move's
    first step to its last (no acceleration: the thesis names ramps as future work);
    mm → steps truncated; a bare ``G92`` sets the origin.  Travel 300 by 210 mm: the
    original's drawing area is "at least A4" (297 by 210 mm).
    """
    per_mm = 1.0 / COREXY_MM_PER_STEP
    return GcodeConfig(
        kinematics="corexy",
        axes=("X", "Y", "Z"),
        steps_per_unit=(per_mm, per_mm, 100.0),
        travel=((0.0, 300.0), (0.0, 210.0), (-20.0, 20.0)),
        max_rate=40_000.0,
        acceleration=math.inf,
        reply_ok="OK",
        reply_error="ERROR",
        banner=PLOTTER_BANNER,
        pen=PenMapping.M3_UP_M4_DOWN,
        plotter_codes=True,
        default_feed=6000.0,
        bare_g92=True,
        ok_when_done=True,
        truncate_steps=True,
        feed_ignored=True,
    )


def grbl_plotter_config() -> GcodeConfig:
    """A GRBL 1.1 servo pen plotter: 80 steps/mm, ``M3 S<n>`` lowers, ``M5`` lifts, arcs."""
    return GcodeConfig(
        kinematics="cartesian",
        axes=("X", "Y", "Z"),
        steps_per_unit=(80.0, 80.0, 80.0),
        travel=((0.0, 300.0), (0.0, 200.0), (-20.0, 20.0)),
        max_rate=8000.0,
        acceleration=80_000.0,
        pen=PenMapping.SPINDLE,
        arcs=True,
        jogging=True,
        dwell_p_seconds=1.0,
        soft_limits=False,
        grbl=True,
        junction_deviation=0.010,
    )


def string_art_config() -> GcodeConfig:
    """The string-art winder: A turns the base (degrees), X the radius, Z along the needle."""
    return GcodeConfig(
        kinematics="cylindrical",
        axes=("A", "X", "Z"),
        steps_per_unit=(STRING_ART_STEPS_PER_TURN / 360.0, 32.0, 133.3),
        travel=(None, (0.0, 250.0), (0.0, 30.0)),
        max_rate=2000.0,
        acceleration=500.0,
        pen=PenMapping.SPINDLE,
        default_feed=60_000.0,
        drivers_off=True,
        hand_zero=(0.0, STRING_ART_BOARD_RADIUS_MM, 0.0),
    )
