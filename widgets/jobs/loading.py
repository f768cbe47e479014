"""One job file read on a worker thread, so a slow or hostile file never freezes the window."""

from __future__ import annotations

import gc
import threading
from collections.abc import Callable
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from app.jobs.loaders import JobOptions, load_job
from app.jobs.program import JobFileError, Program
from app.jobs.run.runner import LoadCheck
from widgets.jobs.preview import ProgramGeometry
from widgets.jobs.source_lines import read_lines


class JobLoading(QObject):
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
                read_lines(program.source),
                self._check(program),
            )
        except JobFileError as exc:
            result = exc
        except Exception as exc:  # a loader bug must not take the window down
            result = f"{type(exc).__name__}: {exc}"
        return result
