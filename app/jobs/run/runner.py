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

Its public surface is the operator's.  The driver talks back to
:class:`~app.jobs.run.driver_side.DriverSide`, which also hears the
session's events and schedules the checkpoint; the counts and the clock are
:attr:`JobRunner.progress` (:class:`~app.jobs.run.progress.JobProgress`).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.jobs.estimate import Estimate
from app.jobs.program import LimitViolation, Program, check_limits
from app.jobs.registration import Placement
from app.jobs.run.checkpoint_keeper import CheckpointKeeper
from app.jobs.run.driver import LINK_DOWN, JobDriver, ResumeChoice, UnsupportedOperation
from app.jobs.run.driver_side import DriverSide, RunFlags
from app.jobs.run.progress import JobProgress, estimate_inputs
from app.jobs.run.states import ACTIVE, CLOCK_RUNS, FINISHED, JobState
from app.jobs.texts import number
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


def job_busy_text() -> str:
    return QCoreApplication.translate("JobRunner", "a job is under way — abort it or let it finish")


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
        #: The station the job runs on (its profile, so its dialect, is kept for life).
        self.station = station
        self.checkpoint_dir = Path(checkpoint_dir)
        self._checkpoints = CheckpointKeeper(self.checkpoint_dir, self.message.emit)
        self._state = JobState.IDLE
        self._program: Program | None = None
        #: Operations done and executed, the estimate, the elapsed, running and waiting
        #: times and the time left; it emits the progress and ETA signals above.
        self.progress = JobProgress(
            station,
            lambda: len(self._program) if self._program is not None else 0,
            self.progressChanged,
            self.executedChanged,
            self.etaChanged,
            self.operationDone,
            self,
        )
        self._flags = RunFlags()
        self._side = DriverSide(
            self, self._flags, self.progress, self._checkpoints, self._set_state, self
        )
        self._driver: JobDriver = self._side.driver
        #: What the jog lock says while this runner's program is under way (a macro's runner
        #: says its own, so that neither kind of runner starts while the other's runs).
        self.busy_text: Callable[[], str] = job_busy_text

    # --- what the dock reads --------------------------------------------------------

    @property
    def state(self) -> JobState:
        return self._state

    @property
    def program(self) -> Program | None:
        return self._program

    @property
    def done(self) -> int:
        """Count of completed operations (always the first ``done`` of the program).

        Where the job stands, so kept here; the other counts and the times are
        :attr:`progress`'s."""
        return self.progress.done

    @property
    def current_index(self) -> int | None:
        """The operation under way, or next, while a job is active or stopped short; else None."""
        if self._program is None or self._state in (JobState.IDLE, JobState.READY, JobState.DONE):
            return None
        in_flight = self._driver.in_flight
        if in_flight is not None:
            return in_flight
        done = self.progress.done
        return done if done < len(self._program) else None

    @property
    def question(self) -> int | None:
        """The operation whose fate the operator is asked to decide (see ``decisionNeeded``)."""
        return self._flags.question

    @property
    def resume_choice(self) -> ResumeChoice | None:
        """Where the operator may resume the paused job from, when only they can say."""
        return self._flags.choice

    @property
    def needs_operator(self) -> bool:
        """Paused until the operator acts: a question, a resume line to pick, an alarm."""
        return self._state is JobState.PAUSED and (
            self._flags.question is not None
            or self._flags.choice is not None
            or self._flags.operator_hold
        )

    @property
    def resume_available(self) -> int | None:
        """Index to resume from when a checkpoint of this program waits for the operator."""
        return self._checkpoints.resume_available

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
        self.progress.restart(0)
        self._flags.clear()
        self._driver.forget()
        self._checkpoints.resume_available = None
        if refused:
            self._program = None
            self.progress.estimate = None
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
        self.progress.estimate = checked.estimate
        resume = self._checkpoints.resume_available
        self.programChanged.emit()
        self._set_state(JobState.READY)
        self.progress.tell_all()
        self.progress.emit_eta()
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

    def start_from(self, index: int) -> None:
        """Run from operation ``index``, those before it counted as run: a resume at the point
        the operator chose, the machine set up as the file had it there (the driver's plan)."""
        program = self._program
        if program is None or self._state not in (JobState.READY, *FINISHED):
            return
        if index == 0:
            self.start()  # nothing before it: the whole job, set up as a whole job is
            return
        if not 0 < index < len(program):
            return  # the callers map lines and numbers to operations, refusing what is out
        reason = (
            QCoreApplication.translate(
                "JobRunner", "Resume from the checkpoint or discard it first"
            )
            if self._checkpoints.resume_available is not None
            else self._driver.start_refusal(index)
        )
        if reason is not None:
            self.message.emit(
                QCoreApplication.translate("JobRunner", "Job {0} not started from {1}: {2}").format(
                    repr(program.name), program[index].source, reason
                )
            )
            return
        if not self._refuse_start_position(program):
            self._begin(index, single_step=False, verify=False, chosen=True)

    def pause(self) -> None:
        """Let the operation under way finish, then stop before the next one."""
        driver = self._driver
        if self._state is JobState.RUNNING:
            driver.hold_back()  # what is not yet on the wire waits for the resume
            if driver.in_flight is None:
                self._set_state(JobState.PAUSED)
            else:
                self._flags.pause_requested = True
                self._set_state(JobState.PAUSING)
        elif self._state is JobState.WAITING:
            self._set_state(JobState.PAUSED)

    def resume(self) -> None:
        """Carry on after a pause or a lost link; an interrupted operation is re-examined first."""
        if self._state is JobState.PAUSING:
            self._flags.pause_requested = False
            self._set_state(JobState.RUNNING)
        elif self._state is JobState.PAUSED:
            if self._flags.question is not None:
                self.message.emit(
                    QCoreApplication.translate(
                        "JobRunner", "Answer the question about the interrupted operation first"
                    )
                )
                return
            if self._flags.choice is not None:
                self.message.emit(
                    QCoreApplication.translate("JobRunner", "Choose the line to resume from first")
                )
                return
            self._flags.operator_hold = False
            self._continue(single_step=False)

    def resume_at(self, index: int) -> None:
        """The operator's pick of where the paused job goes on (one of the choice's candidates)."""
        choice = self._flags.choice
        if choice is None or self._state is not JobState.PAUSED or index not in choice.candidates:
            return
        if self._refuse_for_link():
            return
        self._flags.choice = None
        self._flags.operator_hold = False
        self._flags.single_step = False
        self._flags.pause_requested = False
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
        self._flags.question = None
        self._flags.choice = None
        self._flags.operator_hold = False
        # The resume offer first, so views reacting to the state change see it.
        self._checkpoints.offer(self._program)
        self._set_state(state)

    def decide(self, *, again: bool) -> None:
        """The operator's answer: send the operation in question again, or count it as done."""
        index = self._flags.question
        if index is None or self._state is not JobState.PAUSED or self._refuse_for_link():
            return
        self._flags.question = None
        self._flags.single_step = False
        self._flags.pause_requested = False
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
        elif (
            self._state is JobState.PAUSED
            and self._flags.question is None
            and self._flags.choice is None
        ):
            self._flags.operator_hold = False
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
            ).format(self.progress.executed, len(self._program or ()))
        )

    def confirm(self) -> None:
        """The operator has done what the WAIT asked for."""
        driver = self._driver
        if self._state is not JobState.WAITING or driver.in_flight is None:
            return
        index = driver.in_flight
        driver.confirmed(index)
        self._set_state(JobState.RUNNING)
        self._side.complete(index)

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

    # --- running -------------------------------------------------------------

    def _begin(self, index: int, *, single_step: bool, verify: bool, chosen: bool = False) -> None:
        assert self._program is not None
        driver = self._driver
        if self._refuse_for_link():
            return
        self.progress.restart(index)
        self._flags.single_step = single_step
        self._flags.pause_requested = False
        self._flags.choice = None
        self._flags.operator_hold = False
        if chosen:
            driver.start_at(index)
        else:
            driver.begin(index, verify=verify)
        self.progress.tell_done()
        self._set_state(JobState.RUNNING)
        driver.proceed()

    def _continue(self, *, single_step: bool) -> None:
        if self._refuse_for_link():
            return
        self._flags.single_step = single_step
        self._flags.pause_requested = False
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
        owner = self.station.model.jog_lock_reason
        if owner is not None and self._state not in ACTIVE and owner != self.busy_text():
            # Another kind of runner owns the machine (a macro under way).
            self.message.emit(
                QCoreApplication.translate("JobRunner", "Cannot run the job: {0}").format(owner)
            )
            return True
        reason = self.station.model.motion_lock_reason()
        if self.station.session is None or self.station.model.link_state in LINK_DOWN:
            reason = reason or QCoreApplication.translate("JobRunner", "not connected")
            self.message.emit(
                QCoreApplication.translate("JobRunner", "Cannot run the job: {0}").format(reason)
            )
            return True
        return False

    # --- state and time ------------------------------------------------------

    def _set_state(self, state: JobState) -> None:
        if state is self._state:
            return
        self.progress.flush()  # the views see the progress the new state comes with
        self._flags.paused_by_link = False  # set again by link_pause, after this
        was_running = self._state in CLOCK_RUNS
        was_active = self._state in ACTIVE
        runs = state in CLOCK_RUNS
        self.progress.clock(was_running, runs, state in ACTIVE)
        self.progress.ended = state is JobState.DONE
        self._state = state
        # While a job is under way (paused and waiting included: its resume goes on from
        # where the machine was), a jog would move the machine under it.  The lock another
        # kind of runner holds (a macro's, its own text) is not this runner's to give back.
        model = self.station.model
        if state in ACTIVE:
            model.set_jog_lock(self.busy_text())
        elif was_active or model.jog_lock_reason == self.busy_text():
            model.set_jog_lock(None)
        self.stateChanged.emit(state)
        if not runs:
            self.progress.emit_eta()
