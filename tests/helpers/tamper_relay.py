"""A cable that changes bytes on their way to the device: a wire with no checksum, corrupted.

The emulator serves its device on a pty; the relay opens it and offers the
station a pty of its own (a symlink at ``link``).  Bytes from the device pass
as they come; bytes to the device are cut into messages at ``end`` and each
complete message goes through ``tamper`` (which returns what arrives instead:
the message itself, a corrupted copy, or less).  Bytes in ``passthrough`` (a
G-code board's real-time bytes, which no line holds) go on at once.

Everything relayed is recorded in order, each way, with the station clock's
idea of nothing: ``record`` holds (direction, message) pairs as they passed, so
a test can tell how many reports the device sent between two events.
"""

from __future__ import annotations

import contextlib
import os
import select
import threading
import tty
from collections.abc import Callable
from pathlib import Path

TO_DEVICE = "to device"
TO_HOST = "to host"

#: What arrives instead of one complete message to the device (terminator included).
Tamper = Callable[[bytes], bytes]


class TamperRelay:
    """Relays ``device`` (a pty path) to a pty the station opens at ``link``."""

    def __init__(
        self,
        device: str,
        link: Path,
        *,
        end: bytes,
        tamper: Tamper,
        host_end: bytes,
        passthrough: frozenset[int] = frozenset(),
    ) -> None:
        self.link = link
        self._end = end
        self._host_end = host_end
        self._tamper = tamper
        self._passthrough = passthrough
        self._partial = bytearray()
        self._host_partial = bytearray()
        self.record: list[tuple[str, bytes]] = []
        self._lock = threading.Lock()
        self._device = os.open(device, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self._device)
        master, slave = os.openpty()
        tty.setraw(slave)
        os.set_blocking(master, False)
        self._master, self._slave = master, slave
        link.unlink(missing_ok=True)
        link.symlink_to(os.ttyname(slave))
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._run, name="tamper-relay", daemon=True)
        self._thread.start()

    def messages(self) -> list[tuple[str, bytes]]:
        with self._lock:
            return list(self.record)

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2.0)
        self.link.unlink(missing_ok=True)
        for fd in (self._master, self._slave, self._device):
            with contextlib.suppress(OSError):
                os.close(fd)

    def _run(self) -> None:
        while not self._stop.is_set():
            try:
                readable, _, _ = select.select([self._device, self._master], [], [], 0.005)
            except (OSError, ValueError):
                return
            for fd in readable:
                try:
                    data = os.read(fd, 4096)
                except (BlockingIOError, OSError):
                    continue
                if fd == self._device:
                    self._to_host(data)
                else:
                    self._to_device(data)

    def _to_host(self, data: bytes) -> None:
        with self._lock:
            for byte in data:
                self._host_partial.append(byte)
                if self._host_partial.endswith(self._host_end):
                    self.record.append((TO_HOST, bytes(self._host_partial)))
                    self._host_partial.clear()
        _write(self._master, data)

    def _to_device(self, data: bytes) -> None:
        out = bytearray()
        with self._lock:
            for byte in data:
                if byte in self._passthrough:
                    out.append(byte)
                    continue
                self._partial.append(byte)
                if self._partial.endswith(self._end):
                    arrives = self._tamper(bytes(self._partial))
                    self.record.append((TO_DEVICE, arrives))
                    out += arrives
                    self._partial.clear()
        _write(self._device, bytes(out))


def _write(fd: int, data: bytes) -> None:
    view = memoryview(data)
    while view:
        try:
            written = os.write(fd, view)
        except BlockingIOError:
            select.select([], [fd], [], 0.05)
            continue
        except OSError:
            return
        view = view[written:]
