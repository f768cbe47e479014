"""The emulated device's own controls, as control lines on standard input (``--controls``).

What the station only ever sees as what a device then reports (the usb3
unit's menu and joystick, the stage's charger, USB and buttons, a G-code
board's limit switch and buttons), a test or a developer sets here, one
line at a time; ``help`` lists a device's controls.  A line that is not a
control is reported in one line and changes nothing.
"""

from __future__ import annotations

import functools
import math
import os
import re
import sys
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from typing import Generic, TextIO, TypeVar

from protocol.emulator.device import EmulatedDevice
from protocol.emulator.gcode_firmware import (
    GcodeFirmware,
)
from protocol.emulator.stage_firmware import StageFirmware
from protocol.emulator.usb3_firmware import ADC_MAX, Usb3Firmware
from protocol.usb3.codec import AxisId, StepSize, Thread

#: A control line longer than this is nobody's command: it is dropped whole.
MAX_CONTROL_LINE = 1024


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


def controls_help() -> str:
    """Every profile's controls, for ``--help``."""
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
