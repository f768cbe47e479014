"""Finding devices to connect to: serial ports and advertising BLE stages.

Port listing is quick and synchronous; a BLE scan takes seconds and runs on
the BLE loop thread, so it reports back through a Qt signal and the GUI
thread never waits for it.

The BLE transport (bleak, asyncio) is imported when a scan or a BLE link
is first wanted, not with this module: the window's first paint would wait
for it, and most sessions never use BLE.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import TYPE_CHECKING

from PySide6.QtCore import QObject, Signal

from app.profiles import MachineProfile
from protocol.transport.serial_link import PortInfo, list_ports

if TYPE_CHECKING:
    from protocol.transport.ble import BleDevice, BleLoop, BleUuids

__all__ = ["BleDevice", "BleScan", "PortInfo", "ble_uuids_for", "serial_ports"]

BAUD_RATES = (9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)


def serial_ports() -> list[PortInfo]:
    return list_ports()


def __getattr__(name: str) -> object:
    """``BleDevice``, imported from the BLE transport when first asked for."""
    if name == "BleDevice":
        from protocol.transport.ble import BleDevice

        return BleDevice
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def scan(
    loop: BleLoop,
    *,
    uuids: BleUuids,
    name_prefix: str,
    timeout: float,
    on_done: Callable[[list[BleDevice] | str], None],
) -> None:
    """:func:`protocol.transport.ble.scan`, imported when a scan is first asked for."""
    from protocol.transport.ble import scan as ble_scan

    ble_scan(loop, uuids=uuids, name_prefix=name_prefix, timeout=timeout, on_done=on_done)


def ble_uuids_for(profile: MachineProfile) -> BleUuids:
    from protocol.transport.ble import BleUuids

    link = profile.link
    return BleUuids(link.ble_service_uuid, link.ble_write_uuid, link.ble_notify_uuid)


class BleScan(QObject):
    """One scan at a time for the profile's stage; results arrive as ``finished``."""

    finished = Signal(list)  # list[BleDevice]
    failed = Signal(str)

    def __init__(self, loop: BleLoop, profile: MachineProfile, parent: QObject | None = None):
        super().__init__(parent)
        self._loop = loop
        self._profile = profile
        self.running = False

    def start(self, timeout: float = 5.0) -> None:
        if self.running:
            return
        self.running = True
        scan(
            self._loop,
            uuids=ble_uuids_for(self._profile),
            name_prefix=self._profile.link.ble_name_prefix,
            timeout=timeout,
            on_done=self._done,
        )

    def _done(self, result: list[BleDevice] | str) -> None:
        # Called on the BLE loop thread: only emit (queued to the GUI thread).
        self.running = False
        if isinstance(result, str):
            self.failed.emit(result)
        else:
            self.finished.emit(list(result))
