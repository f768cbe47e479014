"""Runs a program on the connected machine, one operation at a time, so it can be trusted.

Trust here means: no operation is done twice and none is skipped, whatever
happens to the link or to the station.  Three rules give that:

* An operation counts as done only when the machine *reports* it done (every
  moved axis at its target, standing still), never when it was sent.
* After every completed operation a checkpoint (the index of the last
  completed one) is written to disk atomically, *before* the next operation is
  sent.  A crash can therefore lose at most the in-flight operation, and the
  checkpoint always names it as not done.
* An operation that was in flight when the link went (or the station died) is
  re-examined before anything is sent again: the stage finishes a MOVE_ABS on
  its own, so if every axis already stands on the target the operation is
  marked complete without sending it; only otherwise is it sent again.

Replies are judged only once enough fresh echoes have come in, because an
echo already on its way when a move was sent (or one left in a serial buffer
by a killed station) still describes the machine before the move.

The runner speaks three dialects, chosen by the profile:

* **stage** — absolute moves, completion judged from the echoes as above;
  drill and pen operations are refused at :meth:`JobRunner.load`.
* **drill** — the PCB drill/plotter's one-letter procedures through
  :class:`~app.machines.drill.session.DrillSession`, one at a time.  A MOVE becomes
  ``X`` then ``Y`` (one per axis of its target), a DRILL ``V``, PEN_DOWN/UP
  ``K``/``Z``.  The device reports every procedure itself (``R`` received,
  ``D`` done), so an operation is complete when the session goes idle after
  the ``D`` of each of its commands; an ``E`` fails the job at the
  operation's line.  When the link goes, the operation in flight is held as
  not done and re-examined on resume: a MOVE is simply sent again (absolute
  microsteps, harmless whether or not it was finished); a DRILL whose ``V``
  had been received (``RV`` seen) counts as done, because the machine runs a
  procedure it has accepted to its end on its own (as the stage finishes a
  MOVE_ABS) and drilling the hole again would enlarge it; a DRILL whose
  ``RV`` never arrived is sent again.  After a station restart nothing is
  known of the last ``RV``, so the checkpoint's next DRILL is sent again.
"""

from __future__ import annotations

import enum
import json
import math
import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass
from datetime import UTC, datetime
from functools import partial
from pathlib import Path
from typing import Any

from PySide6.QtCore import QObject, Qt, QTimer, Signal

from app.jobs.estimate.stage import Estimate, estimate, parameters_from_model
from app.jobs.program import (
    LimitViolation,
    Operation,
    OpKind,
    Program,
    SourceRef,
    check_limits,
)
from app.jobs.run.gcode import GcodeDriver
from app.machine import LinkState
from app.machines.drill.session import DrillSession
from app.machines.session import MachineSession
from app.station import Station
from protocol.stage.codec import AxisStatus, EchoFrame, EchoType, Rejected

ETA_INTERVAL_MS = 1000
#: Refused operations listed in the message (the dock's list holds them all).
REFUSALS_SHOWN = 20
#: Dialects whose completion reports the runner understands.
RUNNABLE_DIALECTS = frozenset({"stage", "drill", "gcode"})

#: Position echoes per moved axis, counted from a resume, before the machine's state is believed:
#: more than a killed station can leave unread in a serial buffer.
RESUME_ECHOES = 4

_LINK_DOWN = (LinkState.LOST, LinkState.DISCONNECTED, LinkState.CONNECTING)


class JobState(enum.Enum):
    IDLE = "idle"  # no program
    READY = "ready"  # loaded, not started
    RUNNING = "running"
    PAUSING = "pausing"  # the current operation finishes, then PAUSED
    PAUSED = "paused"
    WAITING = "waiting"  # for the operator to confirm a WAIT
    DONE = "done"
    ABORTED = "aborted"
    FAILED = "failed"


_ACTIVE = (JobState.RUNNING, JobState.PAUSING, JobState.PAUSED, JobState.WAITING)
_CLOCK_RUNS = (JobState.RUNNING, JobState.PAUSING)
_FINISHED = (JobState.DONE, JobState.ABORTED, JobState.FAILED)


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


class JobRunner(QObject):
    stateChanged = Signal(object)  # JobState
    progressChanged = Signal(int, int)  # done, total
    etaChanged = Signal(float, float)  # elapsed_s, remaining_s
    operationStarted = Signal(int)
    operationDone = Signal(int)
    waitingForOperator = Signal(str)
    message = Signal(str)
    programChanged = Signal()

    def __init__(
        self, station: Station, checkpoint_dir: Path, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self.station = station
        self.checkpoint_dir = Path(checkpoint_dir)
        self._state = JobState.IDLE
        self._program: Program | None = None
        self._estimate: Estimate | None = None
        self._done = 0  # operations [0, done) are complete
        self._resume_available: int | None = None
        # The operation under way: sent (or being re-examined) and not yet reported done.
        self._in_flight: int | None = None
        self._targets: dict[int, float] = {}  # axis index → mm
        self._verify = False  # re-examine before sending (after a resume)
        self._gate = 0  # position echoes per moved axis before the state is believed
        self._seen: dict[int, int] = {}  # position echoes per moved axis since the reference
        # Drill dialect: letters of the in-flight operation's commands not yet done (``D``),
        # and whether the device acknowledged (``R``) the drill cycle of a DRILL.
        self._drill_pending: list[str] = []
        self._drill_received = False
        self._single_step = False
        self._pause_requested = False
        self._elapsed_before = 0.0
        self._running_since: float | None = None
        self._session: MachineSession | None = None
        self._gcode = GcodeDriver(self)
        self._fingerprint_cache: tuple[Program, str] | None = None
        self._eta_timer = QTimer(self)
        self._eta_timer.setInterval(ETA_INTERVAL_MS)
        self._eta_timer.timeout.connect(self.emit_eta)
        station.sessionChanged.connect(self._bind_session)
        station.model.linkStateChanged.connect(self._on_link_state)
        self._bind_session()

    # --- what the dock reads -------------------------------------------------

    @property
    def state(self) -> JobState:
        return self._state

    @property
    def program(self) -> Program | None:
        return self._program

    @property
    def done(self) -> int:
        """Count of completed operations (always the first ``done`` of the program)."""
        return self._done

    @property
    def estimate(self) -> Estimate | None:
        return self._estimate

    @property
    def current_index(self) -> int | None:
        """The operation under way, or next, while a job is active or stopped short; else None."""
        if self._program is None or self._state in (JobState.IDLE, JobState.READY, JobState.DONE):
            return None
        if self._in_flight is not None:
            return self._in_flight
        return self._done if self._done < len(self._program) else None

    @property
    def resume_available(self) -> int | None:
        """Index to resume from when a checkpoint of this program waits for the operator."""
        return self._resume_available

    @property
    def elapsed_s(self) -> float:
        """Station-clock time spent running, without paused and waiting stretches."""
        if self._running_since is None:
            return self._elapsed_before
        return self._elapsed_before + self.station.clock.now() - self._running_since

    @property
    def remaining_s(self) -> float:
        """The model's time still to go; the estimate's figure, not rescaled by the real one."""
        if self._estimate is None:
            return 0.0
        return self._estimate.remaining_after(self._done)

    # --- loading -------------------------------------------------------------

    def load(self, program: Program) -> list[LimitViolation]:
        """Accept ``program`` unless some operation leaves the travel or the machine cannot do it.

        A refused program changes nothing that was loaded before except that
        it is unloaded: the operator sees the list of offending lines.
        """
        if self._state in _ACTIVE:
            self.message.emit("Stop the running job before loading another")
            return []
        profile = self.station.profile
        refused: list[LimitViolation] = check_limits(program, profile.travel_limits())
        refused += self._unsupported(program)
        refused += self._unexecutable_lines(program)
        # In file order, as the operator reads the file.
        refused.sort(key=lambda v: (v.operation.source.line, v.index))
        self._reset()
        if refused:
            self._program = None
            self._estimate = None
            lines = "\n".join(f"  {v}" for v in refused[:REFUSALS_SHOWN])
            if len(refused) > REFUSALS_SHOWN:
                lines += f"\n  … and {len(refused) - REFUSALS_SHOWN} more"
            count = len({v.index for v in refused})
            self.message.emit(
                f"Job {program.name!r} refused, {count} operation(s) cannot be run:\n{lines}"
            )
            self._set_state(JobState.IDLE)
            self.programChanged.emit()
            return refused
        self._program = program
        self._estimate = self._compute_estimate(program)
        self._resume_available = self._read_checkpoint(program)
        self.programChanged.emit()
        self._set_state(JobState.READY)
        self.progressChanged.emit(self._done, len(program))
        self.emit_eta()
        if self._resume_available is not None:
            op = program[self._resume_available]
            self.message.emit(
                f"Job {program.name!r} was interrupted: {self._resume_available} of {len(program)} "
                f"operations done; resume from {op.source} or discard the checkpoint"
            )
        return []

    def _unsupported(self, program: Program) -> list[LimitViolation]:
        """Operations this machine cannot do at all; scans only when such a kind is used."""
        profile = self.station.profile
        capabilities = profile.capabilities
        kinds = program.kinds()
        refused: list[LimitViolation] = []
        if profile.dialect not in RUNNABLE_DIALECTS and kinds - {OpKind.COMMENT}:
            # A job that could never see an operation end must not start.
            for index, op in enumerate(program):
                if op.kind is not OpKind.COMMENT:
                    reason = f"jobs do not run on the {profile.title} yet (preview only)"
                    return [UnsupportedOperation.of(index, op, reason)]
        problems: dict[OpKind, str] = {}
        if not capabilities.drill:
            problems[OpKind.DRILL] = f"{profile.title} cannot drill"
        if not capabilities.pen:
            problems[OpKind.PEN_DOWN] = problems[OpKind.PEN_UP] = f"{profile.title} has no pen"
        if profile.dialect != "gcode":
            problems[OpKind.GCODE] = f"{profile.title} does not take G-code"
        for kind in sorted(kinds & problems.keys(), key=lambda k: k.value):
            for index in program.indices_of(kind):
                op = program[int(index)]
                refused.append(UnsupportedOperation.of(int(index), op, problems[kind]))
        return refused

    def _unexecutable_lines(self, program: Program) -> list[LimitViolation]:
        """G-code lines the loader found this machine cannot execute (named words, axes)."""
        name = program.source.name if program.source is not None else program.name
        refused: list[LimitViolation] = []
        for problem in program.unexecutable_lines():
            op = Operation(OpKind.GCODE, SourceRef(name, problem.line), line=problem.text)
            refused.append(UnsupportedOperation.of(problem.line, op, problem.reason))
        return refused

    # --- operator commands ---------------------------------------------------

    def start(self) -> None:
        """Run from the first operation (READY, or again after a job ended)."""
        if self._program is None or self._state not in (JobState.READY, *_FINISHED):
            return
        if self._resume_available is not None:
            self.message.emit("Resume from the checkpoint or discard it first")
            return
        self._begin(0, single_step=False, verify=False)

    def pause(self) -> None:
        """Let the operation under way finish, then stop before the next one."""
        if self._state is JobState.RUNNING:
            if self._gcode_dialect():
                self._gcode.hold_back()  # lines not yet on the wire wait for the resume
            if self._in_flight is None:
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
            self._continue(single_step=False)

    def step(self) -> None:
        """Run exactly one operation, then pause."""
        if self._state is JobState.READY:
            if self._resume_available is not None:
                self.message.emit("Resume from the checkpoint or discard it first")
                return
            self._begin(0, single_step=True, verify=False)
        elif self._state is JobState.PAUSED:
            self._continue(single_step=True)

    def abort(self) -> None:
        """Stop the machine now; the checkpoint stays, so the job can be resumed later."""
        if self._state not in _ACTIVE:
            return
        session = self.station.session
        if session is not None:
            session.stop_all()
        if self._gcode_dialect():
            self._gcode.stopped()
        self._in_flight = None
        self._verify = False
        # The resume offer first, so views reacting to the state change see it.
        self._offer_checkpoint()
        self._set_state(JobState.ABORTED)
        self.message.emit(f"Job aborted after {self._done} of {self._total()} operations")

    def confirm(self) -> None:
        """The operator has done what the WAIT asked for."""
        if self._state is not JobState.WAITING or self._in_flight is None:
            return
        if self._gcode_dialect():
            self._gcode.confirmed(self._in_flight)
        self._set_state(JobState.RUNNING)
        self._complete(self._in_flight)

    def resume_from_checkpoint(self) -> None:
        """Carry on an interrupted job where its checkpoint says, re-examining that operation."""
        if self._program is None or self._resume_available is None:
            return
        if self._state not in (JobState.READY, *_FINISHED):
            return
        index = self._resume_available
        self._resume_available = None
        self._begin(index, single_step=False, verify=True)

    def discard_checkpoint(self) -> None:
        """Forget the interrupted run: the next start begins at the first operation."""
        if self._program is None:
            return
        self._checkpoint_path(self._program).unlink(missing_ok=True)
        self._resume_available = None
        if self._state in _FINISHED:
            self._set_state(JobState.READY)
        self.message.emit("Checkpoint discarded; the job starts from the beginning")

    def emit_eta(self) -> None:
        """Tell the dock elapsed and remaining time (a timer calls this every second)."""
        self.etaChanged.emit(self.elapsed_s, self.remaining_s)

    # --- running -------------------------------------------------------------

    def _begin(self, index: int, *, single_step: bool, verify: bool) -> None:
        assert self._program is not None
        if self._refuse_for_link():
            return
        self._done = index
        self._elapsed_before = 0.0
        self._running_since = None
        resumes_move = index < len(self._program) and self._program[index].kind is OpKind.MOVE
        self._in_flight = index if verify and resumes_move else None
        self._verify = self._in_flight is not None
        self._single_step = single_step
        self._pause_requested = False
        if self._gcode_dialect():
            self._in_flight = None
            self._verify = False
            self._gcode.begin(index, verify=verify)
        self.progressChanged.emit(self._done, len(self._program))
        self._set_state(JobState.RUNNING)
        self._proceed()

    def _continue(self, *, single_step: bool) -> None:
        if self._refuse_for_link():
            return
        self._single_step = single_step
        self._pause_requested = False
        self._set_state(JobState.RUNNING)
        self._proceed()

    def _refuse_for_link(self) -> bool:
        reason = self.station.model.motion_lock_reason()
        if self.station.session is None or self.station.model.link_state in _LINK_DOWN:
            self.message.emit(f"Cannot run the job: {reason or 'not connected'}")
            return True
        return False

    def _proceed(self) -> None:
        """Start whatever comes next: a re-examination, an operation, or the end."""
        program = self._program
        assert program is not None
        if self._gcode_dialect():
            self._gcode.proceed()
            return
        while self._state is JobState.RUNNING:
            if self._in_flight is not None:
                if self._verify:
                    self._start_verify(self._in_flight)
                else:
                    self._dispatch(self._in_flight)
                return
            if self._done >= len(program):
                self._finish()
                return
            index = self._done
            op = program[index]
            self.operationStarted.emit(index)
            if op.kind is OpKind.COMMENT:
                self.message.emit(f"{op.source}: {op.message}")
                self._mark_done(index)
                if not self._carry_on():
                    return
                continue
            self._in_flight = index
            self._dispatch(index)
            return

    def _dispatch(self, index: int) -> None:
        """Send operation ``index`` (it is ``_in_flight``)."""
        assert self._program is not None
        op = self._program[index]
        if op.kind is OpKind.WAIT:
            self._set_state(JobState.WAITING)
            self.waitingForOperator.emit(op.message)
            return
        if self._drill_dialect():
            self._dispatch_drill(index)
            return
        if op.kind is not OpKind.MOVE:
            self._fail(index, f"{op.describe()} is not supported on {self.station.profile.title}")
            return
        session = self.station.session
        if session is None or self.station.model.link_state in _LINK_DOWN:
            self._link_pause()
            return
        self._targets = {self.station.profile.axis_index(a): v for a, v in op.target.items()}
        self._seen = dict.fromkeys(self._targets, 0)
        # An echo already in flight describes the machine before this move: only the
        # ones after every frame this operation sends (one per axis) are believed.
        self._gate = len(self._targets) + 2
        for axis, target in self._targets.items():
            if not session.move_absolute(axis, target):
                if self.station.model.link_state in _LINK_DOWN:
                    self._link_pause()
                else:
                    reason = self.station.model.motion_lock_reason() or "the move was refused"
                    self._fail(index, reason)
                return
        self._judge()

    def _start_verify(self, index: int) -> None:
        """Look before sending again: the machine may have finished the operation on its own."""
        assert self._program is not None
        op = self._program[index]
        if self._drill_dialect():
            self._verify_drill(index)
            return
        if op.kind is not OpKind.MOVE:
            self._verify = False
            self._dispatch(index)
            return
        self._targets = {self.station.profile.axis_index(a): v for a, v in op.target.items()}
        self._seen = dict.fromkeys(self._targets, 0)
        self._gate = RESUME_ECHOES
        self.message.emit(f"Checking whether {op.source} ({op.describe()}) was completed…")

    def _judge(self) -> None:
        """Decide, from the machine's latest state, whether the operation in flight is over."""
        if self._in_flight is None or self._state not in _CLOCK_RUNS:
            return
        if not self._targets or any(n < self._gate for n in self._seen.values()):
            return
        model = self.station.model
        axes = [(model.axes[i], target) for i, target in self._targets.items()]
        if any(axis.moving for axis, _ in axes):
            return
        arrived = all(
            abs(axis.position - target) <= self._tolerance_mm(i)
            for i, (axis, target) in zip(self._targets, axes, strict=True)
        )
        index = self._in_flight
        if self._verify:
            self._verify = False
            if arrived:
                self.message.emit(f"Operation at {self._op_source(index)} was already complete")
                self._complete(index)
            else:
                self._dispatch(index)
            return
        if arrived:
            self._complete(index)
            return
        for axis, target in axes:
            if axis.status_code == AxisStatus.END_SWITCH:
                self._fail(index, f"{axis.name} hit an end switch at {axis.position:g} mm")
                return
            if axis.status_code == AxisStatus.STOPPED:
                # Somebody stopped the machine (Esc): the job waits, resume sends the move again.
                self._verify = True
                self._set_state(JobState.PAUSED)
                self.message.emit(
                    f"{axis.name} stopped short of {target:g} mm at {self._op_source(index)}; "
                    "resume sends the move again"
                )
                return

    # --- the drill dialect ---------------------------------------------------

    def _drill_dialect(self) -> bool:
        return self.station.profile.dialect == "drill"

    def _gcode_dialect(self) -> bool:
        return self.station.profile.dialect == "gcode"

    def _dispatch_drill(self, index: int) -> None:
        """Queue the drill commands of operation ``index``; the session's ``idle`` ends it."""
        assert self._program is not None
        op = self._program[index]
        session = self.station.drill_session
        if session is None or self.station.model.link_state in _LINK_DOWN:
            self._link_pause()
            return
        if session.busy:
            # Commands of somebody else (the terminal) still run: ours would finish among them.
            self._fail(index, "the drill is busy with another command")
            return
        profile = self.station.profile
        sends: list[tuple[str, Callable[[], bool]]] = []
        if op.kind is OpKind.MOVE:
            for name, target in op.target.items():
                axis = profile.axis_index(name)
                sends.append((name, partial(session.move_absolute, axis, target)))
        elif op.kind is OpKind.DRILL:
            sends.append(("V", session.drill))
        elif op.kind in (OpKind.PEN_DOWN, OpKind.PEN_UP):
            down = op.kind is OpKind.PEN_DOWN
            sends.append(("K" if down else "Z", partial(session.pen, down)))
        if not sends:
            self._fail(index, f"{op.describe()} is not supported on {profile.title}")
            return
        self._drill_pending = [letter for letter, _ in sends]
        self._drill_received = False
        for _, send in sends:
            if not send():
                self._drill_pending = []
                if self.station.model.link_state in _LINK_DOWN:
                    self._link_pause()
                else:
                    reason = self.station.model.motion_lock_reason() or "the drill refused it"
                    self._fail(index, reason)
                return

    def _verify_drill(self, index: int) -> None:
        """After a lost link: a DRILL the device had received is done; anything else goes again."""
        assert self._program is not None
        op = self._program[index]
        self._verify = False
        if op.kind is OpKind.DRILL and self._drill_received:
            self.message.emit(
                f"Drill cycle at {op.source} was received by the machine, which finishes it "
                "on its own: counted as done"
            )
            self._complete(index)
            return
        self._dispatch(index)

    def _on_drill_received(self, text: str) -> None:
        if self._in_flight is not None and self._drill_pending and text == "V":
            self._drill_received = True

    def _on_drill_done(self, text: str) -> None:
        if self._in_flight is None or not self._drill_pending:
            return
        if text[:1] == self._drill_pending[0]:
            self._drill_pending.pop(0)

    def _on_drill_idle(self) -> None:
        index = self._in_flight
        if index is None or self._verify or self._state not in _CLOCK_RUNS:
            return
        if self._program is None or self._program[index].kind in (OpKind.WAIT, OpKind.COMMENT):
            return
        if self._drill_pending:
            return
        self._complete(index)

    def _on_drill_failed(self, text: str) -> None:
        if self._in_flight is None or self._state not in _ACTIVE:
            return
        self._drill_pending = []
        self._fail(self._in_flight, f"the drill refused {text}")

    def _complete(self, index: int) -> None:
        self._mark_done(index)
        if self._carry_on():
            self._proceed()

    def _mark_done(self, index: int) -> None:
        assert self._program is not None
        self._in_flight = None
        self._verify = False
        self._targets = {}
        self._drill_pending = []
        self._drill_received = False
        self._done = index + 1
        self._write_checkpoint(self._program, index)  # before anything else is sent
        self.operationDone.emit(index)
        self.progressChanged.emit(self._done, len(self._program))
        self.emit_eta()

    def _carry_on(self) -> bool:
        """After an operation: whether the next one starts now (else the job ended or paused)."""
        assert self._program is not None
        if self._done >= len(self._program):
            self._finish()
            return False
        if self._single_step or self._pause_requested:
            self._pause_requested = False
            self._set_state(JobState.PAUSED)
            return False
        if self._state is not JobState.RUNNING:
            self._set_state(JobState.RUNNING)
        return True

    def _finish(self) -> None:
        assert self._program is not None
        self._checkpoint_path(self._program).unlink(missing_ok=True)
        self._set_state(JobState.DONE)
        self.emit_eta()
        self.message.emit(
            f"Job {self._program.name!r} done: {len(self._program)} operations "
            f"in {self.elapsed_s:.1f} s"
        )

    def _fail(self, index: int, reason: str) -> None:
        session = self.station.session
        if session is not None and self.station.model.link_state not in _LINK_DOWN:
            session.stop_all()
        if self._gcode_dialect():
            self._gcode.stopped()
        self._offer_checkpoint()
        self._set_state(JobState.FAILED)
        self.message.emit(f"Job failed at {self._op_source(index)}: {reason}")

    def _link_pause(self) -> None:
        """The link is gone: hold the operation under way as not done, to re-examine later."""
        if self._in_flight is not None:
            self._verify = True
        if self._gcode_dialect():
            self._gcode.link_lost()
        self._pause_requested = False
        self._set_state(JobState.PAUSED)
        where = f" at {self._op_source(self._in_flight)}" if self._in_flight is not None else ""
        self.message.emit(
            f"Job paused{where}: link {self.station.model.link_state.value}; "
            "resume once the machine is back"
        )

    def _tolerance_mm(self, axis: int) -> float:
        """Half a microstep plus the µm the wire rounds to."""
        model = self.station.model
        profile = self.station.profile.axes[axis]

        def known(parameter: int, fallback: float) -> float:
            value = model.parameter(axis, parameter).value
            return float(value) if value is not None else fallback

        lead_um = known(EchoType.LEAD, profile.lead * 1000)
        per_rev = known(EchoType.STEPS_PER_REV, profile.steps_per_rev) * known(
            EchoType.MICROSTEPS, profile.microsteps
        )
        return (lead_um / per_rev / 2 + 1.0) / 1000

    def _op_source(self, index: int | None) -> str:
        if self._program is None or index is None:
            return "?"
        return str(self._program[index].source)

    def _total(self) -> int:
        return len(self._program) if self._program is not None else 0

    # --- signals from the station -------------------------------------------

    def _bind_session(self) -> None:
        session = self.station.session
        if session is self._session:
            return
        self._gcode.bind(session)
        if self._session is not None:
            old = self._session
            try:
                old.frameReceived.disconnect(self._on_frame)
                if isinstance(old, DrillSession):
                    old.commandReceived.disconnect(self._on_drill_received)
                    old.commandDone.disconnect(self._on_drill_done)
                    old.commandFailed.disconnect(self._on_drill_failed)
                    old.idle.disconnect(self._on_drill_idle)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self._session = session
        if session is not None:
            # Queued: the session folds the echo into the model right after announcing it.
            session.frameReceived.connect(self._on_frame, Qt.ConnectionType.QueuedConnection)
        if isinstance(session, DrillSession):
            # Direct: each reply is judged as it is decoded, before the next one can arrive.
            session.commandReceived.connect(self._on_drill_received)
            session.commandDone.connect(self._on_drill_done)
            session.commandFailed.connect(self._on_drill_failed)
            session.idle.connect(self._on_drill_idle)

    def _on_frame(self, frame: object, raw: bytes) -> None:
        if self._in_flight is None:
            return
        if isinstance(frame, EchoFrame):
            for axis in self._seen:
                if axis < len(frame.packets) and frame.packets[axis].type == EchoType.POSITION:
                    self._seen[axis] += 1
        elif not isinstance(frame, Rejected):
            for axis in self._seen:
                self._seen[axis] += 1
        self._judge()

    def _on_link_state(self, state: object) -> None:
        if state in _LINK_DOWN and self._state in _CLOCK_RUNS:
            self._link_pause()

    # --- state and time ------------------------------------------------------

    def _set_state(self, state: JobState) -> None:
        if state is self._state:
            return
        was_running = self._state in _CLOCK_RUNS
        runs = state in _CLOCK_RUNS
        now = self.station.clock.now()
        if was_running and not runs and self._running_since is not None:
            self._elapsed_before += now - self._running_since
            self._running_since = None
        elif runs and not was_running:
            self._running_since = now
        self._state = state
        if runs and self.station.realtime:
            self._eta_timer.start()
        elif not runs:
            self._eta_timer.stop()
        self.stateChanged.emit(state)
        if not runs:
            self.emit_eta()

    def _reset(self) -> None:
        self._done = 0
        self._in_flight = None
        self._verify = False
        self._targets = {}
        self._seen = {}
        self._drill_pending = []
        self._drill_received = False
        self._resume_available = None
        self._single_step = False
        self._pause_requested = False
        self._elapsed_before = 0.0
        self._running_since = None

    def _compute_estimate(self, program: Program) -> Estimate:
        model = self.station.model
        session = self.station.session
        start = {axis.name: axis.position for axis in model.axes}
        return estimate(
            program,
            self.station.profile,
            parameters_from_model(model),
            (session.period_ms if session is not None else self.station.period_ms) / 1000,
            fast=session.fast_selected if session is not None else True,
            start=start,
        )

    # --- checkpoint ----------------------------------------------------------

    def _checkpoint_path(self, program: Program) -> Path:
        return self.checkpoint_dir / f"{self._fingerprint(program)}.json"

    def _fingerprint(self, program: Program) -> str:
        """The program's fingerprint, hashed once: a checkpoint is written twice a second."""
        cached = self._fingerprint_cache
        if cached is None or cached[0] is not program:
            cached = self._fingerprint_cache = (program, program.fingerprint())
        return cached[1]

    def _write_checkpoint(self, program: Program, completed: int) -> None:
        """Atomically: a crash leaves the old checkpoint or the new one, never half of one."""
        record = {
            "fingerprint": self._fingerprint(program),
            "name": program.name,
            "source": str(program.source) if program.source is not None else None,
            "completed": completed,
            "time": datetime.now(UTC).isoformat(timespec="seconds"),
        }
        path = self._checkpoint_path(program)
        try:
            self.checkpoint_dir.mkdir(parents=True, exist_ok=True)
            fd, temp = tempfile.mkstemp(prefix=f".{path.stem}.", dir=self.checkpoint_dir)
            try:
                with os.fdopen(fd, "w", encoding="utf-8") as handle:
                    json.dump(record, handle)
                    handle.flush()
                    os.fsync(handle.fileno())
                os.replace(temp, path)
            except BaseException:
                Path(temp).unlink(missing_ok=True)
                raise
        except OSError as exc:
            self.message.emit(f"Checkpoint not written ({exc}); an interruption restarts the job")

    def _read_checkpoint(self, program: Program) -> int | None:
        """First operation not completed by an earlier run of this very program, or None."""
        path = self._checkpoint_path(program)
        try:
            record: Any = json.loads(path.read_text(encoding="utf-8"))
        except FileNotFoundError:
            return None
        except (OSError, ValueError) as exc:
            self.message.emit(f"Ignoring an unreadable checkpoint {path.name}: {exc}")
            return None
        completed = record.get("completed") if isinstance(record, dict) else None
        if (
            not isinstance(record, dict)
            or record.get("fingerprint") != self._fingerprint(program)
            or not isinstance(completed, int)
            or not -1 <= completed < len(program) - 1
        ):
            return None
        return completed + 1

    def _offer_checkpoint(self) -> None:
        """After an abort or failure: resuming is the operator's choice, from what is on disk."""
        if self._program is not None:
            self._resume_available = self._read_checkpoint(self._program)
