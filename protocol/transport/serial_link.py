"""The serial transport: a USB-serial cable, an SPP development unit or the emulator's pty.

Opening a port can take a while (a USB adapter enumerating, a lock to test),
and a port can vanish at any moment, so nothing here runs on the caller's
thread: :meth:`SerialTransport.open` starts a reader thread that opens the
port and then reads, and a writer thread drains a queue, so :meth:`write`
never blocks the GUI.  Every attempt started by ``open()`` ends in exactly one
``connection_lost`` — ``None`` after :meth:`close`, an operator-facing message
otherwise — after which ``open()`` may be called again: that is how the
station reconnects with back-off.

Only two parties ever end a connection and report it: the reader thread (the
port failed) and :meth:`close`.  The writer thread only records its failure
and wakes the reader, so listener callbacks never come from two threads at
once and ``connection_lost`` is always the last event of an attempt.
"""

from __future__ import annotations

import errno
import os
import queue
import re
import select
import sys
import threading
from collections.abc import Callable
from dataclasses import dataclass, field

import serial
import serial.tools.list_ports

from protocol.transport.base import Transport

#: How long one read waits for bytes: short enough that a stop request is seen
#: at once even if cancelling the read fails, long enough not to spin.
READ_TIMEOUT_S = 0.05
#: The most one read takes (a reply burst is far less).
READ_SIZE = 4096
#: A write that cannot finish in this time means the device stopped taking data;
#: by then the station's link-health check has declared the link lost anyway.
WRITE_TIMEOUT_S = 1.0
#: Closing waits this long for each thread; they notice a stop within one read.
JOIN_TIMEOUT_S = 2.0
#: A close first lets the writer hand over what was written before it, this long at most:
#: the reset that ends a stop is written just before the close, and a board that never
#: gets it stays in feed hold (GUI thread: well under the 100 ms it may be held).
FLUSH_TIMEOUT_S = 0.05
#: The writer's marker in the outbox: everything before it has gone to the port.
_FLUSHED = b""

_NOT_FOUND = frozenset({errno.ENOENT})
_PERMISSION = frozenset({errno.EACCES, errno.EPERM})
_BUSY = frozenset({errno.EBUSY})
_VANISHED = frozenset({errno.EIO, errno.ENXIO, errno.ENODEV})
_ERRNO_IN_TEXT = re.compile(r"\[Errno (\d+)\] ([^:\]]+)")


@dataclass(frozen=True)
class PortInfo:
    """A port as the connection panel lists it; ``hwid`` tells two identical adapters apart."""

    device: str
    description: str
    hwid: str


def list_ports() -> list[PortInfo]:
    """The serial ports present now, by device path, for the connection panel's list.

    A refresh button must never crash the window, so any failure of the
    platform's enumeration just gives an empty list.
    """
    try:
        found = serial.tools.list_ports.comports()
        ports = [PortInfo(str(p.device), str(p.description), str(p.hwid)) for p in found]
    except Exception:
        return []
    return sorted(ports, key=lambda p: p.device)


def describe_serial_error(port: str, exc: BaseException, *, platform: str = sys.platform) -> str:
    """One line telling the operator what went wrong with ``port`` and what to do about it.

    pyserial wraps the operating system's error in a ``SerialException``,
    sometimes keeping its errno, sometimes only its text, so both are checked.
    """
    code, detail = _os_error_of(exc)
    text = str(exc).lower()
    if isinstance(exc, serial.SerialTimeoutException):
        return f"{port}: the device stopped taking data (write timed out)"
    if code in _PERMISSION:
        if platform == "win32":
            # Windows says "access denied" for a port another program holds.
            return f"{port} is in use by another program"
        hint = ""
        if platform.startswith("linux"):
            hint = (
                " — add your user to the dialout group: sudo usermod -aG dialout $USER,"
                " then log out and in"
            )
        return f"{port}: permission denied{hint}"
    if code in _BUSY or "exclusively lock" in text:
        return f"{port} is in use by another program"
    if code in _NOT_FOUND or "filenotfounderror" in text:
        return f"{port} not found — is it plugged in?"
    if code in _VANISHED or "returned no data" in text:
        return f"{port} disappeared (unplugged?)"
    return f"{port}: {detail}"


def _os_error_of(exc: BaseException) -> tuple[int | None, str]:
    """The errno and the plain error text behind ``exc``, however pyserial wrapped them."""
    seen: BaseException | None = exc
    while seen is not None:
        if isinstance(seen, OSError) and isinstance(seen.errno, int):
            return seen.errno, _innermost_text(seen, str(seen.strerror or seen))
        seen = seen.__cause__ or seen.__context__
    found = _ERRNO_IN_TEXT.findall(str(exc))
    if found:
        code, text = found[-1]
        return int(code), text.strip()
    return None, str(exc) or type(exc).__name__


def _innermost_text(exc: BaseException, fallback: str) -> str:
    """``[Errno 22] could not open port x: [Errno 22] Invalid argument`` → ``Invalid argument``."""
    found = _ERRNO_IN_TEXT.findall(str(exc))
    return str(found[-1][1]).strip() if found else fallback


@dataclass(eq=False)
class _Attempt:
    """One ``open()``: its threads, its outgoing queue and, once opened, its port."""

    stop: threading.Event = field(default_factory=threading.Event)
    outbox: queue.Queue[bytes | None] = field(default_factory=queue.Queue)
    port: serial.Serial | None = None
    ended: bool = False
    write_error: BaseException | None = None
    threads: list[threading.Thread] = field(default_factory=list)
    flushed: threading.Event = field(default_factory=threading.Event)
    #: Held while bytes are handed to the port (the writer's or the reader's).
    writing: threading.Lock = field(default_factory=threading.Lock)
    #: Guards ``queued`` only, never held across I/O (``write`` must not block).
    counting: threading.Lock = field(default_factory=threading.Lock)
    #: Data in the outbox the writer has not handed to the port yet.
    queued: int = 0


class SerialTransport(Transport):
    """One serial port, opened and read on a thread of its own (see the module docstring).

    ``serial_factory`` is how the port gets made: ``serial.Serial`` in the app,
    a fake in tests that need a port to fail in a particular way.
    """

    def __init__(
        self,
        port: str,
        baudrate: int = 115200,
        *,
        serial_factory: Callable[..., serial.Serial] = serial.Serial,
    ) -> None:
        super().__init__()
        self.port = port
        self.baudrate = baudrate
        self._factory = serial_factory
        self._lock = threading.Lock()
        self._attempt: _Attempt | None = None

    def describe(self) -> str:
        return f"{self.port} @ {self.baudrate}"

    @property
    def is_open(self) -> bool:
        """True while the port is open and passing bytes (not while still opening)."""
        attempt = self._attempt
        return attempt is not None and attempt.port is not None and not attempt.ended

    def open(self) -> None:
        """Start opening the port in the background; a no-op while an attempt is alive."""
        attempt = _Attempt()
        attempt.threads = [
            self._thread(self._read, attempt, "serial-reader"),
            self._thread(self._drain, attempt, "serial-writer"),
        ]
        with self._lock:
            previous = self._attempt
            if previous is not None and not previous.ended:
                return
        if previous is not None:
            # A loss may still be winding down on the reader thread: let it release the
            # port first, or our own exclusive lock would report the port busy.
            self._join(previous)
        with self._lock:
            if self._attempt is not previous:
                return  # another open() won the race
            self._attempt = attempt
            self._mark_open()
            # Started under the lock so that a close() racing with us always finds
            # threads it can join.
            for thread in attempt.threads:
                thread.start()

    def close(self) -> None:
        attempt = self._attempt
        if attempt is None:
            return
        if attempt.port is not None and not attempt.ended and attempt.write_error is None:
            attempt.outbox.put(_FLUSHED)  # what was written goes out before the port closes
            attempt.flushed.wait(FLUSH_TIMEOUT_S)
        ours = self._end(attempt)
        self._join(attempt)
        if ours:
            self._release(attempt)
            self.listener.connection_lost(None)

    def write(self, data: bytes) -> None:
        attempt = self._attempt
        if attempt is None or attempt.port is None or attempt.ended:
            return
        with attempt.counting:
            attempt.queued += 1
            attempt.outbox.put(bytes(data))

    def write_from_listener(self, data: bytes) -> None:
        """On the reader thread: hand ``data`` to the port now, unless queued bytes come first.

        Streaming (a G-code job) writes the next line as an answer is read;
        waking the writer thread for it cost a thread switch, and under load a
        wait for the interpreter, on every line.  Order is kept: with bytes in
        the outbox, or the writer handing some over, these go behind them.  The
        reader never waits for the port (its caller may hold a lock the window's
        thread wants): on POSIX what the port does not take at once is left to
        the writer, behind.  A failed write is left for the reader, as the
        writer's is.  Any other thread gets :meth:`write`.
        """
        attempt = self._attempt
        if attempt is None or attempt.port is None or attempt.ended:
            return
        if not attempt.threads or threading.current_thread() is not attempt.threads[0]:
            self.write(data)
            return
        if not attempt.writing.acquire(blocking=False):  # the writer is handing bytes over
            self.write(data)
            return
        try:
            with attempt.counting:
                if attempt.queued:
                    attempt.queued += 1
                    attempt.outbox.put(bytes(data))
                    return
            if attempt.write_error is not None or attempt.stop.is_set():
                return
            port = attempt.port
            fd = getattr(port, "fd", None)
            if not isinstance(fd, int):
                port.write(data)  # no descriptor of its own (not POSIX): pyserial's write
                return
            try:
                sent = os.write(fd, data)
            except BlockingIOError:
                sent = 0
            if sent < len(data):
                self.write(data[sent:])
        except (serial.SerialException, OSError) as exc:
            attempt.write_error = exc
        finally:
            attempt.writing.release()

    # --- the threads -----------------------------------------------------------

    @staticmethod
    def _thread(
        target: Callable[[_Attempt], None], attempt: _Attempt, name: str
    ) -> threading.Thread:
        return threading.Thread(target=target, args=(attempt,), name=name, daemon=True)

    def _read(self, attempt: _Attempt) -> None:
        """Reader thread: open the port, report, then deliver bytes until stopped or broken."""
        try:
            port = self._open_port()
        except (serial.SerialException, OSError, ValueError) as exc:
            self._fail(attempt, exc)
            return
        with self._lock:
            if attempt.ended:  # closed while the port was opening
                port.close()
                return
            attempt.port = port
        self.listener.connection_made()
        failure = self._pass_bytes(attempt, port)
        if failure is not None:
            self._fail(attempt, failure)

    def _open_port(self) -> serial.Serial:
        options: dict[str, object] = {"timeout": READ_TIMEOUT_S, "write_timeout": WRITE_TIMEOUT_S}
        if os.name == "posix":
            # Without the lock a second station (or a terminal) would silently share the
            # port and both would see half the replies.
            options["exclusive"] = True
        return self._factory(self.port, self.baudrate, **options)

    def _pass_bytes(self, attempt: _Attempt, port: serial.Serial) -> BaseException | None:
        """Read until stopped (None) or until the port or the writer fails (the error)."""
        fd, abort = getattr(port, "fd", None), getattr(port, "pipe_abort_read_r", None)
        if isinstance(fd, int) and isinstance(abort, int):
            return self._pass_bytes_posix(attempt, fd, abort)
        try:
            while not attempt.stop.is_set():
                if attempt.write_error is not None:
                    return attempt.write_error
                data = port.read(max(1, port.in_waiting))
                if data and not attempt.stop.is_set():
                    self.listener.data_received(data)
        except (serial.SerialException, OSError) as exc:
            return exc
        return None

    def _pass_bytes_posix(self, attempt: _Attempt, fd: int, abort: int) -> BaseException | None:
        """:meth:`_pass_bytes` on a POSIX port: one wait and one read for whatever has come.

        pyserial's ``in_waiting`` + ``read`` took five system calls for a reply, and the
        first read only one byte of it; each call lets another thread take the
        interpreter, and a G-code stream's next line waits for the reply.
        """
        try:
            while not attempt.stop.is_set():
                if attempt.write_error is not None:
                    return attempt.write_error
                ready, _, _ = select.select([fd, abort], [], [], READ_TIMEOUT_S)
                if abort in ready:
                    os.read(abort, 1000)  # cancel_read(): the loop's checks say why
                    continue
                if fd not in ready:
                    continue
                try:
                    data = os.read(fd, READ_SIZE)
                except BlockingIOError:
                    continue
                if not data:
                    # pyserial's words for it, which describe_serial_error knows
                    raise serial.SerialException(
                        "device reports readiness to read but returned no data "
                        "(device disconnected or multiple access on port?)"
                    )
                if not attempt.stop.is_set():
                    self.listener.data_received(data)
        except (serial.SerialException, OSError) as exc:
            return exc
        return None

    def _drain(self, attempt: _Attempt) -> None:
        """Writer thread: hand queued bytes to the port; a failure is left for the reader."""
        while True:
            data = attempt.outbox.get()
            if data is None or attempt.stop.is_set():
                return
            port = attempt.port
            if port is None:
                continue
            if data == _FLUSHED:
                with attempt.writing:
                    _quietly(port.flush)
                attempt.flushed.set()
                continue
            try:
                with attempt.writing:
                    port.write(data)
                    with attempt.counting:
                        attempt.queued -= 1
            except (serial.SerialException, OSError) as exc:
                attempt.write_error = exc
                _quietly(port.cancel_read)
                return

    # --- ending an attempt -----------------------------------------------------

    def _fail(self, attempt: _Attempt, exc: BaseException) -> None:
        """The port broke (reader thread): tear down and report, unless close() got there first."""
        if not self._end(attempt):
            return
        self._join(attempt)
        self._release(attempt)
        self.listener.connection_lost(describe_serial_error(self.port, exc))

    def _end(self, attempt: _Attempt) -> bool:
        """Claim the end of ``attempt`` and wake its threads; True for the one claimant."""
        with self._lock:
            if attempt.ended:
                return False
            attempt.ended = True
            port = attempt.port
        attempt.stop.set()
        attempt.outbox.put(None)
        if port is not None:
            _quietly(port.cancel_read)
            _quietly(port.cancel_write)
        return True

    def _join(self, attempt: _Attempt) -> None:
        me = threading.current_thread()
        for thread in attempt.threads:
            if thread is not me and thread.ident is not None:
                thread.join(JOIN_TIMEOUT_S)

    def _release(self, attempt: _Attempt) -> None:
        """Close the port and unregister, unless a newer attempt has already opened.

        Done before reporting, because whoever hears the report may reopen at once.
        """
        if attempt.port is not None:
            _quietly(attempt.port.close)
        with self._lock:
            if self._attempt is attempt:
                self._mark_closed()


def _quietly(action: Callable[[], object]) -> None:
    """Run a best-effort clean-up step on a port that may already be broken."""
    try:
        action()
    except (serial.SerialException, OSError, ValueError):
        pass
