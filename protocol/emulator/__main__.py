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
import re
import select
import signal
import sys
import threading
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from types import FrameType
from typing import Generic, TextIO, TypeVar

from protocol.clock import Clock, MonotonicClock
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.drill_firmware import (
    CommandDone,
    DrawnSegment,
    DrilledHole,
    DrillFirmware,
    ExecutedCommand,
    HomedAtPowerOn,
    PenEvent,
    StalledAtFrame,
    event_log_line,
)
from protocol.emulator.gcode_firmware import (
    GcodeFirmware,
    corexy_plotter_config,
    grbl_plotter_config,
    string_art_config,
)
from protocol.emulator.gcode_firmware import event_log_line as gcode_log_line
from protocol.emulator.stage_firmware import ExecutedCommand as StageCommand
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import ADC_MAX, Usb3Firmware
from protocol.emulator.wire import PacedWire
from protocol.stage.codec import CommandId
from protocol.usb3.codec import AxisId, StepSize, Thread

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

#: How long one loop iteration waits for host bytes: well inside a 5 ms control
#: cycle, so echoes leave within the 20 ms the contract allows.
POLL_SECONDS = 0.002

#: Host bytes a paced wire reads ahead of what it has delivered (a pty buffers about this).
INBOUND_LIMIT = 4096

#: A control line longer than this is nobody's command: it is dropped whole.
MAX_CONTROL_LINE = 1024


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


# --- the device's own controls, on standard input (--controls) -------------------------


class ControlError(ValueError):
    """A control line that cannot be applied; the message says why."""


_D = TypeVar("_D")


@dataclass(frozen=True)
class Control(Generic[_D]):
    """One control of a device: how to write it, what it does, and doing it."""

    usage: str
    summary: str
    apply: Callable[[_D, Sequence[str]], None]


def _one(args: Sequence[str], what: str) -> str:
    if len(args) != 1:
        raise ControlError(f"expected {what}")
    return args[0]


def _on_off(args: Sequence[str]) -> bool:
    word = _one(args, "on or off").lower()
    if word not in ("on", "off"):
        raise ControlError(f"expected on or off, got {word!r}")
    return word == "on"


def _number(args: Sequence[str], what: str) -> float:
    text = _one(args, what)
    try:
        value = float(text)
    except ValueError:
        raise ControlError(f"expected {what}, got {text!r}") from None
    if not math.isfinite(value):
        raise ControlError(f"expected {what}, got {text!r}")
    return value


_MENU_FIELD = re.compile(r"([MT])([0-9]{3})")


def _usb3_menu(unit: Usb3Firmware, args: Sequence[str]) -> None:
    """``menu M533``, ``menu M5 3 3``, ``menu T444`` or both: the digits of the wire."""
    spec = "".join(args).upper()
    if not spec or _MENU_FIELD.sub("", spec):
        raise ControlError("expected M<mx><my><mz> and/or T<tx><ty><tz>, e.g. M533 or M5 3 3")
    sizes: list[StepSize] | None = None
    threads: list[Thread] | None = None
    for kind, digits in _MENU_FIELD.findall(spec):
        values = [int(d) for d in digits]
        if kind == "M":
            if max(values) > max(StepSize):
                raise ControlError(f"step size digits are 0…{max(StepSize):d} (1/2^m step)")
            sizes = [StepSize(v) for v in values]
        else:
            if max(values) > max(Thread):
                raise ControlError(f"thread digits are 0…{max(Thread):d} (M2 … M10)")
            threads = [Thread(v) for v in values]
    unit.menu_set(step_sizes=sizes, threads=threads)


def _usb3_joystick(unit: Usb3Firmware, args: Sequence[str]) -> None:
    if len(args) != 2:
        raise ControlError("expected an axis and a reading")
    name, reading = args
    try:
        axis = AxisId[name.upper()]
    except KeyError:
        raise ControlError(f"no axis {name!r}: X, Y or Z") from None
    try:
        adc = int(reading)
    except ValueError:
        raise ControlError(f"the reading must be a whole number, got {reading!r}") from None
    unit.set_joystick(axis, adc)


def _gcode_alarm(board: GcodeFirmware, args: Sequence[str]) -> None:
    if len(args) > 1:
        raise ControlError("expected at most an alarm code")
    code = _number(args, "an alarm code") if args else 1.0
    if not (code.is_integer() and 1 <= code <= 99):
        raise ControlError(f"alarm codes are whole numbers 1…99, got {code:g}")
    board.trigger_alarm(int(code))


def _gcode_hold(board: GcodeFirmware, args: Sequence[str]) -> None:
    if args:
        raise ControlError("hold takes nothing")
    board.feed_hold()


def _gcode_reset(board: GcodeFirmware, args: Sequence[str]) -> None:
    if args:
        raise ControlError("reset takes nothing")
    board.soft_reset()


def _gcode_resume(board: GcodeFirmware, args: Sequence[str]) -> None:
    if args:
        raise ControlError("resume takes nothing")
    board.cycle_start()


def _stage_charger(stage: StageFirmware, args: Sequence[str]) -> None:
    stage.charger_connected = _on_off(args)


def _stage_usb(stage: StageFirmware, args: Sequence[str]) -> None:
    stage.usb_connected = _on_off(args)


def _stage_battery(stage: StageFirmware, args: Sequence[str]) -> None:
    percent = _number(args, "a charge in %")
    if not 0 <= percent <= 100:
        raise ControlError(f"the charge must be 0…100 %, got {percent:g}")
    stage.battery_charge = percent


def _stage_temperature(stage: StageFirmware, args: Sequence[str]) -> None:
    stage.board_temperature_c = _number(args, "a temperature in °C")


def _stage_rotation(stage: StageFirmware, args: Sequence[str]) -> None:
    stage.rotation_rate_dps = _number(args, "a rotation rate in °/s")


def _stage_button(stage: StageFirmware, args: Sequence[str]) -> None:
    if len(args) > 1 or (args and args[0].lower() != "long"):
        raise ControlError("button takes nothing, or 'long' (held: a reset)")
    stage.press_button(held_s=stage.config.reset_press_s if args else 0.1)


def _stage_kill(stage: StageFirmware, args: Sequence[str]) -> None:
    if args:
        raise ControlError("kill takes nothing")
    stage.kill_switch()


USB3_CONTROLS: dict[str, Control[Usb3Firmware]] = {
    "menu": Control(
        "menu [M<mx><my><mz>] [T<tx><ty><tz>]",
        "the unit's menu sets step sizes (0…5: 1/2^m) and/or threads (0…6: M2…M10)",
        _usb3_menu,
    ),
    "joystick": Control(
        f"joystick X|Y|Z <0…{ADC_MAX}>",
        "that axis's joystick now reads this (centred 500…524)",
        _usb3_joystick,
    ),
}

STAGE_CONTROLS: dict[str, Control[StageFirmware]] = {
    "charger": Control("charger on|off", "plug the charger in or pull it", _stage_charger),
    "usb": Control("usb on|off", "plug the USB cable in or pull it", _stage_usb),
    "battery": Control("battery <0…100>", "set the battery's charge in %", _stage_battery),
    "temperature": Control("temperature <°C>", "set the board temperature", _stage_temperature),
    "rotation": Control("rotation <°/s>", "set the IMU's rotation rate", _stage_rotation),
    "button": Control(
        "button [long]",
        "press the user button: on, or the shutdown sequence; long: reset the board",
        _stage_button,
    ),
    "kill": Control("kill", "the KillSwitch cuts the power (no shutdown sequence)", _stage_kill),
}

GCODE_CONTROLS: dict[str, Control[GcodeFirmware]] = {
    "alarm": Control(
        "alarm [<code>]", "a limit switch trips: ALARM:<code> (default 1)", _gcode_alarm
    ),
    "hold": Control("hold", "the board's feed-hold button (as '!')", _gcode_hold),
    "resume": Control("resume", "the board's cycle-start button (as '~')", _gcode_resume),
    "reset": Control(
        "reset",
        "the board's reset button (as Ctrl-X): it stops at once, forgets every line, "
        "says its banner",
        _gcode_reset,
    ),
}

#: The controls of each profile's device, for --help.
PROFILE_CONTROLS: Mapping[
    str,
    Mapping[str, Control[Usb3Firmware] | Control[StageFirmware] | Control[GcodeFirmware]],
] = {
    "usb3": USB3_CONTROLS,
    "xy-stage": STAGE_CONTROLS,
    "corexy-plotter": GCODE_CONTROLS,
    "grbl-plotter": GCODE_CONTROLS,
    "string-art": GCODE_CONTROLS,
}


@dataclass(frozen=True)
class BoundControl:
    """A control of one particular device: ``apply(args)`` acts on it."""

    usage: str
    apply: Callable[[Sequence[str]], None]


def controls_for(device: EmulatedDevice) -> dict[str, BoundControl]:
    """The controls ``device`` has, each bound to it; none for an unknown device."""
    if isinstance(device, Usb3Firmware):
        return {
            name: BoundControl(c.usage, functools.partial(c.apply, device))
            for name, c in USB3_CONTROLS.items()
        }
    if isinstance(device, StageFirmware):
        return {
            name: BoundControl(c.usage, functools.partial(c.apply, device))
            for name, c in STAGE_CONTROLS.items()
        }
    if isinstance(device, GcodeFirmware):
        return {
            name: BoundControl(c.usage, functools.partial(c.apply, device))
            for name, c in GCODE_CONTROLS.items()
        }
    return {}


def _controls_help() -> str:
    lines = ["controls, with --controls: one per line on standard input (help lists them)"]
    # Profiles that share their controls (the G-code machines) are listed together.
    shared: dict[int, list[str]] = {}
    for profile, controls in PROFILE_CONTROLS.items():
        shared.setdefault(id(controls), []).append(profile)
    for names in shared.values():
        controls = PROFILE_CONTROLS[names[0]]
        lines.append(f"  {', '.join(names)}:")
        for control in controls.values():
            lines += [f"    {control.usage}", f"        {control.summary}"]
    lines.append("  every profile: help")
    return "\n".join(lines)


class ControlChannel:
    """Control lines from ``fd`` (standard input), applied to the device line by line.

    The loop's ``select`` says when the descriptor is readable; :meth:`read`
    then takes what is there with one ``read``, which returns at once.  The
    descriptor itself is left blocking: it may be the developer's terminal,
    shared with the shell, which must not find it non-blocking afterwards.
    Nothing read here ever raises: a line that is not a control is reported
    on ``errors`` (standard error) in one line and ignored.
    """

    def __init__(self, device: EmulatedDevice, fd: int, errors: TextIO | None = None) -> None:
        self.fd = fd
        #: False once the input has ended; the device goes on being served.
        self.open = True
        self.applied = 0
        self.refused = 0
        self._controls = controls_for(device)
        self._errors = errors
        self._buffer = bytearray()
        self._discarding = False

    def read(self) -> None:
        """Take the bytes waiting on the descriptor and apply every complete line."""
        try:
            data = os.read(self.fd, 4096)
        except BlockingIOError:
            return
        except OSError as exc:
            self._say(f"controls closed: {exc.strerror or exc}")
            self.open = False
            return
        if not data:
            self.open = False
            if self._buffer and not self._discarding:
                self.execute(self._buffer.decode(errors="replace"))
            self._buffer.clear()
            self._say("end of the control input; the device is still served")
            return
        self._buffer += data
        while (end := self._buffer.find(b"\n")) >= 0:
            line = bytes(self._buffer[:end])
            del self._buffer[: end + 1]
            if self._discarding:
                self._discarding = False
            else:
                self.execute(line.decode(errors="replace"))
        if len(self._buffer) > MAX_CONTROL_LINE:
            self._buffer.clear()
            if not self._discarding:
                self._discarding = True
                self.refused += 1
                self._say(f"control line longer than {MAX_CONTROL_LINE} bytes dropped")

    def execute(self, line: str) -> bool:
        """Apply one control line; False, with a one-line error, when it is not one."""
        words = line.split()
        if not words or words[0].startswith("#"):
            return True
        name, args = words[0].lower(), words[1:]
        if name == "help":
            self._say(self.help())
            return True
        bound = self._controls.get(name)
        if bound is None:
            self.refused += 1
            self._say(f"unknown control {line.strip()!r} (try help)")
            return False
        try:
            bound.apply(args)
        except ValueError as exc:  # ControlError, or a value the firmware refuses
            self.refused += 1
            self._say(f"{name}: {exc} (usage: {bound.usage})")
            return False
        self.applied += 1
        return True

    def help(self) -> str:
        if not self._controls:
            return "this device has no controls"
        return "controls: " + "; ".join(c.usage for c in self._controls.values()) + "; help"

    def _say(self, text: str) -> None:
        print(f"stepdeck-emulator: {text}", file=self._errors or sys.stderr, flush=True)


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
        epilog=_controls_help(),
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


if __name__ == "__main__":
    sys.exit(main())
