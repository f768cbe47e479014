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

from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

from app.machine import LinkState
from app.profiles import MachineProfile, ProfileError, load_profile
from app.scripting.errors import (
    ConnectionFailed,
    LinkLost,
    MotionRefused,
    StepdeckError,
)
from app.scripting.job import JobResult, run_job
from app.scripting.machine_parameters import StageParameterCalls
from app.scripting.macros import macro_table, run_macro
from app.scripting.operations import LINK_DOWN as LINK_DOWN
from app.scripting.operations import Operations
from app.scripting.pump import Pump, RealtimePump, SimulatedPump, ensure_qt
from app.scripting.settings import MachineSettings
from app.scripting.waits import Operation, Wait
from app.scripting.work import WorkZeroApi, override
from app.station import Station
from protocol.clock import ManualClock

T = TypeVar("T")

#: Seconds a blocking call waits by default (a move, a parameter read).
DEFAULT_TIMEOUT_S = 60.0
#: The device's messages a refusal or failure is explained with.
MESSAGES_KEPT = 20


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


class Machine(StageParameterCalls):
    """A connected machine; see the module docstring.  Build it with :func:`connect`."""

    def __init__(self, station: Station, pump: Pump, *, timeout: float = DEFAULT_TIMEOUT_S) -> None:
        self.station = station
        self.timeout = timeout
        self._pump = pump
        self._messages: list[str] = []
        self._heard_count = 0
        #: The operations (generators of waits) this machine and its asyncio form drive.
        self.operations = Operations(self, pump)
        #: A GRBL board's work coordinate systems: ``m.work.zero()``, ``m.work.go_to_zero()``.
        self.work = WorkZeroApi(self, self._drive)
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
        return self._drive(self.operations.move(dict(target or {}, **axes), False, timeout))

    def move_by(
        self,
        delta: Mapping[str, float] | None = None,
        *,
        timeout: float | None = None,
        **axes: float,
    ) -> dict[str, float]:
        """Move by distances from where the axes stand (``move_by(X=-1.5)``)."""
        return self._drive(self.operations.move(dict(delta or {}, **axes), True, timeout))

    def jog(self, direction: str | Mapping[str, int], seconds: float) -> dict[str, float]:
        """Jog as a held key would (``jog("+X", 0.5)``), then release and wait until still.

        A jog is never refused at the travel's end: the session ends it just
        inside, as it does for the keyboard.
        """
        return self._drive(self.operations.jog(direction, seconds))

    def home(self, axis: str | None = None, *, timeout: float | None = None) -> dict[str, float]:
        """Home ``axis`` (the first one when None; some machines home every axis at once)."""
        return self._drive(self.operations.home(axis, timeout))

    def stop(self) -> bool:
        """Stop every axis now; True when the device confirmed every axis still."""
        return self._drive(self.operations.stop())

    def sleep(self, asleep: bool = True, *, timeout: float = 5.0) -> None:
        """Put the machine's drivers to sleep (or wake them: ``sleep(False)``)."""
        self._drive(self.operations.sleep(asleep, timeout))

    def wake(self, *, timeout: float = 5.0) -> None:
        self._drive(self.operations.sleep(False, timeout))

    def override(self, *, feed: int | None = None, rapid: int | None = None) -> tuple[int, int]:
        """GRBL's feed (10…200 %) and rapid (25, 50, 100 %) overrides, while a job runs too.

        Returns (feed, rapid) once the board reports them in ``Ov:``; Unsupported
        on a firmware without overrides, MotionRefused for a percentage it cannot take.
        """
        return self._drive(override(self, feed, rapid))

    # --- stored settings ----------------------------------------------------------

    def settings(self, *, timeout: float = 10.0) -> MachineSettings:
        """The device's stored settings (GRBL's ``$$``, the usb3 unit's EEPROM), freshly read.

        The object it returns writes, saves, diffs and restores them
        (:class:`~app.scripting.settings.MachineSettings`).
        """
        stored = MachineSettings(self, self._drive, timeout)
        stored.read()
        return stored

    # --- jobs ---------------------------------------------------------------------

    def run(self, job_path: str | Path, **options: Any) -> JobResult:
        """Run a job file to its end; see :func:`app.scripting.job.run_job` for the options."""
        return self._drive(run_job(self, Path(job_path), **options))

    # --- macros -------------------------------------------------------------------

    def macros(self, *, settings: str | Path | None = None) -> dict[str, str]:
        """The macros the window keeps for this profile, name → G-code (``settings``: an
        INI settings file instead of the station's own)."""
        return macro_table(self.profile.name, settings)

    def run_macro(
        self,
        name: str,
        *,
        code: str | None = None,
        settings: str | Path | None = None,
        **options: Any,
    ) -> JobResult:
        """Run a kept macro (or ``code`` under ``name``) from where the machine stands, as a
        job; refused (JobRefused, ``macro "Name":line: reason``) before a byte is sent.
        ``options``: :func:`app.scripting.job.run_job`'s callbacks."""
        return self._drive(run_macro(self, name, code=code, settings=settings, options=options))

    # --- the end ------------------------------------------------------------------

    def close(self) -> None:
        """Stop the machine (waiting for the device to confirm it), then close the link."""
        station = self.station
        if station.link is not None and not station.stop_and_close():
            self._drive(self.operations.await_close())
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
                        raise self.operations.timed_out(wait)
                    self._pump.step()
                wait = operation.send(None)
        except StopIteration as stop:
            value: T = stop.value
            return value
        except KeyboardInterrupt:
            operation.close()  # a running job aborts (checkpoint kept) before the stop is awaited
            self.operations.stop_after_interrupt()
            raise

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
