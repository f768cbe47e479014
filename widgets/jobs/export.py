"""The jobs dock's Export…: the loaded job as G-code, or a string-art job's SD-card files.

Texts keep the ``JobsDock`` translation context they had in the dock.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtWidgets import QFileDialog, QMenu, QWidget

from app.jobs.formats.string_art.export import export_gcode, export_sd_files
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.run.runner import JobRunner
from app.station import Station
from widgets.jobs.run_controls import job_button
from widgets.retranslate import Texts


class JobExport(QObject):
    """The Export… button (:attr:`button`), its menu of what this job and machine can be
    written as, and the writing; ``say`` tells the operator how it went."""

    def __init__(
        self,
        station: Station,
        runner: JobRunner,
        texts: Texts,
        say: Callable[[str], None],
        parent: QWidget,
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._runner = runner
        self._say = say
        self._parent = parent
        self.button = job_button(
            texts,
            lambda: QCoreApplication.translate("JobsDock", "Export…"),
            "job_export",
            lambda: QCoreApplication.translate(
                "JobsDock", "Write the loaded job out: G-code, or a string-art job's SD-card files"
            ),
            self.ask_export,
        )

    def ask_export(self) -> None:
        program = self._runner.program
        if program is None:
            return
        menu = QMenu(self._parent)
        if isinstance(program, StringArtProgram):
            menu.addAction(
                QCoreApplication.translate("JobsDock", "SD-card files (param.txt, poradi.txt)…"),
                self._ask_export_sd,
            )
        if self._station.profile.gcode is not None:
            menu.addAction(
                QCoreApplication.translate("JobsDock", "G-code program…"), self._ask_export_gcode
            )
        if menu.isEmpty():
            self._say(
                QCoreApplication.translate(
                    "JobsDock", "Nothing to export for this job on this machine"
                )
            )
            return
        menu.exec(self.button.mapToGlobal(self.button.rect().bottomLeft()))

    def _ask_export_sd(self) -> None:
        directory = QFileDialog.getExistingDirectory(
            self._parent,
            QCoreApplication.translate("JobsDock", "Folder for param.txt and poradi.txt"),
        )
        if directory:
            self.export_sd(Path(directory))

    def _ask_export_gcode(self) -> None:
        program = self._runner.program
        name = f"{program.name}.gcode" if program is not None else "job.gcode"
        path, _ = QFileDialog.getSaveFileName(
            self._parent,
            QCoreApplication.translate("JobsDock", "Export G-code"),
            name,
            QCoreApplication.translate("JobsDock", "G-code (*.gcode)"),
        )
        if path:
            self.export_gcode(Path(path))

    def export_sd(self, directory: Path) -> bool:
        """The string-art job as its standalone firmware reads it from an SD card."""
        program = self._runner.program
        if not isinstance(program, StringArtProgram):
            self._say(
                QCoreApplication.translate("JobsDock", "Only string-art jobs have SD-card files")
            )
            return False
        try:
            param, poradi = export_sd_files(program.job, directory)
        except OSError as exc:
            self._say(
                QCoreApplication.translate("JobsDock", "SD-card files not written: {0}").format(exc)
            )
            return False
        self._say(QCoreApplication.translate("JobsDock", "Wrote {0} and {1}").format(param, poradi))
        return True

    def export_gcode(self, path: Path) -> bool:
        """The loaded job as the G-code this machine would be sent."""
        program = self._runner.program
        if program is None:
            return False
        try:
            export_gcode(program, path, self._station.profile)
        except (OSError, ValueError) as exc:
            self._say(QCoreApplication.translate("JobsDock", "G-code not written: {0}").format(exc))
            return False
        self._say(QCoreApplication.translate("JobsDock", "Wrote {0}").format(path))
        return True
