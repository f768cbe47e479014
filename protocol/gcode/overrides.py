"""GRBL 1.1's feed and rapid overrides: its real-time bytes and the ``Ov:`` field.

Both sides of the wire use this: the station to compute the bytes that take
an override from what the board last reported to what the operator wants,
the emulator to act on them as GRBL 1.1h's ``protocol.c`` does.

GRBL knows no "set the feed override to 50 %": only 100 %, ±10 and ±1
(feed), and 100/50/25 % (rapid), clamped to 10…200 % (``config.h``).  The
bytes are flags, not a counter: several bytes of one kind that reach the
board between two passes of its real-time loop count once, so a sequence is
checked against the ``Ov:`` it reports afterwards and completed if short.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

#: The real-time bytes (GRBL 1.1 ``config.h``); never part of a line.
FEED_RESET = b"\x90"
FEED_PLUS_10 = b"\x91"
FEED_MINUS_10 = b"\x92"
FEED_PLUS_1 = b"\x93"
FEED_MINUS_1 = b"\x94"
RAPID_RESET = b"\x95"
RAPID_50 = b"\x96"
RAPID_25 = b"\x97"
#: The spindle's override bytes, which a pen plotter leaves alone (taken and ignored).
SPINDLE_BYTES = frozenset(range(0x99, 0x9F)) | frozenset((0xA0, 0xA1))

#: GRBL 1.1's limits and steps (``config.h``).
FEED_MIN = 10
FEED_MAX = 200
FEED_DEFAULT = 100
RAPID_LEVELS = (25, 50, 100)
_RAPID_BYTES = {100: RAPID_RESET, 50: RAPID_50, 25: RAPID_25}
#: Readable names of the bytes, for the frame log.
BYTE_NAMES: dict[bytes, str] = {
    FEED_RESET: "feed override 100 %",
    FEED_PLUS_10: "feed override +10 %",
    FEED_MINUS_10: "feed override -10 %",
    FEED_PLUS_1: "feed override +1 %",
    FEED_MINUS_1: "feed override -1 %",
    RAPID_RESET: "rapid override 100 %",
    RAPID_50: "rapid override 50 %",
    RAPID_25: "rapid override 25 %",
}


@dataclass(frozen=True, slots=True)
class Overrides:
    """Percentages in force: feed, rapid and spindle (``Ov:100,100,100``)."""

    feed: int = FEED_DEFAULT
    rapid: int = 100
    spindle: int = 100

    def field(self) -> str:
        """The ``Ov:`` field as GRBL writes it."""
        return f"Ov:{self.feed},{self.rapid},{self.spindle}"


def parse_overrides(fields: Mapping[str, str]) -> Overrides | str | None:
    """The report's ``Ov:`` field: None without one, a reason (str) when it is malformed."""
    text = fields.get("Ov")
    if text is None:
        return None
    parts = text.split(",")
    if len(parts) != 3 or not all(p.isdigit() for p in parts):
        return f"bad overrides {text!r}"
    feed, rapid, spindle = (int(p) for p in parts)
    if not 1 <= feed <= 255 or not 1 <= rapid <= 100 or not 1 <= spindle <= 255:
        return f"overrides out of range {text!r}"
    return Overrides(feed, rapid, spindle)


def valid_feed(percent: int) -> bool:
    return FEED_MIN <= percent <= FEED_MAX


def feed_bytes(current: int, target: int) -> bytes:
    """The bytes from the feed override ``current`` to ``target`` (10…200): tens, then ones.

    100 % is its own byte, so a target of 100 is always one byte; otherwise
    the shorter of going from ``current`` or from a reset.  ValueError for a
    target GRBL cannot take.
    """
    if not valid_feed(target):
        raise ValueError(f"feed override {target} % is outside {FEED_MIN}…{FEED_MAX} %")
    if target == current:
        return b""
    if target == FEED_DEFAULT:
        return FEED_RESET
    direct = _steps(target - current)
    via_reset = FEED_RESET + _steps(target - FEED_DEFAULT)
    return via_reset if len(via_reset) < len(direct) else direct


def _steps(difference: int) -> bytes:
    tens, ones = divmod(abs(difference), 10)
    if difference >= 0:
        return FEED_PLUS_10 * tens + FEED_PLUS_1 * ones
    return FEED_MINUS_10 * tens + FEED_MINUS_1 * ones


def rapid_byte(target: int) -> bytes:
    """The one byte for a rapid override of ``target`` (25, 50 or 100 %)."""
    try:
        return _RAPID_BYTES[target]
    except KeyError:
        raise ValueError(f"rapid override {target} % is none of 25, 50, 100 %") from None


def applied(state: Overrides, flags: frozenset[int]) -> Overrides:
    """GRBL's real-time pass over the override bytes received since the last one.

    Each kind counts once however often it came (they are flags), in
    ``protocol.c``'s order: reset, coarse, fine; then clamped to 10…200 %.
    """
    feed = state.feed
    if FEED_RESET[0] in flags:
        feed = FEED_DEFAULT
    for byte, step in (
        (FEED_PLUS_10, 10),
        (FEED_MINUS_10, -10),
        (FEED_PLUS_1, 1),
        (FEED_MINUS_1, -1),
    ):
        if byte[0] in flags:
            feed += step
    feed %= 256  # GRBL adds in a uint8_t: 10 % less 10 and 1 wraps to 255, so 200 %
    feed = min(max(feed, FEED_MIN), FEED_MAX)
    rapid = state.rapid
    for byte, level in ((RAPID_RESET, 100), (RAPID_50, 50), (RAPID_25, 25)):
        if byte[0] in flags:
            rapid = level
    return Overrides(feed, rapid, state.spindle)
