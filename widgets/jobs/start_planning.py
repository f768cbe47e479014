"""A start part-way worked out on a worker thread before the runner is asked to start there.

Reading the state a million-line file has reached near its end (units, modes,
feed, the file's own ``G92``) takes a fraction of a second, which the GUI
thread must not spend.  The plan is worked out here; the runner's own call
then finds it remembered (:func:`app.jobs.run.start_point.plan_start`).
"""

from __future__ import annotations

import threading
from collections.abc import Sequence

from PySide6.QtCore import QObject, Signal

from app.jobs.program import Program
from app.jobs.run.start_point import StartRefused, plan_start


class StartPlanning(QObject):
    """One start's plan on a worker thread; ``done(index)`` arrives on the GUI thread."""

    done = Signal(int)

    def __init__(
        self, program: Program, index: int, axes: Sequence[str], parent: QObject | None
    ) -> None:
        super().__init__(parent)
        self.index = index
        self._program = program
        self._axes = tuple(axes)
        self._thread = threading.Thread(target=self._run, name="start-planning", daemon=True)
        self.done.connect(self.deleteLater)

    def start(self) -> None:
        self._thread.start()

    def join(self) -> None:
        self._thread.join()

    def _run(self) -> None:
        try:
            plan_start(self._program, self.index, self._axes)
        except StartRefused:
            pass  # remembered too: the runner's call says why, where the operator looks
        except Exception:  # a bug: the runner's own call meets it again, and reports it
            pass
        self.done.emit(self.index)
