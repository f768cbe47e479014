"""The ``stepdeck-emulator`` command: an emulated device behind a pseudo-terminal.

With it the station (or any serial terminal) can be tested over a real serial
device path, through the same serial transport and line discipline a USB or
SPP adapter would use, with no board attached::

    python -m protocol.emulator --profile xy-stage --pty
    python -m protocol.emulator --profile usb3 --pty
    python -m protocol.emulator --profile pcb-drill --pty
    python -m protocol.emulator --profile corexy-plotter --pty

The profile picks the firmware; the pty ignores baud rates, so the usb3
unit's and the drill's 19200 and the stage's 115200 need no setting here.
The G-code profiles (``corexy-plotter``, ``grbl-plotter``, ``string-art``)
run one GRBL-like firmware with each machine's kinematics, replies and pen.

A pty gets a new number every time, so ``--link PATH`` also puts a symlink at
a fixed path (as socat's ``link=`` does): an emulator restarted on the same
link looks to the station like a cable plugged back in, and the station's
reconnection finds it there.

``--controls`` also reads control lines on standard input, in the same loop
as the terminal, so a test or a developer can act on the device's own
controls (the usb3 unit's menu and joystick, the stage's charger and USB)
that the station only ever sees as what the device then reports::

    menu M533 T444        usb3: the unit's menu sets step sizes and/or threads
    joystick X 1023       usb3: the X joystick reads 1023 (centred 500…524)
    charger on            xy-stage: plug the charger in (off unplugs it)
    button long           xy-stage: hold the user button (a reset); kill: the KillSwitch
    alarm 1               G-code profiles: a limit switch trips (ALARM:1)

``help`` lists the controls of the running profile; a line that is not a
control gets a one-line error on standard error and changes nothing.

``--time-scale F`` runs the firmware's clock F times faster than real time,
for tests and dry runs that would otherwise wait out the unit's slow moves.

``--log PATH`` appends one line per command the firmware executed (its
command log: time, axis, command, data, accepted), so a test can check what
the machine really did across station restarts::

    12.345000 0 MOVE_ABS 20000 1

The pcb-drill firmware logs its events instead: every line received (or
refused), every procedure done, every hole drilled, every pen movement and
every stroke the pen drew (``drawn X… Y… to X… Y…``), positions in
microsteps, so a job's holes can be checked against the file::

    4.000000 received X1234
    5.604200 done X1234
    7.484700 hole X1234 Y567

The G-code firmwares log one JSON object per line: lines received (with the
bytes then unacknowledged), replies, moves ended, pen changes, dwells, holds,
resets::

    {"t":1.005,"event":"line","text":"G1 X10 F600","unacknowledged":12}
    {"t":1.005,"event":"reply","text":"ok","line":"G1 X10 F600"}
    {"t":2.04,"event":"move","kind":"G1","pos":{"X":10.0,"Y":0.0,"Z":0.0},"pen":false}
"""

from __future__ import annotations

import argparse
import functools
import math
import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from pathlib import Path
from types import FrameType

from protocol.clock import Clock, MonotonicClock
from protocol.emulator.controls import ControlChannel, controls_help
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.drill_firmware import (
    DrillFirmware,
)
from protocol.emulator.gcode_firmware import (
    GcodeFirmware,
    corexy_plotter_config,
    grbl_plotter_config,
    string_art_config,
)
from protocol.emulator.pty import (
    CommandLogFile,
    LinkError,
    make_link,
    open_pty,
    pty_unavailable,
    remove_link,
    serve,
)
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import Usb3Firmware
from protocol.emulator.wire import PacedWire

DeviceFactory = Callable[[Clock], EmulatedDevice]

#: The firmware each machine profile runs, built on the clock it is served on.
PROFILES: dict[str, DeviceFactory] = {
    "xy-stage": StageFirmware,
    "usb3": Usb3Firmware,
    "pcb-drill": DrillFirmware,
    "corexy-plotter": functools.partial(GcodeFirmware, config=corexy_plotter_config()),
    "grbl-plotter": functools.partial(GcodeFirmware, config=grbl_plotter_config()),
    "string-art": functools.partial(GcodeFirmware, config=string_art_config()),
}
DEFAULT_PROFILE = "xy-stage"


class ScaledClock:
    """Real time run ``factor`` times faster from the moment it was made (``--time-scale``)."""

    def __init__(self, factor: float, base: Clock | None = None) -> None:
        if not (math.isfinite(factor) and factor > 0):
            raise ValueError(f"the time scale must be a positive number, got {factor!r}")
        self.factor = factor
        self._base: Clock = base if base is not None else MonotonicClock()
        self._origin = self._base.now()

    def now(self) -> float:
        return self._origin + (self._base.now() - self._origin) * self.factor


def run_on_pty(
    profile: str = DEFAULT_PROFILE,
    link: Path | None = None,
    *,
    controls: bool = False,
    time_scale: float = 1.0,
    log_path: Path | None = None,
    baud: int | None = None,
) -> int:
    """Serve ``profile``'s firmware on a new pty until SIGTERM or SIGINT; the exit status.

    With ``controls`` standard input carries control lines (see :class:`ControlChannel`);
    ``time_scale`` runs the firmware's clock that many times faster than real time;
    ``log_path`` gets a line per executed command (see :class:`CommandLogFile`);
    ``baud`` paces the pty like a serial line of that speed (see :class:`PacedWire`).
    """
    stop = threading.Event()

    def request_stop(signum: int, frame: FrameType | None) -> None:
        stop.set()

    control_fd: int | None = None
    if controls:
        try:
            control_fd = sys.stdin.fileno()
        except (AttributeError, ValueError, OSError):
            print("stepdeck-emulator: --controls needs a standard input", file=sys.stderr)
            return 2
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
        extras = "".join(
            (
                "; control lines on stdin (help lists them)" if controls else "",
                f"; time runs x{time_scale:g}" if time_scale != 1.0 else "",
                f"; paced at {baud} baud" if baud else "",
            )
        )
        print(
            f"{profile} emulator on {where}{extras}; Ctrl+C stops it", file=sys.stderr, flush=True
        )
        clock: Clock = ScaledClock(time_scale) if time_scale != 1.0 else MonotonicClock()
        firmware = PROFILES[profile](clock)
        channel = ControlChannel(firmware, control_fd) if control_fd is not None else None
        log = CommandLogFile(firmware, log_path) if log_path is not None else None
        try:
            wire = PacedWire(baud, time.monotonic()) if baud else None
            serve(firmware, master, clock, stop.is_set, controls=channel, log=log, wire=wire)
        finally:
            if log is not None:
                log.close()
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
        epilog=controls_help(),
        formatter_class=argparse.RawDescriptionHelpFormatter,
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
    parser.add_argument(
        "--controls",
        action="store_true",
        help=(
            "also read control lines on standard input and act on the device's own "
            "controls (listed below); a line that is not one is reported on stderr and ignored"
        ),
    )
    parser.add_argument(
        "--time-scale",
        type=_time_scale,
        default=1.0,
        metavar="F",
        help="run the firmware's clock F times faster than real time (default 1)",
    )
    parser.add_argument(
        "--log",
        type=Path,
        metavar="PATH",
        help="append one line per command the firmware executes to PATH",
    )
    parser.add_argument(
        "--baud",
        type=int,
        metavar="N",
        help=(
            "pace the pty like a serial line at N baud, 10 bits a byte (a pty has no speed "
            "of its own; for streaming measurements)"
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
    reason = pty_unavailable()
    if reason is not None:
        print(
            "stepdeck-emulator: --pty needs a POSIX system (Linux, macOS, BSD) for its "
            f"pseudo-terminal: {reason}; the station's built-in emulator (stepdeck "
            "--emulator) works everywhere",
            file=sys.stderr,
        )
        return 2
    return run_on_pty(
        args.profile,
        args.link,
        controls=args.controls,
        time_scale=args.time_scale,
        log_path=args.log,
        baud=args.baud if args.baud and args.baud > 0 else None,
    )


def _time_scale(text: str) -> float:
    try:
        factor = float(text)
    except ValueError:
        factor = math.nan
    if not (math.isfinite(factor) and factor > 0):
        raise argparse.ArgumentTypeError(f"must be a positive number, got {text!r}")
    return factor
