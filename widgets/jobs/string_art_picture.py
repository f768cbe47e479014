"""A merged string-art thread painted once into an image, on the loading thread.

A generator's 2-million-entry job is drawn merged (:mod:`widgets.jobs.string_art_thread`):
some twelve thousand chords, each alpha-blended.  Drawn as line items they took
tens of milliseconds of every repaint of the preview on the GUI thread, the
first one right when the job came in.  The dock's loading thread now paints
them into a ``QImage`` (a QPainter on a QImage is safe off the GUI thread) at
the scale the view will show the board, with the bands' own pens (one pixel,
the band's opacity, not antialiased: what the line items draw), so each chord
is as dark as its windings, as before; the preview shows the image.  When the
view is zoomed or resized away from that scale, where the image's lines would
thicken or fade, the preview draws the chords as line items again.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import pyqtgraph as pg
from pyqtgraph.graphicsItems.PlotCurveItem import arrayToLineSegments
from PySide6.QtCore import QRectF, Qt, QTimer
from PySide6.QtGui import QColor, QImage, QPainter, QPen
from PySide6.QtWidgets import QStyleOptionGraphicsItem, QWidget

from widgets.jobs.string_art_thread import ThreadGeometry, band_alpha

#: The largest image side painted (pixels): a 4K screen's height and some.
MAX_SIDE_PX = 4096
#: Chords drawn per QPainter call (each call holds the interpreter lock throughout).
CHORDS_PER_CALL = 400
#: How far the view's scale may stray from the image's before the chords are drawn as lines.
SCALE_TOLERANCE = 0.2


@dataclass(frozen=True)
class ThreadPicture:
    """The chords of a merged thread as an image of the square ``rect`` (mm) of the board."""

    image: QImage
    rect: QRectF
    #: Image pixels per millimetre (device pixels: the screen's pixel ratio included).
    pixels_per_mm: float


def band_pen(colour: str, alpha: int) -> QPen:
    """The pen of a band of ``alpha`` (of 255): the preview's line items use the same."""
    pen: QPen = pg.mkPen(pg.mkColor(colour), width=1)
    color = QColor(pen.color())
    color.setAlpha(alpha)
    pen.setColor(color)
    return pen


def paint_thread(
    thread: ThreadGeometry, pixels_per_mm: float, colour: str, alpha: int
) -> ThreadPicture | None:
    """``thread``'s chords painted at ``pixels_per_mm``; None when exact or without a scale."""
    if not thread.merged or not thread.whole or not pixels_per_mm > 0 or not len(thread.nail_xy):
        return None
    half = float(abs(thread.nail_xy).max()) + 1.0  # every nail inside, a millimetre to spare
    side = min(MAX_SIDE_PX, max(2, math.ceil(2 * half * pixels_per_mm)))
    scale = side / (2 * half)
    image = QImage(side, side, QImage.Format.Format_ARGB32_Premultiplied)
    image.fill(Qt.GlobalColor.transparent)
    painter = QPainter(image)
    try:
        painter.setRenderHint(QPainter.RenderHint.Antialiasing, False)
        for k, (x, y) in enumerate(thread.whole):
            painter.setPen(band_pen(colour, band_alpha(alpha, k)))
            # A few hundred chords a call: drawLines holds the interpreter lock while it
            # draws (all twelve thousand at once kept the GUI thread waiting a quarter second).
            for start in range(0, len(x), 2 * CHORDS_PER_CALL):
                piece = slice(start, start + 2 * CHORDS_PER_CALL)
                segments = arrayToLineSegments(
                    (x[piece] + half) * scale,
                    (y[piece] + half) * scale,
                    connect="pairs",
                    finiteCheck=False,
                )
                painter.drawLines(*segments.drawargs())
    finally:
        painter.end()
    return ThreadPicture(image, QRectF(-half, -half, 2 * half, 2 * half), scale)


class ThreadPictureItem(pg.GraphicsObject):  # type: ignore[misc]
    """Shows a :class:`ThreadPicture` in the plot; says once when the view's scale strays.

    ``strayed`` is called (from the event loop, not from inside a paint) when
    the view shows the image more than :data:`SCALE_TOLERANCE` larger or
    smaller than it was painted.
    """

    def __init__(self, strayed: Callable[[], None]) -> None:
        super().__init__()
        self.picture: ThreadPicture | None = None
        self._strayed = strayed
        self._told = False

    def set_picture(self, picture: ThreadPicture | None) -> None:
        self.prepareGeometryChange()
        self.picture = picture
        self._told = False
        self.update()

    def boundingRect(self) -> QRectF:
        return QRectF(self.picture.rect) if self.picture is not None else QRectF()

    def paint(
        self,
        painter: QPainter,
        _option: QStyleOptionGraphicsItem | None = None,
        _widget: QWidget | None = None,
    ) -> None:
        picture = self.picture
        if picture is None:
            return
        transform = painter.transform()
        shown = math.hypot(transform.m11(), transform.m12()) * painter.device().devicePixelRatioF()
        if abs(shown / picture.pixels_per_mm - 1.0) > SCALE_TOLERANCE and not self._told:
            self._told = True
            QTimer.singleShot(0, self._strayed)
        painter.setRenderHint(QPainter.RenderHint.SmoothPixmapTransform, True)
        painter.drawImage(picture.rect, picture.image)
