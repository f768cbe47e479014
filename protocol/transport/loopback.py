"""An emulated device in the same process, as if it were on a cable.

Used for the station's default start, the developer pane's simulation and
the tests.  In real-time mode a ticker thread runs the device on the
monotonic clock; in manual mode whoever owns the clock calls :meth:`pump`, so
tests decide exactly when the device's control cycles happen.

A manipulator sees every chunk in both directions and may drop or corrupt it,
as pymodbus's null modem does, to exercise the station's handling of a bad
link.
"""

from __future__ import annotations

import enum
import threading
from collections.abc import Callable

from protocol.clock import Clock
from protocol.emulator.device import EmulatedDevice
from protocol.transport.base import Transport


class Direction(enum.Enum):
    TO_DEVICE = "tx"
    TO_HOST = "rx"


Manipulator = Callable[[Direction, bytes], bytes]


class LoopbackTransport(Transport):
    def __init__(
        self,
        device: EmulatedDevice,
        clock: Clock,
        *,
        realtime: bool = True,
        tick_seconds: float = 0.002,
        name: str = "built-in emulator",
    ) -> None:
        super().__init__()
        self.device = device
        self.clock = clock
        self._realtime = realtime
        self._tick = tick_seconds
        self._name = name
        self._open = False
        self._severed = False
        self._manipulator: Manipulator | None = None
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None

    def describe(self) -> str:
        return self._name

    @property
    def is_open(self) -> bool:
        return self._open and not self._severed

    def set_manipulator(self, manipulator: Manipulator | None) -> None:
        self._manipulator = manipulator

    def open(self) -> None:
        if self.is_open:
            return
        self._severed = False
        self._open = True
        self.device.set_output(self._from_device)
        self._mark_open()
        if self._realtime and self._thread is None:
            self._stop.clear()
            self._thread = threading.Thread(target=self._run, name="emulator-ticker", daemon=True)
            self._thread.start()
        self.listener.connection_made()

    def close(self) -> None:
        was_open = self._open
        self._open = False
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(timeout=2.0)
        self._thread = None
        self.device.set_output(None)
        self._mark_closed()
        if was_open:
            self.listener.connection_lost(None)

    def sever(self, reason: str = "link dropped") -> None:
        """Cut the cable: the device keeps running, nothing passes, the host is told."""
        if not self.is_open:
            return
        self._severed = True
        self.listener.connection_lost(reason)

    def write(self, data: bytes) -> None:
        if not self.is_open:
            return
        if self._manipulator is not None:
            data = self._manipulator(Direction.TO_DEVICE, data)
        if data:
            self.device.receive(data)

    def pump(self) -> None:
        """Run the device up to the clock's present (manual mode)."""
        self.device.run_until(self.clock.now())

    def _from_device(self, data: bytes) -> None:
        if not self.is_open:
            return
        if self._manipulator is not None:
            data = self._manipulator(Direction.TO_HOST, data)
        if data:
            self.listener.data_received(data)

    def _run(self) -> None:
        while not self._stop.wait(self._tick):
            self.device.run_until(self.clock.now())
