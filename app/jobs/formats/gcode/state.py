"""What the G-code parser carries from line to line, and what a line makes before it is kept."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np

from app.jobs.formats.gcode.program import NO_MOTION, RAPID
from protocol.gcode.words import Word


@dataclass
class State:
    """The modal state of the file as the machine will see it."""

    position: list[float]
    offset: list[float]
    scale: float = 1.0
    relative: bool = False
    motion: int = RAPID
    plane: int = 17
    z_work: float = math.nan
    pen: int = -1  # unknown, shown as up
    feed: float = math.nan  # mm/min, as last set by F (NaN: never)

    def copy(self) -> State:
        return State(
            list(self.position),
            list(self.offset),
            self.scale,
            self.relative,
            self.motion,
            self.plane,
            self.z_work,
            self.pen,
            self.feed,
        )


@dataclass
class Pending:
    """One operation a line makes, before the line is known to be acceptable."""

    kind: int
    text: str
    sent: Sequence[Word] = ()  # the words it sends (checked against the machine)
    motion: int = NO_MOTION
    feed: float = math.nan
    pen: int = -1  # pen state set by this operation (-1: unchanged)
    target: dict[int, float] = field(default_factory=dict)
    arc: np.ndarray | None = None
    dwell: float = 0.0
    message: str = ""
    translated: bool = False  # a pen line sent as the profile's command
    checked: bool = False  # ``text`` is the profile's own, already checked
