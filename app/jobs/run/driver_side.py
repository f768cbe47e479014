"""The runner as its driver and its machine see it: what they tell the job, from below.

The runner's own surface is the operator's (load, start, pause, resume,
step, abort, answer).  What a dialect's driver reports (an operation under
way, done, failed, a pause reached, a question only the operator can answer)
and what the station's session says of the machine (a motion fault, the link
gone, an answer again after a silence) arrive here instead, at
:class:`DriverSide`, the :class:`~app.jobs.run.driver.RunnerPort` the driver
holds.  The checkpoint is scheduled here too: written when the machine
reports an operation done, before the driver may send the next.

Both halves change one job: its state (through the runner's state change,
handed over at construction) and :class:`RunFlags`, what the operator asked
of the run and what a paused job waits on.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from dataclasses import dataclass
from typing import Protocol

from PySide6.QtCore import QCoreApplication, QObject, SignalInstance

from app.jobs.program import Program
from app.jobs.run.checkpoint_keeper import CheckpointKeeper
from app.jobs.run.driver import LINK_DOWN, JobDriver, ResumeChoice
from app.jobs.run.drivers import driver_for
from app.jobs.run.progress import WAITING_SHOWN_S, JobProgress
from app.jobs.run.states import ACTIVE, CLOCK_RUNS, JobState
from app.jobs.texts import number
from app.machines.session import MachineSession
from app.machines.supervision import MotionFault
from app.station import Station


class OperatorSide(Protocol):
    """The runner as its driver side sees it: what the job is, and the signals it tells with."""

    @property
    def station(self) -> Station: ...

    @property
    def program(self) -> Program | None: ...

    @property
    def state(self) -> JobState: ...

    @property
    def current_index(self) -> int | None: ...

    @property
    def needs_operator(self) -> bool: ...

    def resume(self) -> None:
        """The operator's Resume: the machine answers again, intact."""

    @property
    def message(self) -> SignalInstance: ...

    @property
    def operationStarted(self) -> SignalInstance: ...

    @property
    def waitingForOperator(self) -> SignalInstance: ...

    @property
    def decisionNeeded(self) -> SignalInstance: ...

    @property
    def resumeChoiceNeeded(self) -> SignalInstance: ...


@dataclass
class RunFlags:
    """What the operator asked of the run, and what a paused job waits on.

    Written by the runner's commands and by :class:`DriverSide` alike, read by
    both: one object, so neither reaches into the other.
    """

    #: The run stops after the operation under way (Step).
    single_step: bool = False
    #: A pause was asked for while an operation was under way (PAUSING).
    pause_requested: bool = False
    #: The operation the operator is asked about.
    question: int | None = None
    #: Where to go on, for the operator to pick.
    choice: ResumeChoice | None = None
    #: Paused until the operator acts (an alarm, a board that restarted): nothing resumes
    #: it on its own (the scripting API ends the job instead).
    operator_hold: bool = False
    #: Paused because the link went, and nothing else has happened to the job since.
    paused_by_link: bool = False

    def clear(self) -> None:
        """A job loaded: nothing asked, nothing waited on."""
        self.single_step = self.pause_requested = False
        self.question = self.choice = None
        self.operator_hold = self.paused_by_link = False


class DriverSide(QObject):
    """The job's lower half: its driver's reports, the session's events, the checkpoint.

    A child of the runner (``parent``), so the station's signals stop reaching it with the
    runner.
    """

    def __init__(
        self,
        runner: OperatorSide,
        flags: RunFlags,
        progress: JobProgress,
        checkpoints: CheckpointKeeper,
        set_state: Callable[[JobState], None],
        parent: QObject,
    ) -> None:
        super().__init__(parent)
        self._runner = runner
        self._flags = flags
        self._progress = progress
        self._checkpoints = checkpoints
        self._set_state = set_state
        self._failing = False  # a checkpoint write failed and the job is being failed
        self._session: object = None
        # A station keeps its profile, so its dialect and driver, for life.
        self.driver: JobDriver = driver_for(runner.station.profile.dialect)(self)
        runner.station.sessionChanged.connect(self._bind_session)
        runner.station.model.linkStateChanged.connect(self._on_link_state)
        self._bind_session()

    # --- what the driver reads -------------------------------------------------------

    @property
    def station(self) -> Station:
        return self._runner.station

    @property
    def program(self) -> Program | None:
        return self._runner.program

    @property
    def state(self) -> JobState:
        return self._runner.state

    @property
    def done(self) -> int:
        return self._progress.done

    @property
    def single_step(self) -> bool:
        """Whether the run stops after the operation under way (Step)."""
        return self._flags.single_step

    @property
    def checkpoint_sent(self) -> int | None:
        return self._checkpoints.sent

    # --- what a driver tells the runner (RunnerPort) ---------------------------------

    def announce(self, index: int) -> None:
        self._runner.operationStarted.emit(index)

    def note(self, text: str) -> None:
        self._runner.message.emit(text)

    def mark_done(self, index: int) -> bool:
        """Operations up to ``index`` are done; whether the next one starts now."""
        program = self._runner.program
        assert program is not None
        self._progress.reached(index)  # reported done by the machine: it ran
        if not self._write_checkpoint(program, index):  # before anything else is sent
            return False
        self._progress.tell_reached(index)
        return self._carry_on()

    def complete(self, index: int) -> None:
        if self.mark_done(index):
            self.driver.proceed()

    def advance(self, done: int, executed: int | None = None) -> None:
        """A streaming driver's progress, kept at once and told to the views coalesced
        (:class:`~app.jobs.run.progress.JobProgress`)."""
        if self._runner.program is not None:
            self._progress.advance(done, executed)

    def record(self, completed: int, sent: int | None = None) -> None:
        program = self._runner.program
        if program is not None and self._runner.state in ACTIVE:
            self._write_checkpoint(program, completed, sent)

    def fail(self, index: int, reason: str) -> None:
        runner = self._runner
        if runner.state not in ACTIVE:
            return  # already ended (a failure while failing, say the checkpoint's)
        session = self.station.session
        if session is not None and self.station.model.link_state not in LINK_DOWN:
            session.stop_all()
        self.driver.stopped()
        self._flags.choice = None
        self._flags.operator_hold = False
        self._checkpoints.offer(runner.program)
        self._set_state(JobState.FAILED)
        runner.message.emit(
            QCoreApplication.translate("JobRunner", "Job failed at {0}: {1}").format(
                self._op_source(index), reason
            )
        )

    def link_pause(self) -> None:
        """The link is gone: hold the operation under way as not done, to re-examine later."""
        self.driver.link_lost()
        in_flight = self.driver.in_flight
        self._flags.pause_requested = False
        self._set_state(JobState.PAUSED)
        self._flags.paused_by_link = True
        state = self.station.model.link_state.value
        if in_flight is not None:
            text = QCoreApplication.translate(
                "JobRunner", "Job paused at {0}: link {1}; resume once the machine is back"
            )
            self._runner.message.emit(text.format(self._op_source(in_flight), state))
        else:
            text = QCoreApplication.translate(
                "JobRunner", "Job paused: link {0}; resume once the machine is back"
            )
            self._runner.message.emit(text.format(state))

    def stop_short(self, text: str) -> None:
        self._set_state(JobState.PAUSED)
        self._runner.message.emit(text)

    def hold_for_operator(self, text: str) -> None:
        self._flags.operator_hold = True
        self._flags.pause_requested = False
        self._set_state(JobState.PAUSED)
        self._runner.message.emit(text)

    def choose_resume(self, choice: ResumeChoice) -> None:
        self._flags.choice = choice
        self._flags.operator_hold = False
        self._flags.pause_requested = False
        self._set_state(JobState.PAUSED)
        self._runner.message.emit(choice.text)
        self._runner.resumeChoiceNeeded.emit(choice)

    def pause_reached(self) -> None:
        self._flags.single_step = False
        self._flags.pause_requested = False
        self._set_state(JobState.PAUSED)

    def wait_for_operator(self, index: int) -> None:
        program = self._runner.program
        assert program is not None
        self._set_state(JobState.WAITING)
        self._runner.waitingForOperator.emit(program[index].message)

    def ask(self, index: int, question: str, again: str, done: str) -> None:
        self._flags.question = index
        self._set_state(JobState.PAUSED)
        self._runner.message.emit(question)
        self._runner.decisionNeeded.emit(question, again, done)

    def finish(self) -> None:
        program = self._runner.program
        assert program is not None
        self._checkpoints.discard(
            program, "The finished job's checkpoint could not be removed: {0}"
        )
        self._progress.set_executed(len(program))  # drivers finish only once the machine is idle
        self._set_state(JobState.DONE)
        self._progress.emit_eta()
        progress = self._progress
        done = QCoreApplication.translate("JobRunner", "Job {0} done: {1} operations in {2} s")
        done = done.format(repr(program.name), len(program), number(progress.elapsed_s, ".1f"))
        if progress.waiting_s >= WAITING_SHOWN_S:
            done += QCoreApplication.translate("JobRunner", ", of which {0} s waiting for you")
            done = done.format(number(progress.waiting_s, ".1f"))
        self._runner.message.emit(done)

    # --- after an operation ----------------------------------------------------------

    def _carry_on(self) -> bool:
        """After an operation: whether the next one starts now (else the job ended or paused)."""
        program = self._runner.program
        assert program is not None
        if self._progress.done >= len(program):
            if self.driver.wind_up():
                self.finish()
            return False
        if self._flags.single_step or self._flags.pause_requested:
            self._flags.pause_requested = False
            self._set_state(JobState.PAUSED)
            return False
        if self._runner.state is not JobState.RUNNING:
            self._set_state(JobState.RUNNING)
        return True

    def _op_source(self, index: int | None) -> str:
        program = self._runner.program
        if program is None or index is None or not len(program):
            return "?"
        # Every operation done, a fault after the last (a report once the job has all been
        # answered) is at the last one: naming it must not crash the station.
        return str(program[min(max(index, 0), len(program) - 1)].source)

    def _write_checkpoint(self, program: Program, completed: int, sent: int | None = None) -> bool:
        """Record progress; a job that cannot record it stops (FAILED) rather than run on.

        Without its checkpoint an interrupted job could only be run again from the
        start, repeating every operation done so far: better to stop while the
        operator can still see where it stands.
        """
        try:
            self._checkpoints.write(program, completed, sent)
        except OSError as exc:
            if self._runner.state in ACTIVE and not self._failing:
                self._failing = True
                try:
                    self.fail(
                        min(completed + 1, len(program) - 1),
                        f"the checkpoint could not be written to {self._checkpoints.directory} "
                        f"({exc})",
                    )
                finally:
                    self._failing = False
            return False
        return True

    # --- signals from the station ----------------------------------------------------

    def _bind_session(self) -> None:
        session = self.station.session
        if session is self._session:
            return
        old = self._session
        if isinstance(old, MachineSession):
            for signal, slot in (
                (old.motionFault, self._on_motion_fault),
                (old.recovered, self._on_recovered),
            ):
                with contextlib.suppress(RuntimeError, TypeError):  # gone with its link already
                    signal.disconnect(slot)
        self._session = session
        self.driver.bind(session)
        if session is not None:
            session.motionFault.connect(self._on_motion_fault)
            session.recovered.connect(self._on_recovered)

    def _on_motion_fault(self, fault: MotionFault) -> None:
        """The session stopped a machine that went where nothing sent it: the job fails there.

        Not a pause: the machine is not where the job's books say, so nothing of
        it may go on by itself; the checkpoint stays for a resume once the
        operator has looked.
        """
        if self._runner.state not in ACTIVE:
            return
        index = fault.op_index if fault.op_index is not None else self._runner.current_index
        self.fail(index if index is not None else self._progress.done, fault.text)

    def _on_recovered(self, problem: object) -> None:
        """The machine answers again after a silence, its port open all along.

        Intact (no restart, every axis where the books allow), the job goes on
        by itself: the resume re-examines what was under way as the operator's
        Resume would, and asks where only the operator can tell.  Otherwise
        it stays paused for the operator, who is told why.
        """
        runner = self._runner
        if not self._flags.paused_by_link or runner.state is not JobState.PAUSED:
            return
        if runner.needs_operator:
            return  # the operator is asked something already (a question, a line, an alarm)
        if problem is not None:
            self._flags.paused_by_link = False
            runner.message.emit(
                QCoreApplication.translate(
                    "JobRunner",
                    "The machine answers again, but {0}: the job stays paused. "
                    "Check the machine, then Resume",
                ).format(problem)
            )
            return
        runner.message.emit(
            QCoreApplication.translate(
                "JobRunner", "The machine answers again, its state intact: the job goes on"
            )
        )
        runner.resume()

    def _on_link_state(self, state: object) -> None:
        if state in LINK_DOWN and self._runner.state in CLOCK_RUNS:
            self.link_pause()
