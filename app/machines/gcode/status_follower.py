"""Every G-code status report read, followed: the machine's place, the path it must keep to,
and the answers or lines the wire may have lost.

Each report's machine position is judged against the path of the lines
written (:mod:`app.machines.gcode.planned_path`); a report off it stops the
machine and names the line.  An idle board with lines unanswered either lost
their answers (:class:`~app.machines.gcode.lost_answers.LostAnswerWatch`), or
the lines themselves, or holds a line cut on the wire
(:mod:`~app.machines.gcode.stuck_line`); one that holds more bytes than were
sent (:mod:`~app.machines.gcode.byte_count`) is stopped before it runs them.
The session composes this follower; it runs on the GUI thread.
"""

from __future__ import annotations

import copy
import logging
import math
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication

from app.listened import listened
from app.machines.gcode import timing
from app.machines.gcode.byte_count import ByteCount
from app.machines.gcode.byte_shortfall import ShortfallWatch
from app.machines.gcode.feeder import ReportSeen
from app.machines.gcode.jogger import reports_moving
from app.machines.gcode.lines import SentLine
from app.machines.gcode.lost_answers import (
    AnswersLost,
    LostAnswerWatch,
    StreamWaits,
    Unaccounted,
    paused_s,
)
from app.machines.gcode.pen_watch import PenWatch, sync_text
from app.machines.gcode.planned_path import PlannedPath
from app.machines.gcode.stuck_line import StuckLineWatch
from app.machines.supervision import MotionFault, fault_text
from protocol.gcode.codec import StatusReport, with_work_offset

if TYPE_CHECKING:
    from app.machines.gcode.ports import GcodeCore

_log = logging.getLogger(__name__)


class StatusFollower:
    """The reports of one G-code session's board, against the lines written to it."""

    def __init__(self, session: GcodeCore) -> None:
        self._session = session
        settings = session.settings
        self.planned = PlannedPath(
            session.envelope,
            tuple(axis.name for axis in session.model.profile.axes),
            grbl="$J" in settings.words,
        )
        #: A line cut on the wire, its start stuck in the board's buffer (stuck_line.py).
        self.stuck = StuckLineWatch(session.clock, settings.rx_buffer)
        #: The board's buffer against the bytes counted unanswered (byte_count.py).
        self.byte_count = ByteCount(settings.rx_buffer)
        # The board's buffer short of the lines it must hold (byte_shortfall.py).
        self.shortfall = ShortfallWatch(settings.rx_buffer)
        self.lost_answers = LostAnswerWatch(settings.rx_buffer)
        #: Planner blocks the device has, learned from its ``Bf:`` reports (0: unknown).
        self.planner_size = 0
        #: The pen (a GRBL plotter's spindle) against the lines answered (pen_watch.py).
        self.pen = PenWatch(settings, lambda: session.envelope.next_serial)

    def written(self, written: list[tuple[bytes, SentLine]]) -> None:
        """Lines gone on the wire: the path follows them, the frame log shows them."""
        if not written:
            return
        session = self._session
        # Asked once a batch: with nothing connected, no emit per line (app/listened.py).
        frames, lines = listened(session, "frameSent"), listened(session, "lineSent")
        line = self.planned.line
        for raw, sent in written:
            self.pen.written(raw, sent)
            try:
                line(raw.decode("ascii").rstrip(), sent.text, sent.op_index)
            except (ValueError, ArithmeticError):
                # A line this reading cannot place is not followed; the stream goes on.
                _log.exception("the path of %r could not be followed", sent.text)
                session.envelope.release()
            if frames:
                session.frameSent.emit(sent.text, raw)
            if lines:
                session.lineSent.emit(sent)
        session.linesSent.emit([sent for _raw, sent in written])

    def check_lost_answers(
        self,
        report: StatusReport,
        planner_empty: bool,
        unanswered: list[SentLine] | None = None,
    ) -> None:
        """An ``ok`` lost on the wire would stall the stream for ever (:class:`LostAnswerWatch`).

        ``unanswered``: the lines unanswered when the report was read (None: now).
        """
        session = self._session
        if unanswered is None:
            unanswered = session.streamer.unanswered_tags()
        stuck = self.stuck.stuck(report, planner_empty=planner_empty, paused_s=paused_s(unanswered))
        if stuck is not None:
            self.lost_answers.forget()
            session.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "The board holds {0} byte(s) of a line whose end never came (lost on the "
                    "way) and waits for it: it stands idle, so it is reset, keeping its "
                    "position, and what it ran is looked at again",
                ).format(stuck)
            )
            session.soft_reset()
            return
        verdict = self.lost_answers.judge(
            report,
            unanswered,
            self.planner_size,
            planner_empty,
            session.clock.now(),
            timing.SILENCE_S,
        )
        if isinstance(verdict, StreamWaits):
            session.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "{0} line(s) unanswered while the board stands idle; waiting for its "
                    "answer (without Bf: in its reports it cannot show it has them)",
                ).format(verdict.count)
            )
        if isinstance(verdict, Unaccounted):
            session.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "{0} line(s) still unanswered while the board stands idle, and its reports "
                    "cannot show whether it has them: it is reset, keeping its position, and "
                    "what it ran is looked at again",
                ).format(verdict.count)
            )
            session.soft_reset()
            return
        if not isinstance(verdict, AnswersLost):
            return
        if self.short_of_lines_sent(report):
            # Not their answers but the lines themselves were lost: the board stands
            # short of where they end.  Reset (it stands: its position stays) and let
            # the job look at it and go on from what is proven.
            session.model.message.emit(
                QCoreApplication.translate(
                    "GcodeSession",
                    "{0} line(s) sent never reached the board: it has taken every byte "
                    "it got and stands idle short of where they end; it is reset, "
                    "keeping its position, and what it ran is looked at again",
                ).format(len(verdict.lines))
            )
            session.soft_reset()
            return
        session.model.message.emit(
            QCoreApplication.translate(
                "GcodeSession",
                "{0} answer(s) from the board were lost on the way; it has taken and run "
                "every line sent, so they count as answered",
            ).format(len(verdict.lines))
        )
        advanced = False
        for sent in verdict.lines:
            with session.feeder.lock:
                tags = session.streamer.unanswered_tags()
                if not tags or tags[0] != sent:
                    break  # answered meanwhile after all
                answer = session.feeder.acknowledge()
            session.replies.answered(None, answer.entry, counted=answer.counted)
            advanced = advanced or answer.counted
        if advanced:
            session.jobAdvanced.emit()
            session.pump()

    def apply(
        self,
        report: StatusReport,
        unanswered: list[SentLine] | None = None,
        job: object = None,
        *,
        idle_then: bool | None = None,
    ) -> None:
        """``unanswered``, ``job`` and ``idle_then``: the lines unanswered, the job's snapshot
        and whether nothing waited to go, as the report was read (on the reader thread;
        None: read now)."""
        session = self._session
        session.status_asked_at = None
        session.job_at_report = job
        # A work position without any offset heard yet is no machine position.
        placed = (
            not report.work_reported or report.wco is not None or session.work_offset is not None
        )
        # GRBL sends its work offset (WCO:) only now and then: the last one heard completes
        # the reports between, so both the machine and the work position are always known.
        if report.wco is not None:
            session.work_offset = report.wco
        report = with_work_offset(report, session.work_offset)
        session.status = report
        session.alarm.reported(report.state)
        if placed:
            on_path = self.supervise(report)
        self.supervise_pen(report, on_path if placed else False)
        session.stops.reported(report)
        if report.state == "Idle" and report.planner_free is not None and session.streamer.idle:
            # Free blocks of an idle machine with nothing on its way: the planner's size.
            self.planner_size = report.planner_free
        session.jogger.reported(report)
        moving = reports_moving(report)
        for axis in range(min(session.axis_count, len(report.mpos))):
            session.model.update_axis(
                axis,
                position=report.mpos[axis],
                offset=report.mpos[axis] - report.wpos[axis],
                status_text=report.state.lower(),
                moving=moving,
            )
        # Replies and reports share one ordered stream, so with every line answered this
        # report was made after the last line was planned.  A board that has planned a
        # block but not yet started it still says Idle; its Bf then shows the block.
        planner_empty = (
            report.planner_free is None
            or not self.planner_size
            or report.planner_free >= self.planner_size
        )
        # Idle as it was read too: a report read before the last lines went (a burst of held
        # replies, handled here after the reader thread sent them and counted their answers)
        # says nothing of them.
        with session.feeder.lock:  # nothing queued between the look and the note
            idle = session.streamer.idle and idle_then is not False
            at_rest = report.state == "Idle" and idle and planner_empty
            if at_rest:
                session.seen_idle = True
        if at_rest:
            # A GRBL board's offset is known once a WCO: came (the next lines' targets need it).
            offset_known = session.work_offset is not None or not session.jogger.with_command
            if (
                placed
                and offset_known
                and not session.stopping
                and len(report.mpos) >= session.axis_count
            ):
                # Standing with every line answered: where the next lines start from.
                self.planned.anchor(report.mpos, report.wco or ())
        self.check_lost_answers(report, planner_empty, unanswered)
        session.statusChanged.emit(report)
        session.jogger.feed()
        session.stops.confirm(report)
        if session.silent_since is not None:
            heard = session.heard_again_at
            # Replies held back on the way come first: the board's state is judged from a
            # report made a few queries after it was heard again.
            if heard is not None and session.clock.now() - heard >= session.stale_after_s:
                session.report_after_silence = report
            session.check_recovery()

    def short_of_lines_sent(self, report: StatusReport) -> bool:
        """Whether an idle board stands off where the lines written end (as far as known)."""
        session = self._session
        end = session.envelope.end
        if end is None or len(report.mpos) < session.axis_count:
            return False
        here = report.mpos[: session.axis_count]
        return any(abs(a - b) > session.envelope.tolerance for a, b in zip(here, end, strict=False))

    def count_broken(
        self, report: StatusReport, unanswered: list[SentLine], unanswered_bytes: int | None
    ) -> bool:
        """The board holds more than was sent and not answered: stop before it runs it."""
        session = self._session
        extra = self.byte_count.excess(report, unanswered_bytes)
        if extra is None or session.stopping:
            return False
        self.byte_count.forget()  # one stop, one message
        job = next((s.op_index for s in unanswered if s.origin == "job"), None)
        text = QCoreApplication.translate(
            "GcodeSession",
            "The board holds {0} byte(s) more than were sent and not answered (a line or an "
            "answer arrived twice on the way): the lines it holds may be garbled, so it is "
            "stopped before it runs them",
        ).format(extra)
        session.stop_for_fault(MotionFault(text, job))
        return True

    def bytes_lost(self, report: StatusReport, seen: ReportSeen[SentLine]) -> bool:
        """The board holds fewer bytes than the lines it must (byte_shortfall.py): a line
        that lost bytes on the way waits in it; stop before it runs."""
        session = self._session
        if not session.settings.ok_when_done:
            return False
        missing = self.shortfall.judge(report, seen.held)
        if missing is None or session.stopping or seen.held is None:
            return False
        held = session.settings.rx_buffer - (report.rx_free or 0)
        # The oldest may be running: the first line that must be whole in the buffer.
        line = seen.unanswered[1] if len(seen.unanswered) > 1 else None
        text = QCoreApplication.translate(
            "GcodeSession",
            "The board holds {0} byte(s) where the lines sent and not yet run make at least "
            "{1}: {2} byte(s) were lost on the way inside a line waiting in its buffer "
            "(in “{3}” or a line behind it), so it is stopped before it runs it",
        ).format(held, held + missing, missing, "?" if line is None else line.text)
        session.stop_for_fault(MotionFault(text, line.op_index if line is not None else None))
        return True

    def supervise_pen(self, report: StatusReport, on_path: bool) -> None:
        """A report whose spindle (the pen) is not what the lines run leave stops the machine.

        ``on_path``: the report was just placed on the path of the lines written, so the
        leg it is on says which pen lines on their way cannot have run yet."""
        envelope = self._session.envelope
        here = report.mpos[: self._session.axis_count]

        def reached(mark: int) -> bool:
            """Every leg before ``mark`` may be behind the machine (it is at the last's end)."""
            current = envelope.next_serial - envelope.in_flight  # the leg it is on
            if mark <= current:
                return True
            legs = envelope.legs
            if mark > current + 1 or not legs:
                return False
            return math.dist(here, legs[0].end[: len(here)]) <= envelope.tolerance

        mismatch = self.pen.judge(report, reached if on_path and envelope.known else None)
        if mismatch is not None and not self._session.stopping:
            self._session.stop_for_fault(MotionFault(mismatch.text(), mismatch.op_index))

    def past_pen_lines(self, here: tuple[float, ...]) -> SentLine | None:
        """The moves before each pen line proven since the last report are behind the
        machine (GRBL runs them before the pen moves); the first such line the report is
        short of, if any (the line the board got was not the one sent)."""
        envelope = self._session.envelope
        proven, self.pen.synced = self.pen.synced, []
        if proven and copy.deepcopy(envelope).check(here) is not None:
            for _line, mark in proven:  # off the path anyway: not a pen line's doing
                envelope.behind(mark)
            return None
        for line, mark in proven:
            trial = copy.deepcopy(envelope)
            trial.behind(mark)
            if trial.check(here) is not None:
                envelope.behind(mark)
                return line
            envelope.behind(mark)
        return None

    def supervise(self, report: StatusReport) -> bool:
        """A report off the path of the lines written stops the machine, naming the line;
        True when it was judged on the path."""
        session = self._session
        if report.state in ("Home", "Alarm") or len(report.mpos) < session.axis_count:
            return False
        here = report.mpos[: session.axis_count]
        synced = self.past_pen_lines(here)
        deviation = session.envelope.check(here)
        if deviation is None:
            return True
        session.envelope.release()  # one stop, one message: judged again once it stands
        names = [axis.name for axis in session.model.profile.axes]
        tag = deviation.tag if isinstance(deviation.tag, int) else None
        text = fault_text(deviation, names)
        if synced is not None:  # short of a pen line proven run: that line was not the one sent
            text = f"{text}. {sync_text(synced)}"
            tag = synced.op_index if synced.op_index is not None else tag
        session.stop_for_fault(MotionFault(text, tag))
        return False
