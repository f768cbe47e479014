"""How the stage's echoes change the machine model (docs/protocols.md §1.3 to §1.5).

Kept apart from the session so that the developer pane can fold an injected
echo into the model exactly as a received one, with or without a link.
"""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from app.local_numbers import local_number
from app.machine import MachineModel, ParameterState
from app.machines.stage.parameters import BY_TYPE
from protocol.clock import Clock
from protocol.stage.codec import (
    BLOCKED_STATUSES,
    MOVING_STATUSES,
    AxisStatus,
    DeviceFlag,
    EchoFrame,
    EchoType,
    Subscriber,
)

STATUS_TEXT: dict[int, str] = {
    AxisStatus.IDLE: "idle",
    AxisStatus.ACCELERATING: "accelerating",
    AxisStatus.CONSTANT_SPEED: "constant speed",
    AxisStatus.DECELERATING: "decelerating",
    AxisStatus.TARGET_REACHED: "target reached",
    AxisStatus.STOPPED: "stopped",
    AxisStatus.HOMING: "homing",
    AxisStatus.END_SWITCH: "end switch hit",
    AxisStatus.BLOCKED_BATTERY: "blocked: battery low",
    AxisStatus.BLOCKED_CHARGER: "blocked: charger connected",
    AxisStatus.BLOCKED_USB: "blocked: USB connected",
    AxisStatus.SLEEPING: "sleeping",
    AxisStatus.DRIVER_FAULT: "driver fault",
    AxisStatus.PARAMETER_REJECTED: "parameter rejected",
    AxisStatus.UNKNOWN_COMMAND: "unknown command",
}

#: Telemetry keys and the factor from wire units to displayed units.
SUBSCRIBER_TELEMETRY: dict[int, tuple[str, float]] = {
    Subscriber.BATTERY_VOLTAGE: ("battery_voltage", 0.001),  # V
    Subscriber.BATTERY_CHARGE: ("battery_charge", 1.0),  # %
    Subscriber.CHARGING_CURRENT: ("charging_current", 1.0),  # mA
    Subscriber.BOARD_TEMPERATURE: ("board_temperature", 0.01),  # °C
    Subscriber.ROTATION: ("rotation", 0.01),  # °
    Subscriber.YAW_RATE: ("yaw_rate", 0.01),  # °/s
    Subscriber.DEVICE_FLAGS: ("device_flags", 1.0),
    Subscriber.X_ENCODER: ("x_encoder", 0.001),  # mm
    Subscriber.Y_ENCODER: ("y_encoder", 0.001),  # mm
    Subscriber.FIRMWARE_VERSION: ("firmware_version", 1.0),
    Subscriber.REJECTED_FRAMES: ("rejected_frames", 1.0),
}


class StageEchoes:
    """Folds echoes into the model; remembers pending writes to judge their confirmations."""

    def __init__(self, model: MachineModel, clock: Clock) -> None:
        self.model = model
        self.clock = clock
        self._pending_writes: dict[tuple[int, int], int] = {}
        self._device_sleeping = False
        self._last_position: list[tuple[float, float] | None] = [None] * len(model.axes)

    def expect_write(self, axis: int, parameter: EchoType, value: int) -> None:
        self._pending_writes[(axis, parameter)] = value
        self.model.mark_parameter_pending(axis, parameter, value)

    def forget_writes(self) -> None:
        self._pending_writes.clear()

    def apply(self, echo: EchoFrame) -> None:
        now = self.clock.now()
        block: str | None = None
        sleeping = False
        for axis, packet in enumerate(echo.packets[: len(self.model.axes)]):
            status = packet.status
            if status in BLOCKED_STATUSES or status == AxisStatus.DRIVER_FAULT:
                block = block or STATUS_TEXT[status]
            if status == AxisStatus.SLEEPING:
                sleeping = True
            self._apply_packet(axis, packet.type, status, packet.data, now)
        if echo.subscriber in SUBSCRIBER_TELEMETRY:
            key, scale = SUBSCRIBER_TELEMETRY[echo.subscriber]
            self.model.set_telemetry(key, echo.sdata * scale)
        if echo.subscriber == Subscriber.DEVICE_FLAGS:
            self._device_sleeping = bool(echo.sdata & DeviceFlag.SLEEPING)
        elif sleeping:
            self._device_sleeping = True
        elif block is None:
            # Statuses show "sleeping" unless a block outranks it; with no block the
            # statuses alone tell.
            self._device_sleeping = False
        self.model.set_block(block, sleeping=sleeping or self._device_sleeping)

    def _apply_packet(self, axis: int, type_: int, status: int, data: int, now: float) -> None:
        if status == AxisStatus.UNKNOWN_COMMAND:
            self.model.message.emit(
                QCoreApplication.translate("Session", "Axis {0}: device refused a command").format(
                    self.model.axes[axis].name
                )
            )
        if type_ in BY_TYPE:
            # A parameter answer replaces this echo's position; its status is left for the
            # next position packet so the panel never shows a new state beside an old position.
            self._apply_parameter(axis, EchoType(type_), status, data)
            return
        if status not in (AxisStatus.PARAMETER_REJECTED, AxisStatus.UNKNOWN_COMMAND):
            self.model.update_axis(
                axis,
                status_code=status,
                status_text=STATUS_TEXT.get(status, f"status {status:X}"),
                moving=status in MOVING_STATUSES,
            )
        if type_ == EchoType.POSITION:
            self._apply_position(axis, data / 1000, now)
        elif type_ == EchoType.VELOCITY:
            self.model.update_axis(axis, velocity=data / 1000)

    def _apply_position(self, axis: int, position: float, now: float) -> None:
        previous = self._last_position[axis]
        velocity: float | None = None
        if previous is not None and now > previous[1]:
            velocity = (position - previous[0]) / (now - previous[1])
        self._last_position[axis] = (position, now)
        self.model.update_axis(axis, position=position, velocity=velocity)

    def _apply_parameter(self, axis: int, parameter: EchoType, status: int, value: int) -> None:
        requested = self._pending_writes.pop((axis, parameter), None)
        if requested is None:
            self.model.set_parameter(axis, parameter, value, ParameterState.READ)
            return
        meta = BY_TYPE[parameter]
        if status == AxisStatus.PARAMETER_REJECTED or value != requested:
            self.model.set_parameter(axis, parameter, value, ParameterState.REFUSED)
            shown = local_number(meta.to_shown(value), f".{meta.decimals}f")
            kept = f"{shown} {meta.unit}".rstrip()
            label = QCoreApplication.translate("StageParameter", meta.label)
            self.model.message.emit(
                QCoreApplication.translate(
                    "StageSession", "{0} {1}: refused, the device keeps {2}"
                ).format(self.model.axes[axis].name, label, kept)
            )
        else:
            self.model.set_parameter(axis, parameter, value, ParameterState.CONFIRMED)
