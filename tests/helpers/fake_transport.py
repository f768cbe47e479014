"""Transports with nothing behind them: the test is the device, or there is none.

For tests about what the station does with a link rather than with a device:
a real device being connected, a port that comes back after failing, a
board whose every byte the test writes itself.
"""

from __future__ import annotations

import threading

from protocol.transport.base import Transport


class SilentPort(Transport):
    def __init__(self, name: str = "/dev/ttyUSB0 @ 115200", *, failures: int = 0) -> None:
        super().__init__()
        self.name = name
        self.failures = failures
        self.opens = 0
        self._open = False

    def describe(self) -> str:
        return self.name

    @property
    def is_open(self) -> bool:
        return self._open

    def open(self) -> None:
        self.opens += 1
        if self.opens <= self.failures:
            self.listener.connection_lost("port not found")
            return
        self._open = True
        self._mark_open()
        self.listener.connection_made()

    def close(self) -> None:
        was_open, self._open = self._open, False
        self._mark_closed()
        if was_open:
            self.listener.connection_lost(None)

    def write(self, data: bytes) -> None:
        pass


class UnannouncedPort(SilentPort):
    """A port that opens without saying so (the test says when the window hears of it), and
    keeps every byte written to it, from any thread."""

    def __init__(self, name: str = "/dev/ttyACM0 @ 115200") -> None:
        super().__init__(name)
        self.sent: list[bytes] = []
        self.sent_lock = threading.Lock()

    def open(self) -> None:
        self.opens += 1
        self._open = True
        self._mark_open()

    def write(self, data: bytes) -> None:
        with self.sent_lock:
            self.sent.append(bytes(data))
