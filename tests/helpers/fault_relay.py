"""One random fault per run on the cable between a station process and a device process.

A :class:`~tests.helpers.fault_bridge.FaultBridge` relays bytes both ways
between the device's pty and a pty of its own that the station opens; a
:class:`FaultRelay` is that bridge with exactly one :class:`Fault` armed at
a byte of one direction's stream.  When that byte goes by, the fault
happens:

* **drop** — 1…20 bytes from there are lost;
* **duplicate** — the message holding that byte arrives twice;
* **corrupt** — one bit of that byte is flipped;
* **delay** — that direction is held 2…5 s from there, then everything
  held arrives at once, in order (a congested USB adapter, a busy hub);
* **silence** — both directions carry nothing for 3…8 s, the port open (a
  pulled RS232 cable, a Bluetooth SPP link out of range);
* **reopen** — the station's port disappears, as a USB adapter pulled out,
  and comes back 1…5 s later at the same path; ``on_reopen`` runs first,
  or, with ``restart_on_open``, once the station has opened the port again
  (grbl-sim's board restarts then, as an Arduino's does when its port is
  opened: DTR resets it, and what the station sends during the boot is lost).

:func:`random_fault` draws the fault from a seed alone, so a seed printed by
a failing run is enough to run the same case again.
"""

from __future__ import annotations

import contextlib
import enum
import os
import random
import select
import termios
import time
import tty
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from tests.helpers.fault_bridge import Cut, Direction, FaultBridge


class FaultKind(enum.Enum):
    DROP = "drop"
    DUPLICATE = "duplicate"
    CORRUPT = "corrupt"
    DELAY = "delay"
    SILENCE = "silence"
    REOPEN = "reopen"


FAULT_KINDS = tuple(FaultKind)


@dataclass(frozen=True)
class Fault:
    """One fault: what, in which direction's stream, at which byte, and its size."""

    kind: FaultKind
    direction: Direction
    #: The fault happens as this byte of ``direction``'s stream (0 = the first) goes by.
    at_byte: int
    #: Bytes dropped (drop); the bit flipped (corrupt); seconds held, silent or unplugged.
    amount: float

    def __str__(self) -> str:
        where = f"at byte {self.at_byte} {self.direction.value}"
        if self.kind is FaultKind.DROP:
            return f"drop {int(self.amount)} byte(s) {where}"
        if self.kind is FaultKind.CORRUPT:
            return f"flip bit {int(self.amount)} {where}"
        if self.kind is FaultKind.DUPLICATE:
            return f"duplicate the message {where}"
        if self.kind is FaultKind.DELAY:
            return f"hold {self.direction.value} {self.amount:.1f} s {where}"
        if self.kind is FaultKind.SILENCE:
            return f"silence both ways {self.amount:.1f} s {where}"
        return f"pull the port for {self.amount:.1f} s {where}"


def random_fault(seed: int, traffic: dict[Direction, int], salt: str = "") -> Fault:
    """The fault of ``seed`` on a run whose clean traffic is ``traffic`` bytes each way.

    The kind goes round with the seed (six seeds in a row try each kind once);
    the rest is drawn from ``salt`` and the seed, so two dialects' runs of one
    seed differ.  The byte is drawn from the first nine tenths of a clean
    run's stream, so the fault nearly always happens before the job ends.
    """
    draw = random.Random(f"{salt}/{seed}")
    kind = FAULT_KINDS[seed % len(FAULT_KINDS)]
    direction = draw.choice((Direction.TO_DEVICE, Direction.TO_HOST))
    at_byte = draw.randrange(max(1, traffic[direction] * 9 // 10))
    amount: float
    if kind is FaultKind.DROP:
        amount = draw.randint(1, 20)
    elif kind is FaultKind.CORRUPT:
        amount = draw.randrange(8)
    elif kind is FaultKind.DUPLICATE:
        amount = 0
    elif kind is FaultKind.DELAY:
        amount = round(draw.uniform(2.0, 5.0), 2)
    elif kind is FaultKind.SILENCE:
        amount = round(draw.uniform(3.0, 8.0), 2)
    else:
        amount = round(draw.uniform(1.0, 5.0), 2)
    return Fault(kind, direction, at_byte, amount)


class FaultRelay(FaultBridge):
    """A bridge that injects ``fault`` once; see the module docstring."""

    def __init__(
        self,
        device: str,
        link: Path,
        fault: Fault | None,
        *,
        to_device_end: bytes,
        to_host_end: bytes,
        ignored_to_device: frozenset[int] = frozenset(),
        on_reopen: Callable[[], str | None] | None = None,
        restart_on_open: bool = False,
    ) -> None:
        self.fault = fault
        self._on_reopen = on_reopen
        self._restart_on_open = restart_on_open
        #: The station's port once back, until the station opens it (``restart_on_open``).
        self._unopened: tuple[int, str] | None = None
        #: How many times the station's opening of its port restarted the device.
        self.restarts = 0
        self._seen = {Direction.TO_DEVICE: 0, Direction.TO_HOST: 0}
        self._line = bytearray()  # the message under way in the fault's direction
        self._duplicating = False
        self._held = bytearray()
        self._release_at: float | None = None
        self._restore_at: float | None = None
        #: time.monotonic() when the fault happened, and when its effect ended.
        self.fired_at: float | None = None
        self.ended_at: float | None = None
        super().__init__(
            device,
            link,
            to_device_end=to_device_end,
            to_host_end=to_host_end,
            ignored_to_device=ignored_to_device,
        )

    # --- the fault ---------------------------------------------------------------------

    def _tick(self) -> None:
        now = time.monotonic()
        if self._release_at is not None and now >= self._release_at:
            self._release_at = None
            held, self._held = bytes(self._held), bytearray()
            assert self.fault is not None
            self._write(self.fault.direction, held)
            self.ended_at = now
        if self._restore_at is not None and now >= self._restore_at:
            self._restore_at = None
            pulled = self._cut is Cut.PULLED
            if pulled and self._on_reopen is not None and not self._restart_on_open:
                device = self._on_reopen()
                if device is not None:
                    self._swap_device(device)
            self._restore_locked()
            if pulled and self._restart_on_open:
                self._await_open()
            self.ended_at = now
        if self._unopened is not None and _opened(self._unopened[0]):
            self._restart_device()

    # --- a device that restarts when its port is opened (an Arduino's DTR) ----------------

    def _await_open(self) -> None:
        """Let go of the station's new port, so its opening shows (the master's hang-up ends)."""
        assert self._master is not None and self._slave is not None
        path = os.ttyname(self._slave)
        os.close(self._slave)
        self._unopened = (self._master, path)
        self._master = self._slave = None  # nothing relayed to a port nobody has open

    def _restart_device(self) -> None:
        """The station opened its port: the device restarts, deaf to the host while it boots."""
        assert self._unopened is not None
        master, path = self._unopened
        self._unopened = None
        if self._on_reopen is not None:
            device = self._on_reopen()
            if device is not None:
                self._swap_device(device)
        self.restarts += 1
        _drain(master)  # what the station sent during the boot (the bootloader's) is lost
        self._master = master
        self._slave = os.open(path, os.O_RDWR | os.O_NOCTTY)  # held again, as at the start

    def _unplug(self) -> None:
        if self._unopened is not None:
            with contextlib.suppress(OSError):
                os.close(self._unopened[0])
            self._unopened = None
        super()._unplug()

    def _restore_locked(self) -> None:
        """:meth:`restore` from the relaying loop, which holds the lock already."""
        if self._cut is Cut.PULLED:
            self._plug()
        self._cut = None
        for partial in self._partial.values():
            partial.clear()

    def _swap_device(self, device: str) -> None:
        with contextlib.suppress(OSError):
            os.close(self._device)
        self._device = os.open(device, os.O_RDWR | os.O_NOCTTY | os.O_NONBLOCK)
        # Not TCSAFLUSH (setraw's default): that throws away what the new device said
        # already — a restarted board's banner, whenever it beats this open.
        tty.setraw(self._device, termios.TCSANOW)

    def _relay(self, direction: Direction, data: bytes) -> None:
        """Pass ``data`` on with the fault applied where it falls (lock held)."""
        if self._cut is not None:
            self._seen[direction] += len(data)
            return
        fault = self.fault
        if fault is None or direction is not fault.direction:
            self._seen[direction] += len(data)
            self._write(direction, data)
            return
        out = bytearray()
        for byte in data:
            index = self._seen[direction]
            self._seen[direction] += 1
            if self._cut is not None:
                continue  # silenced or pulled by this very byte
            if index == fault.at_byte and self.fired_at is None:
                self.fired_at = time.monotonic()
                instead = self._fire(fault, byte, out)
                if instead is None:
                    continue
                byte = instead
            elif (
                fault.kind is FaultKind.DROP
                and self.fired_at is not None
                and fault.at_byte <= index < fault.at_byte + int(fault.amount)
            ):
                if index == fault.at_byte + int(fault.amount) - 1:
                    self.ended_at = time.monotonic()
                continue
            if self._release_at is not None:
                self._held.append(byte)
                continue
            out.append(byte)
            self._track_line(direction, byte, out)
        self._write(direction, bytes(out))

    def _fire(self, fault: Fault, byte: int, out: bytearray) -> int | None:
        """The fault happens at ``byte``: what goes on in its place (None: nothing)."""
        now = time.monotonic()
        if fault.kind is FaultKind.DROP:
            if int(fault.amount) == 1:
                self.ended_at = now
            return None
        if fault.kind is FaultKind.CORRUPT:
            self.ended_at = now
            return byte ^ (1 << int(fault.amount))
        if fault.kind is FaultKind.DUPLICATE:
            self._duplicating = True
            return byte
        if fault.kind is FaultKind.DELAY:
            self._release_at = now + fault.amount
            self._write(fault.direction, bytes(out))
            out.clear()
            self._held.append(byte)
            return None
        if fault.kind is FaultKind.SILENCE:
            self._write(fault.direction, bytes(out))
            out.clear()
            self._cut_locked(Cut.SILENT)
            self._restore_at = now + fault.amount
            return None
        self._write(fault.direction, bytes(out))
        out.clear()
        self._cut_locked(Cut.PULLED)
        self._restore_at = now + fault.amount
        return None

    def _track_line(self, direction: Direction, byte: int, out: bytearray) -> None:
        """Keep the message under way; a duplicated one is written again once it ends."""
        if byte in self._ignored[direction]:
            return
        self._line.append(byte)
        if not self._line.endswith(self._ends[direction]):
            return
        if self._duplicating:
            self._duplicating = False
            out.extend(self._line)
            self.ended_at = time.monotonic()
        self._line.clear()

    @property
    def seen(self) -> dict[Direction, int]:
        """Bytes that came to the relay each way (a clean run's figures size the faults)."""
        return dict(self._seen)


def _opened(master: int) -> bool:
    """Whether someone has the slave of pty ``master`` open (no hang-up on the master)."""
    poller = select.poll()
    poller.register(master, select.POLLIN | select.POLLHUP)
    return not any(events & select.POLLHUP for _, events in poller.poll(0))


def _drain(fd: int) -> None:
    """Throw away what waits to be read on ``fd``."""
    while select.select([fd], [], [], 0)[0]:
        try:
            if not os.read(fd, 4096):
                return
        except (BlockingIOError, OSError):
            return
