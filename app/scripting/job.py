"""``machine.run(job)``: a job file run to its end by the same runner the jobs dock uses.

The :class:`~app.jobs.run.runner.JobRunner` does the running (each operation
confirmed by the device, a checkpoint after each, an interrupted operation
re-examined on resume); this module only answers for the operator: it
reports progress, asks the script's callbacks where the dock would ask the
operator, and turns the job's end into a return value or an exception.

Callbacks run in the script's thread between two pumps, never inside a Qt
slot, so an exception raised in one stops the job (the machine is stopped,
the checkpoint kept) and reaches the caller.
"""

from __future__ import annotations

import tempfile
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from PySide6.QtCore import QStandardPaths

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import JobFileError, Program
from app.jobs.run.runner import JobRunner
from app.jobs.run.start_point import StartRefused, operation_at_line, operation_numbered
from app.jobs.run.states import ACTIVE, JobState
from app.scripting.errors import CheckpointWaiting, JobAborted, JobFailed, JobRefused
from app.scripting.waits import MachinePort, Operation, Wait

#: Seconds between progress calls while nothing else happens (the ETA moves on).
PROGRESS_EVERY_S = 0.5


@dataclass
class Progress:
    """Where a running job stands; the callback may call :meth:`pause`, :meth:`resume`,
    :meth:`abort` on it."""

    done: int
    total: int
    elapsed_s: float
    remaining_s: float
    state: str
    _requests: list[str] = field(default_factory=list, repr=False)

    def pause(self) -> None:
        """Stop after the operation under way; the callback is called on while paused."""
        self._requests.append("pause")

    def resume(self) -> None:
        self._requests.append("resume")

    def abort(self) -> None:
        """Stop the machine now; the checkpoint stays for ``resume=True``."""
        self._requests.append("abort")


@dataclass(frozen=True)
class JobResult:
    name: str
    operations: int
    elapsed_s: float
    resumed_from: int | None


def default_checkpoint_dir() -> Path:
    """Where the window keeps its checkpoints, so a job interrupted in either resumes in both."""
    data = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
    if not data:
        return Path(tempfile.gettempdir()) / "stepdeck-checkpoints"
    return Path(data) / "checkpoints"


def run_job(
    machine: MachinePort,
    path: Path,
    *,
    on_progress: Callable[[Progress], None] | None = None,
    on_prompt: Callable[[str], bool] | None = None,
    on_decision: Callable[[str, str, str], bool] | None = None,
    on_message: Callable[[str], None] | None = None,
    resume: bool | None = None,
    checkpoint_dir: str | Path | None = None,
    options: JobOptions | None = None,
    from_line: int | None = None,
    from_op: int | None = None,
) -> Operation[JobResult]:
    """Run ``path``; returns a :class:`JobResult`, raises JobRefused / JobAborted / JobFailed.

    * ``on_progress(progress)`` after each operation and every half second;
      it may pause, resume or abort through ``progress``.
    * ``on_prompt(message) -> bool``: a ``wait:`` line asks the operator;
      True carries on, False aborts.  Without it a prompt aborts the job.
    * ``on_decision(question, again, done) -> bool``: after a lost link only
      the operator can tell whether an operation ran; True sends it again.
      Without it the job aborts there (its checkpoint kept).  On G-code, where
      several lines may or may not have run, True resumes from the first not
      proven run, False after the last sent.
    * A pause only the operator can end (an alarm, a board that restarted and
      lost its position, a resume line to pick without ``on_decision``) ends
      the job: JobFailed, with what was said, the checkpoint kept.
    * ``resume``: when a checkpoint of this job waits, True resumes from it,
      False starts over (discarding it); None refuses to choose (JobRefused).
    * ``from_line``: start at this line of a G-code file (the first operation
      of it, or of the next line that makes one), the machine first set up as
      the file had it there (units, distance mode, plane, feed, the file's G92,
      the pen) and brought there with the pen up; ``from_op``: start at this
      operation (counted from 1, as the jobs dock shows them; a drill hole
      starts with its move).  Refused (JobRefused, with file:line and why)
      where that state cannot be rebuilt, and with ``resume=True``.
    """
    station = machine.station
    profile = station.profile
    names = [axis.name for axis in profile.axes]
    try:
        program = load_job(
            path,
            names,
            options
            or JobOptions(
                gcode=profile.gcode, machine_title=profile.title, one_bit=profile.drill_one_bit
            ),
        )
    except (JobFileError, OSError) as exc:
        raise JobRefused(str(exc)) from None
    return run_program(
        machine,
        program,
        on_progress=on_progress,
        on_prompt=on_prompt,
        on_decision=on_decision,
        on_message=on_message,
        resume=resume,
        checkpoint_dir=checkpoint_dir,
        from_line=from_line,
        from_op=from_op,
    )


def run_program(
    machine: MachinePort,
    program: Program,
    *,
    on_progress: Callable[[Progress], None] | None = None,
    on_prompt: Callable[[str], bool] | None = None,
    on_decision: Callable[[str, str, str], bool] | None = None,
    on_message: Callable[[str], None] | None = None,
    resume: bool | None = None,
    checkpoint_dir: str | Path | None = None,
    from_line: int | None = None,
    from_op: int | None = None,
) -> Operation[JobResult]:
    """Run a program already read (a job file's, a macro's) as :func:`run_job` runs a file's."""
    station = machine.station
    runner = JobRunner(station, Path(checkpoint_dir or default_checkpoint_dir()))
    watch = _JobWatch(runner, program, on_progress, on_prompt, on_decision, on_message)
    try:
        watch.start(resume, _start_index(program, from_line, from_op, resume))
        while True:
            yield Wait(watch.something_to_do, 24 * 3600.0, "the job", motion=False)
            if not watch.step():
                break
        return watch.result()
    except (GeneratorExit, KeyboardInterrupt):
        if runner.state in ACTIVE:
            runner.abort()  # stops the machine; the checkpoint stays
        raise
    except BaseException:
        if runner.state in ACTIVE:
            runner.abort()
        raise
    finally:
        runner.deleteLater()


class _JobWatch:
    """One job run from a script: the runner's signals queued, answered between two pumps.

    The script's callbacks answer for the operator; what the runner said is
    kept for the exception that ends a job that did not finish.
    """

    def __init__(
        self,
        runner: JobRunner,
        program: Program,
        on_progress: Callable[[Progress], None] | None,
        on_prompt: Callable[[str], bool] | None,
        on_decision: Callable[[str, str, str], bool] | None,
        on_message: Callable[[str], None] | None,
    ) -> None:
        self.runner = runner
        self.program = program
        self.clock = runner.station.clock
        self._on_progress = on_progress
        self._on_prompt = on_prompt
        self._on_decision = on_decision
        self._on_message = on_message
        self.said: list[str] = []
        self.events: deque[tuple[str, tuple[object, ...]]] = deque()
        self.resumed_from: int | None = None
        self.progress_due = 0.0
        self.paused_by_script = False
        self.why: list[str] = []  # why this module ended the job, when it did
        events = self.events
        runner.message.connect(lambda text: events.append(("message", (text,))))
        runner.progressChanged.connect(lambda *a: events.append(("progress", a)))
        runner.waitingForOperator.connect(lambda text: events.append(("prompt", (text,))))
        runner.decisionNeeded.connect(lambda *a: events.append(("decision", a)))

    def tell(self, text: str) -> None:
        self.said.append(text)
        if self._on_message is not None:
            self._on_message(text)

    def start(self, resume: bool | None, start_at: int | None = None) -> None:
        """Load and start (or resume from a checkpoint, or start at ``start_at``); refused:
        JobRefused, said why."""
        runner, program = self.runner, self.program
        refused = runner.load(program)
        _drain(self.events, self.tell)
        if refused:
            raise JobRefused("\n".join(self.said) or f"{len(refused)} operation(s) refused")
        resumed_from = runner.resume_available
        if resumed_from is not None:
            if resume is None:
                raise CheckpointWaiting(
                    f"{program.name}: a checkpoint says {resumed_from} of {len(program)} "
                    "operations are done; resume=True continues there, resume=False starts over",
                    resumed_from,
                    len(program),
                )
            if resume:
                runner.resume_from_checkpoint()
            else:
                runner.discard_checkpoint()
                resumed_from = None
                _start(runner, start_at)
        else:
            _start(runner, start_at)
        self.resumed_from = resumed_from if start_at is None else start_at
        _drain(self.events, self.tell)
        if runner.state not in ACTIVE:
            raise JobRefused("\n".join(self.said[-3:]) or f"{program.name}: not started")

    def report(self) -> None:
        if self._on_progress is None:
            return
        runner = self.runner
        progress = Progress(
            runner.done,
            len(self.program),
            runner.progress.elapsed_s,
            runner.progress.remaining_s,
            runner.state.value,
        )
        self._on_progress(progress)
        for request in progress._requests:  # noqa: SLF001 - its own dataclass
            if request == "pause":
                self.paused_by_script = True
                runner.pause()
            elif request == "resume":
                self.paused_by_script = False
                runner.resume()
            elif request == "abort":
                runner.abort()

    def something_to_do(self) -> bool:
        return (
            bool(self.events)
            or self.runner.state not in ACTIVE
            or self.clock.now() >= self.progress_due
        )

    def answer_events(self) -> None:
        """What the runner said or asked since the last pump, answered for the operator."""
        runner = self.runner
        while self.events:
            kind, args = self.events.popleft()
            if kind == "message":
                self.tell(str(args[0]))
            elif kind == "progress":
                self.report()
            elif kind == "prompt":
                if self._on_prompt is not None and self._on_prompt(str(args[0])):
                    runner.confirm()
                else:
                    self.why.append(f"the job asked {str(args[0])!r} and no one answered")
                    runner.abort()
            elif kind == "decision":
                question, again, done = (str(a) for a in args)
                if self._on_decision is None:
                    self.why.append(f"{question} (no on_decision to answer it)")
                    runner.abort()
                else:
                    runner.decide(again=self._on_decision(question, again, done))

    def step(self) -> bool:
        """One pump's worth: False once the job is over (done, failed, aborted, given up)."""
        runner, clock = self.runner, self.clock
        self.answer_events()
        if runner.state not in ACTIVE:
            return False
        if clock.now() >= self.progress_due:
            self.progress_due = clock.now() + PROGRESS_EVERY_S
            self.report()
        choice = runner.resume_choice
        if runner.needs_operator and choice is not None and self._on_decision is not None:
            # Only the operator can say where the job goes on; the script answers for them.
            from_first = self._on_decision(
                choice.text,
                f"resume from operation {choice.first + 1}, the first not proven run",
                f"resume after operation {choice.last}, the last sent",
            )
            runner.resume_at(choice.first if from_first else choice.last)
            _drain(self.events, self.tell)
        if runner.needs_operator:
            # An alarm, a board that restarted, a resume line to pick: a script is no
            # operator.  The job ends (failed, its checkpoint kept) with what was said,
            # once, rather than resuming into the same pause again and again.
            runner.give_up()
            _drain(self.events, self.tell)
            self.report()
            return False
        if (
            runner.state is JobState.PAUSED
            and not self.paused_by_script
            and runner.question is None
            and runner.station.model.motion_lock_reason() is None
        ):
            runner.resume()  # the link came back: carry on, the runner re-examines first
        return True

    def result(self) -> JobResult:
        """The finished job's result, or the exception that says why it did not finish."""
        _drain(self.events, self.tell)
        runner, program = self.runner, self.program
        state = runner.state
        if state is JobState.DONE:
            self.report()
            return JobResult(
                program.name, len(program), runner.progress.elapsed_s, self.resumed_from
            )
        reason = "; ".join([*self.why, self.said[-1] if self.said else state.value])
        error = JobFailed if state is JobState.FAILED else JobAborted
        raise error(reason, runner.done, len(program))


def _start_index(
    program: Program, from_line: int | None, from_op: int | None, resume: bool | None
) -> int | None:
    """The operation ``from_line`` or ``from_op`` names (None: the first); JobRefused if none."""
    if from_line is None and from_op is None:
        return None
    if from_line is not None and from_op is not None:
        raise JobRefused("from_line and from_op name two starts: give one")
    if resume:
        raise JobRefused("resume=True goes on from the checkpoint: it takes no from_line/from_op")
    try:
        if from_line is not None:
            return operation_at_line(program, from_line)
        assert from_op is not None
        return operation_numbered(program, from_op)
    except StartRefused as exc:
        raise JobRefused(str(exc)) from None


def _start(runner: JobRunner, index: int | None) -> None:
    if index is None:
        runner.start()
    else:
        runner.start_from(index)


def _drain(events: deque[tuple[str, tuple[object, ...]]], tell: Callable[[str], None]) -> None:
    """Messages said while loading and starting (the rest waits for the loop)."""
    keep = deque(e for e in events if e[0] != "message")
    for kind, args in events:
        if kind == "message":
            tell(str(args[0]))
    events.clear()
    events.extend(keep)
