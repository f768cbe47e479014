"""The telemetry dock: live plots of positions, velocities and one subscriber variable.

A view over :class:`app.telemetry.TelemetryRecorder`, which does the
recording, windowing, pausing, zeroing and CSV writing; the dock only draws
what the recorder says is shown, and only when the recorder's throttled
``updated`` fires, so a 1 kHz stream costs at most ~60 redraws a second.

Long windows stay cheap: a 10-minute window at 1 kHz is 600 000 samples a
curve, but the recorder hands over its min/max envelope (one pair per pixel
of plot width, every peak kept, reduced incrementally), so each frame draws
a few thousand points.  The curves are :class:`Trace` items, not
pyqtgraph's curves: a polyline filled from the envelope's arrays and drawn
in one call, with no downsampling, clipping, NaN scan or bounds work behind
the envelope (the recorder never stores a NaN); with ``PlotCurveItem`` that
bookkeeping cost more than the drawing (8.0 against 6.0 ms of processor
time per frame, same run).

The time axis counts back from the view's end and never moves: time going
by shifts the curve items (``setPos``), which needs neither new data nor a
new axis picture, so the axes are cached as pixmaps.  The shift goes by
whole pixels (the view's end is the first pixel boundary at or after now),
and each curve is drawn from the view's left edge, so between two shifts
(0.6 s in a 10-minute window) only the curves' right ends change: a frame
repaints one narrow rectangle over them (:func:`changed_spans` finds what
changed, :meth:`Trace.paint` draws only the points in it), not the plots.
A whole repaint costs several milliseconds; the sliver, a fraction of one.
A curve whose shown samples did not change is not handed data again.
Each redraw settles the plots' ranges before the paint, or pyqtgraph would
paint every frame twice.  pyqtgraph's OpenGL path
is not used: it needs a GL context, which the offscreen benchmark (and many
remote desktops) lack, so no gain from it could be measured.

Beside the plots, a turning coordinate cross shows the platform's rotation
(relative to the last Zero) while rotation is the plotted variable.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QPointF, QRectF, QSize, Qt
from PySide6.QtGui import (
    QColor,
    QFont,
    QPainter,
    QPaintEvent,
    QPen,
    QPolygonF,
    QShowEvent,
)
from PySide6.QtWidgets import (
    QComboBox,
    QDockWidget,
    QFileDialog,
    QGraphicsItem,
    QGraphicsObject,
    QHBoxLayout,
    QLabel,
    QPushButton,
    QSizePolicy,
    QStyleOptionGraphicsItem,
    QVBoxLayout,
    QWidget,
)

from app.telemetry import (
    ROTATION_KEY,
    VARIABLES,
    WINDOW_CHOICES_S,
    FloatArray,
    TelemetryRecorder,
    Variable,
)
from widgets.number_field import localized
from widgets.retranslate import Texts
from widgets.style import CHECKED_BUTTON_STYLE, monospace_font
from widgets.telemetry_axis import LocaleAxis
from widgets.theme import LIGHT, PlotColours

#: Curve colours per axis (X, Y, Z, then whatever else a profile has).
AXIS_COLOURS = ("#d62728", "#2ca02c", "#1f77b4", "#ff7f0e", "#9467bd", "#8c564b")
VARIABLE_COLOUR = "#9467bd"
#: The least height of the three plots together, in pixels (a 1280 x 800 window must fit).
PLOTS_MIN_HEIGHT = 180
#: The width of the caption (title, unit and key) beside each plot, in pixels.
CAPTION_WIDTH = 118
# Characters of the variable's name the closed list shows at least.
VARIABLE_CHARS = 8
# The height the dock asks for: each plot about 90 px, enough to read a curve's shape.
# Not more: under the pages on an 800 px screen, the page shown must keep its height
# (the window gives a dock what it asks for and the pages the rest).
DEFAULT_PLOTS_HEIGHT = 3 * 90


def _window_label(seconds: float) -> str:
    return f"{seconds:g} s" if seconds < 60 else f"{seconds / 60:g} min"


#: The least height a plot's vertical range shows (in its unit: mm, mm/s, V…).
MIN_Y_RANGE = 0.01


def _variable_name(variable: Variable) -> str:
    """A subscriber variable's name in the operator's language, as the developer pane says it."""
    return QCoreApplication.translate("StageWords", variable.name)


def _variable_caption(variable: Variable) -> str:
    return f"{_variable_name(variable)} ({variable.unit})"


def _common_unit(units: list[str]) -> str:
    """The unit shared by all axes, or "" when they differ (a rotary axis beside linear ones)."""
    return units[0] if units and all(u == units[0] for u in units) else ""


class RotationCross(QWidget):
    """A coordinate cross turned by the platform's angle (counter-clockwise positive).

    A faint fixed cross marks the zero direction, so the turn reads at a
    glance; ``angle`` is None while no rotation is being plotted.
    """

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._angle: float | None = None
        self.colours = LIGHT
        self.setMinimumSize(120, 120)
        self.setSizePolicy(QSizePolicy.Policy.Preferred, QSizePolicy.Policy.Preferred)
        self.setToolTip(
            self.tr("Platform rotation relative to the last Zero (counter-clockwise positive)")
        )

    @property
    def angle(self) -> float | None:
        return self._angle

    def set_angle(self, degrees: float | None) -> None:
        if degrees == self._angle:
            return
        self._angle = degrees
        self.update()

    def sizeHint(self) -> QSize:
        return QSize(150, 150)

    def heightForWidth(self, width: int) -> int:
        return width

    def paintEvent(self, _event: QPaintEvent) -> None:
        painter = QPainter(self)
        painter.setRenderHint(QPainter.RenderHint.Antialiasing)
        side = min(self.width(), self.height())
        radius = side / 2 - 6
        painter.translate(self.width() / 2, self.height() / 2)

        painter.setPen(QPen(QColor(self.colours.rim), 1))
        painter.setBrush(QColor(self.colours.face))
        painter.drawEllipse(QPointF(0, 0), radius, radius)
        reference = QPen(QColor(self.colours.reference), 1, Qt.PenStyle.DashLine)
        painter.setPen(reference)
        painter.drawLine(QPointF(-radius, 0), QPointF(radius, 0))
        painter.drawLine(QPointF(0, -radius), QPointF(0, radius))

        if self._angle is None:
            painter.setPen(QColor(self.colours.axis))
            painter.drawText(
                QRectF(-radius, -radius, 2 * radius, 2 * radius),
                Qt.AlignmentFlag.AlignCenter,
                self.tr("rotation\nnot plotted"),
            )
            painter.end()
            return

        painter.rotate(-self._angle)  # screen y points down: negate for counter-clockwise
        arm = radius * 0.85
        self._draw_arm(painter, arm, 0, QColor(AXIS_COLOURS[0]), "x")
        self._draw_arm(painter, 0, -arm, QColor(AXIS_COLOURS[1]), "y")
        painter.setPen(QPen(QColor(self.colours.axis), 1.5))
        painter.drawLine(QPointF(-arm, 0), QPointF(0, 0))
        painter.drawLine(QPointF(0, arm), QPointF(0, 0))
        painter.setBrush(QColor(self.colours.text))
        painter.drawEllipse(QPointF(0, 0), 3, 3)
        painter.end()

    @staticmethod
    def _draw_arm(painter: QPainter, x: float, y: float, colour: QColor, label: str) -> None:
        painter.setPen(QPen(colour, 2.5))
        painter.setBrush(colour)
        tip = QPointF(x, y)
        painter.drawLine(QPointF(0, 0), tip)
        length = math.hypot(x, y)
        ux, uy = x / length, y / length  # along the arm
        px, py = -uy, ux  # across it
        head = 9.0
        painter.drawPolygon(
            QPolygonF(
                [
                    tip,
                    QPointF(x - head * ux + head / 2 * px, y - head * uy + head / 2 * py),
                    QPointF(x - head * ux - head / 2 * px, y - head * uy - head / 2 * py),
                ]
            )
        )
        font = QFont(painter.font())
        font.setBold(True)
        painter.setFont(font)
        painter.drawText(QPointF(x - 14 * ux + 8 * px - 4, y - 14 * uy + 8 * py + 4), label)


def _padded(low: float, high: float) -> tuple[float, float]:
    """A vertical extent with some height even for a flat line (an empty one is never painted)."""
    if high > low:
        return low, high
    pad = max(abs(low), 1.0) * 1e-9
    return low - pad, high + pad


def changed_spans(
    old_t: FloatArray, old_y: FloatArray, new_t: FloatArray, new_y: FloatArray
) -> list[tuple[float, float]] | None:
    """The stretches of time where a polyline through the new points differs from the old one.

    A scrolling window changes a curve at its ends only: samples (or
    min/max blocks) arrive at the right and leave at the left, while the
    points between are the very same numbers, at other indices.  Lists of
    one length that differ in a few consecutive points only (the usual
    frame: a new tail) give one span, from the first changed point's
    neighbour to the last one's (the segments joining them change too).
    Otherwise the two lists are aligned on the middle point of the new
    one; the run of equal points around it is left alone, and each end
    beyond it is a span from the outermost point of either list to the
    first equal point.  ``[]`` when nothing changed; None when no such run
    is found (repaint the whole curve).
    """
    n, m = len(new_t), len(old_t)
    if n == 0 or m == 0:
        return [] if n == m else None
    if n == m:  # the usual frame: the same blocks, a new tail
        differ = np.flatnonzero((new_t != old_t) | (new_y != old_y))
        if len(differ) == 0:
            return []
        first, last = int(differ[0]), int(differ[-1])
        if last - first < 8 and last - first + 1 == len(differ):  # a few points in a row
            low, high = max(0, first - 1), min(n - 1, last + 1)
            return [(float(min(new_t[low], old_t[low])), float(max(new_t[high], old_t[high])))]
    middle = n // 2
    anchor = new_t[middle]
    at_new = int(np.searchsorted(new_t, anchor, side="left"))
    at_old = int(np.searchsorted(old_t, anchor, side="left"))
    if at_old >= m or old_t[at_old] != anchor:
        return None
    shift = at_old - at_new  # new point i is old point i + shift
    first, stop = max(0, -shift), min(n, m - shift)
    equal = (new_t[first:stop] == old_t[first + shift : stop + shift]) & (
        new_y[first:stop] == old_y[first + shift : stop + shift]
    )
    differ = np.flatnonzero(~equal) + first
    before, after = differ[differ < middle], differ[differ > middle]
    if middle in differ:
        return None
    low = int(before[-1]) + 1 if len(before) else first
    high = int(after[0]) if len(after) else stop  # new[low:high] == old[low + shift:high + shift]
    spans = []
    if low > 0 or low + shift > 0:
        spans.append((float(min(new_t[0], old_t[0])), float(new_t[low])))
    if high < n or high + shift < m:
        spans.append((float(new_t[high - 1]), float(max(new_t[-1], old_t[-1]))))
    return spans


class Trace(QGraphicsObject):
    """One curve: a 1-pixel polyline through points already reduced for the screen.

    What pyqtgraph's ``PlotCurveItem`` does per frame is not needed here and
    cost more than the drawing: a NaN and bounds scan of every new array, a
    painter path rebuilt from it, a pixel-padding bounding rectangle worked
    out through the view's transforms, and a Python ``itemChange`` (and an
    auto-range pass of its view) on every ``setPos`` as the curve slides in
    time.  This item copies the points straight into a ``QPolygonF`` (a
    numpy view of its memory), keeps its bounds from the same arrays, and
    paints one ``drawPolyline`` with a cosmetic pen.  Its view hears of new
    bounds from ``set_points`` alone, and only when the vertical extent
    changed: sliding it in time changes no vertical range, and the
    horizontal one is fixed.  ``dataBounds`` is what the view's auto-range
    asks.

    New points usually differ from the last ones at the ends only (a
    scrolling window): ``set_points`` then repaints nothing itself but hands
    back the stretch that changed, and a paint draws only the points in the
    exposed rectangle, so a frame costs a sliver of the curve.
    """

    def __init__(self, colour: str) -> None:
        super().__init__()
        # Paints get the exposed rectangle: a frame usually repaints a sliver of the curve.
        self.setFlag(QGraphicsItem.GraphicsItemFlag.ItemUsesExtendedStyleOption)
        self._pen = pg.mkPen(colour, width=1)  # cosmetic: one pixel whatever the scale
        self._t: FloatArray = np.empty(0)
        self._y: FloatArray = np.empty(0)
        self._polygon = QPolygonF()
        self._rect = QRectF()
        self._rect_y: tuple[float, float] | None = None  # the rectangle's exact vertical extent
        self._y_range: tuple[float, float] | None = None
        self._t_range: tuple[float, float] | None = None
        # The view box the trace sits in, told when the data's bounds change.
        self.view: pg.ViewBox | None = None

    def set_points(self, t: FloatArray, y: FloatArray) -> QRectF:
        """Draw the points ``(t, y)`` (finite, ``t`` ascending), replacing the last ones.

        Returns the part of the scene the caller must repaint: the hull of
        the stretches where the curve changed (:func:`changed_spans`), at the
        curve's full height; a null rectangle when nothing is left to repaint
        (nothing changed, or the whole item was marked for repainting here).
        The caller joins the curves' rectangles into one repaint: the view
        paints one rectangle several times faster than a few apart.  New
        bounds that no longer hold the points are widened, with room to the
        right for what comes.
        """
        n = len(t)
        spans = changed_spans(self._t, self._y, t, y)
        self._t, self._y = t, y
        polygon = pg.functions.create_qpolygonf(n)
        if n:
            points = pg.functions.ndarray_from_qpolygonf(polygon)
            points[:, 0] = t
            points[:, 1] = y
            t_range: tuple[float, float] | None = (float(t[0]), float(t[-1]))
            y_range: tuple[float, float] | None = (float(y.min()), float(y.max()))
        else:
            t_range = y_range = None
        self._polygon = polygon
        self._t_range = t_range
        bounds_changed = y_range != self._y_range
        self._y_range = y_range
        dirty = QRectF()
        if not self._covers(t_range, y_range):
            self.prepareGeometryChange()
            self._rect = self._room_for(t_range, y_range)
            self._rect_y = _padded(*y_range) if y_range is not None else None
            self.update()
        elif spans is None:
            self.update()
        elif spans and self.scene() is not None:
            start, stop = spans[0][0], spans[-1][1]
            top, height = self._rect.top(), self._rect.height()
            dirty = self.mapRectToScene(QRectF(start, top, max(stop - start, 1e-9), height))
        if bounds_changed and self.view is not None:
            self.view.itemBoundsChanged(self)
        return dirty

    def _covers(
        self, t_range: tuple[float, float] | None, y_range: tuple[float, float] | None
    ) -> bool:
        """Whether the bounding rectangle holds the points and is no taller than they need."""
        if t_range is None or y_range is None:
            return self._rect.isNull()
        rect = self._rect
        if rect.isNull() or t_range[0] < rect.left() or t_range[1] > rect.right():
            return False
        return self._rect_y == _padded(*y_range)

    @staticmethod
    def _room_for(
        t_range: tuple[float, float] | None, y_range: tuple[float, float] | None
    ) -> QRectF:
        """Bounds for the points, reaching a quarter of their span further right."""
        if t_range is None or y_range is None:
            return QRectF()
        start, stop = t_range
        stop += max(stop - start, 1.0) / 4
        low, high = _padded(*y_range)
        return QRectF(start, low, stop - start, high - low)

    def getData(self) -> tuple[FloatArray, FloatArray]:
        return self._t, self._y

    def dataBounds(
        self, ax: int, frac: float = 1.0, orthoRange: object = None
    ) -> tuple[float, float] | None:
        """The data's extent along ``ax`` (0 time, 1 value): every point, whatever ``frac``."""
        return self._t_range if ax == 0 else self._y_range

    def pixelPadding(self) -> float:
        return 0.0

    def boundingRect(self) -> QRectF:
        return self._rect

    def paint(
        self,
        painter: QPainter,
        option: QStyleOptionGraphicsItem,
        _widget: QWidget | None = None,
    ) -> None:
        """The points in the exposed stretch, and one beyond each end (segments crossing in)."""
        if self._polygon.isEmpty():
            return
        painter.setPen(self._pen)
        exposed = option.exposedRect
        # The pen and the view's rounding reach past the exposed rectangle: 2 pixels.
        margin = 2 * abs(painter.deviceTransform().inverted()[0].m11())
        n = len(self._t)
        first = max(0, int(np.searchsorted(self._t, exposed.left() - margin, side="left")) - 1)
        last = min(n, int(np.searchsorted(self._t, exposed.right() + margin, side="right")) + 1)
        if first == 0 and last == n:
            painter.drawPolyline(self._polygon)
        elif last > first:
            painter.drawPolyline(self._polygon.mid(first, last - first))


class _PlotArea(pg.GraphicsLayoutWidget):  # type: ignore[misc]
    """The plots, asking for room for three readable curves (the minimum keeps them legible)."""

    def sizeHint(self) -> QSize:
        return QSize(800, DEFAULT_PLOTS_HEIGHT)


class TelemetryDock(QDockWidget):
    """Plots, variable selector, rotation cross with Zero, Pause, window, Autoscale, exports."""

    def __init__(self, recorder: TelemetryRecorder, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.texts = Texts(self)
        self.texts.set(self.setWindowTitle, lambda: self.tr("Telemetry"))
        self.setObjectName("telemetry_dock")
        self.recorder = recorder
        self._drawn: dict[str, tuple[tuple[int, int, int], int]] = {}
        self._shown_window = 0.0  # the window the time axis spans
        self._shown_end = math.nan  # the view end the curves are shifted to
        self._curves: dict[str, Trace] = {}

        content = QWidget()
        layout = QVBoxLayout(content)
        layout.setContentsMargins(6, 4, 6, 6)
        layout.setSpacing(4)
        layout.addLayout(self._build_toolbar())
        self.body = QWidget()
        body_layout = QHBoxLayout(self.body)
        body_layout.setContentsMargins(0, 0, 0, 0)
        body_layout.setSpacing(6)
        body_layout.addWidget(self._build_plots(), 1)
        # The dial only where a machine can report its rotation (an IMU's subscriber
        # variable): elsewhere it sat there saying "rotation not plotted" for nothing.
        self.rotation_panel = QWidget()
        self.rotation_panel.setObjectName("rotation_panel")
        self.rotation_panel.setLayout(self._build_rotation_column())
        if not recorder.has_variables:
            self.rotation_panel.hide()  # only hidden: shown unplaced, it flashed up as a window
        body_layout.addWidget(self.rotation_panel)
        layout.addWidget(self.body, 1)
        self.setWidget(content)

        recorder.updated.connect(self.redraw)
        recorder.variableChanged.connect(self._show_variable)
        self._show_variable()
        self._show_window()
        self.set_autoscale(True)
        self.redraw()
        self.texts.also(self._retranslate)

    def _retranslate(self) -> None:
        """Texts made from state, and the plots' titles, in the new language."""
        self.cross.setToolTip(
            QCoreApplication.translate(
                "RotationCross",
                "Platform rotation relative to the last Zero (counter-clockwise positive)",
            )
        )
        self.set_paused(self.pause_button.isChecked())
        self._title_plots()
        self._show_variable()

    # --- building ------------------------------------------------------------

    def _build_toolbar(self) -> QHBoxLayout:
        bar = QHBoxLayout()
        bar.setSpacing(6)
        t = self.texts
        bar.addWidget(t.label(lambda: self.tr("Variable")))
        self.variable_combo = QComboBox()
        self.variable_combo.setObjectName("telemetry_variable")
        t.set(
            self.variable_combo.setToolTip,
            lambda: self.tr(
                "Subscriber variable to plot; the station asks for it in every frame"
                " the info panel does not need"
            ),
        )
        self.variable_combo.addItem("", None)
        t.item(self.variable_combo, 0, lambda: self.tr("none"))
        for index, variable in enumerate(VARIABLES, start=1):
            self.variable_combo.addItem("", variable.subscriber)
            t.item(self.variable_combo, index, lambda v=variable: _variable_caption(v))
        self.variable_combo.currentIndexChanged.connect(self._variable_chosen)
        # Narrower than its longest entry when the dock is (under the pages, beside the jobs
        # dock on a 1280 px screen); wider, up to that, where there is room.
        self.variable_combo.setSizeAdjustPolicy(
            QComboBox.SizeAdjustPolicy.AdjustToMinimumContentsLengthWithIcon
        )
        self.variable_combo.setMinimumContentsLength(VARIABLE_CHARS)
        self.variable_combo.setSizePolicy(QSizePolicy.Policy.Expanding, QSizePolicy.Policy.Fixed)
        self.variable_combo.setMaximumWidth(
            self.variable_combo.fontMetrics().horizontalAdvance(
                max(
                    (self.variable_combo.itemText(i) for i in range(self.variable_combo.count())),
                    key=len,
                )
            )
            + 48
        )
        bar.addWidget(self.variable_combo)

        bar.addSpacing(4)
        bar.addWidget(t.label(lambda: self.tr("Window")))
        self.window_combo = QComboBox()
        self.window_combo.setObjectName("telemetry_window")
        for seconds in WINDOW_CHOICES_S:
            self.window_combo.addItem(_window_label(seconds), seconds)
        self.window_combo.currentIndexChanged.connect(self._window_chosen)
        bar.addWidget(self.window_combo)

        self.pause_button = QPushButton(self.tr("Pause"))
        self.pause_button.setObjectName("telemetry_pause")
        self.pause_button.setCheckable(True)
        self.pause_button.setStyleSheet(CHECKED_BUTTON_STYLE)
        t.set(self.pause_button.setToolTip, lambda: self.tr("Freeze the plots; recording goes on"))
        self.pause_button.toggled.connect(self.set_paused)
        self.autoscale_button = t.button(
            lambda: self.tr("Autoscale"),
            lambda: self.tr(
                "Fit each plot's vertical range to what is shown (dragging a plot turns it off)"
            ),
        )
        self.autoscale_button.setObjectName("telemetry_autoscale")
        self.autoscale_button.setCheckable(True)
        self.autoscale_button.setStyleSheet(CHECKED_BUTTON_STYLE)
        self.autoscale_button.toggled.connect(self.set_autoscale)
        self.csv_button = t.button(
            lambda: self.tr("Export CSV…"),
            lambda: self.tr("Save the samples shown, with units, as CSV"),
        )
        self.csv_button.clicked.connect(self._ask_csv)
        self.png_button = t.button(
            lambda: self.tr("Export PNG…"), lambda: self.tr("Save the plots as an image")
        )
        self.png_button.clicked.connect(self._ask_png)
        self.paused_label = t.label(lambda: self.tr("paused — recording goes on"))
        self.paused_label.setStyleSheet("color: #7a5200;")
        self.paused_label.hide()
        for widget in (self.pause_button, self.autoscale_button):
            bar.addWidget(widget)
        bar.addWidget(self.paused_label)
        bar.addStretch(1)
        bar.addWidget(self.csv_button)
        bar.addWidget(self.png_button)
        return bar

    def _build_plots(self) -> pg.GraphicsLayoutWidget:
        self.graphics = _PlotArea()
        # The least that fits a 1280 x 800 window with every dock open; the dock asks for more.
        self.graphics.setMinimumSize(360, PLOTS_MIN_HEIGHT)
        self.graphics.ci.layout.setSpacing(2)
        axes = self.recorder.model.axes
        units = _common_unit([a.unit for a in axes])
        self._titles: dict[int, tuple[str, list[tuple[str, str]]]] = {}
        self.captions: list[pg.LabelItem] = []
        self.position_plot = self._add_plot(0)
        self.velocity_plot = self._add_plot(1)
        self.variable_plot = self._add_plot(2)
        self.plots = (self.position_plot, self.velocity_plot, self.variable_plot)
        for plot in self.plots[:-1]:
            plot.setXLink(self.variable_plot)
            # The shared time axis is labelled once, under the last plot; above, the axis
            # only carries the vertical grid lines, in no height of its own.
            bottom = plot.getAxis("bottom")
            bottom.setStyle(showValues=False, tickLength=0)
            bottom.setHeight(1)
        self._units = units
        self._keys = [(a.name, AXIS_COLOURS[i % len(AXIS_COLOURS)]) for i, a in enumerate(axes)]
        self._titles[2] = ("", [])
        self._title_plots()
        for index, (position, velocity) in enumerate(
            zip(self.recorder.position_names(), self.recorder.velocity_names(), strict=True)
        ):
            colour = AXIS_COLOURS[index % len(AXIS_COLOURS)]
            self._curves[position] = self._add_curve(self.position_plot, colour)
            self._curves[velocity] = self._add_curve(self.velocity_plot, colour)
        self.variable_curve = self._add_curve(self.variable_plot, VARIABLE_COLOUR)
        self.apply_colours(LIGHT)
        return self.graphics

    def apply_colours(self, colours: PlotColours) -> None:
        """Background, axes and titles for the light or the dark theme."""
        self.colours = colours
        self.graphics.setBackground(colours.background)
        for plot in self.plots:
            for side in ("left", "bottom"):
                axis = plot.getAxis(side)
                axis.setPen(pg.mkPen(colours.axis))
                axis.setTextPen(pg.mkPen(colours.text))
        self._show_time_label()
        for row in range(len(self.plots)):
            self._show_title(row)
        cross: RotationCross | None = getattr(self, "cross", None)  # built after the plots
        if cross is not None:
            cross.colours = colours
            cross.update()

    def _title_plots(self) -> None:
        """The position and velocity captions, in the language of the moment."""
        units = self._units
        self._titles[0] = (self.tr("position") + (f" ({units})" if units else ""), self._keys)
        velocity_unit = f" ({units}/s)" if units else ""
        self._titles[1] = (self.tr("velocity") + velocity_unit, self._keys)
        if getattr(self, "colours", None) is not None:  # shown once the colours are known
            self._show_title(0)
            self._show_title(1)
            self._show_time_label()

    def _show_title(self, row: int) -> None:
        """The plot's caption beside it: what it shows, its unit, and a key of its curves.

        Beside the data, not over it (a legend box covered the newest
        samples), horizontal and wrapped rather than rotated (long names
        overprinted the neighbouring plots), and costing width, of which a
        dock has plenty, instead of height, of which it has little.
        """
        title, keys = self._titles[row]
        entries = "<br>".join(
            f"<span style='color:{colour}'>&#9473;&#9473;&nbsp;{name}</span>"
            for name, colour in keys
        )
        text = f"<b>{title}</b>" + (f"<br>{entries}" if entries else "")
        self.captions[row].setText(text, color=self.colours.text, size="8pt")

    def _show_time_label(self) -> None:
        """The time axis counts back from now (or from the moment of the pause)."""
        label = (
            self.tr("time before the pause") if self.recorder.paused else self.tr("time before now")
        )
        self.variable_plot.setLabel("bottom", label, units="s", color=self.colours.text)

    def title(self, plot: pg.PlotItem) -> str:
        """The caption beside ``plot`` (rich text)."""
        return str(self.captions[self.plots.index(plot)].text)

    def _add_plot(self, row: int) -> pg.PlotItem:
        plot = self.graphics.addPlot(
            row=row,
            col=0,
            axisItems={"left": LocaleAxis("left"), "bottom": LocaleAxis("bottom")},
        )
        caption = self.graphics.addLabel("", row=row, col=1, justify="left")
        caption.setFixedWidth(CAPTION_WIDTH)
        self.captions.append(caption)
        # No pyqtgraph downsampling or clipping: the recorder hands over an envelope of the
        # window alone, and the curves are shifted (not re-fed) as time goes by, which
        # pyqtgraph's view-dependent reductions would undo every frame.
        plot.showGrid(x=True, y=True, alpha=0.25)
        plot.hideButtons()
        plot.setMenuEnabled(False)
        plot.setMouseEnabled(x=False, y=True)
        plot.enableAutoRange(x=False)
        # A flat curve (a still axis, float noise around 0) is shown as flat, not zoomed
        # into until its ticks read "5e-16".
        plot.getViewBox().setLimits(minYRange=MIN_Y_RANGE)
        plot.getViewBox().sigRangeChangedManually.connect(self._range_dragged)
        for side in ("left", "bottom"):
            axis = plot.getAxis(side)
            # Grid lines at the labelled ticks only: the finer levels' lines cost several
            # milliseconds per plot per frame to draw.
            axis.setStyle(maxTickLevel=0)
            # The time axis is fixed (it counts back from now) and the value axes change
            # only with the data's range: painted once into a pixmap, each frame blits it.
            axis.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
        plot.getAxis("left").setWidth(54)
        return plot

    @staticmethod
    def _add_curve(plot: pg.PlotItem, colour: str) -> Trace:
        # Not PlotDataItem nor PlotCurveItem: see Trace.  Width 1: wider pens draw line
        # segments one by one, several times slower than a 1-pixel polyline.
        curve = Trace(colour)
        plot.addItem(curve)
        curve.view = plot.getViewBox()
        return curve

    def _build_rotation_column(self) -> QVBoxLayout:
        column = QVBoxLayout()
        column.setContentsMargins(0, 0, 0, 0)
        column.setSpacing(4)
        title = self.texts.label(lambda: self.tr("Rotation"))
        title.setAlignment(Qt.AlignmentFlag.AlignHCenter)
        self.cross = RotationCross()
        self.cross.colours = self.colours
        self.cross.setObjectName("rotation_cross")
        self.angle_label = QLabel()
        self.angle_label.setObjectName("rotation_angle")
        self.angle_label.setFont(monospace_font(2, bold=True))
        self.angle_label.setAlignment(Qt.AlignmentFlag.AlignHCenter)
        self.zero_button = self.texts.button(
            lambda: self.tr("Zero"), lambda: self.tr("Make the present angle read 0°")
        )
        self.zero_button.setObjectName("rotation_zero")
        self.zero_button.clicked.connect(self.zero)
        column.addWidget(title)
        column.addWidget(self.cross)
        column.addWidget(self.angle_label)
        column.addWidget(self.zero_button)
        column.addStretch(1)
        return column

    # --- operator actions ----------------------------------------------------

    def set_paused(self, paused: bool) -> None:
        if self.pause_button.isChecked() != paused:
            self.pause_button.setChecked(paused)  # comes back here through toggled
            return
        self.recorder.set_paused(paused)
        self._show_time_label()
        self.pause_button.setText(self.tr("Paused") if paused else self.tr("Pause"))
        self.paused_label.setVisible(paused)

    def set_autoscale(self, enabled: bool) -> None:
        """Fit the vertical ranges to the shown data (on), or leave them where they are."""
        if self.autoscale_button.isChecked() != enabled:
            self.autoscale_button.setChecked(enabled)
            return
        for plot in self.plots:
            view = plot.getViewBox()
            if enabled:
                # Fit to all the curve holds: the recorder hands over the window alone, and
                # pyqtgraph's "visible only" would compare the view's times, which count back
                # from now, with the curve's own, which are shifted.
                view.setAutoVisible(y=False)
                view.enableAutoRange(axis=pg.ViewBox.YAxis, enable=True)
            else:
                view.disableAutoRange(axis=pg.ViewBox.YAxis)

    def zero(self) -> None:
        self.recorder.zero()
        self.redraw()

    def export_csv(self, path: str | Path) -> int:
        """Write the samples shown to ``path``; returns the number of rows."""
        return self.recorder.export_csv(path)

    def export_png(self, path: str | Path) -> None:
        """Save the plots and the rotation cross as they are drawn now."""
        self.redraw()
        if not self.body.grab().save(str(path), "PNG"):
            raise OSError(f"could not write {path}")

    def _ask_csv(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self, self.tr("Export telemetry as CSV"), "telemetry.csv", self.tr("CSV files (*.csv)")
        )
        if path:
            self.export_csv(path)

    def _ask_png(self) -> None:
        path, _ = QFileDialog.getSaveFileName(
            self,
            self.tr("Export telemetry plots as PNG"),
            "telemetry.png",
            self.tr("PNG images (*.png)"),
        )
        if path:
            self.export_png(path)

    def _variable_chosen(self, index: int) -> None:
        self.recorder.set_variable(self.variable_combo.itemData(index))

    def _window_chosen(self, index: int) -> None:
        self.recorder.set_window_s(float(self.window_combo.itemData(index)))

    def _range_dragged(self, _changed: object) -> None:
        """Dragging or zooming a plot by hand ends autoscaling, visibly."""
        if self.autoscale_button.isChecked():
            self.autoscale_button.blockSignals(True)
            self.autoscale_button.setChecked(False)
            self.autoscale_button.blockSignals(False)
            for plot in self.plots:
                plot.getViewBox().disableAutoRange(axis=pg.ViewBox.YAxis)

    # --- recorder → view -----------------------------------------------------

    def _show_variable(self, _subscriber: object = None) -> None:
        variable = self.recorder.variable
        index = self.variable_combo.findData(variable.subscriber if variable else None)
        self.variable_combo.blockSignals(True)
        self.variable_combo.setCurrentIndex(max(0, index))
        self.variable_combo.blockSignals(False)
        if variable is None:
            self._titles[2] = (self.tr("variable (none)"), [])
        else:
            name = _variable_caption(variable)
            self._titles[2] = (name, [(_variable_name(variable), VARIABLE_COLOUR)])
        self._show_title(2)
        rotation = variable is not None and variable.key == ROTATION_KEY
        self.zero_button.setEnabled(rotation)
        if not self.recorder.has_variables:
            self.variable_combo.setEnabled(False)
            self.variable_combo.setToolTip(self.tr("This machine reports no subscriber variables"))

        self._drawn.pop("variable", None)
        self.variable_curve.set_points(np.empty(0), np.empty(0))
        self.redraw()

    def _show_window(self) -> None:
        index = self.window_combo.findData(self.recorder.window_s)
        self.window_combo.blockSignals(True)
        self.window_combo.setCurrentIndex(max(0, index))
        self.window_combo.blockSignals(False)

    def redraw(self) -> None:
        """Hand changed series to their curves and slide every curve to the present.

        The time axis is fixed (it counts back from the view's end), so time
        going by moves the curves, not the axis: a shift of the items, with no
        new data for pyqtgraph to process and no axis to repaint.  The shift
        goes by whole pixels, with the view's end the first pixel boundary at
        or after the newest sample: between two shifts (0.6 s in a 10-minute
        window) a frame repaints only what changed at the curves' ends.
        """
        if not self.isVisible():
            return  # a hidden dock costs nothing; showEvent catches up
        recorder = self.recorder
        window = recorder.window_s
        if window != self._shown_window:
            self._shown_window = window
            self.variable_plot.setXRange(-window, 0.0, padding=0)
        points = self._max_points()
        pixel_s = window / max(1.0, points / 2)
        shown_end = math.ceil(recorder.view_end() / pixel_s) * pixel_s
        if shown_end != self._shown_end:
            self._shown_end = shown_end
            for curve in (*self._curves.values(), self.variable_curve):
                curve.setPos(-shown_end, 0.0)
        # From the view's left edge, not the window's start (up to a pixel earlier): the
        # curves' left ends then stay put between shifts, and only their right ends change.
        since = shown_end - window
        dirty = QRectF()
        for name, curve in self._curves.items():
            dirty |= self._update_curve(name, name, curve, points, since)
        variable = recorder.variable_name
        if variable is not None:
            dirty |= self._update_curve("variable", variable, self.variable_curve, points, since)
        if not dirty.isNull():
            self.graphics.scene().update(dirty)
        self._show_angle()
        # Settle auto-ranges and view transforms now: left to the paint, they change the
        # scene during it and every frame gets painted twice.
        self.graphics.scene().prepareForPaint()

    def _update_curve(
        self, slot: str, name: str, curve: Trace, points: int, since: float
    ) -> QRectF:
        """Give ``curve`` the envelope of ``name`` unless it already has it; what to repaint."""
        drawn = (self.recorder.revision(name, since), points)
        if self._drawn.get(slot) == drawn:
            return QRectF()
        self._drawn[slot] = drawn
        return curve.set_points(*self.recorder.envelope(name, points, since))

    def _max_points(self) -> int:
        """One min/max pair per pixel of plot width: all a screen can show."""
        width = int(self.variable_plot.getViewBox().width())
        return 2 * max(200, width)

    def _show_angle(self) -> None:
        variable = self.recorder.variable
        angle: float | None = None
        if variable is not None and variable.key == ROTATION_KEY:
            angle = self.recorder.latest(variable.name)
        self.cross.set_angle(angle)
        if angle is not None:
            self.angle_label.setText(localized(f"{angle:+.2f}°"))
        else:
            # "—" only while the rotation is plotted and has no value yet; without it the
            # cross says so, and a lone dash under it read as a glitch.
            rotation = variable is not None and variable.key == ROTATION_KEY
            self.angle_label.setText("—" if rotation else "")

    def showEvent(self, event: QShowEvent) -> None:
        super().showEvent(event)
        self._drawn.clear()
        self._shown_end = math.nan
        self.redraw()
