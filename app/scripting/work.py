"""The API's overrides and work zero on a GRBL board: ``m.override(feed=50)``, ``m.work.zero()``.

The same intents as the window's buttons (:mod:`app.machines.gcode.overrides`,
:mod:`app.machines.gcode.work_zero`), judged by the same gate; each call
returns once the board shows it done (its ``Ov:``, its answer and a report
at rest), and raises with the operator's reason when refused.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TypeVar

from app.machines.gcode.session import GcodeSession
from app.machines.gcode.work_zero import WorkZero
from app.scripting.errors import LinkLost, MotionFailed, MotionRefused, Unsupported
from app.scripting.waits import MachinePort, Operation, Wait

T = TypeVar("T")

#: Seconds the board has to show an override or a work-zero change.
ANSWER_S = 10.0


def _session(machine: MachinePort) -> GcodeSession:
    machine.check_link()
    session = machine.station.session_as(GcodeSession)
    if session is None:
        raise Unsupported(f"{machine.profile.title} has no overrides or work systems")
    return session


def _refusal(heard: list[str], what: str) -> Exception:
    text = "; ".join(heard) or f"{what} refused"
    return (Unsupported if any("has no" in h for h in heard) else MotionRefused)(text)


def override(
    machine: MachinePort, feed: int | None, rapid: int | None
) -> Operation[tuple[int, int]]:
    """Ask for the overrides, then wait until the board reports them (``Ov:``)."""
    session = _session(machine)
    control = session.overrides
    with machine.explained() as heard:
        sent = control.set(feed, rapid)
    if not sent:
        raise _refusal(heard, "override")

    def reported() -> bool:
        machine.check_link()
        if control.wanted is not None:
            return False
        now = control.reported
        asked = (feed, rapid)
        if now is None or any(
            a is not None and a != v for a, v in zip(asked, (now.feed, now.rapid), strict=True)
        ):
            raise MotionFailed("the board did not take the override")
        return True

    yield Wait(reported, ANSWER_S, "the override to show in Ov:", motion=False)
    now = control.reported
    assert now is not None
    return now.feed, now.rapid


def _done(machine: MachinePort, session: GcodeSession, errors: int, what: str) -> Operation[None]:
    """Wait for the answer and a report at rest; an ``error:n`` raises."""

    def settled() -> bool:
        machine.check_link()
        if session.errors > errors:
            raise MotionFailed(f"{what}: the board refused it (see the console's error)")
        return session.settled and session.motion_stopped()

    yield Wait(settled, ANSWER_S, what, motion=False)


class WorkZeroApi:
    """``machine.work``: the GRBL board's work coordinate systems (G54…G59)."""

    def __init__(self, machine: MachinePort, drive: Callable[[Operation[T]], T]) -> None:
        self._machine = machine
        self._drive: Callable[[Operation[object]], object] = drive  # type: ignore[assignment]

    @property
    def system(self) -> str | None:
        """The system in use (``"G54"``); the board is asked (``$G``) while it is not known.

        A board that did not restart as its port opened (a native-USB board, or a banner
        that came before the station listened) has told nothing of it yet; a script
        asking should get the board's answer, not None.
        """
        work = _session(self._machine).work
        if work.system is None and work.available:
            self.read()
        return work.system

    @property
    def offset(self) -> dict[str, float]:
        """The work offset in force (machine minus work position), as the board reported it."""
        session = _session(self._machine)
        offset = session.work.offset or ()
        names = [a.name for a in self._machine.profile.axes]
        return dict(zip(names, offset, strict=False))

    def zero(self, *axes: str) -> dict[str, float]:
        """Make where the tool stands the work zero of ``axes`` (all when none are named)."""
        names = axes or tuple(a.name for a in self._machine.profile.axes)
        self._act(lambda work: work.zero(names), "zeroing")
        return self.offset

    def select(self, system: str) -> dict[str, float]:
        """Work in ``system`` (``"G55"``) from now on; returns its offset."""
        self._act(lambda work: work.select(system.upper()), f"selecting {system}")
        return self.offset

    def go_to_zero(self, *, timeout: float = 60.0) -> dict[str, float]:
        """Lift the pen and travel to the work zero; returns the machine position reached."""
        self._act(lambda work: work.go_to_zero(), "the travel to the work zero", timeout)
        return {a.name: a.position for a in self._machine.station.model.axes}

    def read(self) -> dict[str, tuple[float, ...]]:
        """Ask the board (``$G``, ``$#``); every stored system's offset, by name."""
        self._act(lambda work: work.read(), "reading the work systems")
        return dict(_session(self._machine).work.stored)

    def _act(
        self,
        action: Callable[[WorkZero], bool],
        what: str,
        timeout: float = ANSWER_S,
    ) -> None:
        machine = self._machine
        session = _session(machine)
        errors = session.errors
        with machine.explained() as heard:
            sent = action(session.work)
        if not sent:
            if session.link is None or not session.link.is_open:
                raise LinkLost("not connected")
            raise _refusal(heard, what)
        operation = _done(machine, session, errors, what)
        self._drive(_with_timeout(operation, timeout))


def _with_timeout(operation: Operation[None], timeout: float) -> Operation[None]:
    for wait in operation:
        wait.timeout = timeout
        yield wait
