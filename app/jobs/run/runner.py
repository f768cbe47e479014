"""Runs a program on the connected machine, one operation at a time, so it can be trusted.

Trust here means: no operation is done twice and none is skipped, whatever
happens to the link or to the station.  Three rules give that:

* An operation counts as done only when the machine *reports* it done, never
  when it was sent.
* After every completed operation a checkpoint (the index of the last
  completed one) is written to disk atomically, *before* the next operation is
  sent.  A crash can therefore lose at most the in-flight operation, and the
  checkpoint always names it as not done.
* An operation that was in flight when the link went (or the station died) is
  re-examined before anything is sent again.

The runner holds what every machine shares: job states, the operator's
commands, progress, the ETA and the checkpoint.  What "sent", "done" and
"in flight" mean on the wire is each dialect's own, so the runner hands the
running itself to the dialect's :class:`~app.jobs.run.driver.JobDriver`
(:mod:`app.jobs.run.drivers` says which) and knows no dialect itself.
"""

from __future__ import annotations

import contextlib
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.jobs.estimate import Estimate
from app.jobs.program import LimitViolation, Program, check_limits
from app.jobs.registration import Placement
from app.jobs.run.checkpoint_keeper import CheckpointKeeper
from app.jobs.run.driver import LINK_DOWN, JobDriver, ResumeChoice, UnsupportedOperation
from app.jobs.run.drivers import driver_for
from app.jobs.run.progress import WAITING_SHOWN_S, JobProgress, estimate_inputs
from app.jobs.run.states import ACTIVE, CLOCK_RUNS, FINISHED, JobState
from app.jobs.texts import number
from app.machines.session import MachineSession
from app.machines.supervision import MotionFault
from app.station import Station

__all__ = ["JobRunner", "JobState", "ResumeChoice", "UnsupportedOperation"]

#: Refused operations listed in the message (the dock's list holds them all).
REFUSALS_SHOWN = 20
#: How far from 0 (mm or degrees) a job that counts from its start may start.
START_TOLERANCE = 0.01


@dataclass(frozen=True)
class LoadCheck:
    """What :meth:`JobRunner.load` works out for a program before accepting it.

    Made by :meth:`JobRunner.checker`'s function, which any thread may run: a
    2-million-entry string-art job takes seconds to check, estimate and hash,
    and the dock's loading thread does it, so the GUI thread only takes the result.
    """

    program: Program
    refused: list[LimitViolation]
    estimate: Estimate | None
    fingerprint: str


class JobRunner(QObject):
    stateChanged = Signal(object)  # JobState
    progressChanged = Signal(int, int)  # done, total
    #: Operations the machine reported as run, and the total.  Equal to ``done`` where one
    #: operation is sent at a time; behind it on G-code, whose planner holds answered lines.
    executedChanged = Signal(int, int)
    etaChanged = Signal(float, float)  # elapsed_s, remaining_s
    operationStarted = Signal(int)
    operationDone = Signal(int)
    waitingForOperator = Signal(str)
    #: Only the operator can tell whether an operation ran: question, "again" and "done" labels.
    decisionNeeded = Signal(str, str, str)
    #: Only the operator can say where an interrupted job goes on: a ResumeChoice.
    resumeChoiceNeeded = Signal(object)
    message = Signal(str)
    programChanged = Signal()

    def __init__(
        self, station: Station, checkpoint_dir: Path, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self._station = station
        self.checkpoint_dir = Path(checkpoint_dir)
        self._checkpoints = CheckpointKeeper(self.checkpoint_dir, self.message.emit)
        self._state = JobState.IDLE
        self._program: Program | None = None
        self._progress = JobProgress(
            station,
            self._total,
            self.progressChanged,
            self.executedChanged,
            self.etaChanged,
            self.operationDone,
            self,
        )
        self._single_step = False
        self._pause_requested = False
        self._question: int | None = None  # the operation the operator is asked about
        self._choice: ResumeChoice | None = None  # where to go on, for the operator to pick
        #: Paused until the operator acts (an alarm, a board that restarted): nothing resumes
        #: it on its own (the scripting API ends the job instead).
        self._operator_hold = False
        #: Paused because the link went, and nothing else has happened to the job since.
        self._paused_by_link = False
        self._failing = False  # a checkpoint write failed and the job is being failed
        self._session: object = None
        # A station keeps its profile, so its dialect and driver, for life.
        self._driver: JobDriver = driver_for(station.profile.dialect)(self)
        station.sessionChanged.connect(self._bind_session)
        station.model.linkStateChanged.connect(self._on_link_state)
        self._bind_session()

    # --- what the dock (and the driver) reads ------------------------------------

    @property
    def station(self) -> Station:
        return self._station

    @property
    def state(self) -> JobState:
        return self._state

    @property
    def program(self) -> Program | None:
        return self._program

    @property
    def done(self) -> int:
        """Count of completed operations (always the first ``done`` of the program)."""
        return self._progress.done

    @property
    def executed(self) -> int:
        """Count of operations the machine reported as run (≤ ``done``).

        On a G-code machine ``done`` counts the lines the device answered, many of
        which may still wait in its planner; ``executed`` only those known to have run.
        """
        return self._progress.executed

    @property
    def single_step(self) -> bool:
        """Whether the run stops after the operation under way (Step)."""
        return self._single_step

    @property
    def estimate(self) -> Estimate | None:
        return self._progress.estimate

    @property
    def current_index(self) -> int | None:
        """The operation under way, or next, while a job is active or stopped short; else None."""
        if self._program is None or self._state in (JobState.IDLE, JobState.READY, JobState.DONE):
            return None
        in_flight = self._driver.in_flight
        if in_flight is not None:
            return in_flight
        done = self._progress.done
        return done if done < len(self._program) else None

    @property
    def question(self) -> int | None:
        """The operation whose fate the operator is asked to decide (see ``decisionNeeded``)."""
        return self._question

    @property
    def resume_choice(self) -> ResumeChoice | None:
        """Where the operator may resume the paused job from, when only they can say."""
        return self._choice

    @property
    def needs_operator(self) -> bool:
        """Paused until the operator acts: a question, a resume line to pick, an alarm."""
        return self._state is JobState.PAUSED and (
            self._question is not None or self._choice is not None or self._operator_hold
        )

    @property
    def resume_available(self) -> int | None:
        """Index to resume from when a checkpoint of this program waits for the operator."""
        return self._checkpoints.resume_available

    @property
    def elapsed_s(self) -> float:
        """Wall-clock time from the run's start to its end (or now), prompts included."""
        return self._progress.elapsed_s

    @property
    def running_s(self) -> float:
        """Of :attr:`elapsed_s`, the time operations were under way: what the estimate
        forecasts."""
        return self._progress.running_s

    @property
    def waiting_s(self) -> float:
        """Of :attr:`elapsed_s`, the time the job stood waiting for the operator
        (at a prompt, paused, or on hold)."""
        return self._progress.waiting_s

    @property
    def remaining_s(self) -> float:
        """The model's time still to go; the estimate's figure, not rescaled by the real one."""
        return self._progress.remaining_s

    # --- loading -------------------------------------------------------------

    def checker(self) -> Callable[[Program], LoadCheck]:
        """The load's checks as a function of the program alone, for another thread.

        What they need from the station (the profile, the machine's settings and
        position for the estimate) is read now, on the GUI thread; the function
        touches nothing of the runner or the station.
        """
        profile = self.station.profile
        # A job's coordinates are work coordinates (GRBL adds its G92 offset to them): the
        # travel, in machine coordinates, is checked shifted by the offset the machine has.
        offsets = {axis.name: axis.offset for axis in self.station.model.axes}
        limits = {
            name: (low - offsets.get(name, 0.0), high - offsets.get(name, 0.0))
            for name, (low, high) in profile.travel_limits().items()
        }
        refusals = self._driver.refusals
        timing = estimate_inputs(self.station)

        def check(program: Program) -> LoadCheck:
            refused: list[LimitViolation] = check_limits(program, limits)
            refused += refusals(program)
            # In file order, as the operator reads the file.
            refused.sort(key=lambda v: (v.operation.source.line, v.index))
            if refused:  # neither timed nor hashed: it will not run
                return LoadCheck(program, refused, None, "")
            return LoadCheck(program, refused, timing(program), program.fingerprint())

        return check

    def load(
        self,
        program: Program,
        placed: tuple[Program, Placement] | None = None,
        checked: LoadCheck | None = None,
    ) -> list[LimitViolation]:
        """Accept ``program`` unless some operation leaves the travel or the machine cannot do it.

        A refused program changes nothing that was loaded before except that
        it is unloaded: the operator sees the list of offending lines.
        ``placed``: the job as its file says and how ``program`` was put on the
        board from it (mirrored, registered), kept with the checkpoint.
        ``checked``: the checks already made for ``program`` (:meth:`checker`).
        """
        if self._state in ACTIVE:
            self.message.emit(
                QCoreApplication.translate(
                    "JobRunner", "Stop the running job before loading another"
                )
            )
            return []
        if checked is None or checked.program is not program:
            checked = self.checker()(program)
        refused = checked.refused
        self._reset()
        if refused:
            self._program = None
            self._progress.estimate = None
            lines = "\n".join(f"  {v}" for v in refused[:REFUSALS_SHOWN])
            if len(refused) > REFUSALS_SHOWN:
                lines += f"\n  … and {len(refused) - REFUSALS_SHOWN} more"
            count = len({v.index for v in refused})
            self.message.emit(
                QCoreApplication.translate(
                    "JobRunner", "Job {0} refused, {1} operation(s) cannot be run:\n{2}"
                ).format(repr(program.name), count, lines)
            )
            self._set_state(JobState.IDLE)
            self.programChanged.emit()
            return refused
        self._program = program
        self._checkpoints.loaded(program, checked.fingerprint, placed)
        self._progress.estimate = checked.estimate
        resume = self._checkpoints.resume_available
        self.programChanged.emit()
        self._set_state(JobState.READY)
        self._progress.tell_all()
        self.emit_eta()
        if resume is not None:
            op = program[resume]
            self.message.emit(
                QCoreApplication.translate(
                    "JobRunner",
                    "Job {0} was interrupted: {1} of {2} operations done; "
                    "resume from {3} or discard the checkpoint",
                ).format(repr(program.name), resume, len(program), op.source)
            )
        return []

    # --- operator commands ---------------------------------------------------

    def start(self) -> None:
        """Run from the first operation (READY, or again after a job ended)."""
        if self._program is None or self._state not in (JobState.READY, *FINISHED):
            return
        if self._checkpoints.resume_available is not None:
            self.message.emit(
                QCoreApplication.translate(
                    "JobRunner", "Resume from the checkpoint or discard it first"
                )
            )
            return
        if self._refuse_start_position(self._program):
            return
        self._begin(0, single_step=False, verify=False)

    def pause(self) -> None:
        """Let the operation under way finish, then stop before the next one."""
        driver = self._driver
        if self._state is JobState.RUNNING:
            driver.hold_back()  # what is not yet on the wire waits for the resume
            if driver.in_flight is None:
                self._set_state(JobState.PAUSED)
            else:
                self._pause_requested = True
                self._set_state(JobState.PAUSING)
        elif self._state is JobState.WAITING:
            self._set_state(JobState.PAUSED)

    def resume(self) -> None:
        """Carry on after a pause or a lost link; an interrupted operation is re-examined first."""
        if self._state is JobState.PAUSING:
            self._pause_requested = False
            self._set_state(JobState.RUNNING)
        elif self._state is JobState.PAUSED:
            if self._question is not None:
                self.message.emit(
                    QCoreApplication.translate(
                        "JobRunner", "Answer the question about the interrupted operation first"
                    )
                )
                return
            if self._choice is not None:
                self.message.emit(
                    QCoreApplication.translate("JobRunner", "Choose the line to resume from first")
                )
                return
            self._operator_hold = False
            self._continue(single_step=False)

    def resume_at(self, index: int) -> None:
        """The operator's pick of where the paused job goes on (one of the choice's candidates)."""
        choice = self._choice
        if choice is None or self._state is not JobState.PAUSED or index not in choice.candidates:
            return
        if self._refuse_for_link():
            return
        self._choice = None
        self._operator_hold = False
        self._single_step = False
        self._pause_requested = False
        self._set_state(JobState.RUNNING)
        self._driver.resume_at(index)

    def give_up(self) -> None:
        """End a job paused for the operator as failed, when nobody is there to act (a script).

        The machine stands (paused), so nothing is stopped; the checkpoint stays and
        what was said about the pause is the reason.
        """
        if not self.needs_operator:
            return
        self._end_keeping_checkpoint(JobState.FAILED)

    def _end_keeping_checkpoint(self, state: JobState) -> None:
        """The job ends with nothing more asked of the operator; its checkpoint stays."""
        self._driver.stopped()
        self._driver.forget()
        self._question = None
        self._choice = None
        self._operator_hold = False
        # The resume offer first, so views reacting to the state change see it.
        self._checkpoints.offer(self._program)
        self._set_state(state)

    def decide(self, *, again: bool) -> None:
        """The operator's answer: send the operation in question again, or count it as done."""
        index = self._question
        if index is None or self._state is not JobState.PAUSED or self._refuse_for_link():
            return
        self._question = None
        self._single_step = False
        self._pause_requested = False
        self._set_state(JobState.RUNNING)
        self._driver.decided(index, again=again)

    def step(self) -> None:
        """Run exactly one operation, then pause."""
        if self._state is JobState.READY:
            if self._checkpoints.resume_available is not None:
                self.message.emit(
                    QCoreApplication.translate(
                        "JobRunner", "Resume from the checkpoint or discard it first"
                    )
                )
                return
            self._begin(0, single_step=True, verify=False)
        elif self._state is JobState.PAUSED and self._question is None and self._choice is None:
            self._operator_hold = False
            self._continue(single_step=True)

    def abort(self) -> None:
        """Stop the machine now; the checkpoint stays, so the job can be resumed later."""
        if self._state not in ACTIVE:
            return
        session = self.station.session
        if session is not None:
            session.stop_all()
        self._end_keeping_checkpoint(JobState.ABORTED)
        # The count the checkpoint (and the resume offer) holds: what the machine ran.
        self.message.emit(
            QCoreApplication.translate(
                "JobRunner", "Job aborted after {0} of {1} operations"
            ).format(self._progress.executed, self._total())
        )

    def confirm(self) -> None:
        """The operator has done what the WAIT asked for."""
        driver = self._driver
        if self._state is not JobState.WAITING or driver.in_flight is None:
            return
        index = driver.in_flight
        driver.confirmed(index)
        self._set_state(JobState.RUNNING)
        self.complete(index)

    def resume_from_checkpoint(self) -> None:
        """Carry on an interrupted job where its checkpoint says, re-examining that operation."""
        if self._program is None or self._checkpoints.resume_available is None:
            return
        if self._state not in (JobState.READY, *FINISHED):
            return
        index = self._checkpoints.take_resume(self._program)
        assert index is not None
        try:
            self._begin(index, single_step=False, verify=True)
        finally:
            self._checkpoints.sent = None

    def checkpoint_placement(self, base: Program) -> Placement | None:
        """How an interrupted run of ``base`` (as read from its file) was put on the board."""
        return self._checkpoints.placement_for(base)

    def discard_checkpoint(self) -> None:
        """Forget the interrupted run: the next start begins at the first operation."""
        if self._program is None:
            return
        if not self._checkpoints.discard(self._program, "The checkpoint could not be removed: {0}"):
            return
        if self._state in FINISHED:
            self._set_state(JobState.READY)
        self.message.emit(
            QCoreApplication.translate(
                "JobRunner", "Checkpoint discarded; the job starts from the beginning"
            )
        )

    def emit_eta(self) -> None:
        """Tell the dock elapsed and remaining time (a timer calls this every second)."""
        self._progress.emit_eta()

    # --- what a driver tells the runner (RunnerPort) ---------------------------------

    def announce(self, index: int) -> None:
        self.operationStarted.emit(index)

    def note(self, text: str) -> None:
        self.message.emit(text)

    def mark_done(self, index: int) -> bool:
        """Operations up to ``index`` are done; whether the next one starts now."""
        assert self._program is not None
        self._progress.reached(index)  # reported done by the machine: it ran
        if not self._write_checkpoint(self._program, index):  # before anything else is sent
            return False
        self._progress.tell_reached(index)
        return self._carry_on()

    def complete(self, index: int) -> None:
        if self.mark_done(index):
            self._driver.proceed()

    def advance(self, done: int, executed: int | None = None) -> None:
        """A streaming driver's progress, kept at once and told to the views coalesced
        (:class:`~app.jobs.run.progress.JobProgress`)."""
        if self._program is not None:
            self._progress.advance(done, executed)

    def record(self, completed: int, sent: int | None = None) -> None:
        if self._program is not None and self._state in ACTIVE:
            self._write_checkpoint(self._program, completed, sent)

    @property
    def checkpoint_sent(self) -> int | None:
        return self._checkpoints.sent

    def fail(self, index: int, reason: str) -> None:
        if self._state not in ACTIVE:
            return  # already ended (a failure while failing, say the checkpoint's)
        session = self.station.session
        if session is not None and self.station.model.link_state not in LINK_DOWN:
            session.stop_all()
        self._driver.stopped()
        self._choice = None
        self._operator_hold = False
        self._checkpoints.offer(self._program)
        self._set_state(JobState.FAILED)
        self.message.emit(
            QCoreApplication.translate("JobRunner", "Job failed at {0}: {1}").format(
                self._op_source(index), reason
            )
        )

    def link_pause(self) -> None:
        """The link is gone: hold the operation under way as not done, to re-examine later."""
        self._driver.link_lost()
        in_flight = self._driver.in_flight
        self._pause_requested = False
        self._set_state(JobState.PAUSED)
        self._paused_by_link = True
        state = self.station.model.link_state.value
        if in_flight is not None:
            text = QCoreApplication.translate(
                "JobRunner", "Job paused at {0}: link {1}; resume once the machine is back"
            )
            self.message.emit(text.format(self._op_source(in_flight), state))
        else:
            text = QCoreApplication.translate(
                "JobRunner", "Job paused: link {0}; resume once the machine is back"
            )
            self.message.emit(text.format(state))

    def stop_short(self, text: str) -> None:
        self._set_state(JobState.PAUSED)
        self.message.emit(text)

    def hold_for_operator(self, text: str) -> None:
        self._operator_hold = True
        self._pause_requested = False
        self._set_state(JobState.PAUSED)
        self.message.emit(text)

    def choose_resume(self, choice: ResumeChoice) -> None:
        self._choice = choice
        self._operator_hold = False
        self._pause_requested = False
        self._set_state(JobState.PAUSED)
        self.message.emit(choice.text)
        self.resumeChoiceNeeded.emit(choice)

    def pause_reached(self) -> None:
        self._single_step = False
        self._pause_requested = False
        self._set_state(JobState.PAUSED)

    def wait_for_operator(self, index: int) -> None:
        assert self._program is not None
        self._set_state(JobState.WAITING)
        self.waitingForOperator.emit(self._program[index].message)

    def ask(self, index: int, question: str, again: str, done: str) -> None:
        self._question = index
        self._set_state(JobState.PAUSED)
        self.message.emit(question)
        self.decisionNeeded.emit(question, again, done)

    def finish(self) -> None:
        assert self._program is not None
        self._checkpoints.discard(
            self._program, "The finished job's checkpoint could not be removed: {0}"
        )
        self._progress.set_executed(
            len(self._program)
        )  # drivers finish only once the machine is idle
        self._set_state(JobState.DONE)
        self.emit_eta()
        done = QCoreApplication.translate("JobRunner", "Job {0} done: {1} operations in {2} s")
        done = done.format(
            repr(self._program.name), len(self._program), number(self.elapsed_s, ".1f")
        )
        if self.waiting_s >= WAITING_SHOWN_S:
            done += QCoreApplication.translate("JobRunner", ", of which {0} s waiting for you")
            done = done.format(number(self.waiting_s, ".1f"))
        self.message.emit(done)

    # --- running -------------------------------------------------------------

    def _begin(self, index: int, *, single_step: bool, verify: bool) -> None:
        assert self._program is not None
        driver = self._driver
        if self._refuse_for_link():
            return
        self._progress.restart(index)
        self._single_step = single_step
        self._pause_requested = False
        self._choice = None
        self._operator_hold = False
        driver.begin(index, verify=verify)
        self._progress.tell_done()
        self._set_state(JobState.RUNNING)
        driver.proceed()

    def _continue(self, *, single_step: bool) -> None:
        if self._refuse_for_link():
            return
        self._single_step = single_step
        self._pause_requested = False
        self._set_state(JobState.RUNNING)
        self._driver.proceed()

    def _refuse_start_position(self, program: Program) -> bool:
        """A job that moves relative to where it starts was checked from 0: it starts only there.

        Its travel check (and its preview) took the start as the origin; run from
        anywhere else it would be drawn shifted, past the travel perhaps.
        """
        model = self.station.model
        away = []
        for name in program.start_relative:
            axis = next((i for i, a in enumerate(model.axes) if a.name == name), None)
            if axis is not None and abs(model.axes[axis].work_position) > START_TOLERANCE:
                away.append(name + number(model.axes[axis].work_position, ".3f"))
        if not away:
            return False
        axes = ", ".join(program.start_relative)
        self.message.emit(
            QCoreApplication.translate(
                "JobRunner",
                "Job {0} not started: it moves {1} relative to where the machine stands "
                "(G91 or G92 before any absolute move), and was checked from 0; the machine "
                "is at {2}. Home it or move it to 0 first.",
            ).format(repr(program.name), axes, " ".join(away))
        )
        return True

    def _refuse_for_link(self) -> bool:
        reason = self.station.model.motion_lock_reason()
        if self.station.session is None or self.station.model.link_state in LINK_DOWN:
            reason = reason or QCoreApplication.translate("JobRunner", "not connected")
            self.message.emit(
                QCoreApplication.translate("JobRunner", "Cannot run the job: {0}").format(reason)
            )
            return True
        return False

    def _carry_on(self) -> bool:
        """After an operation: whether the next one starts now (else the job ended or paused)."""
        assert self._program is not None
        if self._progress.done >= len(self._program):
            if self._driver.wind_up():
                self.finish()
            return False
        if self._single_step or self._pause_requested:
            self._pause_requested = False
            self._set_state(JobState.PAUSED)
            return False
        if self._state is not JobState.RUNNING:
            self._set_state(JobState.RUNNING)
        return True

    def _op_source(self, index: int | None) -> str:
        if self._program is None or index is None or not len(self._program):
            return "?"
        # Every operation done, a fault after the last (a report once the job has all been
        # answered) is at the last one: naming it must not crash the station.
        return str(self._program[min(index, len(self._program) - 1)].source)

    def _total(self) -> int:
        return len(self._program) if self._program is not None else 0

    # --- signals from the station -------------------------------------------

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
        self._driver.bind(session)
        if session is not None:
            session.motionFault.connect(self._on_motion_fault)
            session.recovered.connect(self._on_recovered)

    def _on_motion_fault(self, fault: MotionFault) -> None:
        """The session stopped a machine that went where nothing sent it: the job fails there.

        Not a pause: the machine is not where the job's books say, so nothing of
        it may go on by itself; the checkpoint stays for a resume once the
        operator has looked.
        """
        if self._state not in ACTIVE:
            return
        index = fault.op_index if fault.op_index is not None else self.current_index
        self.fail(index if index is not None else self._progress.done, fault.text)

    def _on_recovered(self, problem: object) -> None:
        """The machine answers again after a silence, its port open all along.

        Intact (no restart, every axis where the books allow), the job goes on
        by itself: the resume re-examines what was under way as the operator's
        Resume would, and asks where only the operator can tell.  Otherwise
        it stays paused for the operator, who is told why.
        """
        if not self._paused_by_link or self._state is not JobState.PAUSED:
            return
        if self.needs_operator:
            return  # the operator is asked something already (a question, a line, an alarm)
        if problem is not None:
            self._paused_by_link = False
            self.message.emit(
                QCoreApplication.translate(
                    "JobRunner",
                    "The machine answers again, but {0}: the job stays paused. "
                    "Check the machine, then Resume",
                ).format(problem)
            )
            return
        self.message.emit(
            QCoreApplication.translate(
                "JobRunner", "The machine answers again, its state intact: the job goes on"
            )
        )
        self.resume()

    def _on_link_state(self, state: object) -> None:
        if state in LINK_DOWN and self._state in CLOCK_RUNS:
            self.link_pause()

    # --- state and time ------------------------------------------------------

    def _set_state(self, state: JobState) -> None:
        if state is self._state:
            return
        self._progress.flush()  # the views see the progress the new state comes with
        self._paused_by_link = False  # set again by link_pause, after this
        was_running = self._state in CLOCK_RUNS
        runs = state in CLOCK_RUNS
        self._progress.clock(was_running, runs, state in ACTIVE)
        self._progress.ended = state is JobState.DONE
        self._state = state
        # While a job is under way (paused and waiting included: its resume goes on from
        # where the machine was), a jog would move the machine under it.
        self.station.model.set_jog_lock(
            QCoreApplication.translate(
                "JobRunner", "a job is under way — abort it or let it finish"
            )
            if state in ACTIVE
            else None
        )
        self.stateChanged.emit(state)
        if not runs:
            self.emit_eta()

    def _reset(self) -> None:
        self._progress.restart(0)
        self._question = None
        self._choice = None
        self._operator_hold = False
        self._driver.forget()
        self._checkpoints.resume_available = None
        self._single_step = False
        self._pause_requested = False

    # --- checkpoint ----------------------------------------------------------

    def _write_checkpoint(self, program: Program, completed: int, sent: int | None = None) -> bool:
        """Record progress; a job that cannot record it stops (FAILED) rather than run on.

        Without its checkpoint an interrupted job could only be run again from the
        start, repeating every operation done so far: better to stop while the
        operator can still see where it stands.
        """
        try:
            self._checkpoints.write(program, completed, sent)
        except OSError as exc:
            if self._state in ACTIVE and not self._failing:
                self._failing = True
                try:
                    self.fail(
                        min(completed + 1, len(program) - 1),
                        f"the checkpoint could not be written to {self.checkpoint_dir} ({exc})",
                    )
                finally:
                    self._failing = False
            return False
        return True
