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

import gc
import html
import threading
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import TYPE_CHECKING, overload

import numpy as np
from PySide6.QtCore import QCoreApplication, QElapsedTimer, QObject, Qt, QTimer, Signal
from PySide6.QtWidgets import (
    QCheckBox,
    QComboBox,
    QDockWidget,
    QFileDialog,
    QFrame,
    QGridLayout,
    QHBoxLayout,
    QInputDialog,
    QLabel,
    QMenu,
    QPlainTextEdit,
    QProgressBar,
    QPushButton,
    QSizePolicy,
    QVBoxLayout,
    QWidget,
)

from app.jobs.formats.string_art.export import export_gcode, export_sd_files
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams
from app.jobs.loaders import AmbiguousFormat, JobOptions, JobType, file_dialog_filter, load_job
from app.jobs.names import shown
from app.jobs.program import JobFileError, OpKind, Program
from app.jobs.reading import read_job_text
from app.jobs.registration import Placement, RegistrationError
from app.jobs.run.runner import JobRunner, JobState, LoadCheck
from app.station import Station
from widgets.jobs.operation_text import operation_text
from widgets.jobs.preview import ACTIVE_STATES, DEFAULT_THROTTLE_MS, JobPreview, ProgramGeometry
from widgets.jobs.preview_column import PreviewColumn
from widgets.jobs.registration_bar import RegistrationBar
from widgets.jobs.resume_choice import ResumeChoicePanel
from widgets.jobs.string_art_board import BoardAsker
from widgets.jobs.string_art_board import ask_board as ask_board_dialog
from widgets.retranslate import Maker, Texts
from widgets.style import monospace_font

if TYPE_CHECKING:  # the dialog (and scikit-image behind it) loads when first opened
    from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog

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


#: Files larger than this are not kept in memory for showing source lines.
SOURCE_LINES_MAX_BYTES = 8_000_000


def _banner_style(name: str, background: str, border: str) -> str:
    """A coloured band for one named frame only (its labels and buttons keep their looks)."""
    # Its own text colour too: on the light band the dark theme's light text was unreadable.
    return (
        f"QFrame#{name} {{ background: {background}; border: 1px solid {border};"
        f" border-radius: 4px; }} QFrame#{name} QLabel {{ color: #1d1d1d; }}"
    )


def clock_text(seconds: float | None) -> str:
    """mm:ss (h:mm:ss past an hour); "--:--" when unknown."""
    if seconds is None or seconds != seconds or seconds < 0:  # None, NaN or nonsense
        return "--:--"
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes:02d}:{secs:02d}"


# While a job runs, the progress bar and count move at most this often (ms).
PROGRESS_BAR_MS = 100


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
        self._times: tuple[float | None, float | None] = (None, None)
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
        self._loading: _Loading | None = None
        #: The "From photo…" dialog while it is open.
        self.generator_dialog: StringArtGeneratorDialog | None = None
        self.preview = JobPreview(
            station,
            runner,
            confirm=confirm,
            throttle_ms=DEFAULT_THROTTLE_MS if throttle_ms is None else throttle_ms,
        )
        self.preview.setObjectName("job_preview")
        # While a job runs the bar and count move at most every _bar_ms (0: at once).
        self._bar_ms = PROGRESS_BAR_MS if throttle_ms is None or throttle_ms > 0 else 0
        self._bar_shown = QElapsedTimer()
        self._bar_timer = QTimer(self)
        self._bar_timer.setSingleShot(True)
        self._bar_timer.timeout.connect(self._show_progress)

        content = QWidget()
        layout = QVBoxLayout(content)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.setSpacing(4)
        layout.addLayout(self._build_toolbar())
        layout.addLayout(self._build_options())
        self.registration = RegistrationBar(station, self._load_registered, self.say)
        self.registration.pickRequested.connect(
            lambda k: self.preview.pick_reference(k if k >= 0 else None)
        )
        self.preview.holePicked.connect(self.registration.set_reference)
        resume_offer = self._build_resume_offer()
        prompt = self._build_prompt()
        self.resume_choice = ResumeChoicePanel(
            runner,
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
        layout.addLayout(self._build_progress())
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
        self.setWidget(content)

        runner.stateChanged.connect(self._state_changed)
        runner.progressChanged.connect(self._show_progress)
        runner.executedChanged.connect(self._show_progress)
        runner.etaChanged.connect(self._show_eta)
        runner.operationStarted.connect(self._show_operation)
        runner.waitingForOperator.connect(self._show_prompt)
        runner.decisionNeeded.connect(self._show_question)
        runner.message.connect(self._runner_message)
        runner.programChanged.connect(self._program_changed)
        station.model.lockChanged.connect(self._update_buttons)
        self.preview.message.connect(self.say)
        self._program_changed()
        self.texts.also(self._retranslate)

    def _retranslate(self) -> None:
        """What is made from the job's state, said again in the new language."""
        if self._loading is None:  # while a file is read, its name stays until it is in
            self._show_file(self.runner.program)
        self._show_progress()
        self._set_times(*self._times)
        self._show_resume_offer()
        self._update_buttons()

    # --- building ------------------------------------------------------------

    def _build_options(self) -> QGridLayout:
        """How drill files are read: drill or draw (the original tool's two run modes), and
        the Excellon step for files whose integer coordinates carry no format."""
        grid = QGridLayout()
        grid.setHorizontalSpacing(8)
        grid.setVerticalSpacing(2)
        grid.setContentsMargins(0, 0, 0, 0)
        t = self.texts
        self.draw_check = QCheckBox()
        t.set(self.draw_check.setText, lambda: self.tr("Draw holes with the pen"))
        self.draw_check.setObjectName("job_draw")
        t.set(
            self.draw_check.setToolTip,
            lambda: self.tr(
                "Drill files: instead of drilling, the pen goes down (K) at each bit's first"
                " hole, draws along the following holes, X then Y, and comes up (Z) after the"
                " last, as the original tool drew"
            ),
        )
        self.crosses_check = QCheckBox()
        t.set(self.crosses_check.setText, lambda: self.tr("Crosses at the holes"))
        self.crosses_check.setObjectName("job_draw_crosses")
        t.set(
            self.crosses_check.setToolTip,
            lambda: self.tr(
                "Drawn drill files: a pen cross the size of each hole instead of one line"
                " along the holes"
            ),
        )
        self.crosses_check.setEnabled(False)
        self.draw_check.toggled.connect(self.crosses_check.setEnabled)
        self.smallest_check = QCheckBox()
        t.set(self.smallest_check.setText, lambda: self.tr("Smallest bit first"))
        self.smallest_check.setObjectName("job_smallest_first")
        t.set(
            self.smallest_check.setToolTip,
            lambda: self.tr(
                "Drill files: the bit changes ordered from the smallest drill to the largest"
            ),
        )
        self.step_combo = QComboBox()
        self.step_combo.setObjectName("job_excellon_step")
        for denominator, inch in (("10000", 1e-4), ("1000", 1e-3), ("100000", 1e-5)):
            self.step_combo.addItem("", inch)
            t.item(
                self.step_combo,
                self.step_combo.count() - 1,
                lambda d=denominator: self.tr("1/{0} inch").format(d),
            )
        t.set(
            self.step_combo.setToolTip,
            lambda: self.tr("Excellon step: the unit of bare integer coordinates"),
        )
        step = QHBoxLayout()
        step.setSpacing(4)
        self.step_label = t.label(lambda: self.tr("Excellon step"))
        step.addWidget(self.step_label)
        step.addWidget(self.step_combo)
        step.addStretch(1)
        self.draw_check.toggled.connect(self._options_changed)
        # The drill's timing constants changed (S2-06): the open file is estimated anew.
        self.station.drillTimingChanged.connect(self._options_changed)
        self.crosses_check.toggled.connect(self._options_changed)
        self.smallest_check.toggled.connect(self._options_changed)
        self.step_combo.activated.connect(self._options_changed)
        # G-code files: other flavours' pen commands, and lines the machine cannot run.
        self.translate_pen_check = QCheckBox()
        t.set(self.translate_pen_check.setText, lambda: self.tr("Use this machine's pen commands"))
        self.translate_pen_check.setObjectName("job_translate_pen")
        self.translate_pen_check.setChecked(True)
        t.set(
            self.translate_pen_check.setToolTip,
            lambda: self.tr(
                "G-code: M300/M280 servo lines, Z pen heights, M3/M5 are sent as this machine's "
                "own pen-up / pen-down commands"
            ),
        )
        self.skip_check = QCheckBox()
        t.set(self.skip_check.setText, lambda: self.tr("Skip lines it cannot run"))
        self.skip_check.setObjectName("job_skip_unsupported")
        t.set(
            self.skip_check.setToolTip,
            lambda: self.tr(
                "G-code: lines this machine cannot execute (e.g. M18) are listed and left out "
                "instead of refusing the job"
            ),
        )
        gcode = self.station.profile.dialect == "gcode"
        pen = self.station.profile.capabilities.pen
        drill = self.station.profile.capabilities.drill
        # Drill files are drilled or drawn: where the machine has neither tool they are
        # refused whatever these say, so they are not offered; the pen option only where
        # there is a pen (the winder drills but has none).
        for check in (self.translate_pen_check, self.skip_check):
            check.toggled.connect(self._options_changed)
        step_widget = QWidget()
        step_widget.setLayout(step)
        step.setContentsMargins(0, 0, 0, 0)
        offered: list[tuple[QWidget, bool]] = [
            (self.draw_check, pen),
            (self.crosses_check, pen),
            (step_widget, pen or drill),
            (self.smallest_check, drill),
            (self.translate_pen_check, gcode and pen),
            (self.skip_check, gcode),
        ]
        # Two short columns rather than one long row: the dock must fit beside the window's
        # pages on a 1280 px screen, so no option may set a width of its own.  Only the
        # options this machine offers are placed, in order, so no gap is left where a
        # hidden one would have been.
        placed = [w for w, visible in offered if visible] + [w for w, v in offered if not v]
        for index, widget in enumerate(placed):
            grid.addWidget(widget, index // 2, index % 2)  # hidden ones last: they take no room
        for widget, visible in offered:
            if not visible:
                # Only hidden: shown while not yet in the dock, each flashed up as a window of
                # its own and took the keyboard from the main window (no more arrow jogs).
                widget.hide()
        grid.setColumnStretch(2, 1)  # spare width beside, so a click on a check's caption hits it
        return grid

    def option_values(self) -> dict[str, object]:
        """The operator's reading options, to keep across launches (the main window stores)."""
        return {
            "draw": self.draw_check.isChecked(),
            "draw_crosses": self.crosses_check.isChecked(),
            "smallest_first": self.smallest_check.isChecked(),
            "excellon_step_inch": float(self.step_combo.currentData()),
            "translate_pen": self.translate_pen_check.isChecked(),
            "skip_unsupported": self.skip_check.isChecked(),
        }

    def restore_options(self, values: dict[str, object]) -> None:
        """Set the reading options from ``values`` (unknown or malformed entries are ignored)."""
        checks = {
            "draw": self.draw_check,
            "draw_crosses": self.crosses_check,
            "smallest_first": self.smallest_check,
            "translate_pen": self.translate_pen_check,
            "skip_unsupported": self.skip_check,
        }
        for key, check in checks.items():
            value = values.get(key)
            if isinstance(value, bool):
                check.setChecked(value)
            elif isinstance(value, str) and value in ("true", "false"):  # INI files keep text
                check.setChecked(value == "true")
        step = values.get("excellon_step_inch")
        try:
            index = self.step_combo.findData(float(str(step)))
        except ValueError:
            index = -1
        if index >= 0:
            self.step_combo.setCurrentIndex(index)

    @property
    def options(self) -> JobOptions:
        profile = self.station.profile
        return JobOptions(
            # A choice kept from another machine's session never applies where it is hidden.
            draw=self.draw_check.isChecked() and profile.capabilities.pen,
            draw_crosses=self.crosses_check.isChecked(),
            smallest_first=self.smallest_check.isChecked(),
            excellon_step_inch=float(self.step_combo.currentData()),
            translate_pen=self.translate_pen_check.isChecked(),
            skip_unsupported=self.skip_check.isChecked(),
            gcode=profile.gcode,
            machine_title=profile.shown_title,
            string_art=self._board,
            format=self._format,
        )

    def _options_changed(self, *_args: object) -> None:
        """Re-read the open file with the new choice (not while it runs), on the worker.

        A choice made while the file is being read is taken once that reading ends.
        """
        if self._loading is not None:
            self._reread = True
        elif self._path is not None and self.runner.state not in ACTIVE_STATES:
            self.open_path(self._path, background=True)

    def _button(
        self, text: Maker, name: str, tip: Maker, slot: Callable[[], object]
    ) -> QPushButton:
        button = self.texts.button(text, tip)
        button.setObjectName(name)
        button.clicked.connect(lambda _=False: slot())
        return button

    def _build_toolbar(self) -> QVBoxLayout:
        bar = QVBoxLayout()
        bar.setSpacing(4)
        self.open_button = self._button(
            lambda: self.tr("Open…"),
            "job_open",
            lambda: self.tr("Open a job file (point list; the type is told by its content)"),
            self.ask_open,
        )
        self.export_button = self._button(
            lambda: self.tr("Export…"),
            "job_export",
            lambda: self.tr(
                "Write the loaded job out: G-code, or a string-art job's SD-card files"
            ),
            self.ask_export,
        )
        self.photo_button = self._button(
            lambda: self.tr("From photo…"),
            "job_from_photo",
            lambda: self.tr(
                "String art from a photo: make a nail sequence, see it, load it as a job"
            ),
            self.open_generator,
        )
        # Only the winder winds thread (its axes: base A, needle X, drill Z).
        axes = {axis.name for axis in self.station.profile.axes}
        if not {"A", "X", "Z"} <= axes:
            self.photo_button.hide()  # never shown before it is placed: a window of its own
        self.file_label = QLabel(self.tr("no job loaded"))
        self.file_label.setObjectName("job_file")
        self.file_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        # A long file name is cut at the dock's edge (the tooltip has it whole) instead of
        # widening the dock past the screen.
        self.file_label.setSizePolicy(QSizePolicy.Policy.Ignored, QSizePolicy.Policy.Preferred)
        self.run_button = self._button(
            lambda: self.tr("Run"),
            "job_run",
            lambda: self.tr("Run the job from the start"),
            self.runner.start,
        )
        self.pause_button = self._button(
            lambda: self.tr("Pause"),
            "job_pause",
            lambda: self.tr("Pause after the operation under way finishes"),
            self.runner.pause,
        )
        self.resume_button = self._button(
            lambda: self.tr("Resume"),
            "job_resume",
            lambda: self.tr("Go on from where the job paused"),
            self.runner.resume,
        )
        self.step_button = self._button(
            lambda: self.tr("Step"),
            "job_step",
            lambda: self.tr("Execute the next operation only, then pause"),
            self.runner.step,
        )
        self.abort_button = self._button(
            lambda: self.tr("Abort"),
            "job_abort",
            lambda: self.tr("Stop the machine now and end the job"),
            self.runner.abort,
        )
        self.abort_button.setStyleSheet(
            "QPushButton:enabled { color: #b00020; font-weight: bold; }"
        )
        files = QHBoxLayout()
        files.setSpacing(6)
        files.addWidget(self.open_button)
        files.addWidget(self.export_button)
        files.addWidget(self.photo_button)
        files.addWidget(self.file_label, 1)
        # The run controls on a row of their own: beside the file row they made the dock too
        # wide for a 1280 px screen, and Abort was the first thing pushed off it.
        controls = QHBoxLayout()
        controls.setSpacing(6)
        for button in (
            self.run_button,
            self.pause_button,
            self.resume_button,
            self.step_button,
            self.abort_button,
        ):
            controls.addWidget(button)
        controls.addStretch(1)
        bar.addLayout(files)
        bar.addLayout(controls)
        return bar

    def _build_resume_offer(self) -> QFrame:
        self.resume_offer = QFrame()
        self.resume_offer.setObjectName("job_resume_offer")
        self.resume_offer.setStyleSheet(_banner_style("job_resume_offer", "#e8f0fe", "#8ab4f8"))
        row = QHBoxLayout(self.resume_offer)
        row.setContentsMargins(6, 4, 6, 4)
        self.resume_offer_label = QLabel()
        self.resume_offer_label.setWordWrap(True)
        self.resume_checkpoint_button = self._button(
            lambda: self.tr("Resume"),
            "job_resume_checkpoint",
            lambda: self.tr(
                "Go on after the last operation the machine completed; none is repeated"
            ),
            self.runner.resume_from_checkpoint,
        )
        self.discard_checkpoint_button = self._button(
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
        self.continue_button = self._button(
            lambda: self.tr("Continue"),
            "job_continue",
            lambda: self.tr("Done: let the job go on"),
            self.runner.confirm,
        )
        # Only the operator can tell whether an interrupted operation ran (a hole drilled?).
        self.again_button = self._button(
            lambda: self.tr("Again"), "job_again",
            lambda: self.tr("It did not happen: send it again"),
            lambda: self.runner.decide(again=True),
        )  # fmt: skip
        self.counted_button = self._button(
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

    def _build_progress(self) -> QVBoxLayout:
        rows = QVBoxLayout()
        rows.setSpacing(2)
        row = QHBoxLayout()
        row.setSpacing(8)
        self.progress = QProgressBar()
        self.progress.setObjectName("job_progress")
        self.progress.setRange(0, 1)
        self.progress.setValue(0)
        # The count beside the bar, not on it: text over the bar's edge is half unreadable.
        self.progress.setTextVisible(False)
        self.count_label = QLabel()
        self.count_label.setObjectName("job_count")
        self.count_label.setFont(monospace_font())
        self.elapsed_label = QLabel()
        self.elapsed_label.setObjectName("job_elapsed")
        self.elapsed_label.setFont(monospace_font())
        self.eta_label = QLabel()
        self.eta_label.setObjectName("job_eta")
        self.eta_label.setFont(monospace_font())
        self.texts.set(
            self.eta_label.setToolTip,
            lambda: self.tr("Time left, from the dry run of the job on the machine's model"),
        )
        # The times on a line of their own: beside the bar and a long job's count ("1234 /
        # 1809 ops · 1250 sent", in Slovak longer) they widened the dock while the job ran,
        # and the window with it, past a 1280 px screen.
        self.progress.setMinimumWidth(40)
        row.addWidget(self.progress, 1)
        row.addWidget(self.count_label)
        times = QHBoxLayout()
        times.setSpacing(12)
        times.addWidget(self.elapsed_label)
        times.addWidget(self.eta_label)
        times.addStretch(1)
        rows.addLayout(row)
        rows.addLayout(times)
        self._set_times(None, None)
        return rows

    # --- operator actions ----------------------------------------------------

    def ask_open(self) -> None:
        path, _ = QFileDialog.getOpenFileName(self, self.tr("Open a job"), "", file_dialog_filter())
        if path:
            self.open_path(Path(path), background=True)

    def open_generator(self) -> StringArtGeneratorDialog:
        """The string-art generator, on the board of the loaded string-art job if there is one."""
        if self.generator_dialog is not None:
            self.generator_dialog.raise_()
            self.generator_dialog.activateWindow()
            return self.generator_dialog
        program = self.runner.program
        board = program.job.params if isinstance(program, StringArtProgram) else None
        reach = next((a.travel for a in self.station.profile.axes if a.name == "X"), None)
        from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog

        dialog = StringArtGeneratorDialog(self.open_path, self, board=board, reach_mm=reach)
        dialog.finished.connect(self._generator_closed)
        self.generator_dialog = dialog
        dialog.show()
        return dialog

    def _generator_closed(self, *_args: object) -> None:
        dialog, self.generator_dialog = self.generator_dialog, None
        if dialog is not None:
            dialog.deleteLater()

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
            self._loading = _Loading(
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
            self.progress.setRange(0, 0)  # busy until the worker answers
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
        self.progress.setRange(0, 1)
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
            estimate = self.runner.estimate
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

    def ask_export(self) -> None:
        program = self.runner.program
        if program is None:
            return
        menu = QMenu(self)
        if isinstance(program, StringArtProgram):
            menu.addAction(self.tr("SD-card files (param.txt, poradi.txt)…"), self._ask_export_sd)
        if self.station.profile.gcode is not None:
            menu.addAction(self.tr("G-code program…"), self._ask_export_gcode)
        if menu.isEmpty():
            self.say(self.tr("Nothing to export for this job on this machine"))
            return
        menu.exec(self.export_button.mapToGlobal(self.export_button.rect().bottomLeft()))

    def _ask_export_sd(self) -> None:
        directory = QFileDialog.getExistingDirectory(
            self, self.tr("Folder for param.txt and poradi.txt")
        )
        if directory:
            self.export_sd(Path(directory))

    def _ask_export_gcode(self) -> None:
        program = self.runner.program
        name = f"{program.name}.gcode" if program is not None else "job.gcode"
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Export G-code"), name, self.tr("G-code (*.gcode)")
        )
        if path:
            self.export_gcode(Path(path))

    def export_sd(self, directory: Path) -> bool:
        """The string-art job as its standalone firmware reads it from an SD card."""
        program = self.runner.program
        if not isinstance(program, StringArtProgram):
            self.say(self.tr("Only string-art jobs have SD-card files"))
            return False
        try:
            param, poradi = export_sd_files(program.job, directory)
        except OSError as exc:
            self.say(self.tr("SD-card files not written: {0}").format(exc))
            return False
        self.say(self.tr("Wrote {0} and {1}").format(param, poradi))
        return True

    def export_gcode(self, path: Path) -> bool:
        """The loaded job as the G-code this machine would be sent."""
        program = self.runner.program
        if program is None:
            return False
        try:
            export_gcode(program, path, self.station.profile)
        except (OSError, ValueError) as exc:
            self.say(self.tr("G-code not written: {0}").format(exc))
            return False
        self.say(self.tr("Wrote {0}").format(path))
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
        self._show_progress()
        estimate = self.runner.estimate if program is not None else None
        self._set_times(0.0 if estimate else None, estimate.total_s if estimate else None)
        self.operation_label.setText("")  # no lone dash where no operation is under way
        source = program.source if program is not None else None
        prepared, self._prepared_lines = self._prepared_lines, None
        read = prepared is not None and source is not None and prepared[0] == source
        if prepared is not None and read:
            self._source_lines = prepared[1]
        elif self._source_lines_of[1] is not program or self._source_lines_of[0] != source:
            # Not again for the program they were read for (a 2-million-line file takes long).
            self._source_lines = _read_lines(source)
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
        self._show_progress()

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
        offer = self.runner.resume_available is not None
        self.open_button.setEnabled(state not in ACTIVE_STATES and self._loading is None)
        # Registering replaces the loaded job: not while it runs.
        self.registration.setEnabled(state not in ACTIVE_STATES and self._loading is None)
        self.registration.set_job_running(state in ACTIVE_STATES)
        self.export_button.setEnabled(loaded)
        # With an interrupted run on offer, Run from the start would repeat operations:
        # the operator chooses Resume or Discard first.
        self.run_button.setEnabled(
            loaded
            and can_move
            and not offer
            and state in (JobState.READY, JobState.DONE, JobState.ABORTED, JobState.FAILED)
        )
        self.pause_button.setEnabled(state in (JobState.RUNNING, JobState.WAITING))
        answering = can_move and self.runner.question is not None
        self.resume_button.setEnabled(
            can_move
            and self.runner.question is None
            and self.runner.resume_choice is None
            and state in (JobState.PAUSED, JobState.PAUSING)
        )
        self.step_button.setEnabled(
            loaded
            and can_move
            and not offer
            and self.runner.resume_choice is None
            and state in (JobState.READY, JobState.PAUSED)
        )
        self.abort_button.setEnabled(state in ACTIVE_STATES)
        self.resume_checkpoint_button.setEnabled(can_move)
        self.continue_button.setEnabled(state is JobState.WAITING)
        self.again_button.setEnabled(answering)
        self.counted_button.setEnabled(answering)
        self.resume_choice.update_enabled()
        why = self.tr(" — motion locked: {0}").format(lock) if lock else ""
        self.run_button.setToolTip(self.tr("Run the job from the start") + why)

    def _show_progress(self, *_args: object) -> None:
        """The bar and count say what the machine ran; what is sent ahead is said beside it.

        A G-code machine answers lines long before it runs them (its planner holds a
        dozen or so), so counting answers showed a finished job on its first edge.
        """
        if self._bar_ms and self.runner.state is JobState.RUNNING:
            # QProgressBar repaints itself at once on every visible step (2.5 ms on the
            # window's thread): a fast job's thirty steps a second cost a tenth of a core.
            shown = self._bar_shown.elapsed() if self._bar_shown.isValid() else self._bar_ms
            if shown < self._bar_ms:
                if not self._bar_timer.isActive():
                    self._bar_timer.start(int(self._bar_ms - shown))
                return
            self._bar_shown.start()
        program = self.runner.program
        total = len(program) if program is not None else 0
        executed = self.runner.executed if program is not None else 0
        sent = self.runner.done if program is not None else 0
        self.progress.setRange(0, max(1, total))
        self.progress.setValue(min(executed, max(1, total)))
        text = self.tr("{0} / %n ops", "", total).format(executed)
        # Sent ahead only while the job runs: once it ended (an abort drops what the
        # machine held) the one figure is what ran, as the abort message says.
        if sent > executed and self.runner.state in ACTIVE_STATES:
            text += " · " + self.tr("{0} sent").format(sent)
        self.count_label.setText(text)
        self.count_label.setToolTip(
            self.tr(
                "Operations the machine reported as run, of all; and how many were sent to it "
                "(a G-code machine holds sent lines in its planner before it runs them)"
            )
        )

    def _show_eta(self, elapsed_s: float, remaining_s: float) -> None:
        self._set_times(elapsed_s, remaining_s)

    def _set_times(self, elapsed_s: float | None, remaining_s: float | None) -> None:
        self._times = (elapsed_s, remaining_s)
        self.elapsed_label.setText(self.tr("elapsed {0}").format(clock_text(elapsed_s)))
        self.eta_label.setText(self.tr("left {0}").format(clock_text(remaining_s)))

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
        session = self.station.drill_session
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


def _size(path: Path) -> int:
    try:
        return path.stat().st_size
    except OSError:
        return 0


class _Loading(QObject):
    """One job file read on a worker thread; ``done`` arrives on the GUI thread."""

    #: path, then (Program, its preview geometry, its source lines, the runner's checks), a
    #: JobFileError, or another exception's text.
    done = Signal(object, object)

    def __init__(
        self,
        path: Path,
        axis_names: list[str],
        options: JobOptions,
        geometry: Callable[[Program], ProgramGeometry | None],
        check: Callable[[Program], LoadCheck],
        parent: QObject,
    ) -> None:
        super().__init__(parent)
        self.path = path
        self._axis_names = axis_names
        self._options = options
        self._geometry = geometry
        self._check = check
        self._thread = threading.Thread(target=self._run, name="job-loader", daemon=True)

    def start(self) -> None:
        self._thread.start()

    def join(self) -> None:
        self._thread.join()

    def _run(self) -> None:
        result: object
        # No automatic collection while the file is read: a full one walks the whole heap
        # holding the interpreter lock (a tenth of a second and more), whichever thread
        # it falls on, and the GUI thread waits; what a load makes has no cycles to find.
        # Only this thread re-enables it, and only if it was on (one load at a time).
        collecting = gc.isenabled()
        gc.disable()
        try:
            result = self._result()
        finally:
            if collecting:
                gc.enable()
        self.done.emit(self.path, result)

    def _result(self) -> object:
        result: object
        try:
            program = load_job(self.path, self._axis_names, self._options)
            # The runner's checks and estimate too: for millions of operations they take
            # seconds, which the GUI thread must not.
            result = (
                program,
                self._geometry(program),
                _read_lines(program.source),
                self._check(program),
            )
        except JobFileError as exc:
            result = exc
        except Exception as exc:  # a loader bug must not take the window down
            result = f"{type(exc).__name__}: {exc}"
        return result


def _read_lines(path: Path | None) -> Sequence[str]:
    """The job file's lines, for showing an operation's source as written (empty if unreadable).

    Skipped for very large files: the operations carry their own text, and a copy of
    a million lines is memory for nothing.
    """
    if path is None or _size(path) > SOURCE_LINES_MAX_BYTES:
        return ()
    try:
        text = read_job_text(path, SOURCE_LINES_MAX_BYTES, latin1_fallback=True)
    except JobFileError:
        return ()
    return split_lines(text)


#: Characters split at a time: one ``str.splitlines`` holds the interpreter lock
#: throughout, and on 8 MB that kept the GUI thread waiting for a quarter of a second.
SPLIT_CHUNK_CHARS = 65_536


class SourceLines(Sequence[str]):
    """A file's lines as ``str.splitlines`` gives them, kept as the text and where each starts.

    Not a list of millions of strings: that was a hundred megabytes for a
    generator's 2-million-entry ``poradi.txt``, and every full garbage
    collection walked all two million (on whichever thread it fell, holding
    the interpreter lock).  A line is cut from the text when it is shown.
    """

    def __init__(self, text: str, starts: np.ndarray) -> None:
        self._text = text
        #: Where each line starts, then where the text ends (int64).
        self._starts = starts

    def __len__(self) -> int:
        return len(self._starts) - 1

    @overload
    def __getitem__(self, index: int) -> str: ...

    @overload
    def __getitem__(self, index: slice) -> Sequence[str]: ...

    def __getitem__(self, index: int | slice) -> str | Sequence[str]:
        if isinstance(index, slice):
            return [self[i] for i in range(*index.indices(len(self)))]
        if index < 0:
            index += len(self)
        if not 0 <= index < len(self):
            raise IndexError(index)
        # The line with its line end (one of those splitlines knows), cut off as splitlines does.
        piece = self._text[int(self._starts[index]) : int(self._starts[index + 1])].splitlines()
        return piece[0] if piece else ""


def split_lines(text: str) -> SourceLines:
    """``text.splitlines()`` in pieces, so the GUI thread gets the lock between them."""
    lengths: list[np.ndarray] = []
    start = 0
    while start < len(text):
        end = start + SPLIT_CHUNK_CHARS
        if end < len(text):
            # Cut just after an LF, always a line end (a CR LF pair stays whole); a piece
            # with none runs on to the next (a file of CRs alone is split in one go).
            cut = text.rfind("\n", start, end)
            if cut < 0:
                cut = text.find("\n", end)
            end = cut + 1 if cut >= 0 else len(text)
        else:
            end = len(text)
        piece = text[start:end].splitlines(keepends=True)
        lengths.append(np.fromiter(map(len, piece), dtype=np.int64, count=len(piece)))
        start = end
    starts = np.zeros(1 + sum(len(part) for part in lengths), dtype=np.int64)
    if len(starts) > 1:
        np.cumsum(np.concatenate(lengths), out=starts[1:])
    return SourceLines(text, starts)
