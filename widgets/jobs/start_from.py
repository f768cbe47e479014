"""The jobs dock's "Run from…": pick a line of the job (or a stroke in the preview), run from there.

A start part-way is a resume at a point the operator chose
(:meth:`~app.jobs.run.runner.JobRunner.start_from`): the station sets the
machine up as the file had it there and brings it there with the pen up,
or says why it cannot (file:line), and nothing moves.  The dialog lists the
job's operations with their file lines; while it is open a click in the
preview picks the stroke under the pointer instead of moving the machine.
Texts keep the ``JobsDock`` translation context.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
from PySide6.QtCore import (
    QAbstractListModel,
    QCoreApplication,
    QModelIndex,
    QObject,
    QPersistentModelIndex,
    QPoint,
    Qt,
)
from PySide6.QtGui import QAction, QCloseEvent, QKeySequence
from PySide6.QtWidgets import (
    QDialog,
    QDialogButtonBox,
    QLabel,
    QListView,
    QMenu,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.jobs.program import Program
from app.jobs.run.runner import JobRunner
from app.jobs.run.states import ACTIVE, FINISHED, JobState
from widgets.jobs.operation_text import operation_text
from widgets.jobs.preview import JobPreview
from widgets.jobs.run_controls import job_button
from widgets.jobs.start_planning import StartPlanning
from widgets.retranslate import Texts

# The key that opens the list (Help → Keys lists it).
SHORTCUT = "Ctrl+Shift+R"


class OperationsModel(QAbstractListModel):
    """The job's operations as rows, each made when shown (a file may have a million)."""

    def __init__(self, program: Program, file_line: Callable[[int], str]) -> None:
        super().__init__()
        self.program = program
        self._file_line = file_line

    def rowCount(self, parent: QModelIndex | QPersistentModelIndex | None = None) -> int:
        return 0 if parent is not None and parent.isValid() else len(self.program)

    def data(
        self, index: QModelIndex | QPersistentModelIndex, role: int = Qt.ItemDataRole.DisplayRole
    ) -> object:
        if role != Qt.ItemDataRole.DisplayRole or not 0 <= index.row() < len(self.program):
            return None
        op = self.program[index.row()]
        text = QCoreApplication.translate("JobsDock", "op {0}: {1}  {2}").format(
            index.row() + 1, op.source, operation_text(op)
        )
        raw = self._file_line(op.source.line)
        return f"{text}   ({raw})" if raw else text


def nearest_stroke(program: Program, axes: tuple[str, str | None], x: float, y: float) -> int:
    """The operation whose stretch of path passes nearest (x, y): starting there draws it whole."""
    path = program.preview_path(axes[0], axes[1])
    coords, ops = path.coords[:, :2], path.ops
    if len(ops) == 0:
        return 0
    if len(ops) == 1:
        return int(ops[0])
    a, b = coords[:-1], coords[1:]
    span = b - a
    here = np.array([x, y])
    length2 = np.einsum("ij,ij->i", span, span)
    with np.errstate(invalid="ignore", divide="ignore"):
        t = np.clip(np.einsum("ij,ij->i", here - a, span) / length2, 0.0, 1.0)
    t = np.where(length2 > 0, t, 0.0)
    distance = np.hypot(*(a + t[:, None] * span - here).T)
    distance = np.where(np.isnan(distance), np.inf, distance)
    return int(ops[int(np.argmin(distance)) + 1])


class StartFromDialog(QDialog):
    """The job's operations; Run from here starts at the one picked (list or preview)."""

    def __init__(
        self,
        runner: JobRunner,
        preview: JobPreview,
        file_line: Callable[[int], str],
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("job_start_from")
        self.runner = runner
        self.preview = preview
        self.texts = Texts(self)
        self.texts.set(
            self.setWindowTitle, lambda: QCoreApplication.translate("JobsDock", "Run from a line")
        )
        program = runner.program
        assert program is not None
        self.program = program
        layout = QVBoxLayout(self)
        hint = QLabel()
        hint.setWordWrap(True)
        self.texts.set(
            hint.setText,
            lambda: QCoreApplication.translate(
                "JobsDock",
                "Pick the line to start from, here or by clicking its stroke in the preview. "
                "The machine goes there with the pen up, set as the file had it there (units, "
                "distance mode, feed, offsets, pen), then carries on; the lines before it count "
                "as run.",
            ),
        )
        self.lines = QListView()
        self.lines.setObjectName("job_start_lines")
        self.lines.setUniformItemSizes(True)
        self.model = OperationsModel(program, file_line)
        self.lines.setModel(self.model)
        self.lines.selectionModel().currentChanged.connect(self._picked)
        self.lines.doubleClicked.connect(self.run_from_here)
        self.lines.setContextMenuPolicy(Qt.ContextMenuPolicy.CustomContextMenu)
        self.lines.customContextMenuRequested.connect(self._menu)
        self.reason = QLabel()
        self.reason.setObjectName("job_start_reason")
        self.reason.setWordWrap(True)
        self.reason.setTextFormat(Qt.TextFormat.PlainText)
        self.reason.setStyleSheet("color: #b00020;")
        buttons = QDialogButtonBox(QDialogButtonBox.StandardButton.Close)
        self.run_button = QPushButton()
        self.run_button.setObjectName("job_run_from_here")
        self.texts.set(
            self.run_button.setText, lambda: QCoreApplication.translate("JobsDock", "Run from here")
        )
        self.run_button.clicked.connect(self.run_from_here)
        buttons.addButton(self.run_button, QDialogButtonBox.ButtonRole.ActionRole)
        buttons.rejected.connect(self.close)
        layout.addWidget(hint)
        layout.addWidget(self.lines, 1)
        layout.addWidget(self.reason)
        layout.addWidget(buttons)
        self.resize(640, 420)
        self._said: list[str] = []
        # The start being worked out, while it is.
        self.planning: StartPlanning | None = None
        runner.message.connect(self._heard)
        preview.point_picker = self.pick_point
        self._update_enabled()

    def chosen(self) -> int | None:
        index = self.lines.currentIndex()
        return index.row() if index.isValid() else None

    def select(self, index: int) -> None:
        """Operation ``index`` as the pick (the list scrolls to it, the preview rings it)."""
        row = self.model.index(index, 0)
        self.lines.setCurrentIndex(row)
        self.lines.scrollTo(row)

    def pick_point(self, x: float, y: float) -> None:
        """A click in the preview: the stroke nearest it (the winder's plot is not its axes)."""
        if self.preview.polar is not None:
            self.reason.setText(
                QCoreApplication.translate("JobsDock", "On this machine pick the line in the list")
            )
            return
        names = self.preview.axis_names
        axes = (names[0], names[1] if len(names) > 1 else None)
        self.select(nearest_stroke(self.program, axes, x, y))

    def run_from_here(self) -> None:
        """The state at the pick is worked out on a worker thread first (a long file's takes
        longer than the window may stand still), then the runner starts there."""
        index = self.chosen()
        if index is None or self.planning is not None:
            return
        self.reason.setText(
            QCoreApplication.translate(
                "JobsDock", "Working out the machine's state at {0}…"
            ).format(self.program[index].source)
        )
        axes = [axis.name for axis in self.runner.station.profile.axes]
        self.planning = StartPlanning(self.program, index, axes, self.parent())
        self.planning.done.connect(self._planned)
        self._update_enabled()
        self.planning.start()

    def _planned(self, index: int) -> None:
        self.planning = None
        self._update_enabled()
        self.reason.clear()
        if not self.isVisible() or self.runner.program is not self.program:
            return  # closed meanwhile (the operator changed their mind), or another job
        self._said.clear()
        self.runner.start_from(index)
        if self.runner.state in ACTIVE:
            self.close()
        else:  # refused: why, where the operator looks
            self.reason.setText(self._said[-1] if self._said else "")

    def _picked(self, *_args: object) -> None:
        self.reason.clear()
        index = self.chosen()
        self.preview.mark_question(index)
        self._update_enabled()

    def _update_enabled(self) -> None:
        self.run_button.setEnabled(self.chosen() is not None and self.planning is None)

    def context_menu(self) -> QMenu:
        """The list's right-click menu: Run from here (the row under the pointer is current)."""
        menu = QMenu(self)
        menu.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        action = menu.addAction(QCoreApplication.translate("JobsDock", "Run from here"))
        action.setObjectName("job_run_from_here_menu")
        action.triggered.connect(self.run_from_here)
        return menu

    def _menu(self, where: QPoint) -> None:
        row = self.lines.indexAt(where)
        if row.isValid():
            self.lines.setCurrentIndex(row)
            self.context_menu().popup(self.lines.viewport().mapToGlobal(where))

    def _heard(self, text: str) -> None:
        self._said.append(text)

    def closeEvent(self, event: QCloseEvent) -> None:
        if self.preview.point_picker == self.pick_point:
            self.preview.point_picker = None
        self.preview.mark_question(None)
        self.runner.message.disconnect(self._heard)
        super().closeEvent(event)


class StartFromLaunch(QObject):
    """The "Run from…" button (:attr:`button`), its key, and the dialog while it is open."""

    def __init__(
        self,
        runner: JobRunner,
        preview: JobPreview,
        file_line: Callable[[int], str],
        texts: Texts,
        parent: QWidget,
    ) -> None:
        super().__init__(parent)
        self._runner = runner
        self._preview = preview
        self._file_line = file_line
        self._parent = parent
        self.dialog: StartFromDialog | None = None
        self.button = job_button(
            texts,
            lambda: QCoreApplication.translate("JobsDock", "Run from…"),
            "job_run_from",
            lambda: QCoreApplication.translate(
                "JobsDock", "Start the job at a line you pick (list or preview) ({0})"
            ).format(SHORTCUT),
            self.open,
        )
        self.action = QAction(parent)
        self.action.setObjectName("job_run_from_action")
        self.action.setShortcut(QKeySequence(SHORTCUT))
        self.action.triggered.connect(self.open)
        parent.addAction(self.action)
        runner.stateChanged.connect(self.update_enabled)
        runner.programChanged.connect(self._program_changed)
        self.update_enabled()

    def can_start(self) -> bool:
        runner = self._runner
        return runner.program is not None and runner.state in (JobState.READY, *FINISHED)

    def update_enabled(self, *_args: object) -> None:
        can = self.can_start()
        self.button.setEnabled(can)
        self.action.setEnabled(can)
        if not can and self.dialog is not None:
            self.dialog.close()  # a job under way (or none loaded): nothing to start from

    def open(self) -> StartFromDialog | None:
        if not self.can_start():
            return None
        if self.dialog is not None:
            self.dialog.raise_()
            self.dialog.activateWindow()
            return self.dialog
        dialog = StartFromDialog(self._runner, self._preview, self._file_line, self._parent)
        dialog.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        dialog.finished.connect(self._closed)
        self.dialog = dialog
        dialog.show()
        return dialog

    def _program_changed(self) -> None:
        if self.dialog is not None:
            self.dialog.close()  # its rows were the old job's
        self.update_enabled()

    def _closed(self, *_args: object) -> None:
        self.dialog = None
