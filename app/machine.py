"""The machine model: the one place widgets read machine state from.

Sessions write into it from decoded replies; widgets connect to its change
signals.  Keeping it dialect-neutral (positions in profile units, status as
text plus a few flags) lets every panel serve every machine family.
"""

from __future__ import annotations

import enum
from dataclasses import dataclass, field

from PySide6.QtCore import QCoreApplication, QObject, Signal

from app.profiles import MachineProfile


class LinkState(enum.Enum):
    DISCONNECTED = "disconnected"
    CONNECTING = "connecting"
    CONNECTED = "connected"
    STALE = "stale"
    LOST = "lost"


class ParameterState(enum.Enum):
    UNKNOWN = "unknown"
    PENDING = "pending"
    READ = "read"
    CONFIRMED = "confirmed"
    REFUSED = "refused"


@dataclass
class ParameterValue:
    value: int | None = None
    state: ParameterState = ParameterState.UNKNOWN
    requested: int | None = None


@dataclass
class AxisState:
    name: str
    unit: str
    #: The machine position: travel limits and every motion check use it.
    position: float = 0.0
    #: The work coordinate offset (GRBL's WCO: machine minus work position); 0 elsewhere.
    offset: float = 0.0
    velocity: float = 0.0
    status_code: int | None = None
    status_text: str = "unknown"
    moving: bool = False
    parameters: dict[int, ParameterValue] = field(default_factory=dict)

    @property
    def work_position(self) -> float:
        """Where the axis is in work coordinates (what a G90 line's words mean on GRBL)."""
        return self.position - self.offset

    def shown(self) -> tuple[float, float, float, int | None, str, bool]:
        """What the axis shows: a change of any of it is an ``axisChanged``."""
        return (
            self.position,
            self.offset,
            self.velocity,
            self.status_code,
            self.status_text,
            self.moving,
        )


class MachineModel(QObject):
    linkStateChanged = Signal(object)  # LinkState
    axisChanged = Signal(int)
    parameterChanged = Signal(int, int)  # axis, parameter type
    telemetryChanged = Signal(str)  # telemetry key
    lockChanged = Signal()
    message = Signal(str)  # one-line news for the status bar

    def __init__(self, profile: MachineProfile, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.profile = profile
        self.axes = [AxisState(a.name, a.unit) for a in profile.axes]
        self.link_state = LinkState.DISCONNECTED
        self.link_detail = ""
        self.telemetry: dict[str, float] = {}
        self.block_reason: str | None = None
        self.sleeping = False
        #: Why the operator may not jog now though the machine may move (a job under way).
        self.jog_lock_reason: str | None = None

    # --- written by sessions -------------------------------------------------

    def set_link_state(self, state: LinkState, detail: str = "") -> None:
        if state == self.link_state and detail == self.link_detail:
            return
        self.link_state = state
        self.link_detail = detail
        self.linkStateChanged.emit(state)
        self.lockChanged.emit()

    def update_axis(
        self,
        index: int,
        *,
        position: float | None = None,
        velocity: float | None = None,
        status_code: int | None = None,
        status_text: str | None = None,
        moving: bool | None = None,
        offset: float | None = None,
    ) -> None:
        axis = self.axes[index]
        before = axis.shown()
        if position is not None:
            axis.position = position
        if offset is not None:
            axis.offset = offset
        if velocity is not None:
            axis.velocity = velocity
        if status_code is not None:
            axis.status_code = status_code
        if status_text is not None:
            axis.status_text = status_text
        if moving is not None:
            axis.moving = moving
        if before != axis.shown():
            self.axisChanged.emit(index)

    def set_parameter(
        self, axis: int, parameter: int, value: int | None, state: ParameterState
    ) -> None:
        entry = self.axes[axis].parameters.setdefault(parameter, ParameterValue())
        entry.value = value if value is not None else entry.value
        entry.state = state
        self.parameterChanged.emit(axis, parameter)

    def mark_parameter_pending(self, axis: int, parameter: int, requested: int) -> None:
        entry = self.axes[axis].parameters.setdefault(parameter, ParameterValue())
        entry.requested = requested
        entry.state = ParameterState.PENDING
        self.parameterChanged.emit(axis, parameter)

    def parameter(self, axis: int, parameter: int) -> ParameterValue:
        return self.axes[axis].parameters.get(parameter, ParameterValue())

    def set_telemetry(self, key: str, value: float) -> None:
        if self.telemetry.get(key) == value:
            return
        self.telemetry[key] = value
        self.telemetryChanged.emit(key)

    def set_block(self, reason: str | None, *, sleeping: bool) -> None:
        if reason == self.block_reason and sleeping == self.sleeping:
            return
        self.block_reason = reason
        self.sleeping = sleeping
        self.lockChanged.emit()

    def set_jog_lock(self, reason: str | None) -> None:
        """A job under way owns the machine: jogs are refused (the job's own moves are not)."""
        if reason != self.jog_lock_reason:
            self.jog_lock_reason = reason
            self.lockChanged.emit()

    # --- read by widgets -----------------------------------------------------

    def motion_lock_reason(self) -> str | None:
        """Why motion controls are disabled right now, or None when they are live.

        In the operator's language (the window shows it); the device's block reason is
        one of the axis statuses, translated as the info panel translates them.
        """
        if self.link_state in (LinkState.DISCONNECTED, LinkState.CONNECTING):
            return QCoreApplication.translate("MachineModel", "not connected")
        if self.link_state is LinkState.LOST:
            return QCoreApplication.translate("MachineModel", "link lost")
        if self.sleeping:
            return QCoreApplication.translate("MachineModel", "sleeping — press Wake")
        if self.block_reason is None:
            return None
        return QCoreApplication.translate("AxisStatus", self.block_reason)

    @property
    def any_moving(self) -> bool:
        return any(a.moving for a in self.axes)
