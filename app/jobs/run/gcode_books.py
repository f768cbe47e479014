"""The G-code driver's books: progress, checkpoints, and where the machine stands in the program.

Split from :class:`~app.jobs.run.gcode.GcodeDriver`, which is built on
:class:`GcodeBooks`: the runner hears how far the stream got (paced: the
operation under way at most ten times a second, a checkpoint at most every
half second), and a resume's lines are worked out in the program's
coordinates (the machine position less the work offset the job began with;
``G92`` set again on a board that lost it; the file's own modes after the way
back).  The state is the driver's, set in its ``__init__`` and declared here.
"""

from __future__ import annotations

from collections.abc import Sequence
from contextlib import AbstractContextManager, nullcontext

from app.jobs.run.driver import JobDriver
from app.jobs.run.gcode_stream import GcodeStream, ResumeState, file_offset
from app.jobs.run.pacing import Every
from app.jobs.run.start_point import StartRefused, plan_start
from app.machines.gcode.job_feed import JobFeed
from app.machines.gcode.session import GcodeSession
from protocol.gcode.codec import StatusReport

#: Work offsets closer than this (mm) are the same (GRBL reports three decimals).
OFFSET_SAME_MM = 0.002


class GcodeBooks(JobDriver):
    """The bookkeeping half of the G-code driver (its state is set by the driver's init)."""

    stream: GcodeStream | None
    session: GcodeSession | None
    feed: JobFeed | None
    _origin: tuple[float, ...]
    _checkpoints: Every
    _shown: int | None
    _shows: Every

    def _locked(self) -> AbstractContextManager[object]:
        """The feed's lock: the reader thread pulls and counts the stream under it."""
        feed = self.feed
        return feed.locked() if feed is not None else nullcontext()

    def _file_modes(self, stream: GcodeStream, start: int) -> list[str]:
        """A resume's way back is in mm, G90: the file's own modes at ``start`` go after it
        (units, plane, distance mode, motion and feed; an arc's word before its next move).
        None where the file's state there cannot be rebuilt: the way back alone, as before."""
        program = self.runner.program
        assert program is not None
        try:
            plan = plan_start(program, start, [a.name for a in self.station.profile.axes])
        except StartRefused:
            return []
        with self._locked():
            stream.lead = plan.lead
        return plan.modes(stream.settings)

    def _restore(self, planned: ResumeState, start: int, now: Sequence[float]) -> list[str]:
        """``G92`` setting again the work offset the job needs here, if the board lost it.

        A board that reset (GRBL forgets G92; a USB board resets when its port
        reopens) would run the rest of the file shifted.  Once the machine stands
        at the resume point, ``G92`` calls it the file's work position there, which
        gives back the offset the job began with plus the file's own.  Only on a
        board that reports its offset (GRBL).
        """
        session = self.session
        program = self.runner.program
        if session is None or session.work_offset is None or program is None:
            return []
        axes = list(planned.position)
        names = [a.name for a in self.runner.station.profile.axes]
        own = file_offset(program, start, names)
        wanted = {a: offset_on(self._origin, names.index(a)) + own[a] for a in axes}
        if all(abs(offset_on(now, names.index(a)) - wanted[a]) < OFFSET_SAME_MM for a in axes):
            return []
        return ["G92 " + " ".join(f"{a}{planned.position[a] - own[a]:.3f}" for a in axes)]

    def _here(self, report: StatusReport) -> tuple[float, ...]:
        """Where the machine stands in the program's coordinates (machine less the origin)."""
        return tuple(m - offset_on(self._origin, i) for i, m in enumerate(report.mpos))

    # --- progress and checkpoint -------------------------------------------------------

    def _report(self, stream: GcodeStream) -> None:
        runner = self.runner
        assert runner.program is not None
        now = runner.station.clock.now()
        with self._locked():  # both boundaries as of one moment (the reader moves them)
            answered, executed = stream.answered, stream.executed
        # The operation the machine is at: the first not known executed (the lines answered
        # after it wait in the device's planner).
        current = executed if executed < len(runner.program) else None
        if current is not None and current != self._shown and self._shows.due(now):
            # The dock shows the operation under way; a thousand lines a second need not
            # all be shown, so at most ten a second are.
            self._shown = current
            runner.announce(current)
        runner.advance(answered, executed)
        self._write_checkpoint(force=False)

    def _write_checkpoint(self, *, force: bool) -> None:
        runner = self.runner
        stream = self.stream
        if stream is None or runner.program is None:
            return
        if not self._checkpoints.due(runner.station.clock.now(), force=force):
            return
        with self._locked():
            completed, sent = stream.executed - 1, max(stream.written, stream.answered)
        runner.record(completed, sent)


def offset_on(offsets: Sequence[float], axis: int) -> float:
    """The offset ``offsets`` has on ``axis`` (0 where it names no such axis)."""
    return offsets[axis] if axis < len(offsets) else 0.0
