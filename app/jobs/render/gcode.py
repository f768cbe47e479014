"""One operation as the G-code line a G-code machine is sent (docs/protocols.md §4).

Pure functions, shared by the G-code session's job streaming and the
program export (:mod:`app.jobs.formats.string_art.export`):

* an operation that carries its own text (``op.line``, read from a G-code
  file) is sent as written — except WAIT and COMMENT, which the station
  handles itself (the runner asks the operator; a comment is only shown);
* MOVE → ``G1 X… Y… Z… A… F…`` with the target's axes in G-code order
  (X Y Z A B C unless ``axis_order`` says otherwise), 3 decimals; without a
  feed ``G0`` (the machine's own rapid rate);
* PEN_UP / PEN_DOWN → the profile's ``pen_up`` / ``pen_down`` command;
* WAIT, COMMENT and a GCODE operation without text → None: nothing to send;
* DRILL → ValueError: the G-code dialect has no drill cycle; a G-code
  machine's program drills with explicit moves (the string-art winder's Z).
"""

from __future__ import annotations

import unicodedata
from collections.abc import Mapping, Sequence

from app.jobs.program import Operation, OpKind
from app.profiles import GcodeSettings, MachineProfile

#: The usual order of axis words on a G-code line.
GCODE_AXIS_ORDER = ("X", "Y", "Z", "A", "B", "C")
#: The longest line a G-code device takes, without the ``\n`` (docs/protocols.md §4: 80 with it).
MAX_LINE = 79


def format_number(value: float, decimals: int = 3) -> str:
    """``12.500``, never ``-0.000``."""
    text = f"{value:.{decimals}f}"
    if text.startswith("-") and float(text) == 0.0:
        text = text[1:]
    return text


def format_feed(value: float) -> str:
    """``F`` values without needless zeros: 4500, 937.5."""
    return format_number(value).rstrip("0").rstrip(".")


def _order(axes: Sequence[str], axis_order: Sequence[str]) -> list[str]:
    rank = {name: i for i, name in enumerate(axis_order)}
    for axis in axes:
        if len(axis) != 1 or not axis.isalpha() or not axis.isupper():
            raise ValueError(f"axis {axis!r} is no G-code axis word (one capital letter)")
    return sorted(axes, key=lambda axis: (rank.get(axis, len(rank)), axis))


def feed_for(target: Mapping[str, float], profile: MachineProfile) -> float | None:
    """The feed (units a minute) of a move of ``target``'s axes: its slowest axis' top speed.

    None when the profile knows none of the axes (render a rapid ``G0``).
    """
    speeds = [a.max_speed * 60.0 for a in profile.axes if a.name in target and a.max_speed > 0]
    return min(speeds) if speeds else None


def render_operation(
    op: Operation,
    settings: GcodeSettings,
    feed_mm_min: float | None = None,
    *,
    axis_order: Sequence[str] = GCODE_AXIS_ORDER,
) -> str | None:
    """The line to send for ``op`` (no ``\\n``), or None when there is nothing to send."""
    if op.kind in (OpKind.WAIT, OpKind.COMMENT):
        return None
    if op.line:
        return op.line
    if op.kind is OpKind.MOVE:
        if not op.target:
            return None
        words = [
            f"{axis}{format_number(op.target[axis])}"
            for axis in _order(list(op.target), axis_order)
        ]
        if feed_mm_min is None:
            return " ".join(["G0", *words])
        if not feed_mm_min > 0:
            raise ValueError(f"feed {feed_mm_min!r} must be positive")
        return " ".join(["G1", *words, f"F{format_feed(feed_mm_min)}"])
    if op.kind is OpKind.PEN_UP:
        return settings.pen_up
    if op.kind is OpKind.PEN_DOWN:
        return settings.pen_down
    if op.kind is OpKind.GCODE:
        return None
    raise ValueError(
        f"{op.source}: G-code has no drill cycle — a G-code machine drills with explicit moves"
    )


def comment(text: str, width: int = MAX_LINE, prefix: str = "") -> str:
    """``prefix(text)`` as one G-code comment: ASCII, no nested parentheses, within ``width``."""
    # A translated message keeps its letters without their accents ("Vložte" → "Vlozte").
    plain = "".join(c for c in unicodedata.normalize("NFKD", text) if not unicodedata.combining(c))
    clean = plain.encode("ascii", "replace").decode("ascii")
    clean = clean.replace("(", "[").replace(")", "]").replace("\n", " ").strip()
    room = width - len(prefix) - 2
    if len(clean) > room:
        clean = clean[: max(room - 3, 0)].rstrip() + "..."
    return f"{prefix}({clean})"
