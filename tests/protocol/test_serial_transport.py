"""The serial transport against a real pseudo-terminal, fake ports that fail, and its messages."""

from __future__ import annotations

import errno
import os
import select
import threading
import time
import tty
from collections.abc import Iterator
from pathlib import Path

import pytest
import serial

from protocol.transport.base import open_transports
from protocol.transport.serial_link import (
    PortInfo,
    SerialTransport,
    describe_serial_error,
    list_ports,
)

TIMEOUT = 5.0


class Recorder:
    """A listener that lets the test wait, with a bound, for what the transport reports."""

    def __init__(self) -> None:
        self.made = threading.Event()
        self.lost = threading.Event()
        self.events: list[str] = []
        self.reasons: list[str | None] = []
        self._data = bytearray()
        self._arrived = threading.Condition()

    def connection_made(self) -> None:
        self.events.append("made")
        self.made.set()

    def data_received(self, data: bytes) -> None:
        with self._arrived:
            self._data += data
            self._arrived.notify_all()

    def connection_lost(self, reason: str | None) -> None:
        self.events.append("lost")
        self.reasons.append(reason)
        self.lost.set()

    def wait_for_bytes(self, count: int, timeout: float = TIMEOUT) -> bytes:
        with self._arrived:
            self._arrived.wait_for(lambda: len(self._data) >= count, timeout)
            return bytes(self._data)

    def rearm(self) -> None:
        self.made.clear()
        self.lost.clear()


class Pty:
    """A pseudo-terminal pair; the test plays the device on the master side."""

    def __init__(self) -> None:
        self.master, self.slave = os.openpty()
        tty.setraw(self.slave)
        self.path = os.ttyname(self.slave)
        self._open = {self.master, self.slave}

    def read(self, count: int, timeout: float = TIMEOUT) -> bytes:
        received = b""
        deadline = time.monotonic() + timeout
        while len(received) < count:
            left = deadline - time.monotonic()
            if left <= 0 or not select.select([self.master], [], [], left)[0]:
                break
            received += os.read(self.master, count - len(received))
        return received

    def unplug(self) -> None:
        """Close both ends, as when a USB adapter is pulled out."""
        for fd in sorted(self._open):
            os.close(fd)
        self._open.clear()


@pytest.fixture
def pty() -> Iterator[Pty]:
    pair = Pty()
    yield pair
    pair.unplug()


def serial_threads() -> list[threading.Thread]:
    return [t for t in threading.enumerate() if t.name in ("serial-reader", "serial-writer")]


def assert_serial_threads_end() -> None:
    """After a loss report the reader may still be returning: join it with a bound."""
    for thread in serial_threads():
        thread.join(TIMEOUT)
    assert not serial_threads()


def connect(transport: SerialTransport) -> Recorder:
    recorder = Recorder()
    transport.set_listener(recorder)
    transport.open()
    assert recorder.made.wait(TIMEOUT), f"not connected: {recorder.reasons}"
    return recorder


# --- over a real pseudo-terminal ---------------------------------------------------


def test_bytes_pass_both_ways_and_close_joins_the_threads(pty: Pty) -> None:
    transport = SerialTransport(pty.path)
    assert transport.describe() == f"{pty.path} @ 115200"
    assert not transport.is_open
    recorder = connect(transport)
    assert transport.is_open
    assert transport in open_transports()

    transport.write(b">frame one\n")
    transport.write(b">frame two\n")
    assert pty.read(22) == b">frame one\n>frame two\n"
    os.write(pty.master, b"<echo\n")
    assert recorder.wait_for_bytes(6) == b"<echo\n"

    transport.close()
    assert not serial_threads()
    assert recorder.events == ["made", "lost"]
    assert recorder.reasons == [None]
    assert not transport.is_open
    assert transport not in open_transports()
    transport.close()  # idempotent: nothing more is reported
    assert recorder.reasons == [None]


def test_writes_after_close_are_dropped(pty: Pty) -> None:
    transport = SerialTransport(pty.path)
    connect(transport)
    transport.close()
    transport.write(b"late\n")
    assert pty.read(1, timeout=0.1) == b""


def test_a_port_held_by_another_program_is_reported_busy(pty: Pty) -> None:
    with serial.Serial(pty.path, exclusive=True):
        transport = SerialTransport(pty.path)
        recorder = Recorder()
        transport.set_listener(recorder)
        transport.open()
        assert recorder.lost.wait(TIMEOUT)
    assert recorder.reasons == [f"{pty.path} is in use by another program"]
    assert recorder.events == ["lost"]
    assert_serial_threads_end()
    assert transport not in open_transports()


def test_a_missing_port_is_reported_not_found(tmp_path: Path) -> None:
    path = str(tmp_path / "ttyUSB9")
    transport = SerialTransport(path)
    recorder = Recorder()
    transport.set_listener(recorder)
    transport.open()
    assert recorder.lost.wait(TIMEOUT)
    assert recorder.reasons == [f"{path} not found — is it plugged in?"]
    assert_serial_threads_end()
    transport.close()  # after a loss there is nothing left to close or report
    assert recorder.reasons == [f"{path} not found — is it plugged in?"]


def test_the_device_vanishing_mid_session_is_reported_once(pty: Pty) -> None:
    transport = SerialTransport(pty.path)
    recorder = connect(transport)
    pty.unplug()  # the master closes: reads on the port fail with EIO
    assert recorder.lost.wait(TIMEOUT)
    assert_serial_threads_end()
    assert recorder.reasons == [f"{pty.path} disappeared (unplugged?)"]
    assert not transport.is_open
    assert transport not in open_transports()
    transport.write(b"into the void\n")
    transport.close()
    assert recorder.events == ["made", "lost"]


def test_open_again_after_a_loss_reaches_the_new_device(tmp_path: Path) -> None:
    """The emulator's --link situation: the same path, a new terminal behind it."""
    link = tmp_path / "stage"
    first, second = Pty(), Pty()
    try:
        link.symlink_to(first.path)
        transport = SerialTransport(str(link))
        recorder = connect(transport)
        first.unplug()
        assert recorder.lost.wait(TIMEOUT)

        recorder.rearm()
        transport.open()  # nothing behind the path now
        assert recorder.lost.wait(TIMEOUT)
        assert recorder.reasons[-1] == f"{link} not found — is it plugged in?"

        link.unlink()
        link.symlink_to(second.path)
        recorder.rearm()
        transport.open()
        assert recorder.made.wait(TIMEOUT)
        transport.write(b"hello again\n")
        assert second.read(12) == b"hello again\n"
        os.write(second.master, b"<ok\n")
        assert recorder.wait_for_bytes(4) == b"<ok\n"
        transport.close()
        assert recorder.events == ["made", "lost", "lost", "made", "lost"]
        assert recorder.reasons[-1] is None
        assert not serial_threads()
    finally:
        first.unplug()
        second.unplug()


def test_open_while_open_is_a_no_op(pty: Pty) -> None:
    transport = SerialTransport(pty.path)
    recorder = connect(transport)
    transport.open()
    assert len(serial_threads()) == 2
    transport.close()
    assert recorder.events == ["made", "lost"]


def test_the_listener_may_reopen_from_inside_connection_lost(tmp_path: Path) -> None:
    link = tmp_path / "stage"
    device = Pty()
    transport = SerialTransport(str(link))
    reopened = threading.Event()

    class Reopener(Recorder):
        def connection_lost(self, reason: str | None) -> None:
            super().connection_lost(reason)
            if reason is not None and not reopened.is_set():
                reopened.set()
                link.symlink_to(device.path)
                transport.open()

    recorder = Reopener()
    transport.set_listener(recorder)
    try:
        transport.open()
        assert recorder.made.wait(TIMEOUT)
        transport.write(b"x\n")
        assert device.read(2) == b"x\n"
        transport.close()
        assert recorder.events == ["lost", "made", "lost"]
        assert_serial_threads_end()
    finally:
        device.unplug()


# --- fake ports: failures on demand -------------------------------------------------


class FakePort:
    """Just enough of ``serial.Serial`` for the transport, with a write that fails."""

    def __init__(self, write_error: BaseException | None = None) -> None:
        self.write_error = write_error
        self.is_open = True
        self.in_waiting = 0
        self._wake = threading.Event()

    def read(self, size: int = 1) -> bytes:
        self._wake.wait(0.05)
        self._wake.clear()
        return b""

    def write(self, data: bytes) -> int:
        if self.write_error is not None:
            raise self.write_error
        return len(data)

    def cancel_read(self) -> None:
        self._wake.set()

    def flush(self) -> None:
        pass

    def cancel_write(self) -> None:
        pass

    def close(self) -> None:
        self.is_open = False


def failing_factory(exc: BaseException) -> object:
    def factory(*args: object, **kwargs: object) -> object:
        raise exc

    return factory


@pytest.mark.parametrize(
    ("exc", "expected"),
    [
        (
            serial.SerialException(
                errno.EACCES,
                "could not open port /dev/ttyUSB0: [Errno 13] Permission denied: '/dev/ttyUSB0'",
            ),
            "/dev/ttyUSB0: permission denied",
        ),
        (
            serial.SerialException(
                errno.EAGAIN,
                "Could not exclusively lock port /dev/ttyUSB0: "
                "[Errno 11] Resource temporarily unavailable",
            ),
            "/dev/ttyUSB0 is in use by another program",
        ),
        (
            serial.SerialException(
                errno.ENOENT,
                "could not open port /dev/ttyUSB0: [Errno 2] No such file or directory",
            ),
            "/dev/ttyUSB0 not found — is it plugged in?",
        ),
    ],
)
def test_a_port_that_fails_to_open_is_reported_and_leaves_no_thread(
    exc: BaseException, expected: str
) -> None:
    transport = SerialTransport("/dev/ttyUSB0", serial_factory=failing_factory(exc))
    recorder = Recorder()
    transport.set_listener(recorder)
    transport.open()
    assert recorder.lost.wait(TIMEOUT)
    assert recorder.events == ["lost"]
    reason = recorder.reasons[0]
    assert reason is not None and reason.startswith(expected), reason
    assert "Traceback" not in reason
    assert_serial_threads_end()
    assert transport not in open_transports()


def test_the_factory_is_asked_for_a_locked_port_with_short_timeouts() -> None:
    asked: list[tuple[tuple[object, ...], dict[str, object]]] = []

    def factory(*args: object, **kwargs: object) -> FakePort:
        asked.append((args, kwargs))
        return FakePort()

    transport = SerialTransport("/dev/ttyACM0", 57600, serial_factory=factory)
    connect(transport)
    transport.close()
    args, kwargs = asked[0]
    assert args == ("/dev/ttyACM0", 57600)
    assert kwargs["exclusive"] is True
    assert isinstance(kwargs["timeout"], float) and kwargs["timeout"] <= 0.1


def test_a_write_failure_ends_the_connection_with_a_message() -> None:
    port = FakePort(serial.SerialException("write failed: [Errno 5] Input/output error"))
    transport = SerialTransport("/dev/ttyUSB0", serial_factory=lambda *a, **k: port)
    recorder = connect(transport)
    transport.write(b">frame\n")
    assert recorder.lost.wait(TIMEOUT)
    assert_serial_threads_end()
    assert recorder.reasons == ["/dev/ttyUSB0 disappeared (unplugged?)"]
    assert not port.is_open
    assert transport not in open_transports()


def test_open_during_a_loss_waits_until_the_old_port_is_released() -> None:
    """Reopening while the broken port is still closing must not find it locked by ourselves."""
    closing, may_close = threading.Event(), threading.Event()
    opened: list[FakePort] = []
    overlap: list[bool] = []

    class SlowToClose(FakePort):
        def close(self) -> None:
            closing.set()
            may_close.wait(TIMEOUT)
            super().close()

    def factory(*args: object, **kwargs: object) -> FakePort:
        overlap.append(any(port.is_open for port in opened))
        port = FakePort() if opened else SlowToClose(serial.SerialException("write failed"))
        opened.append(port)
        return port

    transport = SerialTransport("/dev/ttyUSB0", serial_factory=factory)
    recorder = connect(transport)
    transport.write(b">frame\n")
    assert closing.wait(TIMEOUT)
    recorder.rearm()
    opener = threading.Thread(target=transport.open, name="opener")
    opener.start()
    opener.join(0.2)  # room for a premature reopen to show itself
    may_close.set()
    opener.join(TIMEOUT)
    assert recorder.made.wait(TIMEOUT)
    transport.close()
    assert overlap == [False, False]
    assert recorder.events == ["made", "lost", "made", "lost"]


def test_close_while_the_port_is_still_opening_reports_an_orderly_close() -> None:
    release = threading.Event()
    asked = threading.Event()

    def slow_factory(*args: object, **kwargs: object) -> FakePort:
        asked.set()
        release.wait(TIMEOUT)
        return FakePort()

    transport = SerialTransport("/dev/ttyUSB0", serial_factory=slow_factory)
    recorder = Recorder()
    transport.set_listener(recorder)
    transport.open()
    assert asked.wait(TIMEOUT)
    closer = threading.Thread(target=transport.close, name="closer")
    closer.start()
    release.set()
    closer.join(TIMEOUT)
    assert not closer.is_alive()
    assert not serial_threads()
    assert recorder.reasons == [None]
    assert "made" not in recorder.events


# --- the operator's messages ------------------------------------------------------------


def _wrapped(os_error: OSError, text: str) -> serial.SerialException:
    """A SerialException raised while handling ``os_error``, as pyserial's read() does."""
    exc = serial.SerialException(text)
    exc.__context__ = os_error
    return exc


PORT = "/dev/ttyUSB0"


@pytest.mark.parametrize(
    ("exc", "platform", "expected"),
    [
        (
            serial.SerialException(errno.EACCES, f"could not open port {PORT}: [Errno 13] ..."),
            "linux",
            f"{PORT}: permission denied — add your user to the dialout group: "
            "sudo usermod -aG dialout $USER, then log out and in",
        ),
        (
            serial.SerialException(errno.EPERM, "could not open port: [Errno 1] ..."),
            "darwin",
            f"{PORT}: permission denied",
        ),
        (
            serial.SerialException(errno.EACCES, "could not open port: Access is denied."),
            "win32",
            f"{PORT} is in use by another program",
        ),
        (
            serial.SerialException(errno.EBUSY, "could not open port: [Errno 16] busy"),
            "linux",
            f"{PORT} is in use by another program",
        ),
        (
            serial.SerialException(
                errno.EAGAIN, "Could not exclusively lock port x: [Errno 11] Resource ..."
            ),
            "linux",
            f"{PORT} is in use by another program",
        ),
        (
            serial.SerialException(
                errno.ENOENT, "could not open port: [Errno 2] No such file or directory"
            ),
            "linux",
            f"{PORT} not found — is it plugged in?",
        ),
        (
            serial.SerialException(
                "could not open port 'COM7': FileNotFoundError(2, 'The system cannot find')"
            ),
            "win32",
            f"{PORT} not found — is it plugged in?",
        ),
        (
            _wrapped(OSError(errno.EIO, "Input/output error"), "read failed: [Errno 5] I/O"),
            "linux",
            f"{PORT} disappeared (unplugged?)",
        ),
        (
            serial.SerialException("write failed: [Errno 5] Input/output error"),
            "linux",
            f"{PORT} disappeared (unplugged?)",
        ),
        (
            serial.SerialException(
                "device reports readiness to read but returned no data "
                "(device disconnected or multiple access on port?)"
            ),
            "linux",
            f"{PORT} disappeared (unplugged?)",
        ),
        (OSError(errno.ENXIO, "No such device or address"), "linux", f"{PORT} disappeared"),
        (serial.SerialTimeoutException("Write timeout"), "linux", f"{PORT}: the device stopped"),
        (
            serial.SerialException(
                errno.EINVAL, f"could not open port {PORT}: [Errno 22] Invalid argument"
            ),
            "linux",
            f"{PORT}: Invalid argument",
        ),
        (ValueError("Not a valid baudrate: -1"), "linux", f"{PORT}: Not a valid baudrate: -1"),
        (serial.SerialException(), "linux", f"{PORT}: SerialException"),
    ],
)
def test_describe_serial_error(exc: BaseException, platform: str, expected: str) -> None:
    message = describe_serial_error(PORT, exc, platform=platform)
    assert message.startswith(expected), message
    assert "Errno" not in message and "\n" not in message


# --- the port list ------------------------------------------------------------------


def test_list_ports_is_sorted_and_never_raises(monkeypatch: pytest.MonkeyPatch) -> None:
    class Found:
        def __init__(self, device: str) -> None:
            self.device, self.description, self.hwid = device, f"{device} adapter", "USB VID:PID"

    monkeypatch.setattr(
        serial.tools.list_ports, "comports", lambda: [Found("/dev/ttyUSB1"), Found("/dev/ttyS0")]
    )
    assert list_ports() == [
        PortInfo("/dev/ttyS0", "/dev/ttyS0 adapter", "USB VID:PID"),
        PortInfo("/dev/ttyUSB1", "/dev/ttyUSB1 adapter", "USB VID:PID"),
    ]

    def broken() -> list[Found]:
        raise OSError("no sysfs here")

    monkeypatch.setattr(serial.tools.list_ports, "comports", broken)
    assert list_ports() == []


def test_what_was_written_just_before_a_close_still_reaches_the_device(pty: Pty) -> None:
    """G8-04: a stop's reset is written right before the close; it must not be dropped."""
    transport = SerialTransport(pty.path)
    connect(transport)
    for _ in range(20):
        transport.write(b"!")
        transport.write(b"\x18")
        transport.close()
        assert pty.read(2) == b"!\x18"
        connect(transport)
    transport.close()


# --- writing from the reader thread (G-code streaming) ------------------------------


class Answering(Recorder):
    """A listener that writes ``reply`` back from inside ``data_received``, as the feeder does."""

    def __init__(self, transport: SerialTransport, reply: bytes) -> None:
        super().__init__()
        self.transport = transport
        self.reply = reply

    def data_received(self, data: bytes) -> None:
        self.transport.write_from_listener(self.reply)
        super().data_received(data)


def test_an_answer_written_from_the_reader_goes_out_on_it_after_what_was_queued() -> None:
    """The next line goes out on the reader thread itself (no other thread woken), but never
    before bytes an earlier ``write`` queued: a status query, a reset, a line."""
    writes: list[tuple[bytes, str]] = []
    hold_first, reply_now = threading.Event(), threading.Event()

    class OrderPort(FakePort):
        def read(self, size: int = 1) -> bytes:
            if reply_now.wait(0.05):
                reply_now.clear()
                return b"ok\n"
            return b""

        def write(self, data: bytes) -> int:
            if data == b"first\n":
                hold_first.wait(TIMEOUT)  # the writer thread is busy handing it over
            writes.append((data, threading.current_thread().name))
            return len(data)

    transport = SerialTransport("/dev/ttyUSB0", serial_factory=lambda *a, **k: OrderPort())
    listener = Answering(transport, b"next\n")
    transport.set_listener(listener)
    transport.open()
    try:
        assert listener.made.wait(TIMEOUT)
        transport.write(b"first\n")  # the writer thread takes it and is held in the port
        reply_now.set()  # the reader reads "ok" and answers with "next" meanwhile
        deadline = time.monotonic() + TIMEOUT
        while reply_now.is_set() and time.monotonic() < deadline:
            time.sleep(0.01)
        time.sleep(0.1)
        assert writes == []  # "next" did not overtake "first"
        hold_first.set()
        while len(writes) < 2 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert [data for data, _ in writes] == [b"first\n", b"next\n"]

        reply_now.set()  # nothing queued now: the reader writes the answer itself
        while len(writes) < 3 and time.monotonic() < deadline:
            time.sleep(0.01)
        assert writes[2] == (b"next\n", "serial-reader")
    finally:
        hold_first.set()
        transport.close()
    assert_serial_threads_end()
