"""What the recorder keeps: the variables it can plot, the sample buffers and the series.

Each series lives in a :class:`SampleBuffer`, a ring sized for the longest
window at the highest rate (10 min at 1 kHz) that stays one contiguous array,
so reading a window is a zero-copy slice whatever its length; a long window is
drawn from a :class:`PeakEnvelope` of it.  :class:`SeriesSet` holds them by
name: per axis a position and a velocity, then the chosen variable's.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import numpy.typing as npt

from app.machines.stage.session import SUBSCRIBER_TELEMETRY
from protocol.stage.codec import Subscriber

FloatArray = npt.NDArray[np.float64]

#: Window lengths the operator can choose from, in seconds.
WINDOW_CHOICES_S: tuple[float, ...] = (10.0, 30.0, 60.0, 120.0, 300.0, 600.0, 1800.0)
MIN_WINDOW_S = WINDOW_CHOICES_S[0]
MAX_WINDOW_S = WINDOW_CHOICES_S[-1]
#: The highest sample rate the buffers are sized for (a fast serial link or a benchmark).
MAX_RATE_HZ = 1000.0
SERIES_CAPACITY = int(MAX_WINDOW_S * MAX_RATE_HZ)


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
class Series:
    """One recorded curve: its samples, and what the views know of them."""

    name: str
    unit: str
    buffer: SampleBuffer
    #: Counts the changes a view would draw (see :meth:`TelemetryRecorder.revision`).
    revision: int = 0
    #: While paused: the samples as they were when the pause began.
    frozen: tuple[FloatArray, FloatArray] | None = None
    envelope: PeakEnvelope = field(default_factory=PeakEnvelope)


class SeriesSet:
    """The series by name: each axis's position and velocity, then the chosen variable's.

    Shared by the recorder (which reads them for the views) and its sampler
    (which records into them).
    """

    def __init__(self, capacity: int) -> None:
        self.capacity = capacity
        self.by_name: dict[str, Series] = {}
        #: (position, velocity) per axis, in the model's order.
        self.axes: list[tuple[Series, Series]] = []
        #: The plotted subscriber variable and its series (None: none chosen).
        self.variable: Variable | None = None
        self.variable_series: Series | None = None

    def add_axis(self, name: str, unit: str) -> None:
        self.axes.append(
            (self._add(f"{name} position", unit), self._add(f"{name} velocity", f"{unit}/s"))
        )

    def _add(self, name: str, unit: str) -> Series:
        series = Series(name, unit, SampleBuffer(self.capacity))
        self.by_name[name] = series
        return series

    def names(self) -> list[str]:
        """Positions, then velocities, then the variable when one is chosen."""
        names = [p.name for p, _ in self.axes] + [v.name for _, v in self.axes]
        if self.variable_series is not None:
            names.append(self.variable_series.name)
        return names

    def all(self) -> list[Series]:
        extra = [self.variable_series] if self.variable_series is not None else []
        return [*self.by_name.values(), *extra]

    def get(self, name: str) -> Series:
        series = self.by_name.get(name)
        if series is None and self.variable_series and self.variable_series.name == name:
            series = self.variable_series
        if series is None:
            raise KeyError(f"no series {name!r}; have {self.names()}")
        return series
