"""What the emulated drill firmware did, as events: for its logs, the tests and ``--log``."""

from __future__ import annotations

from dataclasses import dataclass

from protocol.drill.codec import Command, Rejected


@dataclass(frozen=True, slots=True)
class ExecutedCommand:
    """One line the device received, when: accepted ones were answered ``R``, the rest ``E``."""

    time: float
    command: Command | Rejected
    accepted: bool


@dataclass(frozen=True, slots=True)
class CommandDone:
    """A procedure finished and was answered ``D``, at ``time``."""

    time: float
    command: Command


@dataclass(frozen=True, slots=True)
class DrilledHole:
    """A hole the drill actually made: at the bottom of its stroke, at (x, y) microsteps."""

    time: float
    x: int
    y: int

    @property
    def position(self) -> tuple[int, int]:
        return self.x, self.y


@dataclass(frozen=True, slots=True)
class PenEvent:
    """The pen finished going down (``down``) or up, at (x, y) microsteps."""

    time: float
    down: bool
    x: int
    y: int


@dataclass(frozen=True, slots=True)
class DrawnSegment:
    """The pen, down, moved from (x0, y0) to (x1, y1) microsteps: a stroke on the paper."""

    time: float
    x0: int
    y0: int
    x1: int
    y1: int


@dataclass(frozen=True, slots=True)
class HomedAtPowerOn:
    """The power-on homing finished (no command asked for it, so no reply), at ``time``."""

    time: float


@dataclass(frozen=True, slots=True)
class StalledAtFrame:
    """A move ran the carriage into the frame (FIDELITY S2-29): it stood there while the
    firmware stepped on, so its counter reads ``lost`` microsteps past where the carriage is.

    ``axis`` is ``"X"`` or ``"Y"``, ``end`` ``"far"`` (the frame opposite the sensor) or
    ``"home"`` (the frame behind the sensor, reached when lost steps made the counter lie).
    """

    time: float
    axis: str
    end: str
    lost: int
    counter: int


DrillEvent = (
    ExecutedCommand
    | CommandDone
    | DrilledHole
    | PenEvent
    | DrawnSegment
    | HomedAtPowerOn
    | StalledAtFrame
)
"""Everything :attr:`DrillFirmware.event_log` records, in the order it happened."""


def event_log_line(event: DrillEvent) -> str:
    """One line of text for the emulator's ``--log`` file, time first."""
    match event:
        case ExecutedCommand(time, Rejected(raw), _):
            return f"{time:.6f} refused {raw!r}"
        case ExecutedCommand(time, Command(letter, value), _):
            return f"{time:.6f} received {letter}{'' if value is None else value}"
        case CommandDone(time, Command(letter, value)):
            return f"{time:.6f} done {letter}{'' if value is None else value}"
        case DrilledHole(time, x, y):
            return f"{time:.6f} hole X{x} Y{y}"
        case PenEvent(time, down, x, y):
            return f"{time:.6f} pen {'down' if down else 'up'} X{x} Y{y}"
        case DrawnSegment(time, x0, y0, x1, y1):
            return f"{time:.6f} drawn X{x0} Y{y0} to X{x1} Y{y1}"
        case HomedAtPowerOn(time):
            return f"{time:.6f} homed at power-on"
        case StalledAtFrame(time, axis, end, lost, counter):
            return (
                f"{time:.6f} stalled {axis} at the {end} frame: {lost} steps lost, "
                f"counter {axis}{counter}"
            )
    raise TypeError(f"not a drill event: {event!r}")
