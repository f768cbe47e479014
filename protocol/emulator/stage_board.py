"""The stage board around its axes: its config, battery, IMU, power flags and what they
let the motors do (docs/protocols.md §1).

The firmware's control loop (:mod:`protocol.emulator.stage_firmware`) asks
this board, under its lock, whether an axis may move, what status an axis
shows, what load the battery carries, which device flags are up and what a
subscriber's value is; the developer's environment controls change it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field

from protocol.emulator.stage_commands import AxisControl
from protocol.emulator.stage_parameters import XY_STAGE_PARAMETERS
from protocol.mechanism import Axis, AxisState
from protocol.stage.codec import DATA_MAX, DATA_MIN, AxisStatus, DeviceFlag, EchoType, Subscriber
from protocol.stage.driver import STEP_CLOCK_HZ

#: Tolerance for comparing cycle times built from float sums.
EPS = 1e-9


@dataclass(frozen=True)
class StageConfig:
    """What differs between stage boards; the defaults describe the XY stage."""

    axes: int = 2
    #: Power-on parameters of every axis (table 1.4); any left out take the XY-stage value.
    parameters: Mapping[EchoType, int] = field(default_factory=lambda: dict(XY_STAGE_PARAMETERS))
    control_cycle: float = 0.005
    jog_watchdog: float = 0.5
    #: The data-session flag drops after this long without a command frame.
    session_timeout: float = 2.0
    #: 1.2.0, sent as ``010200``.
    firmware_version: int = 10200
    battery_capacity_mah: float = 2000.0
    battery_charge: float = 80.0
    low_battery_percent: float = 15.0
    critical_battery_percent: float = 5.0
    empty_voltage_mv: float = 3300.0
    full_voltage_mv: float = 4200.0
    #: Drawn at all times (MCU, BLE module, IMU) unless asleep.
    base_current_ma: float = 40.0
    sleep_current_ma: float = 5.0
    #: Per axis while its driver is enabled, and extra per axis while it moves.
    holding_current_ma: float = 120.0
    moving_current_ma: float = 350.0
    charging_current_ma: float = 800.0
    #: Above this charge the charger tapers its current linearly down to 0 at 100 %.
    charge_taper_percent: float = 90.0
    board_temperature_c: float = 25.0
    #: The step timer's clock (FIDELITY S3-28): speeds run at what whole PSC/ARR give.
    step_clock_hz: int = STEP_CLOCK_HZ
    #: Where each axis physically is when the board is first switched on, in µm from its
    #: low end switch (the absolute encoder's reading, FIDELITY S3-30); missing axes at 0.
    encoder_positions_um: tuple[float, ...] = ()
    #: The original's option (FIDELITY S3-31): the shutdown sequence saves every axis's
    #: step count to FRAM and power-on restores it instead of the encoder's reading.
    save_steps_at_shutdown: bool = False
    #: Holding the user button this long resets the board instead of switching it off.
    reset_press_s: float = 3.0


class Battery:
    """A coulomb-counting cell: charge in %, voltage linear in charge.

    Crude on purpose; what matters to the station is that the gauge moves the
    right way (down faster while driving, up on the charger) and that the
    critical level can be reached.
    """

    def __init__(self, config: StageConfig) -> None:
        self._config = config
        self.charge = config.battery_charge
        self.charger_connected = False

    @property
    def charging_current_ma(self) -> float:
        config = self._config
        if not self.charger_connected or self.charge >= 100.0:
            return 0.0
        if self.charge <= config.charge_taper_percent:
            return config.charging_current_ma
        span = 100.0 - config.charge_taper_percent
        return config.charging_current_ma * (100.0 - self.charge) / span

    @property
    def voltage_mv(self) -> float:
        config = self._config
        span = config.full_voltage_mv - config.empty_voltage_mv
        return config.empty_voltage_mv + span * self.charge / 100.0

    def step(self, dt: float, load_ma: float) -> None:
        net_mah = (self.charging_current_ma - load_ma) * dt / 3600.0
        percent = self.charge + 100.0 * net_mah / self._config.battery_capacity_mah
        self.charge = min(100.0, max(0.0, percent))


class Imu:
    """Yaw integrated from a rotation rate the developer sets."""

    def __init__(self) -> None:
        self.yaw_deg = 0.0
        self.rate_dps = 0.0

    def step(self, dt: float) -> None:
        self.yaw_deg = wrap_degrees(self.yaw_deg + self.rate_dps * dt)


def wrap_degrees(angle: float) -> float:
    """Into [-180, 180), the range the IMU reports."""
    return (angle + 180.0) % 360.0 - 180.0


def fit_data(value: float) -> int:
    """Round and saturate into what six DATA characters can carry."""
    return max(DATA_MIN, min(DATA_MAX, round(value)))


class StageBoard:
    """What the firmware knows of its board besides the axes' motion (under its lock)."""

    def __init__(self, config: StageConfig) -> None:
        self.config = config
        self.battery = Battery(config)
        self.imu = Imu()
        self.temperature_c = config.board_temperature_c
        self.usb_connected = False
        self.sleeping = False
        self.controls = [AxisControl() for _ in range(config.axes)]
        #: The axes it drives (set once the parameters have made them).
        self.axes: tuple[Axis, ...] = ()

    def block_status(self) -> AxisStatus | None:
        if self.battery.charge < self.config.critical_battery_percent:
            return AxisStatus.BLOCKED_BATTERY
        if self.battery.charger_connected:
            return AxisStatus.BLOCKED_CHARGER
        if self.usb_connected:
            return AxisStatus.BLOCKED_USB
        return None

    def may_move(self, index: int) -> bool:
        return (
            self.block_status() is None
            and not self.sleeping
            and not self.controls[index].driver_fault
        )

    def axis_status(self, index: int) -> int:
        block = self.block_status()
        if block is not None:
            return block
        if self.sleeping:
            return AxisStatus.SLEEPING
        if self.controls[index].driver_fault:
            return AxisStatus.DRIVER_FAULT
        state = self.axes[index].state
        if self.controls[index].homed and state is AxisState.TARGET_REACHED:
            return AxisStatus.IDLE
        return int(state.value)

    def load_ma(self) -> float:
        config = self.config
        if self.sleeping:
            return config.sleep_current_ma
        load = config.base_current_ma
        for index, axis in enumerate(self.axes):
            if self.may_move(index):
                load += config.holding_current_ma
                if axis.moving:
                    load += config.moving_current_ma
        return load

    def device_flags(self, *, session_open: bool) -> DeviceFlag:
        flags = DeviceFlag(0)
        if self.battery.charger_connected:
            flags |= DeviceFlag.CHARGER
        if self.usb_connected:
            flags |= DeviceFlag.USB
        if self.battery.charge < self.config.low_battery_percent:
            flags |= DeviceFlag.LOW_BATTERY
        if self.sleeping:
            flags |= DeviceFlag.SLEEPING
        if session_open:
            flags |= DeviceFlag.DATA_SESSION
        return flags

    def subscriber(self, ss: int, *, session_open: bool, rejected: int) -> tuple[int, int]:
        """The subscriber echoed and its value (an unknown one is echoed as UNKNOWN)."""
        value = self.subscriber_value(ss, session_open=session_open, rejected=rejected)
        if value is None:
            return Subscriber.UNKNOWN, ss
        return ss, fit_data(value)

    def subscriber_value(self, ss: int, *, session_open: bool, rejected: int) -> float | None:
        match ss:
            case Subscriber.NONE:
                return 0
            case Subscriber.BATTERY_VOLTAGE:
                return self.battery.voltage_mv
            case Subscriber.BATTERY_CHARGE:
                return self.battery.charge
            case Subscriber.CHARGING_CURRENT:
                return self.battery.charging_current_ma
            case Subscriber.BOARD_TEMPERATURE:
                return 100.0 * self.temperature_c
            case Subscriber.ROTATION:
                return 100.0 * self.imu.yaw_deg
            case Subscriber.YAW_RATE:
                return 100.0 * self.imu.rate_dps
            case Subscriber.DEVICE_FLAGS:
                return int(self.device_flags(session_open=session_open))
            case Subscriber.X_ENCODER | Subscriber.Y_ENCODER:
                return self.encoder(ss - Subscriber.X_ENCODER)
            case Subscriber.FIRMWARE_VERSION:
                return self.config.firmware_version
            case Subscriber.REJECTED_FRAMES:
                return rejected
        return None

    def encoder(self, index: int) -> float | None:
        """The physical position, which a lost step would make differ from the counted one."""
        return self.axes[index].position_um if index < len(self.axes) else None

    def check_jog_watchdogs(self, now: float) -> None:
        """A jog not renewed within the watchdog's time stops (a lost host stops the stage)."""
        for axis, control in zip(self.axes, self.controls, strict=True):
            if control.jog_direction and now - control.last_jog >= self.config.jog_watchdog - EPS:
                control.jog_direction = 0
                axis.stop()

    def enforce_interlocks(self) -> None:
        """Stop dead every axis whose motor must be disabled (block, sleep, fault)."""
        for index, axis in enumerate(self.axes):
            if not self.may_move(index):
                self.controls[index].jog_direction = 0
                if axis.moving:
                    axis.estop()
