"""The string-art generator's worker threads: reading a photo, generating a sequence.

Each runs one function on a plain thread and hands its outcome to the GUI
thread through a queued Qt signal.  The generation reports progress at most
every ``PROGRESS_MS`` with the thread picture so far, and checks between two
chunks of the generator (a few milliseconds each) whether the operator
cancelled; a cancelled run ends with :class:`Cancelled` and keeps nothing.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np
from PySide6.QtCore import QObject, Signal

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.greedy import Result, Settings, generate
from app.string_art_generator.output import picture
from app.string_art_generator.quality import Quality, measure

#: Pixels across each of the dialog's two pictures.
PREVIEW_PX = 300
#: Pixels across the PNG written with the pair.
EXPORT_PX = 800
#: The least time between two progress reports shown (the worker skips the ones between).
PROGRESS_MS = 50


@dataclass(frozen=True)
class Finished:
    """A finished generation with its pictures, made on the worker."""

    result: Result
    quality: Quality
    preview: np.ndarray  # PREVIEW_PX² grey
    png: np.ndarray  # EXPORT_PX² grey


class Worker(QObject):
    """Runs one function on a thread; ``done`` brings its result to the GUI thread."""

    done = Signal(object)  # the result, or the exception raised

    def __init__(
        self, work: Callable[[threading.Event], object], name: str, parent: QObject
    ) -> None:
        super().__init__(parent)
        self.stop = threading.Event()
        self._work = work
        self._thread = threading.Thread(target=self._run, name=name, daemon=True)

    def start(self) -> None:
        self._thread.start()

    def cancel(self) -> None:
        self.stop.set()

    def join(self) -> None:
        self._thread.join()

    def _run(self) -> None:
        result: object
        try:
            result = self._work(self.stop)
        except Exception as exc:  # shown to the operator; the window stays
            result = exc
        try:
            self.done.emit(result)
        except RuntimeError:  # the dialog was deleted with the window: nobody to tell
            pass


class Cancelled(Exception):
    """The operator pressed Cancel: the work was dropped."""


class Generation(Worker):
    """The generator on a worker thread, reporting progress with the picture so far."""

    progressed = Signal(str, int, int, object)  # phase, done, total, darkness or None

    def __init__(
        self, params: StringArtParams, target: np.ndarray, settings: Settings, parent: QObject
    ) -> None:
        self._params = params
        self._target = target
        self._settings = settings
        super().__init__(self._generate, "string-art-generator", parent)

    def _generate(self, stop: threading.Event) -> Finished:
        last = 0.0
        phase = ""
        for progress in generate(self._params, self._target, self._settings):
            if stop.is_set():
                raise Cancelled()
            now = time.monotonic()
            if progress.result is not None:
                return self._finish(progress.result, stop)
            if progress.phase != phase or now - last >= PROGRESS_MS / 1000:
                phase, last = progress.phase, now
                self.progressed.emit(
                    progress.phase, progress.done, progress.total, progress.darkness
                )
        raise AssertionError("generate always ends with a result")

    @staticmethod
    def _finish(result: Result, stop: threading.Event) -> Finished:
        """The figures and both pictures, still cancellable between them."""
        quality = measure(result.target, result.darkness, result.mask)
        pictures = []
        for size in (PREVIEW_PX, EXPORT_PX):
            if stop.is_set():
                raise Cancelled()
            pictures.append(picture(result, size))
        return Finished(result, quality, pictures[0], pictures[1])
