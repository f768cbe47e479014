"""The job preview: a program's path over the machine's travel, progress, and click-to-move.

What it draws, and why:

* travel (moves with the pen up, and plain moves between the points of a
  point list) thin, dashed and grey, because nothing is made there;
* work (moves with the pen down; drill holes — and a point list's points —
  as markers) in a strong colour, because that is the job;
* what is done, drawn again over it in green as the runner reports progress,
  so "where is it" reads at a glance;
* the machine's position as a cross-hair marker, and the soft-limit
  rectangle (0…travel per axis), the only area click-to-move accepts.

A cylindrical machine (the string-art winder: the base turns the work by A
degrees, the tool sits X mm from the centre) is drawn in the plane of the
work, not as an A-by-X chart, because that is where the operator sees nails and
thread: the position marker at (X·cos A, X·sin A), the limits as the disc
the tool reaches (radius = X's travel; A turns freely), the view fitted to
the job rather than to that disc.  A program that knows its plane
(``Program.preview_plane == "board"``, a string-art job) is drawn as it
says; any other has its (A, X) vertices projected, each turn drawn in steps
of ``ARC_STEP_DEG`` because the machine sweeps an arc there, not a chord.

Speed: a 100 000-operation program must open without a pause, so the path is
built once with numpy into one array per kind, runs of the same kind joined
and NaN between runs (``connect="finite"``), never one item per segment.
Progress only slices those arrays (the done prefix), and progress and
position redraws are throttled (``throttle_ms``, 0 in tests) so a fast job
or a 1 kHz position stream costs at most ~30 redraws a second.

Click-to-move is a click, not a drag (drags pan, the wheel zooms), asks
first (``confirm``, injectable so tests need no modal dialog) and sends one
absolute move per axis through the session; outside the travel, while a job
is under way or while motion is locked it refuses with a message and sends
nothing.  On a cylindrical machine the clicked point is taken in polar form:
A turns the shorter way (at most 180°, A stays unwrapped as the machine
keeps it) to the point's bearing, then X moves to its distance from the
centre; beyond X's travel it is refused.  The question names both moves and
their order, because with nails in the board the operator must judge the
way there.
"""

from __future__ import annotations

import html
import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import pyqtgraph as pg
from pyqtgraph.GraphicsScene.mouseEvents import MouseClickEvent
from PySide6.QtCore import QCoreApplication, QPointF, Qt, QTimer, Signal
from PySide6.QtWidgets import QGraphicsItem, QHBoxLayout, QMessageBox, QVBoxLayout, QWidget

from app.jobs.formats.string_art.geometry import shortest_turn
from app.jobs.formats.string_art.program import StringArtProgram
from app.jobs.program import OpKind, Program, ProgramPath
from app.jobs.registration import hole_positions
from app.jobs.run.runner import JobRunner, JobState
from app.local_numbers import local_number
from app.profiles import MachineProfile
from app.station import Station
from widgets.jobs.preview_items import (
    DONE_COLOUR,
    LIMIT_COLOUR,
    POSITION_COLOUR,
    TRAVEL_COLOUR,
    WORK_COLOUR,
    PreviewItems,
)
from widgets.jobs.string_art_picture import (
    ThreadPicture,
    ThreadPictureItem,
    band_pen,
    paint_thread,
)
from widgets.jobs.string_art_thread import (
    BAND_EDGES,
    ThreadGeometry,
    WoundCounter,
    band_alpha,
)
from widgets.retranslate import Texts
from widgets.theme import LIGHT, PlotColours
from widgets.units import shown_unit

DEFAULT_THROTTLE_MS = 33.0
# The plot's least height (px), when the bands over the preview (a prompt, the
# registration row, a resume offer) take their room from it; without them it has
# widgets/jobs/preview_column.py's PREVIEW_ROOM more.
PLOT_MIN_HEIGHT = 60
#: A click this many pixels from a hole picks it as a reference.
PICK_RADIUS_PX = 8
#: Degrees per drawn step of a projected turn: an arc, not a chord, within a pixel or so.
ARC_STEP_DEG = 5.0
#: At most this many steps per move, so a move spinning the base many turns stays cheap.
MAX_ARC_STEPS = 720
#: A path with more points than this is drawn without a dot on each.
MAX_MARKERS = 50_000
#: Points of the drawn reach circle.
CIRCLE_POINTS = 361

#: Runner states in which a job is under way: the machine is the job's, not the mouse's.
ACTIVE_STATES = frozenset({JobState.RUNNING, JobState.PAUSING, JobState.PAUSED, JobState.WAITING})

_EMPTY = np.empty(0)


def legend_html(polar: bool) -> str:
    """The key to the colours, in the row above the plot (a legend inside would hide the
    path); a cylindrical machine's limit is the disc the tool reaches."""
    work = QCoreApplication.translate("JobPreview", "work")
    travel = QCoreApplication.translate("JobPreview", "travel")
    done = QCoreApplication.translate("JobPreview", "done")
    machine = QCoreApplication.translate("JobPreview", "machine")
    if polar:
        limit = "&#9675; " + html.escape(QCoreApplication.translate("JobPreview", "reach"))
    else:
        limit = "&#9633; " + html.escape(QCoreApplication.translate("JobPreview", "travel limits"))
    return (
        f"<span style='color:{WORK_COLOUR}'>&#9679; {html.escape(work)}</span>&nbsp;&nbsp;"
        f"<span style='color:{TRAVEL_COLOUR}'>- - {html.escape(travel)}</span>&nbsp;&nbsp;"
        f"<span style='color:{DONE_COLOUR}'>&#9679; {html.escape(done)}</span>&nbsp;&nbsp;"
        f"<span style='color:{POSITION_COLOUR}'><b>+</b> {html.escape(machine)}</span>"
        f"&nbsp;&nbsp;<span style='color:{LIMIT_COLOUR}'>{limit}</span>"
    )


@dataclass(frozen=True)
class PolarAxes:
    """A cylindrical machine's plane: a rotary axis turns the work, a linear one is the radius."""

    angle: int  # axis index, degrees counter-clockwise from +x
    radius: int  # axis index, mm from the centre
    reach: float  # the radius axis' travel: how far from the centre the tool gets

    def project(self, angle_deg: float, radius: float) -> tuple[float, float]:
        a = math.radians(angle_deg)
        return radius * math.cos(a), radius * math.sin(a)


def polar_axes(profile: MachineProfile) -> PolarAxes | None:
    """The polar axes of a cylindrical G-code machine, None for any other machine."""
    if profile.gcode is None or profile.gcode.kinematics != "cylindrical":
        return None
    kinds = [axis.kind for axis in profile.axes]
    if "rotary" not in kinds or "linear" not in kinds:
        return None
    radius = kinds.index("linear")
    return PolarAxes(kinds.index("rotary"), radius, profile.axes[radius].travel)


def board_plane(path: ProgramPath) -> ProgramPath:
    """(angle°, radius) vertices as points of the work's plane, turns drawn as arcs.

    The machine moves A and X together in proportion, a spiral arc on the
    work; a chord between the ends would cut across what the tool sweeps,
    so each move is drawn in steps of at most ``ARC_STEP_DEG``.  An axis not
    set yet stands at 0, where homing left it.
    """
    coords = np.nan_to_num(path.coords[:, :2])
    count = len(coords)
    if not count:
        return ProgramPath(np.empty((0, 2)), path.ops, path.pen)
    angle, radius = coords[:, 0], coords[:, 1]
    steps = np.ones(count, dtype=np.int64)
    turns = np.ceil(np.abs(np.diff(angle)) / ARC_STEP_DEG)
    steps[1:] = np.clip(turns, 1, MAX_ARC_STEPS).astype(np.int64)
    vertex = np.repeat(np.arange(count), steps)  # the vertex each drawn point leads to
    starts = np.repeat(np.cumsum(steps) - steps, steps)
    fraction = (np.arange(len(vertex)) - starts + 1) / steps[vertex]
    before = np.maximum(vertex - 1, 0)
    a = np.radians(angle[before] + (angle[vertex] - angle[before]) * fraction)
    r = radius[before] + (radius[vertex] - radius[before]) * fraction
    return ProgramPath(
        np.column_stack((r * np.cos(a), r * np.sin(a))), path.ops[vertex], path.pen[vertex]
    )


def ask_operator(parent: QWidget) -> Callable[[str], bool]:
    """The default confirmation: a Yes/No box, No by default (a stray click must not move)."""

    def confirm(text: str) -> bool:
        answer = QMessageBox.question(
            parent,
            QCoreApplication.translate("JobPreview", "Move the machine?"),
            text,
            QMessageBox.StandardButton.Yes | QMessageBox.StandardButton.No,
            QMessageBox.StandardButton.No,
        )
        return answer == QMessageBox.StandardButton.Yes

    return confirm


def _show(
    item: pg.GraphicsObject, x: Sequence[float] | np.ndarray, y: Sequence[float] | np.ndarray
) -> None:
    """A highlight given its points, hidden while it has none: every frame asks each visible
    item for its bounds and paints it, empty or not."""
    if isinstance(item, pg.ScatterPlotItem):
        item.setData(x=x, y=y)
    else:
        item.setData(x, y, connect="finite")
    item.setVisible(len(x) > 0)


class PathArrays:
    """One kind of path (travel or work) as plot-ready arrays plus each point's operation.

    ``ops`` is non-decreasing, so the part done after ``n`` operations is the
    prefix up to ``searchsorted(ops, n)`` — a slice, not a rebuild.
    """

    def __init__(self, x: np.ndarray, y: np.ndarray, ops: np.ndarray) -> None:
        self.x = x
        self.y = y
        self.ops = ops

    def done_count(self, done: int) -> int:
        return int(np.searchsorted(self.ops, done, side="left"))


def _runs(
    x: np.ndarray, y: np.ndarray, ops: np.ndarray, kind: np.ndarray, wanted: bool
) -> PathArrays:
    """The vertices of segments whose ``kind`` is ``wanted``, consecutive ones joined.

    Vertex ``j`` ends segment ``j`` (``kind[j]``; vertex 0 ends none) and starts
    segment ``j + 1``.  It belongs to the curve when either touches a wanted
    segment; a NaN follows every vertex that ends a wanted run.
    """
    ends = kind == wanted  # segment j (ending at vertex j) is wanted
    if len(ends):
        ends[0] = False  # the first move's segment starts where the machine happens to be
    starts = np.append(ends[1:], False)  # segment j + 1 (starting at j) is wanted
    keep = ends | starts
    run_end = ends & ~starts
    index = np.flatnonzero(keep)
    breaks = np.flatnonzero(run_end[index])  # positions within the kept points
    out_x = np.insert(x[index], breaks + 1, np.nan)
    out_y = np.insert(y[index], breaks + 1, np.nan)
    out_ops = np.insert(ops[index], breaks + 1, ops[index][breaks])
    return PathArrays(out_x, out_y, out_ops)


def _bounds(
    xs: Sequence[np.ndarray], ys: Sequence[np.ndarray]
) -> tuple[float, float, float, float] | None:
    """The extent (x0, x1, y0, y1) of the finite values given in parts, None when none is.

    Each axis on its own (NaN for an axis with no finite value), as the view is fitted.
    """

    def extent(parts: Sequence[np.ndarray]) -> tuple[float, float]:
        # Part by part: the finite values of all of them at once were another copy of the path.
        low, high = math.inf, -math.inf
        for part in parts:
            finite = part[np.isfinite(part)]
            if len(finite):
                low, high = min(low, float(finite.min())), max(high, float(finite.max()))
        return (low, high) if low <= high else (math.nan, math.nan)

    x0, x1 = extent(xs)
    y0, y1 = extent(ys)
    if math.isnan(x0) and math.isnan(y0):
        return None
    return x0, x1, y0, y1


def _fitted_scale(
    bounds: tuple[float, float, float, float] | None, board_mm: float, view_px: tuple[float, float]
) -> float:
    """Device pixels per mm once a polar view is fitted to ``bounds`` and the board (its
    :meth:`JobPreview.fit`: padding 5 % each side, aspect locked); 0 when not known."""
    found = [bounds] if bounds is not None and not math.isnan(bounds[0] + bounds[2]) else []
    if board_mm > 0:
        found.append((-board_mm, board_mm, -board_mm, board_mm))
    if not found or min(view_px) <= 0:
        return 0.0
    width = max(b[1] for b in found) - min(b[0] for b in found)
    height = max(b[3] for b in found) - min(b[2] for b in found)
    if width <= 0 or height <= 0:
        return 0.0
    return min(view_px[0] / (1.1 * width), view_px[1] / (1.1 * height))


class ProgramGeometry:
    """The plottable shape of a program on two axes, computed once per program."""

    def __init__(
        self,
        program: Program,
        x_axis: str,
        y_axis: str | None,
        *,
        polar: bool = False,
        view_px: tuple[float, float] = (0.0, 0.0),
    ) -> None:
        """``polar``: the axes are (angle, radius) and the program's path is to be projected.

        ``view_px``: the plot's size in device pixels, when known: a merged string-art
        thread is then painted into an image at the scale the view will fit it to.
        """
        #: A string-art job's nails and thread (merged when huge), laid out here too.
        self.thread = ThreadGeometry.of(program) if isinstance(program, StringArtProgram) else None
        reach = 0.0
        if self.thread is not None and self.thread.merged and isinstance(program, StringArtProgram):
            # The winding is hidden under the thread: only the travel and its extent.
            path, reach = program.preview_travel()
        else:
            path = program.preview_path(x_axis, y_axis)
        if polar and y_axis is not None and program.preview_plane == "axes":
            path = board_plane(path)
        # Views, not copies: a million moves' copies were 16 MB more at the load's peak.
        xs, ys = path.coords[:, 0], path.coords[:, 1]
        ops, pen = path.ops, path.pen
        self.travel = _runs(xs, ys, ops, pen, wanted=False)
        self.work = _runs(xs, ys, ops, pen, wanted=True)
        self.markers = self._markers(program, xs, ys, ops)
        around = np.array([-reach, reach]) if reach > 0 else _EMPTY
        #: (x0, x1, y0, y1) of everything drawn, None when nothing is: fitting the view
        #: must not scan millions of points on the GUI thread.
        self.bounds = _bounds(
            (self.travel.x, self.work.x, self.markers.x, around),
            (self.travel.y, self.work.y, self.markers.y, around),
        )
        if self.thread is not None:
            # The needle's winding path is hidden under the thread: millions of points that
            # would only be handed to a hidden curve.
            self.work = PathArrays(_EMPTY, _EMPTY, np.empty(0, dtype=np.int64))
        #: A merged thread's chords painted here (see :mod:`widgets.jobs.string_art_picture`).
        self.thread_picture: ThreadPicture | None = None
        if self.thread is not None and self.thread.merged and isinstance(program, StringArtProgram):
            scale = _fitted_scale(self.bounds, program.job.params.radius_cm * 10.0, view_px)
            self.thread_picture = paint_thread(self.thread, scale, WORK_COLOUR, THREAD_ALPHA)

    @staticmethod
    def _markers(program: Program, xs: np.ndarray, ys: np.ndarray, ops: np.ndarray) -> PathArrays:
        """Drill holes where they are drilled; a plain point list's points are its work."""
        kinds = program.kinds()
        if OpKind.DRILL in kinds:
            drills = program.indices_of(OpKind.DRILL)
            # Where the tool is at each drill: the last move before it.
            at = np.searchsorted(ops, drills, side="right") - 1
            valid = at >= 0
            at, drills = at[valid], drills[valid]
            return PathArrays(xs[at], ys[at], drills)
        uses_pen = bool(kinds & {OpKind.PEN_DOWN, OpKind.PEN_UP})
        # A job drawn in its own plane (string art) marks its nails itself; and past
        # MAX_MARKERS the dots would only bury the path (and take seconds to build).
        own_plane = program.preview_plane == "board"
        if uses_pen or own_plane or not len(xs) or len(xs) > MAX_MARKERS:
            return PathArrays(_EMPTY, _EMPTY, np.empty(0, dtype=np.int64))
        return PathArrays(np.ascontiguousarray(xs), np.ascontiguousarray(ys), ops)


#: Points in the done trail's growing piece; past this it is frozen and a new piece starts.
TRAIL_PIECE_POINTS = 4096


class FrozenPieces:
    """Full pieces of a growing done part, each an item of its own never touched again.

    Frozen pieces are painted once into a pixmap (they do not change), follow
    the visibility of the growing item, and go on a reset.
    """

    def __init__(self, plot: pg.PlotItem) -> None:
        self.plot = plot
        self.frozen: list[pg.GraphicsObject] = []

    def _freeze(self, piece: pg.GraphicsObject, visible: bool) -> None:
        piece.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
        piece.setVisible(visible)
        self.plot.addItem(piece)
        self.frozen.append(piece)

    def _thaw(self) -> None:
        for item in self.frozen:
            self.plot.removeItem(item)
        self.frozen = []

    def set_visible(self, visible: bool) -> None:
        for item in self.frozen:
            item.setVisible(visible)


class DoneTrail(FrozenPieces):
    """The done part of one path kind, drawn append-only as the job advances.

    Redrawing the whole done prefix on every progress step costs in proportion
    to what is done (a long job slows as it goes).  Here only the last piece,
    at most :data:`TRAIL_PIECE_POINTS` points, is given new data; full pieces
    are frozen into items of their own that are never touched again.  Going
    back (a new run, another program) starts over.
    """

    def __init__(self, plot: pg.PlotItem, tail: pg.PlotCurveItem) -> None:
        super().__init__(plot)
        self.tail = tail  # the growing piece (the preview's done curve, as before)
        self._path: PathArrays | None = None
        self._start = 0  # the first point of the growing piece
        self._shown = 0  # points drawn in all

    def reset(self) -> None:
        self._thaw()
        self._path = None
        self._start = self._shown = 0
        self.tail.setData(_EMPTY, _EMPTY)

    def show(self, path: PathArrays, count: int) -> None:
        """Draw the first ``count`` points of ``path`` as done."""
        if path is not self._path or count < self._shown:
            self.reset()
            self._path = path
        if count == self._shown:
            return
        while count - self._start > TRAIL_PIECE_POINTS:
            end = self._start + TRAIL_PIECE_POINTS
            piece = pg.PlotCurveItem(
                path.x[self._start : end],
                path.y[self._start : end],
                pen=self.tail.opts["pen"],
                connect="finite",
            )
            self._freeze(piece, self.tail.isVisible())
            self._start = end - 1  # the next piece starts where this one ends: no gap
        self.tail.setData(
            path.x[self._start : count], path.y[self._start : count], connect="finite"
        )
        self._shown = count


class JobPreview(QWidget):
    """The path of a program, what is done of it and where the machine is; click to move.

    ``runner`` (optional) supplies progress and whether a job is under way;
    without one, :meth:`set_done` drives the done part by hand.
    """

    #: A refusal or news about click-to-move, for the dock's message area.
    message = Signal(str)
    #: A hole clicked while picking a reference: the reference (0-based) and the hole's
    #: index among the job's holes in drilling order (the registration row's numbering).
    holePicked = Signal(int, int)
    #: The program now drawn (None: cleared), refused ones too: the drill page walks it.
    programShown = Signal(object)

    def __init__(
        self,
        station: Station,
        runner: JobRunner | None = None,
        *,
        confirm: Callable[[str], bool] | None = None,
        throttle_ms: float = DEFAULT_THROTTLE_MS,
        parent: QWidget | None = None,
    ) -> None:
        super().__init__(parent)
        self.station = station
        self.model = station.model
        self.runner = runner
        self.confirm = confirm or ask_operator(self)
        self.program: Program | None = None
        self.path_geometry: ProgramGeometry | None = None
        #: Wall seconds the last :meth:`set_program` took to build the curves.
        self.build_seconds = 0.0
        self._prepared: tuple[Program, ProgramGeometry] | None = None
        self.done = 0
        self.last_message = ""
        #: The reference the next click picks a hole for (None: a click moves the machine).
        self.picking: int | None = None
        #: Takes a click's plot point instead of a move (the "Run from…" dialog picks a stroke).
        self.point_picker: Callable[[float, float], None] | None = None
        axes = station.profile.axes
        #: Set on a cylindrical machine: the plot is the work's plane, not two axes.
        self.polar = polar_axes(station.profile)
        self.axis_indices: tuple[int, ...] = (
            tuple(range(min(2, len(axes))))
            if self.polar is None
            else (self.polar.angle, self.polar.radius)
        )
        self.axis_names: tuple[str, ...] = tuple(axes[i].name for i in self.axis_indices)
        self.travel_limits: tuple[tuple[float, float], ...] = tuple(
            (0.0, axes[i].travel) for i in self.axis_indices
        )
        self._dirty: set[str] = set()
        self._throttle = QTimer(self)
        self._throttle.setSingleShot(True)
        self._throttle.setInterval(max(0, round(throttle_ms)))
        self._throttle.timeout.connect(self._flush)
        self._throttle_ms = throttle_ms

        self._build(axes[self.axis_indices[0]].unit if axes else "mm")
        self.string_art = StringArtPreviewExtras(
            self.plot, (self.work_curve, self.done_work_curve, self.work_markers, self.done_markers)
        )
        self.done_trails = (
            DoneTrail(self.plot, self.done_travel_curve),
            DoneTrail(self.plot, self.done_work_curve),
        )
        self.done_dots = self.done_markers
        self.model.axisChanged.connect(self._axis_changed)
        self.model.lockChanged.connect(self._update_enabled)
        if runner is not None:
            # Green is what the machine ran, not what it was sent: a G-code planner holds
            # answered lines the pen has not drawn yet.
            runner.executedChanged.connect(self._progress)
            runner.stateChanged.connect(self._update_enabled)
        self._draw_position()
        self._update_enabled()
        self.fit()

    # --- building ------------------------------------------------------------

    def _build(self, unit: str) -> None:
        layout = QVBoxLayout(self)
        layout.setContentsMargins(0, 0, 0, 0)
        layout.setSpacing(2)
        layout.addLayout(self._build_bar())
        self.plot_widget = pg.PlotWidget(background="w")
        self.plot_widget.setObjectName("job_preview_plot")
        self.plot_widget.setMinimumSize(240, PLOT_MIN_HEIGHT)
        self.plot = self.plot_widget.getPlotItem()
        self.plot.setAspectLocked(True, ratio=1.0)
        self.plot.showGrid(x=True, y=True, alpha=0.2)
        self.plot.hideButtons()
        self.plot.setMenuEnabled(False)
        names = self.axis_names if self.axis_names else ("X",)
        if self.polar is not None:
            # The work's plane, whatever the axes are called; the radius axis' unit.
            unit = self.station.profile.axes[self.polar.radius].unit
            names = (self.tr("x on the work"), self.tr("y on the work"))
        self.plot.setLabel("bottom", names[0], units=unit)
        self.plot.setLabel("left", names[1] if len(names) > 1 else "", units=unit)
        for side in ("left", "bottom"):
            axis = self.plot.getAxis(side)
            # pyqtgraph would otherwise show "(kmm)" or "(µmm)": these are machine millimetres.
            axis.enableAutoSIPrefix(False)
            # The axes and their grid change only with the view; played from their picture on
            # every repaint they were two thirds of a running job's preview frame (about
            # 15 of 23 ms at 800 x 600).  Painted once into a pixmap, each frame blits it.
            axis.setCacheMode(QGraphicsItem.CacheMode.DeviceCoordinateCache)
        self.apply_colours(LIGHT)
        layout.addWidget(self.plot_widget, 1)

        if self.polar is not None:
            around = np.linspace(0.0, 2.0 * np.pi, CIRCLE_POINTS)
            outline_x = self.polar.reach * np.cos(around)
            outline_y = self.polar.reach * np.sin(around)
        else:
            (x0, x1), (y0, y1) = self._limits_2d()
            outline_x, outline_y = np.array([x0, x1, x1, x0, x0]), np.array([y0, y0, y1, y1, y0])
        items = self.items = PreviewItems(self.plot, outline_x, outline_y)
        self.limits_curve, self.path_picture = items.limits_curve, items.path_picture
        self.travel_curve, self.work_curve = items.travel_curve, items.work_curve
        self.done_travel_curve, self.done_work_curve = (
            items.done_travel_curve,
            items.done_work_curve,
        )
        self.work_markers, self.done_markers = items.work_markers, items.done_markers
        self.position_marker, self.question_marker = items.position_marker, items.question_marker
        self.step_marker, self.candidate_curve = items.step_marker, items.candidate_curve
        self.plot.scene().sigMouseClicked.connect(self._clicked)

    def _build_bar(self) -> QHBoxLayout:
        """The row over the plot: the colours' key (a legend inside would hide the path), Fit."""
        bar = QHBoxLayout()
        bar.setSpacing(6)
        polar = self.polar is not None
        t = self.texts = Texts(self)
        self.hint_label = t.label(lambda: legend_html(polar))
        self.hint_label.setObjectName("preview_hint")
        t.set(
            self.hint_label.setToolTip,
            lambda: (
                self.tr(
                    "Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) within "
                    "the tool's reach turns the base and moves the tool there after you confirm"
                )
                if polar
                else self.tr(
                    "Drag pans, the wheel zooms, Fit shows it all; a click (not a drag) inside "
                    "the travel limits moves the machine there after you confirm"
                )
            ),
        )
        self.fit_button = t.button(
            lambda: self.tr("Fit"),
            lambda: (
                self.tr("Show the whole job (without a job, the tool's reach)")
                if polar
                else self.tr("Show the whole job and the machine's travel")
            ),
        )
        self.fit_button.setObjectName("preview_fit")
        t.also(self._update_enabled)
        self.fit_button.clicked.connect(self.fit)
        bar.addWidget(self.hint_label, 1)
        bar.addWidget(self.fit_button)
        return bar

    def _limits_2d(self) -> tuple[tuple[float, float], tuple[float, float]]:
        limits = self.travel_limits
        x = limits[0] if limits else (0.0, 0.0)
        y = limits[1] if len(limits) > 1 else (0.0, 0.0)
        return x, y

    # --- public --------------------------------------------------------------

    def mark_question(self, index: int | None) -> None:
        """Ring where operation ``index`` acts (None clears): the place the operator must look."""
        where = self._where(index) if index is not None else None
        if where is None:
            _show(self.question_marker, _EMPTY, _EMPTY)
        else:
            _show(self.question_marker, [where[0]], [where[1]])

    def mark_step(self, position: object) -> None:
        """Square the step-through's stop at ``position`` ((x, y) in mm; None clears)."""
        if isinstance(position, tuple) and len(position) == 2:
            x, y = float(position[0]), float(position[1])
            if self.polar is not None:
                x, y = self.polar.project(x, y)
            _show(self.step_marker, [x], [y])
        else:
            _show(self.step_marker, _EMPTY, _EMPTY)

    def mark_candidates(self, first: int | None, last: int = 0) -> None:
        """Highlight the path of operations ``first … last - 1`` (None clears): the lines
        that may or may not have run, among which the operator picks where to resume."""
        program = self.program
        if first is None or program is None or not self.axis_names or last <= first:
            _show(self.candidate_curve, _EMPTY, _EMPTY)
            return
        y_name = self.axis_names[1] if len(self.axis_names) > 1 else None
        path = program.preview_path(self.axis_names[0], y_name)
        begin = int(np.searchsorted(path.ops, first, side="left"))
        end = int(np.searchsorted(path.ops, last, side="left"))
        # From where the first candidate starts (the vertex before it) to the last one's end.
        xs = path.coords[max(begin - 1, 0) : end, 0]
        ys = path.coords[max(begin - 1, 0) : end, 1]
        if self.polar is not None:
            points = [self.polar.project(float(x), float(y)) for x, y in zip(xs, ys, strict=True)]
            xs = np.array([p[0] for p in points])
            ys = np.array([p[1] for p in points])
        _show(self.candidate_curve, xs, ys)

    def _where(self, index: int) -> tuple[float, float] | None:
        """Where the machine stands for operation ``index``: the last target before it."""
        program = self.program
        if program is None or not self.axis_names or not 0 <= index < len(program):
            return None
        x_name = self.axis_names[0]
        y_name = self.axis_names[1] if len(self.axis_names) > 1 else None
        x = y = None
        for back in range(index, -1, -1):
            target = program[back].target
            if x is None and x_name in target:
                x = target[x_name]
            if y is None and y_name is not None and y_name in target:
                y = target[y_name]
            if x is not None and (y is not None or y_name is None):
                break
        if x is None:
            return None
        y = y if y is not None else 0.0
        return self.polar.project(x, y) if self.polar is not None else (x, y)

    def geometry_maker(self) -> Callable[[Program], ProgramGeometry | None]:
        """What :meth:`set_program` computes for a program, as a function of the program
        alone: the dock's loading thread runs it, so millions of operations are laid out
        off the GUI thread (hand the result to :meth:`prepare`)."""
        names = tuple(self.axis_names)
        polar = self.polar is not None
        view = self.plot.getViewBox().size()
        ratio = self.plot_widget.devicePixelRatioF()
        view_px = (view.width() * ratio, view.height() * ratio) if self.isVisible() else (0.0, 0.0)

        def make(program: Program) -> ProgramGeometry | None:
            if not names:
                return None
            y_axis = names[1] if len(names) > 1 else None
            return ProgramGeometry(program, names[0], y_axis, polar=polar, view_px=view_px)

        return make

    def prepare(self, program: Program, geometry: ProgramGeometry | None) -> None:
        """The geometry :meth:`set_program` uses for ``program`` instead of computing it."""
        self._prepared = (program, geometry) if geometry is not None else None

    def apply_colours(self, colours: PlotColours) -> None:
        """Background, axes and their text for the light or the dark theme."""
        self.plot_widget.setBackground(colours.background)
        for side in ("left", "bottom"):
            axis = self.plot.getAxis(side)
            axis.setPen(pg.mkPen(colours.axis))
            axis.setTextPen(pg.mkPen(colours.text))
            axis.setLabel(axis.labelText, axis.labelUnits, color=colours.text)

    def set_program(self, program: Program | None) -> None:
        """Draw ``program`` (None clears); times the build in ``build_seconds``."""
        start = time.perf_counter()
        prepared, self._prepared = self._prepared, None
        self.program = program
        self.done = 0
        _show(self.question_marker, _EMPTY, _EMPTY)
        _show(self.candidate_curve, _EMPTY, _EMPTY)
        if program is None or not self.axis_names:
            self.path_geometry = None
            for curve in (self.travel_curve, self.work_curve):
                curve.setData(_EMPTY, _EMPTY)
            self.path_picture.set_layers((), None)
            self.work_markers.setData(x=_EMPTY, y=_EMPTY)
        else:
            y_axis = self.axis_names[1] if len(self.axis_names) > 1 else None
            if prepared is not None and prepared[0] is program:
                geometry = prepared[1]
            else:
                geometry = ProgramGeometry(
                    program, self.axis_names[0], y_axis, polar=self.polar is not None
                )
            self.path_geometry = geometry
            self.items.show_path(geometry.travel, geometry.work, geometry.bounds)
            self.work_markers.setData(x=geometry.markers.x, y=geometry.markers.y)
        thread = self.path_geometry.thread if self.path_geometry is not None else None
        picture = self.path_geometry.thread_picture if self.path_geometry is not None else None
        self.string_art.set_program(program, thread, picture)
        if self.string_art.merged_note:
            self._say(self.string_art.merged_note)
        self._draw_done()
        self.fit()
        self.build_seconds = time.perf_counter() - start
        self.programShown.emit(program)

    def set_done(self, done: int) -> None:
        """Operations ``0 … done - 1`` are done (throttled redraw)."""
        if done == self.done:
            return
        self.done = done
        self._request("done")

    def fit(self) -> None:
        """Show the whole job and the soft-limit rectangle (polar: the job, else the reach)."""
        if self.polar is not None:
            self._fit_polar(self.polar)
            return
        (x0, x1), (y0, y1) = self._limits_2d()
        geometry = self.path_geometry
        if geometry is not None and geometry.bounds is not None:
            gx0, gx1, gy0, gy1 = geometry.bounds
            if not math.isnan(gx0):
                x0, x1 = min(x0, gx0), max(x1, gx1)
            if not math.isnan(gy0):
                y0, y1 = min(y0, gy0), max(y1, gy1)
        self.plot.getViewBox().setRange(xRange=(x0, x1), yRange=(y0, y1), padding=0.05)

    def _fit_polar(self, polar: PolarAxes) -> None:
        """The job's path and its board; the disc the tool reaches only when there is no job.

        The reach (X's whole travel) is far larger than most boards: fitting it
        would leave the nails a small ring in the middle.
        """
        geometry = self.path_geometry
        bounds = geometry.bounds if geometry is not None else None
        # Polar fitting needs both coordinates of a point: the projected plane always has them.
        found = [bounds] if bounds is not None and not math.isnan(bounds[0] + bounds[2]) else []
        board = self.string_art.board_radius_mm
        if board > 0:
            found.append((-board, board, -board, board))
        if found:
            x0, x1 = min(b[0] for b in found), max(b[1] for b in found)
            y0, y1 = min(b[2] for b in found), max(b[3] for b in found)
        else:
            x0 = y0 = -polar.reach
            x1 = y1 = polar.reach
        self.plot.getViewBox().setRange(xRange=(x0, x1), yRange=(y0, y1), padding=0.05)

    @property
    def click_refusal(self) -> str | None:
        """Why a click would not move the machine now, or None when it would."""
        if self.runner is not None and self.runner.state in ACTIVE_STATES:
            return self.tr("a job is under way")
        reason = self.model.motion_lock_reason()
        if reason is not None:
            return self.tr("motion is locked: {0}").format(reason)
        if self.station.session is None:
            return self.tr("not connected")
        return None

    def request_move(self, x: float, y: float) -> bool:
        """What a click at (x, y) does: refuse, or ask and move.  True when moves were sent."""
        if self.polar is not None:
            return self._request_polar_move(self.polar, x, y)
        target = (x, y)[: len(self.axis_names)]
        described = ", ".join(
            f"{name} {local_number(value, '.3f')}"
            for name, value in zip(self.axis_names, target, strict=True)
        )
        refusal = self.click_refusal
        if refusal is not None:
            return self._say(self.tr("Click-to-move refused ({0}): {1}").format(described, refusal))
        outside = [
            self.tr("{0} {1} is outside {2}…{3}").format(
                name, local_number(value, ".3f"), local_number(low), local_number(high)
            )
            for name, value, (low, high) in zip(
                self.axis_names, target, self.travel_limits, strict=True
            )
            if not low <= value <= high
        ]
        if outside:
            return self._say(
                self.tr("Click-to-move refused: {0} (soft limits)").format("; ".join(outside))
            )
        unit = shown_unit(self.station.profile.axes[0].unit)
        if not self.confirm(self.tr("Move to {0} {1}?").format(described, unit)):
            return self._say(self.tr("Click-to-move cancelled"))
        session = self.station.session
        assert session is not None  # click_refusal said so
        for axis, value in zip(self.axis_indices, target, strict=True):
            if not session.move_absolute(axis, value):
                return self._say(self.tr("The machine refused the move to {0}").format(described))
        self._say(self.tr("Moving to {0}").format(described))
        return True

    def _request_polar_move(self, polar: PolarAxes, x: float, y: float) -> bool:
        """The point (x, y) of the work as the shorter turn of A to its bearing, then X out."""
        angle_name, radius_name = self.axis_names
        axes = self.station.profile.axes
        angle_unit, radius_unit = shown_unit(axes[polar.angle].unit), axes[polar.radius].unit
        radius = math.hypot(x, y)
        current = self.model.axes[polar.angle].position
        # At the centre every bearing is the same point: no turn.
        bearing = math.degrees(math.atan2(y, x)) if radius > 1e-9 else current
        turn = shortest_turn(current, bearing)
        angle = current + turn
        described = (
            f"{angle_name} {local_number(angle, '.3f')} {angle_unit}, "
            f"{radius_name} {local_number(radius, '.3f')} {radius_unit}"
        )
        refusal = self.click_refusal
        if refusal is not None:
            return self._say(self.tr("Click-to-move refused ({0}): {1}").format(described, refusal))
        if radius > polar.reach:
            return self._say(
                self.tr(
                    "Click-to-move refused: {0} {1} from the centre is beyond "
                    "{2}'s travel 0…{3} (the reach)"
                ).format(
                    local_number(radius, ".3f"), radius_unit, radius_name, local_number(polar.reach)
                )
            )
        question = self.tr("Turn {0} by {1}° to {2} {3}, then move {4} to {5} {6}?").format(
            angle_name,
            local_number(turn, "+.1f"),
            local_number(angle, ".3f"),
            angle_unit,
            radius_name,
            local_number(radius, ".3f"),
            radius_unit,
        )
        if not self.confirm(question):
            return self._say(self.tr("Click-to-move cancelled"))
        session = self.station.session
        assert session is not None  # click_refusal said so
        for axis, value in ((polar.angle, angle), (polar.radius, radius)):
            if not session.move_absolute(axis, value):
                return self._say(self.tr("The machine refused the move to {0}").format(described))
        self._say(self.tr("Moving to {0}").format(described))
        return True

    # --- picking reference holes ------------------------------------------------

    def pick_reference(self, reference: int | None) -> None:
        """The next click on a hole chooses it as ``reference`` (0-based); None: moves again."""
        self.picking = reference
        if reference is not None:
            self._say(
                self.tr("Click a hole in the preview for reference {0}").format(reference + 1)
            )

    def nearest_hole(self, x: float, y: float, within: float) -> int | None:
        """The hole (drilling order) nearest (x, y) on the plot, if one lies ``within``."""
        program = self.program
        if program is None or self.polar is not None:
            return None
        holes = hole_positions(program)
        if not holes:
            return None
        points = np.asarray(holes, dtype=np.float64)
        distances = np.hypot(points[:, 0] - x, points[:, 1] - y)
        best = int(np.argmin(distances))
        return best if distances[best] <= within else None

    def _pick(self, point: QPointF) -> None:
        reference = self.picking
        assert reference is not None
        view = self.plot.getViewBox()
        # A hole under the pointer: within a few pixels, whatever the zoom.
        pixel_w, pixel_h = view.viewPixelSize()
        within = PICK_RADIUS_PX * max(abs(pixel_w), abs(pixel_h))
        hole = self.nearest_hole(point.x(), point.y(), within)
        if hole is None:
            self._say(self.tr("No hole there: click on a hole, or press Pick again to stop"))
            return
        self.picking = None
        self._say(self.tr("Hole {0} is reference {1}").format(hole + 1, reference + 1))
        self.holePicked.emit(reference, hole)

    # --- events --------------------------------------------------------------

    def _clicked(self, event: object) -> None:
        """A left click (pyqtgraph sends none for a drag) in the plot area is a move request."""
        if not isinstance(event, MouseClickEvent):
            return
        if event.button() != Qt.MouseButton.LeftButton or event.double():
            return
        view = self.plot.getViewBox()
        scene_pos = event.scenePos()
        if not view.sceneBoundingRect().contains(scene_pos):
            return  # on an axis or the margin, not on the plate
        event.accept()
        point: QPointF = view.mapSceneToView(scene_pos)
        if self.picking is not None:
            self._pick(point)  # choosing a reference hole moves nothing
            return
        if self.point_picker is not None:
            self.point_picker(point.x(), point.y())  # picking where to start moves nothing
            return
        self.request_move(point.x(), point.y())

    def _say(self, text: str) -> bool:
        self.last_message = text
        self.message.emit(text)
        return False

    def _progress(self, done: int, _total: int) -> None:
        self.set_done(done)

    def _axis_changed(self, index: int) -> None:
        if index in self.axis_indices:
            self._request("position")

    def _update_enabled(self, *_args: object) -> None:
        refusal = self.click_refusal
        if refusal is not None:
            self.plot_widget.setToolTip(self.tr("Click-to-move is off: {0}").format(refusal))
        elif self.polar is not None:
            self.plot_widget.setToolTip(
                self.tr("Click a point within the tool's reach to move there (after confirming)")
            )
        else:
            self.plot_widget.setToolTip(
                self.tr("Click a point inside the travel to move there (after confirming)")
            )

    # --- throttled drawing ---------------------------------------------------

    def _request(self, what: str) -> None:
        self._dirty.add(what)
        if self._throttle_ms <= 0:
            self._flush()
        elif not self._throttle.isActive():
            self._flush()  # draw at once, then at most once per interval
            self._throttle.start()

    def _flush(self) -> None:
        dirty, self._dirty = self._dirty, set()
        if "done" in dirty:
            self._draw_done()
        if "position" in dirty:
            self._draw_position()
        if dirty and self._throttle_ms > 0 and not self._throttle.isActive():
            self._throttle.start()  # a beat with work: keep the pace for what comes next

    def _draw_done(self) -> None:
        self.string_art.set_done(self.done)
        geometry = self.path_geometry
        if geometry is None:
            for trail in self.done_trails:
                trail.reset()
            self.done_dots.reset()
            return
        for trail, path in zip(self.done_trails, (geometry.travel, geometry.work), strict=True):
            trail.show(path, path.done_count(self.done))  # append-only: no full rebuild
        self.done_trails[1].set_visible(self.done_work_curve.isVisible())
        # Append-only, as the trails: each dot painted once (widgets/jobs/done_dots.py).
        self.done_dots.show(geometry.markers, geometry.markers.done_count(self.done))

    def _draw_position(self) -> None:
        axes = self.model.axes
        values: Sequence[float] = [axes[i].position for i in self.axis_indices]
        x = values[0] if values else 0.0
        y = values[1] if len(values) > 1 else 0.0
        if self.polar is not None:
            x, y = self.polar.project(x, y)  # (A°, X) → where the tool is over the work
        self.position_marker.setData(x=[x], y=[y])


# --- string art ------------------------------------------------------------------------------

NAIL_COLOUR = "#6b4423"
#: The thread's opacity (of 255): low, so that where threads cross the colour deepens.
THREAD_ALPHA = 40
DONE_THREAD_ALPHA = 90


class StringArtPreviewExtras:
    """What a string-art program adds to the preview: nails, thread, the current nail.

    The thread is drawn nail to nail, one segment per connection, with a
    faint pen, each segment blended on its own (pyqtgraph's segmented line
    mode), so density shows as it will on the board; the wound
    part is drawn again in green, drilled nails turn green, and a ring marks
    the nail the running operation serves.  A huge job's thread is drawn
    merged, each chord once in the opacity of its windings
    (:mod:`widgets.jobs.string_art_thread`).  While a string-art program is
    shown, the generic work items (``replaced``: the needle's path, drawn
    in the board plane) are hidden; any other program shows them again.
    """

    def __init__(self, plot: pg.PlotItem, replaced: Sequence[pg.GraphicsObject]) -> None:
        self.plot = plot
        self.replaced = tuple(replaced)
        self.program: StringArtProgram | None = None
        self.thread = self._segments(WORK_COLOUR, THREAD_ALPHA)
        self.done_thread = self._segments(DONE_COLOUR, DONE_THREAD_ALPHA)
        self._done_cleared = False  # the done items are empty and need not be set again
        self._active = False  # a string-art program is shown
        #: A merged thread's bands (see the module of the thread geometry), all and wound.
        self.thread_bands = [
            self._segments(WORK_COLOUR, band_alpha(THREAD_ALPHA, k)) for k in range(len(BAND_EDGES))
        ]
        self.done_bands = [
            self._segments(DONE_COLOUR, band_alpha(DONE_THREAD_ALPHA, k))
            for k in range(len(BAND_EDGES))
        ]
        #: The whole job's bands as one image painted on the loading thread, shown instead
        #: of ``thread_bands`` while the view is at the scale it was painted for.
        self.picture = ThreadPictureItem(self._picture_strayed)
        self.picture.setZValue(self.thread_bands[0].zValue())
        plot.addItem(self.picture)
        self.nails = pg.ScatterPlotItem(
            size=4, symbol="o", pen=pg.mkPen(NAIL_COLOUR), brush=pg.mkBrush(NAIL_COLOUR)
        )
        self.drilled = pg.ScatterPlotItem(
            size=4, symbol="o", pen=pg.mkPen(DONE_COLOUR), brush=pg.mkBrush(DONE_COLOUR)
        )
        self.current = pg.ScatterPlotItem(
            size=14, symbol="o", pen=pg.mkPen(POSITION_COLOUR, width=2), brush=None
        )
        for item in (self.nails, self.drilled, self.current):
            plot.addItem(item)
        self.current.setZValue(9)
        self.geometry: ThreadGeometry | None = None
        self._wound: WoundCounter | None = None
        #: What the preview says when it draws the thread merged ("" when exact).
        self.merged_note = ""
        self._show_own(False)

    def _segments(self, colour: str, alpha: int) -> pg.PlotCurveItem:
        curve = pg.PlotCurveItem(pen=band_pen(colour, alpha), connect="pairs", skipFiniteCheck=True)
        curve.setSegmentedLineMode("on")
        self.plot.addItem(curve)
        return curve

    def _show_own(self, active: bool) -> None:
        """Hidden while there is no string art: every frame of another job asked each of
        these empty items for its bounds and painted it."""
        for own in (self.thread, self.done_thread, *self.done_bands, self.nails, self.drilled):
            own.setVisible(active)
        self.current.setVisible(active)
        if not active:
            for band in self.thread_bands:
                band.setVisible(False)

    def _show_picture(self, shown: bool) -> None:
        """The painted image of the whole thread, or its bands drawn as lines (none without
        a string-art job)."""
        self.picture.setVisible(shown)
        for band in self.thread_bands:
            band.setVisible(not shown and self._active)

    def _picture_strayed(self) -> None:
        """The view was zoomed or resized: the image's lines would not be one pixel."""
        self._show_picture(False)

    @property
    def thread_segments(self) -> int:
        """Connections wound in the shown job (drawn one by one, or merged into chords)."""
        return self.geometry.connections if self.geometry is not None else 0

    @property
    def board_radius_mm(self) -> float:
        """The shown job's board radius (its edge, 15 mm beyond the nails), 0 without one."""
        return self.program.job.params.radius_cm * 10.0 if self.program is not None else 0.0

    def set_program(
        self,
        program: Program | None,
        thread: ThreadGeometry | None = None,
        picture: ThreadPicture | None = None,
    ) -> None:
        """Show ``program``'s nails and thread when it is a string-art one, else nothing.

        ``thread``: its layout, made on the loading thread (else it is made here);
        ``picture``: its merged chords painted there too (else they are drawn as lines).
        """
        active = self._active = isinstance(program, StringArtProgram)
        for item in self.replaced:
            item.setVisible(not active)
        self._show_own(active)
        self.merged_note = ""
        self.picture.set_picture(picture if active and thread is not None else None)
        self._show_picture(self.picture.picture is not None)
        for band in (*self.thread_bands, *self.done_bands):
            band.setData(_EMPTY, _EMPTY)
        if not isinstance(program, StringArtProgram):
            self.program = None
            self.geometry = None
            self._wound = None
            self.nails.setData(x=_EMPTY, y=_EMPTY)
            self.thread.setData(_EMPTY, _EMPTY)
            return
        self.program = program
        geometry = thread if thread is not None else ThreadGeometry.of(program)
        self.geometry = geometry
        xy = geometry.nail_xy
        self.nails.setData(x=xy[:, 0], y=xy[:, 1])
        if geometry.merged:
            self.thread.setData(_EMPTY, _EMPTY)
            self._wound = WoundCounter(geometry)
            # The bands of the whole job were made with the geometry (the loading thread):
            # counting two million connections here held the GUI thread.
            whole = geometry.whole or geometry.bands(geometry.counts(geometry.connections))
            for band, (x, y) in zip(self.thread_bands, whole, strict=True):
                band.setData(x, y)
            self.merged_note = QCoreApplication.translate(
                "JobPreview",
                "Preview: the {connections} connections are drawn merged, each of the {chords} "
                "different chords once, as dark as its windings make it",
            ).format(connections=f"{geometry.connections:,}", chords=f"{geometry.chords:,}")
        else:
            self._wound = None
            self.thread.setData(*geometry.pairs)

    def set_done(self, done: int) -> None:
        """The first ``done`` operations are done: wound thread, drilled nails, current nail."""
        program = self.program
        geometry = self.geometry
        if program is None or geometry is None:
            # Cleared once, not on every progress step of another kind of job (three
            # items given empty data 5-30 times a second cost a plotter job's window).
            if not self._done_cleared:
                for item in (self.drilled, self.current):
                    item.setData(x=_EMPTY, y=_EMPTY)
                self.done_thread.setData(_EMPTY, _EMPTY)
                self._done_cleared = True
            return
        self._done_cleared = False
        total = len(program.nail_of_op)
        if done >= total:
            segments = geometry.connections
        else:
            segments = max(int(program.entry_of_op[max(done, 0)]) - 1, 0)
        if self._wound is not None:
            # Only the connections wound since the last call are counted (append-only).
            if self._wound.advance(segments):
                for band, (x, y) in zip(
                    self.done_bands, geometry.bands(self._wound.counts), strict=True
                ):
                    band.setData(x, y)
        else:
            x, y = geometry.pairs
            self.done_thread.setData(x[: 2 * segments], y[: 2 * segments])
        nail_xy = geometry.nail_xy
        drilled = int(np.searchsorted(geometry.drill_ends, done, side="left"))
        self.drilled.setData(x=nail_xy[:drilled, 0], y=nail_xy[:drilled, 1])
        nail = program.current_nail(done) if done > 0 else -1
        if nail < 0:
            self.current.setData(x=_EMPTY, y=_EMPTY)
        else:
            self.current.setData(x=[nail_xy[nail, 0]], y=[nail_xy[nail, 1]])
