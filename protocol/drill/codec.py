"""Codec of the PCB drill's one-letter procedures over RS232 (docs/protocols.md §3).

The codec is shared by the station (encodes commands, decodes replies) and the
firmware emulator (decodes commands, encodes replies), so both sides agree on
the wire format by construction.  Decoding never raises on wire input: a line
that is not a message comes back as :class:`Rejected` (the device answers it
with ``E<letter>``, see :func:`error_letter`) and the reader carries on with
the next line.

The two directions end their lines differently, as the reference machine
does: the host ends a command with CR alone (what the Visual Basic tool's
terminal sends on Enter), the device ends every reply with CR LF.  Each reader
resynchronises on the byte its direction is sure to end with (CR for
commands, LF for replies) and is lenient about the other one: an LF after a
command's CR and a reply whose CR went missing are both accepted, since a
serial terminal or an adapter may add or drop them.

Positions are absolute microsteps from the machine's zero and never negative:
the host converts millimetres and does all rounding (docs/protocols.md §3).
"""

from __future__ import annotations

import enum
from collections.abc import Callable
from dataclasses import dataclass
from typing import TypeVar

from protocol.framing import DecodeResult, LineDecoder
from protocol.framing import Rejected as Rejected  # re-exported for this dialect's readers

COMMAND_TERMINATOR = b"\r"
REPLY_TERMINATOR = b"\r\n"

#: Every procedure the device knows, by its letter.
COMMAND_LETTERS = "NXYVKZP"
#: The procedures that carry a position (absolute microsteps from zero).
POSITION_LETTERS = "XY"

#: Digits of a position field at most: 999 999 microsteps is about 50 m of
#: travel at 19.8 per mm, far beyond any machine of the family, and the bound
#: keeps a stuck link from growing the reader's buffer.
MAX_DIGITS = 6
MAX_POSITION = 10**MAX_DIGITS - 1

#: The longest valid command line, ``X999999\r``.  A run of this many bytes
#: without a CR can no longer become a command and is rejected.
MAX_COMMAND = 1 + MAX_DIGITS + 1
#: The longest valid reply line, ``RX\r\n``; as :data:`MAX_COMMAND`.
MAX_REPLY = 4

#: The letter an ``E`` reply carries for a line whose first byte is no letter.
UNKNOWN_LETTER = "?"

_DIGIT_BYTES = frozenset(b"0123456789")
_ASCII_LETTERS = frozenset("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz")
#: Bytes between lines that carry no meaning: empty lines, and the LF that may
#: follow a command's CR (or stand before a reply's text after a lost line).
_LINE_ENDS = frozenset(b"\r\n")


class ReplyKind(enum.Enum):
    """What a reply says about the command its letter names; the value is the wire byte."""

    RECEIVED = "R"
    DONE = "D"
    ERROR = "E"


# -- messages ----------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Command:
    """One host command: ``letter`` from :data:`COMMAND_LETTERS`, ``value`` for X and Y only.

    ``value`` is the absolute target in microsteps from zero (0…:data:`MAX_POSITION`)
    for ``X`` and ``Y`` and must be None for every other letter, so that a
    command that reaches the wire is always one the device accepts.
    """

    letter: str
    value: int | None = None

    def __post_init__(self) -> None:
        if len(self.letter) != 1 or self.letter not in COMMAND_LETTERS:
            raise ValueError(f"unknown drill command {self.letter!r}; known: {COMMAND_LETTERS}")
        if self.letter in POSITION_LETTERS:
            if (
                not isinstance(self.value, int)
                or isinstance(self.value, bool)
                or not 0 <= self.value <= MAX_POSITION
            ):
                raise ValueError(
                    f"{self.letter} needs a position of 0…{MAX_POSITION} microsteps, "
                    f"got {self.value!r}"
                )
        elif self.value is not None:
            raise ValueError(f"{self.letter} takes no value, got {self.value!r}")


@dataclass(frozen=True, slots=True)
class Reply:
    """One device reply: ``R``/``D``/``E`` and the letter of the command it concerns.

    Receipt and done name a known command; an error names whatever letter the
    malformed line started with (``?`` when it started with no letter), so
    the operator's terminal shows which line the device refused.
    """

    kind: ReplyKind
    letter: str

    def __post_init__(self) -> None:
        if self.kind is ReplyKind.ERROR:
            if len(self.letter) != 1 or (
                self.letter not in _ASCII_LETTERS and self.letter != UNKNOWN_LETTER
            ):
                raise ValueError(f"an error names one ASCII letter or '?', got {self.letter!r}")
        elif len(self.letter) != 1 or self.letter not in COMMAND_LETTERS:
            raise ValueError(
                f"{self.kind.name.lower()} names a command letter from {COMMAND_LETTERS}, "
                f"got {self.letter!r}"
            )


# -- helpers -------------------------------------------------------------------------------


#: Convenience commands for the procedures that take no value.
HOME = Command("N")
DRILL = Command("V")
PEN_DOWN = Command("K")
PEN_UP = Command("Z")
PARK = Command("P")


def move_x(position: int) -> Command:
    """``X<position>``: X to that absolute microstep position."""
    return Command("X", position)


def move_y(position: int) -> Command:
    """``Y<position>``: Y to that absolute microstep position."""
    return Command("Y", position)


def error_letter(raw: bytes) -> str:
    """The letter an ``E`` reply names for a refused line: its first byte if a letter, else ``?``.

    Leading line ends are skipped first, so an over-long run that began after
    an empty line still names its own first letter.
    """
    text = raw.lstrip(b"\r\n")
    first = chr(text[0]) if text else ""
    return first if first in _ASCII_LETTERS else UNKNOWN_LETTER


def error_reply(rejected: Rejected) -> Reply:
    """The ``E`` reply the device gives to a line it could not parse."""
    return Reply(ReplyKind.ERROR, error_letter(rejected.raw))


# -- encoding ----------------------------------------------------------------------------


def encode_command(command: Command) -> bytes:
    """The wire bytes of a host command, CR included: ``X1234\\r``, ``N\\r``."""
    if command.value is None:
        return command.letter.encode("ascii") + COMMAND_TERMINATOR
    return b"%s%d\r" % (command.letter.encode("ascii"), command.value)


def encode_reply(reply: Reply) -> bytes:
    """The wire bytes of a device reply, CR LF included: ``RX\\r\\n``."""
    return (reply.kind.value + reply.letter).encode("ascii") + REPLY_TERMINATOR


# -- decoding ----------------------------------------------------------------------------

_M = TypeVar("_M")

_REPLY_KINDS = {ord(kind.value): kind for kind in ReplyKind}


def _parse_command_line(body: bytes) -> Command | str:
    """A host command from the bytes before its CR, or the reason it is not one."""
    if not body:
        return "empty command"
    head, field = chr(body[0]), body[1:]
    if head not in COMMAND_LETTERS:
        return "unknown command"
    if head not in POSITION_LETTERS:
        return Command(head) if not field else f"{head} takes no value"
    if not field:
        return f"{head} needs a position"
    if field[:1] == b"-":
        return "a position is never negative"
    if len(field) > MAX_DIGITS or any(b not in _DIGIT_BYTES for b in field):
        return f"a position must be 1…{MAX_DIGITS} decimal digits"
    return Command(head, int(field))


def _parse_reply_line(body: bytes) -> Reply | str:
    """A device reply from the bytes before its LF (and CR), or the reason it is not one."""
    if len(body) != 2:
        return "a reply is a kind letter and a command letter"
    kind = _REPLY_KINDS.get(body[0])
    if kind is None:
        return "unknown reply kind"
    letter = chr(body[1])
    if kind is ReplyKind.ERROR:
        if letter not in _ASCII_LETTERS and letter != UNKNOWN_LETTER:
            return "an error names a letter or '?'"
    elif letter not in COMMAND_LETTERS:
        return "unknown command letter"
    return Reply(kind, letter)


def _decode_line(
    buffer: bytes | bytearray,
    terminator: int,
    longest: int,
    parse: Callable[[bytes], _M | str],
) -> DecodeResult[_M]:
    skip = 0
    while skip < len(buffer) and buffer[skip] in _LINE_ENDS:
        skip += 1
    if skip:
        return skip, None
    end = buffer.find(terminator)
    if end < 0:
        if len(buffer) >= longest:
            return len(buffer), Rejected(bytes(buffer), "too long without a line end")
        return 0, None
    used = end + 1
    raw = bytes(buffer[:used])
    parsed = parse(raw[:-1])
    return used, Rejected(raw, parsed) if isinstance(parsed, str) else parsed


def _reply_body(body: bytes) -> Reply | str:
    """A reply's text without the CR before its LF, which may have gone missing."""
    return _parse_reply_line(body[:-1] if body[-1:] == b"\r" else body)


def decode_command(buffer: bytes | bytearray) -> DecodeResult[Command]:
    """Take the first host command off ``buffer`` (the emulator's side of the wire).

    Returns ``(used, result)``: ``used == 0`` means "need more bytes"; otherwise
    ``used`` bytes were consumed and ``result`` is the command, the
    :class:`Rejected` line (CR included), or None when only line ends between
    commands were skipped (an empty line, the LF after a CR).  Pure: counting
    is the caller's business.
    """
    return _decode_line(buffer, COMMAND_TERMINATOR[0], MAX_COMMAND, _parse_command_line)


def decode_reply(buffer: bytes | bytearray) -> DecodeResult[Reply]:
    """Take the first device reply off ``buffer`` (the station's side); as :func:`decode_command`.

    A reply ends with LF; the CR before it may be missing.  A stray CR
    between replies is skipped.
    """
    return _decode_line(buffer, REPLY_TERMINATOR[-1], MAX_REPLY, _reply_body)


class CommandDecoder(LineDecoder[Command]):
    """Host commands from a byte stream (the emulator's reader)."""

    def __init__(self) -> None:
        super().__init__(decode_command, COMMAND_TERMINATOR)


class ReplyDecoder(LineDecoder[Reply]):
    """Device replies from a byte stream (the station's reader)."""

    def __init__(self) -> None:
        super().__init__(decode_reply, REPLY_TERMINATOR[-1:])
