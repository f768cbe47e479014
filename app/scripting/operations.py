"""What a scripted machine does, as operations: generators of waits, driven by a caller.

Each operation gives the station its intent (a move, a jog, a stop), then
yields :class:`~app.scripting.waits.Wait` objects until the machine has done
it, raising with the operator's reason when it cannot.  The blocking
:class:`~app.scripting.machine.Machine` drives them by pumping Qt between
looks; the asyncio form (:mod:`app.scripting.aio`) awaits between pumps.
Both drive the same :class:`Operations` object (``machine.operations``),
including what a driver needs when a wait runs out or the caller is
interrupted (:meth:`Operations.timed_out`, :meth:`Operations.stop_after_interrupt`).
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping
from typing import Protocol

from app.machine import LinkState
from app.machines.drill.session import DrillSession
from app.machines.gcode.session import GcodeSession
from app.machines.session import MachineSession
from app.machines.usb3.session import Usb3Session
from app.scripting import parameters as params
from app.scripting.errors import (
    LinkLost,
    MotionFailed,
    MotionRefused,
    MotionTimeout,
    ParameterRefused,
    StepdeckError,
    Unsupported,
)
from app.scripting.pump import Pump
from app.scripting.waits import MachinePort, Operation, Wait
from app.station import STOP_CONFIRM_S

#: How close an axis must stand to its target to count as there (mm or °): the usb3 unit's
#: step is 1/64 of 1 mm/rev at its finest, a G-code board reports 0.001.
POSITION_TOLERANCE = 0.01
#: An axis still for this long after moving (or after a motion was sent and nothing moved)
#: has ended its motion.
SETTLE_S = 0.4
#: Seconds a jog's key is "repeated" (the dead-man wants a sign at least every second).
JOG_KEEPALIVE_S = 0.1
#: Stage statuses after which a motion has ended short of its target.
FAILED_STATUSES = frozenset({"end switch hit", "driver fault", "stopped"})

LINK_DOWN = (LinkState.DISCONNECTED, LinkState.LOST)


class OperatedMachine(MachinePort, Protocol):
    """What the operations read of their machine besides :class:`MachinePort`."""

    @property
    def axes(self) -> tuple[str, ...]: ...

    @property
    def position(self) -> dict[str, float]: ...

    @property
    def timeout(self) -> float: ...

    @property
    def messages(self) -> list[str]: ...


class Operations:
    """One machine's operations, and the stop a driver owes when it gives up on one."""

    def __init__(self, machine: OperatedMachine, pump: Pump) -> None:
        self._machine = machine
        self.station = machine.station
        #: The station's pump: a driver steps it while a wait is not yet met.
        self.pump = pump
        #: What the last parameter write replaced (for its undo), None once undone.
        self.undo: dict[str, dict[str, float]] | None = None

    def session(self) -> MachineSession:
        session = self.station.session
        if session is None or self.station.model.link_state in LINK_DOWN:
            detail = self.station.model.link_detail
            raise LinkLost(f"not connected{f': {detail}' if detail else ''}")
        return session

    def timed_out(self, wait: Wait) -> Exception:
        if wait.on_timeout is not None:
            return wait.on_timeout()
        if wait.motion:
            self.stop_quietly()
            return MotionTimeout(f"{wait.what}: not done within {wait.timeout:g} s; stopped")
        return StepdeckError(f"{wait.what}: no answer within {wait.timeout:g} s")

    def stop_quietly(self) -> None:
        session = self.station.session
        if session is not None and self.station.model.link_state not in LINK_DOWN:
            session.stop_all()

    def stop_after_interrupt(self) -> None:
        """Ctrl+C: stop every axis and give the device a moment to confirm it."""
        self.stop_quietly()
        session = self.station.session
        deadline = self.station.clock.now() + STOP_CONFIRM_S
        while session is not None and not session.motion_stopped():
            if self.station.clock.now() > deadline:
                break
            self.pump.step()

    def move(
        self, wanted: dict[str, float], relative: bool, timeout: float | None
    ) -> Operation[dict[str, float]]:
        session = self.session()
        lock = self.station.model.motion_lock_reason()
        if lock is not None:
            raise MotionRefused(f"Motion refused: {lock}")
        gate = session.gate
        plan: list[tuple[int, float]] = []
        for name, value in wanted.items():
            axis = self._machine.axis_index(name)
            value = float(value)
            refusal = (
                gate.refuse_relative(axis, value) if relative else gate.refuse_target(axis, value)
            )
            if refusal is not None:
                raise MotionRefused(f"Motion refused: {refusal}")
            here = gate.position(axis)
            plan.append((axis, value - here if not relative else value))
        ends: dict[int, float] = {}
        for axis, delta in plan:
            here = gate.position(axis)
            with self._machine.explained() as heard:
                if relative or not _has_absolute(session):
                    sent = session.move_relative(axis, delta)
                else:
                    sent = session.move_absolute(axis, here + delta)
            if not sent:
                self.stop_quietly()
                raise MotionRefused("; ".join(heard) or f"{self._machine.axes[axis]} move refused")
            if isinstance(session, Usb3Session):
                ends[axis] = here + session.reachable(axis, delta)
            elif isinstance(session, DrillSession):  # whole microsteps, 19.7 to the mm
                ends[axis] = session.to_mm(axis, session.to_microsteps(axis, here + delta))
            else:
                ends[axis] = here + delta
        yield from self._settle(ends, timeout)
        return self._machine.position

    def _settle(self, ends: dict[int, float], timeout: float | None) -> Operation[None]:
        """Wait until every axis stands at its end; raise when one stopped short."""
        model = self.station.model
        clock = self.station.clock
        sent_at = clock.now()
        still_since: dict[int, float | None] = dict.fromkeys(ends)
        seen_moving: set[int] = set()

        def arrived() -> bool:
            self._machine.check_link()
            session = self.session()
            _raise_alarm(session, self._machine.messages)
            now = clock.now()
            if _busy(session):  # a queue still runs: the axes wait their turn
                for axis in still_since:
                    still_since[axis] = None
                return False
            done = True
            for axis, end in ends.items():
                state = model.axes[axis]
                if state.moving:
                    seen_moving.add(axis)
                    still_since[axis] = None
                    done = False
                    continue
                if abs(state.position - end) <= POSITION_TOLERANCE:
                    continue
                done = False
                if axis in seen_moving and state.status_text in FAILED_STATUSES:
                    raise MotionFailed(
                        f"{state.name} stopped at {state.position:.3f} {state.unit}, short of "
                        f"{end:.3f}: {state.status_text}"
                    )
                since = still_since[axis]
                if since is None:
                    still_since[axis] = now
                elif now - since > SETTLE_S and (axis in seen_moving or now - sent_at > 2.0):
                    reason = model.block_reason or state.status_text
                    raise MotionFailed(
                        f"{state.name} stands at {state.position:.3f} {state.unit}, not at "
                        f"{end:.3f}: {reason}"
                    )
            return done

        targets = ", ".join(f"{model.axes[a].name} {e:.3f}" for a, e in ends.items())
        yield Wait(arrived, timeout or self._machine.timeout, f"moving to {targets}")

    def jog(
        self, direction: str | Mapping[str, int], seconds: float
    ) -> Operation[dict[str, float]]:
        session = self.session()
        vector = [0] * len(self._machine.axes)
        items = _parse_direction(direction) if isinstance(direction, str) else direction.items()
        for name, sign in items:
            vector[self._machine.axis_index(name)] = max(-1, min(1, int(sign)))
        if not any(vector):
            raise MotionRefused(f"no direction in {direction!r}")
        if not math.isfinite(seconds) or seconds < 0:
            raise MotionRefused(f"{seconds} s is not a jog's length")
        clock = self.station.clock
        with self._machine.explained() as heard:
            session.set_jog(vector)
        if session.jog_vector != tuple(vector):
            raise MotionRefused("; ".join(heard) or "jog refused")
        end = clock.now() + seconds
        fed = [clock.now()]

        def held() -> bool:
            self._machine.check_link()
            now = clock.now()
            if now - fed[0] >= JOG_KEEPALIVE_S:
                fed[0] = now
                session.keep_jogging()
            return now >= end

        try:
            yield Wait(held, seconds + 5.0, "jogging")
        finally:
            if self.station.session is session:
                session.set_jog([0] * len(vector))
        yield from self._still(5.0, "the jog to end")
        return self._machine.position

    def _still(self, timeout: float, what: str) -> Operation[None]:
        clock = self.station.clock
        since: list[float | None] = [None]

        def still() -> bool:
            self._machine.check_link()
            session = self.station.session
            if session is not None:
                _raise_alarm(session, self._machine.messages)
            if session is None or not session.motion_stopped() or _busy(session):
                since[0] = None
                return False
            started = since[0]
            if started is None:
                since[0] = clock.now()
                return False
            return clock.now() - started >= SETTLE_S

        yield Wait(still, timeout, what)

    def home(self, axis_name: str | None, timeout: float | None) -> Operation[dict[str, float]]:
        session = self.session()
        axis = 0 if axis_name is None else self._machine.axis_index(axis_name)
        with self._machine.explained() as heard:
            sent = session.home(axis)
        if not sent:
            raise (Unsupported if any("has no" in h for h in heard) else MotionRefused)(
                "; ".join(heard) or "homing refused"
            )
        clock = self.station.clock
        sent_at = clock.now()
        seen: list[bool] = [False]
        model = self.station.model

        def started() -> bool:
            self._machine.check_link()
            if model.any_moving or any(a.status_text == "homing" for a in model.axes):
                seen[0] = True
            return seen[0] or clock.now() - sent_at > 2.0

        yield Wait(started, timeout or self._machine.timeout, "homing to start")
        yield from self._still(timeout or self._machine.timeout, "homing")
        failed = [a for a in model.axes if a.status_text in ("end switch hit", "driver fault")]
        if failed and failed[0].status_text == "driver fault":
            raise MotionFailed(f"homing: {failed[0].name} {failed[0].status_text}")
        return self._machine.position

    def stop(self) -> Operation[bool]:
        session = self.session()
        session.stop_all()
        clock = self.station.clock
        deadline = clock.now() + STOP_CONFIRM_S * 2

        def confirmed() -> bool:
            return session.motion_stopped() or clock.now() > deadline

        yield Wait(confirmed, STOP_CONFIRM_S * 3, "the stop", motion=False)
        return session.motion_stopped()

    def sleep(self, asleep: bool, timeout: float) -> Operation[None]:
        session = self.session()
        with self._machine.explained() as heard:
            session.set_sleep(asleep)
        if any("has no" in h for h in heard):
            raise Unsupported("; ".join(heard))
        model = self.station.model
        yield Wait(lambda: model.sleeping == asleep, timeout, "sleep" if asleep else "waking")

    def read_parameters(self, timeout: float) -> Operation[dict[str, dict[str, float]]]:
        yield from params.read_all(self._machine, timeout)
        return params.values_of(self.station.model)

    def write_parameters(
        self, values: Mapping[str, Mapping[str, float]], timeout: float, *, remember: bool = True
    ) -> Operation[dict[str, dict[str, float]]]:
        before = params.values_of(self.station.model)
        written: dict[str, dict[str, float]] = {}
        try:
            written = yield from params.write(self._machine, values, timeout)
        except ParameterRefused as refused:
            written = refused.written  # the writes that went through can be undone too
            raise
        finally:
            if remember and written:
                self.undo = {
                    axis: {n: before[axis][n] for n in names if n in before.get(axis, {})}
                    for axis, names in written.items()
                }
        return written

    def await_close(self) -> Operation[None]:
        station = self.station
        yield Wait(
            lambda: not station.stopping_to_close,
            STOP_CONFIRM_S * 3,
            "the stop before closing",
            motion=False,
        )


def _busy(session: MachineSession) -> bool:
    """Whether commands the session sent (or queued) are still being carried out."""
    if isinstance(session, DrillSession):
        return session.busy
    if isinstance(session, GcodeSession):
        return not session.settled
    return False


def _raise_alarm(session: MachineSession, messages: list[str]) -> None:
    """A G-code board in alarm has stopped whatever it was doing: say so with its words."""
    if isinstance(session, GcodeSession) and session.machine_state.startswith("Alarm"):
        said = f": {messages[-1]}" if messages else ""
        raise MotionFailed(f"the machine is in alarm{said}")


def _has_absolute(session: MachineSession) -> bool:
    """Whether the dialect carries absolute moves (the usb3 unit only moves by distances)."""
    return type(session).move_absolute is not MachineSession.move_absolute


def _parse_direction(text: str) -> list[tuple[str, int]]:
    """``"+X"``, ``"x-"``, ``"+X -Y"``: axis names with their signs (no sign: +)."""
    found = re.findall(r"([+-]?)\s*([A-Za-z][A-Za-z0-9]*)\s*([+-]?)", text)
    rest = re.sub(r"[+-]?\s*[A-Za-z][A-Za-z0-9]*\s*[+-]?", "", text).strip()
    if not found or rest:
        raise MotionRefused(f"{text!r} is not a direction (try '+X' or '-Y')")
    return [(name, -1 if "-" in before + after else 1) for before, name, after in found]
