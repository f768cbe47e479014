"""Codec of the three-axis USB unit's ``;``-terminated text (docs/protocols.md §2).

The codec is shared by the station (encodes commands, decodes replies) and the
firmware emulator (decodes commands, encodes replies), so both sides agree on
the wire format by construction.  Decoding never raises on wire input: bytes
up to and including the next ``;`` that do not form a message come back as
:class:`Rejected` (the unit answers those with ``?;``) and the reader carries
on with the next message.

Counts are always in 1/32-step units, whatever step size the unit is set to:
the step size only decides which counts a move can actually reach (multiples
of ``32 / 2^m``), and the thread only turns counts into millimetres.
"""

from __future__ import annotations

import enum
import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from typing import TypeVar

from protocol.framing import DecodeResult, LineDecoder
from protocol.framing import Rejected as Rejected  # re-exported for this dialect's readers

TERMINATOR = b";"
TERMINATOR_BYTE = ord(";")

#: Counts in one full step: every count on the wire is a 1/32 step.
COUNTS_PER_STEP = 32
#: Full steps per motor revolution.
STEPS_PER_REV = 200
COUNTS_PER_REV = COUNTS_PER_STEP * STEPS_PER_REV

#: Digits of a move command's count field, always all of them.
MOVE_DIGITS = 15
MAX_COUNT = 10**MOVE_DIGITS - 1

#: The longest valid message, ``X-`` + 15 digits + ``;``.  A run of this many
#: bytes without a terminator can no longer become a message and is dropped, so
#: a stuck link cannot grow the buffer without bound.
MAX_MESSAGE = 2 + MOVE_DIGITS + 1

#: Bytes skipped between messages: a terminal (or a firmware that ends its
#: replies with CR LF) may put them there, and they carry no meaning.
_WHITESPACE = frozenset(b" \t\r\n")

_T = TypeVar("_T")
#: One value per axis, in X, Y, Z order.
Triple = tuple[_T, _T, _T]


class AxisId(enum.IntEnum):
    """The unit's three axes; the value indexes every per-axis triple."""

    X = 0
    Y = 1
    Z = 2

    @property
    def letter(self) -> bytes:
        return self.name.encode()


class StepSize(enum.IntEnum):
    """Step size of one axis; the value is the wire digit m (1/2^m step)."""

    FULL = 0
    HALF = 1
    QUARTER = 2
    EIGHTH = 3
    SIXTEENTH = 4
    THIRTY_SECOND = 5

    @property
    def exponent(self) -> int:
        return int(self.value)

    @property
    def divisor(self) -> int:
        """Pulses per full step (1, 2, 4 … 32)."""
        return 1 << self.value

    @property
    def counts_per_pulse(self) -> int:
        """1/32-step counts one driver pulse moves: a move is made of whole pulses."""
        return COUNTS_PER_STEP >> self.value

    @property
    def label(self) -> str:
        """How the unit's own menu shows it: ``1``, ``1/2`` … ``1/32``."""
        return "1" if self is StepSize.FULL else f"1/{self.divisor}"


_PITCH_MM = (0.4, 0.5, 0.7, 0.8, 1.0, 1.25, 1.5)


class Thread(enum.IntEnum):
    """Metric lead screw of one axis; the value is the wire digit 0…6."""

    M2 = 0
    M3 = 1
    M4 = 2
    M5 = 3
    M6 = 4
    M8 = 5
    M10 = 6

    @property
    def pitch_mm(self) -> float:
        """Travel of one screw revolution (coarse ISO pitch)."""
        return _PITCH_MM[self.value]


# -- conversions -----------------------------------------------------------------------


def count_per_mm(thread: Thread) -> float:
    """Counts in one millimetre; independent of the step size, which counts never depend on."""
    return COUNTS_PER_REV / thread.pitch_mm


def count_to_mm(count: int, thread: Thread) -> float:
    """Millimetres a position or move count stands for: count / 32 / 200 * pitch."""
    return count * thread.pitch_mm / COUNTS_PER_REV


#: The unit's top pulse rate (its speed table's fastest entry), pulses per second.
TOP_PULSE_RATE = 300.0


def top_speed_mm_s(step_size: StepSize, thread: Thread) -> float:
    """An axis's top speed: the pulse rate is fixed, so finer steps and threads are slower."""
    return TOP_PULSE_RATE * step_size.counts_per_pulse * thread.pitch_mm / COUNTS_PER_REV


def nearest_reachable_count(mm: float, step_size: StepSize, thread: Thread) -> int:
    """The count of whole pulses closest to ``mm`` (signed like ``mm``).

    The unit rounds a count that is not a multiple of its pulse size *down*, so
    the station rounds to the nearest whole pulse first and asks only for what
    the unit can do; the position it then shows is the one the unit will
    report.  Ties round away from zero, so ``-mm`` always gives ``-count``.
    """
    if not math.isfinite(mm):
        raise ValueError(f"distance must be finite, got {mm!r}")
    unit = step_size.counts_per_pulse
    pulses = math.floor(abs(mm) * count_per_mm(thread) / unit + 0.5)
    count = pulses * unit
    return -count if mm < 0 else count


# -- messages ----------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class SetDirection:
    """``D<sx><sy><sz>;``: the direction (+1 or -1 per axis) of the moves that follow."""

    signs: Triple[int]

    def __post_init__(self) -> None:
        if len(self.signs) != 3 or any(s not in (1, -1) for s in self.signs):
            raise ValueError(f"directions must be three of +1/-1, got {self.signs!r}")


@dataclass(frozen=True, slots=True)
class Move:
    """``X|Y|Z<15 digits>;``: move one axis by ``count`` (≥ 0) in its current direction."""

    axis: AxisId
    count: int

    def __post_init__(self) -> None:
        if not 0 <= self.count <= MAX_COUNT:
            raise ValueError(f"move count {self.count} outside 0…{MAX_COUNT}")


@dataclass(frozen=True, slots=True)
class StepSizes:
    """``M<mx><my><mz>;``: set (host) or report (unit) the step size of each axis."""

    sizes: Triple[StepSize]


@dataclass(frozen=True, slots=True)
class Threads:
    """``T<tx><ty><tz>;``: set (host) or report (unit) the thread of each axis."""

    threads: Triple[Thread]


@dataclass(frozen=True, slots=True)
class ZeroAll:
    """``C;``: declare every axis's present position to be 0."""


@dataclass(frozen=True, slots=True)
class GetSettings:
    """``G;``: ask for ``M…;T…;``."""


@dataclass(frozen=True, slots=True)
class StopAll:
    """``S;``: decelerate every axis to a stop (extension; only for profiles declaring it)."""


@dataclass(frozen=True, slots=True)
class Position:
    """``X|Y|Z<signed count>;``: where an axis is, in counts from its zero."""

    axis: AxisId
    count: int

    def __post_init__(self) -> None:
        if not -MAX_COUNT <= self.count <= MAX_COUNT:
            raise ValueError(f"position {self.count} outside ±{MAX_COUNT}")


@dataclass(frozen=True, slots=True)
class NotUnderstood:
    """``?;``: the unit could not parse something it was sent."""


Command = SetDirection | Move | StepSizes | Threads | ZeroAll | GetSettings | StopAll
"""What the host sends."""
Reply = Position | StepSizes | Threads | NotUnderstood
"""What the unit sends; ``M…;T…;`` arrives as a StepSizes then a Threads."""
Message = Command | Reply


# -- encoding ----------------------------------------------------------------------------

_SIGN_CHARS = {1: b"+", -1: b"-"}


def _digits(values: Sequence[int]) -> bytes:
    return b"".join(b"%d" % v for v in values)


def encode(message: Message) -> bytes:
    """The wire bytes of any message, ``;`` included."""
    match message:
        case SetDirection(signs):
            return b"D" + b"".join(_SIGN_CHARS[s] for s in signs) + TERMINATOR
        case Move(axis, count):
            return b"%s%0*d;" % (axis.letter, MOVE_DIGITS, count)
        case StepSizes(sizes):
            return b"M" + _digits(sizes) + TERMINATOR
        case Threads(threads):
            return b"T" + _digits(threads) + TERMINATOR
        case Position(axis, count):
            return b"%s%d;" % (axis.letter, count)
        case ZeroAll():
            return b"C;"
        case GetSettings():
            return b"G;"
        case StopAll():
            return b"S;"
        case NotUnderstood():
            return b"?;"
    raise TypeError(f"not a usb3 message: {message!r}")


def encode_settings(sizes: Triple[StepSize], threads: Triple[Thread]) -> bytes:
    """The unit's settings report, ``M…;T…;``."""
    return encode(StepSizes(sizes)) + encode(Threads(threads))


def move_commands(counts: Sequence[int]) -> list[Command]:
    """Commands that move each axis by a signed count (X, Y, Z; 0 = leave it).

    One ``D`` sets all three directions at once, so it comes first and every
    axis that moves follows; axes left alone get ``+``.  Nothing at all for a
    move of nothing.
    """
    if len(counts) != 3:
        raise ValueError(f"need three counts (X, Y, Z), got {len(counts)}")
    if not any(counts):
        return []
    signs = (
        -1 if counts[0] < 0 else 1,
        -1 if counts[1] < 0 else 1,
        -1 if counts[2] < 0 else 1,
    )
    moves: list[Command] = [Move(axis, abs(c)) for axis, c in zip(AxisId, counts, strict=True) if c]
    return [SetDirection(signs), *moves]


# -- decoding ----------------------------------------------------------------------------

_AXIS_LETTERS = {ord(a.name): a for a in AxisId}
_SIGN_BYTES = {ord("+"): 1, ord("-"): -1}
_DIGIT_BYTES = frozenset(b"0123456789")


def _triple_of_digits(field: bytes, highest: int) -> Triple[int] | None:
    if len(field) != 3 or any(b not in _DIGIT_BYTES for b in field):
        return None
    x, y, z = (b - ord("0") for b in field)
    if max(x, y, z) > highest:
        return None
    return x, y, z


def _parse_settings(head: int, field: bytes) -> StepSizes | Threads | str:
    """``M`` or ``T`` and its three digits; a reason string if they are not valid."""
    if head == ord("M"):
        digits = _triple_of_digits(field, StepSize.THIRTY_SECOND)
        if digits is None:
            return "step sizes must be three digits 0…5"
        return StepSizes((StepSize(digits[0]), StepSize(digits[1]), StepSize(digits[2])))
    digits = _triple_of_digits(field, Thread.M10)
    if digits is None:
        return "threads must be three digits 0…6"
    return Threads((Thread(digits[0]), Thread(digits[1]), Thread(digits[2])))


_SIMPLE_COMMANDS: dict[bytes, Command] = {b"C": ZeroAll(), b"G": GetSettings(), b"S": StopAll()}


def _parse_command_body(body: bytes) -> Command | str:
    """A host command from the bytes before ``;``, or the reason it is not one."""
    if not body:
        return "empty command"
    head, field = body[0], body[1:]
    if head in _AXIS_LETTERS:
        if len(field) != MOVE_DIGITS or any(b not in _DIGIT_BYTES for b in field):
            return f"a move count must be exactly {MOVE_DIGITS} digits"
        return Move(_AXIS_LETTERS[head], int(field))
    if head == ord("D"):
        if len(field) != 3 or any(b not in _SIGN_BYTES for b in field):
            return "directions must be three of + or -"
        x, y, z = (_SIGN_BYTES[b] for b in field)
        return SetDirection((x, y, z))
    if head in (ord("M"), ord("T")):
        return _parse_settings(head, field)
    return _SIMPLE_COMMANDS.get(body, "unknown command")


def _parse_reply_body(body: bytes) -> Reply | str:
    """A unit reply from the bytes before ``;``, or the reason it is not one.

    Lenient where the contract leaves the form open: a position may carry a
    ``+`` and leading zeros, since "signed count" fixes neither.
    """
    if not body:
        return "empty reply"
    head, field = body[0], body[1:]
    if head in _AXIS_LETTERS:
        digits = field[1:] if field[:1] in (b"+", b"-") else field
        if not 1 <= len(digits) <= MOVE_DIGITS or any(b not in _DIGIT_BYTES for b in digits):
            return f"a position must be a signed count of 1…{MOVE_DIGITS} digits"
        count = int(digits)
        return Position(_AXIS_LETTERS[head], -count if field[:1] == b"-" else count)
    if head in (ord("M"), ord("T")):
        return _parse_settings(head, field)
    if body == b"?":
        return NotUnderstood()
    return "unknown reply"


_M = TypeVar("_M")


def _decode(buffer: bytes | bytearray, parse: Callable[[bytes], _M | str]) -> DecodeResult[_M]:
    skip = 0
    while skip < len(buffer) and buffer[skip] in _WHITESPACE:
        skip += 1
    if skip:
        return skip, None
    end = buffer.find(TERMINATOR)
    if end < 0:
        if len(buffer) >= MAX_MESSAGE:
            return len(buffer), Rejected(bytes(buffer), "too long without ';'")
        return 0, None
    used = end + 1
    raw = bytes(buffer[:used])
    parsed = parse(raw[:-1])
    return used, Rejected(raw, parsed) if isinstance(parsed, str) else parsed


def decode_command(buffer: bytes | bytearray) -> DecodeResult[Command]:
    """Take the first host command off ``buffer`` (the emulator's side of the wire).

    Returns ``(used, result)``: ``used == 0`` means "need more bytes"; otherwise
    ``used`` bytes were consumed and ``result`` is the command, the
    :class:`Rejected` bytes, or None when only whitespace between messages was
    skipped.  Pure: counting is the caller's business.
    """
    return _decode(buffer, _parse_command_body)


def decode_reply(buffer: bytes | bytearray) -> DecodeResult[Reply]:
    """Take the first unit reply off ``buffer`` (the station's side); as :func:`decode_command`."""
    return _decode(buffer, _parse_reply_body)


class CommandDecoder(LineDecoder[Command]):
    """Host commands from a byte stream (the emulator's reader)."""

    def __init__(self) -> None:
        super().__init__(decode_command, TERMINATOR)


class ReplyDecoder(LineDecoder[Reply]):
    """Unit replies from a byte stream (the station's reader)."""

    def __init__(self) -> None:
        super().__init__(decode_reply, TERMINATOR)
