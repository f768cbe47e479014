"""Physical model of one stepper axis, for the firmware emulators and for dry runs.

Dry runs must replay a whole job far faster than real time, and the firmware
emulator may be advanced in anything from 1 ms ticks to one leap of minutes, so
the model never integrates in small fixed time steps. Instead, every command
plans the motion as a short list of constant-acceleration *phases* (with
instant speed jumps between them, as a stepper driver may jump to and from its
start speed), and :meth:`Axis.advance` walks from event to event — the end of
a phase, or the axis reaching an end-switch edge — evaluating the closed form
inside each phase. Positions are always computed from the start of the current
phase, never accumulated over calls, so one long ``advance`` and many short ones
land on the same numbers.

Units are micrometres and seconds throughout; positions are "logical" (the
frame the firmware reports, shifted by SET_POS and homing), while the end
switches sit at fixed *physical* positions: the low one at 0, the high one at
the travel. ``physical = logical - offset``.

The switches have one microstep of hysteresis: a switch closes when the axis
reaches its edge and opens again only once the axis has moved one microstep
back. That is what makes homing's back-off well defined ("until the switch
releases"), and it means an axis that has just touched a switch cannot creep
back into it by a fraction of a microstep.
"""

from __future__ import annotations

import copy
import enum
import math
from dataclasses import dataclass
from typing import Literal

TIME_EPS = 1e-12
"""Seconds. A phase with less than this left is treated as finished, so that
rounding never leaves slivers of phases for the event loop to chew on."""

POS_EPS = 1e-9
"""Micrometres. Positions closer than this are the same place: a move within
this of its target has arrived, an axis within this of a switch edge is on it."""

SwitchName = Literal["low", "high"]


class AxisState(enum.Enum):
    """Axis state; the values are the stage echo's STATUS codes 0…7."""

    IDLE = 0
    ACCELERATING = 1
    CRUISING = 2
    DECELERATING = 3
    TARGET_REACHED = 4
    STOPPED = 5
    HOMING = 6
    END_SWITCH = 7


@dataclass
class AxisLimits:
    """Mechanical facts of an axis, rewritten when the firmware's parameters change."""

    travel_um: float
    """Soft limit (targets are clamped to ``[0, travel_um]``) and the physical
    position of the high end switch."""
    microstep_um: float
    """Resolution of the position counter, and the switches' hysteresis."""

    def __post_init__(self) -> None:
        if not (math.isfinite(self.travel_um) and self.travel_um > 0):
            raise ValueError(f"travel must be positive, got {self.travel_um!r}")
        if not (math.isfinite(self.microstep_um) and self.microstep_um > 0):
            raise ValueError(f"microstep must be positive, got {self.microstep_um!r}")


def _sign(value: float) -> int:
    return (value > 0) - (value < 0)


@dataclass(frozen=True)
class _Phase:
    """A stretch of constant acceleration, starting at ``v0`` (after any jump)."""

    v0: float
    accel: float
    duration: float  # may be math.inf: a cruise that only an event ends
    state: AxisState

    @property
    def direction(self) -> int:
        """Direction of travel; constant over a phase because no phase crosses v = 0."""
        return _sign(self.v0) or _sign(self.accel)

    def position(self, x0: float, t: float) -> float:
        return x0 + self.v0 * t + 0.5 * self.accel * t * t

    def velocity(self, t: float) -> float:
        return self.v0 + self.accel * t

    def time_to_reach(self, x0: float, x: float) -> float:
        """When (from the phase start) the axis passes ``x``, known to lie on this phase's path.

        Uses the cancellation-free root ``2d / (u + sqrt(u^2 + 2ad))`` so that a
        point met at the very start of a phase gives t = 0, not rounding noise;
        rounding near a phase that brakes to a halt is clamped rather than
        allowed to lose the event.
        """
        distance = max((x - x0) * self.direction, 0.0)
        if distance == 0:
            return 0.0
        speed = abs(self.v0)
        accel = self.accel * self.direction  # > 0 speeding up, < 0 slowing down
        discriminant = max(speed * speed + 2.0 * accel * distance, 0.0)
        denominator = speed + math.sqrt(discriminant)
        if denominator <= 0:
            return self.duration
        return min(2.0 * distance / denominator, self.duration)


class _Goal(enum.Enum):
    """What a plan is for: decides what happens when its phases run out or it meets a switch."""

    MOVE = enum.auto()  # decelerate onto a target: TARGET_REACHED
    RUN = enum.auto()  # run on until a switch stops it (jog, clamped move)
    HALT = enum.auto()  # decelerate to standstill: STOPPED
    HOME_SEEK = enum.auto()  # run to the low switch, then back off
    HOME_BACK_OFF = enum.auto()  # creep off the low switch until it releases


@dataclass(frozen=True)
class _Plan:
    goal: _Goal
    phases: tuple[_Phase, ...]
    target: float | None = None  # MOVE: logical position the last phase ends on
    speed: float = 0.0  # HOME_SEEK: to re-plan the seek after bouncing off the high switch
    open_ended: bool = False  # a jog: its end is the operator's (or the watchdog's) decision


class _ProfileBuilder:
    """Lays phases end to end from the axis's present position and velocity.

    It keeps its own running position and velocity, so each profile is written
    as the sequence of manoeuvres a driver would do ("brake to start speed,
    reverse, accelerate, cruise, brake"), and the distances come out of the
    closed forms rather than from bookkeeping in the caller.

    Speeds at or below the start speed are reached by jumping; only the part of
    a speed change above the start speed is ramped.
    """

    def __init__(
        self,
        position: float,
        velocity: float,
        *,
        acceleration: float,
        start_speed: float,
        state: AxisState | None = None,
    ) -> None:
        self.x = position
        self.v = velocity
        self._accel = acceleration
        self._floor = start_speed
        self._state = state  # overrides the per-phase state (homing shows HOMING throughout)
        self.phases: list[_Phase] = []

    # -- primitives ---------------------------------------------------------

    def jump(self, velocity: float) -> None:
        self.v = velocity

    def ramp_to(self, velocity: float) -> None:
        """Constant acceleration to ``velocity``, which must have the current sign (or be 0)."""
        dv = velocity - self.v
        duration = abs(dv) / self._accel
        state = AxisState.ACCELERATING if abs(velocity) > abs(self.v) else AxisState.DECELERATING
        self._emit(math.copysign(self._accel, dv), duration, state)
        self.v = velocity  # exact, whatever rounding the emitted phase had

    def cruise(self, duration: float) -> None:
        self._emit(0.0, duration, AxisState.CRUISING)

    def _emit(self, accel: float, duration: float, state: AxisState) -> None:
        if duration <= TIME_EPS:
            return
        if self._state is not None:
            state = self._state
        self.phases.append(_Phase(self.v, accel, duration, state))
        if math.isfinite(duration):
            self.x += self.v * duration + 0.5 * accel * duration * duration
            self.v += accel * duration

    # -- manoeuvres ---------------------------------------------------------

    def ramp_distance(self, from_speed: float, to_speed: float) -> float:
        """Distance a speed change covers; the part below the start speed is a jump."""
        high = max(from_speed, self._floor)
        low = max(to_speed, self._floor)
        return abs(high * high - low * low) / (2.0 * self._accel)

    def change_speed(self, speed: float, direction: int) -> None:
        """Get to ``speed`` (unsigned) in ``direction``, which is the current one or v = 0."""
        current = abs(self.v)
        floor = self._floor
        if current <= floor and speed <= floor:
            self.jump(direction * speed)
            return
        if speed > current:
            if current < floor:
                self.jump(direction * floor)
            self.ramp_to(direction * speed)
        else:
            self.ramp_to(direction * max(speed, floor))
            if speed < floor:
                self.jump(direction * speed)

    def brake(self) -> None:
        """Slow to the start speed, from where the driver may stop or reverse at once."""
        if abs(self.v) > self._floor:
            self.ramp_to(math.copysign(self._floor, self.v))

    def move(self, target: float, speed: float) -> None:
        """Arrive at ``target`` at start speed (or ``speed`` if lower) and stop there."""
        heading = _sign(self.v)
        if abs(self.v) > self._floor:
            ahead = (target - self.x) * heading
            if ahead < self.ramp_distance(abs(self.v), 0.0) - POS_EPS:
                # Behind us, or too close to stop in time: brake first, then come back.
                self.brake()
        if abs(self.v) <= self._floor:
            if abs(target - self.x) <= POS_EPS:
                return
            heading = _sign(target - self.x)
            self.jump(heading * min(self._floor, speed))
        distance = abs(target - self.x)
        current = abs(self.v)
        ramps = self.ramp_distance(current, speed) + self.ramp_distance(speed, 0.0)
        if ramps <= distance:
            self.change_speed(speed, heading)
            self.cruise((distance - ramps) / speed)
        else:
            # Triangular: the peak where the speed-up and the slow-down meet.
            top = max(current, self._floor)
            peak = math.sqrt(self._accel * distance + 0.5 * (top * top + self._floor**2))
            self.change_speed(peak, heading)
        self.change_speed(0.0, heading)

    def run(self, direction: int, speed: float) -> None:
        """Reach ``speed`` in ``direction`` and keep going until something stops the axis."""
        if self.v * direction < 0:
            self.brake()
        if abs(self.v) <= self._floor:
            self.jump(direction * min(self._floor, speed))
        self.change_speed(speed, direction)
        self.cruise(math.inf)


class AxisMotion:
    """Where an axis is and how it moves: the plan's phases walked event by event.

    :class:`Axis` is the command surface (settings checked, commands planned,
    positions read out); this is the state those commands change and the walk
    through time that :meth:`Axis.advance` asks for, end switches included.
    Its attributes are the axis's own; only :class:`Axis` writes them.
    """

    def __init__(
        self, limits: AxisLimits, *, acceleration: float, start_speed: float, position_um: float
    ) -> None:
        #: Settings, checked by :class:`Axis` before they are written here.
        self.limits = limits
        self.acceleration = acceleration
        self.start_speed = start_speed
        self.offset = 0.0  # logical - physical
        self.x0 = float(position_um)  # logical position at the start of the phase (or at rest)
        self.t = 0.0  # time into the current phase
        self.plan: _Plan | None = None
        self.phase: _Phase | None = None
        self.queue: tuple[_Phase, ...] = ()  # phases after the current one
        self.rest_state = AxisState.IDLE
        #: Physical position at which a closed switch opens again; None = open.
        self.low_release_at: float | None = None
        self.high_release_at: float | None = None
        self.sync_switches()

    @property
    def position(self) -> float:
        if self.phase is None:
            return self.x0
        return self.phase.position(self.x0, self.t)

    @property
    def velocity(self) -> float:
        if self.phase is None:
            return 0.0
        return self.phase.velocity(self.t)

    @property
    def state(self) -> AxisState:
        if self.phase is None:
            return self.rest_state
        return self.phase.state

    def physical(self) -> float:
        return self.position - self.offset

    # -- plans ----------------------------------------------------------------

    def builder(self, state: AxisState | None = None) -> _ProfileBuilder:
        return _ProfileBuilder(
            self.position,
            self.velocity,
            acceleration=self.acceleration,
            start_speed=self.start_speed,
            state=state,
        )

    def seek_plan(self, speed: float) -> _Plan:
        builder = self.builder(AxisState.HOMING)
        builder.run(-1, speed)
        return _Plan(_Goal.HOME_SEEK, tuple(builder.phases), speed=speed)

    def install(self, plan: _Plan) -> None:
        """Replace the plan from the present instant (no time passes)."""
        self.x0 = self.position
        self.t = 0.0
        self.plan = plan
        self.phase = plan.phases[0] if plan.phases else None
        self.queue = plan.phases[1:]

    def start(self, plan: _Plan) -> None:
        self.install(plan)
        self.run(0.0)  # refusals and zero-length plans resolve before the caller looks

    def halt(self, state: AxisState) -> None:
        """Standstill here and now."""
        self.x0 = self.position
        self.t = 0.0
        self.plan = None
        self.phase = None
        self.queue = ()
        self.rest_state = state
        self.sync_switches()

    def sync_switches(self) -> None:
        """Close a switch whose edge the axis rests on, open one it has backed off from.

        Only for an axis at rest: while moving, switches change only through
        the events of :meth:`_next_event`, which know to let a move that ends
        on a switch edge arrive. Judging a moving axis by its position here
        would turn the last nanometre of such a move into a crash.
        """
        physical = self.physical()
        travel = self.limits.travel_um
        step = self.limits.microstep_um
        if self.low_release_at is None:
            if physical <= POS_EPS:
                self.low_release_at = max(physical, 0.0) + step
        elif physical >= self.low_release_at - POS_EPS:
            self.low_release_at = None
        if self.high_release_at is None:
            if physical >= travel - POS_EPS:
                self.high_release_at = min(physical, travel) - step
        elif physical <= self.high_release_at + POS_EPS:
            self.high_release_at = None

    # -- time -----------------------------------------------------------------

    def run(self, dt: float) -> float:
        """Advance up to ``dt`` (may be inf); return the time that passed while moving."""
        elapsed = 0.0
        while self.plan is not None:
            if self._settle():
                continue
            phase = self.phase
            assert phase is not None  # _settle() ends a plan whose phases ran out
            budget = max(dt - elapsed, 0.0)
            event = self._next_event(phase)
            if event is not None and event[0] - self.t <= budget:
                at, which, closing = event
                elapsed += at - self.t
                self._arrive(phase, at, which, closing)
                continue
            if budget <= 0:
                break
            left = phase.duration - self.t
            if math.isinf(left):
                if math.isinf(budget):
                    return math.inf  # an endless run: no event will ever stop it
                self.t += budget
                elapsed = dt
            elif left <= budget + TIME_EPS:
                elapsed += left
                self._next_phase(phase)
            else:
                self.t += budget
                elapsed = dt
        return elapsed

    def _settle(self) -> bool:
        """Apply what the present instant demands; True if that changed the plan."""
        plan = self.plan
        assert plan is not None
        phase = self.phase
        if phase is None:
            self._finish(plan)
            return True
        if plan.goal is _Goal.HOME_BACK_OFF and self.low_release_at is None:
            self._finish_homing()
            return True
        direction = phase.direction
        if direction < 0 and self.low_release_at is not None:
            self._on_switch(plan, "low")
            return True
        if direction > 0 and self.high_release_at is not None:
            self._on_switch(plan, "high")
            return True
        return False

    def _next_event(self, phase: _Phase) -> tuple[float, SwitchName, bool] | None:
        """Earliest switch edge this phase reaches before its end: (time, switch, closing).

        An edge that coincides with the phase's end is left to the phase end, so
        a move planned to stop exactly on a switch arrives (TARGET_REACHED)
        rather than crashes into it.
        """
        direction = phase.direction
        travel = self.limits.travel_um
        edges: list[tuple[float, SwitchName, bool]] = []
        if direction < 0:
            if self.low_release_at is None:
                edges.append((0.0, "low", True))
            if self.high_release_at is not None:
                edges.append((self.high_release_at, "high", False))
        elif direction > 0:
            if self.high_release_at is None:
                edges.append((travel, "high", True))
            if self.low_release_at is not None:
                edges.append((self.low_release_at, "low", False))
        end = self._phase_end_position(phase)
        best: tuple[float, SwitchName, bool] | None = None
        here = phase.position(self.x0, self.t)
        for physical, which, closing in edges:
            edge = physical + self.offset
            if (end - edge) * direction <= POS_EPS:
                continue
            if (edge - here) * direction <= 0:
                at = self.t  # already on or past it (the travel just shrank)
            else:
                at = max(phase.time_to_reach(self.x0, edge), self.t)
            if best is None or at < best[0]:
                best = (at, which, closing)
        return best

    def _phase_end_position(self, phase: _Phase) -> float:
        if math.isinf(phase.duration):
            return math.inf * phase.direction
        plan = self.plan
        if not self.queue and plan is not None and plan.target is not None:
            return plan.target
        return phase.position(self.x0, phase.duration)

    def _arrive(self, phase: _Phase, at: float, which: SwitchName, closing: bool) -> None:
        """Re-base the phase on the switch edge reached at ``at``, exactly on the edge."""
        physical = self._physical_edge(which, closing)
        self.x0 = physical + self.offset
        self.phase = _Phase(phase.velocity(at), phase.accel, phase.duration - at, phase.state)
        self.t = 0.0
        step = self.limits.microstep_um
        # Latch explicitly (not via sync_switches) so the edge cannot be found again.
        if which == "low":
            self.low_release_at = physical + step if closing else None
        else:
            self.high_release_at = physical - step if closing else None

    def _physical_edge(self, which: SwitchName, closing: bool) -> float:
        if closing:
            return 0.0 if which == "low" else self.limits.travel_um
        release = self.low_release_at if which == "low" else self.high_release_at
        assert release is not None
        return release

    def _next_phase(self, phase: _Phase) -> None:
        self.x0 = self._phase_end_position(phase)
        self.t = 0.0
        if self.queue:
            self.phase, self.queue = self.queue[0], self.queue[1:]
        else:
            self.phase = None

    def _finish(self, plan: _Plan) -> None:
        if plan.goal is _Goal.MOVE:
            assert plan.target is not None
            self.x0 = plan.target
            self.halt(AxisState.TARGET_REACHED)
        else:
            self.halt(AxisState.STOPPED)

    def _on_switch(self, plan: _Plan, which: SwitchName) -> None:
        """The axis is pushing into a closed switch: it stops dead, without ramp."""
        self.halt(AxisState.END_SWITCH)
        if plan.goal is _Goal.HOME_SEEK:
            if which == "low":
                back_off = self.start_speed or plan.speed
                builder = self.builder(AxisState.HOMING)
                builder.run(1, back_off)
                self.install(_Plan(_Goal.HOME_BACK_OFF, tuple(builder.phases)))
            else:
                # Braking out of a + motion carried the axis into the high switch:
                # homing goes on, away from it.
                self.install(self.seek_plan(plan.speed))

    def _finish_homing(self) -> None:
        physical = self.physical()
        self.halt(AxisState.TARGET_REACHED)
        self.offset = -physical
        self.x0 = 0.0


class Axis:
    """One emulated stepper axis: plans trapezoidal moves and steps through them exactly.

    Commands only re-plan from the present position and velocity; nothing moves
    until :meth:`advance` is called with elapsed time, which the owner takes
    from its injected clock.  The state and the walk through time are
    :class:`AxisMotion`'s.
    """

    def __init__(
        self,
        limits: AxisLimits,
        *,
        acceleration: float,
        start_speed: float,
        position_um: float = 0.0,
    ) -> None:
        if not math.isfinite(position_um):
            raise ValueError(f"position must be finite, got {position_um!r}")
        self._motion = AxisMotion(
            limits, acceleration=1.0, start_speed=0.0, position_um=position_um
        )
        self.acceleration = acceleration
        self.start_speed = start_speed
        self._target: float | None = None

    # -- settings -------------------------------------------------------------

    @property
    def acceleration(self) -> float:
        """µm/s²; read when a motion is planned, so a change applies from the next command."""
        return self._motion.acceleration

    @acceleration.setter
    def acceleration(self, value: float) -> None:
        if not (math.isfinite(value) and value > 0):
            raise ValueError(f"acceleration must be positive, got {value!r}")
        self._motion.acceleration = float(value)

    @property
    def start_speed(self) -> float:
        """µm/s the motor can jump to from rest (and stop from) without losing steps."""
        return self._motion.start_speed

    @start_speed.setter
    def start_speed(self, value: float) -> None:
        if not (math.isfinite(value) and value >= 0):
            raise ValueError(f"start speed must be >= 0, got {value!r}")
        self._motion.start_speed = float(value)

    @property
    def limits(self) -> AxisLimits:
        return self._motion.limits

    @limits.setter
    def limits(self, limits: AxisLimits) -> None:
        motion = self._motion
        previous, motion.limits = motion.limits, limits
        if limits.travel_um != previous.travel_um:
            # The high switch sits at the travel, so it moved: forget its latch
            # and judge it afresh from the position.
            motion.high_release_at = None
        if motion.plan is None:
            motion.sync_switches()
        # A moving axis meets a moved switch through its events, at once if already past it.
        motion.run(0.0)

    # -- read-out -------------------------------------------------------------

    @property
    def position_um(self) -> float:
        return self._motion.position

    @property
    def physical_um(self) -> float:
        """Where the axis really is, from its low end switch: what an absolute encoder reads,
        whatever SET_POS and homing have made of the logical frame."""
        return self._motion.physical()

    @property
    def microsteps(self) -> int:
        """Logical position in whole microsteps, as the firmware's step counter holds it.

        Ties round up, so the count does not depend on Python's banker's rounding.
        """
        return math.floor(self.position_um / self._motion.limits.microstep_um + 0.5)

    @property
    def position_quantised_um(self) -> float:
        return self.microsteps * self._motion.limits.microstep_um

    @property
    def velocity(self) -> float:
        return self._motion.velocity

    @property
    def state(self) -> AxisState:
        return self._motion.state

    @property
    def moving(self) -> bool:
        return self._motion.plan is not None

    @property
    def target_um(self) -> float | None:
        """The (clamped) target of the last move command; None after a jog, stop or home."""
        return self._target

    @property
    def end_switch_low(self) -> bool:
        return self._motion.low_release_at is not None

    @property
    def end_switch_high(self) -> bool:
        return self._motion.high_release_at is not None

    # -- commands -------------------------------------------------------------

    def move_to(self, target_um: float, speed: float) -> None:
        """MOVE_ABS. A target beyond the travel is clamped and run into the switch undecelerated."""
        if not math.isfinite(target_um):
            raise ValueError(f"target must be finite, got {target_um!r}")
        _check_speed(speed)
        travel = self._motion.limits.travel_um
        clamped = float(min(max(target_um, 0.0), travel))
        self._target = clamped
        if clamped != target_um:
            # The firmware gives up on a position it may not reach and simply
            # heads for that end until the switch stops it.
            builder = self._motion.builder()
            builder.run(1 if target_um > travel else -1, speed)
            self._motion.start(_Plan(_Goal.RUN, tuple(builder.phases)))
            return
        builder = self._motion.builder()
        builder.move(clamped, speed)
        self._motion.start(_Plan(_Goal.MOVE, tuple(builder.phases), target=clamped))

    def move_by(self, delta_um: float, speed: float) -> None:
        """MOVE_REL: relative to where the axis is now, not to a target it is still heading for."""
        self.move_to(self.position_um + delta_um, speed)

    def jog(self, direction: int, speed: float) -> None:
        """JOG: run towards that end until stopped or a switch; 0 brakes to a stop."""
        if direction not in (-1, 0, 1):
            raise ValueError(f"jog direction must be -1, 0 or +1, got {direction!r}")
        if direction == 0:
            self.stop()
            return
        _check_speed(speed)
        self._target = None
        builder = self._motion.builder()
        builder.run(direction, speed)
        self._motion.start(_Plan(_Goal.RUN, tuple(builder.phases), open_ended=True))

    def stop(self) -> None:
        """STOP: brake to start speed and halt (STOPPED); nothing to do if at rest."""
        if self._motion.plan is None:
            return
        self._target = None
        builder = self._motion.builder()
        builder.brake()
        self._motion.start(_Plan(_Goal.HALT, tuple(builder.phases)))

    def estop(self) -> None:
        """ESTOP: standstill at once, whatever the speed (steps are lost on real hardware)."""
        if self._motion.plan is None:
            return
        self._target = None
        self._motion.halt(AxisState.STOPPED)

    def home(self, speed: float) -> None:
        """HOME: seek the low switch, back off until it releases, call that 0."""
        _check_speed(speed)
        self._target = None
        self._motion.start(self._motion.seek_plan(speed))

    def set_position(self, position_um: float) -> None:
        """SET_POS: rename the present position; a motion in progress carries on physically.

        Targets of a move in progress shift with the frame, so the axis stops
        at the same physical place it was heading for.
        """
        if not math.isfinite(position_um):
            raise ValueError(f"position must be finite, got {position_um!r}")
        motion = self._motion
        shift = position_um - self.position_um
        motion.offset += shift
        if motion.phase is None:
            motion.x0 = float(position_um)
        else:
            motion.x0 += shift
        if self._target is not None:
            self._target += shift
        if motion.plan is not None and motion.plan.target is not None:
            motion.plan = _Plan(
                motion.plan.goal,
                motion.plan.phases,
                target=motion.plan.target + shift,
                speed=motion.plan.speed,
                open_ended=motion.plan.open_ended,
            )

    def trigger_end_switch(self, which: SwitchName) -> None:
        """Fault hook: close a switch where the axis is now (a crash, a stuck lever).

        It opens again once the axis has moved a microstep away from it, like
        the real switches.
        """
        motion = self._motion
        physical = motion.physical()
        step = motion.limits.microstep_um
        if which == "low":
            motion.low_release_at = max(physical, 0.0) + step
        elif which == "high":
            motion.high_release_at = min(physical, motion.limits.travel_um) - step
        else:
            raise ValueError(f"no such end switch: {which!r}")
        motion.run(0.0)

    # -- time -----------------------------------------------------------------

    def advance(self, dt: float) -> None:
        """Let ``dt`` seconds pass; any dt gives the same result as the same time in pieces."""
        if not (math.isfinite(dt) and dt >= 0):
            raise ValueError(f"dt must be finite and >= 0, got {dt!r}")
        self._motion.run(dt)

    def time_to_idle(self) -> float | None:
        """Seconds until standstill if nothing else is commanded.

        Found by running a copy of the axis's motion to the end, so it includes
        switch stops and homing's back-off exactly as :meth:`advance` would do
        them. None for a jog, whose end is the operator's decision.
        """
        plan = self._motion.plan
        if plan is None:
            return 0.0
        if plan.open_ended:
            return None
        elapsed = copy.copy(self._motion).run(math.inf)
        return elapsed if math.isfinite(elapsed) else None


def _check_speed(speed: float) -> None:
    if not (math.isfinite(speed) and speed > 0):
        raise ValueError(f"speed must be positive, got {speed!r}")
