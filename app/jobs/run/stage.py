"""Running a program on the XY stage: absolute moves, judged from the echoes.

An operation counts as done only when the machine *reports* it done: every
moved axis at its target, standing still.  Replies are judged only once
enough fresh echoes have come in, because an echo already on its way when a
move was sent (or one left in a serial buffer by a killed station) still
describes the machine before the move.

After a lost link the stage finishes a MOVE_ABS on its own, so the operation
in flight is re-examined first: if every axis already stands on the target it
is marked complete without being sent; only otherwise is it sent again (an
absolute move, harmless either way).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, Qt

from app.jobs.program import Operation, OpKind
from app.jobs.run.driver import RunnerPort, unsupported_on
from app.jobs.run.sequential import SequentialDriver
from app.jobs.texts import number
from app.machines.session import MachineSession
from protocol.stage.codec import AxisStatus, EchoFrame, EchoType, Rejected

#: Position echoes per moved axis, counted from a resume, before the machine's state is believed:
#: more than a killed station can leave unread in a serial buffer.
RESUME_ECHOES = 4


class StageDriver(SequentialDriver):
    def __init__(self, runner: RunnerPort) -> None:
        super().__init__(runner)
        self._session: MachineSession | None = None
        self._targets: dict[int, float] = {}  # axis index → mm
        self._gate = 0  # position echoes per moved axis before the state is believed
        self._seen: dict[int, int] = {}  # position echoes per moved axis since the reference

    def bind(self, session: MachineSession | None) -> None:
        if self._session is not None:
            try:
                self._session.frameReceived.disconnect(self._on_frame)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self._session = session
        if session is not None:
            # Queued: the session folds the echo into the model right after announcing it.
            session.frameReceived.connect(self._on_frame, Qt.ConnectionType.QueuedConnection)

    def _send(self, index: int, op: Operation) -> None:
        if op.kind is not OpKind.MOVE:
            self.runner.fail(index, unsupported_on(op, self.station.profile))
            return
        session = self.station.session
        assert session is not None
        self._expect(op)
        # An echo already in flight describes the machine before this move: only the
        # ones after every frame this operation sends (one per axis) are believed.
        self._gate = len(self._targets) + 2
        for axis, target in self._targets.items():
            if not session.move_absolute(axis, target):
                self._refused_send(
                    index, QCoreApplication.translate("JobRunner", "the move was refused")
                )
                return
        self._judge()

    def _start_verify(self, index: int) -> None:
        program = self.runner.program
        assert program is not None
        op = program[index]
        if op.kind is not OpKind.MOVE:
            super()._start_verify(index)
            return
        self._expect(op)
        self._gate = RESUME_ECHOES
        self.runner.note(
            QCoreApplication.translate(
                "JobRunner", "Checking whether {0} ({1}) was completed…"
            ).format(op.source, op.describe())
        )

    def _expect(self, op: Operation) -> None:
        self._targets = {self.station.profile.axis_index(a): v for a, v in op.target.items()}
        self._seen = dict.fromkeys(self._targets, 0)

    def _clear(self) -> None:
        super()._clear()
        self._targets = {}
        self._seen = {}

    def _on_frame(self, frame: object, raw: bytes) -> None:
        if self.in_flight is None:
            return
        if isinstance(frame, EchoFrame):
            for axis in self._seen:
                if axis < len(frame.packets) and frame.packets[axis].type == EchoType.POSITION:
                    self._seen[axis] += 1
        elif not isinstance(frame, Rejected):
            for axis in self._seen:
                self._seen[axis] += 1
        self._judge()

    def _judge(self) -> None:
        """Decide, from the machine's latest state, whether the operation in flight is over."""
        index = self.in_flight
        if index is None or not self._judging():
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
        source = self._source(index)
        if self.verifying:
            self._verify = False
            if arrived:
                self.runner.note(
                    QCoreApplication.translate(
                        "JobRunner", "Operation at {0} was already complete"
                    ).format(source)
                )
                self._done(index)
            else:
                self._dispatch(index)
            return
        if arrived:
            self._done(index)
            return
        for axis, target in axes:
            if axis.status_code == AxisStatus.END_SWITCH:
                self.runner.fail(
                    index,
                    QCoreApplication.translate(
                        "JobRunner", "{0} hit an end switch at {1} mm"
                    ).format(axis.name, number(axis.position)),
                )
                return
            if axis.status_code == AxisStatus.STOPPED:
                # Somebody stopped the machine (Esc): the job waits, resume sends the move again.
                self._verify = True
                self.runner.stop_short(
                    f"{axis.name} stopped short of {target:g} mm at {source}; "
                    "resume sends the move again"
                )
                return

    def _source(self, index: int) -> str:
        program = self.runner.program
        return str(program[index].source) if program is not None else "?"

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
