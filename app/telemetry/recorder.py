"""Telemetry recording: what the plots draw and what "Export CSV" writes.

The recorder keeps, per series, time-stamped samples of each axis's position
and velocity and of one chosen subscriber variable (rotation, battery
voltage…), taken from the machine model's change signals against the
station's clock.  It holds no widgets, so the same numbers feed the plots,
the CSV export and the tests, and a test drives it on the emulator's clock.

It is the views' side: what is shown (the window, the pause, the chosen
variable) and how it reads.  The samples come in through
:class:`~app.telemetry.sampling.TelemetrySampler` (sample and hold, the
velocity estimate, the rotation unwrapped); the series and their buffers are
:mod:`app.telemetry.series`; ``updated`` is paced by
:class:`~app.telemetry.pacing.UpdatePacer`.  Decisions worth knowing before
changing it:

* **Pause freezes the view, not the recording.**  Samples keep arriving while
  paused (nothing the device reports is lost); :meth:`TelemetryRecorder.data`
  then answers from a snapshot taken when the pause began, so the frozen
  curves stay put even if the ring buffer drops old samples meanwhile.
* **Bounded memory.**  Each series lives in a ring buffer sized for the
  longest window at the highest rate (10 min at 1 kHz); the oldest samples go
  first.  The buffer stays one contiguous array, so reading a window is a
  zero-copy slice whatever its length.
* **Drawing long windows.**  :meth:`TelemetryRecorder.envelope` gives the
  shown samples as a min/max envelope of about the plot's pixel count,
  reusing the blocks it reduced for the previous frame
  (:class:`~app.telemetry.series.PeakEnvelope`), so a 10-minute window at
  1 kHz costs a view only the samples that are new.  A view that moves by
  whole pixels asks from its left edge (``since``), so the envelope's left end
  stays put between moves and only the right end changes from one frame to the next.
"""

from __future__ import annotations

import csv
from pathlib import Path

import numpy as np
import numpy.typing as npt
from PySide6.QtCore import QObject, Signal

from app.station import Station
from app.telemetry.pacing import DEFAULT_SCROLL_MS, DEFAULT_THROTTLE_MS, UpdatePacer
from app.telemetry.sampling import TelemetrySampler
from app.telemetry.series import (
    MAX_WINDOW_S,
    MIN_WINDOW_S,
    SERIES_CAPACITY,
    VARIABLES_BY_ID,
    FloatArray,
    PeakEnvelope,
    SampleBuffer,
    Series,
    SeriesSet,
    Variable,
)


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
        self._t0 = station.clock.now()
        self._series = SeriesSet(capacity)
        for axis in self.model.axes:
            self._series.add_axis(axis.name, axis.unit)
        self._window_s = MIN_WINDOW_S
        self._paused_at: float | None = None
        self._pacer = UpdatePacer(
            self.updated,
            lambda: self._paused_at is None,
            throttle_ms=throttle_ms,
            scroll_ms=scroll_ms,
            parent=self,
        )
        self._sampler = TelemetrySampler(
            station,
            self._series,
            self.now,
            lambda: self._paused_at is None,
            self._pacer.changed,
            parent=self,
        )
        self._sampler.connect_station()

    # --- what is recorded ----------------------------------------------------

    def series_names(self) -> list[str]:
        """Positions, then velocities, then the variable when one is chosen."""
        return self._series.names()

    def position_names(self) -> list[str]:
        return [p.name for p, _ in self._series.axes]

    def velocity_names(self) -> list[str]:
        return [v.name for _, v in self._series.axes]

    def unit(self, name: str) -> str:
        return self._series.get(name).unit

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
        series = self._series.get(name)
        if series.frozen is not None:
            t, base = series.frozen[0], 0
        else:
            t, base = series.buffer.view()[0], series.buffer.first_index
        first, last = self._shown_slice(t, since)
        return series.revision, base + first, base + last

    @property
    def variable(self) -> Variable | None:
        return self._series.variable

    @property
    def has_variables(self) -> bool:
        """Whether the machine reports subscriber variables at all (the profile says)."""
        return self.station.profile.capabilities.subscribers

    @property
    def variable_name(self) -> str | None:
        variable = self._series.variable
        return variable.name if variable is not None else None

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
        series = self._series.get(name)
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
        series = self._series.get(name)
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
        return self._series.get(name).buffer.view()

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
        series = self._series
        if variable == series.variable:
            self._sampler.apply_to_session()
            return
        series.variable = variable
        self._sampler.variable_changed()
        if variable is None:
            series.variable_series = None
        else:
            series.variable_series = Series(
                variable.name, variable.unit, SampleBuffer(series.capacity)
            )
            if self._paused_at is not None:
                series.variable_series.frozen = (np.empty(0), np.empty(0))
        self._sampler.apply_to_session()
        self.variableChanged.emit(subscriber)
        self._pacer.changed()

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
            for series in self._series.all():
                t, y = series.buffer.view()
                first = int(np.searchsorted(t, keep_from, side="left"))
                series.frozen = (t[first:].copy(), y[first:].copy())
        else:
            self._paused_at = None
            for series in self._series.all():
                series.frozen = None
        self._touch_all()
        self._pacer.emit_now()

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
        self._pacer.emit_now()

    def zero(self) -> None:
        """Make the current rotation read 0°; without a reading yet, the next one."""
        self._sampler.zero()

    def clear(self) -> None:
        """Forget every sample and restart the time base at now."""
        self._t0 = self.station.clock.now()
        if self._paused_at is not None:
            self._paused_at = 0.0
        for series in self._series.all():
            series.buffer.clear()
            if series.frozen is not None:
                series.frozen = (np.empty(0), np.empty(0))
        self._sampler.forget_holds()
        self._touch_all()
        self._pacer.emit_now()

    def extend(self, name: str, t: npt.ArrayLike, y: npt.ArrayLike) -> None:
        """Load samples in bulk (times in this recorder's time base, not going backwards).

        For loading a recording and for benchmarks; live samples come from the model.
        """
        series = self._series.get(name)
        series.buffer.extend(t, y)
        series.revision += 1
        self._pacer.changed()

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

    def _touch_all(self) -> None:
        for series in self._series.all():
            series.revision += 1
