"""The jobs dock's "From photo…": the string-art generator, opened on the loaded board.

Only the winder winds thread (its axes: base A, needle X, drill Z), so only
there is the button shown.  The dialog (and scikit-image behind it) is loaded
when first opened.  Texts keep the ``JobsDock`` translation context.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING

from PySide6.QtCore import QCoreApplication, QObject
from PySide6.QtWidgets import QWidget

from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.run.runner import JobRunner
from app.station import Station
from widgets.jobs.run_controls import job_button
from widgets.retranslate import Texts

if TYPE_CHECKING:
    from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog


class StringArtLaunch(QObject):
    """The "From photo…" button (:attr:`button`) and the generator dialog while it is open."""

    def __init__(
        self,
        station: Station,
        runner: JobRunner,
        texts: Texts,
        open_path: Callable[[Path], bool],
        parent: QWidget,
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._runner = runner
        self._open_path = open_path
        self._parent = parent
        #: The "From photo…" dialog while it is open.
        self.dialog: StringArtGeneratorDialog | None = None
        self.button = job_button(
            texts,
            lambda: QCoreApplication.translate("JobsDock", "From photo…"),
            "job_from_photo",
            lambda: QCoreApplication.translate(
                "JobsDock",
                "String art from a photo: make a nail sequence, see it, load it as a job",
            ),
            self.open_generator,
        )
        axes = {axis.name for axis in station.profile.axes}
        if not {"A", "X", "Z"} <= axes:
            self.button.hide()  # never shown before it is placed: a window of its own

    def open_generator(self) -> StringArtGeneratorDialog:
        """The string-art generator, on the board of the loaded string-art job if there is one."""
        if self.dialog is not None:
            self.dialog.raise_()
            self.dialog.activateWindow()
            return self.dialog
        program = self._runner.program
        board = program.job.params if isinstance(program, StringArtProgram) else None
        reach = next((a.travel for a in self._station.profile.axes if a.name == "X"), None)
        from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog

        dialog = StringArtGeneratorDialog(
            self._open_path, self._parent, board=board, reach_mm=reach
        )
        dialog.finished.connect(self._closed)
        self.dialog = dialog
        dialog.show()
        return dialog

    def _closed(self, *_args: object) -> None:
        dialog, self.dialog = self.dialog, None
        if dialog is not None:
            dialog.deleteLater()
