"""Telemetry recording: what the plots draw and what "Export CSV" writes.

The recorder keeps, per series, time-stamped samples of each axis's position
and velocity and of one chosen subscriber variable (rotation, battery
voltage…), taken from the machine model's change signals against the
station's clock.  It holds no widgets, so the same numbers feed the plots,
the CSV export and the tests, and a test drives it on the emulator's clock.

Decisions worth knowing before changing it:

* **Sample and hold.**  The model only signals *changes*, so a standing axis
  would leave no samples and a line drawn between two changes far apart
  would invent a slope (a velocity "ramping" for minutes before a jog).  When
  the session reports an echo, every series the previous echo left unchanged
  gets a sample at that echo's time with the value it held: each echo then
  yields one sample per series (the variable: per echo that carried it), and
  straight lines between samples are honest.  Fed by the model alone (the
  developer pane's injector, the benchmark), recording is change-driven.
* **Velocity is estimated, not copied.**  The plotted velocity of an axis is
  the least-squares slope of its positions over the last half second
  (:mod:`app.velocity_estimate`), held samples included, so a standing axis
  reads 0.  Sessions divide consecutive position reports by their jittered
  receive times, which put 210 mm/s spikes on a 10 mm/s axis.
* **Pause freezes the view, not the recording.**  Samples keep arriving while
  paused (nothing the device reports is lost); :meth:`data` then answers from
  a snapshot taken when the pause began, so the frozen curves stay put even
  if the ring buffer drops old samples meanwhile.
* **Bounded memory.**  Each series lives in a ring buffer sized for the
  longest window at the highest rate (10 min at 1 kHz); the oldest samples go
  first.  The buffer stays one contiguous array, so reading a window is a
  zero-copy slice whatever its length.
* **Drawing long windows.**  :meth:`TelemetryRecorder.envelope` gives the
  shown samples as a min/max envelope of about the plot's pixel count,
  reusing the blocks it reduced for the previous frame (:class:`PeakEnvelope`),
  so a 10-minute window at 1 kHz costs a view only the samples that are new.
  A view that moves by whole pixels asks from its left edge (``since``), so
  the envelope's left end stays put between moves and only the right end
  changes from one frame to the next.
* **Throttled** ``updated``.  Samples may come at 1 kHz; the screen needs
  ~60 Hz.  ``updated`` fires at once after a quiet spell, then at most once
  per ``throttle_ms`` (60 Hz by default) while samples keep coming (the last change is never
  lost), on a steady beat: each interval counts from when the previous one
  was due, not from when the timer happened to fire, so timer latency does
  not drag 30 Hz down to 29.  ``throttle_ms=0`` emits once per change, for
  tests.  While live, a
  slow ``scroll_ms`` beat also fires it so that the time window keeps moving
  when nothing changes.  Every ``updated`` restarts that beat, so it only
  fills silences: an idle link's echoes and the beat do not each cost a frame.
* **Rotation** is unwrapped (the IMU reports -180…180°; a turn past ±180°
  continues the line instead of jumping by 360°, assuming less than half a
  turn between consecutive samples) and shown relative to the angle at the
  last :meth:`zero`.  Zero shifts the whole recorded series, so the curve
  stays continuous and every shown value reads "angle from the zero".
"""

from __future__ import annotations

import csv
import math
import time
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import numpy.typing as npt
from PySide6.QtCore import QObject, Qt, QTimer, Signal

from app.machine import LinkState
from app.machines.stage.session import SUBSCRIBER_TELEMETRY, StageSession
from app.station import Station
from app.velocity_estimate import VelocityEstimator
from protocol.gcode.codec import StatusReport
from protocol.stage.codec import EchoFrame, Subscriber
from protocol.usb3.codec import Position

FloatArray = npt.NDArray[np.float64]

#: Window lengths the operator can choose from, in seconds.
WINDOW_CHOICES_S: tuple[float, ...] = (10.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1800.0)
MIN_WINDOW_S = WINDOW_CHOICES_S[0]
MAX_WINDOW_S = WINDOW_CHOICES_S[-1]
#: The highest sample rate the buffers are sized for (a fast serial link or a benchmark).
MAX_RATE_HZ = 1000.0
SERIES_CAPACITY = int(MAX_WINDOW_S * MAX_RATE_HZ)

DEFAULT_THROTTLE_MS = 1000 / 60  # redraws per second at most: 60, a display's rate
#: Longer than the stage's 100 ms echo period, so a live link's frames alone move the window.
DEFAULT_SCROLL_MS = 150
#: Frames that report where the axes are (a value unchanged by one is known to hold).
POSITION_REPORTS = (EchoFrame, StatusReport, Position)


@dataclass(frozen=True)
class Variable:
    """A subscriber variable the operator can plot."""

    subscriber: int
    name: str
    unit: str

    @property
    def key(self) -> str:
        """The machine model's telemetry key the session fills for this subscriber."""
        return SUBSCRIBER_TELEMETRY[self.subscriber][0]


#: What the variable selector offers, in its order (none is offered separately).
VARIABLES: tuple[Variable, ...] = (
    Variable(Subscriber.ROTATION, "rotation", "°"),
    Variable(Subscriber.YAW_RATE, "yaw rate", "°/s"),
    Variable(Subscriber.BATTERY_VOLTAGE, "battery voltage", "V"),
    Variable(Subscriber.BATTERY_CHARGE, "battery charge", "%"),
    Variable(Subscriber.CHARGING_CURRENT, "charging current", "mA"),
    Variable(Subscriber.BOARD_TEMPERATURE, "board temperature", "°C"),
    Variable(Subscriber.X_ENCODER, "X encoder", "mm"),
    Variable(Subscriber.Y_ENCODER, "Y encoder", "mm"),
)
VARIABLES_BY_ID: dict[int, Variable] = {v.subscriber: v for v in VARIABLES}
ROTATION_KEY = VARIABLES_BY_ID[Subscriber.ROTATION].key


class SampleBuffer:
    """Time-stamped samples in one contiguous, growable, bounded array pair.

    Appends are amortised O(1): storage grows by doubling up to ``capacity``
    plus a quarter, and once full the live samples are moved back to the
    front (dropping the oldest) only when the spare quarter is used up.
    Views returned by :meth:`view` are valid until the next append.
    """

    def __init__(self, capacity: int = SERIES_CAPACITY, initial: int = 1024) -> None:
        if capacity < 1:
            raise ValueError("capacity must be positive")
        self.capacity = capacity
        self._max_storage = capacity + max(1, capacity // 4)
        size = min(initial, self._max_storage)
        self._t: FloatArray = np.empty(size)
        self._y: FloatArray = np.empty(size)
        self._start = 0
        self._end = 0
        self._base = 0  # how many samples ever held sat before storage index 0
        #: Bumped whenever held values change in place (zero, clear), invalidating caches.
        self.epoch = 0

    def __len__(self) -> int:
        return self._end - self._start

    @property
    def first_index(self) -> int:
        """The running number (since creation) of the oldest held sample."""
        return self._base + self._start

    @property
    def last_t(self) -> float | None:
        return float(self._t[self._end - 1]) if self._end > self._start else None

    @property
    def last_y(self) -> float | None:
        return float(self._y[self._end - 1]) if self._end > self._start else None

    def append(self, t: float, y: float) -> None:
        """Add a sample; a sample at the same time as the last one replaces it."""
        if self._end > self._start and self._t[self._end - 1] == t:
            self._y[self._end - 1] = y
            return
        if self._end == len(self._t):
            self._reserve(1)
        self._t[self._end] = t
        self._y[self._end] = y
        self._end += 1
        if self._end - self._start > self.capacity:
            self._start += 1

    def extend(self, t: npt.ArrayLike, y: npt.ArrayLike) -> None:
        """Add many samples at once (loading, benchmarks); times must not go backwards."""
        ts = np.asarray(t, dtype=np.float64).ravel()
        ys = np.asarray(y, dtype=np.float64).ravel()
        if ts.shape != ys.shape:
            raise ValueError("t and y differ in length")
        if len(ts) > self.capacity:
            ts, ys = ts[-self.capacity :], ys[-self.capacity :]
        n = len(ts)
        if n == 0:
            return
        self._reserve(n)
        self._t[self._end : self._end + n] = ts
        self._y[self._end : self._end + n] = ys
        self._end += n

    def shift(self, delta: float) -> None:
        """Add ``delta`` to every held value (used by the rotation zero)."""
        self._y[self._start : self._end] += delta
        self.epoch += 1

    def clear(self) -> None:
        self._base += self._end
        self._start = self._end = 0
        self.epoch += 1

    def view(self) -> tuple[FloatArray, FloatArray]:
        """All held samples as read-only views, oldest first."""
        t = self._t[self._start : self._end]
        y = self._y[self._start : self._end]
        t.flags.writeable = False
        y.flags.writeable = False
        return t, y

    def _reserve(self, n: int) -> None:
        """Make room for ``n`` more samples at the end, dropping what they push out."""
        self._start = max(self._start, self._end + n - self.capacity)
        if self._end + n <= len(self._t):
            return
        live = self._end - self._start
        needed = live + n
        size = len(self._t)
        if needed > size * 3 // 4 and size < self._max_storage:
            size = min(self._max_storage, max(2 * size, needed + needed // 3))
            t, y = np.empty(size), np.empty(size)
            t[:live] = self._t[self._start : self._end]
            y[:live] = self._y[self._start : self._end]
            self._t, self._y = t, y
        else:
            self._t[:live] = self._t[self._start : self._end]
            self._y[:live] = self._y[self._start : self._end]
        self._base += self._start
        self._start, self._end = 0, live


class PeakEnvelope:
    """A window of samples reduced for drawing: the minimum and maximum of each block.

    A 10-minute window at 1 kHz is 600 000 samples, a plot is ~1000 pixels
    wide: one min/max pair per pixel loses nothing visible and keeps every
    peak.  Blocks are aligned to the samples' running numbers, so those
    computed for one frame are reused by the next and each frame only reduces
    the samples that arrived since (plus the partial blocks at both ends).
    The newest sample is always drawn as is: it may still be replaced.
    """

    def __init__(self) -> None:
        self._key: tuple[int, int] | None = None  # (buffer epoch, block length)
        self._k0 = 0  # first cached block
        self._k1 = 0  # one past the last cached block
        self._bt: FloatArray = np.empty(0)
        self._bmax: FloatArray = np.empty(0)
        self._bmin: FloatArray = np.empty(0)

    def reduce(
        self,
        t: FloatArray,
        y: FloatArray,
        first: int,
        last: int,
        max_points: int,
        *,
        base: int = 0,
        epoch: int = 0,
    ) -> tuple[FloatArray, FloatArray]:
        """``t[first:last]``, ``y[first:last]`` in at most about ``max_points`` points.

        ``base`` is the running number of ``t[0]`` and ``epoch`` changes whenever
        values were altered in place; both only matter for reusing blocks.
        """
        n = last - first
        if n <= max(4, max_points):
            return t[first:last], y[first:last]
        block = self._block_length(n, max_points)
        a0, a1 = base + first, base + last - 1  # the newest sample stays out of blocks
        k0 = -(-a0 // block)
        k1 = a1 // block
        if k1 <= k0:
            return t[first:last], y[first:last]
        key = (epoch, block)
        if key != self._key or k0 < self._k0 or k0 > self._k1:
            self._key = key
            self._k0 = self._k1 = k0
            self._bt, self._bmax, self._bmin = np.empty(0), np.empty(0), np.empty(0)
        if k0 > self._k0:
            drop = k0 - self._k0
            self._bt, self._bmax, self._bmin = self._bt[drop:], self._bmax[drop:], self._bmin[drop:]
            self._k0 = k0
        if k1 > self._k1:
            start, stop = self._k1 * block - base, k1 * block - base
            blocks = y[start:stop].reshape(-1, block)
            self._bt = np.concatenate((self._bt, t[start:stop:block]))
            self._bmax = np.concatenate((self._bmax, blocks.max(axis=1)))
            self._bmin = np.concatenate((self._bmin, blocks.min(axis=1)))
            self._k1 = k1
        nb = k1 - k0
        pairs_t = np.repeat(self._bt[:nb], 2)
        pairs_y = np.empty(2 * nb)
        pairs_y[0::2] = self._bmax[:nb]
        pairs_y[1::2] = self._bmin[:nb]
        pieces_t: list[FloatArray] = []
        pieces_y: list[FloatArray] = []
        head_end = k0 * block - base  # samples before the first whole block
        if head_end > first:
            pieces_t.append(np.array([t[first], t[first]]))
            pieces_y.append(np.array([y[first:head_end].max(), y[first:head_end].min()]))
        pieces_t.append(pairs_t)
        pieces_y.append(pairs_y)
        tail_start = k1 * block - base  # samples after the last whole block, but the newest
        if last - 1 > tail_start:
            pieces_t.append(np.array([t[tail_start], t[tail_start]]))
            pieces_y.append(
                np.array([y[tail_start : last - 1].max(), y[tail_start : last - 1].min()])
            )
        pieces_t.append(t[last - 1 : last])
        pieces_y.append(y[last - 1 : last])
        return np.concatenate(pieces_t), np.concatenate(pieces_y)

    def _block_length(self, n: int, max_points: int) -> int:
        """A power of two giving about ``max_points`` points; kept while it stays near.

        The hysteresis stops a window hovering at a boundary from rebuilding
        every block on every frame.
        """
        if self._key is not None:
            current = self._key[1]
            if max_points / 4 <= 2 * n / current <= 2 * max_points:
                return current
        return 1 << max(0, math.ceil(math.log2(2 * n / max_points)))


@dataclass
class _Series:
    name: str
    unit: str
    buffer: SampleBuffer
    revision: int = 0
    frozen: tuple[FloatArray, FloatArray] | None = None
    envelope: PeakEnvelope = field(default_factory=PeakEnvelope)


class TelemetryRecorder(QObject):
    """Records positions, velocities and one subscriber variable of a station's machine.

    Series names: ``"<axis> position"``, ``"<axis> velocity"`` per axis, then
    the chosen variable's name (e.g. ``"rotation"``).  Times are seconds since
    the recorder started (or was cleared), on the station's clock.
    """

    #: The shown data changed (throttled; see the module docstring).
    updated = Signal()
    #: The plotted variable changed: its subscriber ID, or None.
    variableChanged = Signal(object)

    def __init__(
        self,
        station: Station,
        *,
        throttle_ms: float = DEFAULT_THROTTLE_MS,
        scroll_ms: int = DEFAULT_SCROLL_MS,
        capacity: int = SERIES_CAPACITY,
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self.station = station
        self.model = station.model
        self.throttle_ms = throttle_ms
        self._capacity = capacity
        self._t0 = station.clock.now()
        self._series: dict[str, _Series] = {}
        self._axis_series: list[tuple[_Series, _Series]] = []
        for axis in self.model.axes:
            position = self._add_series(f"{axis.name} position", axis.unit)
            velocity = self._add_series(f"{axis.name} velocity", f"{axis.unit}/s")
            self._axis_series.append((position, velocity))
        self._velocity = [VelocityEstimator() for _ in self._axis_series]
        self._variable: Variable | None = None
        self._variable_series: _Series | None = None
        self._window_s = MIN_WINDOW_S
        self._paused_at: float | None = None
        # Rotation: the last raw reading and its unwrapped value, and the zero offset.
        self._rotation_raw: float | None = None
        self._rotation_unwrapped = 0.0
        self._rotation_offset = 0.0
        self._zero_pending = False
        # Sample and hold: when the last echo came, and the last one carrying the variable.
        self._echo_t: float | None = None
        self._variable_echo_t: float | None = None

        self._throttle = QTimer(self)
        self._throttle.setSingleShot(True)
        self._throttle.setTimerType(Qt.TimerType.PreciseTimer)
        self._throttle.timeout.connect(self._throttle_done)
        self._pending = False
        self._due: float | None = None  # wall time the throttle's current interval ends
        self._scroll = QTimer(self)
        self._scroll.timeout.connect(self._on_scroll)
        if scroll_ms > 0:
            self._scroll.start(scroll_ms)

        self.model.axisChanged.connect(self._on_axis)
        self.model.telemetryChanged.connect(self._on_telemetry)
        self.model.linkStateChanged.connect(self._on_link_state)
        station.sessionChanged.connect(self._attach_session)
        self._attach_session()

    # --- what is recorded ----------------------------------------------------

    def series_names(self) -> list[str]:
        """Positions, then velocities, then the variable when one is chosen."""
        names = [p.name for p, _ in self._axis_series] + [v.name for _, v in self._axis_series]
        if self._variable_series is not None:
            names.append(self._variable_series.name)
        return names

    def position_names(self) -> list[str]:
        return [p.name for p, _ in self._axis_series]

    def velocity_names(self) -> list[str]:
        return [v.name for _, v in self._axis_series]

    def unit(self, name: str) -> str:
        return self._get(name).unit

    def header(self, name: str) -> str:
        """The CSV column title: name and unit, e.g. ``X position (mm)``."""
        unit = self.unit(name)
        return f"{name} ({unit})" if unit else name

    def revision(self, name: str, since: float | None = None) -> tuple[int, int, int]:
        """Differs whenever :meth:`data` (or :meth:`envelope` with ``since``) answers differently.

        A view can skip redrawing a curve whose revision it has drawn: the
        count of changes, and the running numbers of the first and last shown
        samples (the window moving in time changes those).
        """
        series = self._get(name)
        if series.frozen is not None:
            t, base = series.frozen[0], 0
        else:
            t, base = series.buffer.view()[0], series.buffer.first_index
        first, last = self._shown_slice(t, since)
        return series.revision, base + first, base + last

    @property
    def variable(self) -> Variable | None:
        return self._variable

    @property
    def has_variables(self) -> bool:
        """Whether the machine reports subscriber variables at all (the profile says)."""
        return self.station.profile.capabilities.subscribers

    @property
    def variable_name(self) -> str | None:
        return self._variable.name if self._variable is not None else None

    # --- reading -------------------------------------------------------------

    def now(self) -> float:
        """The station clock in the recorder's time base (seconds since start)."""
        return self.station.clock.now() - self._t0

    def view_end(self) -> float:
        """Where the shown window ends: now, or the moment the pause began."""
        return self._paused_at if self._paused_at is not None else self.now()

    def view_start(self) -> float:
        return self.view_end() - self._window_s

    def data(self, name: str) -> tuple[FloatArray, FloatArray]:
        """The samples currently shown: inside the window, as of the pause when paused.

        Read-only views into the buffers, valid until the next sample: copy to keep.
        """
        series = self._get(name)
        t, y = series.frozen if series.frozen is not None else series.buffer.view()
        first, last = self._shown_slice(t)
        return t[first:last], y[first:last]

    def envelope(
        self, name: str, max_points: int, since: float | None = None
    ) -> tuple[FloatArray, FloatArray]:
        """The shown samples reduced for drawing to about ``max_points`` points.

        Minimum and maximum per block of samples (see :class:`PeakEnvelope`):
        every peak survives, and a frame costs only the samples that are new.
        Windows with fewer samples come back exactly as :meth:`data` gives them.
        ``since`` leaves out the samples before it too: a view whose left edge
        is a little later than the window's start (it moves by whole pixels)
        pins its curves' left end there, so that end stays put between moves.
        """
        series = self._get(name)
        if series.frozen is not None:
            t, y = series.frozen
            first, last = self._shown_slice(t, since)
            return PeakEnvelope().reduce(t, y, first, last, max_points)
        buffer = series.buffer
        t, y = buffer.view()
        first, last = self._shown_slice(t, since)
        return series.envelope.reduce(
            t, y, first, last, max_points, base=buffer.first_index, epoch=buffer.epoch
        )

    def _shown_slice(self, t: FloatArray, since: float | None = None) -> tuple[int, int]:
        end = self.view_end()
        start = end - self._window_s if since is None else max(end - self._window_s, since)
        first = int(np.searchsorted(t, start, side="left"))
        last = int(np.searchsorted(t, end, side="right"))
        return first, last

    def recorded(self, name: str) -> tuple[FloatArray, FloatArray]:
        """Everything held for ``name``, pause or window notwithstanding."""
        return self._get(name).buffer.view()

    def latest(self, name: str) -> float | None:
        """The last shown value of ``name``, or None when nothing is shown."""
        _, y = self.data(name)
        return float(y[-1]) if len(y) else None

    # --- operator choices ----------------------------------------------------

    def set_variable(self, subscriber: int | None) -> None:
        """Plot ``subscriber`` (a key of :data:`VARIABLES_BY_ID`) or nothing.

        The session is asked to carry it in every frame the info panel does not
        need; a new variable starts an empty series (units differ).
        """
        variable = VARIABLES_BY_ID[subscriber] if subscriber is not None else None
        if variable == self._variable:
            self._apply_to_session()
            return
        self._variable = variable
        self._variable_echo_t = None
        # Rotation readings stop or start here: the platform may turn any amount unseen.
        self._rotation_raw = None
        if variable is None:
            self._variable_series = None
        else:
            self._variable_series = _Series(
                variable.name, variable.unit, SampleBuffer(self._capacity)
            )
            if self._paused_at is not None:
                self._variable_series.frozen = (np.empty(0), np.empty(0))
        self._apply_to_session()
        self.variableChanged.emit(subscriber)
        self._changed()

    @property
    def paused(self) -> bool:
        return self._paused_at is not None

    def set_paused(self, paused: bool) -> None:
        """Freeze (or release) the shown window; recording goes on either way."""
        if paused == self.paused:
            return
        if paused:
            self._paused_at = self.now()
            keep_from = self._paused_at - MAX_WINDOW_S
            for series in self._all_series():
                t, y = series.buffer.view()
                first = int(np.searchsorted(t, keep_from, side="left"))
                series.frozen = (t[first:].copy(), y[first:].copy())
        else:
            self._paused_at = None
            for series in self._all_series():
                series.frozen = None
        self._touch_all()
        self._emit_now()

    @property
    def window_s(self) -> float:
        return self._window_s

    def set_window_s(self, seconds: float) -> None:
        """Show the last ``seconds`` (10 s … 10 min)."""
        seconds = min(MAX_WINDOW_S, max(MIN_WINDOW_S, float(seconds)))
        if seconds == self._window_s:
            return
        self._window_s = seconds
        self._touch_all()
        self._emit_now()

    @property
    def rotation_offset(self) -> float:
        """The unwrapped raw angle that reads 0° (set by :meth:`zero`)."""
        return self._rotation_offset

    def zero(self) -> None:
        """Make the current rotation read 0°; without a reading yet, the next one."""
        if self._rotation_raw is None:
            self._zero_pending = True
            return
        self._set_offset(self._rotation_unwrapped)

    def clear(self) -> None:
        """Forget every sample and restart the time base at now."""
        self._t0 = self.station.clock.now()
        if self._paused_at is not None:
            self._paused_at = 0.0
        for series in self._all_series():
            series.buffer.clear()
            if series.frozen is not None:
                series.frozen = (np.empty(0), np.empty(0))
        self._echo_t = self._variable_echo_t = None
        self._reset_velocities()
        self._touch_all()
        self._emit_now()

    def extend(self, name: str, t: npt.ArrayLike, y: npt.ArrayLike) -> None:
        """Load samples in bulk (times in this recorder's time base, not going backwards).

        For loading a recording and for benchmarks; live samples come from the model.
        """
        series = self._get(name)
        series.buffer.extend(t, y)
        self._touched(series)

    def export_csv(self, path: str | Path) -> int:
        """Write exactly the shown samples; returns the number of data rows.

        One row per distinct sample time, a column per series with its unit in
        the header; a cell is empty where that series has no sample at that
        time (series are sampled at their own moments).  Values are written
        with full precision so the file reads back to the same numbers.
        """
        names = self.series_names()
        shown = [self.data(name) for name in names]
        times = np.unique(np.concatenate([t for t, _ in shown])) if shown else np.empty(0)
        columns: list[list[str]] = []
        for t, y in shown:
            column = [""] * len(times)
            if np.array_equal(t, times):  # sampled at every moment: no gaps to leave
                column = list(map(repr, y.tolist()))
            else:
                for index, value in zip(
                    np.searchsorted(times, t).tolist(), y.tolist(), strict=True
                ):
                    column[index] = repr(value)
            columns.append(column)
        with open(path, "w", newline="", encoding="utf-8") as handle:
            writer = csv.writer(handle)
            writer.writerow(["time (s)", *(self.header(name) for name in names)])
            writer.writerows(zip(map(repr, times.tolist()), *columns, strict=True))
        return len(times)

    # --- recording -----------------------------------------------------------

    def _on_axis(self, index: int) -> None:
        axis = self.model.axes[index]
        position, velocity = self._axis_series[index]
        if position.buffer.last_y != axis.position:
            self._sample_axis(index, self.now(), axis.position)
        elif not axis.moving and velocity.buffer.last_y not in (None, 0.0):
            # The session says the axis stopped, without a new position (usb3 and G-code
            # machines report no more until it moves): the slope of what came before
            # would otherwise be the last word.
            now = self.now()
            self._velocity[index].update(now, axis.position)
            self._record(position, now, axis.position)
            self._record(velocity, now, 0.0)
        else:
            return  # a status or velocity change only: the plotted values stand
        self._recorded()

    def _sample_axis(self, index: int, t: float, position: float) -> None:
        """Record a position and the velocity estimated from the positions up to it.

        The model's velocity is not plotted: sessions derive it from two
        consecutive reports, whose receive times jitter (see :mod:`app.velocity_estimate`).
        """
        position_series, velocity_series = self._axis_series[index]
        self._record(position_series, t, position)
        self._record(velocity_series, t, self._velocity[index].update(t, position))

    def _on_telemetry(self, key: str) -> None:
        if key == ROTATION_KEY:
            self._track_rotation(self.model.telemetry[key])
        variable = self._variable
        if variable is None or key != variable.key or self._variable_series is None:
            return
        value = self.model.telemetry[key]
        if key == ROTATION_KEY:
            value = self._rotation_unwrapped - self._rotation_offset
        self._record(self._variable_series, self.now(), value)
        self._recorded()

    def _track_rotation(self, raw: float) -> None:
        if self._rotation_raw is None:
            # First reading after a gap: take the turn that reads nearest to the zero.
            turns = math.floor((raw - self._rotation_offset + 180.0) / 360.0)
            self._rotation_unwrapped = raw - 360.0 * turns
        else:
            step = (raw - self._rotation_raw + 180.0) % 360.0 - 180.0
            self._rotation_unwrapped += step
        self._rotation_raw = raw
        if self._zero_pending:
            self._zero_pending = False
            self._set_offset(self._rotation_unwrapped)

    def _set_offset(self, offset: float) -> None:
        delta = self._rotation_offset - offset
        self._rotation_offset = offset
        series = self._variable_series
        if self._variable is not None and self._variable.key == ROTATION_KEY and series is not None:
            series.buffer.shift(delta)
            if series.frozen is not None:
                t, y = series.frozen
                series.frozen = (t, y + delta)
            self._touched(series)

    def _on_frame(self, frame: object, _raw: bytes) -> None:
        """An echo or a position report arrived: values the last one left unchanged are
        known to hold.

        Not the stage's echoes alone: a G-code board's status reports and the usb3
        unit's positions say as much, and without them the curves of a machine at
        rest ended where its last move did (a CoreXY jog seemed to stop drawing early,
        its velocity left at the last estimate instead of 0).
        """
        if not isinstance(frame, POSITION_REPORTS):
            return
        now = self.now()
        held = False
        if self._echo_t is not None:
            for index, (position, _velocity) in enumerate(self._axis_series):
                last_t, last_y = position.buffer.last_t, position.buffer.last_y
                if last_t is not None and last_y is not None and last_t < self._echo_t:
                    self._sample_axis(index, self._echo_t, last_y)
                    held = True
        self._echo_t = now
        variable = self._variable
        if (
            isinstance(frame, EchoFrame)
            and variable is not None
            and frame.subscriber == variable.subscriber
        ):
            if self._variable_echo_t is not None and self._variable_series is not None:
                held = self._hold(self._variable_series, self._variable_echo_t) | held
            self._variable_echo_t = now
        if held:
            self._recorded()

    def _hold(self, series: _Series, at: float) -> bool:
        """Record that ``series`` still held its last value at ``at``; True if that was news."""
        last_t = series.buffer.last_t
        last_y = series.buffer.last_y
        if last_t is not None and last_y is not None and last_t < at:
            self._record(series, at, last_y)
            return True
        return False

    def _record(self, series: _Series, t: float, y: float) -> None:
        """Store a sample; the caller calls :meth:`_recorded` once for all it stored."""
        series.buffer.append(t, y)
        if self._paused_at is None:
            series.revision += 1

    def _recorded(self) -> None:
        if self._paused_at is None:
            self._changed()

    # --- session and link ----------------------------------------------------

    def _attach_session(self) -> None:
        session = self.station.session
        self._echo_t = self._variable_echo_t = None
        self._reset_velocities()
        self._rotation_raw = None
        if session is not None:
            session.frameReceived.connect(self._on_frame)
        self._apply_to_session()

    def _apply_to_session(self) -> None:
        # Only the stage dialect multiplexes subscriber variables; others have none to ask.
        session = self.station.session_as(StageSession)
        if session is not None:
            variable = self._variable
            session.set_plotted_subscriber(variable.subscriber if variable else None)

    def _on_link_state(self, state: object) -> None:
        """A link that is down says nothing about what held meanwhile: bridge nothing."""
        if state not in (LinkState.CONNECTED, LinkState.STALE):
            self._echo_t = self._variable_echo_t = None
            self._reset_velocities()
            self._rotation_raw = None

    # --- change notification -------------------------------------------------

    def _touched(self, series: _Series) -> None:
        series.revision += 1
        self._changed()

    def _touch_all(self) -> None:
        for series in self._all_series():
            series.revision += 1

    def _changed(self) -> None:
        """Emit ``updated`` now, or once when the throttle interval is over."""
        if self.throttle_ms <= 0:
            self._rearm_scroll()
            self.updated.emit()
        elif self._throttle.isActive():
            self._pending = True
        else:
            self._emit_now()

    def _emit_now(self, *, on_beat: bool = False) -> None:
        """Emit, and start the next throttle interval.

        ``on_beat``: the throttle timer fired.  The next interval then counts
        from when this one was due, so the timer's lateness does not pile up;
        after a quiet spell a fresh interval counts from now.
        """
        self._pending = False
        if self.throttle_ms > 0:
            # Wall time, not the station clock: this paces the screen, not the machine.
            interval = self.throttle_ms / 1000
            now = time.perf_counter()
            if on_beat and self._due is not None and now - self._due < interval:
                self._due += interval
            else:
                self._due = now + interval
            self._throttle.start(max(1, math.ceil((self._due - now) * 1000)))
        self._rearm_scroll()
        self.updated.emit()

    def _throttle_done(self) -> None:
        if self._pending:
            self._emit_now(on_beat=True)

    def _rearm_scroll(self) -> None:
        """The beat counts from the last ``updated``: it only fills silences."""
        if self._scroll.isActive():
            self._scroll.start()

    def _on_scroll(self) -> None:
        if self._paused_at is None:
            self._changed()

    # --- helpers -------------------------------------------------------------

    def _reset_velocities(self) -> None:
        for estimator in self._velocity:
            estimator.reset()

    def _add_series(self, name: str, unit: str) -> _Series:
        series = _Series(name, unit, SampleBuffer(self._capacity))
        self._series[name] = series
        return series

    def _all_series(self) -> list[_Series]:
        extra = [self._variable_series] if self._variable_series is not None else []
        return [*self._series.values(), *extra]

    def _get(self, name: str) -> _Series:
        series = self._series.get(name)
        if series is None and self._variable_series and self._variable_series.name == name:
            series = self._variable_series
        if series is None:
            raise KeyError(f"no series {name!r}; have {self.series_names()}")
        return series
