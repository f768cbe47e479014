"""A transport with nothing behind it: a port that opens (after some refusals) and stays silent.

For tests about what the station does with a link rather than with a device:
a real device being connected, a port that comes back after failing.
"""

from __future__ import annotations

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
