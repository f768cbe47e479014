"""Held arrows on a G-code board: short moves kept a little ahead of the machine.

A board with ``$J=`` gets jog lines, which leave its modal state as it was,
and the jog-cancel byte on release; any other gets absolute ``G90 G1``
steps, and a release holds it and drops what it has queued (the session's
stop: feed hold, then reset), so it stops within its deceleration.  Neither
leaves the machine in ``G91``.  The next step goes only while the board's
planner holds fewer than :data:`JOG_BLOCKS_AHEAD` blocks (it answers ``ok``
when a line is *planned*, so counting answers alone would let a held key
fill the planner), and never while the steps sent lead where the board says
it is by a step or more.

Runs on the GUI thread only: the session tells it of each jog line's answer
and each status report.
"""

from __future__ import annotations

import math
from typing import Protocol

from PySide6.QtCore import QCoreApplication

from app.link import Link
from app.machine import MachineModel
from app.machines.envelope import Envelope
from app.machines.motion_gate import MotionGate
from protocol.clock import Clock
from protocol.gcode.codec import JOG_CANCEL, StatusReport

#: Each held-arrow step is this much motion, and the next goes only while the device's
#: planner holds fewer than JOG_BLOCKS_AHEAD blocks.
JOG_STEP_S = 0.1
JOG_BLOCKS_AHEAD = 2
#: Fraction of an axis's top speed a held arrow jogs at.
JOG_SPEED_SHARE = 0.5
#: A jog step shorter than this (the travel's end reached) is not sent.
JOG_RESOLUTION = 1e-3
MOVING_STATES = frozenset({"Run", "Jog", "Home"})


def reports_moving(report: StatusReport | None) -> bool:
    """Whether the board's last report shows it moving (running, jogging, homing)."""
    return report is not None and report.state in MOVING_STATES


class JogPort(Protocol):
    """What the jogger uses of its session (the G-code session)."""

    @property
    def model(self) -> MachineModel: ...
    @property
    def gate(self) -> MotionGate: ...
    @property
    def clock(self) -> Clock: ...
    @property
    def link(self) -> Link: ...
    @property
    def envelope(self) -> Envelope: ...
    @property
    def status(self) -> StatusReport | None: ...
    @property
    def planner_size(self) -> int: ...
    @property
    def stopping(self) -> bool: ...
    @property
    def jog_vector(self) -> tuple[int, ...]: ...
    @property
    def jog_speed_share(self) -> float: ...
    def send_line(self, text: str, origin: str) -> bool: ...
    def send_realtime(self, byte: bytes, name: str) -> None: ...
    def query_status(self) -> None: ...
    def stop_all(self, *, keep_jog: bool = False, quiet: bool = False) -> None: ...


class GcodeJogger:
    """The held jog of one G-code session: its steps, their answers, and their end."""

    def __init__(self, session: JogPort, *, with_command: bool) -> None:
        self._session = session
        #: Whether the board takes ``$J=`` jogs (0x85 cancels them).
        self.with_command = with_command
        self._unanswered = 0
        #: Without ``Bf:`` in the reports: when each planned jog step should be done (clock).
        self._ends: list[float] = []
        self._status_fresh = False
        #: Where the steps sent so far take each axis (None: no jog under way).
        self._target: list[float] | None = None
        self._told_end = False
        #: A jog cancel was sent and the board still reports Jog: a new jog waits.
        self.cancelling = False

    def changed(self, previous: tuple[int, ...], wanted: tuple[int, ...]) -> None:
        """The held directions changed from ``previous`` to ``wanted`` (the session's jog)."""
        if any(previous):
            self.end()
        if any(wanted) and not self.cancelling:
            self._step()  # at once: the key must reach the wire now

    def end(self) -> None:
        """The operator let go (or changed direction, or the dead-man ended it): brake now.

        Once a step of this jog went out the board is told, whatever the last
        report said: a report made before the board took the step (late, on a
        busy computer) still says Idle, and the steps planned would run out.
        A jog cancel to a board that stands does nothing.
        """
        session = self._session
        stepped = self._target is not None
        self._target = None
        self._ends = []
        self._told_end = False
        if not session.link.is_open:
            return
        if not (stepped or self._unanswered or reports_moving(session.status)):
            return
        if self.with_command:
            session.send_realtime(JOG_CANCEL, "0x85 (jog cancel)")
            self.cancelling = True
            session.envelope.release()  # stopped short of the steps sent: idle, it is anchored
            session.query_status()
        else:
            session.stop_all(keep_jog=True, quiet=True)

    def forget(self) -> None:
        """No jog under way any more (a stop, a silence, a lost link): nothing is told."""
        self._target = None

    def forget_cancel(self) -> None:
        """The board was lost meanwhile: a cancel under way is not waited for."""
        self._target = None
        self.cancelling = False

    def lines_gone(self) -> None:
        """The board lost every unanswered line (a reset): no jog step is waited for."""
        self._unanswered = 0

    def answered(self, ok: bool) -> None:
        """A jog line was answered (``ok``, or refused)."""
        session = self._session
        self._unanswered = max(0, self._unanswered - 1)
        if ok:
            now = session.clock.now()
            self._ends.append(max([now, *self._ends]) + JOG_STEP_S)
            if not any(session.jog_vector) and self.with_command and session.link.is_open:
                # A step still on its way when the key was let go: GRBL read it after
                # the cancel and runs it as a new jog; cancel that one too.
                session.send_realtime(JOG_CANCEL, "0x85 (jog cancel)")
                self.cancelling = True
                session.query_status()
        if any(session.jog_vector):
            session.query_status()  # its Bf says whether the next step may go
        if not ok:
            self._unanswered = 0

    def reported(self, report: StatusReport) -> None:
        """A status report: a cancelled jog that stands lets a held key jog anew."""
        self._status_fresh = True
        if self.cancelling and report.state != "Jog":
            self.cancelling = False
            self._unanswered = 0

    def feed(self) -> None:
        """Another step when the last is answered and the planner is nearly through."""
        session = self._session
        if not any(session.jog_vector) or self._unanswered or not self._status_fresh:
            return
        if self.cancelling or session.stopping:
            return
        report = session.status
        if report is None:
            return
        if report.planner_free is not None and session.planner_size:
            planned = session.planner_size - report.planner_free
        elif report.state == "Idle":
            planned, self._ends = 0, []
        else:
            # No Bf: (GRBL's default $10=1): the steps are timed, each JOG_STEP_S long.
            now = session.clock.now()
            self._ends = [end for end in self._ends if end > now]
            planned = len(self._ends)
        if planned < JOG_BLOCKS_AHEAD and not self._lead_full():
            self._step()

    def _lead_full(self) -> bool:
        """Whether the steps sent already lead the reported position by a step or more.

        By the board's own reports, not the station's clock: on a busy computer
        (or a board running below real time) the timed estimate lets steps pile
        up in the planner, and a release whose cancel is lost would leave the
        machine to run them all out.  So at most :data:`JOG_BLOCKS_AHEAD` steps
        ever lead where the board says it is.
        """
        target = self._target
        if target is None:
            return False
        model = self._session.model
        for axis, direction in enumerate(self._session.jog_vector):
            if not direction:
                continue
            step = self._speed(axis) * JOG_STEP_S
            lead = (target[axis] - model.axes[axis].position) * direction
            if lead > (JOG_BLOCKS_AHEAD - 1) * step + JOG_RESOLUTION:
                return True
        return False

    def _speed(self, axis: int) -> float:
        """A held jog's speed on ``axis``: a share of its top speed (less, a stick half pushed)."""
        top = self._session.model.profile.axes[axis].max_speed
        return top * JOG_SPEED_SHARE * self._session.jog_speed_share

    def _step(self) -> None:
        """One step of the held jog, ending inside the travel; none once the travel ends."""
        session = self._session
        model = session.model
        if self._target is None:
            self._target = [axis.position for axis in model.axes]
        moves: list[tuple[str, float, float]] = []
        speed = math.inf
        for axis, direction in enumerate(session.jog_vector):
            if not direction:
                continue
            profile = model.profile.axes[axis]
            axis_speed = self._speed(axis)
            here = self._target[axis]
            end = session.gate.clamp(axis, here + direction * axis_speed * JOG_STEP_S)
            if abs(end - here) < JOG_RESOLUTION:
                continue
            self._target[axis] = end
            speed = min(speed, axis_speed)
            moves.append((profile.name, end - here, end))
        if not moves:
            if not self._told_end:
                self._told_end = True
                model.message.emit(
                    QCoreApplication.translate("GcodeSession", "Jog ends: the end of the travel")
                )
            return
        feed = f"F{speed * 60:.0f}"
        if self.with_command:
            words = " ".join(f"{name}{delta:.3f}" for name, delta, _ in moves)
            line = f"$J=G91 G21 {words} {feed}"
        else:
            offsets = {a.name: a.offset for a in model.axes}
            words = " ".join(f"{name}{end - offsets[name]:.3f}" for name, _, end in moves)
            line = f"G90 G1 {words} {feed}"
        if session.send_line(line, "jog"):
            self._unanswered += 1
            self._status_fresh = False
