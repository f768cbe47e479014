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
from dataclasses import dataclass

from protocol.clock import Clock
from protocol.emulator.cycles import ControlCycles
from protocol.emulator.fram import Fram
from protocol.emulator.stage_board import StageBoard, wrap_degrees
from protocol.emulator.stage_board import StageConfig as StageConfig
from protocol.emulator.stage_commands import (
    StageCommands,
)
from protocol.emulator.stage_dispatch import COMMAND_LOG_LENGTH as COMMAND_LOG_LENGTH
from protocol.emulator.stage_dispatch import ExecutedCommand as ExecutedCommand
from protocol.emulator.stage_dispatch import StageDispatch
from protocol.emulator.stage_parameters import PARAMETER_RANGES as PARAMETER_RANGES
from protocol.emulator.stage_parameters import XY_STAGE_PARAMETERS as XY_STAGE_PARAMETERS
from protocol.emulator.stage_parameters import StageParameters
from protocol.emulator.stage_parameters import parameter_in_range as parameter_in_range
from protocol.mechanism import Axis, SwitchName
from protocol.stage.codec import (
    CommandFrame,
    EchoFrame,
    StageDecoder,
)
from protocol.stage.led import LedRing, led_ring

#: The LED ring's states (the original's table 7-4); shared with the station.
Led = LedRing


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
        self._powered = True
        #: Battery, IMU, power flags and the axes' controls (stage_board.py).
        self._board = StageBoard(self.config)
        self.fram = Fram(self.config.axes)
        #: The parameters in the FRAM and what each does to its axis (stage_parameters.py).
        self._parameters = StageParameters(self.fram)
        # A profile names only the parameters in which its board differs from the XY stage.
        self._parameters.store_defaults(
            {**XY_STAGE_PARAMETERS, **self.config.parameters}, self.config.axes
        )
        positions = self.config.encoder_positions_um
        self._axes = tuple(
            self._parameters.make_axis(i, positions[i] if i < len(positions) else 0.0)
            for i in range(self.config.axes)
        )
        self._parameters.axes = self._board.axes = self._axes
        self._power_on()
        commands = StageCommands(
            self._axes,
            self._board.controls,
            self.fram,
            self.config.step_clock_hz,
            self._board.may_move,
            self._set_sleeping,
        )
        #: Each command to its handler, and its echo made (stage_dispatch.py).
        self._dispatch = StageDispatch(commands, self._parameters, self._board)

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
                sleeping=self._board.sleeping,
                led=led_ring(self._board.device_flags(session_open=self._session_open()))
                if powered
                else Led.OFF,
                motors_enabled=self._board.block_status() is None
                and not self._board.sleeping
                and powered,
                session_open=self._session_open(),
                rejected_frames=self._rejected_frames(),
                fast=tuple(control.fast for control in self._board.controls),
                driver_faults=tuple(control.driver_fault for control in self._board.controls),
                charger_connected=self._board.battery.charger_connected,
                usb_connected=self._board.usb_connected,
                battery_charge=self._board.battery.charge,
                board_temperature_c=self._board.temperature_c,
                rotation_rate_dps=self._board.imu.rate_dps,
                yaw_deg=self._board.imu.yaw_deg,
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
        for control in self._board.controls:
            control.jog_direction = 0
        self._queue.clear()
        self._decoder = StageDecoder(self.config.axes)
        self._last_frame = None
        self._powered = False

    def _power_on(self) -> None:
        """The firmware's start: awake, slow speed, not homed, and every step counter set
        from where the axis is (FIDELITY S3-30: the absolute encoder's reading), or from
        the count the last shutdown saved (S3-31), which keeps the operator's zero."""
        self._board.sleeping = False
        for index, (axis, control) in enumerate(zip(self._axes, self._board.controls, strict=True)):
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
            return tuple(self._dispatch.log)

    def parameter(self, axis: int, parameter: int) -> int:
        """A parameter as a READ would answer it (encoder included)."""
        with self._lock:
            return self._parameters.value(axis, parameter)

    # -- environment and fault controls -----------------------------------------

    @property
    def charger_connected(self) -> bool:
        with self._lock:
            return self._board.battery.charger_connected

    @charger_connected.setter
    def charger_connected(self, connected: bool) -> None:
        with self._lock:
            self._board.battery.charger_connected = connected
            self._board.enforce_interlocks()

    @property
    def usb_connected(self) -> bool:
        with self._lock:
            return self._board.usb_connected

    @usb_connected.setter
    def usb_connected(self, connected: bool) -> None:
        with self._lock:
            self._board.usb_connected = connected
            self._board.enforce_interlocks()

    @property
    def battery_charge(self) -> float:
        """State of charge in %."""
        with self._lock:
            return self._board.battery.charge

    @battery_charge.setter
    def battery_charge(self, percent: float) -> None:
        with self._lock:
            self._board.battery.charge = min(100.0, max(0.0, percent))
            self._board.enforce_interlocks()

    @property
    def board_temperature_c(self) -> float:
        with self._lock:
            return self._board.temperature_c

    @board_temperature_c.setter
    def board_temperature_c(self, celsius: float) -> None:
        with self._lock:
            self._board.temperature_c = celsius

    @property
    def rotation_rate_dps(self) -> float:
        with self._lock:
            return self._board.imu.rate_dps

    @rotation_rate_dps.setter
    def rotation_rate_dps(self, rate: float) -> None:
        with self._lock:
            self._board.imu.rate_dps = rate

    @property
    def yaw_deg(self) -> float:
        with self._lock:
            return self._board.imu.yaw_deg

    @yaw_deg.setter
    def yaw_deg(self, angle: float) -> None:
        with self._lock:
            self._board.imu.yaw_deg = wrap_degrees(angle)

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
            self._board.controls[axis].driver_fault = fault
            self._board.enforce_interlocks()

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
            self._board.battery.step(dt, 0.0)
            self._cycles += 1
            return
        self._board.enforce_interlocks()
        if self._queue:
            self._last_frame = now
        pending = [self._dispatch.handle(frame, now) for frame in self._queue]
        self._queue.clear()
        self._board.check_jog_watchdogs(now)
        for axis in self._axes:
            axis.advance(dt)
        self._board.battery.step(dt, self._board.load_ma())
        self._board.imu.step(dt)
        self._cycles += 1
        self._board.enforce_interlocks()
        for echo in pending:
            frame = self._dispatch.echo(
                echo, session_open=self._session_open(), rejected=self._rejected_frames()
            )
            self._send_to_host(frame)

    def _rejected_frames(self) -> int:
        return self._decoder.rejected + self._host_echoes

    def _session_open(self) -> bool:
        if self._last_frame is None:
            return False
        return self._cycle_time(self._cycles) - self._last_frame < self.config.session_timeout

    def _set_sleeping(self, sleeping: bool) -> None:
        """SLEEP: the motors off (or on again); an axis still moving stops dead."""
        self._board.sleeping = sleeping
        self._board.enforce_interlocks()
