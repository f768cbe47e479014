"""VRTACKA's step-through: the loaded job's file walked line by line (FIDELITY S2-41).

The original PC program's "Načti řádek" read the Excellon file one line at a
time and showed the line, its coordinates and the coordinates converted to
microsteps; the operator then called the drill's procedures by their letter
buttons, in any order ("nemusime dodrzovat poradi instrukci, jak by to udelala
automatika").  This is the teaching mode the drill was built for.

The walk is built from the job the station loaded, not from a second reading
of the file: its operations carry their file lines, and their targets are
where the machine goes (a board placed by registration goes where it lies).
Every line of the file is a stop; a line with several positions (a slot's
two ends, a repeat) is one stop per position.  A stop's procedures are what
the program does there: ``X`` and ``Y`` to its position, then the drill's own
letters for what follows on the line (``V`` drill, ``K`` pen down, ``Z`` pen
up).  Nothing here sends anything: the session judges each command when the
operator sends it.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

if TYPE_CHECKING:  # the page that walks a job is built before any job (numpy) is loaded
    from app.jobs.program import Program

#: The drill's letter for each operation (by kind) that acts where the head stands.
PROCEDURE_LETTERS = {"drill": "V", "pen down": "K", "pen up": "Z"}


@dataclass(frozen=True)
class WalkStop:
    """One stop of the walk: a file line, and one position the job goes to on it."""

    line: int  # 1-based, in the job's file
    text: str  # the line as written (without its end)
    #: Where the job goes for this stop, in the program's millimetres (None: the line has none).
    position: tuple[float, float] | None
    #: The drill's letters for what the job does there after the move (``V``, ``K``, ``Z``).
    procedures: tuple[str, ...]
    part: int = 1  # which of the line's positions (1-based)
    parts: int = 1  # how many positions the line has


def walk_stops(
    program: Program, lines: Sequence[str], axes: tuple[str, str] = ("X", "Y")
) -> list[WalkStop]:
    """Every line of the job's file, each position the program reaches on it a stop.

    The position of a stop is where the program stands at the end of each run
    of moves sourced on that line (a drawn hole moves X, then Y: one stop).
    A procedure on a line before any move there acts where the previous line
    left the head.
    """
    from app.jobs.program import OpKind

    source = program.source
    name = source.name if source is not None else ""
    x_name, y_name = axes
    found: dict[int, list[tuple[tuple[float, float] | None, list[str]]]] = {}
    x: float | None = None
    y: float | None = None
    previous_move_line: int | None = None
    for op in program:
        on_file = op.source.file == name and 1 <= op.source.line <= len(lines)
        line = op.source.line
        if op.kind is OpKind.MOVE:
            x = op.target.get(x_name, x)
            y = op.target.get(y_name, y)
            here = (x, y) if x is not None and y is not None else None
            if on_file:
                stops = found.setdefault(line, [])
                if previous_move_line == line and stops:
                    stops[-1] = (here, stops[-1][1])  # the run of moves goes on
                else:
                    stops.append((here, []))
            previous_move_line = line if on_file else None
            continue
        previous_move_line = None
        letter = PROCEDURE_LETTERS.get(op.kind.value)
        if letter is None or not on_file:
            continue
        stops = found.setdefault(line, [])
        if not stops:
            here = (x, y) if x is not None and y is not None else None
            stops.append((here, []))
        stops[-1][1].append(letter)
    walk: list[WalkStop] = []
    for number, text in enumerate(lines, start=1):
        on_line = found.get(number, [])
        if not on_line:
            walk.append(WalkStop(number, text, None, ()))
            continue
        for part, (position, letters) in enumerate(on_line, start=1):
            walk.append(WalkStop(number, text, position, tuple(letters), part, len(on_line)))
    return walk


class JobWalk:
    """Where the operator is in the walk: Next and Previous move one stop."""

    def __init__(self, stops: Sequence[WalkStop]) -> None:
        self.stops = tuple(stops)
        #: The stop shown (-1: none yet, before the first "Next line").
        self.index = -1

    @property
    def current(self) -> WalkStop | None:
        return self.stops[self.index] if 0 <= self.index < len(self.stops) else None

    def next(self) -> WalkStop | None:
        """The next stop (the last one stays when there is none)."""
        if self.index + 1 < len(self.stops):
            self.index += 1
        return self.current

    def previous(self) -> WalkStop | None:
        """The previous stop (the first one stays when there is none)."""
        if self.index > 0:
            self.index -= 1
        return self.current

    @property
    def at_end(self) -> bool:
        return self.index >= len(self.stops) - 1

    @property
    def at_start(self) -> bool:
        return self.index <= 0
