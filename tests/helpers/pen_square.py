"""A 100 mm pen square: the small plotter job the G-code resume tests draw and cut."""

from __future__ import annotations

from app.jobs.program import Operation, OpKind, Program, SourceRef, move

SQUARE = [(10.0, 10.0), (110.0, 10.0), (110.0, 110.0), (10.0, 110.0), (10.0, 10.0)]


def square_program(*, back_home: bool = False) -> Program:
    """Pen up, to the first corner, pen down, round the square, pen up (then to 0, 0)."""
    ops: list[Operation] = [Operation(OpKind.PEN_UP, SourceRef("square", 1))]
    ops.append(move(SourceRef("square", 2), X=SQUARE[0][0], Y=SQUARE[0][1]))
    ops.append(Operation(OpKind.PEN_DOWN, SourceRef("square", 3)))
    for n, (x, y) in enumerate(SQUARE[1:], start=4):
        ops.append(move(SourceRef("square", n), X=x, Y=y))
    ops.append(Operation(OpKind.PEN_UP, SourceRef("square", 8)))
    if back_home:
        ops.append(move(SourceRef("square", 9), X=0.0, Y=0.0))
    return Program("square", tuple(ops))
