"""What the runner and a dialect's job driver say to each other.

The runner (:mod:`app.jobs.run.runner`) knows job states, operator commands,
progress, the ETA and the checkpoint, and nothing of any dialect.  A driver
knows one dialect and owns four things for it:

* sending the next operation (or, for a streaming dialect, as many as the
  device may hold);
* judging completion from the device's replies;
* what "in flight" means after the link went: which operation may or may
  not have run;
* how to resume: re-examine that operation and send it again only when the
  machine shows it was not done.

A driver talks back only through :class:`RunnerPort`, so the runner's
private state never leaks into it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar, Protocol

from PySide6.QtCore import QCoreApplication

from app.jobs.program import LimitViolation, Operation, OpKind, Program, SourceRef
from app.jobs.run.states import JobState
from app.machine import LinkState
from app.machines.session import MachineSession
from app.profiles import MachineProfile
from app.station import Station


def unsupported_on(op: Operation, profile: MachineProfile) -> str:
    """Why ``op`` failed on this machine, for the job's messages."""
    return QCoreApplication.translate("JobRunner", "{0} is not supported on {1}").format(
        op.describe(), profile.shown_title
    )


def capability_refusals(
    program: Program, profile: MachineProfile, *, takes_gcode: bool
) -> list[LimitViolation]:
    """Operations ``profile``'s machine cannot do at all (no link needed: ``stepdeck check``)."""
    capabilities = profile.capabilities
    problems: dict[OpKind, str] = {}
    if not capabilities.drill:
        problems[OpKind.DRILL] = QCoreApplication.translate("JobRunner", "{0} cannot drill").format(
            profile.shown_title
        )
    elif takes_gcode:
        # The winder drills with its own program's Z moves: G-code has no drill cycle, so a
        # drill file would load and fail at its first hole.  Refused here, line by line.
        problems[OpKind.DRILL] = QCoreApplication.translate(
            "JobRunner", "{0} drills only with explicit moves: G-code has no drill cycle"
        ).format(profile.shown_title)
    if not capabilities.pen:
        problems[OpKind.PEN_DOWN] = problems[OpKind.PEN_UP] = QCoreApplication.translate(
            "JobRunner", "{0} has no pen"
        ).format(profile.shown_title)
    if not takes_gcode:
        problems[OpKind.GCODE] = QCoreApplication.translate(
            "JobRunner", "{0} does not take G-code"
        ).format(profile.shown_title)
    refused: list[LimitViolation] = []
    for kind in sorted(program.kinds() & problems.keys(), key=lambda k: k.value):
        for index in program.indices_of(kind):
            op = program[int(index)]
            refused.append(UnsupportedOperation.of(int(index), op, problems[kind]))
    name = program.source.name if program.source is not None else program.name
    for problem in program.unexecutable_lines():
        op = Operation(OpKind.GCODE, SourceRef(name, problem.line), line=problem.text)
        refused.append(UnsupportedOperation.of(problem.line, op, problem.reason))
    return refused


#: Link states in which nothing can be sent.
LINK_DOWN = (LinkState.LOST, LinkState.DISCONNECTED, LinkState.CONNECTING)


@dataclass(frozen=True)
class UnsupportedOperation(LimitViolation):
    """An operation the machine cannot do at all (a drill cycle on a stage): refused like a limit.

    A subclass so that :meth:`JobRunner.load` returns one list the dock can
    show line by line, whatever the reason for each refusal.
    """

    reason: str = ""

    @classmethod
    def of(cls, index: int, operation: Operation, reason: str) -> UnsupportedOperation:
        return cls(index, operation, "", math.nan, math.nan, math.nan, reason)

    def __str__(self) -> str:
        return f"{self.operation.source}: {self.operation.describe()} — {self.reason}"


@dataclass(frozen=True)
class ResumeChoice:
    """Where an interrupted job may go on, when only the operator can say.

    Operations before ``first`` are proven run (answered ``ok`` by a board
    that answers once a line ran, or shown run by its reports); from
    ``first`` to ``last - 1`` they were sent and may or may not have run.
    Resuming at ``first`` sends them all again (a stroke may be drawn twice),
    at ``last`` counts them all as run (one may be missing); the operator,
    looking at the paper, picks.  ``default`` is offered only where nothing
    that could draw is among them.  ``position_lost``: the board restarted, so
    its position must be homed or checked before anything moves.
    """

    first: int
    last: int
    default: int | None
    text: str
    position_lost: bool = False

    @property
    def candidates(self) -> range:
        return range(self.first, self.last + 1)


class RunnerPort(Protocol):
    """The runner as a driver sees it."""

    @property
    def station(self) -> Station: ...

    @property
    def program(self) -> Program | None: ...

    @property
    def state(self) -> JobState: ...

    @property
    def done(self) -> int: ...

    @property
    def single_step(self) -> bool: ...

    def announce(self, index: int) -> None:
        """Operation ``index`` is now under way (the dock highlights it)."""

    def note(self, text: str) -> None:
        """One line for the operator."""

    def mark_done(self, index: int) -> bool:
        """Operations up to ``index`` are done (checkpointed); whether the job goes on now."""

    def complete(self, index: int) -> None:
        """``mark_done``, then the driver's next ``proceed`` if the job goes on."""

    def advance(self, done: int, executed: int | None = None) -> None:
        """A streaming driver's progress: the first ``done`` operations are answered, the
        first ``executed`` (default: ``done``) known to have run."""

    def record(self, completed: int, sent: int | None = None) -> None:
        """Checkpoint operations ``[0, completed]`` as run (a streaming driver's own pace),
        and ``[0, sent)`` as perhaps sent."""

    @property
    def checkpoint_sent(self) -> int | None:
        """For a run resumed from its checkpoint: how far the interrupted run may have sent."""

    def fail(self, index: int, reason: str) -> None: ...

    def link_pause(self) -> None:
        """The link is gone: pause, holding the operation under way for re-examination."""

    def stop_short(self, text: str) -> None:
        """The machine stopped an operation short (the operator's Esc): pause with ``text``."""

    def pause_reached(self) -> None:
        """Nothing of the job is under way any more: a requested pause (or step) takes hold."""

    def wait_for_operator(self, index: int) -> None: ...

    def ask(self, index: int, question: str, again: str, done: str) -> None:
        """Only the operator can tell whether operation ``index`` ran: pause and ask.

        ``again`` and ``done`` name the two answers (send it again / count it
        as done); the runner passes the answer to :meth:`JobDriver.decided`.
        """

    def choose_resume(self, choice: ResumeChoice) -> None:
        """Proof of what ran is partial (or the board lost its position): pause, and let the
        operator pick the operation to go on from (the runner passes it to
        :meth:`JobDriver.resume_at`)."""

    def hold_for_operator(self, text: str) -> None:
        """Pause with ``text`` until the operator acts (an alarm): never resumed on its own."""

    def finish(self) -> None: ...


class JobDriver:
    """One dialect's way of running a program's operations on its session."""

    #: Whether G-code lines (``OpKind.GCODE``) can be sent as they are.
    takes_gcode: ClassVar[bool] = False

    def __init__(self, runner: RunnerPort) -> None:
        self.runner = runner

    @property
    def station(self) -> Station:
        return self.runner.station

    @property
    def in_flight(self) -> int | None:
        """The operation under way: sent, or held for re-examination, and not yet done."""
        return None

    # --- loading --------------------------------------------------------------

    def refusals(self, program: Program) -> list[LimitViolation]:
        """Operations this machine cannot do at all; scans only when such a kind is used."""
        return capability_refusals(program, self.station.profile, takes_gcode=self.takes_gcode)

    # --- the runner's requests -----------------------------------------------

    def bind(self, session: MachineSession | None) -> None:
        """Listen to this session's replies (None: no link)."""

    def begin(self, index: int, *, verify: bool) -> None:
        """A run starts at ``index``; ``verify``: it may have been under way before."""

    def start_refusal(self, index: int) -> str | None:
        """Why the job cannot start at operation ``index`` the operator chose (None: it can).

        Here every operation goes to absolute places by itself, except a drill
        cycle, which drills where the tool stands: it starts with its hole's move.
        """
        program = self.runner.program
        if program is not None and program[index].kind is OpKind.DRILL:
            return QCoreApplication.translate(
                "JobRunner",
                "{0}: a drill cycle drills where the tool stands; start at op {1}, "
                "the move to its hole",
            ).format(program[index].source, index)
        return None

    def start_at(self, index: int) -> None:
        """A run starts at the operator's chosen ``index`` (:meth:`start_refusal` said yes)."""
        self.begin(index, verify=False)

    def proceed(self) -> None:
        """Send what may be sent now; end, wait or pause when the program says so."""

    def wind_up(self) -> bool:
        """The last operation is done: True when the job may end now.

        A machine that has more to do after a job (the drill parks) starts it
        here, returns False and calls :meth:`RunnerPort.finish` itself once it
        is done.
        """
        return True

    def hold_back(self) -> None:
        """A pause was asked for: take back what is queued but not yet on the wire."""

    def confirmed(self, index: int) -> None:
        """The operator confirmed the WAIT at ``index``; the runner completes it next."""

    def stopped(self) -> None:
        """The job failed or was aborted and the machine was stopped."""

    def forget(self) -> None:
        """Nothing is under way any more (aborted): drop what was held."""

    def decided(self, index: int, *, again: bool) -> None:
        """The operator's answer to :meth:`RunnerPort.ask`: send ``index`` again, or count it."""

    def resume_at(self, index: int) -> None:
        """The operator's pick after :meth:`RunnerPort.choose_resume`: go on from ``index``."""

    def link_lost(self) -> None:
        """The link went: whatever was under way may or may not have run."""

    def link_up(self) -> bool:
        return self.station.model.link_state not in LINK_DOWN
