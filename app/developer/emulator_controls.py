"""The developer pane's knobs on the emulator, and the simulation timer.

Every state the info panel can show (a charger block, an end switch, a
dropped or noisy link) can be provoked on the desk.  The pane reaches the
emulator only through :class:`EmulatorControls`: widgets never import
``protocol.emulator`` or ``protocol.transport``.
"""

from __future__ import annotations

import threading
from dataclasses import dataclass

from PySide6.QtCore import QObject, Signal

from app.machine import LinkState
from app.station import Station
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import Usb3Firmware
from protocol.mechanism import SwitchName as SwitchName  # the pane names its buttons by it
from protocol.transport.loopback import Direction, LoopbackTransport
from protocol.usb3.codec import AxisId

# --- the emulator's knobs and the simulation ------------------------------------------


#: The two end switches of an axis, as :meth:`EmulatorControls.press_end_switch` names them.
END_SWITCHES: tuple[SwitchName, ...] = ("low", "high")


class SimulationRefused(RuntimeError):
    """Simulation cannot start: a real device is connected."""


@dataclass(frozen=True)
class EmulatorState:
    """The emulator's environment as the controls should show it right now."""

    charger: bool
    usb: bool
    battery_percent: float
    temperature_c: float
    rotation_dps: float
    verification_fault: bool
    driver_faults: tuple[bool, ...]


def _flip_one_byte(data: bytes) -> bytes:
    """Corrupt a chunk so it still ends its line: a flipped bit mid-frame breaks the checksum."""
    if not data:
        return data
    index = len(data) // 2
    if data[index] == 0x0A:
        index = 0
    return data[:index] + bytes([data[index] ^ 0x01]) + data[index + 1 :]


class _Corrupter:
    """A loopback manipulator that flips a byte in the next N chunks from the device.

    It runs on the emulator's ticker thread in real time while the GUI thread
    adds to it, so installing and removing it happen under one lock: it is on
    the transport exactly while it has chunks left to spoil, and takes itself
    off after the last so the link is clean again without anyone remembering.
    """

    def __init__(self, transport: LoopbackTransport) -> None:
        self.transport = transport
        self._remaining = 0
        self._lock = threading.Lock()

    @property
    def remaining(self) -> int:
        with self._lock:
            return self._remaining

    def add(self, count: int) -> None:
        with self._lock:
            self._remaining += count
            self.transport.set_manipulator(self)

    def __call__(self, direction: Direction, data: bytes) -> bytes:
        if direction is not Direction.TO_HOST or not data:
            return data
        with self._lock:
            if self._remaining <= 0:
                return data
            self._remaining -= 1
            if self._remaining == 0:
                self.transport.set_manipulator(None)
        return _flip_one_byte(data)


class EmulatorControls(QObject):
    """The built-in emulator's environment and faults, for the developer pane.

    A facade so widgets never import ``protocol.emulator``: it acts on
    ``station.emulator`` while that emulator is the station's link (behind the
    loopback), and is :attr:`available` only then.  Setters are ignored when
    no emulator is attached — the pane disables its controls then.

    The *simulation* ("a timer answering the tool's own commands" in the
    original tool) is the emulator connected as the station's device; so
    :attr:`simulating` equals :attr:`available`.  Starting it while a real
    device is connected is **refused** (:class:`SimulationRefused`) rather than
    silently disconnecting the machine: a developer checkbox must never be
    the thing that cuts a real stage off mid-move.
    """

    #: Emitted with the new availability whenever the emulator appears, goes or is replaced.
    availabilityChanged = Signal(bool)

    def __init__(self, station: Station, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._corrupter: _Corrupter | None = None
        self._seen = self._identity()
        # close_link() announces no session change; the link state going DISCONNECTED does.
        station.sessionChanged.connect(self._check_availability)
        station.model.linkStateChanged.connect(self._check_availability)

    # --- availability and simulation ------------------------------------------------

    @property
    def available(self) -> bool:
        """The emulator is the station's device: connected, or lost and being reconnected.

        Judged by the link state rather than by ``station.link`` alone: an
        orderly close reports DISCONNECTED while the link object still exists.
        """
        station = self._station
        return (
            station.emulator is not None
            and station.loopback is not None
            and station.model.link_state is not LinkState.DISCONNECTED
        )

    @property
    def simulating(self) -> bool:
        return self.available

    @property
    def real_device_connected(self) -> bool:
        return self._station.link is not None and self._station.loopback is None

    def set_simulation(self, on: bool) -> None:
        """On: connect the built-in emulator (if nothing is connected).  Off: close it.

        Raises :class:`SimulationRefused` when turning on with a real device
        connected; turning off never touches a real device's link.
        """
        if on:
            if self.simulating:
                return
            if self.real_device_connected:
                assert self._station.link is not None
                raise SimulationRefused(
                    f"{self._station.link.describe()} is connected: disconnect it first"
                )
            self._station.connect_emulator()
        elif self.simulating:
            self._station.close_link()

    def state(self) -> EmulatorState | None:
        emulator = self._emulator()
        if emulator is None:
            return None
        now = emulator.snapshot()  # one lock: the figures of one control cycle
        return EmulatorState(
            charger=now.charger_connected,
            usb=now.usb_connected,
            battery_percent=now.battery_charge,
            temperature_c=now.board_temperature_c,
            rotation_dps=now.rotation_rate_dps,
            verification_fault=now.verification_fault,
            driver_faults=now.driver_faults,
        )

    # --- environment --------------------------------------------------------------------

    def set_charger(self, connected: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.charger_connected = connected

    def set_usb(self, connected: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.usb_connected = connected

    def set_battery(self, percent: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.battery_charge = percent

    def set_temperature(self, celsius: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.board_temperature_c = celsius

    def set_rotation_rate(self, dps: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.rotation_rate_dps = dps

    def set_joystick(self, axis: int, adc: int) -> None:
        """The usb3 unit's joystick: ADC 0…1023 per axis, 500…524 is the dead zone."""
        emulator = self._station.emulator_as(Usb3Firmware)
        if emulator is not None and self.available:
            emulator.set_joystick(AxisId(axis), max(0, min(1023, int(adc))))

    # --- faults ----------------------------------------------------------------------------

    def press_end_switch(self, axis: int, which: SwitchName) -> None:
        """Close an end switch where the axis is (a crash or a stuck lever); stage or usb3."""
        usb3 = self._station.emulator_as(Usb3Firmware)
        if usb3 is not None and self.available:
            usb3.press_end_switch(AxisId(axis), which)
        elif (emulator := self._emulator()) is not None:
            emulator.press_end_switch(axis, which)

    def set_driver_fault(self, axis: int, fault: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.set_driver_fault(axis, fault)

    def set_verification_fault(self, fault: bool) -> None:
        """FRAM read-back differs: every parameter write is refused until cleared."""
        if (emulator := self._emulator()) is not None:
            emulator.verification_fault = fault

    def drop_link(self) -> None:
        """Cut the emulated cable; the station sees the link lost and reconnects with back-off."""
        loopback = self._station.loopback
        if self.available and loopback is not None:
            loopback.sever("link dropped (developer pane)")

    def corrupt_next(self, count: int) -> None:
        """Flip a byte in each of the next ``count`` frames from the device (adds up)."""
        loopback = self._station.loopback
        if count <= 0 or not self.available or loopback is None:
            return
        if self._corrupter is None or self._corrupter.transport is not loopback:
            self._corrupter = _Corrupter(loopback)
        self._corrupter.add(count)

    @property
    def corruptions_pending(self) -> int:
        """Frames from the device still to be corrupted."""
        corrupter = self._corrupter
        if corrupter is None or corrupter.transport is not self._station.loopback:
            return 0
        return corrupter.remaining

    # --- internals -------------------------------------------------------------------------

    def _emulator(self) -> StageFirmware | None:
        """The emulator to act on, or None: setters are ignored without one."""
        return self._station.emulator_as(StageFirmware) if self.available else None

    def _identity(self) -> tuple[bool, EmulatedDevice | None]:
        available = self.available
        return available, self._station.emulator if available else None

    def _check_availability(self, *_args: object) -> None:
        seen = self._identity()
        if seen[0] == self._seen[0] and seen[1] is self._seen[1]:
            return
        self._seen = seen
        self.availabilityChanged.emit(seen[0])
