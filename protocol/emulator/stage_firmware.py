"""Firmware of the battery XY stage, emulated (docs/protocols.md §1).

It is the device side of the ``stage`` dialect written from the contract alone,
so the station can be developed and tested against it with no board attached,
and so a test can provoke every state the real board can show: blocked by the
charger, USB or a flat battery, asleep, a driver fault, a FRAM that fails
read-back, an end switch.

Time only moves in :meth:`StageFirmware.run_until`, in whole control cycles,
like the real firmware's main loop: frames that arrived since the previous
cycle are handled at its start, the axes and the environment advance by one
cycle, and each accepted frame is answered by one echo at its end.  On a
:class:`~protocol.clock.ManualClock` that makes every timing exact.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from protocol.clock import Clock
from protocol.emulator.cycles import ControlCycles
from protocol.emulator.fram import Fram
from protocol.emulator.stage_commands import (
    UNKNOWN,
    AxisControl,
    Handler,
    Reply,
    StageCommands,
)
from protocol.mechanism import Axis, AxisLimits, AxisState, SwitchName
from protocol.stage.codec import (
    DATA_MAX,
    DATA_MIN,
    AxisStatus,
    CommandFrame,
    CommandId,
    CommandPacket,
    DeviceFlag,
    EchoFrame,
    EchoPacket,
    EchoType,
    StageDecoder,
    Subscriber,
    encode_echo,
    written_parameter,
)
from protocol.stage.driver import STEP_CLOCK_HZ
from protocol.stage.led import LedRing, led_ring

#: Table 1.4 defaults of the XY stage.
XY_STAGE_PARAMETERS: Mapping[EchoType, int] = MappingProxyType(
    {
        EchoType.FAST_SPEED: 10_000,
        EchoType.SLOW_SPEED: 2_000,
        EchoType.ACCELERATION: 20_000,
        EchoType.START_SPEED: 500,
        EchoType.IRUN: 16,
        EchoType.IHOLD: 8,
        EchoType.MICROSTEPS: 16,
        EchoType.LEAD: 1_000,
        EchoType.STEPS_PER_REV: 200,
        EchoType.TRAVEL: 50_000,
    }
)

#: Table 1.4 ranges; microsteps are further restricted to powers of two.
PARAMETER_RANGES: Mapping[EchoType, tuple[int, int]] = MappingProxyType(
    {
        EchoType.FAST_SPEED: (1, 999_999),
        EchoType.SLOW_SPEED: (1, 999_999),
        EchoType.ACCELERATION: (1, 999_999),
        EchoType.START_SPEED: (0, 99_999),
        EchoType.IRUN: (0, 31),
        EchoType.IHOLD: (0, 31),
        EchoType.MICROSTEPS: (1, 256),
        EchoType.LEAD: (1, 99_999),
        EchoType.STEPS_PER_REV: (1, 9_999),
        EchoType.TRAVEL: (1, 999_999),
    }
)

#: Commands kept for inspection: enough for a test or the developer pane, bounded
#: so that an emulator left running for days does not grow.
COMMAND_LOG_LENGTH = 1000
#: Tolerance for comparing cycle times built from float sums.
_EPS = 1e-9


def parameter_in_range(parameter: EchoType, value: int) -> bool:
    """Whether the device accepts ``value`` for ``parameter`` (table 1.4)."""
    low, high = PARAMETER_RANGES[parameter]
    if not low <= value <= high:
        return False
    return parameter != EchoType.MICROSTEPS or value & (value - 1) == 0


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


@dataclass(frozen=True, slots=True)
class ExecutedCommand:
    """One command packet the firmware handled (NOPs are not recorded)."""

    time: float
    axis: int
    command: int
    data: int
    accepted: bool


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
        self.yaw_deg = _wrap_degrees(self.yaw_deg + self.rate_dps * dt)


def _wrap_degrees(angle: float) -> float:
    """Into [-180, 180), the range the IMU reports."""
    return (angle + 180.0) % 360.0 - 180.0


def _fit(value: float) -> int:
    """Round and saturate into what six DATA characters can carry."""
    return max(DATA_MIN, min(DATA_MAX, round(value)))


#: The LED ring's states (the original's table 7-4); shared with the station.
Led = LedRing


@dataclass(frozen=True, slots=True)
class _PendingEcho:
    subscriber: int
    replies: tuple[Reply, ...]


@dataclass(frozen=True)
class StageSnapshot:
    """The firmware's state at one instant, read under its lock in one go (any thread):
    a view that reads several of these sees them as of the same cycle."""

    powered: bool
    sleeping: bool
    led: Led
    #: False while blocked, asleep or off (a faulted driver disables only its own axis).
    motors_enabled: bool
    session_open: bool
    rejected_frames: int
    #: Per axis: the fast speed selected, and a driver fault.
    fast: tuple[bool, ...]
    driver_faults: tuple[bool, ...]
    charger_connected: bool
    usb_connected: bool
    battery_charge: float
    board_temperature_c: float
    rotation_rate_dps: float
    yaw_deg: float
    verification_fault: bool


class StageFirmware(ControlCycles):
    """The stage's control loop over emulated axes, FRAM, battery and IMU.

    Thread-safe: the loopback's ticker thread runs cycles while the GUI thread
    flips the environment controls, so every public method and property takes
    the same re-entrant lock.
    """

    def __init__(self, clock: Clock, config: StageConfig | None = None) -> None:
        self.config = config if config is not None else StageConfig()
        super().__init__(clock, self.config.control_cycle)
        self._decoder = StageDecoder(self.config.axes)
        self._queue: deque[CommandFrame] = deque()
        self._host_echoes = 0
        self._last_frame: float | None = None
        self._sleeping = False
        self._powered = True
        self._usb_connected = False
        self._battery = Battery(self.config)
        self._imu = Imu()
        self._board_temperature_c = self.config.board_temperature_c
        self.fram = Fram(self.config.axes)
        self._controls = [AxisControl() for _ in range(self.config.axes)]
        self._store_defaults()
        self._axes = tuple(self._make_axis(i) for i in range(self.config.axes))
        self._power_on()
        self._command_log: deque[ExecutedCommand] = deque(maxlen=COMMAND_LOG_LENGTH)
        commands = StageCommands(
            self._axes,
            self._controls,
            self.fram,
            self.config.step_clock_hz,
            self._may_move,
            self._set_sleeping,
        )
        self._handlers: dict[int, Handler] = {
            CommandId.NOP: commands.nop,
            CommandId.STOP: commands.stop,
            CommandId.JOG: commands.jog,
            CommandId.MOVE_ABS: commands.move_abs,
            CommandId.MOVE_REL: commands.move_rel,
            CommandId.HOME: commands.home,
            CommandId.SET_POS: commands.set_pos,
            CommandId.SPEED: commands.speed,
            CommandId.ESTOP: commands.estop,
            CommandId.SLEEP: commands.sleep,
            CommandId.READ: self._read,
        }

    # -- EmulatedDevice --------------------------------------------------------

    def receive(self, data: bytes) -> None:
        with self._lock:
            if not self._powered:
                return  # switched off: the radio hears nothing
            for frame in self._decoder.feed(data):
                if isinstance(frame, CommandFrame):
                    self._queue.append(frame)
                elif isinstance(frame, EchoFrame):
                    # A well-formed echo coming *from* the host is still not a command.
                    self._host_echoes += 1

    # -- introspection -----------------------------------------------------------

    @property
    def axes(self) -> tuple[Axis, ...]:
        with self._lock:
            return self._axes

    def snapshot(self) -> StageSnapshot:
        """Everything a view or a test reads of the firmware, as of one instant.

        The LED is what the ring shows (FIDELITY S3-33, table 7-4): see
        :func:`led_ring`, the same precedence the station draws from the device flags.
        """
        with self._lock:
            powered = self._powered
            return StageSnapshot(
                powered=powered,
                sleeping=self._sleeping,
                led=led_ring(self._device_flags()) if powered else Led.OFF,
                motors_enabled=self._block_status() is None and not self._sleeping and powered,
                session_open=self._session_open(),
                rejected_frames=self._rejected_frames(),
                fast=tuple(control.fast for control in self._controls),
                driver_faults=tuple(control.driver_fault for control in self._controls),
                charger_connected=self._battery.charger_connected,
                usb_connected=self._usb_connected,
                battery_charge=self._battery.charge,
                board_temperature_c=self._board_temperature_c,
                rotation_rate_dps=self._imu.rate_dps,
                yaw_deg=self._imu.yaw_deg,
                verification_fault=self.fram.verification_fault,
            )

    def press_button(self, held_s: float = 0.1) -> None:
        """The user button (FIDELITY S3-36): on, off, or a reset when held long.

        Off, a press switches on (see :meth:`_power_on`).  On, a short press runs
        the original's shutdown sequence: every axis stops dead, the drivers are
        disabled, the step counts go to FRAM if the board is set to save them
        (the parameters are there already, written as they change), and the
        firmware then cuts its own power through the KillSwitch.  Held for
        ``reset_press_s`` or longer it resets the board: no shutdown sequence,
        nothing saved, the firmware starts again at once as at power-on.
        """
        with self._lock:
            if not self._powered:
                self._powered = True
                self._power_on()
                return
            if held_s >= self.config.reset_press_s:
                self._cut_power()
                self._powered = True
                self._power_on()
                return
            self._cut_power()
            if self.config.save_steps_at_shutdown:
                for index, axis in enumerate(self._axes):
                    self.fram.save_step_count(index, axis.microsteps)

    def kill_switch(self) -> None:
        """The KillSwitch cuts the power outright (FIDELITY S3-36): what the shutdown
        sequence ends with, here without the sequence before it, as when the board
        hangs or the battery is pulled.  Everything stops dead and nothing is saved."""
        with self._lock:
            if self._powered:
                self._cut_power()

    def _cut_power(self) -> None:
        """Power gone: axes stop dead, drivers off; the board hears and answers nothing."""
        for axis in self._axes:
            axis.estop()
        for control in self._controls:
            control.jog_direction = 0
        self._queue.clear()
        self._decoder = StageDecoder(self.config.axes)
        self._last_frame = None
        self._powered = False

    def _power_on(self) -> None:
        """The firmware's start: awake, slow speed, not homed, and every step counter set
        from where the axis is (FIDELITY S3-30: the absolute encoder's reading), or from
        the count the last shutdown saved (S3-31), which keeps the operator's zero."""
        self._sleeping = False
        for index, (axis, control) in enumerate(zip(self._axes, self._controls, strict=True)):
            control.homed = False
            control.fast = False
            saved = self.fram.take_step_count(index)
            if saved is not None and self.config.save_steps_at_shutdown:
                axis.set_position(saved * axis.limits.microstep_um)
            else:
                axis.set_position(axis.physical_um)

    @property
    def command_log(self) -> tuple[ExecutedCommand, ...]:
        """The latest commands handled, oldest first (a snapshot, safe from any thread)."""
        with self._lock:
            return tuple(self._command_log)

    def parameter(self, axis: int, parameter: int) -> int:
        """A parameter as a READ would answer it (encoder included)."""
        with self._lock:
            return self._parameter(axis, parameter)

    # -- environment and fault controls -----------------------------------------

    @property
    def charger_connected(self) -> bool:
        with self._lock:
            return self._battery.charger_connected

    @charger_connected.setter
    def charger_connected(self, connected: bool) -> None:
        with self._lock:
            self._battery.charger_connected = connected
            self._enforce_interlocks()

    @property
    def usb_connected(self) -> bool:
        with self._lock:
            return self._usb_connected

    @usb_connected.setter
    def usb_connected(self, connected: bool) -> None:
        with self._lock:
            self._usb_connected = connected
            self._enforce_interlocks()

    @property
    def battery_charge(self) -> float:
        """State of charge in %."""
        with self._lock:
            return self._battery.charge

    @battery_charge.setter
    def battery_charge(self, percent: float) -> None:
        with self._lock:
            self._battery.charge = min(100.0, max(0.0, percent))
            self._enforce_interlocks()

    @property
    def board_temperature_c(self) -> float:
        with self._lock:
            return self._board_temperature_c

    @board_temperature_c.setter
    def board_temperature_c(self, celsius: float) -> None:
        with self._lock:
            self._board_temperature_c = celsius

    @property
    def rotation_rate_dps(self) -> float:
        with self._lock:
            return self._imu.rate_dps

    @rotation_rate_dps.setter
    def rotation_rate_dps(self, rate: float) -> None:
        with self._lock:
            self._imu.rate_dps = rate

    @property
    def yaw_deg(self) -> float:
        with self._lock:
            return self._imu.yaw_deg

    @yaw_deg.setter
    def yaw_deg(self, angle: float) -> None:
        with self._lock:
            self._imu.yaw_deg = _wrap_degrees(angle)

    @property
    def verification_fault(self) -> bool:
        with self._lock:
            return self.fram.verification_fault

    @verification_fault.setter
    def verification_fault(self, fault: bool) -> None:
        with self._lock:
            self.fram.verification_fault = fault

    def set_driver_fault(self, axis: int, fault: bool) -> None:
        """Over-temperature or stall on one driver: that axis stops dead and shows C."""
        with self._lock:
            self._controls[axis].driver_fault = fault
            self._enforce_interlocks()

    def press_end_switch(self, axis: int, which: SwitchName) -> None:
        """Trip an end switch where the axis is, as a crash or a stuck lever would."""
        with self._lock:
            self._axes[axis].trigger_end_switch(which)

    # -- the control cycle ---------------------------------------------------------

    def _run_cycle(self) -> None:
        now = self._cycle_time(self._cycles)
        dt = self.config.control_cycle
        if not self._powered:
            for axis in self._axes:
                axis.advance(dt)  # standing: the estop left nothing to run
            self._battery.step(dt, 0.0)
            self._cycles += 1
            return
        self._enforce_interlocks()
        pending = [self._handle_frame(frame, now) for frame in self._queue]
        self._queue.clear()
        self._check_jog_watchdogs(now)
        for axis in self._axes:
            axis.advance(dt)
        self._battery.step(dt, self._load_ma())
        self._imu.step(dt)
        self._cycles += 1
        self._enforce_interlocks()
        for echo in pending:
            self._emit(echo)

    def _handle_frame(self, frame: CommandFrame, now: float) -> _PendingEcho:
        self._last_frame = now
        replies = tuple(
            self._handle_packet(index, packet, now) for index, packet in enumerate(frame.packets)
        )
        return _PendingEcho(frame.subscriber, replies)

    def _handle_packet(self, index: int, packet: CommandPacket, now: float) -> Reply:
        parameter = written_parameter(packet.command)
        if parameter is not None:
            reply = self._write(index, parameter, packet.data)
        else:
            handler = self._handlers.get(packet.command)
            reply = UNKNOWN if handler is None else handler(index, packet.data, now)
        if packet.command != CommandId.NOP:
            self._command_log.append(
                ExecutedCommand(now, index, packet.command, packet.data, reply.accepted)
            )
        return reply

    def _check_jog_watchdogs(self, now: float) -> None:
        for axis, control in zip(self._axes, self._controls, strict=True):
            if control.jog_direction and now - control.last_jog >= self.config.jog_watchdog - _EPS:
                control.jog_direction = 0
                axis.stop()

    def _enforce_interlocks(self) -> None:
        """Stop dead every axis whose motor must be disabled (block, sleep, fault)."""
        for index, axis in enumerate(self._axes):
            if not self._may_move(index):
                self._controls[index].jog_direction = 0
                if axis.moving:
                    axis.estop()

    def _emit(self, echo: _PendingEcho) -> None:
        packets = tuple(self._echo_packet(i, reply) for i, reply in enumerate(echo.replies))
        subscriber, sdata = self._subscriber(echo.subscriber)
        frame = encode_echo(EchoFrame(packets, subscriber, sdata))
        self._send_to_host(frame)

    def _echo_packet(self, index: int, reply: Reply) -> EchoPacket:
        status = reply.status if reply.status is not None else self._axis_status(index)
        data = reply.data if reply.data is not None else self._axes[index].position_quantised_um
        return EchoPacket(reply.type, status, _fit(data))

    # -- device state ----------------------------------------------------------------

    def _block_status(self) -> AxisStatus | None:
        if self._battery.charge < self.config.critical_battery_percent:
            return AxisStatus.BLOCKED_BATTERY
        if self._battery.charger_connected:
            return AxisStatus.BLOCKED_CHARGER
        if self._usb_connected:
            return AxisStatus.BLOCKED_USB
        return None

    def _may_move(self, index: int) -> bool:
        return (
            self._block_status() is None
            and not self._sleeping
            and not self._controls[index].driver_fault
        )

    def _axis_status(self, index: int) -> int:
        block = self._block_status()
        if block is not None:
            return block
        if self._sleeping:
            return AxisStatus.SLEEPING
        if self._controls[index].driver_fault:
            return AxisStatus.DRIVER_FAULT
        state = self._axes[index].state
        if self._controls[index].homed and state is AxisState.TARGET_REACHED:
            return AxisStatus.IDLE
        return int(state.value)

    def _rejected_frames(self) -> int:
        return self._decoder.rejected + self._host_echoes

    def _session_open(self) -> bool:
        if self._last_frame is None:
            return False
        return self._cycle_time(self._cycles) - self._last_frame < self.config.session_timeout

    def _load_ma(self) -> float:
        config = self.config
        if self._sleeping:
            return config.sleep_current_ma
        load = config.base_current_ma
        for index, axis in enumerate(self._axes):
            if self._may_move(index):
                load += config.holding_current_ma
                if axis.moving:
                    load += config.moving_current_ma
        return load

    def _device_flags(self) -> DeviceFlag:
        flags = DeviceFlag(0)
        if self._battery.charger_connected:
            flags |= DeviceFlag.CHARGER
        if self._usb_connected:
            flags |= DeviceFlag.USB
        if self._battery.charge < self.config.low_battery_percent:
            flags |= DeviceFlag.LOW_BATTERY
        if self._sleeping:
            flags |= DeviceFlag.SLEEPING
        if self._session_open():
            flags |= DeviceFlag.DATA_SESSION
        return flags

    def _subscriber(self, ss: int) -> tuple[int, int]:
        value = self._subscriber_value(ss)
        if value is None:
            return Subscriber.UNKNOWN, ss
        return ss, _fit(value)

    def _subscriber_value(self, ss: int) -> float | None:
        match ss:
            case Subscriber.NONE:
                return 0
            case Subscriber.BATTERY_VOLTAGE:
                return self._battery.voltage_mv
            case Subscriber.BATTERY_CHARGE:
                return self._battery.charge
            case Subscriber.CHARGING_CURRENT:
                return self._battery.charging_current_ma
            case Subscriber.BOARD_TEMPERATURE:
                return 100.0 * self._board_temperature_c
            case Subscriber.ROTATION:
                return 100.0 * self._imu.yaw_deg
            case Subscriber.YAW_RATE:
                return 100.0 * self._imu.rate_dps
            case Subscriber.DEVICE_FLAGS:
                return int(self._device_flags())
            case Subscriber.X_ENCODER | Subscriber.Y_ENCODER:
                return self._encoder(ss - Subscriber.X_ENCODER)
            case Subscriber.FIRMWARE_VERSION:
                return self.config.firmware_version
            case Subscriber.REJECTED_FRAMES:
                return self._rejected_frames()
        return None

    def _encoder(self, index: int) -> float | None:
        """The physical position, which a lost step would make differ from the counted one."""
        return self._axes[index].position_um if index < len(self._axes) else None

    # -- parameters --------------------------------------------------------------------

    def _store_defaults(self) -> None:
        # A profile names only the parameters in which its board differs from the XY stage.
        defaults = {**XY_STAGE_PARAMETERS, **self.config.parameters}
        for index in range(self.config.axes):
            for parameter, value in defaults.items():
                if not parameter_in_range(parameter, value):
                    raise ValueError(f"default {parameter.name} = {value} is out of range")
                self.fram.write(index, parameter, value)

    def _make_axis(self, index: int) -> Axis:
        limits = self._limits(index)
        positions = self.config.encoder_positions_um
        where = positions[index] if index < len(positions) else 0.0
        if not 0.0 <= where <= limits.travel_um:
            raise ValueError(f"encoder position {where} µm of axis {index} is off its travel")
        return Axis(
            limits,
            acceleration=self.fram.read(index, EchoType.ACCELERATION),
            start_speed=self.fram.read(index, EchoType.START_SPEED),
            position_um=where,
        )

    def _limits(self, index: int) -> AxisLimits:
        read = self.fram.read
        microsteps_per_rev = read(index, EchoType.STEPS_PER_REV) * read(index, EchoType.MICROSTEPS)
        return AxisLimits(
            travel_um=read(index, EchoType.TRAVEL),
            microstep_um=read(index, EchoType.LEAD) / microsteps_per_rev,
        )

    def _parameter(self, index: int, parameter: int) -> int:
        if parameter == EchoType.ENCODER:
            return round(self._axes[index].position_um)
        return self.fram.read(index, parameter)

    def _apply_parameter(self, index: int, parameter: EchoType) -> None:
        """Make a stored parameter take effect on the mechanism (speeds are read per move)."""
        axis = self._axes[index]
        if parameter == EchoType.ACCELERATION:
            axis.acceleration = self.fram.read(index, parameter)
        elif parameter == EchoType.START_SPEED:
            axis.start_speed = self.fram.read(index, parameter)
        elif parameter in (
            EchoType.MICROSTEPS,
            EchoType.LEAD,
            EchoType.STEPS_PER_REV,
            EchoType.TRAVEL,
        ):
            axis.limits = self._limits(index)

    def _write(self, index: int, parameter: EchoType, value: int) -> Reply:
        if parameter_in_range(parameter, value) and self.fram.write(index, parameter, value):
            self._apply_parameter(index, parameter)
            return Reply(type=parameter, data=value)
        kept = self.fram.read(index, parameter)
        return Reply(parameter, AxisStatus.PARAMETER_REJECTED, kept, accepted=False)

    def _read(self, index: int, data: int, now: float) -> Reply:
        if not EchoType.FAST_SPEED <= data <= EchoType.ENCODER:
            return UNKNOWN
        return Reply(type=data, data=self._parameter(index, data))

    def _set_sleeping(self, sleeping: bool) -> None:
        """SLEEP: the motors off (or on again); an axis still moving stops dead."""
        self._sleeping = sleeping
        self._enforce_interlocks()
