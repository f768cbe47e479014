"""Running a macro: refused before a byte is sent, or run as a small job.

A macro is read into a program from where the machine stands
(:mod:`app.macros.program`), checked against the travel and the machine's
repertoire by the job runner's own check, and run by a
:class:`~app.jobs.run.runner.JobRunner` of its own: the same driver, feed and
motion gate as a job, its progress, Stop ending it, a lost link pausing it
(and the runner resuming it once the machine answers again intact).

Refused while a job is under way (the runner's jog lock says so), while
another macro runs, while motion is locked (not connected, link lost) and
while the machine moves.  Where only the operator can say how a run
interrupted goes on (which lines ran, an alarm), the macro ends there, the
machine standing: a macro is short, and the operator runs it again or not.
Its checkpoint is kept only for that run; the next run starts from its start.
"""

from __future__ import annotations

import tempfile
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject, QStandardPaths, QTimer, Signal

from app.jobs.formats.gcode.loader import GcodeProgram
from app.jobs.program import JobFileError
from app.jobs.run.runner import JobRunner, LoadCheck
from app.jobs.run.states import ACTIVE, JobState
from app.macros.machines import macros_available
from app.macros.program import file_error_text, macro_program, refusal_text
from app.macros.store import Macro
from app.station import Station

#: Refusals listed in a message; more are counted.
REFUSALS_SHOWN = 10


def macro_checkpoint_dir() -> Path:
    """Where macro runs keep their checkpoints (beside the jobs', apart from them)."""
    data = QStandardPaths.writableLocation(QStandardPaths.StandardLocation.AppDataLocation)
    if not data:
        return Path(tempfile.gettempdir()) / "stepdeck-macro-checkpoints"
    return Path(data) / "macro-checkpoints"


def macro_busy_text() -> str:
    """The jog lock's reason while a macro runs (a job is refused with it, too)."""
    return QCoreApplication.translate("Macros", "a macro is under way — stop it or let it finish")


class MacroRefused(ValueError):
    """A macro that will not run as written, with every reason (``macro "Name":line: …``)."""


def prepare_macro(
    station: Station, runner: JobRunner, macro: Macro
) -> tuple[GcodeProgram, LoadCheck]:
    """``macro`` read from where the machine stands and checked by ``runner``'s own check
    (travel, repertoire) for its load; MacroRefused lists what is wrong."""
    start = {axis.name.upper(): axis.work_position for axis in station.model.axes}
    try:
        program = macro_program(macro, station.profile, start)
    except JobFileError as exc:
        raise MacroRefused(file_error_text(exc)) from None
    checked = runner.checker()(program)
    if checked.refused:
        lines = [refusal_text(v) for v in checked.refused[:REFUSALS_SHOWN]]
        if len(checked.refused) > REFUSALS_SHOWN:
            lines.append(
                QCoreApplication.translate("Macros", "… and {0} more").format(
                    len(checked.refused) - REFUSALS_SHOWN
                )
            )
        raise MacroRefused("\n".join(lines))
    return program, checked


class MacroRunner(QObject):
    """Runs one macro at a time on a station; says why when it will not."""

    #: The macro run's JobState.
    stateChanged = Signal(object)
    progressChanged = Signal(int, int)  # done, total
    #: A macro's ``M0``/``M6`` asks the operator (confirm with :meth:`confirm`).
    waitingForOperator = Signal(str)
    message = Signal(str)

    def __init__(self, station: Station, checkpoint_dir: Path, parent: QObject | None = None):
        super().__init__(parent)
        self.station = station
        self.runner = JobRunner(station, checkpoint_dir, parent=self)
        self.runner.busy_text = macro_busy_text
        #: The macro running, or last run.
        self.name: str | None = None
        #: While a macro is loaded: the runner's words about an earlier run's checkpoint
        #: (a macro always starts from its start) are not the operator's business.
        self._quiet = False
        runner = self.runner
        runner.stateChanged.connect(self._on_state)
        runner.progressChanged.connect(self.progressChanged)
        runner.waitingForOperator.connect(self.waitingForOperator)
        runner.message.connect(self._on_message)

    @property
    def state(self) -> JobState:
        return self.runner.state

    @property
    def active(self) -> bool:
        return self.runner.state in ACTIVE

    def refusal(self) -> str | None:
        """Why no macro may start now (None: one may), in the operator's language."""
        model = self.station.model
        if not macros_available(self.station.profile):
            return QCoreApplication.translate("Macros", "{0} takes no G-code macros").format(
                self.station.profile.shown_title
            )
        if self.active:
            return QCoreApplication.translate("Macros", "macro {0} is running").format(
                repr(self.name)
            )
        if model.jog_lock_reason is not None:
            return model.jog_lock_reason
        reason = model.motion_lock_reason()
        if reason is not None or self.station.session is None:
            return reason or QCoreApplication.translate("Macros", "not connected")
        if model.any_moving:
            return QCoreApplication.translate("Macros", "the machine is moving")
        return None

    def run(self, macro: Macro) -> bool:
        """Check ``macro`` from where the machine stands and start it; False: refused, said why."""
        why = self.refusal()
        if why is not None:
            return self._refuse(macro, why)
        runner = self.runner
        try:
            program, checked = prepare_macro(self.station, runner, macro)
        except MacroRefused as exc:
            return self._refuse(macro, str(exc))
        self._quiet = True
        try:
            if runner.load(program, checked=checked):
                return self._refuse(
                    macro, QCoreApplication.translate("Macros", "the travel check failed")
                )
            if runner.resume_available is not None:
                # An earlier run of the same text that did not end: it starts from its start.
                runner.discard_checkpoint()
        finally:
            self._quiet = False
        self.name = macro.name
        runner.start()
        if not self.active:
            return self._refuse(macro, QCoreApplication.translate("Macros", "it did not start"))
        return True

    def abort(self) -> None:
        """Stop: the machine stops and the macro ends (nothing of it goes on by itself)."""
        if self.active:
            self.runner.abort()

    def resume(self) -> None:
        """Go on after a pause (a lost link that came back)."""
        self.runner.resume()

    def confirm(self) -> None:
        """The operator did what the macro's ``M0``/``M6`` asked."""
        self.runner.confirm()

    def _refuse(self, macro: Macro, why: str) -> bool:
        self.message.emit(
            QCoreApplication.translate("Macros", "Macro {0} refused: {1}").format(
                repr(macro.name), why
            )
        )
        return False

    def _on_message(self, text: str) -> None:
        if not self._quiet:
            self.message.emit(text)

    def _on_state(self, state: JobState) -> None:
        if state is JobState.PAUSED:
            # After the runner has said what it asks (its slot must not end the job under it).
            QTimer.singleShot(0, self, self._end_if_operator_needed)
        self.stateChanged.emit(state)

    def _end_if_operator_needed(self) -> None:
        """Which lines ran, where to go on, an alarm: only the operator can say, and a macro
        is no job to pick up in the middle.  It ends (failed), the machine standing."""
        runner = self.runner
        if runner.state is JobState.PAUSED and runner.needs_operator:
            self.message.emit(
                QCoreApplication.translate(
                    "Macros", "Macro {0} ended: the machine needs you first"
                ).format(repr(self.name))
            )
            runner.give_up()
