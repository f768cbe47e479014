"""Running a program on a G-code machine: streaming lines, judged from ``ok`` and status.

Here many operations are under way at once (see :mod:`app.jobs.run.gcode_stream`
for what counts as answered and executed): the device's planner holds the
lines answered but not yet run.  After a lost link or a reset the driver
looks at the machine (a status report) before anything is sent again, and
resumes from the first operation not known to have run, retracing the
program's own path back to where the machine stands.

While the job runs its lines are pulled, and its answers counted, by the
session's feeder on the transport's reader thread (see
:mod:`app.machines.gcode.feeder`): the wire stays full whatever the window
is doing.  The job goes through one :class:`~app.machines.gcode.job_feed.JobFeed`
this driver starts (:meth:`GcodeSession.start_job`), lets be pulled only while
the job runs, holds, and releases; it hears of its answers once per batch
(``jobAdvanced``), and reads and changes the stream under the feed's lock.

Positions are compared in the program's coordinates: the machine position
less the work offset (GRBL's G92) the board had when the job began — the
work position, as long as the offset stays — so a job run after a ``G92``
finds its place on its path, and the way back is sent as the work
coordinates that reach it with the offset the board has then.
"""

from __future__ import annotations

from dataclasses import replace

from PySide6.QtCore import QCoreApplication

from app.jobs.run.driver import ResumeChoice, RunnerPort
from app.jobs.run.gcode_alarm_pause import GcodeAlarmPause
from app.jobs.run.gcode_alarm_pause import where_in as _where
from app.jobs.run.gcode_books import offset_on as _offset
from app.jobs.run.gcode_stream import (
    RETRACE_WINDOW,
    AtReport,
    GcodeStream,
    preamble,
    resume_state,
    retrace,
)
from app.jobs.run.pacing import Every
from app.jobs.run.standing import Standing, StandingProof
from app.jobs.run.start_point import StartPlan, StartRefused, plan_start
from app.jobs.run.states import ACTIVE, CLOCK_RUNS, JobState
from app.machines.gcode.feeder import PullGate
from app.machines.gcode.job_feed import JobFeed
from app.machines.gcode.session import GcodeSession, SentLine
from app.machines.session import MachineSession
from protocol.gcode.codec import Feedback, StatusReport

#: Station-clock seconds between checkpoint writes while lines stream (each write is an fsync).
CHECKPOINT_EVERY_S = 0.5
#: Station-clock seconds between "operation under way" announcements while lines stream.
SHOW_EVERY_S = 0.1
#: The modal words a program is checked in (absolute, millimetres, XY plane), sent before
#: its first line where the machine has them: a jog or a console line may have changed them.
SETUP_WORDS = ("G90", "G21", "G17")
# GRBL's ``error:9``: G-code locked out while the board is in alarm.
LOCKED_IN_ALARM = 9
# A set-up whose ``$G`` answer was lost is sent again this often before the job fails.
SETUP_CONFIRM_TRIES = 3


def session_holds_unasked(session: GcodeSession | None) -> bool:
    """Whether the session's board holds with no stop of the station's under way."""
    return session is not None and not session.stopping


def setup_lines(words: tuple[str, ...]) -> list[str]:
    """The set-up a job starts with on a machine whose repertoire is ``words``."""
    present = [word for word in SETUP_WORDS if word in words]
    return [" ".join(present)] if present else []


def modes_confirm(modes: str, words: tuple[str, ...]) -> str | None:
    """What is wrong with a ``[GC:…]`` line after the set-up (None: the machine is set up)."""
    stated = set(modes.strip("[]").removeprefix("GC:").split())
    missing = [word for word in SETUP_WORDS if word in words and word not in stated]
    return f"still not in {' '.join(missing)} after the set-up ({modes})" if missing else None


def setup_gate(words: tuple[str, ...]) -> PullGate[SentLine]:
    """The set-up's confirmation judged where it is read: the ``[GC:…]`` answering the
    set-up's own ``$G`` lets the job go there when :func:`modes_confirm` finds nothing wrong,
    the check the driver makes of it too (:meth:`GcodeDriver._judge_setup`)."""

    def lets_go(reply: object) -> bool:
        text = reply.text if isinstance(reply, Feedback) else ""
        return text.startswith("[GC:") and modes_confirm(text, words) is None

    return PullGate(lambda sent: sent.origin == "setup" and sent.text == "$G", lets_go)


class GcodeDriver(GcodeAlarmPause):
    """Feeds the runner's program to the G-code session and reports progress to the runner."""

    takes_gcode = True

    def __init__(self, runner: RunnerPort) -> None:
        super().__init__(runner)
        self.stream: GcodeStream | None = None
        #: The work offset when the job began: program coordinates are machine less it.
        self._origin: tuple[float, ...] = ()
        #: Where the machine stood when the job began, in the program's coordinates (None
        #: when the run began elsewhere than operation 0): standing there again after a fault
        #: may mean nothing ran as well as that the file came back to it.
        self._start_at: tuple[float, ...] | None = None
        self.session: GcodeSession | None = None
        #: The running job's way to the wire (None without a stream or a session).
        self.feed: JobFeed | None = None
        self._waiting: int | None = None  # the WAIT the operator is asked to confirm
        self._recheck = False  # look at the machine before sending again
        #: The last ``[GC:…]`` heard while the set-up is confirmed, awaiting its line's ``ok``.
        self._modes_heard: str | None = None
        self._asked_since_recheck = False
        #: Checkpoints while lines stream, and "operation under way" announcements, are paced.
        self._checkpoints = Every(CHECKPOINT_EVERY_S)
        self._shown: int | None = None
        self._shows = Every(SHOW_EVERY_S)
        #: ``$G`` was sent after the set-up: nothing of the job goes before its answer.
        self._confirming = False
        #: The operation the last resume went back to (a refused way back fails there).
        self._resume_at = 0
        #: Set-up and way-back lines sent and not yet answered: the job waits for them, so
        #: that none of its lines runs on a machine they did not set up.
        self._preparing = 0
        #: A pause took back the set-up before it went: it goes again first on the resume.
        self._redo_setup = False
        #: The board reset itself since the job began or last resumed: its position is lost.
        self._position_lost = False
        #: The operation the operator chose to resume from (ResumeChoice), not yet gone on.
        self._chosen: int | None = None
        #: A ResumeChoice waits for the operator's pick.
        self._choice_open = False
        #: Judges whether the board stands before anything of a resume goes (see standing.py).
        self._standing = StandingProof()
        #: The board went into a feed hold the station did not ask for (its hold button, or
        #: a ``!`` that reached it on the wire): the job is paused, and its resume is a
        #: cycle start — the board still has every line it was sent.
        self._held_by_machine = False
        #: The operator's chosen start (its state rebuilt once the machine is looked at).
        self._start: StartPlan | None = None
        # The job is paused for an alarm, said once: a restart the board adds to it (GRBL
        #: follows ALARM:3 with its banner) is kept for the Resume, not said again.
        self._alarm_said = False
        # Set-ups whose confirmation was lost in this run (see _unconfirmed).
        self._unconfirmed_count = 0
        # This run knows every line the device may have (see _sent_upto).
        self._written_known = False

    def _hold(self) -> None:
        """Pull nothing more of the job (what is queued stays)."""
        if self.feed is not None:
            self.feed.hold()

    @property
    def in_flight(self) -> int | None:
        if self._waiting is not None:
            return self._waiting
        stream = self.stream
        if stream is None:
            return None
        with self._locked():
            return stream.pending[0] if stream.pending else None

    # --- session wiring --------------------------------------------------------

    def bind(self, session: MachineSession | None) -> None:
        old = self.session
        if old is not None:
            try:
                self._follow(stream_too=False)
                old.linesSent.disconnect(self._on_sent)
                old.jobAdvanced.disconnect(self._on_advanced)
                old.lineAcknowledged.disconnect(self._on_line_ok)
                old.lineFailed.disconnect(self._on_error)
                old.statusChanged.disconnect(self._on_status)
                old.reset.disconnect(self._on_reset)
                old.alarmed.disconnect(self._on_alarm)
                old.replyText.disconnect(self._on_reply_text)
            except (RuntimeError, TypeError):
                pass  # already deleted with its link
        self.session = session if isinstance(session, GcodeSession) else None
        if self.session is not None:
            self.session.linesSent.connect(self._on_sent)
            self.session.jobAdvanced.connect(self._on_advanced)
            self.session.lineAcknowledged.connect(self._on_line_ok)
            self.session.lineFailed.connect(self._on_error)
            self.session.statusChanged.connect(self._on_status)
            self.session.reset.connect(self._on_reset)
            self.session.alarmed.connect(self._on_alarm)
            self.session.replyText.connect(self._on_reply_text)
            self._follow()

    def _follow(self, *, stream_too: bool = True) -> None:
        """The session counts this job's answers (and may be let pull its lines); the feed of
        the one before is released (``stream_too`` False: no new one is started)."""
        feed, self.feed = self.feed, None
        if feed is not None:
            feed.release()
        session, stream = self.session, self.stream
        if stream_too and session is not None and stream is not None:
            self.feed = session.start_job(stream)

    # --- what the runner asks ----------------------------------------------------

    def begin(self, index: int, *, verify: bool) -> None:
        """Start streaming at operation ``index``; after a restart look at the machine first."""
        runner = self.runner
        assert runner.program is not None
        self.stream = GcodeStream(runner.program, runner.station.profile, index)
        sent = runner.checkpoint_sent if verify else None
        if sent is not None and sent > index:
            self.stream.written = sent  # what the interrupted run may have got to the machine
        self._written_known = not verify or sent is not None
        self._follow()
        session = self.session
        # The program's coordinates are the machine's less the work offset it had when the
        # job began (GRBL's G92 offset; 0 elsewhere); the file's own G92 lines keep that so,
        # as the loader applies them as GRBL does.
        self._origin = tuple(session.work_offset or ()) if session is not None else ()
        self._start_at = None
        if index == 0 and not verify and session is not None:
            self._start_at = tuple(
                axis.position - _offset(self._origin, i)
                for i, axis in enumerate(session.model.axes)
            )
        self._waiting = None
        self._recheck = verify
        self._asked_since_recheck = False
        self._confirming = False
        self._preparing = 0
        self._redo_setup = False
        self._position_lost = False
        self._chosen = None
        self._choice_open = False
        self._held_by_machine = False
        self._start = None
        self._alarm_said = False
        self._unconfirmed_count = 0
        if index == 0 and not verify and session is not None:
            self._set_up(session)

    def start_refusal(self, index: int) -> str | None:
        """Whether the file's state at ``index`` can be rebuilt (see start_point.py)."""
        program = self.runner.program
        assert program is not None
        try:
            self._start = plan_start(program, index, [a.name for a in self.station.profile.axes])
        except StartRefused as exc:
            self._start = None
            return str(exc)
        return None

    def start_at(self, index: int) -> None:
        """Looked at first, as a resume: then set up as the file had it, and on from there."""
        plan = self._start if self._start is not None and self._start.index == index else None
        self.begin(index, verify=True)
        self._start, self._chosen = plan, index
        if self.stream is not None and plan is not None:
            self.stream.lead = plan.lead

    def _set_up(self, session: GcodeSession) -> None:
        """The machine in the state the program was checked for, confirmed where it can say.

        A jog, a console line or an earlier job may have left it relative, in
        inches or on another plane; a file that never says G90 would then run
        wherever that put it.
        """
        words = session.settings.words
        self._hold()  # nothing of the job is pulled until the set-up is confirmed
        self._modes_heard = None
        for line in setup_lines(words):
            self._preparing += session.send_line(line, "setup")
        if "$G" in words:
            self._confirming = session.send_line("$G", "setup")

    def link_lost(self) -> None:
        """The lines the device had may or may not run: decide when it is back."""
        self._held_by_machine = False  # the recheck looks at the hold (and resets out of it)
        if self.stream is not None:
            self._recheck = True
            self._asked_since_recheck = False
            self._preparing = 0  # lost with the link: the recheck sets the machine up again
            if self._confirming:
                # The set-up's ``$G`` (or its answer) may be lost with the link: waiting for
                # it would hold the job for good.  The set-up is checked again once back.
                self._confirming = False
                self._redo_setup = True
            self._write_checkpoint(force=True)

    def proceed(self) -> None:
        """Send what may be sent now; end, wait or pause when the stream says so."""
        self._proceed()

    def _proceed(self) -> bool:
        """:meth:`proceed`; True when it has told the runner the progress (it fed lines)."""
        runner = self.runner
        stream, session, feed = self.stream, self.session, self.feed
        if stream is None or session is None or feed is None:
            runner.link_pause()
            return False
        running = runner.state is JobState.RUNNING
        if self._held_by_machine and running:
            self._held_by_machine = False
            session.cycle_start()  # out of the hold: the board goes on with what it has
        if self._redo_setup and running and not self._recheck:
            self._redo_setup = False
            self._set_up(session)
        preparing = self._confirming or self._preparing > 0
        held = self._recheck or not running or runner.single_step
        if self._confirming and not held:
            # Held for the set-up's answer; a [GC:…] that confirms it lets the job go where
            # it is read, a GUI turn sooner (a wrong one holds it, and fails it here).
            feed.pull_when(setup_gate(session.settings.words))
        elif preparing or held:
            self._hold()  # the job is pulled only while it runs on its own
        if preparing:
            return False  # the answer to the set-up or the way back carries on
        if self._recheck and running and session.limit_lock.waiting:
            self._hold_in_alarm()  # GRBL's lock after a limit: no report comes before a reset
            return False
        if self._recheck:
            if not self._asked_since_recheck:
                self._asked_since_recheck = True
                self._standing.forget()  # a new look: only reports from now on count
                session.query_status()
            return False  # _on_status carries on
        if runner.state is not JobState.RUNNING:
            return False
        with feed.locked():
            if runner.single_step and stream.in_flight:
                return False
        if runner.single_step:
            feed.step()  # one operation that sends something, then the runner pauses
        else:
            feed.pull()  # from here on the reader thread sends the job as room frees
        with feed.locked():
            wait = stream.waiting_at
            in_flight, sent_all, refused = stream.in_flight, stream.sent_all, stream.refused
        self._report(stream)
        if in_flight:
            return True
        if refused is not None:  # every line before it has been answered
            runner.fail(*refused)
            return True
        if wait is not None or sent_all:
            if not session.settled:
                if session.status_asked_at is None:
                    # Asked now, not at the next poll (up to status_ms away): every line is
                    # answered, and the job is done, or waits, once a report shows it idle.
                    session.query_status()
                return True  # the session's next status report can show it settled
            self._hold()
            if wait is not None:
                self._report(stream)
                self._waiting = wait
                runner.wait_for_operator(wait)
            else:
                runner.finish()
        return True

    def hold_back(self) -> None:
        """Pausing: take back the lines still queued in the session, not yet on the wire.

        Only what the device already has runs before the pause; the rest is sent again
        from the stream when the operator resumes.
        """
        stream, session = self.stream, self.session
        if stream is None or session is None:
            return
        with self._locked():  # the reader thread pulls no more from here on
            taken = session.discard_queued()
            indices = [s.op_index for s in taken if s.origin == "job" and s.op_index is not None]
            if indices:
                stream.take_back(min(indices))
        origins = {sent.origin for sent in taken}
        if "resume" in origins:
            # The way back did not all go: on the resume the machine is looked at again and
            # a way back made from where it stands then.
            self._preparing = 0
            self._recheck = True
            self._asked_since_recheck = False
        if "setup" in origins:
            self._preparing = 0
            self._confirming = False
            self._redo_setup = True
        if indices:
            self._report(stream)

    def confirmed(self, index: int) -> None:
        """The operator confirmed the WAIT at ``index``."""
        self._waiting = None
        if self.stream is not None:
            with self._locked():
                self.stream.rewind(index + 1)

    def stopped(self) -> None:
        """Abort or failure: the device was reset, so only executed operations count."""
        self._preparing = 0
        self._hold()  # nothing more is pulled (the stop took the queue back)
        self._write_checkpoint(force=True)

    def forget(self) -> None:
        self._waiting = None
        self._hold()

    # --- replies ------------------------------------------------------------------

    def _on_sent(self, lines: list[SentLine]) -> None:
        """One write's lines (a batch: a signal a line cost the window as much as the line)."""
        stream = self.stream
        if stream is None:
            return
        for sent in lines:
            if sent.origin == "job" and sent.op_index is not None:
                stream.note_written(sent.op_index)

    def _on_line_ok(self, sent: SentLine) -> None:
        """The set-up or the way back answered, line by line: the job goes on after the last."""
        modes, self._modes_heard = self._modes_heard, None  # a [GC:…] is its line's, before its ok
        if sent.origin == "setup" and self._confirming and sent.text == "$G":
            if modes is None:
                self._unconfirmed()  # its [GC:…] comes before its ok: that answer was lost
            else:
                self._judge_setup(modes)
            return
        if sent.origin not in ("setup", "resume") or not self._preparing:
            return
        self._preparing -= 1
        if not self._preparing:
            self.proceed()

    def _on_advanced(self) -> None:
        """Lines of the job were answered (counted by the feeder): once per batch of replies."""
        stream = self.stream
        runner = self.runner
        if stream is None:
            return
        with self._locked():
            in_flight = stream.in_flight
        if (runner.single_step or runner.state is JobState.PAUSING) and not in_flight:
            self._report(stream)
            runner.pause_reached()
            return
        if not self._proceed():  # feeding reports the progress itself: once a batch, not twice
            self._report(stream)

    def _on_reply_text(self, text: str) -> None:
        """A ``[GC:…]``, judged with the ``ok`` that follows it (:meth:`_on_line_ok`).

        Only the one answering the set-up's own ``$G`` confirms the set-up: an operator's
        console ``$G`` still unanswered as the job started answers first, with the modes
        from before the set-up.
        """
        if self._confirming and text.startswith("[GC:"):
            self._modes_heard = text

    def _judge_setup(self, text: str) -> None:
        """The ``[GC:…]`` answer to the set-up's ``$G``: the job goes on only when it is right."""
        self._confirming = False
        session = self.session
        problem = modes_confirm(text, session.settings.words) if session is not None else None
        if problem is not None:
            self.runner.fail(0, f"the machine is {problem}")
            return
        self.proceed()

    def _unconfirmed(self) -> None:
        """The set-up's ``$G`` counts as answered, but its ``[GC:…]`` never came.

        Lost on the way back, or the set-up itself was cut on the way there (relay
        grbl-plotter seed 168: ``\n$G\n`` dropped, ``G90 G21 G17`` left unended in
        GRBL's line buffer, where ``Bf:`` cannot show it, and the two answers then
        taken for lost): waiting for the confirmation would wait for good.  A board
        standing idle is reset — it keeps its position, and a fragment of the set-up
        goes — and the set-up is sent again once the machine is looked at; a few
        times, then the job fails (never a job on a machine not known set up).
        """
        session = self.session
        self._confirming = False
        self._redo_setup = True
        self._unconfirmed_count += 1
        if session is None or self._unconfirmed_count > SETUP_CONFIRM_TRIES:
            self.runner.fail(
                self._resume_at, "the machine never confirmed its set-up (no answer to $G)"
            )
            return
        self._recheck = True
        self._asked_since_recheck = False
        if session.machine_state == "Idle":
            session.soft_reset()
        self.proceed()

    def _on_error(self, sent: SentLine, code: int, meaning: str) -> None:
        runner = self.runner
        session = self.session
        if code == LOCKED_IN_ALARM and session is not None and session.alarm.code is not None:
            return  # refused by the alarm the job is paused for: not run, the resume sends it
        if sent.origin in ("setup", "resume") and runner.state in ACTIVE:
            # The job runs only on a machine set up as the program expects it (back at its
            # place, pen and modes restored): refused, the rest would run elsewhere.
            self._confirming = False
            self._hold()
            refused = f"{sent.text!r}: error:{code} ({meaning})"
            if sent.origin == "setup":
                runner.fail(0, f"the machine refused the set-up {refused}")
            else:
                runner.fail(self._resume_at, f"the machine refused the way back {refused}")
            return
        if self.stream is None or sent.origin != "job" or sent.op_index is None:
            return
        if runner.state not in ACTIVE:
            return
        self._hold()  # not one more line of the job after a refusal
        runner.fail(
            sent.op_index, f"the machine answered error:{code} ({meaning}) to {sent.text!r}"
        )

    def _on_status(self, report: StatusReport) -> None:
        stream = self.stream
        runner = self.runner
        if stream is None or runner.state not in CLOCK_RUNS:
            # While a lost link is unresolved an idle machine proves nothing: it may have
            # lost what it had.  The recheck on resume decides.
            if stream is not None and not self._recheck:
                self._status_to(stream, report)
            return
        if self._recheck:
            self._resume_after_recheck(stream, report)
            return
        if report.state == "Hold" and session_holds_unasked(self.session):
            self._machine_held()
            return
        self._status_to(stream, report)
        with self._locked():
            in_flight = stream.in_flight
        if in_flight:
            # Lines may stay unanswered a while (GRBL answers a pen change only once the
            # moves before it ran): what this report proves run is shown now, not then.
            self._report(stream)
        else:
            self._write_checkpoint(force=False)
            self.proceed()

    def _machine_held(self) -> None:
        """The board holds, and no stop of the station's asked it to: pause for the operator.

        Its hold button, or a byte that turned into ``!`` on the wire (GRBL takes
        it wherever it comes, even mid-line).  Streaming on would only fill its
        buffer; waiting would wait for good.  The board keeps its planner and
        position in a hold, so Resume is a cycle start and the job goes on from
        where it is, nothing repeated.
        """
        self._held_by_machine = True
        self.hold_back()  # what is not on the wire yet waits for the resume
        self._hold()
        program = self.runner.program
        stream = self.stream
        with self._locked():
            where = stream.executed if stream is not None else 0
        self.runner.stop_short(
            QCoreApplication.translate(
                "GcodeDriver",
                "The machine holds (a feed hold: its hold button, the Hold button here, or "
                "a '!' that reached it on the wire): the job is paused at {0}. Resume lets "
                "it go on (cycle start).",
            ).format(_where(program, where) if program is not None else "?")
        )

    def _status_to(self, stream: GcodeStream, report: StatusReport) -> None:
        """The report to the stream, with the stream as it was when the report was read."""
        session = self.session
        planner_size = session.planner_size if session else 0
        seen = session.job_at_report if session is not None else None
        with self._locked():
            stream.status(
                report.state,
                report.planner_free,
                planner_size,
                self._here(report),
                seen if isinstance(seen, AtReport) else None,
            )

    def _on_reset(self) -> None:
        """The device was reset: its planner is gone, so look before going on.

        A reset the station sent (to leave a hold) carries on once the machine
        is seen.  A reset of the board's own — its reset button, which is how
        many GRBL machines are stopped by hand, a power dip, or an Arduino
        board restarting as its port reopens — may have lost its position too,
        whether the job was running or already paused for a lost link: the job
        stays paused, said once, until the operator has homed the machine or
        checked where the tool is and chosen where to go on (:meth:`resume_at`).
        """
        runner = self.runner
        if self.stream is None or runner.state not in ACTIVE:
            return
        with self._locked():
            self.stream.pending.clear()
        self._preparing = 0  # the reset took what was left of it
        if self._confirming:
            self._confirming = False  # its answer went with the reset: checked again
            self._redo_setup = True
        self._recheck = True
        self._asked_since_recheck = False
        session = self.session
        if session is not None and session.reset_by_device and self._alarm_said:
            # Paused for the alarm already, said once (GRBL resets after ALARM:3): the board
            # may have lost its position, so the Resume asks where to go on.
            self._position_lost = True
            self._write_checkpoint(force=True)
            return
        if session is not None and session.reset_by_device:
            self._chosen = None  # a pick made before the restart was for a machine it forgot
            self._waiting = None  # a WAIT under way is offered again if the pick is before it
            self._write_checkpoint(force=True)
            if not (self._position_lost and self._choice_open):  # said once
                self._position_lost = True
                stream = self.stream
                with self._locked():
                    first = stream.answered if stream.settings.ok_when_done else stream.executed
                    upto = _sent_upto(stream, first, known=self._written_known)
                self._choose(stream, first, upto)
            return
        if runner.state in CLOCK_RUNS:
            self.proceed()

    def resume_at(self, index: int) -> None:
        """The operator chose ``index``: the machine is looked at, then the job goes on there."""
        if self.stream is None:
            return
        self._chosen = index
        self._choice_open = False
        self._recheck = True
        self._asked_since_recheck = False
        self.proceed()

    def _choose(self, stream: GcodeStream, first: int, upto: int) -> None:
        """Only the operator can say where to go on: offer ``first … upto`` (see ResumeChoice)."""
        program = self.runner.program
        assert program is not None
        self._asked_since_recheck = False  # the pick looks at the machine again
        last = min(upto, len(program))
        draws = stream.draws_between(first, last)
        if self._position_lost:
            text = QCoreApplication.translate(
                "GcodeDriver",
                "The machine restarted during the job (its reset button, its power, or its "
                "port reopened) and may have lost its position: the job is paused. Home it "
                "($H) or check where the tool is (clear an alarm with $X), then choose the "
                "line to resume from; {0} operation(s) from {1} were sent but not proven run.",
            ).format(last - first, _where(program, first))
        else:
            text = QCoreApplication.translate(
                "GcodeDriver",
                "{0} operation(s) from {1} were sent but their running is not proven: "
                "choose the line to resume from (the candidates are highlighted).",
            ).format(last - first, _where(program, first))
        if draws and last > first:
            text += " " + QCoreApplication.translate(
                "GcodeDriver",
                "Some of them draw: resuming too early draws a stroke twice, too late "
                "leaves one out.",
            )
        default = first if not draws or last == first else None
        self._choice_open = True
        self.runner.choose_resume(
            ResumeChoice(first, last, default, text, position_lost=self._position_lost)
        )

    def _resume_after_recheck(self, stream: GcodeStream, report: StatusReport) -> None:
        runner = self.runner
        session = self.session
        program = runner.program
        assert program is not None and session is not None
        if report.state == "Alarm":
            self._hold_in_alarm()
            return
        self._alarm_said = False
        if report.state == "Hold":
            # Leaving a hold takes a reset, which drops what the planner held (the position
            # stays: the hold is complete); the next report decides.
            self._asked_since_recheck = False
            session.soft_reset()
            return
        # Idle alone is no proof: between two lines the board says Idle with the next one
        # still in its buffer, and a way back sent then would run after it.
        verdict = self._standing.judge(report, session.planner_size, stream.settings.rx_buffer)
        if verdict is Standing.ASK_AGAIN:
            session.query_status()
        if verdict is not Standing.STANDS:
            return  # still finishing what it had: the next report decides
        here = self._here(report)
        # What is proven run: every answered line on a board that answers once a line ran;
        # on GRBL, which answers once a line is planned, only what its reports showed run —
        # a reset whose banner was lost with the link takes the rest of the planner with it.
        # Where the machine stands then proves how far it got, when only one place fits.
        with self._locked():
            first = stream.answered if stream.settings.ok_when_done else stream.executed
            upto = _sent_upto(stream, first, known=self._written_known)
            if self._chosen is not None:
                start = self._chosen
                note = f"from {_where(program, start)}, as the operator chose"
            elif self._position_lost:
                start = None
            else:
                start = stream.stands_after(here, first, upto, self._start_at)
                if start is not None:
                    unanswered = start - stream.answered
                    note = "every answered line ran" + (
                        f", and {unanswered} more whose answer was lost" if unanswered > 0 else ""
                    )
                elif not stream.draws_between(first, upto):
                    start = first
                    note = f"{upto - first} operation(s) that draw nothing are sent again"
        if start is None:
            self._choose(stream, first, upto)
            return
        self._recheck = False
        self._chosen = None
        self._position_lost = False
        self._resume_at = start
        axes = [a.name for a in runner.station.profile.axes]
        plan, self._start = self._start, None
        if plan is not None and plan.index != start:
            plan = None
        way_back = (
            retrace(
                program, axes, start, _sent_upto(stream, start, known=self._written_known), here
            )
            if plan is None
            else []
        )
        with self._locked():
            stream.rewind(start)
        if start >= len(program):
            runner.note(f"The machine is back: {note}")
            runner.finish()
            return
        planned = resume_state(program, start, axes)
        # Its moves are G90 lines, so work coordinates: the offset the board has now (a
        # reset clears GRBL's G92) replaces the one the program's coordinates were made with.
        # (G54…G59 stay: the station sets none, so they are taken as 0.)
        now = report.wco or ()
        shift = {name: _offset(self._origin, i) - _offset(now, i) for i, name in enumerate(axes)}
        state = replace(planned, position={a: v + shift[a] for a, v in planned.position.items()})
        way_back = [{a: v + shift[a] for a, v in point.items()} for point in way_back]
        lines = (
            preamble(state, stream.settings, way_back, self._restore(planned, start, now))
            + self._file_modes(stream, start)
            if plan is None
            else plan.lines(stream.settings, shift)
        )
        for line in lines:
            self._preparing += session.send_line(line, "resume")
        runner.note(
            plan.summary(program)
            if plan is not None
            else f"Resuming at {program[start].source}: {note}; machine set up again "
            f"({'pen down' if state.pen_down else 'pen up'}, at the program's position)"
        )
        self._report(stream)
        self.proceed()


def _sent_upto(stream: GcodeStream, start: int, *, known: bool = False) -> int:
    """Operations the device may have received: known in this run, else a window.

    ``known``: this run has written every line the device may have (not a run
    resumed from a checkpoint that could not say): nothing past ``written`` went,
    even when nothing went at all (relay grbl-plotter seed 168: a set-up cut on the
    wire, reset before any line of the job went, was offered the first 30
    operations to pick from, as if sent).
    """
    sent = max(stream.written, stream.answered)
    if sent > start or known:
        return max(sent, start)
    return min(len(stream.program), start + RETRACE_WINDOW)
