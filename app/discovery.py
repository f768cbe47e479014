"""Finding devices to connect to: serial ports and advertising BLE stages.

Port listing is quick and synchronous; a BLE scan takes seconds and runs on
the BLE loop thread, so it reports back through a Qt signal and the GUI
thread never waits for it.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Signal

from app.profiles import MachineProfile
from protocol.transport.ble import BleDevice, BleLoop, BleUuids, scan
from protocol.transport.serial_link import PortInfo, list_ports

__all__ = ["BleDevice", "BleScan", "PortInfo", "ble_uuids_for", "serial_ports"]

BAUD_RATES = (9600, 19200, 38400, 57600, 115200, 230400, 460800, 921600)


def serial_ports() -> list[PortInfo]:
    return list_ports()


def ble_uuids_for(profile: MachineProfile) -> BleUuids:
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
