"""The ``stepdeck-emulator`` command: an emulated device behind a pseudo-terminal.

With it the station (or any serial terminal) can be tested over a real serial
device path, through the same serial transport and line discipline a USB or
SPP adapter would use, with no board attached::

    python -m protocol.emulator --profile xy-stage --pty
    python -m protocol.emulator --profile usb3 --pty

The profile picks the firmware; the pty ignores baud rates, so the usb3
unit's 19200 and the stage's 115200 need no setting here.

A pty gets a new number every time, so ``--link PATH`` also puts a symlink at
a fixed path (as socat's ``link=`` does): an emulator restarted on the same
link looks to the station like a cable plugged back in, and the station's
reconnection finds it there.
"""

from __future__ import annotations

import argparse
import os
import select
import signal
import sys
import threading
import tty
from collections.abc import Callable, Sequence
from pathlib import Path
from types import FrameType

from protocol.clock import Clock, MonotonicClock
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import Usb3Firmware

DeviceFactory = Callable[[Clock], EmulatedDevice]

#: The firmware each machine profile runs, built on the clock it is served on.
PROFILES: dict[str, DeviceFactory] = {"xy-stage": StageFirmware, "usb3": Usb3Firmware}
DEFAULT_PROFILE = "xy-stage"

#: How long one loop iteration waits for host bytes: well inside a 5 ms control
#: cycle, so echoes leave within the 20 ms the contract allows.
POLL_SECONDS = 0.002


def open_pty() -> tuple[int, int, str]:
    """A raw pseudo-terminal: ``(master_fd, slave_fd, slave_path)``.

    The slave stays open here so that a client closing and reopening the path
    neither loses the raw settings nor makes reads on the master fail with EIO.
    The master is non-blocking so that a host that stops reading can never stall
    the firmware's loop.
    """
    master, slave = os.openpty()
    tty.setraw(slave)
    os.set_blocking(master, False)
    return master, slave, os.ttyname(slave)


def pump(
    firmware: EmulatedDevice, fd: int, clock: Clock, outbox: bytearray, timeout: float
) -> None:
    """One loop iteration: host bytes in, control cycles up to now, replies out."""
    readable, _, _ = select.select([fd], [], [], timeout)
    if readable:
        try:
            data = os.read(fd, 4096)
        except BlockingIOError:
            data = b""
        firmware.receive(data)
    firmware.run_until(clock.now())
    _flush(fd, outbox)


def _flush(fd: int, outbox: bytearray) -> None:
    while outbox:
        try:
            written = os.write(fd, outbox)
        except BlockingIOError:
            # Nobody reads the terminal: stale echoes are worth nothing, drop them.
            outbox.clear()
            return
        del outbox[:written]


def serve(
    firmware: EmulatedDevice,
    fd: int,
    clock: Clock,
    should_stop: Callable[[], bool],
    poll: float = POLL_SECONDS,
) -> None:
    """Run ``firmware`` against the terminal ``fd`` until ``should_stop()``."""
    outbox = bytearray()
    firmware.set_output(outbox.extend)
    try:
        while not should_stop():
            pump(firmware, fd, clock, outbox, poll)
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


def run_on_pty(profile: str = DEFAULT_PROFILE, link: Path | None = None) -> int:
    """Serve ``profile``'s firmware on a new pty until SIGTERM or SIGINT; the exit status."""
    stop = threading.Event()

    def request_stop(signum: int, frame: FrameType | None) -> None:
        stop.set()

    signal.signal(signal.SIGTERM, request_stop)
    signal.signal(signal.SIGINT, request_stop)
    master, slave, path = open_pty()
    try:
        if link is not None:
            make_link(link, path)
    except LinkError as exc:
        _close_all(master, slave)
        print(f"stepdeck-emulator: {exc}", file=sys.stderr)
        return 2
    try:
        print(path, flush=True)
        where = f"{path} (linked from {link})" if link is not None else path
        print(f"{profile} emulator on {where}; Ctrl+C stops it", file=sys.stderr, flush=True)
        clock = MonotonicClock()
        serve(PROFILES[profile](clock), master, clock, stop.is_set)
    finally:
        if link is not None:
            remove_link(link, path)
        _close_all(master, slave)
    return 0


def _close_all(*fds: int) -> None:
    for fd in fds:
        os.close(fd)


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="stepdeck-emulator",
        description="Emulate a StepDeck machine's firmware on a pseudo-terminal.",
    )
    parser.add_argument("--profile", choices=sorted(PROFILES), default=DEFAULT_PROFILE)
    parser.add_argument(
        "--pty", action="store_true", help="serve the device on a new pseudo-terminal"
    )
    parser.add_argument(
        "--link",
        type=Path,
        metavar="PATH",
        help=(
            "also make PATH a symlink to the pty (implies --pty) and remove it on exit, "
            "so a restarted emulator keeps the same device path; a symlink left at PATH "
            "is replaced, a regular file never"
        ),
    )
    args = parser.parse_args(argv)
    if not args.pty and args.link is None:
        parser.print_usage(sys.stderr)
        print(
            "stepdeck-emulator: nothing to serve on; try --pty and open the printed path",
            file=sys.stderr,
        )
        return 2
    return run_on_pty(args.profile, args.link)


if __name__ == "__main__":
    sys.exit(main())
