"""Which machine a byte stream sounds like: for a station connected to the wrong one.

A station set up for one machine but cabled to another hears only garbage in
its own dialect; each dialect's reply decoder, run over the same bytes, tells
whose replies they are.  Pure and headless, like every codec.
"""

from __future__ import annotations

from collections.abc import Callable

from protocol.drill.codec import ReplyDecoder as DrillReplies
from protocol.framing import Rejected
from protocol.gcode.codec import make_decoder as gcode_replies
from protocol.stage.codec import EchoFrame, StageDecoder
from protocol.usb3.codec import ReplyDecoder as Usb3Replies


def _any_reply(result: object) -> bool:
    return not isinstance(result, Rejected)


def _echo(result: object) -> bool:
    """A command frame is what a stage is *sent*: only echoes count as its replies."""
    return isinstance(result, EchoFrame)


#: Dialect → words for the operator, a reader of that dialect's replies, and which of what
#: it reads are replies.
_READERS: dict[str, tuple[str, Callable[[], object], Callable[[object], bool]]] = {
    "stage": ("an XY stage", StageDecoder, _echo),
    "usb3": ("a three-axis USB unit", Usb3Replies, _any_reply),
    "drill": ("a PCB drill", DrillReplies, _any_reply),
    "gcode": ("a G-code board (GRBL or alike)", gcode_replies, _any_reply),
}


def replies_in(dialect: str, data: bytes) -> int:
    """How many well-formed replies of ``dialect`` the bytes hold."""
    _, make_reader, is_reply = _READERS[dialect]
    results = make_reader().feed(data)  # type: ignore[attr-defined]
    return sum(is_reply(r) for r in results)


def sounds_like(data: bytes, besides: str) -> str | None:
    """The machine the bytes sound like (in words), other than ``besides``; None if none."""
    others = dict(_READERS)
    others.pop(besides, None)
    scores = {dialect: replies_in(dialect, data) for dialect in others}
    best = max(scores, key=lambda d: scores[d], default=None)
    if best is None or scores[best] == 0:
        return None
    return _READERS[best][0]
