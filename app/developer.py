"""The developer pane's models: echo injection, the TX/RX frame log, emulator controls.

The stage's original tool had a developer extension (Shift+V) that could
fake received echoes and run a timer answering the tool's own commands.
StepDeck keeps both and adds a frame log and knobs on the emulator, so that
every state the info panel can show — a charger block, an end switch, a
dropped or noisy link — can be provoked on the desk.

Everything here is Qt models and plain functions, no widgets, so that the
pane stays a thin view and the behaviour is tested without clicking.  The
pane reaches the emulator only through :class:`EmulatorControls`: widgets
never import ``protocol.emulator`` or ``protocol.transport``.
"""

from __future__ import annotations

import enum
import re
import threading
from collections import deque
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field, fields, is_dataclass
from pathlib import Path

from PySide6.QtCore import QObject, Signal

from app.machine import LinkState
from app.machines.gcode.developer import describe_gcode
from app.machines.session import MachineSession
from app.machines.stage.echoes import STATUS_TEXT
from app.machines.stage.parameters import BY_TYPE
from app.station import Station
from protocol.emulator.device import EmulatedDevice
from protocol.emulator.mechanism import SwitchName
from protocol.emulator.stage_firmware import StageFirmware
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
    Rejected,
    Subscriber,
    echo_frame_length,
    encode_echo,
)
from protocol.transport.loopback import Direction, LoopbackTransport
from protocol.usb3.codec import AxisId

# --- words for the wire's numbers ---------------------------------------------------


def _lower_first(text: str) -> str:
    return text[:1].lower() + text[1:]


#: What an echo packet's TYPE says its DATA holds, in words (PROTOCOLS.md 1.3).
TYPE_TEXT: dict[int, str] = {
    EchoType.POSITION: "position",
    EchoType.VELOCITY: "velocity",
    **{t: _lower_first(p.label) for t, p in BY_TYPE.items()},
}

#: Subscriber variables in words (PROTOCOLS.md 1.5).
SUBSCRIBER_TEXT: dict[int, str] = {
    Subscriber.NONE: "none",
    Subscriber.BATTERY_VOLTAGE: "battery voltage",
    Subscriber.BATTERY_CHARGE: "battery charge",
    Subscriber.CHARGING_CURRENT: "charging current",
    Subscriber.BOARD_TEMPERATURE: "board temperature",
    Subscriber.ROTATION: "rotation",
    Subscriber.YAW_RATE: "yaw rate",
    Subscriber.DEVICE_FLAGS: "device flags",
    Subscriber.X_ENCODER: "X encoder",
    Subscriber.Y_ENCODER: "Y encoder",
    Subscriber.FIRMWARE_VERSION: "firmware version",
    Subscriber.REJECTED_FRAMES: "rejected frames",
    Subscriber.UNKNOWN: "unknown subscriber",
}

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
    """TYPE 0…C: position, velocity or a parameter (PROTOCOLS.md 1.3)."""
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


def escape_raw(raw: bytes) -> str:
    r"""The bytes as one printable line: ``\n``, ``\r``, ``\t`` and ``\xNN`` for the rest.

    A corrupted frame may hold any byte; the log must still be one line per frame.
    """
    out = []
    for byte in raw:
        if byte == 0x0A:
            out.append("\\n")
        elif byte == 0x0D:
            out.append("\\r")
        elif byte == 0x09:
            out.append("\\t")
        elif byte == 0x5C:
            out.append("\\\\")
        elif 0x20 <= byte < 0x7F:
            out.append(chr(byte))
        else:
            out.append(f"\\x{byte:02X}")
    return "".join(out)


def _signed(value: int) -> str:
    return f"{value:+d}"


def _mm(value_um: int, unit: str, *, signed: bool = False) -> str:
    return f"{value_um / 1000:{'+' if signed else ''}.3f} {unit}"


def describe_message(message: object) -> str:
    """Other dialects' messages are small dataclasses: their fields read well enough."""
    gcode = describe_gcode(message)
    if gcode is not None:
        return gcode
    if is_dataclass(message) and not isinstance(message, type):
        values = ", ".join(f"{f.name}={_plain(getattr(message, f.name))}" for f in fields(message))
        return f"{type(message).__name__}({values})"
    return repr(message)


def _plain(value: object) -> str:
    if isinstance(value, enum.Enum):
        return value.name
    if isinstance(value, tuple):
        return "(" + ", ".join(_plain(v) for v in value) + ")"
    return str(value)


def describe_command(frame: CommandFrame, axis_names: Sequence[str], units: Sequence[str]) -> str:
    """A command frame in words: ``X JOG +1 | Y NOP | SS battery voltage``."""
    parts = [
        f"{_name(axis_names, i)} {_command_words(p.command, p.data, _unit(units, i))}"
        for i, p in enumerate(frame.packets)
    ]
    parts.append(f"SS {SUBSCRIBER_TEXT.get(frame.subscriber, f'{frame.subscriber:02X}')}")
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
            return f"SPEED {'fast' if data == 1 else 'slow' if data == 0 else data}"
        case CommandId.SLEEP:
            return f"SLEEP {'on' if data == 1 else 'off' if data == 0 else data}"
        case CommandId.READ:
            return f"READ {TYPE_TEXT.get(data, f'TYPE {data}')}"
        case CommandId.NOP | CommandId.STOP | CommandId.HOME | CommandId.ESTOP:
            return cid.name
    # WRITE_*: the parameter it writes, with the value as the dynamics panel shows it.
    parameter = BY_TYPE.get(command - 0x0E)
    if parameter is None:
        return f"{cid.name} {data}"
    return f"WRITE {_lower_first(parameter.label)} {_parameter_value(command - 0x0E, data)}"


def _parameter_value(type_: int, data: int) -> str:
    meta = BY_TYPE[type_]
    return f"{meta.to_shown(data):.{meta.decimals}f} {meta.unit}".rstrip()


def describe_echo(echo: EchoFrame, axis_names: Sequence[str], units: Sequence[str]) -> str:
    """An echo in words: ``X pos 12.345 mm accelerating | Y pos 0.000 mm idle | …``."""
    parts = [
        f"{_name(axis_names, i)} {_packet_words(p, _unit(units, i))}"
        for i, p in enumerate(echo.packets)
    ]
    parts.append(_subscriber_words(echo.subscriber, echo.sdata))
    return " | ".join(parts)


def _packet_words(packet: EchoPacket, unit: str) -> str:
    status = STATUS_TEXT.get(packet.status, f"status {packet.status:X}")
    if packet.type == EchoType.POSITION:
        return f"pos {_mm(packet.data, unit)} {status}"
    if packet.type == EchoType.VELOCITY:
        return f"vel {_mm(packet.data, unit + '/s')} {status}"
    if packet.type in BY_TYPE:
        return f"{TYPE_TEXT[packet.type]} {_parameter_value(packet.type, packet.data)} {status}"
    return f"TYPE {packet.type:X} {packet.data} {status}"


def _subscriber_words(subscriber: int, sdata: int) -> str:
    name = SUBSCRIBER_TEXT.get(subscriber)
    match subscriber:
        case Subscriber.NONE:
            return "SS none"
        case Subscriber.BATTERY_VOLTAGE:
            return f"{name} {sdata} mV"
        case Subscriber.BATTERY_CHARGE:
            return f"{name} {sdata} %"
        case Subscriber.CHARGING_CURRENT:
            return f"{name} {sdata} mA"
        case Subscriber.BOARD_TEMPERATURE:
            return f"{name} {sdata / 100:.2f} °C"
        case Subscriber.ROTATION:
            return f"{name} {sdata / 100:.2f}°"
        case Subscriber.YAW_RATE:
            return f"{name} {sdata / 100:.2f} °/s"
        case Subscriber.DEVICE_FLAGS:
            return f"{name} {_flag_words(sdata)}"
        case Subscriber.X_ENCODER | Subscriber.Y_ENCODER:
            return f"{name} {sdata / 1000:.3f} mm"
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
        flag.name.lower().replace("_", " ")
        for flag in DeviceFlag
        if flag.name is not None and value & flag
    ]
    return f"{value:#04x} ({', '.join(names) or 'none'})"


# --- the frame log --------------------------------------------------------------------


class LogDirection(enum.StrEnum):
    TX = "TX"  # a command frame the station sent
    RX = "RX"  # an echo the station received
    INJ = "INJ"  # an echo the developer injected
    BAD = "BAD"  # bytes that did not decode (dropped and counted)


@dataclass(frozen=True, slots=True)
class LogEntry:
    seq: int
    time: float  # station clock time
    direction: LogDirection
    raw: str  # escaped, one line
    decoded: str
    line: str = field(compare=False)


#: Entries kept; a 1 kHz stream fills it in 10 s (TX and RX), a 100 ms one in 17 minutes.
LOG_CAPACITY = 20_000


class FrameLog(QObject):
    """Every frame the station sends and receives, injected echoes and rejected bytes.

    Fed by the current session's ``frameSent``/``frameReceived`` (re-attached
    on ``station.sessionChanged``) and by ``station.echoInjected``; bounded to
    the last ``capacity`` entries.

    **Pause** freezes the *view*, not the recording: entries keep arriving in
    the log while paused, but ``entriesAdded`` is held back until resume, so a
    view that follows the signal stands still and then catches up with
    everything that came meanwhile (bar what the capacity pushed out — see
    :meth:`entries_since`).  Dropping frames while paused would make the log lie
    about what crossed the wire exactly when someone is studying it.

    ``entriesAdded`` fires once per entry: views should only mark themselves
    dirty on it and redraw on a timer, pulling :meth:`entries_since`.
    """

    entriesAdded = Signal()
    cleared = Signal()
    pausedChanged = Signal(bool)

    def __init__(
        self, station: Station, capacity: int = LOG_CAPACITY, parent: QObject | None = None
    ) -> None:
        super().__init__(parent)
        self._station = station
        self._clock = station.clock
        self.origin = self._clock.now()
        self._entries: deque[LogEntry] = deque(maxlen=capacity)
        self._seq = 0
        self._paused = False
        self._held = False
        self._session: MachineSession | None = None
        self._axis_names = [axis.name for axis in station.model.axes]
        self._units = [axis.unit for axis in station.model.axes]
        self._raw_width = echo_frame_length(len(self._axis_names)) + 1
        station.sessionChanged.connect(self._attach)
        station.echoInjected.connect(self._on_injected)
        self._attach()

    # --- reading ------------------------------------------------------------------

    @property
    def capacity(self) -> int:
        return self._entries.maxlen or 0

    @property
    def entries(self) -> list[LogEntry]:
        """Everything recorded, oldest first (held entries of a pause included)."""
        return list(self._entries)

    @property
    def last_seq(self) -> int:
        """Sequence number of the newest entry (0 before the first)."""
        return self._seq

    def __len__(self) -> int:
        return len(self._entries)

    def entries_since(self, seq: int) -> list[LogEntry]:
        """Entries newer than ``seq``.  If the first returned is not ``seq + 1`` the
        capacity pushed some out before they were read."""
        if not self._entries or self._entries[-1].seq <= seq:
            return []
        first = self._entries[0].seq
        if seq < first:
            return list(self._entries)
        out: list[LogEntry] = []
        for entry in reversed(self._entries):
            if entry.seq <= seq:
                break
            out.append(entry)
        out.reverse()
        return out

    @staticmethod
    def matches(entry: LogEntry, text: str) -> bool:
        """The filter: every whitespace-separated word occurs in the line, any case.

        ``"rx charger"`` keeps received echoes that mention the charger; an empty
        filter keeps everything.
        """
        line = entry.line.casefold()
        return all(word in line for word in text.casefold().split())

    def filtered(self, text: str, entries: Iterable[LogEntry] | None = None) -> list[LogEntry]:
        pool = self._entries if entries is None else entries
        if not text.split():
            return list(pool)
        return [e for e in pool if self.matches(e, text)]

    # --- pause, clear, save ---------------------------------------------------------

    @property
    def paused(self) -> bool:
        return self._paused

    def set_paused(self, paused: bool) -> None:
        if paused == self._paused:
            return
        self._paused = paused
        self.pausedChanged.emit(paused)
        if not paused and self._held:
            self._held = False
            self.entriesAdded.emit()

    def clear(self) -> None:
        self._entries.clear()
        self._held = False
        self.cleared.emit()

    def save(self, path: str | Path, filter_text: str = "") -> int:
        """Write the entries that pass ``filter_text`` (all by default), oldest first.

        Entries held by a pause are written too: the file is the record, the
        pause only concerns the view.  Returns the number of entries written.
        """
        chosen = self.filtered(filter_text)
        title = self._station.profile.name
        what = f", filter {filter_text.strip()!r}" if filter_text.strip() else ""
        lines = [
            f"# StepDeck frame log, {title}: {len(chosen)} entries{what}",
            "# time (s since the log started)  dir  raw frame  decoded",
            *(entry.line for entry in chosen),
        ]
        Path(path).write_text("\n".join(lines) + "\n", encoding="utf-8")
        return len(chosen)

    # --- recording ----------------------------------------------------------------------

    def _attach(self) -> None:
        session = self._station.session
        if session is self._session:
            return
        self._detach()
        self._session = session
        if session is not None:
            session.frameSent.connect(self._on_sent)
            session.frameReceived.connect(self._on_received)

    def _detach(self) -> None:
        old, self._session = self._session, None
        if old is None:
            return
        try:
            old.frameSent.disconnect(self._on_sent)
            old.frameReceived.disconnect(self._on_received)
        except RuntimeError:
            pass  # already deleted by the station (close_link → deleteLater)

    def _on_sent(self, frame: object, raw: bytes) -> None:
        if isinstance(frame, CommandFrame):
            words = describe_command(frame, self._axis_names, self._units)
        else:
            words = describe_message(frame)
        self._add(LogDirection.TX, raw, words)

    def _on_received(self, frame: object, raw: bytes) -> None:
        if isinstance(frame, EchoFrame):
            self._add(LogDirection.RX, raw, describe_echo(frame, self._axis_names, self._units))
        elif isinstance(frame, Rejected):  # every dialect shares one Rejected
            self._add(LogDirection.BAD, raw, f"rejected: {frame.reason}")
        else:
            self._add(LogDirection.RX, raw, describe_message(frame))

    def _on_injected(self, echo: object) -> None:
        if isinstance(echo, EchoFrame):
            words = describe_echo(echo, self._axis_names, self._units)
            self._add(LogDirection.INJ, encode_echo(echo), words)

    def _add(self, direction: LogDirection, raw: bytes, decoded: str) -> None:
        now = self._clock.now()
        self._seq += 1
        text = escape_raw(raw)
        line = f"{now - self.origin:9.3f}  {direction:<3}  {text:<{self._raw_width}}  {decoded}"
        self._entries.append(LogEntry(self._seq, now, direction, text, decoded, line))
        if self._paused:
            self._held = True
        else:
            self.entriesAdded.emit()


# --- the emulator's knobs and the simulation ------------------------------------------


#: The two end switches of an axis, as :meth:`EmulatorControls.press_end_switch` names them.
END_SWITCHES: tuple[SwitchName, ...] = ("low", "high")


class SimulationRefused(RuntimeError):
    """Simulation cannot start: a real device is connected."""


@dataclass(frozen=True)
class EmulatorState:
    """The emulator's environment as the controls should show it right now."""

    charger: bool
    usb: bool
    battery_percent: float
    temperature_c: float
    rotation_dps: float
    verification_fault: bool
    driver_faults: tuple[bool, ...]


def _flip_one_byte(data: bytes) -> bytes:
    """Corrupt a chunk so it still ends its line: a flipped bit mid-frame breaks the checksum."""
    if not data:
        return data
    index = len(data) // 2
    if data[index] == 0x0A:
        index = 0
    return data[:index] + bytes([data[index] ^ 0x01]) + data[index + 1 :]


class _Corrupter:
    """A loopback manipulator that flips a byte in the next N chunks from the device.

    It runs on the emulator's ticker thread in real time while the GUI thread
    adds to it, so installing and removing it happen under one lock: it is on
    the transport exactly while it has chunks left to spoil, and takes itself
    off after the last so the link is clean again without anyone remembering.
    """

    def __init__(self, transport: LoopbackTransport) -> None:
        self.transport = transport
        self._remaining = 0
        self._lock = threading.Lock()

    @property
    def remaining(self) -> int:
        with self._lock:
            return self._remaining

    def add(self, count: int) -> None:
        with self._lock:
            self._remaining += count
            self.transport.set_manipulator(self)

    def __call__(self, direction: Direction, data: bytes) -> bytes:
        if direction is not Direction.TO_HOST or not data:
            return data
        with self._lock:
            if self._remaining <= 0:
                return data
            self._remaining -= 1
            if self._remaining == 0:
                self.transport.set_manipulator(None)
        return _flip_one_byte(data)


class EmulatorControls(QObject):
    """The built-in emulator's environment and faults, for the developer pane.

    A facade so widgets never import ``protocol.emulator``: it acts on
    ``station.emulator`` while that emulator is the station's link (behind the
    loopback), and is :attr:`available` only then.  Setters are ignored when
    no emulator is attached — the pane disables its controls then.

    The *simulation* ("a timer answering the tool's own commands" in the
    original tool) is the emulator connected as the station's device; so
    :attr:`simulating` equals :attr:`available`.  Starting it while a real
    device is connected is **refused** (:class:`SimulationRefused`) rather than
    silently disconnecting the machine: a developer checkbox must never be
    the thing that cuts a real stage off mid-move.
    """

    #: Emitted with the new availability whenever the emulator appears, goes or is replaced.
    availabilityChanged = Signal(bool)

    def __init__(self, station: Station, parent: QObject | None = None) -> None:
        super().__init__(parent)
        self._station = station
        self._corrupter: _Corrupter | None = None
        self._seen = self._identity()
        # close_link() announces no session change; the link state going DISCONNECTED does.
        station.sessionChanged.connect(self._check_availability)
        station.model.linkStateChanged.connect(self._check_availability)

    # --- availability and simulation ------------------------------------------------

    @property
    def available(self) -> bool:
        """The emulator is the station's device: connected, or lost and being reconnected.

        Judged by the link state rather than by ``station.link`` alone: an
        orderly close reports DISCONNECTED while the link object still exists.
        """
        station = self._station
        return (
            station.emulator is not None
            and station.loopback is not None
            and station.model.link_state is not LinkState.DISCONNECTED
        )

    @property
    def simulating(self) -> bool:
        return self.available

    @property
    def real_device_connected(self) -> bool:
        return self._station.link is not None and self._station.loopback is None

    def set_simulation(self, on: bool) -> None:
        """On: connect the built-in emulator (if nothing is connected).  Off: close it.

        Raises :class:`SimulationRefused` when turning on with a real device
        connected; turning off never touches a real device's link.
        """
        if on:
            if self.simulating:
                return
            if self.real_device_connected:
                assert self._station.link is not None
                raise SimulationRefused(
                    f"{self._station.link.describe()} is connected: disconnect it first"
                )
            self._station.connect_emulator()
        elif self.simulating:
            self._station.close_link()

    def state(self) -> EmulatorState | None:
        emulator = self._emulator()
        if emulator is None:
            return None
        return EmulatorState(
            charger=emulator.charger_connected,
            usb=emulator.usb_connected,
            battery_percent=emulator.battery_charge,
            temperature_c=emulator.board_temperature_c,
            rotation_dps=emulator.rotation_rate_dps,
            verification_fault=emulator.verification_fault,
            driver_faults=tuple(emulator.driver_fault(i) for i in range(len(emulator.axes))),
        )

    # --- environment --------------------------------------------------------------------

    def set_charger(self, connected: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.charger_connected = connected

    def set_usb(self, connected: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.usb_connected = connected

    def set_battery(self, percent: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.battery_charge = percent

    def set_temperature(self, celsius: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.board_temperature_c = celsius

    def set_rotation_rate(self, dps: float) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.rotation_rate_dps = dps

    def set_joystick(self, axis: int, adc: int) -> None:
        """The usb3 unit's joystick: ADC 0…1023 per axis, 500…524 is the dead zone."""
        emulator = self._station.usb3_emulator
        if emulator is not None and self.available:
            emulator.set_joystick(AxisId(axis), max(0, min(1023, int(adc))))

    # --- faults ----------------------------------------------------------------------------

    def press_end_switch(self, axis: int, which: SwitchName) -> None:
        """Close an end switch where the axis is (a crash or a stuck lever)."""
        if (emulator := self._emulator()) is not None:
            emulator.press_end_switch(axis, which)

    def set_driver_fault(self, axis: int, fault: bool) -> None:
        if (emulator := self._emulator()) is not None:
            emulator.set_driver_fault(axis, fault)

    def set_verification_fault(self, fault: bool) -> None:
        """FRAM read-back differs: every parameter write is refused until cleared."""
        if (emulator := self._emulator()) is not None:
            emulator.verification_fault = fault

    def drop_link(self) -> None:
        """Cut the emulated cable; the station sees the link lost and reconnects with back-off."""
        loopback = self._station.loopback
        if self.available and loopback is not None:
            loopback.sever("link dropped (developer pane)")

    def corrupt_next(self, count: int) -> None:
        """Flip a byte in each of the next ``count`` frames from the device (adds up)."""
        loopback = self._station.loopback
        if count <= 0 or not self.available or loopback is None:
            return
        if self._corrupter is None or self._corrupter.transport is not loopback:
            self._corrupter = _Corrupter(loopback)
        self._corrupter.add(count)

    @property
    def corruptions_pending(self) -> int:
        """Frames from the device still to be corrupted."""
        corrupter = self._corrupter
        if corrupter is None or corrupter.transport is not self._station.loopback:
            return 0
        return corrupter.remaining

    # --- internals -------------------------------------------------------------------------

    def _emulator(self) -> StageFirmware | None:
        """The emulator to act on, or None: setters are ignored without one."""
        return self._station.stage_emulator if self.available else None

    def _identity(self) -> tuple[bool, EmulatedDevice | None]:
        available = self.available
        return available, self._station.emulator if available else None

    def _check_availability(self, *_args: object) -> None:
        seen = self._identity()
        if seen[0] == self._seen[0] and seen[1] is self._seen[1]:
            return
        self._seen = seen
        self.availabilityChanged.emit(seen[0])
