"""``stepdeck.connect(...)``: one machine, driven by blocking calls with timeouts.

A :class:`Machine` owns a :class:`~app.station.Station` (the same object the
window uses) and calls its session's intents: ``move_to`` is the Absolute
panel's Go, ``jog`` a held arrow key, ``stop`` the STOP button.  Every
motion is judged by the session's motion gate before anything is sent, and
a refusal, a device's complaint or a lost link is raised as an exception
carrying the reason the operator would have read (:mod:`app.scripting.errors`).

The Qt side runs in the caller's thread, while a call waits
(:mod:`app.scripting.pump` says why); a Machine must therefore be used from
the thread that made it.  The asyncio form (:mod:`app.scripting.aio`) runs
the same operations, awaiting between pumps.
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

from app.machine import LinkState
from app.machines.drill.session import DrillSession
from app.machines.gcode.session import GcodeSession
from app.machines.session import MachineSession
from app.machines.usb3.session import Usb3Session
from app.profiles import MachineProfile, ProfileError, load_profile
from app.scripting import parameters as params
from app.scripting.errors import (
    ConnectionFailed,
    LinkLost,
    MotionFailed,
    MotionRefused,
    MotionTimeout,
    ParameterRefused,
    StepdeckError,
    Unsupported,
)
from app.scripting.job import JobResult, run_job
from app.scripting.pump import Pump, RealtimePump, SimulatedPump, ensure_qt
from app.scripting.waits import Operation, Wait
from app.station import STOP_CONFIRM_S, Station
from protocol.clock import ManualClock

T = TypeVar("T")

#: Seconds a blocking call waits by default (a move, a parameter read).
DEFAULT_TIMEOUT_S = 60.0
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
#: The device's messages a refusal or failure is explained with.
MESSAGES_KEPT = 20

LINK_DOWN = (LinkState.DISCONNECTED, LinkState.LOST)


@dataclass(frozen=True)
class AxisStatus:
    name: str
    position: float
    unit: str
    moving: bool
    status: str


@dataclass(frozen=True)
class Status:
    """What the station knows about the machine right now (the info panel's content)."""

    link: str
    link_detail: str
    #: Why motion is locked (not connected, sleeping, a block), or None when it is allowed.
    locked: str | None
    axes: tuple[AxisStatus, ...]

    @property
    def moving(self) -> bool:
        return any(a.moving for a in self.axes)


class Machine:
    """A connected machine; see the module docstring.  Build it with :func:`connect`."""

    def __init__(self, station: Station, pump: Pump, *, timeout: float = DEFAULT_TIMEOUT_S) -> None:
        self.station = station
        self.timeout = timeout
        self._pump = pump
        self._messages: list[str] = []
        self._heard_count = 0
        self._undo: dict[str, dict[str, float]] | None = None
        station.model.message.connect(self._heard)

    # --- state --------------------------------------------------------------------

    @property
    def profile(self) -> MachineProfile:
        return self.station.profile

    @property
    def axes(self) -> tuple[str, ...]:
        return tuple(axis.name for axis in self.station.model.axes)

    @property
    def position(self) -> dict[str, float]:
        """Where each axis stands, as the device last reported it (mm, or ° on a rotary axis)."""
        return {axis.name: axis.position for axis in self.station.model.axes}

    @property
    def status(self) -> Status:
        model = self.station.model
        return Status(
            link=model.link_state.value,
            link_detail=model.link_detail,
            locked=model.motion_lock_reason(),
            axes=tuple(
                AxisStatus(a.name, a.position, a.unit, a.moving, a.status_text) for a in model.axes
            ),
        )

    @property
    def messages(self) -> list[str]:
        """The station's latest news (what the status bar showed), newest last."""
        return list(self._messages)

    # --- motion -------------------------------------------------------------------

    def move_to(
        self,
        target: Mapping[str, float] | None = None,
        *,
        timeout: float | None = None,
        **axes: float,
    ) -> dict[str, float]:
        """Move to absolute positions (``move_to(X=10, Y=5)``); returns where the axes ended.

        Every target is judged by the motion gate before any axis is sent, so a
        refused move moves nothing.  Machines without absolute moves (the usb3
        unit) are sent the distance from where they stand.
        """
        return self._drive(self._move(dict(target or {}, **axes), False, timeout))

    def move_by(
        self,
        delta: Mapping[str, float] | None = None,
        *,
        timeout: float | None = None,
        **axes: float,
    ) -> dict[str, float]:
        """Move by distances from where the axes stand (``move_by(X=-1.5)``)."""
        return self._drive(self._move(dict(delta or {}, **axes), True, timeout))

    def jog(self, direction: str | Mapping[str, int], seconds: float) -> dict[str, float]:
        """Jog as a held key would (``jog("+X", 0.5)``), then release and wait until still.

        A jog is never refused at the travel's end: the session ends it just
        inside, as it does for the keyboard.
        """
        return self._drive(self._jog(direction, seconds))

    def home(self, axis: str | None = None, *, timeout: float | None = None) -> dict[str, float]:
        """Home ``axis`` (the first one when None; some machines home every axis at once)."""
        return self._drive(self._home(axis, timeout))

    def stop(self) -> bool:
        """Stop every axis now; True when the device confirmed every axis still."""
        return self._drive(self._stop())

    def sleep(self, asleep: bool = True, *, timeout: float = 5.0) -> None:
        """Put the machine's drivers to sleep (or wake them: ``sleep(False)``)."""
        self._drive(self._sleep(asleep, timeout))

    def wake(self, *, timeout: float = 5.0) -> None:
        self._drive(self._sleep(False, timeout))

    # --- parameters ---------------------------------------------------------------

    def read_parameters(self, *, timeout: float = 10.0) -> dict[str, dict[str, float]]:
        """Every stored parameter of every axis, freshly read (``{"X": {"fast_speed": 10.0}}``).

        Values are in the units the Dynamics page shows (mm, mm/s, mm/s², counts).
        """
        return self._drive(self._read_parameters(timeout))

    def write_parameters(
        self, values: Mapping[str, Mapping[str, float]], *, timeout: float = 10.0
    ) -> dict[str, dict[str, float]]:
        """Write parameters, each verified by the device's answer; returns what was written.

        Raises :class:`~app.scripting.errors.ParameterRefused` naming every
        refusal (the station's or the device's, with the value it keeps) after
        trying all of them.  :meth:`undo_last_write` puts back what was there.
        """
        return self._drive(self._write_parameters(values, timeout))

    def undo_last_write(self, *, timeout: float = 10.0) -> dict[str, dict[str, float]]:
        """Write back the values the last :meth:`write_parameters` replaced."""
        if not self._undo:
            raise StepdeckError("no parameter write to undo")
        previous, self._undo = self._undo, None
        result = self._drive(self._write_parameters(previous, timeout, remember=False))
        return result

    def save_parameters(self, path: str | Path, *, timeout: float = 10.0) -> Path:
        """Save every stored parameter to a TOML snapshot (machine, firmware, date)."""
        values = self.read_parameters(timeout=timeout)
        self._drive(params.read_firmware(self, timeout))
        return params.save_snapshot(Path(path), self.station, values)

    def parameter_diff(
        self, path: str | Path, *, other_machine: bool = False, timeout: float = 10.0
    ) -> list[params.Difference]:
        """What loading a snapshot would change: the parameters that differ from the device."""
        snapshot = params.load_snapshot(Path(path))
        params.check_machine(snapshot, self.station.profile, other_machine=other_machine)
        return params.diff(snapshot, self.read_parameters(timeout=timeout))

    def load_parameters(
        self, path: str | Path, *, other_machine: bool = False, timeout: float = 10.0
    ) -> list[params.Difference]:
        """Write what differs between a snapshot and the device, each write verified.

        Another machine's snapshot is refused unless ``other_machine=True``.
        Returns the differences written; refusals raise ParameterRefused after
        every write was tried.  :meth:`undo_last_write` reverts it.
        """
        differences = self.parameter_diff(path, other_machine=other_machine, timeout=timeout)
        changes: dict[str, dict[str, float]] = {}
        for difference in differences:
            if difference.writable:
                changes.setdefault(difference.axis, {})[difference.name] = difference.wanted
        if changes:
            self.write_parameters(changes, timeout=timeout)
        return [d for d in differences if d.writable]

    # --- jobs ---------------------------------------------------------------------

    def run(self, job_path: str | Path, **options: Any) -> JobResult:
        """Run a job file to its end; see :func:`app.scripting.job.run_job` for the options."""
        return self._drive(run_job(self, Path(job_path), **options))

    # --- the end ------------------------------------------------------------------

    def close(self) -> None:
        """Stop the machine (waiting for the device to confirm it), then close the link."""
        station = self.station
        if station.link is not None and not station.stop_and_close():
            self._drive(self._await_close())
        station.shutdown()
        station.model.message.disconnect(self._heard)
        self._pump.close()

    def __enter__(self) -> Machine:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # --- running operations -------------------------------------------------------

    def _drive(self, operation: Operation[T]) -> T:
        """Run an operation to its end, pumping the station while it waits."""
        clock = self.station.clock
        try:
            wait = next(operation)
            while True:
                deadline = clock.now() + wait.timeout
                while not wait.until():
                    if clock.now() > deadline:
                        operation.close()
                        raise self._timed_out(wait)
                    self._pump.step()
                wait = operation.send(None)
        except StopIteration as stop:
            value: T = stop.value
            return value
        except KeyboardInterrupt:
            operation.close()  # a running job aborts (checkpoint kept) before the stop is awaited
            self._stop_after_interrupt()
            raise

    def _timed_out(self, wait: Wait) -> Exception:
        if wait.on_timeout is not None:
            return wait.on_timeout()
        if wait.motion:
            self._stop_quietly()
            return MotionTimeout(f"{wait.what}: not done within {wait.timeout:g} s; stopped")
        return StepdeckError(f"{wait.what}: no answer within {wait.timeout:g} s")

    def _stop_quietly(self) -> None:
        session = self.station.session
        if session is not None and self.station.model.link_state not in LINK_DOWN:
            session.stop_all()

    def _stop_after_interrupt(self) -> None:
        """Ctrl+C: stop every axis and give the device a moment to confirm it."""
        self._stop_quietly()
        session = self.station.session
        deadline = self.station.clock.now() + STOP_CONFIRM_S
        while session is not None and not session.motion_stopped():
            if self.station.clock.now() > deadline:
                break
            self._pump.step()

    # --- the operations (generators of waits) --------------------------------------

    def _heard(self, text: str) -> None:
        self._heard_count += 1
        self._messages.append(text)
        del self._messages[:-MESSAGES_KEPT]

    @contextmanager
    def explained(self) -> Iterator[list[str]]:
        """The station's messages while an intent is given: the reason when it is refused."""
        start = self._heard_count
        heard: list[str] = []
        yield heard
        new = self._heard_count - start
        if new:
            heard.extend(self._messages[-new:])

    def _session(self) -> MachineSession:
        session = self.station.session
        if session is None or self.station.model.link_state in LINK_DOWN:
            detail = self.station.model.link_detail
            raise LinkLost(f"not connected{f': {detail}' if detail else ''}")
        return session

    def axis_index(self, name: str) -> int:
        names = [n.upper() for n in self.axes]
        try:
            return names.index(name.upper())
        except ValueError:
            raise MotionRefused(
                f"{self.profile.title} has no axis {name!r} (it has {', '.join(self.axes)})"
            ) from None

    def check_link(self) -> None:
        model = self.station.model
        if model.link_state in LINK_DOWN:
            raise LinkLost(f"link {model.link_state.value}: {model.link_detail}")

    def _move(
        self, wanted: dict[str, float], relative: bool, timeout: float | None
    ) -> Operation[dict[str, float]]:
        session = self._session()
        lock = self.station.model.motion_lock_reason()
        if lock is not None:
            raise MotionRefused(f"Motion refused: {lock}")
        gate = session.gate
        plan: list[tuple[int, float]] = []
        for name, value in wanted.items():
            axis = self.axis_index(name)
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
            with self.explained() as heard:
                if relative or not _has_absolute(session):
                    sent = session.move_relative(axis, delta)
                else:
                    sent = session.move_absolute(axis, here + delta)
            if not sent:
                self._stop_quietly()
                raise MotionRefused("; ".join(heard) or f"{self.axes[axis]} move refused")
            if isinstance(session, Usb3Session):
                ends[axis] = here + session.reachable(axis, delta)
            elif isinstance(session, DrillSession):  # whole microsteps, 19.7 to the mm
                ends[axis] = session.to_mm(axis, session.to_microsteps(axis, here + delta))
            else:
                ends[axis] = here + delta
        yield from self._settle(ends, timeout)
        return self.position

    def _settle(self, ends: dict[int, float], timeout: float | None) -> Operation[None]:
        """Wait until every axis stands at its end; raise when one stopped short."""
        model = self.station.model
        clock = self.station.clock
        sent_at = clock.now()
        still_since: dict[int, float | None] = dict.fromkeys(ends)
        seen_moving: set[int] = set()

        def arrived() -> bool:
            self.check_link()
            session = self._session()
            _raise_alarm(session, self._messages)
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
        yield Wait(arrived, timeout or self.timeout, f"moving to {targets}")

    def _jog(
        self, direction: str | Mapping[str, int], seconds: float
    ) -> Operation[dict[str, float]]:
        session = self._session()
        vector = [0] * len(self.axes)
        items = _parse_direction(direction) if isinstance(direction, str) else direction.items()
        for name, sign in items:
            vector[self.axis_index(name)] = max(-1, min(1, int(sign)))
        if not any(vector):
            raise MotionRefused(f"no direction in {direction!r}")
        if not math.isfinite(seconds) or seconds < 0:
            raise MotionRefused(f"{seconds} s is not a jog's length")
        clock = self.station.clock
        with self.explained() as heard:
            session.set_jog(vector)
        if session.jog_vector != tuple(vector):
            raise MotionRefused("; ".join(heard) or "jog refused")
        end = clock.now() + seconds
        fed = [clock.now()]

        def held() -> bool:
            self.check_link()
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
        return self.position

    def _still(self, timeout: float, what: str) -> Operation[None]:
        clock = self.station.clock
        since: list[float | None] = [None]

        def still() -> bool:
            self.check_link()
            session = self.station.session
            if session is not None:
                _raise_alarm(session, self._messages)
            if session is None or not session.motion_stopped() or _busy(session):
                since[0] = None
                return False
            started = since[0]
            if started is None:
                since[0] = clock.now()
                return False
            return clock.now() - started >= SETTLE_S

        yield Wait(still, timeout, what)

    def _home(self, axis_name: str | None, timeout: float | None) -> Operation[dict[str, float]]:
        session = self._session()
        axis = 0 if axis_name is None else self.axis_index(axis_name)
        with self.explained() as heard:
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
            self.check_link()
            if model.any_moving or any(a.status_text == "homing" for a in model.axes):
                seen[0] = True
            return seen[0] or clock.now() - sent_at > 2.0

        yield Wait(started, timeout or self.timeout, "homing to start")
        yield from self._still(timeout or self.timeout, "homing")
        failed = [a for a in model.axes if a.status_text in ("end switch hit", "driver fault")]
        if failed and failed[0].status_text == "driver fault":
            raise MotionFailed(f"homing: {failed[0].name} {failed[0].status_text}")
        return self.position

    def _stop(self) -> Operation[bool]:
        session = self._session()
        session.stop_all()
        clock = self.station.clock
        deadline = clock.now() + STOP_CONFIRM_S * 2

        def confirmed() -> bool:
            return session.motion_stopped() or clock.now() > deadline

        yield Wait(confirmed, STOP_CONFIRM_S * 3, "the stop", motion=False)
        return session.motion_stopped()

    def _sleep(self, asleep: bool, timeout: float) -> Operation[None]:
        session = self._session()
        with self.explained() as heard:
            session.set_sleep(asleep)
        if any("has no" in h for h in heard):
            raise Unsupported("; ".join(heard))
        model = self.station.model
        yield Wait(lambda: model.sleeping == asleep, timeout, "sleep" if asleep else "waking")

    def _read_parameters(self, timeout: float) -> Operation[dict[str, dict[str, float]]]:
        yield from params.read_all(self, timeout)
        return params.values_of(self.station.model)

    def _write_parameters(
        self, values: Mapping[str, Mapping[str, float]], timeout: float, *, remember: bool = True
    ) -> Operation[dict[str, dict[str, float]]]:
        before = params.values_of(self.station.model)
        written: dict[str, dict[str, float]] = {}
        try:
            written = yield from params.write(self, values, timeout)
        except ParameterRefused as refused:
            written = refused.written  # the writes that went through can be undone too
            raise
        finally:
            if remember and written:
                self._undo = {
                    axis: {n: before[axis][n] for n in names if n in before.get(axis, {})}
                    for axis, names in written.items()
                }
        return written

    def _await_close(self) -> Operation[None]:
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


def connect(
    profile: str | MachineProfile,
    *,
    port: str | None = None,
    ble: str | bool | None = None,
    emulator: bool = False,
    baud: int | None = None,
    simulated: bool = False,
    timeout: float = 10.0,
) -> Machine:
    """Connect to a machine and wait until it answers; one of ``port``, ``ble``, ``emulator``.

    ``ble=True`` connects to the strongest stage found, ``ble="AA:BB:…"`` to
    that one.  ``emulator=True`` runs the built-in emulator in real time;
    with ``simulated=True`` on a simulated clock instead, as fast as the
    computer goes (a rehearsal, and the tests' way).
    """
    chosen = [port is not None, ble not in (None, False), emulator]
    if sum(chosen) != 1:
        raise ConnectionFailed("name exactly one link: port=..., ble=... or emulator=True")
    if simulated and not emulator:
        raise ConnectionFailed("simulated=True needs emulator=True: real devices run in real time")
    try:
        machine_profile = profile if isinstance(profile, MachineProfile) else load_profile(profile)
    except ProfileError as exc:
        raise ConnectionFailed(str(exc)) from None
    ensure_qt()
    pump: Pump
    if simulated:
        clock = ManualClock()
        station = Station(machine_profile, clock, realtime=False)
        pump = SimulatedPump(station, clock)
    else:
        station = Station(machine_profile)
        pump = RealtimePump()
    machine = Machine(station, pump)
    try:
        if emulator:
            station.connect_emulator()
        elif port is not None:
            station.connect_serial(port, baud)
        else:
            station.connect_ble(ble if isinstance(ble, str) and ble else None)
        machine._drive(_await_answer(station, timeout))  # noqa: SLF001 - its own module
    except BaseException:
        station.shutdown()
        raise
    return machine


def _await_answer(station: Station, timeout: float) -> Operation[None]:
    def answered() -> bool:
        session = station.session
        return (
            session is not None
            and session.device_answered
            and station.model.link_state is LinkState.CONNECTED
        )

    def failed() -> StepdeckError:
        detail = station.model.link_detail or "no answer"
        return ConnectionFailed(f"{station.model.profile.title}: {detail}")

    yield Wait(answered, timeout, "connecting", motion=False, on_timeout=failed)
