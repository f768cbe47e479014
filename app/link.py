"""A transport wrapped in a QObject so its events arrive as Qt signals.

Transports call their listener from their own threads (serial reader,
BLE loop, emulator ticker); emitting signals from there lets Qt queue the
events onto the GUI thread, where sessions and widgets live.  When the
transport runs on the GUI thread (tests on a manual clock) the same signals
are delivered directly, so tests stay synchronous and deterministic.
"""

from __future__ import annotations

import sys
import threading
import time
from collections.abc import Callable

from PySide6.QtCore import QObject, Qt, QThread, QTimer, Signal

from app.listened import listened
from protocol.transport.base import Transport

#: How long a thread may keep the interpreter lock while another waits, with a tap in use.
#: Python's 5 ms default is about the 127 bytes a G-code board buffers (11 ms at 115 200
#: baud) twice over (the reader's turn, then the writer's): a busy window thread then
#: paced the stream to 75-90 % of the wire; at 0.5 ms it ran at 94 %.
TAP_SWITCH_INTERVAL_S = 0.0005
#: The window hears of a tapped link's reads at most this often: a streaming job is answered
#: some 700 times a second, and the reader thread has already sent what each answer let go,
#: so the window takes them in batches, about once a frame.
DELIVER_EVERY_S = 1 / 30


class Link(QObject):
    connected = Signal()
    disconnected = Signal(object)  # str reason, or None for an orderly close
    dataReceived = Signal(bytes)
    dataSent = Signal(bytes)  # exactly what was handed to the transport (for the TX log)
    #: What the tap made of received bytes (see :meth:`set_tap`), instead of ``dataReceived``.
    received = Signal(object)
    #: The tap's results wait in the inbox (emitted once per batch, from the reader thread).
    _inboxFilled = Signal()
    #: The link ended, told from the reader thread: the inbox goes first.
    _lostFromThread = Signal(object)

    def __init__(self, transport: Transport, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.transport = transport
        self._tap: Callable[[bytes], object] | None = None
        self._merge: Callable[[list[object]], list[object]] | None = None
        self._urgent: Callable[[object], bool] | None = None
        #: An urgent result waits in the inbox: it goes now, not at the next 1/30 s.
        self._hurry = False
        self._inbox: list[object] = []
        self._inbox_lock = threading.Lock()
        self._inbox_posted = False
        self._delivered_at = -DELIVER_EVERY_S
        self._later = QTimer(self)
        self._later.setSingleShot(True)
        self._later.timeout.connect(self._deliver)
        self._inboxFilled.connect(self._deliver, Qt.ConnectionType.QueuedConnection)
        self._lostFromThread.connect(self._lost, Qt.ConnectionType.QueuedConnection)
        transport.set_listener(self)

    def set_tap(
        self,
        tap: Callable[[bytes], object] | None,
        merge: Callable[[list[object]], list[object]] | None = None,
        urgent: Callable[[object], bool] | None = None,
    ) -> None:
        """Run ``tap`` on received bytes where they arrive (the transport's reader thread).

        A session whose loop must not wait for the GUI thread (G-code streaming:
        the next line goes when an ``ok`` comes) does its part there; what
        ``tap`` returns reaches the GUI thread as ``received``.  ``merge`` makes
        the results gathered meanwhile into as few as it can (one per batch).
        ``urgent``: a result the window hears of at once, with what waited before it,
        not at the next batch (G-code: a report that can end a job).
        """
        self._tap = tap
        self._merge = merge
        self._urgent = urgent
        if tap is not None and sys.getswitchinterval() > TAP_SWITCH_INTERVAL_S:
            sys.setswitchinterval(TAP_SWITCH_INTERVAL_S)  # the reader's turn comes sooner

    # TransportListener, possibly on a foreign thread: only emit here.
    def connection_made(self) -> None:
        self.connected.emit()

    def data_received(self, data: bytes) -> None:
        tap = self._tap
        if tap is None:
            self.dataReceived.emit(data)
            return
        result = tap(data)
        if QThread.currentThread() is self.thread():
            self.received.emit(result)  # a transport run on this thread: at once, as before
            return
        # From the reader thread: one wake-up of the window's thread per batch.  While it
        # is busy the results gather here and are told in order, all before any later
        # event of this link (a loss is emitted after them, so queued behind the wake-up).
        urgent = self._urgent is not None and self._urgent(result)
        with self._inbox_lock:
            self._inbox.append(result)
            if self._inbox_posted and not urgent:
                return
            self._inbox_posted = True
            self._hurry = self._hurry or urgent
        self._inboxFilled.emit()

    def _deliver(self) -> None:
        """The inbox to the window, at most every :data:`DELIVER_EVERY_S` (later ones wait)."""
        wait = self._delivered_at + DELIVER_EVERY_S - time.monotonic()
        if wait > 0 and not self._hurry:
            if not self._later.isActive():
                self._later.start(max(1, round(wait * 1000)))
            return  # still posted: the reader thread adds to the inbox without waking us
        self._flush()

    def _flush(self) -> None:
        self._later.stop()
        self._delivered_at = time.monotonic()
        with self._inbox_lock:
            results, self._inbox = self._inbox, []
            self._inbox_posted = False
            self._hurry = False
        if self._merge is not None and len(results) > 1:
            results = self._merge(results)
        for result in results:
            self.received.emit(result)

    def connection_lost(self, reason: str | None) -> None:
        if QThread.currentThread() is self.thread():
            self._lost(reason)
        else:
            self._lostFromThread.emit(reason)

    def _lost(self, reason: object) -> None:
        """What was read before the loss is heard of before it (a waiting batch goes now)."""
        self._flush()
        self.disconnected.emit(reason)

    # Used from the GUI thread.
    def open(self) -> None:
        self.transport.open()

    def close(self) -> None:
        self.transport.close()

    def write(self, data: bytes) -> None:
        if not self.transport.is_open:
            return
        self.transport.write(data)
        self.dataSent.emit(data)

    def write_from_tap(self, pieces: list[bytes]) -> None:
        """:meth:`write` for the tap, where the bytes were read: all in one write, no other
        thread woken (the serial port's reader writes them itself), then told piece by piece."""
        if not self.transport.is_open:
            return
        self.transport.write_from_listener(b"".join(pieces))
        if listened(self, "dataSent"):  # asked once a write, not an emit per line for nobody
            for data in pieces:
                self.dataSent.emit(data)

    @property
    def is_open(self) -> bool:
        return self.transport.is_open

    def describe(self) -> str:
        return self.transport.describe()
