"""The drill firmware's procedures: what each command does to the axes, step by step.

A procedure is a generator that starts each step on the mechanism and yields
how long it takes; the firmware's control loop
(:mod:`protocol.emulator.drill_firmware`) runs it across cycles and answers
``D`` when it ends.  Each mirrors the original's routine of the same name
(FIDELITY S2).  Run under the firmware's lock.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Iterator

from protocol.drill.codec import Command
from protocol.emulator.drill_config import DrillConfig
from protocol.emulator.drill_events import (
    DrawnSegment,
    DrilledHole,
    DrillEvent,
    PenEvent,
    StalledAtFrame,
)
from protocol.mechanism import Axis

#: Seconds added to a motion's computed duration.  Advancing an axis by exactly
#: its ``time_to_idle`` can leave it a rounding error short of the event that
#: ends the motion (homing's switch opening), still moving; the next step would
#: then re-plan it and homing would never set its zero.  Far below a step
#: period and below the firmware's time tolerance, so it never shifts a reply
#: into another cycle.
_SLOP = 1e-10

#: A procedure: a generator that starts each step and yields how long it takes.
Procedure = Iterator[float]


class DrillProcedures:
    """The procedures of one drill firmware, over its X, Y and Z, and what they leave set."""

    def __init__(
        self,
        axes: tuple[Axis, Axis, Axis],
        config: DrillConfig,
        switch_spans: tuple[int, int],
        now: Callable[[], float],
        log: Callable[[DrillEvent], None],
    ) -> None:
        self.axes = axes
        #: The firmware's config (replaced when the timing is set).
        self.config = config
        self.speeds = tuple(1.0 / p for p in config.step_periods)
        #: Microsteps from the home sensor's edge to the far frame, X and Y.
        self.switch_spans = switch_spans
        self.now = now
        self.log = log
        self.homed = False
        self.motors_on = False
        self.pen_down = False

    def set_config(self, config: DrillConfig) -> None:
        """New timing from the next procedure step on (S2-06)."""
        self.config = config
        self.speeds = tuple(1.0 / p for p in config.step_periods)

    def positions(self) -> tuple[int, int, int]:
        x, y, z = (axis.microsteps for axis in self.axes)
        return x, y, z

    def for_command(self, command: Command) -> Procedure:
        match command.letter:
            case "N":
                return self.home()
            case "X" | "Y":
                assert command.value is not None
                return self.move("XY".index(command.letter), command.value)
            case "V":
                return self.drill()
            case "K":
                return self.pen(down=True)
            case "Z":
                return self.pen(down=False)
            case "P":
                return self.park()
        raise AssertionError(f"no procedure for {command!r}")

    def until_idle(self, index: int) -> float:
        """Seconds until the axis has surely stopped (its moves are never open-ended)."""
        left = self.axes[index].time_to_idle()
        assert left is not None
        return left + _SLOP if left > 0 else 0.0

    def move(self, index: int, target: int) -> Procedure:
        """Step the counter to ``target``; the carriage follows until a frame stops it.

        The original has one sensor per axis, at the home end, read only while homing
        ("Kazdy pohyb je ukoncen v jednom smeru cidlem"): a move past the far end of the
        travel runs the carriage into the frame, where it stalls while the firmware steps
        on, so the move takes every step's period and the counter ends ``lost`` microsteps
        past the carriage (FIDELITY S2-29).  Lost steps make later targets lie as well.
        """
        self.motors_on = True
        axis = self.axes[index]
        axis.start_speed = self.speeds[index]
        x0, y0, _ = self.positions()
        # Where the frames are in the counter's frame: the far one at the physical end of
        # the travel, the home one behind the sensor at physical 0.
        offset = axis.position_um - axis.physical_um
        far = math.floor(self.switch_spans[index] + offset + 1e-9)
        home = math.ceil(offset - 1e-9)
        reach = min(max(target, home), far)
        axis.move_to(float(reach), self.speeds[index])
        yield self.until_idle(index)
        x1, y1, _ = self.positions()  # where the pen got to: the frame stops it too
        lost = abs(target - reach)
        if lost:
            yield lost / self.speeds[index]  # the firmware steps on, the carriage stands
            axis.set_position(float(axis.microsteps + target - reach))
            end = "far" if target > reach else "home"
            self.log(StalledAtFrame(self.now(), "XY"[index], end, lost, axis.microsteps))
        if self.pen_down and (x1, y1) != (x0, y0):
            self.log(DrawnSegment(self.now(), x0, y0, x1, y1))

    def home(self) -> Procedure:
        self.motors_on = True
        for index in (0, 1):
            axis = self.axes[index]
            axis.start_speed = self.speeds[index]
            axis.home(self.speeds[index])  # to the switch, and off it until it opens
            yield self.until_idle(index)
            axis.move_to(float(self.config.zero_offsets[index]), self.speeds[index])
            yield self.until_idle(index)
            axis.set_position(0.0)
        self.homed = True

    def drill(self) -> Procedure:
        yield from self.z_down(hole=True)
        yield from self.z_up()

    def z_down(self, *, hole: bool) -> Procedure:
        """``Vrtat``'s first half (and all of ``Kresli``): down to the bottom, and the wait.

        ``hole``: a drill is in, so the bottom of the stroke makes a hole (logged there).
        """
        self.motors_on = True
        cfg = self.config
        z = self.axes[2]
        down = 1.0 / cfg.step_periods[2]
        z.start_speed = down
        # To the sensor, then the overtravel, a pause after every second microstep.
        bottom = cfg.drill_depth
        while (here := z.microsteps) < bottom:
            z.move_to(float(min(here + cfg.down_pause_every, bottom)), down)
            yield self.until_idle(2)
            if z.microsteps == bottom:
                break
            yield cfg.down_pause
        if hole:
            x, y, _ = self.positions()
            self.log(DrilledHole(self.now(), x, y))
        if here < bottom and bottom - here == cfg.down_pause_every:
            yield cfg.down_pause  # the pause after the last pair of microsteps
        yield cfg.dwell

    def z_up(self) -> Procedure:
        """``Vrtat``'s second half (and all of ``Zvedni``): the return, and the wait after."""
        cfg = self.config
        z = self.axes[2]
        up = cfg.z_microsteps_per_step / cfg.step_periods[2]
        z.start_speed = up
        climb = cfg.return_full_steps * cfg.z_microsteps_per_step
        z.move_to(float(max(z.microsteps - climb, 0)), up)
        yield self.until_idle(2)
        yield cfg.after_wait

    def pen(self, *, down: bool) -> Procedure:
        if down:
            yield from self.z_down(hole=False)
        else:
            yield from self.z_up()
        self.pen_down = down
        x, y, _ = self.positions()
        self.log(PenEvent(self.now(), down, x, y))

    def park(self) -> Procedure:
        yield from self.move(0, 0)
        yield from self.move(1, self.config.travel[1])
        self.motors_on = False
