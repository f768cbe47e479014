"""The BLE transport: the stage's transparent-UART bridge, driven through bleak.

bleak is asyncio-only and ``PySide6.QtAsyncio`` cannot run it, so every BLE
operation runs on one :class:`BleLoop` — an asyncio loop in its own thread —
that transports and scans share.  The GUI thread only ever posts work to that
loop: :meth:`BleTransport.open`, :meth:`~BleTransport.write` and
:meth:`~BleTransport.close` return at once and never wait on a future.

Every attempt started by ``open()`` ends in exactly one ``connection_lost`` —
``None`` after :meth:`BleTransport.close`, an operator-facing one-line message
otherwise (no adapter, nothing found, timeout, link dropped) — after which
``open()`` may be called again with a fresh client: that is how the station
reconnects with back-off.  Listener callbacks come from the loop thread,
except the ``connection_lost(None)`` of ``close()``, which comes from the
caller; a lock makes sure nothing of a closed attempt reaches the listener
after it.

Notifications are passed through as they come: a frame may arrive split over
several 20-byte notifications or several frames in one, and the stage's
decoder reassembles them on ``\\n``.
"""

from __future__ import annotations

import asyncio
import concurrent.futures
import logging
import threading
from collections.abc import Awaitable, Callable, Coroutine, Mapping
from dataclasses import dataclass
from typing import Any, TypeVar

from bleak import BleakClient, BleakScanner
from bleak.backends.device import BLEDevice
from bleak.backends.scanner import AdvertisementData
from bleak.exc import (
    BleakBluetoothNotAvailableError,
    BleakBluetoothNotAvailableReason,
    BleakCharacteristicNotFoundError,
    BleakDBusError,
    BleakDeviceNotFoundError,
    BleakError,
)

from protocol.transport.base import Transport

__all__ = [
    "DEFAULT_NAME_PREFIX",
    "LOOP_STOPPED_MESSAGE",
    "MICROCHIP_UART",
    "NORDIC_UART",
    "NO_ADAPTER_MESSAGE",
    "BleDevice",
    "BleLinkError",
    "BleLoop",
    "BleTransport",
    "BleUuids",
    "Scanner",
    "bleak_discover",
    "describe_ble_error",
    "scan",
]

_log = logging.getLogger(__name__)
_T = TypeVar("_T")

#: The advertised-name prefix of the XY stage (docs/protocols.md §1.7).
DEFAULT_NAME_PREFIX = "XY-STAGE"
#: Every BLE link carries at least 20 bytes per write (MTU 23 minus 3 bytes of header).
FALLBACK_WRITE_SIZE = 20
DEFAULT_SCAN_TIMEOUT_S = 5.0
#: Shorter than bleak's 30 s: the station retries with back-off anyway.
DEFAULT_CONNECT_TIMEOUT_S = 10.0
#: A disconnect that hangs (adapter gone) must not hold up closing.
DISCONNECT_TIMEOUT_S = 2.0
#: Longer than a disconnect may take, so a loop stopping after a close finishes it.
LOOP_JOIN_TIMEOUT_S = DISCONNECT_TIMEOUT_S + 1.0

LOOP_STOPPED_MESSAGE = "Bluetooth stopped (the BLE loop was shut down)"
NO_ADAPTER_MESSAGE = (
    "No Bluetooth adapter found (on Linux: is bluetoothd running and the adapter powered? "
    "`bluetoothctl power on`)"
)
#: D-Bus answers that mean BlueZ is not there to ask, or has no usable adapter.
_NO_ADAPTER_DBUS_ERRORS = frozenset(
    {
        "org.freedesktop.DBus.Error.ServiceUnknown",
        "org.freedesktop.DBus.Error.NameHasNoOwner",
        "org.freedesktop.DBus.Error.Spawn.ServiceNotFound",
        "org.bluez.Error.NotReady",
    }
)
_DENIED = frozenset(
    {
        BleakBluetoothNotAvailableReason.DENIED_BY_USER,
        BleakBluetoothNotAvailableReason.DENIED_BY_SYSTEM,
        BleakBluetoothNotAvailableReason.DENIED_BY_UNKNOWN,
    }
)


@dataclass(frozen=True)
class BleUuids:
    """Which GATT service the UART bridge lives in, and its two characteristics."""

    service: str
    write: str
    notify: str


MICROCHIP_UART = BleUuids(
    service="49535343-FE7D-4AE5-8FA9-9FAFD205E455",
    write="49535343-8841-43F4-A8D4-ECBE34729BB3",
    notify="49535343-1E4D-4BD9-BA61-23C647249616",
)
NORDIC_UART = BleUuids(
    service="6E400001-B5A3-F393-E0A9-E50E24DCCA9E",
    write="6E400002-B5A3-F393-E0A9-E50E24DCCA9E",
    notify="6E400003-B5A3-F393-E0A9-E50E24DCCA9E",
)


@dataclass(frozen=True)
class BleDevice:
    """A device a scan found, as the connection panel lists it."""

    name: str
    address: str
    rssi: int | None


class BleLinkError(Exception):
    """A BLE failure whose message is already worded for the operator."""


# --- the loop thread -------------------------------------------------------------


class BleLoop:
    """One asyncio event loop in one thread ("ble-loop"), shared by transports and scans.

    The thread starts on the first :meth:`submit` and ends with :meth:`stop`,
    which cancels whatever still runs (a transport's cancellation disconnects
    its client) and joins the thread; a later ``submit`` starts a fresh loop.
    Whoever creates a BleLoop stops it: the app at exit, a test at teardown, a
    :class:`BleTransport` given none in its ``close()``.
    """

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None

    @property
    def running(self) -> bool:
        with self._lock:
            return self._loop is not None

    def submit(self, coro: Coroutine[Any, Any, _T]) -> concurrent.futures.Future[_T]:
        """Run ``coro`` on the loop; cancelling the returned future cancels it there."""
        with self._lock:
            return asyncio.run_coroutine_threadsafe(coro, self._running_loop())

    def call_soon(self, callback: Callable[..., object], *args: object) -> bool:
        """Run ``callback(*args)`` on the loop thread; False (and nothing runs) when stopped."""
        with self._lock:
            if self._loop is None:
                return False
            self._loop.call_soon_threadsafe(callback, *args)
            return True

    def stop(self, timeout: float = LOOP_JOIN_TIMEOUT_S) -> bool:
        """End the loop and join its thread; True when the thread is gone.

        Called from the loop thread itself (a listener closing its transport)
        it can only ask the loop to end: the thread finishes on its own.
        """
        with self._lock:
            loop, thread = self._loop, self._thread
            self._loop = self._thread = None
        if loop is None or thread is None:
            return True
        loop.call_soon_threadsafe(loop.stop)
        if thread is threading.current_thread():
            return False
        thread.join(timeout)
        return not thread.is_alive()

    def _running_loop(self) -> asyncio.AbstractEventLoop:
        if self._loop is None:
            loop = asyncio.new_event_loop()
            thread = threading.Thread(target=_run_loop, args=(loop,), name="ble-loop", daemon=True)
            thread.start()
            self._loop, self._thread = loop, thread
        return self._loop


def _run_loop(loop: asyncio.AbstractEventLoop) -> None:
    """The loop thread: run until stopped, then wind down as ``asyncio.run`` does."""
    asyncio.set_event_loop(loop)
    try:
        loop.run_forever()
        _cancel_remaining_tasks(loop)
        loop.run_until_complete(loop.shutdown_asyncgens())
        loop.run_until_complete(loop.shutdown_default_executor())
    finally:
        asyncio.set_event_loop(None)
        loop.close()


def _cancel_remaining_tasks(loop: asyncio.AbstractEventLoop) -> None:
    # Cancelled tasks may start others while they wind down (a disconnect),
    # so repeat a few rounds rather than leave any pending at close.
    for _ in range(3):
        tasks = asyncio.all_tasks(loop)
        if not tasks:
            return
        for task in tasks:
            task.cancel()
        loop.run_until_complete(asyncio.gather(*tasks, return_exceptions=True))


# --- scanning --------------------------------------------------------------------

#: The scan seam: ``await scanner(timeout)`` returns what
#: ``BleakScanner.discover(timeout=..., return_adv=True)`` does.
Scanner = Callable[[float], Awaitable[Mapping[str, tuple[BLEDevice, AdvertisementData]]]]


async def bleak_discover(timeout: float) -> Mapping[str, tuple[BLEDevice, AdvertisementData]]:
    """Listen for advertisements for ``timeout`` seconds (the real radio)."""
    return await BleakScanner.discover(timeout=timeout, return_adv=True)


@dataclass(frozen=True)
class _Found:
    device: BleDevice
    #: bleak's own device object: connecting with it spares bleak a second scan.
    handle: BLEDevice


async def _discover(
    scanner: Scanner, uuids: BleUuids, name_prefix: str, timeout: float
) -> list[_Found]:
    """Devices advertising the service or named with the prefix, strongest first."""
    seen = await scanner(timeout)
    found = [
        _Found(_device_of(handle, adv), handle)
        for handle, adv in seen.values()
        if _matches(handle, adv, uuids, name_prefix)
    ]
    return sorted(found, key=lambda f: _strength(f.device.rssi), reverse=True)


def _device_of(handle: BLEDevice, adv: AdvertisementData) -> BleDevice:
    return BleDevice(adv.local_name or handle.name or "", handle.address, adv.rssi)


def _matches(handle: BLEDevice, adv: AdvertisementData, uuids: BleUuids, name_prefix: str) -> bool:
    if uuids.service.lower() in (uuid.lower() for uuid in adv.service_uuids):
        return True
    name = adv.local_name or handle.name or ""
    return bool(name_prefix) and name.startswith(name_prefix)


def _strength(rssi: int | None) -> int:
    return rssi if rssi is not None else -1000


def scan(
    loop: BleLoop,
    *,
    uuids: BleUuids,
    name_prefix: str,
    timeout: float = DEFAULT_SCAN_TIMEOUT_S,
    on_done: Callable[[list[BleDevice] | str], None],
    scanner: Scanner = bleak_discover,
) -> concurrent.futures.Future[list[BleDevice] | str]:
    """Find stages on the loop thread; ``on_done`` gets them strongest first, or an error line.

    ``on_done`` is called on the loop thread, so a Qt caller only emits a
    signal from it.  A scan cancelled by stopping the loop calls nothing.
    """
    return loop.submit(_scan_and_report(scanner, uuids, name_prefix, timeout, on_done))


async def _scan_and_report(
    scanner: Scanner,
    uuids: BleUuids,
    name_prefix: str,
    timeout: float,
    on_done: Callable[[list[BleDevice] | str], None],
) -> list[BleDevice] | str:
    result: list[BleDevice] | str
    try:
        result = [f.device for f in await _discover(scanner, uuids, name_prefix, timeout)]
    except Exception as exc:
        result = describe_ble_error(exc, device=_device_label(name_prefix))
    on_done(result)
    return result


# --- operator-facing errors ---------------------------------------------------------


def describe_ble_error(exc: BaseException, *, device: str = DEFAULT_NAME_PREFIX) -> str:
    """One line telling the operator what went wrong, never a traceback.

    bleak reports a missing adapter differently per platform and version (a
    BleakError, a D-Bus error, or the system bus socket not being there at
    all), so all of them collapse into the one message with the fix.
    """
    if isinstance(exc, BleLinkError):
        return _one_line(str(exc))
    if isinstance(exc, BleakBluetoothNotAvailableError):
        if exc.reason in _DENIED:
            return _one_line(f"Bluetooth access was denied: {exc.args[0]}")
        return NO_ADAPTER_MESSAGE
    if isinstance(exc, BleakDBusError):
        if exc.dbus_error in _NO_ADAPTER_DBUS_ERRORS:
            return NO_ADAPTER_MESSAGE
        return _one_line(f"Bluetooth error: {exc}")
    if isinstance(exc, BleakDeviceNotFoundError):
        return _not_found_message(device)
    if isinstance(exc, BleakCharacteristicNotFoundError):
        return f"Device has no transparent-UART characteristic {exc.char_specifier}"
    if isinstance(exc, BleakError):
        if "adapter" in str(exc).lower():
            return NO_ADAPTER_MESSAGE
        return _one_line(f"Bluetooth error: {exc}")
    if isinstance(exc, TimeoutError):
        return "Connecting timed out — is the device in range and not connected to another host?"
    if isinstance(exc, FileNotFoundError | ConnectionRefusedError):
        return NO_ADAPTER_MESSAGE  # no D-Bus system bus socket, or nobody listening on it
    if type(exc).__module__.split(".")[0] in {"dbus_fast", "dbus_next"}:
        return NO_ADAPTER_MESSAGE
    return _one_line(f"Bluetooth error: {type(exc).__name__}: {exc}")


def _not_found_message(device: str) -> str:
    return f"No {device} device found — is it powered and advertising?"


def _missing_service_message(uuids: BleUuids) -> str:
    return f"Device has no transparent-UART service {uuids.service}"


def _device_label(name_prefix: str) -> str:
    return name_prefix or "transparent-UART"


def _one_line(text: str) -> str:
    return " ".join(text.split())


# --- the transport ---------------------------------------------------------------------


class BleTransport(Transport):
    """Bytes over a BLE transparent-UART service, on a :class:`BleLoop`.

    With ``address`` the transport connects straight to it (the last used
    device); without, each ``open()`` scans and takes the strongest match.
    Given no ``loop`` it makes its own and stops it in :meth:`close`; the app
    passes its shared one, which ``close()`` leaves running.
    """

    def __init__(
        self,
        address: str | None,
        uuids: BleUuids,
        *,
        name_prefix: str = "",
        loop: BleLoop | None = None,
        client_factory: Callable[..., Any] = BleakClient,
        scanner: Scanner = bleak_discover,
        scan_timeout: float = DEFAULT_SCAN_TIMEOUT_S,
        connect_timeout: float = DEFAULT_CONNECT_TIMEOUT_S,
    ) -> None:
        super().__init__()
        self.address = address
        self.uuids = uuids
        self.name_prefix = name_prefix
        self._owns_loop = loop is None
        self._loop = loop if loop is not None else BleLoop()
        self._client_factory = client_factory
        self._scanner = scanner
        self._scan_timeout = scan_timeout
        self._connect_timeout = connect_timeout
        #: The device of the last attempt that found or reached one.
        self.device: BleDevice | None = None
        # Guards which attempt is current and every listener call of an attempt.
        self._lock = threading.RLock()
        self._attempt: _Attempt | None = None

    def describe(self) -> str:
        device = self.device
        if device is not None:
            return f"BLE {device.name or device.address}"
        return f"BLE {self.address or self.name_prefix or self.uuids.service}"

    @property
    def is_open(self) -> bool:
        attempt = self._attempt
        return attempt is not None and attempt.connected

    def open(self) -> None:
        with self._lock:
            if self._attempt is not None and not self._attempt.finished:
                return  # already connecting or connected
            attempt = _Attempt(self)
            self._attempt = attempt
            attempt.future = self._loop.submit(attempt.run())
        self._mark_open()

    def close(self) -> None:
        with self._lock:
            attempt, self._attempt = self._attempt, None
            report = attempt is not None and not attempt.finished
            if attempt is not None:
                attempt.finished = True
                attempt.connected = False
        if attempt is not None:
            attempt.cancel()  # its task disconnects the client as it unwinds
        if self._owns_loop:
            self._loop.stop()
        self._mark_closed()
        if report:
            self.listener.connection_lost(None)

    def write(self, data: bytes) -> None:
        attempt = self._attempt
        if attempt is not None and attempt.connected and data:
            self._loop.call_soon(attempt.queue_write, bytes(data))

    # -- called by the current attempt, on the loop thread ------------------------------

    def _found(self, attempt: _Attempt, device: BleDevice) -> None:
        with self._lock:
            if attempt is self._attempt:
                self.device = device

    def _made(self, attempt: _Attempt) -> bool:
        """Report the connection; False if the attempt ended meanwhile (closed, dropped)."""
        with self._lock:
            if attempt is not self._attempt or attempt.finished:
                return False
            attempt.connected = True
            self.listener.connection_made()
            early, attempt.early = attempt.early, []
            for data in early:
                self.listener.data_received(data)
            return True

    def _received(self, attempt: _Attempt, data: bytes) -> None:
        with self._lock:
            if attempt is not self._attempt or attempt.finished:
                return
            if attempt.connected:
                self.listener.data_received(data)
            else:  # notified between start_notify and connection_made
                attempt.early.append(data)

    def _lost(self, attempt: _Attempt, reason: str) -> None:
        with self._lock:
            if attempt.finished:
                return
            attempt.finished = True
            attempt.connected = False
            if attempt is self._attempt:
                self.listener.connection_lost(reason)


class _Attempt:
    """One ``open()``: find the device, connect a fresh client, then carry bytes until it ends.

    Everything but :meth:`cancel` runs on the loop thread.  Its state flags
    are changed only under the transport's lock.
    """

    def __init__(self, transport: BleTransport) -> None:
        self._transport = transport
        self._uuids = transport.uuids
        self._label = _device_label(transport.name_prefix)
        self.connected = False
        self.finished = False
        self.early: list[bytes] = []
        self.future: concurrent.futures.Future[None] | None = None
        self._client: Any = None
        self._write_char: Any = None
        self._writes: asyncio.Queue[bytes | None] = asyncio.Queue()

    def cancel(self) -> None:
        if self.future is not None:
            self.future.cancel()

    def queue_write(self, data: bytes) -> None:
        self._writes.put_nowait(data)

    async def run(self) -> None:
        try:
            await self._connect()
            if self._transport._made(self):
                await self._pump_writes()
        except asyncio.CancelledError:
            # By close() (already reported), or by the loop stopping under us.
            self._transport._lost(self, LOOP_STOPPED_MESSAGE)
            raise
        except Exception as exc:  # every failure becomes one line for the operator
            self._transport._lost(self, describe_ble_error(exc, device=self._label))
        finally:
            await self._disconnect()

    async def _connect(self) -> None:
        target: BLEDevice | str | None = self._transport.address
        if target is None:
            target = await self._find()
        t = self._transport
        self._client = t._client_factory(
            target, disconnected_callback=self._on_disconnected, timeout=t._connect_timeout
        )
        await asyncio.wait_for(self._client.connect(), t._connect_timeout)
        services = self._client.services
        self._write_char = services.get_characteristic(self._uuids.write)
        if self._write_char is None or services.get_characteristic(self._uuids.notify) is None:
            raise BleLinkError(_missing_service_message(self._uuids))
        await self._client.start_notify(self._uuids.notify, self._on_notify)

    async def _find(self) -> BLEDevice:
        t = self._transport
        found = await _discover(t._scanner, self._uuids, t.name_prefix, t._scan_timeout)
        if not found:
            raise BleLinkError(_not_found_message(self._label))
        t._found(self, found[0].device)
        return found[0].handle

    async def _pump_writes(self) -> None:
        """Send queued bytes in order, each in chunks the link takes without a response."""
        while (data := await self._writes.get()) is not None:
            size = self._chunk_size()
            for start in range(0, len(data), size):
                chunk = data[start : start + size]
                await self._client.write_gatt_char(self._uuids.write, chunk, response=False)

    def _chunk_size(self) -> int:
        # Read per write: BlueZ learns the negotiated MTU only after connecting.
        size = getattr(self._write_char, "max_write_without_response_size", None)
        return size if isinstance(size, int) and size > 0 else FALLBACK_WRITE_SIZE

    def _on_notify(self, _sender: object, data: bytearray) -> None:
        self._transport._received(self, bytes(data))

    def _on_disconnected(self, _client: object) -> None:
        name = self._transport.describe().removeprefix("BLE ")
        self._transport._lost(self, f"Bluetooth link to {name} lost")
        self._writes.put_nowait(None)  # ends the write pump

    async def _disconnect(self) -> None:
        client = self._client
        if client is None or not client.is_connected:
            return
        try:
            await asyncio.wait_for(client.disconnect(), DISCONNECT_TIMEOUT_S)
        except Exception:  # the link is being dropped anyway
            _log.debug("BLE disconnect failed", exc_info=True)
