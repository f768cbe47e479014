"""What differs between drill plotters, for the emulated firmware (docs/protocols.md §3).

The defaults describe the reference plotter; a profile's ``[timing]`` gives
another machine's constants (:meth:`DrillConfig.with_timing`, FIDELITY S2-06).
"""

from __future__ import annotations

from dataclasses import dataclass

from protocol.drill import timing
from protocol.drill.timing import DRILL_OVERTRAVEL, DrillTiming


@dataclass(frozen=True)
class DrillConfig:
    """What differs between machines; the defaults describe the reference plotter.

    Lengths are microsteps, times seconds.  ``travel`` is the range of
    positions reachable from the machine's zero (X 4200 and Y 3000 are about
    212 by 152 mm at 19.8 and 19.7 microsteps per mm: the original drills
    boards "do velikosti A5 (148mm x 210mm)", FIDELITY S2-27).
    """

    travel: tuple[int, int] = (4200, 3000)
    #: Seconds per microstep of X, Y and Z.
    step_periods: tuple[float, float, float] = (
        timing.STEP_PERIODS_S["X"],
        timing.STEP_PERIODS_S["Y"],
        timing.STEP_PERIODS_S["Z"],
    )
    #: Microsteps from where each end switch opens to the zero, X and Y.
    zero_offsets: tuple[int, int] = (timing.ZERO_OFFSETS["X"], timing.ZERO_OFFSETS["Y"])
    #: Where the carriage stands at power-on, microsteps from the X/Y switch edges.
    power_on: tuple[int, int] = (1200, 900)
    #: Z microsteps from the top to where the optical sensor sees the board.
    sensor_depth: int = timing.SENSOR_DEPTH
    #: Microsteps in one full step of Z (half-step drive): the return goes that many a period.
    z_microsteps_per_step: int = timing.Z_MICROSTEPS_PER_FULL_STEP
    #: Full steps of the return stroke.
    return_full_steps: int = timing.RETURN_FULL_STEPS
    #: Going down, a pause of ``down_pause`` seconds after every ``down_pause_every`` microsteps.
    down_pause: float = timing.DOWN_PAUSE_S
    down_pause_every: int = timing.DOWN_PAUSE_EVERY
    #: Seconds the drill stays at the bottom of the stroke, and waits after the return.
    dwell: float = timing.BOTTOM_WAIT_S
    after_wait: float = timing.AFTER_WAIT_S
    control_cycle: float = 0.005
    #: Run the ``N`` procedure at power-on, before any command, as the original does.
    home_at_power_on: bool = True

    def __post_init__(self) -> None:
        if any(t <= 0 for t in self.travel):
            raise ValueError(f"travel must be positive, got {self.travel!r}")
        if any(not p > 0 for p in self.step_periods):
            raise ValueError(f"step periods must be positive, got {self.step_periods!r}")
        if any(o < 0 for o in self.zero_offsets):
            raise ValueError(f"zero offsets must be >= 0, got {self.zero_offsets!r}")
        for start, travel, offset in zip(
            self.power_on, self.travel, self.zero_offsets, strict=True
        ):
            if not 0 <= start <= travel + offset + 1:
                raise ValueError(f"power-on position {start} is outside the switches")
        if self.sensor_depth <= 0 or self.z_microsteps_per_step <= 0:
            raise ValueError("the sensor depth and the Z full step must be positive")
        if self.return_full_steps <= 0 or self.down_pause_every <= 0:
            raise ValueError("the return stroke and the pause interval must be positive")
        if min(self.dwell, self.after_wait, self.down_pause) < 0 or not (self.control_cycle > 0):
            raise ValueError("times must be >= 0 and the control cycle positive")

    @classmethod
    def with_timing(cls, drill_timing: DrillTiming, **others: object) -> DrillConfig:
        """A machine with ``drill_timing``'s constants (a profile's ``[timing]``, S2-06)."""
        t = drill_timing
        return cls(
            step_periods=(t.x_period_s, t.y_period_s, t.z_period_s),
            down_pause=t.down_pause_s,
            down_pause_every=t.down_pause_every,
            dwell=t.bottom_wait_s,
            after_wait=t.after_wait_s,
            return_full_steps=t.return_full_steps,
            **others,  # type: ignore[arg-type]
        )

    @property
    def drill_depth(self) -> int:
        """Z microsteps from the top to the bottom of a drilling stroke."""
        return self.sensor_depth + DRILL_OVERTRAVEL
