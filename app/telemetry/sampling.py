"""The recorder's input: samples taken from the machine model and the session's reports.

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
* **Rotation** is unwrapped (the IMU reports -180…180°; a turn past ±180°
  continues the line instead of jumping by 360°, assuming less than half a
  turn between consecutive samples) and shown relative to the angle at the
  last :meth:`TelemetrySampler.zero`.  Zero shifts the whole recorded series,
  so the curve stays continuous and every shown value reads "angle from the zero".
"""

from __future__ import annotations

import math
from collections.abc import Callable

from PySide6.QtCore import QObject

from app.machine import LinkState
from app.machines.stage.session import StageSession
from app.station import Station
from app.telemetry.series import ROTATION_KEY, Series, SeriesSet
from app.velocity_estimate import VelocityEstimator
from protocol.gcode.codec import StatusReport
from protocol.stage.codec import EchoFrame
from protocol.usb3.codec import Position

#: Frames that report where the axes are (a value unchanged by one is known to hold).
POSITION_REPORTS = (EchoFrame, StatusReport, Position)


class TelemetrySampler(QObject):
    """Records into the recorder's series what the model and the session say, as it comes.

    ``now``: the recorder's time base; ``live``: not paused (a sample recorded
    while paused changes nothing shown); ``changed``: tell the views.
    """

    def __init__(
        self,
        station: Station,
        series: SeriesSet,
        now: Callable[[], float],
        live: Callable[[], bool],
        changed: Callable[[], None],
        parent: QObject | None = None,
    ) -> None:
        super().__init__(parent)
        self.station = station
        self.model = station.model
        self._series = series
        self._now = now
        self._live = live
        self._changed = changed
        self._velocity = [VelocityEstimator() for _ in series.axes]
        # Rotation: the last raw reading and its unwrapped value, and the zero offset.
        self._rotation_raw: float | None = None
        self._rotation_unwrapped = 0.0
        self._rotation_offset = 0.0
        self._zero_pending = False
        # Sample and hold: when the last echo came, and the last one carrying the variable.
        self._echo_t: float | None = None
        self._variable_echo_t: float | None = None

    def connect_station(self) -> None:
        """Start listening (once the recorder has all it needs in place)."""
        self.model.axisChanged.connect(self._on_axis)
        self.model.telemetryChanged.connect(self._on_telemetry)
        self.model.linkStateChanged.connect(self._on_link_state)
        self.station.sessionChanged.connect(self._attach_session)
        self._attach_session()

    # --- what the recorder asks ------------------------------------------------------

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

    def variable_changed(self) -> None:
        """Another variable is plotted: nothing of the last one holds for it."""
        self._variable_echo_t = None
        # Rotation readings stop or start here: the platform may turn any amount unseen.
        self._rotation_raw = None

    def forget_holds(self) -> None:
        """The samples were cleared: no echo is known, no velocity estimated."""
        self._echo_t = self._variable_echo_t = None
        self._reset_velocities()

    def apply_to_session(self) -> None:
        # Only the stage dialect multiplexes subscriber variables; others have none to ask.
        session = self.station.session_as(StageSession)
        if session is not None:
            variable = self._series.variable
            session.set_plotted_subscriber(variable.subscriber if variable else None)

    # --- recording -----------------------------------------------------------

    def _on_axis(self, index: int) -> None:
        axis = self.model.axes[index]
        position, velocity = self._series.axes[index]
        if position.buffer.last_y != axis.position:
            self._sample_axis(index, self._now(), axis.position)
        elif not axis.moving and velocity.buffer.last_y not in (None, 0.0):
            # The session says the axis stopped, without a new position (usb3 and G-code
            # machines report no more until it moves): the slope of what came before
            # would otherwise be the last word.
            now = self._now()
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
        position_series, velocity_series = self._series.axes[index]
        self._record(position_series, t, position)
        self._record(velocity_series, t, self._velocity[index].update(t, position))

    def _on_telemetry(self, key: str) -> None:
        if key == ROTATION_KEY:
            self._track_rotation(self.model.telemetry[key])
        variable = self._series.variable
        series = self._series.variable_series
        if variable is None or key != variable.key or series is None:
            return
        value = self.model.telemetry[key]
        if key == ROTATION_KEY:
            value = self._rotation_unwrapped - self._rotation_offset
        self._record(series, self._now(), value)
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
        variable = self._series.variable
        series = self._series.variable_series
        if variable is not None and variable.key == ROTATION_KEY and series is not None:
            series.buffer.shift(delta)
            if series.frozen is not None:
                t, y = series.frozen
                series.frozen = (t, y + delta)
            series.revision += 1
            self._changed()

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
        now = self._now()
        held = False
        if self._echo_t is not None:
            for index, (position, _velocity) in enumerate(self._series.axes):
                last_t, last_y = position.buffer.last_t, position.buffer.last_y
                if last_t is not None and last_y is not None and last_t < self._echo_t:
                    self._sample_axis(index, self._echo_t, last_y)
                    held = True
        self._echo_t = now
        variable = self._series.variable
        if (
            isinstance(frame, EchoFrame)
            and variable is not None
            and frame.subscriber == variable.subscriber
        ):
            series = self._series.variable_series
            if self._variable_echo_t is not None and series is not None:
                held = self._hold(series, self._variable_echo_t) | held
            self._variable_echo_t = now
        if held:
            self._recorded()

    def _hold(self, series: Series, at: float) -> bool:
        """Record that ``series`` still held its last value at ``at``; True if that was news."""
        last_t = series.buffer.last_t
        last_y = series.buffer.last_y
        if last_t is not None and last_y is not None and last_t < at:
            self._record(series, at, last_y)
            return True
        return False

    def _record(self, series: Series, t: float, y: float) -> None:
        """Store a sample; the caller calls :meth:`_recorded` once for all it stored."""
        series.buffer.append(t, y)
        if self._live():
            series.revision += 1

    def _recorded(self) -> None:
        if self._live():
            self._changed()

    # --- session and link ----------------------------------------------------

    def _attach_session(self) -> None:
        session = self.station.session
        self._echo_t = self._variable_echo_t = None
        self._reset_velocities()
        self._rotation_raw = None
        if session is not None:
            session.frameReceived.connect(self._on_frame)
        self.apply_to_session()

    def _on_link_state(self, state: object) -> None:
        """A link that is down says nothing about what held meanwhile: bridge nothing."""
        if state not in (LinkState.CONNECTED, LinkState.STALE):
            self._echo_t = self._variable_echo_t = None
            self._reset_velocities()
            self._rotation_raw = None

    def _reset_velocities(self) -> None:
        for estimator in self._velocity:
            estimator.reset()
