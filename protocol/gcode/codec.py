"""Codec of the ``gcode`` dialect: GRBL-style lines and replies (docs/protocols.md §4).

The station encodes G-code lines and decodes what the board says; the
emulator answers in the same forms, so both sides agree on the wire format by
construction.  Decoding never raises on wire input: a line that is none of
the known reply forms comes back as :class:`Rejected` with a reason, and the
reader carries on with the next line.

What the station must count on is the acknowledgement of every line it sent
(``ok`` or ``error:<n>``), since character counting and ping-pong both move
on those alone; everything else a board says (status reports, banners,
settings, ``[...]`` messages, alarms) is information that never acknowledges
a line.  The CoreXY plotter's firmware says ``OK`` and ``ERROR:<n>``, GRBL
``ok`` and ``error:<n>``, so the words are matched case-insensitively.
"""

from __future__ import annotations

import math
import re
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace

from protocol.framing import DecodeResult, LineDecoder
from protocol.framing import Rejected as Rejected  # re-exported for this dialect's readers
from protocol.gcode.overrides import Overrides, parse_overrides

#: Real-time commands: single bytes a board acts on at once, never part of a line.
STATUS_QUERY = b"?"
FEED_HOLD = b"!"
CYCLE_START = b"~"
SOFT_RESET = b"\x18"
#: GRBL 1.1's jog cancel: a ``$J=`` jog brakes and its queued jog lines are dropped.
JOG_CANCEL = b"\x85"
REALTIME_BYTES = frozenset(STATUS_QUERY + FEED_HOLD + CYCLE_START + SOFT_RESET + JOG_CANCEL)

TERMINATOR = b"\n"
#: A character no line may hold: a real-time byte, or a control byte other than a tab.
_UNSENDABLE = re.compile(
    "["
    + re.escape("".join(sorted({chr(b) for b in REALTIME_BYTES} | {"\x7f"})))
    + "\x00-\x08\x0a-\x1f]"
)
#: The longest line a board takes, its ``\n`` included (GRBL's line buffer).
MAX_LINE_BYTES = 80
#: GRBL's serial receive buffer; a character-counting host keeps at most one
#: byte less than this unacknowledged, since the ring buffer never fills its last slot.
RX_BUFFER = 128
#: A reply longer than this without a line end is noise: a status report with
#: every optional field stays well under it.
MAX_REPLY_BYTES = 256

#: GRBL 1.1's error codes (``error:<n>``), in short: what the board refused and why.
ERROR_MESSAGES: dict[int, str] = {
    1: "expected command letter: a G-code word needs a letter",
    2: "bad number format: a word's value is missing or malformed",
    3: "invalid statement: '$' system command not recognised",
    4: "negative value where a positive one is expected",
    5: "setting disabled: homing is not enabled",
    6: "step pulse time must be at least 3 microseconds",
    7: "EEPROM read failed, defaults restored",
    8: "not idle: this '$' command needs the machine idle",
    9: "G-code locked out during alarm or jog",
    10: "soft limits need homing enabled",
    11: "line overflow: too many characters in the line, not executed",
    12: "setting would exceed the maximum step rate",
    13: "safety door open",
    14: "line length exceeded: build info or startup line too long to store",
    15: "travel exceeded: target beyond the machine's travel, ignored",
    16: "invalid jog command",
    17: "laser mode requires PWM output",
    20: "unsupported or invalid G-code command",
    21: "modal group violation: two commands of one modal group in a line",
    22: "undefined feed rate",
    23: "command requires an integer value",
    24: "more than one command in the line needs axis words",
    25: "repeated word in the line",
    26: "no axis words for a command that needs them",
    27: "invalid line number",
    28: "command is missing a required value word",
    29: "G59.x work coordinate systems are not supported",
    30: "G53 only with G0 and G1",
    31: "axis words that no command uses",
    32: "G2/G3 arcs need at least one in-plane axis word",
    33: "motion target is invalid",
    34: "arc radius is invalid",
    35: "G2/G3 arcs need at least one in-plane offset word",
    36: "unused value words in the line",
    37: "dynamic tool length offset not on the tool length axis",
    38: "tool number greater than supported",
}

#: GRBL 1.1's alarm codes (``ALARM:<n>``).
ALARM_MESSAGES: dict[int, str] = {
    1: "hard limit triggered: position likely lost; reset, then home",
    2: "soft limit: target beyond the travel; reset, then unlock or home",
    3: "reset while in motion: position likely lost, re-home",
    4: "probe fail: probe not in the expected initial state",
    5: "probe fail: no contact within the programmed travel",
    6: "homing fail: the homing cycle was reset",
    7: "homing fail: safety door opened while homing",
    8: "homing fail: pull-off did not clear the limit switch",
    9: "homing fail: limit switch not found within the search distance",
    10: "homing fail: the second switch of a dual axis did not trigger after the first",
}

#: Welcome lines begin with one of these (GRBL, grblHAL, FluidNC, and the
#: emulator's own plotter); any line naming ``'$' for help`` is one too.
BANNER_PREFIXES = ("grbl", "fluidnc", "stepdeck")
GRBL_BANNER = "Grbl 1.1h ['$' for help]"
PLOTTER_BANNER = "StepDeck CoreXY plotter 1.0 ['$' for help]"


# -- messages ----------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Ok:
    """The line was accepted (``ok``, or ``OK`` from the plotter)."""


@dataclass(frozen=True, slots=True)
class ErrorReply:
    """The line was refused (``error:<n>``); it still counts as acknowledged.

    ``code`` 0 stands for an error without a number (GRBL 0.9 said its reason
    in words), so that such a reply still acknowledges its line.
    """

    code: int

    @property
    def meaning(self) -> str:
        return ERROR_MESSAGES.get(self.code, f"unknown error {self.code}")


@dataclass(frozen=True, slots=True)
class AlarmReply:
    """The board entered its alarm state (``ALARM:<n>``); it acknowledges no line."""

    code: int

    @property
    def meaning(self) -> str:
        return ALARM_MESSAGES.get(self.code, f"unknown alarm {self.code}")


@dataclass(frozen=True, slots=True)
class StatusReport:
    """A ``<...>`` report, the answer to ``?``.

    ``mpos`` is the machine position and ``wpos`` the work position (GRBL:
    machine position minus the work coordinate offset ``wco``).  A GRBL board
    reports one of the two (``$10`` bit 0) and its ``WCO:`` only now and then
    (on a change, and every 10 to 30 reports), so a report alone may not tell
    the other: then ``wco`` is None and the missing position is taken equal to
    the reported one until :func:`with_work_offset` completes it with the
    offset last heard (``work_reported`` says which one came).  A board without
    work offsets reports ``MPos`` and the two are the same.  ``planner_free`` and
    ``rx_free`` come from ``Bf:`` when the board sends it.  ``fields`` holds
    every ``key:value`` field as written, for whatever else a board reports.
    """

    state: str
    mpos: tuple[float, ...]
    feed: float
    spindle: float
    planner_free: int | None
    rx_free: int | None
    fields: Mapping[str, str] = field(default_factory=dict)
    #: What follows the state after a colon: ``Hold:0`` is hold complete, ``Hold:1`` braking.
    substate: str | None = None
    #: The work position (``WPos``, or ``MPos`` minus the offset); see the class.
    wpos: tuple[float, ...] = ()
    #: The work coordinate offset (``WCO:``) when this report carried it or it was completed.
    wco: tuple[float, ...] | None = None
    #: The board reported ``WPos`` (``$10`` bit 0 clear), not ``MPos``.
    work_reported: bool = False
    #: GRBL's overrides when this report carried ``Ov:`` (now and then, and after a change).
    overrides: Overrides | None = None


def with_work_offset(report: StatusReport, wco: Sequence[float] | None) -> StatusReport:
    """``report`` with both positions, from its own ``WCO:`` or else ``wco`` (last heard).

    Without either the offset is taken as 0 (a board without work offsets, or
    one whose first report has not come yet: GRBL's first report carries it).
    """
    offset = report.wco if report.wco is not None else tuple(wco) if wco is not None else None
    if offset is None:
        offset = (0.0,) * len(report.mpos)
    count = min(len(offset), len(report.mpos))
    pad = tuple(offset[:count]) + (0.0,) * (len(report.mpos) - count)
    if report.work_reported:
        work = report.wpos
        machine = tuple(w + o for w, o in zip(work, pad, strict=True))
    else:
        machine = report.mpos
        work = tuple(m - o for m, o in zip(machine, pad, strict=True))
    return replace(report, mpos=machine, wpos=work, wco=pad)


@dataclass(frozen=True, slots=True)
class Banner:
    """The welcome line a board sends after power-up and after a soft reset."""

    text: str


@dataclass(frozen=True, slots=True)
class Feedback:
    """Information that acknowledges nothing: ``[MSG:...]``, ``[GC:...]``, ``$100=250.000``."""

    text: str


GcodeReply = Ok | ErrorReply | AlarmReply | StatusReport | Banner | Feedback


# -- encoding ----------------------------------------------------------------------------


def encode_line(text: str) -> bytes:
    """The wire bytes of one G-code line: stripped, ``\\n`` appended.

    Raises ValueError (with the reason) for what would corrupt the stream:
    bytes that are not ASCII, a line end or control byte inside the line, a
    real-time byte (the board would act on it and drop it from the line),
    or a line the board cannot hold.
    """
    line = text.strip()
    if not line.isascii():
        raise ValueError(f"G-code lines are ASCII; {line!r} is not")
    # One search for the rare bad byte, not a loop over every character of every line.
    bad = _UNSENDABLE.search(line)
    if bad is not None:
        char = bad.group()
        if ord(char) in REALTIME_BYTES:
            raise ValueError(
                f"{char!r} is a real-time command byte and cannot be part of a line: {line!r}"
            )
        raise ValueError(f"control byte {char!r} inside the line {line!r}")
    data = line.encode("ascii") + TERMINATOR
    if len(data) > MAX_LINE_BYTES:
        raise ValueError(
            f"line of {len(data)} bytes with its line end; the board takes at most "
            f"{MAX_LINE_BYTES}: {line!r}"
        )
    return data


# -- decoding ----------------------------------------------------------------------------


def _number(text: str) -> float | None:
    try:
        value = float(text)
    except ValueError:
        return None
    return value if math.isfinite(value) else None


def _code(text: str) -> int | None:
    text = text.strip()
    return int(text) if text.isdigit() else None


def _parse_status(body: str) -> StatusReport | str:
    parts = body.split("|")
    state, _, substate = parts[0].partition(":")
    if not state.isalpha():
        return "status report without a state"
    fields: dict[str, str] = {}
    for part in parts[1:]:
        key, colon, value = part.partition(":")
        if not colon or not key:
            return f"status field {part!r} is not key:value"
        fields[key] = value
    where = fields.get("MPos", fields.get("WPos"))
    if where is None:
        return "status report without MPos or WPos"
    position = [_number(v) for v in where.split(",")]
    if not position or any(v is None for v in position):
        return f"bad position {where!r}"
    wco: tuple[float, ...] | None = None
    if "WCO" in fields:
        offsets = [_number(v) for v in fields["WCO"].split(",")]
        if len(offsets) != len(position) or any(v is None for v in offsets):
            return f"bad work coordinate offset {fields['WCO']!r}"
        wco = tuple(v for v in offsets if v is not None)
    work_reported = "MPos" not in fields
    feed, spindle = 0.0, 0.0
    rates = fields.get("FS", fields.get("F"))
    if rates is not None:
        numbers = [_number(v) for v in rates.split(",")]
        if not 1 <= len(numbers) <= 2 or any(v is None for v in numbers):
            return f"bad feed/speed {rates!r}"
        feed = numbers[0] or 0.0
        spindle = (numbers[1] or 0.0) if len(numbers) == 2 else 0.0
    planner_free: int | None = None
    rx_free: int | None = None
    if "Bf" in fields:
        counts = [_code(v) for v in fields["Bf"].split(",")]
        if len(counts) != 2 or counts[0] is None or counts[1] is None:
            return f"bad buffer state {fields['Bf']!r}"
        planner_free, rx_free = counts
    overrides = parse_overrides(fields)
    if isinstance(overrides, str):
        return overrides
    reported = tuple(v for v in position if v is not None)
    report = StatusReport(
        state=state,
        mpos=reported,
        wpos=reported,
        work_reported=work_reported,
        feed=feed,
        spindle=spindle,
        planner_free=planner_free,
        rx_free=rx_free,
        fields=fields,
        substate=substate or None,
        overrides=overrides,
    )
    return report if wco is None else with_work_offset(report, wco)


def _parse_reply(text: str) -> GcodeReply | str:
    """One reply from a line's text (no line end), or the reason it is none."""
    lower = text.lower()
    if lower == "ok":
        return Ok()
    if lower.startswith(("error:", "alarm:")):
        # A reason in words (GRBL 0.9) still acknowledges the line: code 0.
        number = _code(text.partition(":")[2]) or 0
        return ErrorReply(number) if lower.startswith("error") else AlarmReply(number)
    if text.startswith("<"):
        if not text.endswith(">"):
            return "status report without its closing '>'"
        return _parse_status(text[1:-1])
    if lower.startswith(BANNER_PREFIXES) or "'$' for help]" in text:
        return Banner(text)
    if text.startswith("[") and text.endswith("]"):
        return Feedback(text)
    if text.startswith("$") and "=" in text:
        return Feedback(text)
    if text.startswith(">"):
        return Feedback(text)  # a startup line's echo: ``>G54:ok``
    return "not a G-code board reply"


def decode(buffer: bytes | bytearray) -> DecodeResult[GcodeReply]:
    """Take the first reply off ``buffer`` (the station's side of the wire).

    Returns ``(used, result)`` as every dialect does: ``used == 0`` means
    "need more bytes"; ``result`` is the reply, the :class:`Rejected` line, or
    None when only an empty line (or the CR of a CR LF) was skipped.
    """
    skip = 0
    while skip < len(buffer) and buffer[skip] in b"\r\n":
        skip += 1
    if skip:
        return skip, None
    end = buffer.find(TERMINATOR)
    if end < 0:
        if len(buffer) >= MAX_REPLY_BYTES:
            return len(buffer), Rejected(bytes(buffer), "too long without a line end")
        return 0, None
    used = end + 1
    raw = bytes(buffer[:used])
    if end >= MAX_REPLY_BYTES:
        # Refused whole as it would be in pieces (see the unterminated case above).
        return used, Rejected(raw, "too long")
    try:
        text = raw.decode("ascii").strip()
    except UnicodeDecodeError:
        return used, Rejected(raw, "not ASCII")
    if not text:
        return used, None
    parsed = _parse_reply(text)
    return used, Rejected(raw, parsed) if isinstance(parsed, str) else parsed


def make_decoder() -> LineDecoder[GcodeReply]:
    """A counting reader of board replies for one link."""
    return LineDecoder(decode, TERMINATOR)
