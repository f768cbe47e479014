"""Running a program on the PCB drill/plotter: one-letter procedures, one at a time.

A MOVE becomes ``X`` then ``Y`` (one per axis of its target), a DRILL ``V``,
PEN_DOWN/UP ``K``/``Z``.  The device reports every procedure itself (``R``
received, ``D`` done), so an operation is complete when the session goes
idle after the ``D`` of each of its commands; an ``E`` fails the job at the
operation's line.

When the link goes, the operation in flight is held as not done and
re-examined on resume: a MOVE is simply sent again (absolute microsteps,
harmless whether or not it was finished); a DRILL whose ``V`` had been
received (``RV`` seen) counts as done, because the machine runs a procedure
it has accepted to its end on its own and drilling the hole again would
enlarge it; a DRILL whose ``RV`` never arrived is sent again.  After a
station restart nothing is known of the last ``RV``, so the checkpoint's
next DRILL is sent again.
"""

from __future__ import annotations

from collections.abc import Callable
from functools import partial

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

    def bind(self, session: MachineSession | None) -> None:
        old = self._session
        if old is not None:
            try:
                old.commandReceived.disconnect(self._on_received)
                old.commandDone.disconnect(self._on_done)
                old.commandFailed.disconnect(self._on_failed)
                old.idle.disconnect(self._on_idle)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self._session = session if isinstance(session, DrillSession) else None
        if self._session is not None:
            # Direct: each reply is judged as it is decoded, before the next one can arrive.
            self._session.commandReceived.connect(self._on_received)
            self._session.commandDone.connect(self._on_done)
            self._session.commandFailed.connect(self._on_failed)
            self._session.idle.connect(self._on_idle)

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
        for _, send in sends:
            if not send():
                self._pending = []
                self._refused_send(index, "the drill refused it")
                return

    def _start_verify(self, index: int) -> None:
        """After a lost link: a DRILL the device had received is done; anything else goes again."""
        program = self.runner.program
        assert program is not None
        op = program[index]
        self._verify = False
        if op.kind is OpKind.DRILL and self._received:
            self.runner.note(
                f"Drill cycle at {op.source} was received by the machine, which finishes it "
                "on its own: counted as done"
            )
            self._done(index)
            return
        self._dispatch(index)

    def _clear(self) -> None:
        super()._clear()
        self._pending = []
        self._received = False

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
