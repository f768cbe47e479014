"""The macros dock: a button per macro, the run under way, Stop and Resume, and Edit….

A button runs its macro through :class:`~app.macros.runner.MacroRunner`,
which refuses it (said here, with the line and the reason) or runs it as a
small job.  The buttons are off, with the reason beside them, whenever a run
would be refused anyway (a job under way, disconnected, a macro running).
"""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtWidgets import (
    QDockWidget,
    QGridLayout,
    QHBoxLayout,
    QLabel,
    QProgressBar,
    QPushButton,
    QVBoxLayout,
    QWidget,
)

from app.jobs.run.states import ACTIVE, JobState
from app.macros.runner import MacroRunner, macro_checkpoint_dir
from app.macros.store import Macro, MacroStore
from app.station import Station
from widgets.jobs.lock_text import retranslate_jog_lock
from widgets.retranslate import Texts

#: Buttons a row.
COLUMNS = 3


class MacrosDock(QDockWidget):
    """One profile's macro buttons, and the run of the one pressed."""

    def __init__(
        self,
        station: Station,
        store: MacroStore,
        checkpoint_dir: Path | None = None,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.setObjectName("macros_dock")
        self.station = station
        self.store = store
        self.runner = MacroRunner(station, checkpoint_dir or macro_checkpoint_dir(), self)
        self.macros: list[Macro] = store.load()
        t = self.texts = Texts(self)
        t.set(self.setWindowTitle, lambda: self.tr("Macros"))
        body = QWidget()
        layout = QVBoxLayout(body)
        self.grid = QGridLayout()
        layout.addLayout(self.grid)
        self.empty_label = t.label(lambda: self.tr("No macros yet: Edit… adds one."))
        layout.addWidget(self.empty_label)
        self.lock_label = QLabel()
        self.lock_label.setObjectName("macro_lock")
        self.lock_label.setWordWrap(True)
        layout.addWidget(self.lock_label)
        self.progress = QProgressBar()
        self.progress.setTextVisible(True)
        layout.addWidget(self.progress)
        controls = QHBoxLayout()
        self.stop_button = t.button(
            lambda: self.tr("Stop"), lambda: self.tr("Stop the macro (Esc)")
        )
        self.stop_button.clicked.connect(self.runner.abort)
        self.resume_button = t.button(
            lambda: self.tr("Resume"), lambda: self.tr("Go on after a pause or a prompt")
        )
        self.resume_button.clicked.connect(self._resume)
        self.edit_button = t.button(
            lambda: self.tr("Edit…"), lambda: self.tr("Add, change, order, import and export")
        )
        self.edit_button.clicked.connect(self.edit)
        for button in (self.stop_button, self.resume_button, self.edit_button):
            controls.addWidget(button)
        layout.addLayout(controls)
        self.message_label = QLabel()
        self.message_label.setObjectName("macro_message")
        self.message_label.setWordWrap(True)
        self.message_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        layout.addWidget(self.message_label)
        layout.addStretch(1)
        self.setWidget(body)
        self.buttons: list[QPushButton] = []
        self.editor: QWidget | None = None
        runner = self.runner
        runner.message.connect(self.message_label.setText)
        runner.stateChanged.connect(self._update)
        runner.progressChanged.connect(self._on_progress)
        runner.waitingForOperator.connect(self._on_prompt)
        model = station.model
        model.lockChanged.connect(self._update)
        model.linkStateChanged.connect(self._update)
        station.sessionChanged.connect(self._update)
        t.also(lambda: retranslate_jog_lock(self.runner.runner))  # first: _update reads it
        t.also(self._update)
        self._build_buttons()
        # Macros the settings file held but could not be read back (said once, here).
        warnings = store.settings.take_warnings()
        if warnings:
            self.message_label.setText("\n".join(warnings))

    # --- the buttons ---------------------------------------------------------------

    def _build_buttons(self) -> None:
        for button in self.buttons:
            self.grid.removeWidget(button)
            button.deleteLater()
        self.buttons = []
        for index, macro in enumerate(self.macros):
            button = QPushButton(f"{index + 1}  {macro.name}" if index < 9 else macro.name)
            button.setObjectName(f"macro_button_{index}")
            key = f"Ctrl+{index + 1}" if index < 9 else ""
            button.setToolTip(f"{key}\n{macro.code}".strip())
            button.clicked.connect(lambda _=False, name=macro.name: self.run_named(name))
            self.grid.addWidget(button, index // COLUMNS, index % COLUMNS)
            self.buttons.append(button)
        self.empty_label.setVisible(not self.macros)
        self._update()

    def run_named(self, name: str) -> bool:
        macro = next((m for m in self.macros if m.name == name), None)
        return macro is not None and self.runner.run(macro)

    def run_index(self, index: int) -> bool:
        """The ``index``-th macro (its key); one that is not there is said, not guessed."""
        if not 0 <= index < len(self.macros):
            self.message_label.setText(self.tr("No macro {0}").format(index + 1))
            return False
        return self.runner.run(self.macros[index])

    def set_macros(self, macros: list[Macro]) -> None:
        """Keep ``macros`` for this profile and show their buttons."""
        self.store.save(macros)
        self.macros = list(macros)
        self._build_buttons()

    def edit(self) -> None:
        """The editor (non-modal): its OK keeps the list and rebuilds the buttons."""
        from widgets.macros.editor import MacroEditor

        editor = MacroEditor(self.macros, self.station.profile.name, self)
        editor.accepted.connect(lambda: self.set_macros(editor.macros))
        editor.setAttribute(Qt.WidgetAttribute.WA_DeleteOnClose)
        self.editor = editor
        editor.show()

    # --- the run -----------------------------------------------------------------

    def _resume(self) -> None:
        if self.runner.state is JobState.WAITING:
            self.runner.confirm()
        else:
            self.runner.resume()

    def _on_progress(self, done: int, total: int) -> None:
        self.progress.setMaximum(max(total, 1))
        self.progress.setValue(done)

    def _on_prompt(self, text: str) -> None:
        self.message_label.setText(
            self.tr("Macro {0} waits: {1} — Resume when done").format(repr(self.runner.name), text)
        )

    def _update(self, *_: object) -> None:
        state = self.runner.state
        why = self.runner.refusal()
        for button in self.buttons:
            button.setEnabled(why is None)
        self.lock_label.setText(
            "" if why is None or not self.macros else self.tr("Macros locked: {0}").format(why)
        )
        self.lock_label.setVisible(why is not None and bool(self.macros))
        # No bar (an empty white box) until a macro has run: it shows that run's progress.
        self.progress.setVisible(state is not JobState.IDLE)
        self.stop_button.setEnabled(state in ACTIVE)
        self.resume_button.setEnabled(state in (JobState.PAUSED, JobState.WAITING))
        if state in ACTIVE:
            self.progress.setFormat(
                QCoreApplication.translate("MacrosDock", "{0}: %v of %m").format(self.runner.name)
            )
        elif state is JobState.DONE:
            self.progress.setFormat(self.tr("{0}: done").format(self.runner.name))
        elif state in (JobState.ABORTED, JobState.FAILED):
            self.progress.setFormat(self.tr("{0}: stopped").format(self.runner.name))
        else:
            self.progress.setFormat("")
