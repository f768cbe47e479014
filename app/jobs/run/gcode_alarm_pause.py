"""The G-code driver's pause for an alarm: said once, nothing more sent, resumed from proof.

Split from :class:`~app.jobs.run.gcode.GcodeDriver`, which is built on it; the
state is the driver's, set in its ``__init__`` and declared here.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.jobs.program import Program
from app.jobs.run.gcode_books import GcodeBooks
from app.jobs.run.states import ACTIVE, CLOCK_RUNS
from app.machines.gcode.meanings import alarm_meaning


def where_in(program: Program, index: int) -> str:
    """Operation ``index``'s place in its file, or "the end" past the last."""
    return str(program[index].source) if index < len(program) else "the end"


class GcodeAlarmPause(GcodeBooks):
    """What the driver does when the board goes into alarm mid-job, or is found in one."""

    _held_by_machine: bool
    _preparing: int
    _confirming: bool
    _redo_setup: bool
    _recheck: bool
    _asked_since_recheck: bool
    _alarm_said: bool

    def _on_alarm(self, code: int) -> None:
        """The board went into alarm mid-job (a limit switch, a failed probe, its reset in
        motion): it stopped, dropped what it had planned, and takes no line until the
        operator homes or unlocks it.

        The job is paused, said once (the session says the alarm once too), and nothing
        more is sent: every line would be refused (``error:9``).  Resume looks at the
        machine first — still in alarm, it stays paused — and goes on from what is proven
        run, asking where only the operator can tell.  A job already paused (the link, a
        question, a restart) stays as it is, its Resume looks again.
        """
        runner = self.runner
        if self.stream is None or runner.state not in ACTIVE:
            return
        self.hold_back()  # what is not on the wire yet waits for the resume
        if self.feed is not None:
            self.feed.hold()  # pull nothing more of the job
        self._held_by_machine = False  # the alarm dropped the hold with the rest
        with self._locked():
            self.stream.pending.clear()  # lost with the planner, or refused: not proven run
        self._preparing = 0
        if self._confirming:
            self._confirming = False
            self._redo_setup = True
        self._recheck = True
        self._asked_since_recheck = False
        self._write_checkpoint(force=True)
        if runner.state not in CLOCK_RUNS:
            return
        self._alarm_said = True
        program = runner.program
        with self._locked():
            where = self.stream.executed
        runner.hold_for_operator(
            QCoreApplication.translate(
                "GcodeDriver",
                "The machine went into alarm {0} ({1}) during the job and stopped: the job "
                "is paused at {2}. Clear the alarm (home it with $H, or unlock it with $X if "
                "its position is still right), then Resume: the job goes on from what is "
                "proven run.",
            ).format(code, alarm_meaning(code), where_in(program, where) if program else "?")
        )

    def _hold_in_alarm(self) -> None:
        """A board that reset itself mid-motion (GRBL: ALARM:3, its position no longer
        trusted) or powered up with homing on takes no line until unlocked: streaming into
        it would only be refused (error:9), and unlocking is the operator's call.  The job
        stays paused, still to be rechecked on the next Resume."""
        self._asked_since_recheck = False
        self.runner.hold_for_operator(
            QCoreApplication.translate(
                "GcodeDriver",
                "The machine is in alarm: the job stays paused. Check the machine, "
                "clear the alarm (home it with $H, or unlock it with $X if its position "
                "is still right), then Resume.",
            )
        )
