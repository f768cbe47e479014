"""The operator's pick of where an interrupted G-code job goes on, when only they can say.

After a fault the station knows which lines are proven run and which were
sent but may or may not have run (see :class:`app.jobs.run.driver.ResumeChoice`).
Resuming too early draws a stroke twice, too late leaves one out, and only
someone looking at the paper can tell: so the candidates are listed, their
segments highlighted in the preview, and nothing moves until one is picked.
"""

from __future__ import annotations

from collections.abc import Callable

from PySide6.QtCore import Qt
from PySide6.QtWidgets import (
    QFrame,
    QHBoxLayout,
    QLabel,
    QListWidget,
    QListWidgetItem,
    QPushButton,
    QVBoxLayout,
)

from app.jobs.run.driver import ResumeChoice
from app.jobs.run.runner import JobRunner
from widgets.jobs.operation_text import operation_text
from widgets.jobs.preview import JobPreview
from widgets.retranslate import Texts

#: The rows' data role: the operation index resuming there starts with.
INDEX_ROLE = Qt.ItemDataRole.UserRole
#: Rows listed at most (a resume from a checkpoint offers a window of lines).
ROWS_SHOWN = 400


class ResumeChoicePanel(QFrame):
    """A banner with the candidate lines; Resume goes on from the one picked."""

    def __init__(
        self,
        runner: JobRunner,
        preview: JobPreview,
        file_line: Callable[[int], str],
        can_move: Callable[[], bool],
    ) -> None:
        super().__init__()
        self.setObjectName("job_resume_choice")
        self.setStyleSheet("#job_resume_choice { background: #fde8e8; border: 1px solid #e08080; }")
        self.runner = runner
        self.preview = preview
        self._file_line = file_line
        self._can_move = can_move
        self.texts = Texts(self)
        layout = QVBoxLayout(self)
        layout.setContentsMargins(6, 4, 6, 4)
        self.label = QLabel()
        self.label.setObjectName("job_resume_choice_text")
        self.label.setWordWrap(True)
        self.label.setTextFormat(Qt.TextFormat.PlainText)
        self.lines = QListWidget()
        self.lines.setObjectName("job_resume_lines")
        self.lines.setMaximumHeight(120)
        self.texts.set(
            self.lines.setToolTip,
            lambda: self.tr(
                "Sent, but not proven run: pick the first line the drawing does not show yet"
            ),
        )
        self.lines.currentItemChanged.connect(self._picked)
        row = QHBoxLayout()
        self.resume_button = self.texts.button(
            lambda: self.tr("Resume from the chosen line"),
            lambda: self.tr("The machine goes there with the pen up, then carries on"),
        )
        self.resume_button.setObjectName("job_resume_at")
        self.resume_button.clicked.connect(self._resume)
        row.addStretch(1)
        row.addWidget(self.resume_button)
        layout.addWidget(self.label)
        layout.addWidget(self.lines)
        layout.addLayout(row)
        self._choice: ResumeChoice | None = None
        runner.resumeChoiceNeeded.connect(self.offer)
        self.hide()

    @property
    def button(self) -> QPushButton:
        return self.resume_button

    def offer(self, choice: ResumeChoice) -> None:
        """List ``choice``'s candidates, highlight their segments, preselect only a safe one."""
        program = self.runner.program
        if program is None:
            return
        self._choice = choice
        self.label.setText(choice.text)
        self.lines.blockSignals(True)
        self.lines.clear()
        for index in list(choice.candidates)[:ROWS_SHOWN]:
            if index < len(program):
                op = program[index]
                text = self.tr("from op {0}: {1}  {2}").format(
                    index + 1, op.source, operation_text(op)
                )
                raw = self._file_line(op.source.line)
                if raw:
                    text += f"   ({raw})"
            else:
                text = self.tr("none of them: the job is at its end")
            item = QListWidgetItem(text)
            item.setData(INDEX_ROLE, index)
            self.lines.addItem(item)
        self.lines.blockSignals(False)
        self.preview.mark_candidates(choice.first, choice.last)
        if choice.default is not None:
            self.lines.setCurrentRow(choice.default - choice.first)
        else:
            self.lines.setCurrentRow(-1)
            self.preview.mark_question(None)
        self.show()
        self.update_enabled()

    def withdraw(self) -> None:
        """The choice was made or the job ended: nothing to pick any more."""
        if self._choice is None and self.isHidden():
            return
        self._choice = None
        self.lines.clear()
        self.preview.mark_candidates(None)
        self.preview.mark_question(None)
        self.hide()

    def chosen(self) -> int | None:
        item = self.lines.currentItem()
        if item is None:
            return None
        index = item.data(INDEX_ROLE)
        return int(index) if index is not None else None

    def update_enabled(self) -> None:
        self.resume_button.setEnabled(
            self._choice is not None and self.chosen() is not None and self._can_move()
        )

    def _picked(self, *_args: object) -> None:
        index = self.chosen()
        program = self.runner.program
        if index is not None and program is not None and index < len(program):
            self.preview.mark_question(index)
        else:
            self.preview.mark_question(None)
        self.update_enabled()

    def _resume(self) -> None:
        index = self.chosen()
        if index is None or self._choice is None:
            return
        self.runner.resume_at(index)
