"""A cable with faults on demand, between the station and the emulator process.

The emulator serves its device on a pty; the bridge opens that pty as the
far end of a cable and offers the station a pty of its own (behind a fixed
symlink, as ``--link`` does, so the station's reconnection finds it again).
Bytes are relayed both ways on a thread of the test process until the test
cuts the link, in one of two ways:

* **pulled** — the station's pty is closed and its path removed, as a USB
  adapter pulled out: the station's reads fail and its port is gone until
  :meth:`FaultBridge.restore` makes a new one at the same path;
* **silent** — both ptys stay open but every byte, either way, is dropped,
  as a pulled RS232 cable: only the station's own liveness can notice.

A cut can be *armed* to happen at a chosen message on the wire: a
:data:`Watch` sees every complete message (split at each direction's
terminator) and says whether the link goes before it (``DROP``: the message
is lost with everything after) or just after it (``PASS``: it arrives, what
follows is lost).  That is how a test cuts an operation when it is sent but
not received, received but not answered, or done with its reply lost.

While the link is cut the device's bytes are read and thrown away, so the
emulator never blocks on a full pty.
"""

from __future__ import annotations

import contextlib
import enum
import os
import select
import threading
import tty
from collections.abc import Callable
from pathlib import Path


class Direction(enum.Enum):
    TO_DEVICE = "to device"
    TO_HOST = "to host"


class Cut(enum.Enum):
    PULLED = "pulled"
    SILENT = "silent"


class Action(enum.Enum):
    DROP = "drop"  # the link goes before this message: it is lost
    PASS = "pass"  # the link goes right after this message has been relayed


#: Judges each complete message of an armed bridge (bytes without the terminator).
Watch = Callable[[Direction, bytes], Action | None]

POLL_S = 0.005


class FaultBridge:
    """Relays ``device`` (a pty path) to a pty the station opens at ``link``."""

    def __init__(
        self,
        device: str,
        link: Path,
        *,
        to_device_end: bytes,
        to_host_end: bytes,
        ignored_to_device: frozenset[int] = frozenset(),
    ) -> None:
        self.link = link
        self._ends = {Direction.TO_DEVICE: to_device_end, Direction.TO_HOST: to_host_end}
        self._ignored = {Direction.TO_DEVICE: ignored_to_device, Direction.TO_HOST: frozenset()}
        self._partial = {Direction.TO_DEVICE: bytearray(), Direction.TO_HOST: bytearray()}
        self._lock = threading.Lock()
        self._device = os.open(device, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        tty.setraw(self._device)
        self._drain_device()
        self._master: int | None = None
        self._slave: int | None = None
        self._cut: Cut | None = None
        self._watch: Watch | None = None
        self._watch_mode = Cut.SILENT
        #: Set when an armed cut has happened.
        self.fired = threading.Event()
        #: Bytes relayed each way (while the link was up), for a test's sanity checks.
        self.relayed = {Direction.TO_DEVICE: 0, Direction.TO_HOST: 0}
        self._stop = threading.Event()
        self._plug()
        self._thread = threading.Thread(target=self._run, name="fault-bridge", daemon=True)
        self._thread.start()

    # --- what a test does ------------------------------------------------------------

    @property
    def cut_mode(self) -> Cut | None:
        return self._cut

    def arm(self, watch: Watch, mode: Cut) -> None:
        """Cut the link in ``mode`` where ``watch`` says (see the module docstring)."""
        with self._lock:
            self.fired.clear()
            self._watch = watch
            self._watch_mode = mode

    def cut(self, mode: Cut) -> None:
        """Cut the link now."""
        with self._lock:
            self._cut_locked(mode)

    def restore(self) -> None:
        """The cable is back: a pulled port reappears at the same path; silence ends."""
        with self._lock:
            if self._cut is Cut.PULLED:
                self._plug()
            self._cut = None
            for partial in self._partial.values():
                partial.clear()

    def close(self) -> None:
        self._stop.set()
        self._thread.join(2.0)
        with self._lock:
            self._unplug()
            with contextlib.suppress(OSError):
                os.close(self._device)

    def _drain_device(self) -> None:
        """Drop what the device said to a cable that was unplugged (an earlier test's replies)."""
        while select.select([self._device], [], [], 0.02)[0]:
            try:
                if not os.read(self._device, 4096):
                    return
            except (BlockingIOError, OSError):
                return

    # --- the station's end -------------------------------------------------------------

    def _plug(self) -> None:
        master, slave = os.openpty()
        tty.setraw(slave)
        os.set_blocking(master, False)
        self._master, self._slave = master, slave
        staging = self.link.with_name(f".{self.link.name}.new")
        staging.unlink(missing_ok=True)
        staging.symlink_to(os.ttyname(slave))
        staging.replace(self.link)

    def _unplug(self) -> None:
        self.link.unlink(missing_ok=True)
        for fd in (self._master, self._slave):
            if fd is not None:
                with contextlib.suppress(OSError):
                    os.close(fd)
        self._master = self._slave = None

    def _cut_locked(self, mode: Cut) -> None:
        if self._cut is not None:
            return
        self._cut = mode
        self._watch = None
        if mode is Cut.PULLED:
            self._unplug()
        self.fired.set()

    # --- relaying ------------------------------------------------------------------------

    def _run(self) -> None:
        while not self._stop.is_set():
            with self._lock:
                self._tick()
                fds = [self._device] + ([self._master] if self._master is not None else [])
            try:
                readable, _, _ = select.select(fds, [], [], POLL_S)
            except (OSError, ValueError):
                continue  # a descriptor closed under us by a cut: look again
            for fd in readable:
                try:
                    data = os.read(fd, 4096)
                except (BlockingIOError, OSError):
                    continue
                if not data:
                    continue
                with self._lock:
                    if fd == self._device:
                        self._relay(Direction.TO_HOST, data)
                    elif fd == self._master:
                        self._relay(Direction.TO_DEVICE, data)

    def _tick(self) -> None:
        """Called on every turn of the relaying loop (lock held): a subclass's timed faults."""

    def _relay(self, direction: Direction, data: bytes) -> None:
        """Pass ``data`` on, cutting the link where an armed watch says (lock held)."""
        if self._cut is not None:
            return  # a cut link carries nothing
        out = bytearray()
        end = self._ends[direction]
        ignored = self._ignored[direction]
        partial = self._partial[direction]
        # Where the message being read starts in ``out`` (its head may have gone already).
        head = 0
        for byte in data:
            if byte in ignored:
                out.append(byte)
                continue
            if not partial:
                head = len(out)
            partial.append(byte)
            out.append(byte)
            if not partial.endswith(end):
                continue
            message = bytes(partial[: -len(end)])
            partial.clear()
            action = self._watch(direction, message) if self._watch is not None else None
            if action is None:
                continue
            if action is Action.DROP:
                del out[head:]
            self._write(direction, bytes(out))
            self._cut_locked(self._watch_mode)
            return
        self._write(direction, bytes(out))

    def _write(self, direction: Direction, data: bytes) -> None:
        if not data:
            return
        fd = self._device if direction is Direction.TO_DEVICE else self._master
        if fd is None:
            return
        view = memoryview(data)
        while view:
            try:
                written = os.write(fd, view)
            except BlockingIOError:
                select.select([], [fd], [], 0.05)
                continue
            except OSError:
                return  # the station's port was pulled meanwhile
            view = view[written:]
        self.relayed[direction] += len(data)
