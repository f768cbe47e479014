"""A huge job's path painted into an image on a worker thread, for the preview to show.

A million-line G-code file is a million-vertex path.  Handed to a plot curve,
pyqtgraph strokes all of it on the GUI thread at the first paint and at every
repaint after a zoom or a pan: 1.6 to 1.8 s with the window frozen.  Past
:data:`PICTURE_MIN_POINTS` the preview instead shows a :class:`PathPictureItem`:
the path painted into a ``QImage`` (a QPainter on a QImage is safe off the GUI
thread) at the view's scale, a few thousand points per QPainter call so the GUI
thread never waits long for the interpreter lock.  The item asks for a new image
whenever the view shows more than the image holds or at another scale, and shows
the one it has, stretched, until the new one comes: a zoom is blurred for a moment,
never frozen.  What changes while a job runs (the done part, the markers, the
highlights) stays in the preview's own items, drawn over the image.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QObject, QRectF, Qt, QTimer, Signal
from PySide6.QtGui import QImage, QPainter, QPen
from PySide6.QtWidgets import QStyleOptionGraphicsItem, QWidget

#: Paths with more vertices than this are painted on a worker thread, not by plot curves.
PICTURE_MIN_POINTS = 200_000
#: Vertices per QPainter call at most: each call holds the interpreter lock throughout
#: (PySide6's ``drawPath`` does not let it go: a 50 ms call stalled another thread 100 ms).
POINTS_PER_CALL = 4096
#: Pixels of line per QPainter call at most (about 30 ns each: 1.5 ms a call).  A call
#: the system preempts holds the lock the while, so the shorter the calls, the shorter
#: the GUI thread's waits on a loaded machine (150 000 before: holds up to 100 ms at load 3).
PIXELS_PER_CALL = 50_000
#: The largest image side painted (device pixels).
MAX_SIDE_PX = 4096
#: How far the view's scale may stray from the image's before a new one is painted.
SCALE_TOLERANCE = 0.05
#: The image covers this fraction of the view more on each side, so a small pan needs none.
MARGIN = 0.25


@dataclass(frozen=True)
class PathLayer:
    """One kind of path (travel or work): its vertices, NaN between runs, and its pen."""

    x: np.ndarray
    y: np.ndarray
    pen: QPen


@dataclass(frozen=True)
class PathPicture:
    """The layers painted over ``rect`` (plot units) at ``scale`` device pixels a unit."""

    image: QImage
    rect: QRectF
    scale: tuple[float, float]


def paint_layers(
    layers: Sequence[PathLayer], rect: QRectF, scale: tuple[float, float]
) -> PathPicture | None:
    """``layers`` painted over ``rect`` at ``scale`` (x, y device pixels a unit).

    The image's row 0 is ``rect``'s lowest y, as the plot's own transform maps it
    when the image is drawn into ``rect``; None when the rect or the scale is empty.
    """
    sx, sy = scale
    if not (sx > 0 and sy > 0 and rect.width() > 0 and rect.height() > 0):
        return None
    width = min(MAX_SIDE_PX, max(1, math.ceil(rect.width() * sx)))
    height = min(MAX_SIDE_PX, max(1, math.ceil(rect.height() * sy)))
    # A capped side is painted coarser: the image still covers the whole rect.
    sx, sy = width / rect.width(), height / rect.height()
    image = QImage(width, height, QImage.Format.Format_ARGB32_Premultiplied)
    image.fill(Qt.GlobalColor.transparent)
    left, top = rect.left(), rect.top()
    painter = QPainter(image)
    try:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, False)
        for layer in layers:
            painter.setPen(layer.pen)
            x, y = (layer.x - left) * sx, (layer.y - top) * sy
            for start, end in _pieces(x, y):
                # One vertex of overlap: the run goes on across the pieces without a gap.
                painter.drawPath(
                    pg.arrayToQPath(x[start : end + 1], y[start : end + 1], connect="finite")
                )
                time.sleep(0)  # the interpreter lock to the window now, if it waits for it
    finally:
        painter.end()
    return PathPicture(image, QRectF(rect), (sx, sy))


def _pieces(x: np.ndarray, y: np.ndarray) -> list[tuple[int, int]]:
    """(start, end) vertex pieces of a path in pixels, each cheap enough for one call.

    Stroking costs by the pixels a line covers (a million long lines took 3 s
    however they were cut): a piece ends after :data:`POINTS_PER_CALL` vertices
    or :data:`PIXELS_PER_CALL` pixels of line, whichever comes first.
    """
    count = len(x)
    if count < 2:
        return []
    length = np.hypot(np.diff(x), np.diff(y))
    np.nan_to_num(length, copy=False, nan=0.0, posinf=0.0)
    # Every pixel a line crosses and one for its start: a dot of a line costs too.
    reach = np.cumsum(np.minimum(length, 4.0 * MAX_SIDE_PX) + 1.0)
    cuts = np.searchsorted(reach, np.arange(PIXELS_PER_CALL, reach[-1], PIXELS_PER_CALL))
    ends = np.union1d(cuts, np.arange(POINTS_PER_CALL, count - 1, POINTS_PER_CALL))
    ends = np.append(ends[(ends > 0) & (ends < count - 1)], count - 1)
    starts = np.concatenate(([0], ends[:-1]))
    return [(int(a), int(b)) for a, b in zip(starts, ends, strict=True) if b > a]


class _Painted(QObject):
    """Carries a finished picture from the worker thread to the GUI thread."""

    done = Signal(object, int)


class PathPictureItem(pg.GraphicsObject):  # type: ignore[misc]
    """Shows :class:`PathLayer` s as an image painted on a worker thread (see the module).

    ``pictures`` counts the images received, for whoever waits on one (tests).
    """

    def __init__(self) -> None:
        super().__init__()
        self.layers: tuple[PathLayer, ...] = ()
        self.picture: PathPicture | None = None
        self.pictures = 0
        self._bounds = QRectF()
        self._generation = 0
        self._wanted: tuple[int, QRectF, tuple[float, float]] | None = None
        self._asked: tuple[int, QRectF, tuple[float, float]] | None = None
        self._worker: threading.Thread | None = None
        self._painted = _Painted()
        self._painted.done.connect(self._received)

    def set_layers(
        self, layers: Sequence[PathLayer], bounds: tuple[float, float, float, float] | None
    ) -> None:
        """Show ``layers`` (none: nothing) whose finite extent is ``bounds`` (x0, x1, y0, y1)."""
        self.prepareGeometryChange()
        self.layers = tuple(layers)
        self.picture = None
        self._generation += 1
        self._wanted = self._asked = None
        if self.layers and bounds is not None and not math.isnan(bounds[0] + bounds[2]):
            x0, x1, y0, y1 = bounds
            self._bounds = QRectF(x0, y0, max(x1 - x0, 1e-9), max(y1 - y0, 1e-9))
        else:
            self._bounds = QRectF()
        self.update()

    def boundingRect(self) -> QRectF:
        return QRectF(self._bounds)

    def paint(
        self,
        painter: QPainter,
        _option: QStyleOptionGraphicsItem | None = None,
        _widget: QWidget | None = None,
    ) -> None:
        if not self.layers:
            return
        transform = painter.transform()
        ratio = painter.device().devicePixelRatioF()
        scale = (
            math.hypot(transform.m11(), transform.m12()) * ratio,
            math.hypot(transform.m21(), transform.m22()) * ratio,
        )
        picture = self.picture
        if picture is not None:
            painter.setRenderHint(QPainter.RenderHint.SmoothPixmapTransform, True)
            painter.drawImage(picture.rect, picture.image)
        view = self.viewRect()
        if view is None:
            return
        if not view.intersects(self._bounds):
            return  # panned away from the path: nothing to paint
        shown = view.intersected(self._bounds)
        if picture is not None and self._fits(picture, shown, scale):
            return
        self._ask(view, scale)

    @staticmethod
    def _fits(picture: PathPicture, shown: QRectF, scale: tuple[float, float]) -> bool:
        """The picture holds what is shown, at about the scale it is shown at."""
        if not picture.rect.contains(shown):
            return False
        return all(
            abs(now / then - 1.0) <= SCALE_TOLERANCE
            for now, then in zip(scale, picture.scale, strict=True)
        )

    def _ask(self, view: QRectF, scale: tuple[float, float]) -> None:
        """Ask for the view, with a margin round it, within the path's extent; once."""
        margin_x, margin_y = view.width() * MARGIN, view.height() * MARGIN
        rect = view.adjusted(-margin_x, -margin_y, margin_x, margin_y).intersected(self._bounds)
        if rect.width() <= 0 or rect.height() <= 0:
            # A straight line along one axis: the extent has no width; give it a pixel.
            rect = QRectF(self._bounds)
            rect.adjust(-1.0 / scale[0], -1.0 / scale[1], 1.0 / scale[0], 1.0 / scale[1])
        wanted = (self._generation, rect, scale)
        if self._asked is not None and self._asked[0] == self._generation and self._same(wanted):
            return
        self._wanted = wanted
        # Not from inside a paint: the thread starts from the event loop.
        QTimer.singleShot(0, self._start)

    def _same(self, wanted: tuple[int, QRectF, tuple[float, float]]) -> bool:
        asked = self._asked
        assert asked is not None
        return asked[1] == wanted[1] and all(
            abs(a / b - 1.0) <= SCALE_TOLERANCE for a, b in zip(asked[2], wanted[2], strict=True)
        )

    def _start(self) -> None:
        if self._wanted is None or (self._worker is not None and self._worker.is_alive()):
            return  # one at a time: the one wanted last starts when this one is done
        generation, rect, scale = wanted = self._wanted
        self._wanted = None
        self._asked = wanted
        layers = tuple(PathLayer(layer.x, layer.y, QPen(layer.pen)) for layer in self.layers)
        painted = self._painted

        def paint() -> None:
            picture = paint_layers(layers, rect, scale)
            try:
                painted.done.emit(picture, generation)
            except RuntimeError:
                pass  # the preview was closed meanwhile: nobody waits for it

        self._worker = threading.Thread(target=paint, name="path-picture", daemon=True)
        self._worker.start()

    def _received(self, picture: object, generation: int) -> None:
        worker, self._worker = self._worker, None
        if worker is not None:
            worker.join()
        if generation == self._generation and isinstance(picture, PathPicture):
            self.picture = picture
            self.pictures += 1
            self.update()
        if self._wanted is not None:
            self._start()
