"""Running a program on the PCB drill/plotter: one-letter procedures, one at a time.

A MOVE becomes ``X`` then ``Y`` (one per axis of its target), a DRILL ``V``,
PEN_DOWN/UP ``K``/``Z``.  The device reports every procedure itself (``R``
received, ``D`` done), so an operation is complete when the session goes
idle after the ``D`` of each of its commands; an ``E`` fails the job at the
operation's line.

When the link goes, the operation in flight is held as not done and
re-examined on resume.  The drill cannot be asked what it did, so the rule
uses only what it said before the link went:

* a MOVE or a pen movement is simply sent again (absolute microsteps, a pen
  position: harmless whether or not it was done);
* a DRILL whose ``V`` was received (``RV`` seen) counts as done: the machine
  runs a procedure it has accepted to its end on its own, and drilling the
  hole again would enlarge it;
* a DRILL whose ``V`` never left the station is sent;
* a DRILL whose ``V`` was written but never acknowledged may or may not have
  been drilled (the ``V`` or its ``RV`` was lost), and so may the checkpoint's
  next DRILL after a station restart: the operator decides, looking at the
  board, with the hole marked in the preview.  Never a silent resend.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

from PySide6.QtCore import QCoreApplication

from app.jobs.program import Operation, OpKind
from app.jobs.run.driver import RunnerPort
from app.jobs.run.sequential import SequentialDriver
from app.jobs.run.states import ACTIVE
from app.machines.drill.session import DrillSession
from app.machines.session import MachineSession


class DrillDriver(SequentialDriver):
    def __init__(self, runner: RunnerPort) -> None:
        super().__init__(runner)
        self._session: DrillSession | None = None
        # Letters of the in-flight operation's commands not yet done (``D``), and whether
        # the device acknowledged (``R``) the drill cycle of a DRILL.
        self._pending: list[str] = []
        self._received = False
        self._written = False  # the in-flight DRILL's V went out on the wire

    def bind(self, session: MachineSession | None) -> None:
        old = self._session
        if old is not None:
            try:
                old.commandReceived.disconnect(self._on_received)
                old.commandDone.disconnect(self._on_done)
                old.commandFailed.disconnect(self._on_failed)
                old.idle.disconnect(self._on_idle)
                old.frameSent.disconnect(self._on_sent)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self._session = session if isinstance(session, DrillSession) else None
        if self._session is not None:
            # Direct: each reply is judged as it is decoded, before the next one can arrive.
            self._session.commandReceived.connect(self._on_received)
            self._session.commandDone.connect(self._on_done)
            self._session.commandFailed.connect(self._on_failed)
            self._session.idle.connect(self._on_idle)
            self._session.frameSent.connect(self._on_sent)

    def _send(self, index: int, op: Operation) -> None:
        session = self._session
        if session is None:
            self.runner.link_pause()
            return
        if session.busy:
            # Commands of somebody else (the terminal) still run: ours would finish among them.
            self.runner.fail(index, "the drill is busy with another command")
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
            self._unsupported(index, op)
            return
        self._pending = [letter for letter, _ in sends]
        self._received = False
        self._written = False
        for _, send in sends:
            if not send():
                self._pending = []
                self._refused_send(index, "the drill refused it")
                return

    def begin(self, index: int, *, verify: bool) -> None:
        super().begin(index, verify=verify)
        program = self.runner.program
        assert program is not None
        if verify and index < len(program) and program[index].kind is OpKind.DRILL:
            # A new station knows nothing of what the last one sent: the V may have gone.
            self._in_flight = index
            self._verify = True
            self._written = True

    def _start_verify(self, index: int) -> None:
        """After a lost link: what the drill said before it went decides (module docstring)."""
        program = self.runner.program
        assert program is not None
        op = program[index]
        if op.kind is not OpKind.DRILL or not (self._received or self._written):
            self._verify = False
            self._dispatch(index)
            return
        if self._received:
            self._verify = False
            self.runner.note(
                f"Drill cycle at {op.source} was received by the machine, which finishes it "
                "on its own: counted as done"
            )
            self._done(index)
            return
        self.runner.ask(
            index,
            QCoreApplication.translate(
                "DrillDriver",
                "The hole at {0} may or may not have been drilled: the link went before "
                "the drill confirmed the command. Look at the board (the hole is marked in the "
                "preview), then drill it again or count it as drilled.",
            ).format(op.source),
            QCoreApplication.translate("DrillDriver", "Drill it again"),
            QCoreApplication.translate("DrillDriver", "Count it as drilled"),
        )

    def _clear(self) -> None:
        super()._clear()
        self._pending = []
        self._received = False
        self._written = False

    def _on_sent(self, command: object, raw: bytes) -> None:
        if self.in_flight is not None and self._pending and raw.startswith(b"V"):
            self._written = True

    def _on_received(self, text: str) -> None:
        if self.in_flight is not None and self._pending and text == "V":
            self._received = True

    def _on_done(self, text: str) -> None:
        if self.in_flight is None or not self._pending:
            return
        if text[:1] == self._pending[0]:
            self._pending.pop(0)

    def _on_idle(self) -> None:
        index = self.in_flight
        if index is None or self.verifying or not self._judging():
            return
        program = self.runner.program
        if program is None or program[index].kind in (OpKind.WAIT, OpKind.COMMENT):
            return
        if self._pending:
            return
        self._done(index)

    def _on_failed(self, text: str) -> None:
        if self.in_flight is None or self.runner.state not in ACTIVE:
            return
        self._pending = []
        self.runner.fail(self.in_flight, f"the drill refused {text}")
