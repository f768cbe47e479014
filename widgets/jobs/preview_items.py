"""The preview's plot items: the job's path, its done part, the machine and the highlights.

Made here, apart from :class:`widgets.jobs.preview.JobPreview`, which decides what
they show: which items exist and how each is drawn (colours, pens, caching, the
order they stack in) is one concern, the program, progress and clicks another.
"""

from __future__ import annotations

from typing import Protocol

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import Qt
from PySide6.QtGui import QPen
from PySide6.QtWidgets import QGraphicsItem

from widgets.jobs.done_dots import DoneDots
from widgets.jobs.path_picture import PICTURE_MIN_POINTS, PathLayer, PathPictureItem

_EMPTY = np.empty(0)


class PathPoints(Protocol):
    """One kind of path as plot-ready arrays, NaN between its runs."""

    x: np.ndarray
    y: np.ndarray


TRAVEL_COLOUR = "#9a9a9a"
WORK_COLOUR = "#1f4fb4"
DONE_COLOUR = "#2ca02c"
POSITION_COLOUR = "#d62728"
QUESTION_COLOUR = "#ff7f0e"
LIMIT_COLOUR = "#e08a00"


def travel_pen() -> QPen:
    """Travel is thin and dashed: nothing is made there.  Width-1 pens everywhere: wider
    ones make Qt stroke segment by segment, far slower on big paths."""
    pen: QPen = pg.mkPen(TRAVEL_COLOUR, width=1, style=Qt.PenStyle.DashLine)
    return pen


def work_pen() -> QPen:
    pen: QPen = pg.mkPen(WORK_COLOUR, width=1)
    return pen


class PreviewItems:
    """Every item of the preview's plot, added to ``plot`` in the order they stack."""

    def __init__(self, plot: pg.PlotItem, outline_x: np.ndarray, outline_y: np.ndarray) -> None:
        self.plot = plot
        #: The soft limits (a rectangle) or the reach (a circle).
        self.limits_curve = plot.plot(
            outline_x,
            outline_y,
            pen=pg.mkPen(LIMIT_COLOUR, width=1, style=Qt.PenStyle.DashDotLine),
        )
        self.travel_curve = self._curve(travel_pen())
        self.work_curve = self._curve(work_pen())
        #: A huge path (travel and work) painted on a worker thread instead of the curves.
        self.path_picture = PathPictureItem()
        self.path_picture.setZValue(self.travel_curve.zValue())
        plot.addItem(self.path_picture)
        # Plain curves, not PlotDataItems: given new data with every step of a job, and a
        # PlotDataItem works out its data sets and bounds in Python before its curve's.
        self.done_travel_curve = self._done_curve(
            pg.mkPen(DONE_COLOUR, width=1, style=Qt.PenStyle.DashLine)
        )
        self.done_work_curve = self._done_curve(pg.mkPen(DONE_COLOUR, width=1))
        self.work_markers = self._markers(WORK_COLOUR, 6)
        #: Done dots painted once each into a picture (a scatter restyled and redrew them all).
        self.done_markers = DoneDots(
            size=6, symbol="o", pen=pg.mkPen(DONE_COLOUR), brush=pg.mkBrush(DONE_COLOUR)
        )
        plot.addItem(self.done_markers)
        for item in (self.limits_curve, self.travel_curve, self.work_curve, self.work_markers):
            # Unchanged while a job runs, yet repainted with every frame of its done part and
            # position (10 000 dots drawn again and again): painted once into a pixmap
            # instead, redrawn only when their data or the view changes.
            item.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
        self.position_marker = self._marker(
            size=16, symbol="+", pen=pg.mkPen(POSITION_COLOUR, width=2), z=10
        )
        self.position_marker.setBrush(pg.mkBrush(POSITION_COLOUR))
        #: A ring around the operation the operator is asked about (a hole perhaps drilled).
        self.question_marker = self._marker(
            size=22, symbol="o", pen=pg.mkPen(QUESTION_COLOUR, width=3), z=11
        )
        #: The hole the drill page's step-through stands at (FIDELITY S2-41).
        self.step_marker = self._marker(
            size=18, symbol="s", pen=pg.mkPen(QUESTION_COLOUR, width=2), z=11
        )
        #: The segments of lines sent but not proven run, for the operator's resume pick.
        self.candidate_curve = self._curve(pg.mkPen(QUESTION_COLOUR, width=3))
        self.candidate_curve.setZValue(9)
        for empty in (self.question_marker, self.step_marker, self.candidate_curve):
            empty.setVisible(False)  # until there is something to highlight

    def show_path(
        self,
        travel: PathPoints,
        work: PathPoints,
        bounds: tuple[float, float, float, float] | None,
    ) -> None:
        """The job's travel and work: as curves, or past :data:`PICTURE_MIN_POINTS` vertices as
        an image painted on a worker thread (stroked by the curves on the GUI thread, a
        million vertices held the window 1.6 to 1.8 s at the first paint and after every zoom)."""
        if len(travel.x) + len(work.x) > PICTURE_MIN_POINTS:
            for curve in (self.travel_curve, self.work_curve):
                curve.setData(_EMPTY, _EMPTY)
            self.path_picture.set_layers(
                (
                    PathLayer(travel.x, travel.y, travel_pen()),
                    PathLayer(work.x, work.y, work_pen()),
                ),
                bounds,
            )
            return
        self.path_picture.set_layers((), None)
        self.travel_curve.setData(travel.x, travel.y, connect="finite")
        self.work_curve.setData(work.x, work.y, connect="finite")

    def _curve(self, pen: object) -> pg.PlotDataItem:
        return self.plot.plot(pen=pen, connect="finite")

    def _done_curve(self, pen: object) -> pg.PlotCurveItem:
        curve = pg.PlotCurveItem(pen=pen, connect="finite")
        self.plot.addItem(curve)
        return curve

    def _markers(self, colour: str, size: int) -> pg.ScatterPlotItem:
        markers = pg.ScatterPlotItem(
            size=size, symbol="o", pen=pg.mkPen(colour), brush=pg.mkBrush(colour)
        )
        self.plot.addItem(markers)
        return markers

    def _marker(self, *, size: int, symbol: str, pen: object, z: float) -> pg.ScatterPlotItem:
        marker = pg.ScatterPlotItem(size=size, symbol=symbol, pen=pen, brush=None)
        marker.setZValue(z)
        self.plot.addItem(marker)
        return marker
