"""The stage's half of the developer pane: echoes composed and injected, frames in words.

The stage's original tool had a developer extension (Shift+V) that could
fake received echoes; this composes them from the pane's fields, checks them
as the station's decoder would, injects them as if received, and puts every
command and echo frame into words for the frame log.  It needs the station
(injection goes through its session), so it sits above the dialect's package.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.developer.raw_text import escape_raw
from app.local_numbers import local_number
from app.machines.stage.echoes import STATUS_TEXT
from app.machines.stage.parameters import BY_TYPE
from app.station import Station
from protocol.stage.codec import (
    DATA_MAX,
    DATA_MIN,
    AxisStatus,
    CommandFrame,
    CommandId,
    DeviceFlag,
    EchoFrame,
    EchoPacket,
    EchoType,
    Subscriber,
    encode_echo,
)

# --- words for the wire's numbers ---------------------------------------------------


def _lower_first(text: str) -> str:
    return text[:1].lower() + text[1:]


#: What an echo packet's TYPE says its DATA holds, in words (docs/protocols.md §1.3).
TYPE_TEXT: dict[int, str] = {
    EchoType.POSITION: str(QT_TRANSLATE_NOOP("StageWords", "position")),
    EchoType.VELOCITY: str(QT_TRANSLATE_NOOP("StageWords", "velocity")),
    **{t: p.label for t, p in BY_TYPE.items()},
}

#: Subscriber variables in words (docs/protocols.md §1.5).
SUBSCRIBER_TEXT: dict[int, str] = {
    Subscriber.NONE: str(QT_TRANSLATE_NOOP("StageWords", "none")),
    Subscriber.BATTERY_VOLTAGE: str(QT_TRANSLATE_NOOP("StageWords", "battery voltage")),
    Subscriber.BATTERY_CHARGE: str(QT_TRANSLATE_NOOP("StageWords", "battery charge")),
    Subscriber.CHARGING_CURRENT: str(QT_TRANSLATE_NOOP("StageWords", "charging current")),
    Subscriber.BOARD_TEMPERATURE: str(QT_TRANSLATE_NOOP("StageWords", "board temperature")),
    Subscriber.ROTATION: str(QT_TRANSLATE_NOOP("StageWords", "rotation")),
    Subscriber.YAW_RATE: str(QT_TRANSLATE_NOOP("StageWords", "yaw rate")),
    Subscriber.DEVICE_FLAGS: str(QT_TRANSLATE_NOOP("StageWords", "device flags")),
    Subscriber.X_ENCODER: str(QT_TRANSLATE_NOOP("StageWords", "X encoder")),
    Subscriber.Y_ENCODER: str(QT_TRANSLATE_NOOP("StageWords", "Y encoder")),
    Subscriber.FIRMWARE_VERSION: str(QT_TRANSLATE_NOOP("StageWords", "firmware version")),
    Subscriber.REJECTED_FRAMES: str(QT_TRANSLATE_NOOP("StageWords", "rejected frames")),
    Subscriber.UNKNOWN: str(QT_TRANSLATE_NOOP("StageWords", "unknown subscriber")),
}


def type_text(code: int) -> str:
    """What an echo TYPE holds, in the operator's language ("position", "poloha")."""
    if code in BY_TYPE:
        return _lower_first(QCoreApplication.translate("StageParameter", BY_TYPE[code].label))
    if code in TYPE_TEXT:
        return QCoreApplication.translate("StageWords", TYPE_TEXT[code])
    return f"TYPE {code:X}"


def status_text(code: int) -> str:
    """An echo STATUS in the operator's language, as the info panel says it."""
    if code in STATUS_TEXT:
        return QCoreApplication.translate("AxisStatus", STATUS_TEXT[code])
    return f"status {code:X}"


def subscriber_text(code: int) -> str:
    """A subscriber variable's name in the operator's language."""
    if code in SUBSCRIBER_TEXT:
        return QCoreApplication.translate("StageWords", SUBSCRIBER_TEXT[code])
    return f"{code:02X}"


_STATUS_CODES = frozenset(int(s) for s in AxisStatus)
_MAX_TYPE = max(EchoType)


# --- composing an echo --------------------------------------------------------------

#: A field as a widget or a test hands it over: text typed or chosen, or a number.
Field = str | int


class InjectError(ValueError):
    """A composed echo that cannot be sent; ``message`` says which field and why."""

    def __init__(self, message: str) -> None:
        super().__init__(message)
        self.message = message


@dataclass(frozen=True)
class AxisFields:
    """One axis packet as composed: TYPE and STATUS in hex, DATA in decimal."""

    type: Field = 0
    status: Field = 0
    data: Field = 0


@dataclass(frozen=True)
class EchoFields:
    """A whole echo as composed: one :class:`AxisFields` per axis, then the subscriber."""

    axes: Sequence[AxisFields]
    subscriber: Field = 0
    sdata: Field = 0


_WHOLE = re.compile(r"[+-]?\d+")
_HEX = re.compile(r"(?:0[xX])?([0-9A-Fa-f]+)")


def _first_token(value: str) -> str:
    """The code in a combo text such as ``"9 blocked: charger connected"``."""
    parts = value.split()
    return parts[0] if parts else ""


def _parse_hex(value: Field, where: str, what: str) -> int:
    if isinstance(value, bool):
        raise InjectError(f"{where} {what}: {value!r} is not a number")
    if isinstance(value, int):
        return value
    token = _first_token(value)
    match = _HEX.fullmatch(token)
    if match is None:
        shown = token or "(empty)"
        raise InjectError(f"{where} {what}: {shown!r} is not a hexadecimal number")
    return int(match.group(1), 16)


def parse_data(value: Field, where: str) -> int:
    """A DATA field: a whole number the six wire characters can carry.

    Refused rather than rounded: "12.5" may mean 12.5 mm where the wire wants
    12500 µm, and a silently wrong injection misleads the very test it was for.
    """
    if isinstance(value, bool):
        raise InjectError(f"{where}: {value!r} is not a whole number")
    if isinstance(value, str):
        text = value.strip().replace("\u2212", "-")  # a pasted typographic minus
        if not text:
            raise InjectError(f"{where} is empty: enter a whole number")
        if _WHOLE.fullmatch(text) is None:
            raise InjectError(f"{where}: {value.strip()!r} is not a whole number")
        value = int(text)
    if not DATA_MIN <= value <= DATA_MAX:
        raise InjectError(f"{where}: {value} is outside {DATA_MIN}…{DATA_MAX}")
    return value


def parse_type(value: Field, where: str) -> int:
    """TYPE 0…C: position, velocity or a parameter (docs/protocols.md §1.3)."""
    code = _parse_hex(value, where, "TYPE")
    if not 0 <= code <= _MAX_TYPE:
        raise InjectError(f"{where} TYPE: {code:X} is outside 0…{_MAX_TYPE:X}")
    return code


def parse_status(value: Field, where: str) -> int:
    """STATUS: one of the codes table 1.3 defines (D is not one)."""
    code = _parse_hex(value, where, "STATUS")
    if code not in _STATUS_CODES:
        known = ", ".join(f"{s:X}" for s in sorted(_STATUS_CODES))
        raise InjectError(f"{where} STATUS: {code:X} is not a known status ({known})")
    return code


def parse_subscriber(value: Field) -> int:
    """SS: a :class:`Subscriber` by name or code, or any ID 00…FF (to test unknown ones)."""
    if isinstance(value, str):
        name = _first_token(value).upper()
        if name in Subscriber.__members__:
            return int(Subscriber[name])
    code = _parse_hex(value, "subscriber", "ID")
    if not 0 <= code <= 0xFF:
        raise InjectError(f"subscriber ID: {code:X} is outside 00…FF")
    return code


def parse_echo(fields: EchoFields, axis_names: Sequence[str] | None = None) -> EchoFrame:
    """The echo the fields describe, or :class:`InjectError` naming the first bad field.

    ``axis_names`` only label the messages ("X DATA: …"); without them axes are
    numbered from 1.
    """
    packets = []
    for index, axis in enumerate(fields.axes):
        where = axis_names[index] if axis_names and index < len(axis_names) else f"axis {index + 1}"
        packets.append(
            EchoPacket(
                parse_type(axis.type, where),
                parse_status(axis.status, where),
                parse_data(axis.data, f"{where} DATA"),
            )
        )
    subscriber = parse_subscriber(fields.subscriber)
    sdata = parse_data(fields.sdata, "subscriber DATA")
    return EchoFrame(tuple(packets), subscriber, sdata)


def raw_echo_text(echo: EchoFrame) -> str:
    """The wire form of an echo as the log shows it (for "injected …" feedback)."""
    return escape_raw(encode_echo(echo))


def inject_echo(station: Station, fields: EchoFields) -> EchoFrame:
    """Parse ``fields`` and fold the echo into the station as if received.

    Nothing reaches the model (or the log) unless every field is valid.
    """
    names = [axis.name for axis in station.model.axes]
    if len(fields.axes) != len(names):
        raise InjectError(f"the machine has {len(names)} axes, the echo {len(fields.axes)}")
    echo = parse_echo(fields, names)
    station.inject_echo(echo)
    return echo


# --- describing frames in words -----------------------------------------------------


#: The device flags' bits in words.
FLAG_TEXT: dict[int, str] = {
    DeviceFlag.CHARGER: str(QT_TRANSLATE_NOOP("StageWords", "charger")),
    DeviceFlag.USB: str(QT_TRANSLATE_NOOP("StageWords", "USB")),
    DeviceFlag.LOW_BATTERY: str(QT_TRANSLATE_NOOP("StageWords", "low battery")),
    DeviceFlag.SLEEPING: str(QT_TRANSLATE_NOOP("StageWords", "sleeping")),
    DeviceFlag.DATA_SESSION: str(QT_TRANSLATE_NOOP("StageWords", "data session")),
}
FAST_SLOW = (
    str(QT_TRANSLATE_NOOP("StageWords", "slow")),
    str(QT_TRANSLATE_NOOP("StageWords", "fast")),
)
ON_OFF = (str(QT_TRANSLATE_NOOP("StageWords", "off")), str(QT_TRANSLATE_NOOP("StageWords", "on")))


def _choice(data: int, words: tuple[str, str]) -> str:
    """0 and 1 in words (``words``: what 0 and 1 mean), anything else as the number."""
    return QCoreApplication.translate("StageWords", words[data]) if data in (0, 1) else str(data)


def _signed(value: int) -> str:
    return f"{value:+d}"


def _mm(value_um: int, unit: str, *, signed: bool = False) -> str:
    return f"{local_number(value_um / 1000, '+.3f' if signed else '.3f')} {unit}"


def describe_command(frame: CommandFrame, axis_names: Sequence[str], units: Sequence[str]) -> str:
    """A command frame in words: ``X JOG +1 | Y NOP | SS battery voltage``."""
    parts = [
        f"{_name(axis_names, i)} {_command_words(p.command, p.data, _unit(units, i))}"
        for i, p in enumerate(frame.packets)
    ]
    parts.append(f"SS {subscriber_text(frame.subscriber)}")
    return " | ".join(parts)


def _name(axis_names: Sequence[str], index: int) -> str:
    return axis_names[index] if index < len(axis_names) else f"#{index + 1}"


def _unit(units: Sequence[str], index: int) -> str:
    return units[index] if index < len(units) else ""


def _command_words(command: int, data: int, unit: str) -> str:
    try:
        cid = CommandId(command)
    except ValueError:
        return f"ID {command:02X} {data}"
    match cid:
        case CommandId.JOG:
            return f"JOG {_signed(data) if data else '0'}"
        case CommandId.MOVE_ABS | CommandId.SET_POS:
            return f"{cid.name} {_mm(data, unit)}"
        case CommandId.MOVE_REL:
            return f"MOVE_REL {_mm(data, unit, signed=True)}"
        case CommandId.SPEED:
            return f"SPEED {_choice(data, FAST_SLOW)}"
        case CommandId.SLEEP:
            return f"SLEEP {_choice(data, ON_OFF)}"
        case CommandId.READ:
            return f"READ {type_text(data)}"
        case CommandId.NOP | CommandId.STOP | CommandId.HOME | CommandId.ESTOP:
            return cid.name
    # WRITE_*: the parameter it writes, with the value as the dynamics panel shows it.
    parameter = BY_TYPE.get(command - 0x0E)
    if parameter is None:
        return f"{cid.name} {data}"
    return f"WRITE {type_text(command - 0x0E)} {_parameter_value(command - 0x0E, data)}"


def _parameter_value(type_: int, data: int) -> str:
    meta = BY_TYPE[type_]
    unit = QCoreApplication.translate("Unit", meta.unit) if meta.unit else ""
    return f"{local_number(meta.to_shown(data), f'.{meta.decimals}f')} {unit}".rstrip()


def describe_echo(echo: EchoFrame, axis_names: Sequence[str], units: Sequence[str]) -> str:
    """An echo in words: ``X pos 12.345 mm accelerating | Y pos 0.000 mm idle | …``."""
    parts = [
        f"{_name(axis_names, i)} {_packet_words(p, _unit(units, i))}"
        for i, p in enumerate(echo.packets)
    ]
    parts.append(_subscriber_words(echo.subscriber, echo.sdata))
    return " | ".join(parts)


def _packet_words(packet: EchoPacket, unit: str) -> str:
    status = status_text(packet.status)
    if packet.type == EchoType.POSITION:
        pos = QCoreApplication.translate("StageWords", "pos")
        return f"{pos} {_mm(packet.data, unit)} {status}"
    if packet.type == EchoType.VELOCITY:
        vel = QCoreApplication.translate("StageWords", "vel")
        return f"{vel} {_mm(packet.data, unit + '/s')} {status}"
    if packet.type in BY_TYPE:
        return f"{type_text(packet.type)} {_parameter_value(packet.type, packet.data)} {status}"
    return f"TYPE {packet.type:X} {packet.data} {status}"


def _subscriber_words(subscriber: int, sdata: int) -> str:
    name = subscriber_text(subscriber)
    match subscriber:
        case Subscriber.NONE:
            return f"SS {name}"
        case Subscriber.BATTERY_VOLTAGE:
            return f"{name} {sdata} mV"
        case Subscriber.BATTERY_CHARGE:
            return f"{name} {sdata} %"
        case Subscriber.CHARGING_CURRENT:
            return f"{name} {sdata} mA"
        case Subscriber.BOARD_TEMPERATURE:
            return f"{name} {local_number(sdata / 100, '.2f')} °C"
        case Subscriber.ROTATION:
            return f"{name} {local_number(sdata / 100, '.2f')}°"
        case Subscriber.YAW_RATE:
            return f"{name} {local_number(sdata / 100, '.2f')} °/s"
        case Subscriber.DEVICE_FLAGS:
            return f"{name} {_flag_words(sdata)}"
        case Subscriber.X_ENCODER | Subscriber.Y_ENCODER:
            return f"{name} {local_number(sdata / 1000, '.3f')} mm"
        case Subscriber.FIRMWARE_VERSION:
            return f"{name} {sdata // 10000}.{sdata // 100 % 100}.{sdata % 100}"
        case Subscriber.REJECTED_FRAMES:
            return f"{name} {sdata}"
        case Subscriber.UNKNOWN:
            asked = f"{sdata:02X}" if 0 <= sdata <= 0xFF else str(sdata)
            return f"{name} {asked}"
    return f"SS {subscriber:02X} {sdata}"


def _flag_words(value: int) -> str:
    names = [
        QCoreApplication.translate("StageWords", FLAG_TEXT[flag])
        for flag in DeviceFlag
        if flag in FLAG_TEXT and value & flag
    ]
    none = QCoreApplication.translate("StageWords", "none")
    return f"{value:#04x} ({', '.join(names) or none})"
