"""Running a point list on the three-axis USB unit: absolute targets as relative moves.

The unit only moves by counts from where it stands, and reports an axis's
position every 100 ms while it moves and once when it stops.  So an
operation's absolute target becomes, per axis, the reachable count nearest
to ``target - position``; the operation is done when a report *after* the
move was sent shows every moved axis where that count ends.

An axis *stands* only when it has fallen silent: the unit reports every
100 ms while an axis moves, but at its slowest speed a pulse can take
longer than that, so a report that repeats the last count does not prove
the axis stopped.  Short of its end, an operation is judged (stopped short,
or after a question: sent on) only once every axis of it is silent.

Because the moves are relative, sending one twice would move twice as far.
After a lost link the station's idea of the position is stale (the unit may
have finished, or run on, while nobody listened), so nothing is sent until
the unit has said where each axis stands: a move of nothing (which ends at
once, and so reports) asks it.  At the target, the operation counts as done;
short of it, the move is sent again from the reported position, toward the
same absolute target.  A unit that does not answer leaves the job paused.

An axis the session finds stopped at an end switch (FIDELITY S4-18) pauses
the job at once with that news, naming the axis and the end: the next step
is not sent into a machine that ran into its stop, and the operator decides
(resume asks where the axes stand and moves on toward the same target).
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.jobs.program import Operation, OpKind
from app.jobs.run.driver import RunnerPort
from app.jobs.run.sequential import SequentialDriver
from app.machine import LinkState
from app.machines.session import MachineSession
from app.machines.usb3.session import STILL_AFTER_S, Usb3Session
from protocol.usb3.codec import Position, count_to_mm

#: Station-clock seconds the unit has to show it started a move, or to say where it stands.
ANSWER_TIMEOUT_S = 2.0


class Usb3Driver(SequentialDriver):
    def __init__(self, runner: RunnerPort) -> None:
        super().__init__(runner)
        self._session: Usb3Session | None = None
        self._expected: dict[int, float] = {}  # axis → mm where its move ends (or the target)
        self._start: dict[int, float] = {}  # axis → mm where it stood when the move was sent
        #: Per axis of the operation: mm and station-clock time of its last report since the
        #: move (or the question) went out.
        self._heard: dict[int, tuple[float, float]] = {}
        self._since: float | None = None  # station-clock time the move or question went out
        #: Station-clock time the unit was asked where it stands because it fell silent short
        #: of the end: its answer, not the silence, says whether it stopped short.
        self._short_asked_at: float | None = None
        #: The last position each axis reported.  A report is judged as it is decoded, before
        #: the session folds it into the model, so the model lags by the report under judgement.
        self._last: dict[int, float] = {}

    def bind(self, session: MachineSession | None) -> None:
        if self._session is not None:
            try:
                self._session.frameReceived.disconnect(self._on_frame)
                self._session.ticked.disconnect(self._on_tick)
                self._session.settingsChanged.disconnect(self._forget_positions)
                self._session.endSwitchHit.disconnect(self._on_end_switch)
                self._session.moveRefused.disconnect(self._on_move_refused)
                self._session.model.linkStateChanged.disconnect(self._forget_positions)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self._session = session if isinstance(session, Usb3Session) else None
        self._forget_positions()
        if self._session is not None:
            # Direct, judged from the report itself: a queued report could arrive after the
            # next move went out and pass for that move's.
            self._session.frameReceived.connect(self._on_frame)
            # The session's periods are station-clock time, in the app and under test alike:
            # silence (an axis that stopped) and unanswered questions are judged on them.
            self._session.ticked.connect(self._on_tick)
            # Another thread changes what a count means: the model has the new positions.
            self._session.settingsChanged.connect(self._forget_positions)
            # Judged before the session's tick reaches _on_tick: the switch, not the silence.
            self._session.endSwitchHit.connect(self._on_end_switch)
            # A move the unit could not read (?;): it never ran, and the link is fine.
            self._session.moveRefused.connect(self._on_move_refused)
            # While nobody listens the unit may move (it runs its move out; its joystick).
            self._session.model.linkStateChanged.connect(self._forget_positions)

    def _send(self, index: int, op: Operation) -> None:
        session = self._session
        if session is None:
            self.runner.link_pause()
            return
        if op.kind is not OpKind.MOVE:
            self._unsupported(index, op)
            return
        profile = self.station.profile
        if any(profile.axis_index(name) not in self._last for name in op.target):
            # Nothing heard from an axis on this link yet (a new station, a unit moved by its
            # joystick or its menu meanwhile): a relative move needs to know where it starts.
            self._verify = True
            self._start_verify(index)
            return
        moves: dict[int, float] = {}
        start: dict[int, float] = {}
        for name, target in op.target.items():
            axis = profile.axis_index(name)
            start[axis] = self._last[axis]
            delta = session.reachable(axis, target - start[axis])
            if delta != 0.0:
                moves[axis] = delta
        if not moves:
            self._done(index)  # already there, to the step
            return
        self._start = {axis: start[axis] for axis in moves}
        self._expected = {axis: self._start[axis] + d for axis, d in moves.items()}
        self._heard = {}
        self._since = self.station.clock.now()
        self._short_asked_at = None
        for axis, delta in moves.items():
            if not session.move_relative(axis, delta, start=start[axis]):
                self._forget_move()
                self._refused_send(
                    index, QCoreApplication.translate("JobRunner", "the move was refused")
                )
                return

    def _start_verify(self, index: int) -> None:
        """Ask where the operation's axes stand; the answer decides (see the module's docstring)."""
        program = self.runner.program
        session = self._session
        assert program is not None
        op = program[index]
        if session is None or op.kind is not OpKind.MOVE:
            super()._start_verify(index)
            return
        profile = self.station.profile
        self._expected = {profile.axis_index(name): target for name, target in op.target.items()}
        self._start = {}
        self._heard = {}
        self._since = self.station.clock.now()
        self._short_asked_at = None
        self.runner.note(
            QCoreApplication.translate(
                "JobRunner", "Asking the unit where it stands ({0}, {1})…"
            ).format(op.source, op.describe())
        )
        session.request_positions(list(self._expected))

    def _clear(self) -> None:
        super()._clear()
        self._forget_move()

    def _forget_positions(self, *_: object) -> None:
        self._last = {}

    def _forget_move(self) -> None:
        self._expected = {}
        self._start = {}
        self._heard = {}
        self._since = None
        self._short_asked_at = None

    # --- replies ------------------------------------------------------------------

    def _on_frame(self, frame: object, raw: bytes) -> None:
        session = self._session
        if session is None or not isinstance(frame, Position):
            return
        axis = int(frame.axis)
        mm = self._last[axis] = count_to_mm(frame.count, session.threads[axis])
        if axis in self._expected:
            self._heard[axis] = (mm, self.station.clock.now())
            self._judge()

    def _on_end_switch(self, axis: int, which: str, mm: float) -> None:
        """An axis of the operation under way stopped at a switch: pause, say which."""
        index = self.in_flight
        if index is None or not self._judging() or axis not in self._expected:
            return
        self._forget_move()
        self._verify = True  # the resume asks where the axes stand before anything moves
        name = self.station.profile.axes[axis].name
        self.runner.stop_short(
            f"{name} stopped at its {which} end switch at {mm:.3f} mm during "
            f"{self._source(index)}: the job is paused; check the machine before resuming"
        )

    def _on_move_refused(self, axis: int, mm: float) -> None:
        """An axis of the operation under way never took its move (the unit answered ``?;``).

        The job pauses saying so, not as a lost link; the resume asks where the
        axes stand and moves them on toward the same absolute target, so the
        axes that did move are not moved twice.
        """
        index = self.in_flight
        if index is None or not self._judging() or axis not in self._expected:
            return
        if self.verifying:
            return  # asking where it stands: the question's own answer decides
        self._forget_move()
        self._verify = True
        name = self.station.profile.axes[axis].name
        self.runner.stop_short(
            f"The unit could not read the move of {name} at {self._source(index)} (it "
            f"answered ?;, a byte lost or changed on the wire) and {name} stayed at "
            f"{mm:.3f} mm: the job is paused; resume asks where the axes stand and moves "
            "them on to the target"
        )

    def _on_tick(self) -> None:
        if self._since is None or not self._judging():
            return
        self._judge()
        if self._since is not None and self.station.model.link_state is not LinkState.CONNECTED:
            # Nothing at all heard is the link's silence, for its liveness to judge (a lost
            # link pauses the job; the unit is asked again once it answers): the unit's own
            # time to answer counts from when the link is green again.
            self._since = self.station.clock.now()
            return
        if self._since is None or self.station.clock.now() - self._since < ANSWER_TIMEOUT_S:
            return
        if self._heard_news():
            return
        # A unit that neither starts the move nor answers the question holds the job.
        asked = self.verifying
        self._forget_move()
        self._verify = True  # the resume asks where it stands before anything moves
        if asked:
            text = "The unit did not say where it stands, so nothing was sent"
        else:
            text = "The unit did not start the move"
        self.runner.stop_short(f"{text}; check the machine, then resume to ask it again")

    def _heard_news(self) -> bool:
        """Whether a report shows the unit took the move (it moved) or answered the question."""
        if self.verifying:
            return bool(self._heard)
        return any(abs(mm - self._start[a]) > 1e-9 for a, (mm, _) in self._heard.items())

    def _silent(self) -> bool:
        """Every axis of the operation reported, and none has since STILL_AFTER_S."""
        now = self.station.clock.now()
        return self._heard.keys() == self._expected.keys() and all(
            now - at >= STILL_AFTER_S for _, at in self._heard.values()
        )

    def _judge(self) -> None:
        index = self.in_flight
        if index is None or not self._judging() or not self._expected:
            return
        if self._heard.keys() != self._expected.keys():
            return  # the station's position is stale until each axis has reported
        arrived = all(
            abs(self._heard[axis][0] - end) <= self._tolerance_mm(axis)
            for axis, end in self._expected.items()
        )
        if self.verifying:
            if not arrived and not self._silent():
                return  # still running out what it had: its silence decides
            self._verify = False
            self._forget_move()
            if arrived:
                self.runner.note(
                    QCoreApplication.translate(
                        "JobRunner", "Operation at {0} was already complete"
                    ).format(self._source(index))
                )
                self._done(index)
            else:
                self._dispatch(index)  # toward the same absolute target, from where it stands
            return
        if arrived:
            # A relative move ends exactly where its count ends: proof enough that it is over.
            self._done(index)
            return
        # Short of the end, only a unit that moved and fell silent again is judged: a report
        # that left it before the move arrived still shows the old position.
        if not self._heard_news() or not self._silent():
            return
        if not self._asked_after_silence():
            return
        self._forget_move()
        self._verify = True
        self.runner.stop_short(
            f"The unit stopped short at {self._source(index)}; resume moves it on to the target"
        )

    def _asked_after_silence(self) -> bool:
        """Whether the unit, silent short of the end, has said so itself when asked.

        Silence alone cannot tell a unit that stopped short from a link that went
        silent (a lost last report, a pulled cable): the unit is asked where it
        stands (a move of nothing, which reports), and only its answer, once it is
        silent again, is taken as a stop.  Unanswered, the link's liveness declares
        it lost and the job pauses for that; only a unit that goes on answering
        nothing else past :data:`ANSWER_TIMEOUT_S` is taken as stopped.
        """
        session = self._session
        now = self.station.clock.now()
        asked = self._short_asked_at
        if asked is None:
            if session is None:
                return True
            self._short_asked_at = now
            session.request_positions(list(self._expected))
            return False
        answered = all(at >= asked for _, at in self._heard.values())
        return answered or now - asked >= ANSWER_TIMEOUT_S

    def _tolerance_mm(self, axis: int) -> float:
        """Half a step at the axis's step size: the nearest the unit can come to a target."""
        session = self._session
        if session is None:
            return 1e-6
        counts = session.step_sizes[axis].counts_per_pulse
        return count_to_mm(counts, session.threads[axis]) / 2 + 1e-9

    def _source(self, index: int) -> str:
        program = self.runner.program
        return str(program[index].source) if program is not None else "?"
