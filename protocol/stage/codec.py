"""Codec of the XY stage's command/echo/subscriber frames (docs/protocols.md §1).

The codec is shared by the station and the firmware emulator, so both sides
agree on the wire format by construction.  Decoding never raises on wire
input: a line that is not a valid frame comes back as :class:`Rejected` (with
a reason for the developer log) and the caller counts it; the reader then
carries on with the next line.
"""

from __future__ import annotations

import enum
import functools
from dataclasses import dataclass

# Rejected is re-exported: readers of this dialect import it from here.
from protocol.framing import (
    LineDecoder,
)
from protocol.framing import (
    Rejected as Rejected,
)

TERMINATOR = b"\n"
COMMAND_START = ord(">")
ECHO_START = ord("<")
CHECKSUM_MARK = ord("*")

DATA_MIN = -99_999
DATA_MAX = 999_999
DUMMY = 0

#: A line longer than any frame a 16-axis device could send is noise; it is
#: dropped without waiting for its terminator so a stuck link cannot grow the
#: buffer without bound.
MAX_LINE = 7 + 8 * 16 + 6 + 64


class CommandId(enum.IntEnum):
    """Command IDs of table 1.2 (one per axis packet)."""

    NOP = 0x00
    STOP = 0x01
    JOG = 0x02
    MOVE_ABS = 0x03
    MOVE_REL = 0x04
    HOME = 0x05
    SET_POS = 0x06
    SPEED = 0x07
    ESTOP = 0x08
    SLEEP = 0x09
    READ = 0x0F
    WRITE_FAST_SPEED = 0x10
    WRITE_SLOW_SPEED = 0x11
    WRITE_ACCELERATION = 0x12
    WRITE_START_SPEED = 0x13
    WRITE_IRUN = 0x14
    WRITE_IHOLD = 0x15
    WRITE_MICROSTEPS = 0x16
    WRITE_LEAD = 0x17
    WRITE_STEPS_PER_REV = 0x18
    WRITE_TRAVEL = 0x19


class EchoType(enum.IntEnum):
    """What an echo packet's DATA holds (1.3): position, velocity or a parameter."""

    POSITION = 0x0
    VELOCITY = 0x1
    FAST_SPEED = 0x2
    SLOW_SPEED = 0x3
    ACCELERATION = 0x4
    START_SPEED = 0x5
    IRUN = 0x6
    IHOLD = 0x7
    MICROSTEPS = 0x8
    LEAD = 0x9
    STEPS_PER_REV = 0xA
    TRAVEL = 0xB
    ENCODER = 0xC


#: The parameters of table 1.4, in TYPE order.
PARAMETERS: tuple[EchoType, ...] = tuple(t for t in EchoType if t >= EchoType.FAST_SPEED)
#: Parameters the host may write (the encoder position is read-only).
WRITABLE_PARAMETERS: tuple[EchoType, ...] = tuple(t for t in PARAMETERS if t != EchoType.ENCODER)

_WRITE_OFFSET = 0x0E


def write_command(parameter: EchoType) -> CommandId:
    """The WRITE command ID for a parameter TYPE (ID = TYPE + 0x0E)."""
    if parameter not in WRITABLE_PARAMETERS:
        raise ValueError(f"parameter {parameter!r} is not writable")
    return CommandId(parameter + _WRITE_OFFSET)


def written_parameter(command: int) -> EchoType | None:
    """The parameter a WRITE command ID writes, or None for any other ID."""
    if CommandId.WRITE_FAST_SPEED <= command <= CommandId.WRITE_TRAVEL:
        return EchoType(command - _WRITE_OFFSET)
    return None


class AxisStatus(enum.IntEnum):
    """Axis states shown in the info panel (1.3)."""

    IDLE = 0x0
    ACCELERATING = 0x1
    CONSTANT_SPEED = 0x2
    DECELERATING = 0x3
    TARGET_REACHED = 0x4
    STOPPED = 0x5
    HOMING = 0x6
    END_SWITCH = 0x7
    BLOCKED_BATTERY = 0x8
    BLOCKED_CHARGER = 0x9
    BLOCKED_USB = 0xA
    SLEEPING = 0xB
    DRIVER_FAULT = 0xC
    PARAMETER_REJECTED = 0xE
    UNKNOWN_COMMAND = 0xF


BLOCKED_STATUSES = frozenset(
    {AxisStatus.BLOCKED_BATTERY, AxisStatus.BLOCKED_CHARGER, AxisStatus.BLOCKED_USB}
)
MOVING_STATUSES = frozenset(
    {
        AxisStatus.ACCELERATING,
        AxisStatus.CONSTANT_SPEED,
        AxisStatus.DECELERATING,
        AxisStatus.HOMING,
    }
)


class Subscriber(enum.IntEnum):
    """Subscriber variables (1.5) the host can ask for, one per frame."""

    NONE = 0x00
    BATTERY_VOLTAGE = 0x01
    BATTERY_CHARGE = 0x02
    CHARGING_CURRENT = 0x03
    BOARD_TEMPERATURE = 0x04
    ROTATION = 0x05
    YAW_RATE = 0x06
    DEVICE_FLAGS = 0x07
    X_ENCODER = 0x08
    Y_ENCODER = 0x09
    FIRMWARE_VERSION = 0x0A
    REJECTED_FRAMES = 0x0B
    UNKNOWN = 0xFF


class DeviceFlag(enum.IntFlag):
    """Bits of the DEVICE_FLAGS subscriber."""

    CHARGER = 1 << 0
    USB = 1 << 1
    LOW_BATTERY = 1 << 2
    SLEEPING = 1 << 3
    DATA_SESSION = 1 << 4


@dataclass(frozen=True, slots=True)
class CommandPacket:
    command: int
    data: int = DUMMY


@dataclass(frozen=True, slots=True)
class CommandFrame:
    packets: tuple[CommandPacket, ...]
    subscriber: int = Subscriber.NONE


@dataclass(frozen=True, slots=True)
class EchoPacket:
    type: int
    status: int
    data: int


@dataclass(frozen=True, slots=True)
class EchoFrame:
    packets: tuple[EchoPacket, ...]
    subscriber: int = Subscriber.NONE
    sdata: int = 0


Frame = CommandFrame | EchoFrame


def command_frame_length(axes: int) -> int:
    return 1 + 8 * axes + 2 + 3 + 1


def echo_frame_length(axes: int) -> int:
    return 1 + 8 * axes + 2 + 6 + 3 + 1


def checksum(body: bytes) -> int:
    """XOR of every byte before ``*``, the start character included."""
    ck = 0
    for byte in body:
        ck ^= byte
    return ck


def encode_data(value: int) -> bytes:
    """Six characters: ``000000``…``999999`` or ``-00001``…``-99999``."""
    if not DATA_MIN <= value <= DATA_MAX:
        raise ValueError(f"DATA {value} outside {DATA_MIN}…{DATA_MAX}")
    if value < 0:
        return b"-%05d" % -value
    return b"%06d" % value


def decode_data(field: bytes) -> int | None:
    """The integer a six-character DATA field holds, or None if malformed."""
    if len(field) != 6:
        return None
    if field[:1] == b"-":
        digits = field[1:]
        if not digits.isdigit():
            return None
        value = -int(digits)
        return value if value != 0 else None
    return int(field) if field.isdigit() else None


def _hex(value: int, width: int) -> bytes:
    if not 0 <= value < 16**width:
        raise ValueError(f"{value} does not fit {width} hex digit(s)")
    return b"%0*X" % (width, value)


def _finish(body: bytes) -> bytes:
    return body + b"*" + _hex(checksum(body), 2) + TERMINATOR


def encode_command(frame: CommandFrame) -> bytes:
    body = bytearray(b">")
    for packet in frame.packets:
        body += _hex(packet.command, 2) + encode_data(packet.data)
    body += _hex(frame.subscriber, 2)
    return _finish(bytes(body))


def encode_echo(frame: EchoFrame) -> bytes:
    body = bytearray(b"<")
    for packet in frame.packets:
        body += _hex(packet.type, 1) + _hex(packet.status, 1) + encode_data(packet.data)
    body += _hex(frame.subscriber, 2) + encode_data(frame.sdata)
    return _finish(bytes(body))


_HEX_DIGITS = frozenset(b"0123456789ABCDEF")


def _parse_hex(field: bytes) -> int | None:
    # Uppercase only, as the contract says; int(..., 16) alone would accept "0x", "+1", " a".
    if not field or any(b not in _HEX_DIGITS for b in field):
        return None
    return int(field, 16)


def parse_line(line: bytes, axes: int) -> Frame | Rejected:
    """Parse one terminated line (``\\n`` included) into a frame for ``axes`` axes."""
    if not line.endswith(TERMINATOR):
        return Rejected(line, "no terminator")
    start = line[0]
    expected = {COMMAND_START: command_frame_length(axes), ECHO_START: echo_frame_length(axes)}
    if start not in expected:
        return Rejected(line, "bad start character")
    if len(line) != expected[start]:
        return Rejected(line, f"bad length {len(line)} (expected {expected[start]})")
    if line[-4] != CHECKSUM_MARK:
        return Rejected(line, "no checksum mark")
    ck = _parse_hex(line[-3:-1])
    if ck is None:
        return Rejected(line, "malformed checksum")
    body = line[:-4]
    if checksum(body) != ck:
        return Rejected(line, "checksum mismatch")
    if start == COMMAND_START:
        return _parse_command(line, body, axes)
    return _parse_echo(line, body, axes)


def _parse_command(line: bytes, body: bytes, axes: int) -> Frame | Rejected:
    packets = []
    for i in range(axes):
        chunk = body[1 + 8 * i : 9 + 8 * i]
        command = _parse_hex(chunk[:2])
        if command is None:
            return Rejected(line, f"non-hex ID in packet {i}")
        data = decode_data(chunk[2:])
        if data is None:
            return Rejected(line, f"malformed DATA in packet {i}")
        packets.append(CommandPacket(command, data))
    subscriber = _parse_hex(body[1 + 8 * axes :])
    if subscriber is None:
        return Rejected(line, "non-hex subscriber ID")
    return CommandFrame(tuple(packets), subscriber)


def _parse_echo(line: bytes, body: bytes, axes: int) -> Frame | Rejected:
    packets = []
    for i in range(axes):
        chunk = body[1 + 8 * i : 9 + 8 * i]
        type_ = _parse_hex(chunk[:1])
        status = _parse_hex(chunk[1:2])
        if type_ is None or status is None:
            return Rejected(line, f"non-hex TYPE/STATUS in packet {i}")
        data = decode_data(chunk[2:])
        if data is None:
            return Rejected(line, f"malformed DATA in packet {i}")
        packets.append(EchoPacket(type_, status, data))
    tail = body[1 + 8 * axes :]
    subscriber = _parse_hex(tail[:2])
    if subscriber is None:
        return Rejected(line, "non-hex subscriber ID")
    sdata = decode_data(tail[2:])
    if sdata is None:
        return Rejected(line, "malformed subscriber DATA")
    return EchoFrame(tuple(packets), subscriber, sdata)


def decode(buffer: bytes | bytearray, axes: int = 2) -> tuple[int, Frame | Rejected | None]:
    """Take the first line off ``buffer``.

    Returns ``(used, result)``: ``used == 0`` means "need more bytes" (result is
    None); otherwise ``used`` bytes were consumed and ``result`` is the frame or
    the :class:`Rejected` bytes.  Pure: counting is the caller's business.
    """
    end = buffer.find(TERMINATOR)
    if end < 0:
        if len(buffer) > MAX_LINE:
            return len(buffer), Rejected(bytes(buffer), "line too long")
        return 0, None
    used = end + 1
    if end > MAX_LINE:
        # Refused whole as it would be in pieces: never parse the tail of an over-long run.
        return used, Rejected(bytes(buffer[:used]), "line too long")
    return used, parse_line(bytes(buffer[:used]), axes)


class StageDecoder(LineDecoder[Frame]):
    """Stateful reader for a byte stream: buffers, resynchronises, counts.

    Transports hand over bytes in arbitrary pieces (20-byte BLE notifications,
    several frames per serial read); this keeps the leftover between calls, and
    drops the rest of an over-long run up to its terminator, so a frame is
    accepted or refused the same way wherever the stream was cut.
    """

    def __init__(self, axes: int = 2) -> None:
        super().__init__(functools.partial(decode, axes=axes), TERMINATOR)
        self.axes = axes

    @property
    def frames(self) -> int:
        return self.messages
