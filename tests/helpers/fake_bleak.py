"""A fake radio at bleak's boundary: scanner, client and the stage's BLE module.

:class:`FakeBleakClient` has the names and signatures of the ``BleakClient``
members the BLE transport uses, so the transport runs unchanged on top of
it.  Behind it sits a :class:`FakePeripheral` — the stage's transparent-UART
bridge — wired to the real stage firmware emulator: written bytes go to
``StageFirmware.receive``, and the firmware's echoes come back as
notifications, cut into pieces the way a BLE link cuts them, delivered on the
client's event loop thread as bleak delivers them.

The test owns the firmware's clock: it advances it and calls ``run_until``
itself, after waiting (bounded) for the bytes it wrote to arrive.
"""

from __future__ import annotations

import asyncio
import threading
from collections.abc import Callable
from typing import Any

from bleak.backends.device import BLEDevice
from bleak.backends.scanner import AdvertisementData
from bleak.exc import BleakCharacteristicNotFoundError, BleakDeviceNotFoundError, BleakError

from protocol.emulator.stage_firmware import StageFirmware
from protocol.transport.ble import MICROCHIP_UART, BleUuids

WAIT_S = 2.0

NotifyCallback = Callable[[Any, bytearray], None]


def wait_until(condition: threading.Condition, predicate: Callable[[], bool]) -> bool:
    """Wait (bounded) until ``predicate`` holds; the condition is notified on every change."""
    with condition:
        return condition.wait_for(predicate, timeout=WAIT_S)


class FakeCharacteristic:
    def __init__(self, uuid: str, max_write_without_response_size: int | None = 20) -> None:
        self.uuid = uuid.lower()
        self.max_write_without_response_size = max_write_without_response_size


class FakeServices:
    def __init__(self, characteristics: list[FakeCharacteristic]) -> None:
        self._characteristics = characteristics

    def get_characteristic(self, specifier: str) -> FakeCharacteristic | None:
        for characteristic in self._characteristics:
            if characteristic.uuid == str(specifier).lower():
                return characteristic
        return None


class FakePeripheral:
    """The stage's BLE module: advertises, takes one client, bridges bytes to the firmware.

    ``notify_size`` is the payload of one notification (20 at the default
    MTU); with ``frames_per_notification`` > 1 the module holds echoes back
    until that many are complete and sends them glued together.
    """

    def __init__(
        self,
        address: str,
        name: str | None = "XY-STAGE-01",
        rssi: int = -60,
        *,
        firmware: StageFirmware | None = None,
        uuids: BleUuids = MICROCHIP_UART,
        advertised_uuids: tuple[str, ...] | None = None,
        has_uart: bool = True,
        max_write: int | None = 20,
        notify_size: int = 20,
        frames_per_notification: int = 1,
        greeting: bytes = b"",
    ) -> None:
        self.address = address
        self.name = name
        self.rssi = rssi
        self.uuids = uuids
        self.advertised_uuids = (
            advertised_uuids if advertised_uuids is not None else (uuids.service.lower(),)
        )
        self.has_uart = has_uart
        self.max_write = max_write
        self.notify_size = notify_size
        self.frames_per_notification = frames_per_notification
        #: Notified the moment the host subscribes, before ``start_notify`` returns.
        self.greeting = greeting
        self.firmware = firmware
        #: Set to make every write fail, as a link dying mid-write does.
        self.write_error: BaseException | None = None
        self.changed = threading.Condition()
        self.chunks: list[bytes] = []  # guarded by changed
        self.write_modes: list[bool | None] = []  # the ``response`` argument of each write
        self.notifications: list[bytes] = []
        self.connections = 0
        self._client: FakeBleakClient | None = None
        self._pending = bytearray()
        if firmware is not None:
            firmware.set_output(self._from_firmware)

    @property
    def client(self) -> FakeBleakClient | None:
        with self.changed:
            return self._client

    def services(self) -> FakeServices:
        if not self.has_uart:
            return FakeServices([FakeCharacteristic("00002a00-0000-1000-8000-00805f9b34fb")])
        return FakeServices(
            [
                FakeCharacteristic(self.uuids.write, self.max_write),
                FakeCharacteristic(self.uuids.notify),
            ]
        )

    def received(self) -> bytes:
        with self.changed:
            return b"".join(self.chunks)

    def wait_received(self, count: int) -> bool:
        """Wait until ``count`` bytes in all have arrived from the host."""
        return wait_until(self.changed, lambda: sum(map(len, self.chunks)) >= count)

    def wait_client(self, connected: bool) -> bool:
        return wait_until(self.changed, lambda: (self._client is not None) == connected)

    def drop(self) -> None:
        """The link breaks (device out of range, powered off): the host hears of it."""
        client = self.client
        assert client is not None, "nothing connected to drop"
        client.lose_link()

    # -- called by the fake client ---------------------------------------------------

    def attach(self, client: FakeBleakClient) -> None:
        with self.changed:
            self._client = client
            self.connections += 1
            self._pending.clear()
            self.changed.notify_all()

    def detach(self, client: FakeBleakClient) -> None:
        with self.changed:
            if self._client is client:
                self._client = None
            self.changed.notify_all()

    def write(self, data: bytes, response: bool | None) -> None:
        if self.write_error is not None:
            raise self.write_error
        with self.changed:
            self.chunks.append(data)
            self.write_modes.append(response)
            self.changed.notify_all()
        if self.firmware is not None:
            self.firmware.receive(data)

    # -- from the firmware (the test's thread, inside run_until) ----------------------

    def _from_firmware(self, data: bytes) -> None:
        with self.changed:
            client = self._client
            self._pending += data
            while self._pending.count(b"\n") >= self.frames_per_notification:
                end = _nth_index(self._pending, b"\n", self.frames_per_notification) + 1
                block = bytes(self._pending[:end])
                del self._pending[:end]
                for start in range(0, len(block), self.notify_size):
                    piece = block[start : start + self.notify_size]
                    self.notifications.append(piece)
                    if client is not None:
                        client.notify(piece)


def _nth_index(buffer: bytearray, needle: bytes, n: int) -> int:
    index = -1
    for _ in range(n):
        index = buffer.index(needle, index + 1)
    return index


class FakeBleakClient:
    """What the transport uses of ``BleakClient``, talking to a :class:`FakePeripheral`."""

    def __init__(
        self,
        radio: FakeRadio,
        address_or_ble_device: BLEDevice | str,
        disconnected_callback: Callable[[FakeBleakClient], None] | None = None,
        services: object = None,
        *,
        timeout: float = 30.0,
        **kwargs: object,
    ) -> None:
        self._radio = radio
        if isinstance(address_or_ble_device, BLEDevice):
            self.address = address_or_ble_device.address
        else:
            self.address = address_or_ble_device
        self.timeout = timeout
        self._disconnected_callback = disconnected_callback
        self._peripheral: FakePeripheral | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._notify: NotifyCallback | None = None
        self._notify_char: FakeCharacteristic | None = None

    @property
    def is_connected(self) -> bool:
        return self._peripheral is not None

    @property
    def services(self) -> FakeServices:
        if self._peripheral is None:
            raise BleakError("Service Discovery has not been performed yet")
        return self._peripheral.services()

    async def connect(self, **kwargs: object) -> None:
        await asyncio.sleep(0)  # a real connect yields to the loop
        self._radio.check_adapter()
        if self._radio.connect_error is not None:
            raise self._radio.connect_error
        if self._radio.hang_connect:
            await asyncio.Event().wait()  # until the transport gives up or is closed
        peripheral = self._radio.peripherals.get(self.address.upper())
        if peripheral is None:
            raise BleakDeviceNotFoundError(self.address, f"Device {self.address} was not found")
        self._loop = asyncio.get_running_loop()
        self._peripheral = peripheral
        peripheral.attach(self)

    async def disconnect(self) -> None:
        await asyncio.sleep(0)
        self._link_down()

    async def start_notify(
        self, char_specifier: str, callback: NotifyCallback, **kwargs: object
    ) -> None:
        if self._peripheral is None:
            raise BleakError("Not connected")
        characteristic = self.services.get_characteristic(char_specifier)
        if characteristic is None:
            raise BleakCharacteristicNotFoundError(char_specifier)
        self._notify_char = characteristic
        self._notify = callback
        if self._peripheral.greeting:
            # BlueZ may hand over a notification while the subscription call is still
            # awaiting its reply: on the loop thread, ahead of whatever follows it.
            self._deliver(bytearray(self._peripheral.greeting))

    async def write_gatt_char(
        self, char_specifier: str, data: bytes, response: bool | None = None
    ) -> None:
        peripheral = self._peripheral
        if peripheral is None:
            raise BleakError("Not connected")
        characteristic = self.services.get_characteristic(char_specifier)
        if characteristic is None or characteristic.uuid != peripheral.uuids.write.lower():
            raise BleakCharacteristicNotFoundError(char_specifier)
        limit = characteristic.max_write_without_response_size or 20
        if not response and len(data) > limit:
            raise BleakError(f"{len(data)} bytes exceed the {limit}-byte write")
        peripheral.write(bytes(data), response)

    # -- the peripheral's side -------------------------------------------------------

    def notify(self, data: bytes) -> None:
        """Deliver a notification on the loop thread, in order, as bleak does."""
        if self._loop is not None and self._notify is not None:
            self._loop.call_soon_threadsafe(self._deliver, bytearray(data))

    def lose_link(self) -> None:
        assert self._loop is not None
        self._loop.call_soon_threadsafe(self._link_down)

    def _deliver(self, data: bytearray) -> None:
        if self._notify is not None and self._peripheral is not None:
            self._notify(self._notify_char, data)

    def _link_down(self) -> None:
        peripheral, self._peripheral = self._peripheral, None
        if peripheral is None:
            return
        self._notify = None
        peripheral.detach(self)
        if self._disconnected_callback is not None:
            self._disconnected_callback(self)


class FakeRadio:
    """The neighbourhood a test controls: which peripherals are around, what fails.

    Pass :meth:`client_factory` and :meth:`scanner` to the transport or to
    ``scan`` in place of ``BleakClient`` and ``bleak_discover``.
    """

    def __init__(self, *peripherals: FakePeripheral) -> None:
        self.peripherals = {p.address.upper(): p for p in peripherals}
        #: Raised by scans and connects alike, as a missing adapter is.
        self.adapter_error: BaseException | None = None
        self.connect_error: BaseException | None = None
        self.hang_connect = False
        self.scans = 0
        self.clients: list[FakeBleakClient] = []

    def check_adapter(self) -> None:
        if self.adapter_error is not None:
            raise self.adapter_error

    def client_factory(
        self,
        address_or_ble_device: BLEDevice | str,
        disconnected_callback: Callable[[FakeBleakClient], None] | None = None,
        services: object = None,
        **kwargs: Any,
    ) -> FakeBleakClient:
        client = FakeBleakClient(
            self, address_or_ble_device, disconnected_callback, services, **kwargs
        )
        self.clients.append(client)
        return client

    async def scanner(self, timeout: float) -> dict[str, tuple[BLEDevice, AdvertisementData]]:
        """Stands in for ``bleak_discover``: every peripheral around, as bleak reports them."""
        await asyncio.sleep(0)
        self.scans += 1
        self.check_adapter()
        return {p.address: _advertisement(p) for p in self.peripherals.values()}


def _advertisement(p: FakePeripheral) -> tuple[BLEDevice, AdvertisementData]:
    """What bleak reports for one device: its OS name may lag; the advertised name is fresh."""
    adv = AdvertisementData(
        local_name=p.name,
        manufacturer_data={},
        service_data={},
        service_uuids=list(p.advertised_uuids),
        tx_power=None,
        rssi=p.rssi,
        platform_data=(),
    )
    return BLEDevice(p.address, p.name, details=None), adv
