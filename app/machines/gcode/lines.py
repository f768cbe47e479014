"""A line on its way to a G-code board, as every part of the session tags it."""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class SentLine:
    """A line on its way: what was sent, by whom, and for a job the operation it carries."""

    serial: int
    text: str
    #: "job", "resume" (the set-up before a resumed job), "console", "intent" (panels) or "jog"
    origin: str
    op_index: int | None = None
