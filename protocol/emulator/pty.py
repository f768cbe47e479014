"""Serving an emulated device on a pseudo-terminal: the loop, the paced wire, the link.

The loop reads host bytes off the pty's master, runs the firmware's control
cycles up to now and writes its replies back; on a paced wire (``--baud``)
bytes cross as a serial line of that speed would carry them.  ``--link``
keeps a fixed path pointing at the pty; ``--log`` appends what the firmware
did.  Pseudo-terminals are POSIX: ``tty`` is imported when serving starts,
so that importing this module works everywhere.
"""

from __future__ import annotations

import os
import select
import time
from collections.abc import Callable, Sequence
from pathlib import Path

from protocol.clock import Clock
from protocol.emulator.controls import ControlChannel
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.drill_firmware import (
    CommandDone,
    DrawnSegment,
    DrilledHole,
    ExecutedCommand,
    HomedAtPowerOn,
    PenEvent,
    StalledAtFrame,
    event_log_line,
)
from protocol.emulator.gcode_firmware import event_log_line as gcode_log_line
from protocol.emulator.stage_firmware import ExecutedCommand as StageCommand
from protocol.emulator.wire import PacedWire
from protocol.stage.codec import CommandId

#: How long one loop iteration waits for host bytes: well inside a 5 ms control
#: cycle, so echoes leave within the 20 ms the contract allows.
POLL_SECONDS = 0.002

#: Host bytes a paced wire reads ahead of what it has delivered (a pty buffers about this).
INBOUND_LIMIT = 4096


class CommandLogFile:
    """Appends the firmware's newly executed commands to a file (``--log``).

    The firmware keeps only its latest commands in memory; polling that log
    after every loop iteration (a few commands at most) and remembering the
    last entry written turns it into a complete record on disk.  Each batch
    is flushed at once, so whoever reads the file sees what the device did
    even while it keeps running.  A firmware with an ``event_log`` (the
    drill's: commands, holes, pen) is logged from that instead, since what
    it did matters more than what it was told.
    """

    def __init__(self, firmware: EmulatedDevice, path: Path) -> None:
        self._firmware = firmware
        self._attribute = "event_log" if hasattr(firmware, "event_log") else "command_log"
        self._handle = path.open("a", encoding="utf-8")
        self._last: object | None = None

    def write_new(self) -> None:
        entries: Sequence[object] = getattr(self._firmware, self._attribute, ())
        start = 0
        if self._last is not None:
            for index in range(len(entries) - 1, -1, -1):
                if entries[index] is self._last:
                    start = index + 1
                    break
        new = entries[start:]
        if not new:
            return
        self._handle.writelines(_log_line(entry) for entry in new)
        self._handle.flush()
        self._last = new[-1]

    def close(self) -> None:
        self.write_new()
        self._handle.close()


def _log_line(entry: object) -> str:
    if isinstance(
        entry,
        ExecutedCommand
        | CommandDone
        | DrilledHole
        | PenEvent
        | DrawnSegment
        | HomedAtPowerOn
        | StalledAtFrame,
    ):
        return event_log_line(entry) + "\n"
    if isinstance(entry, dict):  # the G-code firmwares' events
        return gcode_log_line(entry) + "\n"
    if isinstance(entry, StageCommand):
        try:
            name = CommandId(entry.command).name
        except ValueError:
            name = f"{entry.command:02X}"
        return f"{entry.time:.6f} {entry.axis} {name} {entry.data} {int(entry.accepted)}\n"
    return f"{getattr(entry, 'time', 0.0):.6f} {getattr(entry, 'command', entry)}\n"


def pty_unavailable() -> str | None:
    """Why this system cannot serve on a pseudo-terminal; None when it can.

    Pseudo-terminals (and ``tty``, ``termios`` underneath) are POSIX: Linux, macOS,
    the BSDs.  They are imported when serving starts, never at the top, so that
    ``--help`` and every import of this module work on Windows too.
    """
    try:
        import tty  # noqa: F401  (only asked whether it is there)
    except ImportError as exc:
        return f"this Python has no terminal control ({exc})"
    if not hasattr(os, "openpty"):
        return "this Python has no os.openpty"
    return None


def open_pty() -> tuple[int, int, str]:
    """A raw pseudo-terminal: ``(master_fd, slave_fd, slave_path)``.

    The slave stays open here so that a client closing and reopening the path
    neither loses the raw settings nor makes reads on the master fail with EIO.
    The master is non-blocking so that a host that stops reading can never stall
    the firmware's loop.
    """
    import tty  # POSIX only: see pty_unavailable

    master, slave = os.openpty()
    tty.setraw(slave)
    os.set_blocking(master, False)
    return master, slave, os.ttyname(slave)


def pump(
    firmware: EmulatedDevice,
    fd: int,
    clock: Clock,
    outbox: bytearray,
    timeout: float,
    controls: ControlChannel | None = None,
    wire: PacedWire | None = None,
) -> None:
    """One loop iteration: host bytes and control lines in, cycles up to now, replies out."""
    watched = []
    allowed = 4096
    if wire is not None:
        allowed = wire.readable(time.monotonic())
        timeout = min(timeout, wire.wait_for_byte())
    if allowed > 0:
        watched.append(fd)
    if controls is not None and controls.open:
        watched.append(controls.fd)
    readable, _, _ = select.select(watched, [], [], timeout)
    if fd in readable:
        try:
            data = os.read(fd, allowed)
        except BlockingIOError:
            data = b""
        if wire is not None:
            wire.took(len(data))
        firmware.receive(data)
    if controls is not None and controls.fd in readable:
        controls.read()
    firmware.run_until(clock.now())
    _flush(fd, outbox, wire)


def _flush(fd: int, outbox: bytearray, wire: PacedWire | None = None) -> None:
    while outbox:
        room = len(outbox) if wire is None else wire.writable(time.monotonic())
        if room <= 0:
            return  # the rest goes as the line frees up
        try:
            written = os.write(fd, outbox[:room])
        except BlockingIOError:
            # Nobody reads the terminal: stale echoes are worth nothing, drop them.
            outbox.clear()
            return
        del outbox[:written]
        if wire is not None:
            wire.gave(written)


class PacedLine:
    """The serving loop's side of a paced wire: bytes in transit each way, and when to wake.

    Waking for every byte the wire carries (87 µs at 115 200 baud) kept the
    emulator's process busy for a third of a core while a host streamed, on a
    machine whose other core ran the station.  Here host bytes are read off the
    pty as soon as they come and handed to the firmware as the wire would have
    delivered them, by the time its next control cycle runs (it reads none
    before); replies leave as the wire carries them, the loop waking when the
    next whole reply line has gone.  So it wakes per cycle, per host write and
    per reply line.
    """

    def __init__(self, wire: PacedWire) -> None:
        self.wire = wire
        #: Host bytes read off the pty that the wire has not delivered yet.
        self.inbound = bytearray()
        self._inbound_waiting = 0
        self._outbound_waiting = 0

    def timeout(self, firmware: EmulatedDevice, clock: Clock, outbox: bytearray) -> float:
        """Seconds until the next thing is due: a control cycle, or a reply line carried."""
        timeout = POLL_SECONDS
        next_cycle = getattr(firmware, "next_cycle_at", None)
        if callable(next_cycle):
            scale = float(getattr(clock, "factor", 1.0))
            timeout = min(timeout, max(next_cycle() - clock.now(), 0.0) / scale)
        elif self.inbound:
            timeout = min(timeout, self.wire.wait_for_byte())
        if outbox:
            end = outbox.find(b"\n")
            count = len(outbox) if end < 0 else end + 1
            timeout = min(timeout, self.wire.reply_wait(time.monotonic(), count))
        return timeout

    def deliver(self, firmware: EmulatedDevice) -> None:
        """Hand the firmware the host bytes the wire has delivered by now."""
        now = time.monotonic()
        count = min(self.wire.readable(now, self._inbound_waiting), len(self.inbound))
        if count:
            firmware.receive(bytes(self.inbound[:count]))
            del self.inbound[:count]
            self.wire.took(count)
        self._inbound_waiting = len(self.inbound)

    def flush(self, fd: int, outbox: bytearray) -> None:
        """Write the reply bytes the wire has carried by now."""
        if outbox:
            room = min(self.wire.writable(time.monotonic(), self._outbound_waiting), len(outbox))
            if room > 0:
                try:
                    written = os.write(fd, outbox[:room])
                except BlockingIOError:
                    outbox.clear()  # nobody reads the terminal: stale replies are worth nothing
                    written = 0
                del outbox[:written]
                self.wire.gave(written)
        self._outbound_waiting = len(outbox)


def pump_paced(
    firmware: EmulatedDevice,
    fd: int,
    clock: Clock,
    outbox: bytearray,
    line: PacedLine,
    controls: ControlChannel | None = None,
) -> None:
    """One loop iteration on a paced wire (see :class:`PacedLine`)."""
    # A host far ahead of the wire is held back by the pty's own buffer, as before.
    watched = [fd] if len(line.inbound) < INBOUND_LIMIT else []
    if controls is not None and controls.open:
        watched.append(controls.fd)
    readable, _, _ = select.select(watched, [], [], line.timeout(firmware, clock, outbox))
    if fd in readable:
        try:
            line.inbound += os.read(fd, 4096)
        except BlockingIOError:
            pass
    if controls is not None and controls.fd in readable:
        controls.read()
    line.deliver(firmware)
    firmware.run_until(clock.now())
    line.flush(fd, outbox)


def serve(
    firmware: EmulatedDevice,
    fd: int,
    clock: Clock,
    should_stop: Callable[[], bool],
    poll: float = POLL_SECONDS,
    controls: ControlChannel | None = None,
    log: CommandLogFile | None = None,
    wire: PacedWire | None = None,
) -> None:
    """Run ``firmware`` against the terminal ``fd`` until ``should_stop()``."""
    outbox = bytearray()
    firmware.set_output(outbox.extend)
    line = PacedLine(wire) if wire is not None else None
    try:
        while not should_stop():
            if line is not None:
                pump_paced(firmware, fd, clock, outbox, line, controls)
            else:
                pump(firmware, fd, clock, outbox, poll, controls)
            if log is not None:
                log.write_new()
    finally:
        firmware.set_output(None)


class LinkError(Exception):
    """The ``--link`` path cannot be used; the message says why."""


def make_link(link: Path, device: str) -> None:
    """Point ``link`` at ``device``.

    A symlink already there is taken to be left by an emulator that died
    (SIGKILL leaves no chance to remove it) and is replaced; anything else is
    somebody's file and is never overwritten.  The new link is renamed into
    place, so a station retrying the path never catches it missing.
    """
    if link.exists() and not link.is_symlink():
        raise LinkError(f"{link} exists and is not a symlink; not replacing it")
    staging = link.with_name(f".{link.name}.{os.getpid()}.new")
    try:
        staging.unlink(missing_ok=True)
        staging.symlink_to(device)
        staging.replace(link)
    except OSError as exc:
        staging.unlink(missing_ok=True)
        raise LinkError(f"cannot create the link {link}: {exc.strerror or exc}") from exc


def remove_link(link: Path, device: str) -> None:
    """Remove ``link`` if it still points at ``device`` (a newer emulator may own it now)."""
    try:
        if link.is_symlink() and os.readlink(link) == device:
            link.unlink()
    except OSError:
        pass
