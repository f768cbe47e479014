"""A job's progress and clock: the counts the views see, coalesced, and the ETA.

A streaming job answers a line every millisecond or so; the views hear of
its progress at most every :data:`PROGRESS_INTERVAL_MS` on a real-time
station (and with every state change), so a thousand answered lines a second
cost the GUI thirty redraws, not a thousand.  The elapsed time is the wall
clock's from the run's start to its end, prompts and pauses included (what the
operator lived through: a drill job of 24 s said "00:14" when it left out its
bit changes); how much of it the machine stood waiting for the operator is
told apart.  The ETA is the dry-run estimate's machine time still to go after
the operations done.

The runner owns the signals and the states; this keeps the figures and says
when to tell them (:class:`JobProgress`).  A streaming driver paces its
checkpoints and announcements with :class:`~app.jobs.run.pacing.Every`.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QObject, QTimer, SignalInstance

from app.jobs.estimate import Estimate, estimate, parameters_from_model
from app.jobs.program import Program
from app.station import Station

ETA_INTERVAL_MS = 1000
#: Waiting shorter than this is not worth a word (a prompt answered at once).
WAITING_SHOWN_S = 0.5
#: A streaming job answers a line every millisecond or so: the views hear of progress at
#: most this often (a real-time station), never once per line.
PROGRESS_INTERVAL_MS = 33


class JobProgress(QObject):
    """Operations done and executed, the job's running time, and the views told of both."""

    def __init__(
        self,
        station: Station,
        total: Callable[[], int],
        progress_changed: SignalInstance,
        executed_changed: SignalInstance,
        eta_changed: SignalInstance,
        operation_done: SignalInstance,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._total = total
        self._progress_changed = progress_changed
        self._executed_changed = executed_changed
        self._eta_changed = eta_changed
        self._operation_done = operation_done
        self.done = 0  # operations [0, done) are complete
        #: Operations ``[0, executed)`` are reported run by the machine (≤ ``done``): on a
        #: G-code machine ``done`` counts the lines the device answered, many of which may
        #: still wait in its planner; ``executed`` only those known to have run.
        self.executed = 0
        self.estimate: Estimate | None = None
        #: The job is done: nothing is left, whatever was reported last.
        self.ended = False
        self._eta_told_at = 0.0
        self._elapsed_before = 0.0
        self._running_since: float | None = None
        #: Station-clock times the run began and ended (None: not begun / not ended).
        self._started_at: float | None = None
        self._ended_at: float | None = None
        self._eta_timer = QTimer(self)
        self._eta_timer.setInterval(ETA_INTERVAL_MS)
        self._eta_timer.timeout.connect(self.emit_eta)
        #: Progress told to the views (done, executed), and the timer that coalesces it.
        self._told: tuple[int, int] = (0, 0)
        self._timer = QTimer(self)
        self._timer.setSingleShot(True)
        self._timer.setInterval(PROGRESS_INTERVAL_MS)
        self._timer.timeout.connect(self.tell)

    # --- counts ----------------------------------------------------------------------

    def set_executed(self, executed: int) -> None:
        executed = min(executed, self.done)
        if executed != self.executed:
            self.executed = executed
            self._told = (self._told[0], executed)
            self._executed_changed.emit(executed, self._total())

    def restart(self, index: int) -> None:
        """A run begins at operation ``index``: counts there, no time spent yet."""
        self.done = index
        self.set_executed(index)
        self._elapsed_before = 0.0
        self._running_since = None
        self._started_at = None
        self._ended_at = None
        self.ended = False

    def tell_all(self) -> None:
        """Both counts to the views now (a job loaded)."""
        self._progress_changed.emit(self.done, self._total())
        self._told = (self.done, self.executed)
        self._executed_changed.emit(self.executed, self._total())

    def tell_done(self) -> None:
        """The done count to the views now (a run began)."""
        self._progress_changed.emit(self.done, self._total())
        self._told = (self.done, self.executed)

    def reached(self, index: int) -> None:
        """Operation ``index`` is done, reported so by the machine: it ran."""
        self.done = index + 1
        self.set_executed(self.done)

    def tell_reached(self, index: int) -> None:
        """:meth:`reached`'s operation to the views, and the time (its checkpoint is written)."""
        self._operation_done.emit(index)
        self._progress_changed.emit(self.done, self._total())
        self._told = (self.done, self.executed)
        self.emit_eta()

    def advance(self, done: int, executed: int | None = None) -> None:
        """A streaming driver's progress, kept at once and told to the views coalesced."""
        self.done = done
        self.executed = min(done if executed is None else executed, done)
        if not self._station.realtime:
            self.tell()
        elif not self._timer.isActive():
            self._timer.start()

    def tell(self) -> None:
        """Emit what changed since the views were last told (see :meth:`advance`)."""
        self._timer.stop()
        told_done, told_executed = self._told
        self._told = (self.done, self.executed)
        total = self._total()
        if self.done != told_done:
            if self.done:
                self._operation_done.emit(self.done - 1)
            self._progress_changed.emit(self.done, total)
        if self.executed != told_executed:
            self._executed_changed.emit(self.executed, total)
        self._eta_on_the_clock()

    def flush(self) -> None:
        """Progress held back for the timer is told now (a state change comes with it)."""
        if self._timer.isActive():
            self.tell()

    # --- time ------------------------------------------------------------------------

    def clock(self, was_running: bool, runs: bool, active: bool = False) -> None:
        """The job's state changes: its clocks follow.

        ``runs``: operations are being sent; ``active``: the job owns the machine
        (running, paused or waiting for the operator); the wall clock runs from
        the first active state to the first that is not.
        """
        now = self._station.clock.now()
        if was_running and not runs and self._running_since is not None:
            self._elapsed_before += now - self._running_since
            self._running_since = None
        elif runs and not was_running:
            self._running_since = now
        if (runs or active) and self._started_at is None:
            self._started_at = now
        elif not (runs or active) and self._started_at is not None and self._ended_at is None:
            self._ended_at = now
        if (runs or active) and self._station.realtime:
            self._eta_timer.start()  # the elapsed time goes on while a prompt waits
        elif not (runs or active):
            self._eta_timer.stop()

    @property
    def running_s(self) -> float:
        """Station-clock time spent running, without paused and waiting stretches."""
        if self._running_since is None:
            return self._elapsed_before
        return self._elapsed_before + self._station.clock.now() - self._running_since

    @property
    def elapsed_s(self) -> float:
        """Wall-clock (station-clock) time from the run's start to its end, or to now."""
        if self._started_at is None:
            return 0.0
        end = self._ended_at if self._ended_at is not None else self._station.clock.now()
        return max(0.0, end - self._started_at)

    @property
    def waiting_s(self) -> float:
        """Of :attr:`elapsed_s`, the time the job stood: at a prompt, paused, held."""
        return max(0.0, self.elapsed_s - self.running_s)

    @property
    def remaining_s(self) -> float:
        """The model's time still to go; the estimate's figure, not rescaled by the real one."""
        if self.estimate is None or self.ended:
            return 0.0  # done is done, also when the driver ended past the last report (park)
        return self.estimate.remaining_after(self.done)

    def emit_eta(self) -> None:
        """Tell the views elapsed and remaining time (a timer calls this every second)."""
        self._eta_told_at = self._station.clock.now()
        self._eta_changed.emit(self.elapsed_s, self.remaining_s)

    def _eta_on_the_clock(self) -> None:
        """On a station clock that is not real time (tests, screenshots) no timer ticks:
        progress tells the time once per second of that clock instead."""
        if not self._station.realtime and self._started_at is not None:
            if self._station.clock.now() - self._eta_told_at >= ETA_INTERVAL_MS / 1000:
                self.emit_eta()


def estimate_inputs(station: Station) -> Callable[[Program], Estimate]:
    """The dry-run estimate with the machine's settings and position as they are now
    (read here, on the GUI thread; the function returned may run on any)."""
    model = station.model
    session = station.session
    profile = station.profile
    start = {axis.name: axis.work_position for axis in model.axes}
    parameters = parameters_from_model(model)
    period_s = (session.period_ms if session is not None else station.period_ms) / 1000
    fast = session.fast_selected if session is not None else True
    speeds = session.top_speeds_mm_s() if session is not None else None
    home_first = session.homes_before_job if session is not None else False

    def timed(program: Program) -> Estimate:
        return estimate(
            program,
            profile,
            parameters,
            period_s,
            fast=fast,
            start=start,
            speeds_mm_s=speeds,
            home_first=home_first,
        )

    return timed
