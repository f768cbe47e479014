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
from app.jobs.program import JobFileError
from app.jobs.run.runner import JobRunner
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
    runner = JobRunner(station, Path(checkpoint_dir or default_checkpoint_dir()))
    said: list[str] = []
    events: deque[tuple[str, tuple[object, ...]]] = deque()

    def tell(text: str) -> None:
        said.append(text)
        if on_message is not None:
            on_message(text)

    runner.message.connect(lambda text: events.append(("message", (text,))))
    runner.progressChanged.connect(lambda *a: events.append(("progress", a)))
    runner.waitingForOperator.connect(lambda text: events.append(("prompt", (text,))))
    runner.decisionNeeded.connect(lambda *a: events.append(("decision", a)))
    try:
        refused = runner.load(program)
        _drain(events, tell)
        if refused:
            raise JobRefused("\n".join(said) or f"{len(refused)} operation(s) refused")
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
                runner.start()
        else:
            runner.start()
        _drain(events, tell)
        if runner.state not in ACTIVE:
            raise JobRefused("\n".join(said[-3:]) or f"{program.name}: not started")
        progress_due = [0.0]
        clock = station.clock
        paused_by_script = [False]
        why: list[str] = []  # why this module ended the job, when it did

        def report() -> None:
            if on_progress is None:
                return
            progress = Progress(
                runner.done,
                len(program),
                runner.elapsed_s,
                runner.remaining_s,
                runner.state.value,
            )
            on_progress(progress)
            for request in progress._requests:  # noqa: SLF001 - its own dataclass
                if request == "pause":
                    paused_by_script[0] = True
                    runner.pause()
                elif request == "resume":
                    paused_by_script[0] = False
                    runner.resume()
                elif request == "abort":
                    runner.abort()

        def something_to_do() -> bool:
            return bool(events) or runner.state not in ACTIVE or clock.now() >= progress_due[0]

        while True:
            yield Wait(something_to_do, 24 * 3600.0, "the job", motion=False)
            while events:
                kind, args = events.popleft()
                if kind == "message":
                    tell(str(args[0]))
                elif kind == "progress":
                    report()
                elif kind == "prompt":
                    if on_prompt is not None and on_prompt(str(args[0])):
                        runner.confirm()
                    else:
                        why.append(f"the job asked {str(args[0])!r} and no one answered")
                        runner.abort()
                elif kind == "decision":
                    question, again, done = (str(a) for a in args)
                    if on_decision is None:
                        why.append(f"{question} (no on_decision to answer it)")
                        runner.abort()
                    else:
                        runner.decide(again=on_decision(question, again, done))
            if runner.state not in ACTIVE:
                break
            if clock.now() >= progress_due[0]:
                progress_due[0] = clock.now() + PROGRESS_EVERY_S
                report()
            choice = runner.resume_choice
            if runner.needs_operator and choice is not None and on_decision is not None:
                # Only the operator can say where the job goes on; the script answers for them.
                from_first = on_decision(
                    choice.text,
                    f"resume from operation {choice.first + 1}, the first not proven run",
                    f"resume after operation {choice.last}, the last sent",
                )
                runner.resume_at(choice.first if from_first else choice.last)
                _drain(events, tell)
            if runner.needs_operator:
                # An alarm, a board that restarted, a resume line to pick: a script is no
                # operator.  The job ends (failed, its checkpoint kept) with what was said,
                # once, rather than resuming into the same pause again and again.
                runner.give_up()
                _drain(events, tell)
                report()
                break
            if (
                runner.state is JobState.PAUSED
                and not paused_by_script[0]
                and runner.question is None
                and station.model.motion_lock_reason() is None
            ):
                runner.resume()  # the link came back: carry on, the runner re-examines first
        _drain(events, tell)
        state = runner.state
        if state is JobState.DONE:
            report()
            return JobResult(program.name, len(program), runner.elapsed_s, resumed_from)
        reason = "; ".join([*why, said[-1] if said else state.value])
        error = JobFailed if state is JobState.FAILED else JobAborted
        raise error(reason, runner.done, len(program))
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


def _drain(events: deque[tuple[str, tuple[object, ...]]], tell: Callable[[str], None]) -> None:
    """Messages said while loading and starting (the rest waits for the loop)."""
    keep = deque(e for e in events if e[0] != "message")
    for kind, args in events:
        if kind == "message":
            tell(str(args[0]))
    events.clear()
    events.extend(keep)
