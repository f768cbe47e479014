"""The jobs dock's run controls: Run, Pause, Resume, Step, Abort, and where the job is.

Buttons are enabled from the runner's state alone, so a button the operator
can press is one the runner will honour.  The bar and count say what the
machine ran, moving at most every :data:`PROGRESS_BAR_MS` while a job runs.
Texts keep the ``JobsDock`` translation context they had in the dock.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import QCoreApplication, QElapsedTimer, QObject, QTimer
from PySide6.QtWidgets import QHBoxLayout, QLabel, QProgressBar, QPushButton, QVBoxLayout

from app.jobs.run.progress import WAITING_SHOWN_S
from app.jobs.run.runner import JobRunner, JobState
from widgets.jobs.preview import ACTIVE_STATES
from widgets.retranslate import Maker, Texts
from widgets.style import monospace_font

# While a job runs, the progress bar and count move at most this often (ms).
PROGRESS_BAR_MS = 100


def job_button(
    texts: Texts, text: Maker, name: str, tip: Maker, slot: Callable[[], object]
) -> QPushButton:
    """A dock button with its object name, its texts made again on a language switch."""
    button = texts.button(text, tip)
    button.setObjectName(name)
    button.clicked.connect(lambda _=False: slot())
    return button


def clock_text(seconds: float | None) -> str:
    """mm:ss (h:mm:ss past an hour); "--:--" when unknown."""
    if seconds is None or seconds != seconds or seconds < 0:  # None, NaN or nonsense
        return "--:--"
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes:02d}:{secs:02d}"


class RunControls(QObject):
    """The run buttons (:attr:`buttons`, a row) and the progress (:attr:`progress_rows`)."""

    def __init__(
        self,
        runner: JobRunner,
        texts: Texts,
        throttle_ms: float | None,
        count_text: Callable[[int, int], str],
        parent: QObject,
    ) -> None:
        """``count_text``: "{executed} / %n ops" for (executed, total), made where lupdate
        sees its plural forms (a ``tr`` in the dock's own class)."""
        super().__init__(parent)
        self._count_text = count_text
        self._runner = runner
        self._texts = texts
        self._times: tuple[float | None, float | None] = (None, None)
        # While a job runs the bar and count move at most every _bar_ms (0: at once).
        self._bar_ms = PROGRESS_BAR_MS if throttle_ms is None or throttle_ms > 0 else 0
        self._bar_shown = QElapsedTimer()
        self._bar_timer = QTimer(self)
        self._bar_timer.setSingleShot(True)
        self._bar_timer.timeout.connect(self.show_progress)
        self.buttons = self._build_buttons()
        self.progress_rows = self._build_progress()
        runner.progressChanged.connect(self.show_progress)
        runner.executedChanged.connect(self.show_progress)
        runner.etaChanged.connect(self.set_times)

    def _build_buttons(self) -> QHBoxLayout:
        t, runner = self._texts, self._runner
        self.run_button = job_button(
            t,
            lambda: QCoreApplication.translate("JobsDock", "Run"),
            "job_run",
            lambda: QCoreApplication.translate("JobsDock", "Run the job from the start"),
            runner.start,
        )
        self.pause_button = job_button(
            t,
            lambda: QCoreApplication.translate("JobsDock", "Pause"),
            "job_pause",
            lambda: QCoreApplication.translate(
                "JobsDock", "Pause after the operation under way finishes"
            ),
            runner.pause,
        )
        self.resume_button = job_button(
            t,
            lambda: QCoreApplication.translate("JobsDock", "Resume"),
            "job_resume",
            lambda: QCoreApplication.translate("JobsDock", "Go on from where the job paused"),
            runner.resume,
        )
        self.step_button = job_button(
            t,
            lambda: QCoreApplication.translate("JobsDock", "Step"),
            "job_step",
            lambda: QCoreApplication.translate(
                "JobsDock", "Execute the next operation only, then pause"
            ),
            runner.step,
        )
        self.abort_button = job_button(
            t,
            lambda: QCoreApplication.translate("JobsDock", "Abort"),
            "job_abort",
            lambda: QCoreApplication.translate("JobsDock", "Stop the machine now and end the job"),
            runner.abort,
        )
        self.abort_button.setStyleSheet(
            "QPushButton:enabled { color: #b00020; font-weight: bold; }"
        )
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
        return controls

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
        self._texts.set(
            self.elapsed_label.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "Time since the job started, prompts and pauses included; "
                "of it, how long the machine waited for you",
            ),
        )
        self.eta_label = QLabel()
        self.eta_label.setObjectName("job_eta")
        self.eta_label.setFont(monospace_font())
        self._texts.set(
            self.eta_label.setToolTip,
            lambda: QCoreApplication.translate(
                "JobsDock", "Time left, from the dry run of the job on the machine's model"
            ),
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
        self.set_times(None, None)
        return rows

    def update_enabled(self, lock: str | None, offer: bool) -> None:
        """The buttons the runner will honour now (``lock``: why motion is refused; ``offer``:
        an interrupted run is on offer)."""
        runner = self._runner
        state = runner.state
        loaded = runner.program is not None
        can_move = lock is None
        # With an interrupted run on offer, Run from the start would repeat operations:
        # the operator chooses Resume or Discard first.
        self.run_button.setEnabled(
            loaded
            and can_move
            and not offer
            and state in (JobState.READY, JobState.DONE, JobState.ABORTED, JobState.FAILED)
        )
        self.pause_button.setEnabled(state in (JobState.RUNNING, JobState.WAITING))
        self.resume_button.setEnabled(
            can_move
            and runner.question is None
            and runner.resume_choice is None
            and state in (JobState.PAUSED, JobState.PAUSING)
        )
        self.step_button.setEnabled(
            loaded
            and can_move
            and not offer
            and runner.resume_choice is None
            and state in (JobState.READY, JobState.PAUSED)
        )
        self.abort_button.setEnabled(state in ACTIVE_STATES)
        why = (
            QCoreApplication.translate("JobsDock", " — motion locked: {0}").format(lock)
            if lock
            else ""
        )
        self.run_button.setToolTip(
            QCoreApplication.translate("JobsDock", "Run the job from the start") + why
        )

    def show_progress(self, *_args: object) -> None:
        """The bar and count say what the machine ran; what is sent ahead is said beside it.

        A G-code machine answers lines long before it runs them (its planner holds a
        dozen or so), so counting answers showed a finished job on its first edge.
        """
        runner = self._runner
        if self._bar_ms and runner.state is JobState.RUNNING:
            # QProgressBar repaints itself at once on every visible step (2.5 ms on the
            # window's thread): a fast job's thirty steps a second cost a tenth of a core.
            shown = self._bar_shown.elapsed() if self._bar_shown.isValid() else self._bar_ms
            if shown < self._bar_ms:
                if not self._bar_timer.isActive():
                    self._bar_timer.start(int(self._bar_ms - shown))
                return
            self._bar_shown.start()
        program = runner.program
        total = len(program) if program is not None else 0
        executed = runner.progress.executed if program is not None else 0
        sent = runner.done if program is not None else 0
        # QProgressBar repaints at once (a synchronous paint of its part of the window)
        # on a visible step; held, it is painted with the rest of the window's frame.
        self.progress.setUpdatesEnabled(False)
        self.progress.setRange(0, max(1, total))
        self.progress.setValue(min(executed, max(1, total)))
        self.progress.setUpdatesEnabled(True)  # schedules the one paint (an update())
        text = self._count_text(executed, total)
        # Sent ahead only while the job runs: once it ended (an abort drops what the
        # machine held) the one figure is what ran, as the abort message says.
        if sent > executed and runner.state in ACTIVE_STATES:
            text += " · " + QCoreApplication.translate("JobsDock", "{0} sent").format(sent)
        self.count_label.setText(text)
        self.count_label.setToolTip(
            QCoreApplication.translate(
                "JobsDock",
                "Operations the machine reported as run, of all; and how many were sent to it "
                "(a G-code machine holds sent lines in its planner before it runs them)",
            )
        )

    def set_times(self, elapsed_s: float | None, remaining_s: float | None) -> None:
        self._times = (elapsed_s, remaining_s)
        text = QCoreApplication.translate("JobsDock", "elapsed {0}").format(clock_text(elapsed_s))
        waiting = self._runner.progress.waiting_s if elapsed_s else 0.0
        if waiting >= WAITING_SHOWN_S:
            text += " " + QCoreApplication.translate(
                "JobsDock", "(of which {0} waiting for you)"
            ).format(clock_text(waiting))
        self.elapsed_label.setText(text)
        self.eta_label.setText(
            QCoreApplication.translate("JobsDock", "left {0}").format(clock_text(remaining_s))
        )

    def retranslate(self) -> None:
        """The progress and times said again in the new language."""
        self.show_progress()
        self.set_times(*self._times)
