"""The jobs dock: open a job, see it, run it, and know at every moment where it is.

A view over :class:`app.jobs.run.runner.JobRunner`, which owns the program, the
state machine, the dry-run estimate and the checkpoint; the dock only asks
it (Run, Pause, Resume, Step, Abort, Continue) and shows what it says.
Buttons are enabled from the runner's state alone, so a button the operator
can press is one the runner will honour.

Opening goes through :mod:`app.jobs.loaders` (the name, the extension or the
content chooses the reader; when they leave the format open the dock asks)
and then ``runner.load``.  Opened from the dialog (or the command line), a
file is read on a worker thread with a busy bar, so a slow or hostile file
never freezes the window.  A malformed file shows
``file:line: reason`` and loads nothing: the runner is not even asked, so a
job loaded before stays as it was.  A program that leaves the machine's
travel (or needs a tool the machine lacks) is refused by the runner, which
unloads and lists every offending operation with its file and line; the
dock shows that list as it comes, in the message area.

Two things ask for the operator: an interrupted run of the loaded job
(``resume_available``) offers to resume from the operation after the last
completed one or to discard the checkpoint, and a WAIT operation shows its
message with a Continue button.
"""

from __future__ import annotations

import html
from collections.abc import Callable, Sequence
from pathlib import Path

from PySide6.QtCore import QCoreApplication, Qt, Signal
from PySide6.QtWidgets import (
    QDockWidget,
    QFileDialog,
    QFrame,
    QHBoxLayout,
    QInputDialog,
    QLabel,
    QPlainTextEdit,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams
from app.jobs.loaders import AmbiguousFormat, JobOptions, JobType, file_dialog_filter, load_job
from app.jobs.names import shown
from app.jobs.program import JobFileError, OpKind, Program
from app.jobs.registration import Placement, RegistrationError
from app.jobs.run.runner import JobRunner, JobState, LoadCheck
from app.machines.drill.session import DrillSession
from app.station import Station
from widgets.jobs.export import JobExport
from widgets.jobs.loading import JobLoading
from widgets.jobs.lock_text import retranslate_jog_lock
from widgets.jobs.operation_text import operation_text
from widgets.jobs.options import JobOptionsBox
from widgets.jobs.preview import ACTIVE_STATES, DEFAULT_THROTTLE_MS, JobPreview
from widgets.jobs.preview_column import PreviewColumn
from widgets.jobs.registration_bar import RegistrationBar
from widgets.jobs.resume_choice import ResumeChoicePanel
from widgets.jobs.run_controls import RunControls, job_button
from widgets.jobs.source_lines import read_lines
from widgets.jobs.start_from import StartFromLaunch
from widgets.jobs.string_art_board import BoardAsker
from widgets.jobs.string_art_board import ask_board as ask_board_dialog
from widgets.jobs.string_art_launch import StringArtLaunch
from widgets.retranslate import Texts
from widgets.style import monospace_font

MESSAGE_LINES = 200
#: A refused file's further refused lines listed under the first one.
MORE_REFUSALS_SHOWN = 20

#: Asks which job type an ambiguous file is; the chosen type's key, None when cancelled.
FormatAsker = Callable[[AmbiguousFormat], str | None]


def ask_format_dialog(parent: QWidget | None) -> FormatAsker:
    def ask(ambiguous: AmbiguousFormat) -> str | None:
        choices: Sequence[JobType] = ambiguous.choices
        item, ok = QInputDialog.getItem(
            parent,
            QCoreApplication.translate("JobsDock", "Which kind of job?"),
            QCoreApplication.translate(
                "JobsDock", "{0}: the name and the content do not tell.\nRead it as:"
            ).format(shown(ambiguous.path.name)),
            [t.description for t in choices],
            0,
            False,
        )
        if not ok:
            return None
        return next((t.key for t in choices if t.description == item), None)

    return ask


def _bold(name: str) -> str:
    """A file or job name for a rich-text label: escaped, never markup."""
    return f"<b>{html.escape(shown(name))}</b>"


def _banner_style(name: str, background: str, border: str) -> str:
    """A coloured band for one named frame only (its labels and buttons keep their looks)."""
    # Its own text colour too: on the light band the dark theme's light text was unreadable.
    return (
        f"QFrame#{name} {{ background: {background}; border: 1px solid {border};"
        f" border-radius: 4px; }} QFrame#{name} QLabel {{ color: #1d1d1d; }}"
    )


class JobsDock(QDockWidget):
    """Open…, preview, Run / Pause / Resume / Step / Abort, progress, ETA, operator prompts."""

    #: A job file was loaded (its path): the window lists it under File → Recent jobs.
    jobOpened = Signal(object)

    def __init__(
        self,
        station: Station,
        runner: JobRunner,
        parent: QWidget | None = None,
        *,
        confirm: Callable[[str], bool] | None = None,
        throttle_ms: float | None = None,
        ask_board: BoardAsker | None = None,
        ask_format: FormatAsker | None = None,
    ) -> None:
        super().__init__(parent)
        self.texts = Texts(self)
        self.texts.set(self.setWindowTitle, lambda: self.tr("Jobs"))
        self.setObjectName("jobs_dock")
        self.station = station
        self.runner = runner
        self._path: Path | None = None
        self._source_lines: Sequence[str] = ()
        #: The file ``_source_lines`` came from and the program they were read for.
        self._source_lines_of: tuple[Path | None, Program | None] = (None, None)
        self._ask_board: BoardAsker = ask_board or ask_board_dialog(self)
        #: The board the operator gave for a bare nail list (kept while the file is re-read).
        self._board: StringArtParams | None = None
        self._ask_format: FormatAsker = ask_format or ask_format_dialog(self)
        #: The job type the operator chose for an ambiguous file (kept while it is re-read).
        self._format: str | None = None
        #: An option changed while a file was being read: read it again when that ends.
        self._reread = False
        #: The source lines the loading thread read with the program (None: read them here).
        self._prepared_lines: tuple[Path | None, Sequence[str]] | None = None
        self._loading: JobLoading | None = None
        self.preview = JobPreview(
            station,
            runner,
            confirm=confirm,
            throttle_ms=DEFAULT_THROTTLE_MS if throttle_ms is None else throttle_ms,
        )
        self.preview.setObjectName("job_preview")
        self.run_controls = RunControls(
            runner,
            self.texts,
            throttle_ms,
            lambda executed, total: self.tr("{0} / %n ops", "", total).format(executed),
            self,
        )
        # The parts' widgets as the dock's attributes, as tests have always found them.
        for name in ("run", "pause", "resume", "step", "abort"):
            setattr(self, f"{name}_button", getattr(self.run_controls, f"{name}_button"))
        for name in ("progress", "count_label", "elapsed_label", "eta_label"):
            setattr(self, name, getattr(self.run_controls, name))
        self.options_box = JobOptionsBox(station, self.texts)
        self.options_box.changed.connect(self._options_changed)
        for name in ("draw", "crosses", "smallest", "translate_pen", "skip"):
            setattr(self, f"{name}_check", getattr(self.options_box, f"{name}_check"))
        self.step_combo = self.options_box.step_combo
        self.string_art = StringArtLaunch(station, runner, self.texts, self.open_path, self)
        self.photo_button = self.string_art.button
        self.exports = JobExport(station, runner, self.texts, self.say, self)
        self.export_button = self.exports.button
        self.start_from = StartFromLaunch(runner, self.preview, self._source_line, self.texts, self)
        self.run_from_button = self.start_from.button

        self.setWidget(self._build_content())

        runner.stateChanged.connect(self._state_changed)
        runner.operationStarted.connect(self._show_operation)
        runner.waitingForOperator.connect(self._show_prompt)
        runner.decisionNeeded.connect(self._show_question)
        runner.message.connect(self._runner_message)
        runner.programChanged.connect(self._program_changed)
        station.model.lockChanged.connect(self._update_buttons)
        self.preview.message.connect(self.say)
        self._program_changed()
        self.texts.also(self._retranslate)

    def _build_content(self) -> QWidget:
        """The file row and run controls, the options, the preview with its bands, the
        progress, the operation under way and the messages, top to bottom."""
        content = QWidget()
        layout = QVBoxLayout(content)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.setSpacing(4)
        layout.addLayout(self._build_toolbar())
        layout.addWidget(self.options_box)
        self.registration = RegistrationBar(self.station, self._load_registered, self.say)
        self.registration.pickRequested.connect(
            lambda k: self.preview.pick_reference(k if k >= 0 else None)
        )
        self.preview.holePicked.connect(self.registration.set_reference)
        resume_offer = self._build_resume_offer()
        prompt = self._build_prompt()
        self.resume_choice = ResumeChoicePanel(
            self.runner,
            self.preview,
            self._source_line,
            lambda: self.station.model.motion_lock_reason() is None,
        )
        # The bands take their room from the preview: a prompt never makes the window grow.
        self.preview_column = PreviewColumn(
            (self.registration, resume_offer, self.resume_choice, prompt),
            # The registration row steps aside while a job runs, when prompts come; the
            # choice of a resume line comes with a paused job, beside the registration row.
            ((self.registration, resume_offer), (self.registration, self.resume_choice), (prompt,)),
            self.preview,
        )
        layout.addWidget(self.preview_column, 1)
        layout.addLayout(self.run_controls.progress_rows)
        self.operation_label = QLabel("")
        self.operation_label.setObjectName("job_operation")
        self.operation_label.setFont(monospace_font())
        self.operation_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        self.texts.set(
            self.operation_label.setToolTip,
            lambda: self.tr("The operation being executed and the line it came from"),
        )
        # A long source line must not widen the dock past the screen: it is cut instead.
        self.operation_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        layout.addWidget(self.operation_label)
        self.messages = QPlainTextEdit()
        self.messages.setObjectName("job_messages")
        self.messages.setReadOnly(True)
        self.messages.setMaximumBlockCount(MESSAGE_LINES)
        self.messages.setFont(monospace_font(-1))
        self.texts.set(
            self.messages.setPlaceholderText, lambda: self.tr("Messages about the job appear here")
        )
        self.messages.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Preferred)
        self.messages.setFixedHeight(self.messages.fontMetrics().lineSpacing() * 4 + 12)
        layout.addWidget(self.messages)
        return content

    def _retranslate(self) -> None:
        """What is made from the job's state, said again in the new language."""
        if self._loading is None:  # while a file is read, its name stays until it is in
            self._show_file(self.runner.program)
        self.run_controls.retranslate()
        retranslate_jog_lock(self.runner)
        self._show_resume_offer()
        self._update_buttons()

    # --- building ------------------------------------------------------------

    def option_values(self) -> dict[str, object]:
        """The operator's reading options, to keep across launches (the main window stores)."""
        return self.options_box.option_values()

    def restore_options(self, values: dict[str, object]) -> None:
        """Set the reading options from ``values`` (unknown or malformed entries are ignored)."""
        self.options_box.restore_options(values)

    @property
    def options(self) -> JobOptions:
        return self.options_box.job_options(self._board, self._format)

    def _options_changed(self, *_args: object) -> None:
        """Re-read the open file with the new choice (not while it runs), on the worker.

        A choice made while the file is being read is taken once that reading ends.
        """
        if self._loading is not None:
            self._reread = True
        elif self._path is not None and self.runner.state not in ACTIVE_STATES:
            self.open_path(self._path, background=True)

    def _build_toolbar(self) -> QVBoxLayout:
        """The file row (Open…, Export…, From photo…, the file's name) over the run controls."""
        bar = QVBoxLayout()
        bar.setSpacing(4)
        self.open_button = job_button(
            self.texts,
            lambda: self.tr("Open…"),
            "job_open",
            lambda: self.tr("Open a job file (point list; the type is told by its content)"),
            self.ask_open,
        )
        self.file_label = QLabel(self.tr("no job loaded"))
        self.file_label.setObjectName("job_file")
        self.file_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        # A long file name is cut at the dock's edge (the tooltip has it whole) instead of
        # widening the dock past the screen.
        self.file_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        files = QHBoxLayout()
        files.setSpacing(6)
        files.addWidget(self.open_button)
        # On the file row: beside Run it made the dock too wide for a 1280 px screen.
        files.addWidget(self.run_from_button)
        files.addWidget(self.export_button)
        files.addWidget(self.photo_button)
        files.addWidget(self.file_label, 1)
        bar.addLayout(files)
        bar.addLayout(self.run_controls.buttons)
        return bar

    def _build_resume_offer(self) -> QFrame:
        self.resume_offer = QFrame()
        self.resume_offer.setObjectName("job_resume_offer")
        self.resume_offer.setStyleSheet(_banner_style("job_resume_offer", "#e8f0fe", "#8ab4f8"))
        row = QHBoxLayout(self.resume_offer)
        row.setContentsMargins(6, 4, 6, 4)
        self.resume_offer_label = QLabel()
        self.resume_offer_label.setWordWrap(True)
        self.resume_checkpoint_button = job_button(
            self.texts,
            lambda: self.tr("Resume"),
            "job_resume_checkpoint",
            lambda: self.tr(
                "Go on after the last operation the machine completed; none is repeated"
            ),
            self.runner.resume_from_checkpoint,
        )
        self.discard_checkpoint_button = job_button(
            self.texts,
            lambda: self.tr("Discard"),
            "job_discard_checkpoint",
            lambda: self.tr("Forget the interrupted run; Run then starts from the first operation"),
            self.runner.discard_checkpoint,
        )
        row.addWidget(self.resume_offer_label, 1)
        row.addWidget(self.resume_checkpoint_button)
        row.addWidget(self.discard_checkpoint_button)
        self.resume_offer.hide()
        return self.resume_offer

    def _build_prompt(self) -> QFrame:
        self.prompt = QFrame()
        self.prompt.setObjectName("job_prompt")
        self.prompt.setStyleSheet(_banner_style("job_prompt", "#fff3cd", "#e0c060"))
        row = QHBoxLayout(self.prompt)
        row.setContentsMargins(6, 4, 6, 4)
        self.prompt_label = QLabel()
        self.prompt_label.setObjectName("job_prompt_text")
        self.prompt_label.setWordWrap(True)
        font = self.prompt_label.font()
        font.setBold(True)
        self.prompt_label.setFont(font)
        self.continue_button = job_button(
            self.texts,
            lambda: self.tr("Continue"),
            "job_continue",
            lambda: self.tr("Done: let the job go on"),
            self.runner.confirm,
        )
        # Only the operator can tell whether an interrupted operation ran (a hole drilled?).
        self.again_button = job_button(
            self.texts,
            lambda: self.tr("Again"), "job_again",
            lambda: self.tr("It did not happen: send it again"),
            lambda: self.runner.decide(again=True),
        )  # fmt: skip
        self.counted_button = job_button(
            self.texts,
            lambda: self.tr("Done"), "job_counted",
            lambda: self.tr("It happened: count it as done"),
            lambda: self.runner.decide(again=False),
        )  # fmt: skip
        row.addWidget(self.prompt_label, 1)
        row.addWidget(self.continue_button)
        row.addWidget(self.again_button)
        row.addWidget(self.counted_button)
        self.prompt.hide()
        return self.prompt

    # --- operator actions ----------------------------------------------------

    def ask_open(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, self.tr("Open a job"), "", file_dialog_filter())
        if path:
            self.open_path(Path(path), background=True)

    def open_path(self, path: Path, *, background: bool = False) -> bool:
        """Load the job in ``path`` into the runner; False (and says why) when it is not loaded.

        With ``background`` a large file is read on a worker thread (a million G-code lines
        take seconds) and the window stays responsive; the result arrives later, and True
        only means the reading began.
        """
        name = shown(path.name)
        if self.runner.state in ACTIVE_STATES:
            self.say(self.tr("{0}: not opened — a job is under way (abort it first)").format(name))
            return False
        if self._loading is not None:
            self.say(
                self.tr("{0}: not opened — still reading {1}").format(
                    name, shown(self._loading.path.name)
                )
            )
            return False
        if path != self._path:
            self._board = None
            self._format = None
        axis_names = [axis.name for axis in self.station.profile.axes]
        self._path = path
        if background:  # even a small file can be slow (huge arcs), or be no file (a pipe)
            self._loading = JobLoading(
                path,
                axis_names,
                self.options,
                self.preview.geometry_maker(),
                self.runner.checker(),
                self,
            )
            self._loading.done.connect(self._loaded)
            self.file_label.setText(self.tr("reading {0}…").format(_bold(path.name)))
            self.open_button.setEnabled(False)
            self.run_controls.progress.setRange(0, 0)  # busy until the worker answers
            self._loading.start()
            return True
        try:
            program = load_job(path, axis_names, self.options)
        except JobFileError as exc:
            return self._refused(path, exc)
        return self._accept(path, program)

    def _loaded(self, path: Path, result: object) -> None:
        """The worker finished reading ``path`` (GUI thread)."""
        loading, self._loading = self._loading, None
        if loading is not None:
            loading.join()
        self.run_controls.progress.setRange(0, 1)
        if isinstance(result, JobFileError):
            self._refused(path, result, background=True)
        elif isinstance(result, tuple):
            program, geometry, lines, checked = result
            self.preview.prepare(program, geometry)
            self._prepared_lines = (program.source, lines)
            self._accept(path, program, checked)
        else:
            self.say(self.tr("{0}: not loaded — {1}").format(shown(path.name), result))
        self._program_changed()
        if self._reread and self._loading is None:
            self._reread = False
            self._options_changed()

    def _refused(self, path: Path, exc: JobFileError, *, background: bool = False) -> bool:
        if isinstance(exc, NeedsNailCount) and self._board is None:
            board = self._ask_board(exc)
            if board is not None:
                self._board = board
                return self.open_path(path, background=background)
        if isinstance(exc, AmbiguousFormat) and self._format is None:
            chosen = self._ask_format(exc)
            if chosen is not None:
                self._format = chosen
                return self.open_path(path, background=background)
        self.say(self.tr("{0} — not loaded").format(exc))
        for more in exc.more[:MORE_REFUSALS_SHOWN]:
            self.say(f"  {more}")
        if len(exc.more) > MORE_REFUSALS_SHOWN:
            left = len(exc.more) - MORE_REFUSALS_SHOWN
            self.say("  " + self.tr("… and %n more line(s) refused", "", left))
        return False

    def _placed(self, program: Program) -> tuple[Program, Placement] | None:
        """The file's job put on the board as before: read again, or resumed after a restart.

        The same file read again keeps the side and registration it had; a
        file whose interrupted run was registered gets that registration back
        from the checkpoint, so the resume drills where the board is.
        """
        if OpKind.DRILL not in program.kinds():
            return None  # only drill jobs are registered on a board
        previous = self.registration.original
        kept = self.registration.placement
        placement: Placement | None = None
        if kept and previous is not None and previous.fingerprint() == program.fingerprint():
            placement = kept
        else:
            placement = self.runner.checkpoint_placement(program)
        if not placement:
            return None
        try:
            return placement.apply(program), placement
        except RegistrationError as exc:
            self.say(
                self.tr("{0}: the board placement was not applied: {1}").format(program.name, exc)
            )
            return None

    def _accept(self, path: Path, program: Program, checked: LoadCheck | None = None) -> bool:
        placed = self._placed(program)
        if placed is not None and not self.runner.load(placed[0], (program, placed[1])):
            self.registration.set_job(program, placed[1])
            self.say(
                self.tr("{0}: kept on the board as before ({1})").format(
                    shown(path.name), placed[0].notes[-1] if placed[0].notes else ""
                )
            )
            self._finish_accept(path, placed[0])
            return True
        if self.runner.load(program, checked=checked):
            # The runner said which operations, line by line (its message).  The drawing is
            # still worth seeing — where it leaves the travel, what it would do — so the
            # preview shows it while Run stays off.
            self.preview.set_program(program)
            self.file_label.setText(
                self.tr("{0} — refused, preview only").format(_bold(program.name))
            )
            self.file_label.setToolTip(str(program.source) if program.source else program.name)
            self.registration.set_job(None)
            return False
        self.registration.set_job(program)
        self._finish_accept(path, program)
        return True

    def _finish_accept(self, path: Path, program: Program) -> None:
        self.say(self.tr("{0}: %n operation(s) loaded", "", len(program)).format(shown(path.name)))
        self.jobOpened.emit(path)
        notes = list(program.notes)
        if isinstance(program, StringArtProgram):
            # The totals with this machine's time for them (the loader knew no machine).
            estimate = self.runner.progress.estimate
            plain = program.job.summary()
            notes = [n for n in notes if n != plain]
            notes.insert(0, program.job.summary(estimate.total_s if estimate else None))
        for note in notes:
            self.say(f"{shown(path.name)}: {note}")
        self._program_changed()

    def _load_registered(self, program: Program, placement: Placement) -> bool:
        """A registered (or cleared) job replaces the loaded one; the runner checks its travel.

        The runner keeps the placement with the checkpoint, for a resume.
        """
        original = self.registration.original
        placed = (original, placement) if original is not None else None
        if self.runner.load(program, placed):
            return False  # the runner listed the holes off the bed
        note = program.notes[-1] if program.notes else self.tr("loaded")
        self.say(f"{program.name}: {note}")
        return True

    def say(self, text: str) -> None:
        self.messages.appendPlainText(text)
        self.messages.ensureCursorVisible()

    # --- runner → view -------------------------------------------------------

    def _runner_message(self, text: str) -> None:
        """Show it, and look at the runner again: it offers a checkpoint (abort, failure,
        discard) after its state change, with no signal of its own, but always says so."""
        self.say(text)
        self._state_changed()

    def _program_changed(self) -> None:
        program = self.runner.program
        if program is not self.preview.program:
            self.preview.set_program(program)
        self._show_file(program)
        self.run_controls.show_progress()
        estimate = self.runner.progress.estimate if program is not None else None
        self.run_controls.set_times(
            0.0 if estimate else None, estimate.total_s if estimate else None
        )
        self.operation_label.setText("")  # no lone dash where no operation is under way
        source = program.source if program is not None else None
        prepared, self._prepared_lines = self._prepared_lines, None
        read = prepared is not None and source is not None and prepared[0] == source
        if prepared is not None and read:
            self._source_lines = prepared[1]
        elif self._source_lines_of[1] is not program or self._source_lines_of[0] != source:
            # Not again for the program they were read for (a 2-million-line file takes long).
            self._source_lines = read_lines(source)
        self._source_lines_of = (source, program)
        self._state_changed()

    def _show_file(self, program: Program | None) -> None:
        if program is None:
            self.file_label.setText(self.tr("no job loaded"))
            self.file_label.setToolTip("")
            return
        source = str(program.source) if program.source else program.name
        self.file_label.setText(
            self.tr("{0} — %n operation(s)", "", len(program)).format(_bold(program.name))
        )
        self.file_label.setToolTip(source)

    def _state_changed(self, *_args: object) -> None:
        state = self.runner.state
        if self.runner.resume_choice is None:
            self.resume_choice.withdraw()
        if state is not JobState.WAITING and self.runner.question is None:
            self.prompt.hide()
            if self.runner.resume_choice is None:
                self.preview.mark_question(None)
        if state in (JobState.READY, JobState.PAUSED) and self.runner.program is not None:
            # Stepping through: show what the next Step will send before it is sent.
            self._show_operation(self.runner.done)
        self._show_resume_offer()
        self._update_buttons()
        self.run_controls.show_progress()

    def _show_resume_offer(self) -> None:
        index = self.runner.resume_available
        program = self.runner.program
        if index is None or program is None or self.runner.state in ACTIVE_STATES:
            self.resume_offer.hide()
            return
        if 0 <= index < len(program):
            where = f"{program[index].source}  {operation_text(program[index])}"
        else:
            where = self.tr("the end")
        self.resume_offer_label.setText(
            self.tr(
                "An interrupted run of <b>{0}</b> completed {1} of %n operation(s). "
                "Resume from operation {2} ({3})?",
                "",
                len(program),
            ).format(html.escape(program.name), index, index + 1, html.escape(where))
        )
        self.resume_checkpoint_button.setText(self.tr("Resume from op {0}").format(index + 1))
        self.resume_offer.show()

    def _update_buttons(self, *_args: object) -> None:
        state = self.runner.state
        loaded = self.runner.program is not None
        lock = self.station.model.motion_lock_reason()
        can_move = lock is None
        self.open_button.setEnabled(state not in ACTIVE_STATES and self._loading is None)
        # Registering replaces the loaded job: not while it runs.
        self.registration.setEnabled(state not in ACTIVE_STATES and self._loading is None)
        self.registration.set_job_running(state in ACTIVE_STATES)
        self.export_button.setEnabled(loaded)
        self.run_controls.update_enabled(lock, self.runner.resume_available is not None)
        answering = can_move and self.runner.question is not None
        self.resume_checkpoint_button.setEnabled(can_move)
        self.continue_button.setEnabled(state is JobState.WAITING)
        self.again_button.setEnabled(answering)
        self.counted_button.setEnabled(answering)
        self.resume_choice.update_enabled()

    def _show_operation(self, index: int) -> None:
        """The operation with its source line as written in the file and, on a machine that
        counts microsteps, what will go on the wire — what stepping through a file needs."""
        program = self.runner.program
        if program is None or not 0 <= index < len(program):
            return
        op = program[index]
        text = f"{op.source}  {operation_text(op)}"
        raw = self._source_line(op.source.line)
        if raw:
            text += "\n    " + self.tr("file: {0}").format(raw)
        session = self.station.session_as(DrillSession)
        if session is not None and op.target:
            names = [axis.name for axis in self.station.profile.axes]
            steps = [
                f"{axis}{session.to_microsteps(names.index(axis), value)}"
                for axis, value in op.target.items()
                if axis in names
            ]
            text += "    " + self.tr("machine: {0} microsteps").format(" ".join(steps))
        self.operation_label.setText(text)

    def _source_line(self, number: int) -> str:
        if number < 1 or number > len(self._source_lines):
            return ""
        return self._source_lines[number - 1].strip()

    def _show_prompt(self, text: str) -> None:
        self.prompt_label.setText(self.tr("Operator: {0}").format(text))
        self._show_answers(question=False)
        self.prompt.show()
        self.continue_button.setEnabled(True)
        self.continue_button.setFocus()
        self.say(self.tr("waiting for the operator: {0}").format(text))

    def _show_question(self, text: str, again: str, done: str) -> None:
        self.prompt_label.setText(text)
        self.again_button.setText(again)
        self.counted_button.setText(done)
        self._show_answers(question=True)
        self.prompt.show()
        self.preview.mark_question(self.runner.question)
        self.say(text)

    def _show_answers(self, *, question: bool) -> None:
        self.continue_button.setVisible(not question)
        self.again_button.setVisible(question)
        self.counted_button.setVisible(question)
