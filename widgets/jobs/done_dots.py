"""The done dots of a plain point list, painted once each into a picture of the view.

A scatter item works out every new dot's style in Python and draws every dot
again on every frame; a 10 000-line job's done dots (grown five times a second
as the machine reports) cost the window's thread about a tenth of a millisecond
per line in all.  Here a dot is painted once, the first frame after it is done,
into an image the size of the view (in the device's pixels, with the symbol
pyqtgraph renders for a scatter of the same style, centred where the scatter
centres it); every frame blits that image, and only the new dots' area is
marked for repainting.  A zoom, a pan or a resize (another item-to-device
transform) paints every done dot again into a fresh image, as going back does
(a new run, another program): what is drawn is always exactly the first
``count`` dots, in order.
"""

from __future__ import annotations

import math
from typing import Any, Protocol

import numpy as np
import pyqtgraph as pg
from pyqtgraph.graphicsItems.ScatterPlotItem import renderSymbol
from pyqtgraph.Qt import internals
from PySide6.QtCore import QRectF, Qt
from PySide6.QtGui import QImage, QPainter, QPixmap, QTransform
from PySide6.QtWidgets import QStyleOptionGraphicsItem, QWidget

_EMPTY = np.empty(0)


class DotPoints(Protocol):
    """The dots of a program in done order (the preview's markers)."""

    x: np.ndarray
    y: np.ndarray


def _transform_key(transform: QTransform) -> tuple[float, ...]:
    return (
        transform.m11(),
        transform.m12(),
        transform.m21(),
        transform.m22(),
        transform.dx(),
        transform.dy(),
    )


class DoneDots(pg.GraphicsObject):  # type: ignore[misc]
    """The first ``count`` dots of a program, each painted once into a cached picture."""

    def __init__(self, *, size: float, symbol: str, pen: object, brush: object) -> None:
        super().__init__()
        self.size = size
        self.pen = pg.mkPen(pen)
        self.brush = pg.mkBrush(brush)
        self.symbol = symbol
        self._x = self._y = _EMPTY
        self._markers: DotPoints | None = None
        self._count = 0  # dots done
        self._painted = 0  # dots in the picture
        self._image: QImage | None = None
        self._image_key: tuple[float, ...] = ()
        self._symbol: QPixmap | None = None
        self._symbol_dpr = 0.0
        self._fragments = internals.PrimitiveArray(QPainter.PixmapFragment, 10)
        #: (x0, x1, y0, y1) of the done dots in the plot's units, None before the first.
        self._extent: tuple[float, float, float, float] | None = None
        self._rect: QRectF | None = None
        self._pixel: tuple[float, float] | None = None  # a pixel's size in the plot's units

    # --- what is done --------------------------------------------------------------------

    @property
    def shown(self) -> int:
        """How many dots are done (drawn by the next frame at the latest)."""
        return self._count

    def done_xy(self) -> tuple[np.ndarray, np.ndarray]:
        """The done dots' coordinates, in order."""
        return self._x[: self._count], self._y[: self._count]

    def getData(self) -> tuple[np.ndarray, np.ndarray]:
        """As a pyqtgraph item answers: the done dots."""
        return self.done_xy()

    def reset(self) -> None:
        self.show(None, 0)

    def show(self, markers: DotPoints | None, count: int) -> None:
        """Draw the first ``count`` dots of ``markers`` as done."""
        if markers is not self._markers or count < self._count:
            self._markers = markers
            self._x = _EMPTY if markers is None else markers.x
            self._y = _EMPTY if markers is None else markers.y
            self._count = self._painted = 0
            self._image = None  # painted again from the first dot
            self.prepareGeometryChange()
            self._extent = None
            self._rect = None
            self.update()
        count = min(count, len(self._x))
        if count <= self._count:
            return
        new = self._grow(self._x[self._count : count], self._y[self._count : count])
        self._count = count
        if new is not None:
            self.update(new)  # only where the new dots are

    def _grow(self, x: np.ndarray, y: np.ndarray) -> QRectF | None:
        """Take new dots into the extent; their own area (padded), None when none is finite."""
        finite = np.isfinite(x) & np.isfinite(y)
        if not finite.any():
            return None
        x, y = x[finite], y[finite]
        part = (float(x.min()), float(x.max()), float(y.min()), float(y.max()))
        old = self._extent
        grown = (
            part
            if old is None
            else (
                min(old[0], part[0]),
                max(old[1], part[1]),
                min(old[2], part[2]),
                max(old[3], part[3]),
            )
        )
        if grown != old:
            self.prepareGeometryChange()
            self._extent = grown
            self._rect = None
        return self._padded(part)

    def _padded(self, extent: tuple[float, float, float, float]) -> QRectF:
        """``extent`` grown by half a dot and its pen (pixels) and a pixel to spare."""
        reach = self.size / 2 + max(self.pen.widthF(), 1.0) + 1.0
        pixel = self._pixel
        if pixel is None:  # pyqtgraph works it out from the view's transform, in Python
            pixel = (abs(self.pixelWidth() or 0.0), abs(self.pixelHeight() or 0.0))
            if pixel[0] > 0 and pixel[1] > 0:  # kept only once there is a view to measure
                self._pixel = pixel
        dx, dy = reach * pixel[0], reach * pixel[1]
        x0, x1, y0, y1 = extent
        return QRectF(x0 - dx, y0 - dy, x1 - x0 + 2 * dx, y1 - y0 + 2 * dy)

    # --- pyqtgraph and Qt ------------------------------------------------------------------

    def dataBounds(self, ax: int, frac: float = 1.0, orthoRange: object = None) -> object:
        extent = self._extent
        if extent is None:
            return None
        return (extent[0], extent[1]) if ax == 0 else (extent[2], extent[3])

    def boundingRect(self) -> QRectF:
        rect = self._rect
        if rect is None:
            extent = self._extent
            rect = self._rect = QRectF() if extent is None else self._padded(extent)
        return rect

    def viewTransformChanged(self) -> None:
        """The pixel padding (in the plot's units) changed with the view."""
        self.prepareGeometryChange()
        self._rect = self._pixel = None
        super().viewTransformChanged()

    def paint(
        self, painter: QPainter, _option: QStyleOptionGraphicsItem, widget: QWidget | None = None
    ) -> None:
        if not self._count:
            return
        transform = painter.transform()
        if widget is None:
            # Not the view (an export): every done dot straight onto the painter.
            painter.resetTransform()
            self._stamp(painter, transform, 0, self._count, self._symbol_for(1.0))
            return
        dpr = widget.devicePixelRatioF()
        key = (*_transform_key(transform), widget.width(), widget.height(), dpr)
        image = self._image
        if image is None or key != self._image_key:
            image = QImage(
                max(1, math.ceil(widget.width() * dpr)),
                max(1, math.ceil(widget.height() * dpr)),
                QImage.Format.Format_ARGB32_Premultiplied,
            )
            image.setDevicePixelRatio(dpr)
            image.fill(Qt.GlobalColor.transparent)
            self._image, self._image_key, self._painted = image, key, 0
        if self._painted < self._count:
            onto = QPainter(image)
            try:
                self._stamp(onto, transform, self._painted, self._count, self._symbol_for(dpr))
            finally:
                onto.end()
            self._painted = self._count
        target = transform.mapRect(self.boundingRect()).intersected(
            QRectF(0.0, 0.0, widget.width(), widget.height())
        )
        if target.isEmpty():
            return
        source = QRectF(
            target.x() * dpr, target.y() * dpr, target.width() * dpr, target.height() * dpr
        )
        painter.resetTransform()
        painter.drawImage(target, image, source)

    def _symbol_for(self, dpr: float) -> QPixmap:
        if self._symbol is None or self._symbol_dpr != dpr:
            image = renderSymbol(self.symbol, self.size, self.pen, self.brush, dpr=dpr)
            self._symbol, self._symbol_dpr = QPixmap.fromImage(image), dpr
        return self._symbol

    def _stamp(
        self, painter: QPainter, transform: QTransform, start: int, end: int, symbol: QPixmap
    ) -> None:
        """Dots ``start``..``end`` drawn with ``symbol`` centred where ``transform`` puts them
        (on a painter without a transform of its own), as a scatter draws its dots."""
        x, y = self._x[start:end], self._y[start:end]
        finite = np.isfinite(x) & np.isfinite(y)
        x, y = x[finite], y[finite]
        if not len(x):
            return
        points = pg.functions.transformCoordinates(transform, np.vstack([x, y]))
        points = pg.functions.clip_array(points, -(2**30), 2**30)
        dpr = symbol.devicePixelRatioF()
        self._fragments.resize(points.shape[1])
        fragments = self._fragments.ndarray()
        fragments[:, 0:2] = points.T
        fragments[:, 2:6] = (0.0, 0.0, symbol.width(), symbol.height())
        fragments[:, 6:10] = (1 / dpr, 1 / dpr, 0.0, 1.0)
        arguments: list[Any] = [*self._fragments.drawargs(), symbol]
        painter.drawPixmapFragments(*arguments)
