"""What every link (serial, BLE, in-process loopback) offers the station.

The shape follows asyncio's Transport/Protocol pair: the transport pushes
bytes and connection events to one listener, and never blocks its caller.
Listener callbacks may arrive on the transport's own thread; the app layer
re-emits them as queued Qt signals.
"""

from __future__ import annotations

import threading
import weakref
from abc import ABC, abstractmethod
from typing import Protocol


class TransportListener(Protocol):
    def connection_made(self) -> None: ...

    def data_received(self, data: bytes) -> None: ...

    def connection_lost(self, reason: str | None) -> None:
        """``reason`` is None for an orderly close, else a message for the operator."""


class _NullListener:
    def connection_made(self) -> None:
        pass

    def data_received(self, data: bytes) -> None:
        pass

    def connection_lost(self, reason: str | None) -> None:
        pass


_open: weakref.WeakSet[Transport] = weakref.WeakSet()
_open_lock = threading.Lock()


def open_transports() -> list[Transport]:
    """Transports opened and not yet closed: a test that leaves one behind leaks a link."""
    with _open_lock:
        return list(_open)


class Transport(ABC):
    """Bytes in, bytes out, open/close, connection events."""

    def __init__(self) -> None:
        self._listener: TransportListener = _NullListener()

    def set_listener(self, listener: TransportListener | None) -> None:
        self._listener = listener if listener is not None else _NullListener()

    @property
    def listener(self) -> TransportListener:
        return self._listener

    @abstractmethod
    def describe(self) -> str:
        """A short human name of the link, e.g. ``/dev/ttyUSB0 @ 115200``."""

    @abstractmethod
    def open(self) -> None:
        """Start connecting; success or failure is reported to the listener."""

    @abstractmethod
    def close(self) -> None:
        """Close for good (idempotent); the listener hears ``connection_lost(None)``."""

    @abstractmethod
    def write(self, data: bytes) -> None:
        """Queue bytes for the device; never blocks. Dropped silently when closed."""

    def write_from_listener(self, data: bytes) -> None:
        """Bytes for the device, from inside the listener's ``data_received``.

        A transport that reads on a thread of its own may write them there and
        then, after whatever :meth:`write` queued before (the serial port: an
        answer's next line goes without waking another thread); by default, and
        from any other thread, this is :meth:`write`.
        """
        self.write(data)

    @property
    @abstractmethod
    def is_open(self) -> bool: ...

    def _mark_open(self) -> None:
        with _open_lock:
            _open.add(self)

    def _mark_closed(self) -> None:
        with _open_lock:
            _open.discard(self)
