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

Home first, park at the end, as the original tool did (FIDELITY S2-26).  The
drill cannot say whether it has homed (it answers only ``R``/``D``/``E``), so
the session counts an ``N`` it saw finish since the link opened; until then
the first operation sent is preceded by ``N`` (the pen raised first if the
job has it down) and, since homing moved the tool, by the moves back to where
the job stands.  After the last operation the tool goes to the profile's
park position through the motion gate, and ``P`` follows when that is where
``P`` parks anyway (X 0, Y at the back): it then only switches the motors off.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from functools import partial

from PySide6.QtCore import QCoreApplication

from app.jobs.program import Operation, OpKind, Program
from app.jobs.run.driver import RunnerPort
from app.jobs.run.sequential import SequentialDriver
from app.jobs.run.states import ACTIVE, JobState
from app.jobs.texts import number
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
        # The park after the last operation: under way, or done for this run.
        self._parking = False
        self._parked = False
        # Homing before the operator is asked anything (the job's first WAIT, a bit prompt).
        self._homing_first = False

    def bind(self, session: MachineSession | None) -> None:
        old = self._session
        if old is not None:
            try:
                old.commandReceived.disconnect(self._on_received)
                old.commandDone.disconnect(self._on_done)
                old.commandFailed.disconnect(self._on_failed)
                old.idle.disconnect(self._on_idle)
                old.commandUnasked.disconnect(self._on_unasked)
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
            self._session.commandUnasked.connect(self._on_unasked)
            self._session.frameSent.connect(self._on_sent)

    def _send(self, index: int, op: Operation) -> None:
        session = self._session
        if session is None:
            self.runner.link_pause()
            return
        if session.busy:
            # Commands of somebody else (the terminal) still run: ours would finish among them.
            self.runner.fail(
                index,
                QCoreApplication.translate("JobRunner", "the drill is busy with another command"),
            )
            return
        profile = self.station.profile
        sends: list[tuple[str, Callable[[], bool]]] = []
        if not session.homed_since_connect:
            sends += self._home_first(session, index)
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
                self._refused_send(
                    index, QCoreApplication.translate("JobRunner", "the drill refused it")
                )
                return

    def _dispatch(self, index: int) -> None:
        """As any sequential machine; a WAIT on a drill not yet homed homes first.

        So a job opens as the original's did, with ``N``, before the first bit
        prompt, and the operator changes bits with the carriage at rest.
        """
        program = self.runner.program
        session = self._session
        assert program is not None
        if (
            program[index].kind is OpKind.WAIT
            and session is not None
            and session.homes_before_job
            and self.link_up()
            and not session.busy
        ):
            sends = self._home_first(session, index)
            self._pending = [letter for letter, _ in sends]
            self._homing_first = True
            for _, send in sends:
                if not send():
                    self._pending = []
                    self._homing_first = False
                    self._refused_send(
                        index, QCoreApplication.translate("JobRunner", "the drill refused to home")
                    )
                    return
            return
        super()._dispatch(index)

    def _home_first(
        self, session: DrillSession, index: int
    ) -> list[tuple[str, Callable[[], bool]]]:
        """``N`` before operation ``index``, and back to where the job stands there."""
        program = self.runner.program
        assert program is not None
        where, pen_down = _state_before(program, index)
        self.runner.note(
            QCoreApplication.translate(
                "JobRunner",
                "The drill cannot report whether it has homed, and the station has not seen it "
                "home since this link opened: homing first (N)",
            )
        )
        sends: list[tuple[str, Callable[[], bool]]] = []
        if pen_down:
            sends.append(("Z", partial(session.pen, False)))
        sends.append(("N", partial(session.home, 0)))
        profile = self.station.profile
        for name, target in where.items():
            sends.append((name, partial(session.move_absolute, profile.axis_index(name), target)))
        if pen_down:
            sends.append(("K", partial(session.pen, True)))
        return sends

    def wind_up(self) -> bool:
        """Park at the profile's park position (then ``P`` if that is P's own place)."""
        park = self.station.profile.park
        session = self._session
        if self._parked or not park:
            return True
        if self._parking:
            return False
        if session is None or not self.link_up():
            self.runner.link_pause()
            return False
        profile = self.station.profile
        sends: list[tuple[str, Callable[[], bool]]] = [
            (name, partial(session.move_absolute, profile.axis_index(name), target))
            for name, target in park.items()
        ]
        if _is_firmware_park(park, profile.travel_limits()):
            sends.append(("P", session.park))
        self._pending = [letter for letter, _ in sends]
        self._parking = True
        self.runner.note(
            QCoreApplication.translate("JobRunner", "Parking at {0}").format(
                " ".join(f"{name}{number(value, '.3f')}" for name, value in park.items())
            )
        )
        for letter, send in sends:
            if not send():
                self._pending = []
                self._parking = False
                if not self.link_up():
                    self.runner.link_pause()
                    return False
                self.runner.note(_not_parked(letter))
                self._parked = True
                return True
        return False

    def begin(self, index: int, *, verify: bool) -> None:
        self._parked = False
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
                QCoreApplication.translate(
                    "JobRunner",
                    "Drill cycle at {0} was received by the machine, which finishes it "
                    "on its own: counted as done",
                ).format(op.source)
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

    def link_lost(self) -> None:
        """What was queued went with the link: a park or a homing is started again on resume."""
        if self._parking or self._homing_first:
            self._parking = False
            self._homing_first = False
            self._pending = []
        super().link_lost()

    def _clear(self) -> None:
        super()._clear()
        self._parking = False
        self._homing_first = False
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
        if (self.in_flight is None and not self._parking) or not self._pending:
            return
        if text[:1] == self._pending[0]:
            self._pending.pop(0)

    def _on_idle(self) -> None:
        if self._parking:
            if not self._pending:
                self._parking = False
                self._parked = True
                if self.runner.state is JobState.RUNNING:
                    self.runner.finish()
            return
        index = self.in_flight
        if self._homing_first:
            if self._pending or index is None:
                return
            self._homing_first = False
            if self.runner.state is JobState.RUNNING:
                self._dispatch(index)  # homed: now the prompt
            elif self.runner.state is JobState.PAUSING:
                self.runner.pause_reached()  # the prompt comes on resume
            return
        if index is None or self.verifying or not self._judging():
            return
        program = self.runner.program
        if program is None or program[index].kind in (OpKind.WAIT, OpKind.COMMENT):
            return
        if self._pending:
            return
        self._done(index)

    def _on_failed(self, text: str) -> None:
        if self._parking:
            # Every hole is done; a refused park leaves the tool where it is, said so.
            self._pending = []
            self._parking = False
            self._parked = True
            self.runner.note(_not_parked(text))
            if self.runner.state is JobState.RUNNING:
                self.runner.finish()
            return
        if self.in_flight is None or self.runner.state not in ACTIVE:
            return
        self._pending = []
        self.runner.fail(
            self.in_flight,
            QCoreApplication.translate("JobRunner", "the drill refused {0}").format(text),
        )

    def _on_unasked(self, heard: str) -> None:
        """The drill ran what the station did not send: the job is not done as the file says.

        The drill has no stop command, so what it queued still runs; the job
        stops sending and fails, never "done" past a hole drilled twice or elsewhere.
        """
        if self.runner.state not in ACTIVE:
            return
        program = self.runner.program
        index = self.in_flight
        if index is None:
            index = max(0, self.runner.done - 1) if program is not None else 0
        self._pending = []
        self._parking = False
        self.runner.fail(
            index,
            QCoreApplication.translate(
                "DrillDriver",
                "the drill ran a command the station did not send ({0}): a hole may have been "
                "drilled twice or in the wrong place; look at the board",
            ).format(heard),
        )


def _state_before(program: Program, index: int) -> tuple[dict[str, float], bool]:
    """Where the job has put the tool before operation ``index``, and whether its pen is down."""
    where: dict[str, float] = {}
    pen_down = False
    for op in program.operations[:index]:
        if op.kind is OpKind.MOVE:
            where.update(op.target)
        elif op.kind is OpKind.PEN_DOWN:
            pen_down = True
        elif op.kind is OpKind.PEN_UP:
            pen_down = False
    return where, pen_down


def _is_firmware_park(park: Mapping[str, float], limits: Mapping[str, tuple[float, float]]) -> bool:
    """Whether ``park`` is where the drill's own ``P`` goes: X at 0, Y at the back."""
    x, y = park.get("X"), park.get("Y")
    back = limits.get("Y", (0.0, 0.0))[1]
    return x is not None and y is not None and abs(x) < 1e-9 and abs(y - back) < 1e-9


def _not_parked(what: str) -> str:
    return QCoreApplication.translate("JobRunner", "Not parked: the drill refused {0}").format(what)
