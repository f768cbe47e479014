"""Where a typed G-code line would send the machine: the motion gate's view of a console line.

The console is the operator's raw access to the board, so its lines are not
rewritten; but a line that would move beyond the travel is first shown to
the operator for confirmation.  This reads just enough G-code for that: the
distance mode in force (tracked from every line the station sent), G90/G91
and G20/G21 on the line itself, ``$J=`` jogs and G53.  Lines that set
coordinates (G92, G10) or home (G28, ``$H``) move nothing this check can
place, and are let through.

The line is read by the one G-code lexer (:func:`protocol.gcode.words.scan_words`)
as GRBL reads it: an unclosed ``(`` comments out the rest, spaces do not
count (``X1 000`` is X1000, ``$ J=`` a jog), and what is not a word is
skipped rather than refused, so the gate never places a move short of where
the board would go; whether the board takes the line is the board's to answer.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from protocol.gcode.words import grbl_text, scan_words

_INCH = 25.4
#: Words after which axis letters are not a destination.
_NOT_A_MOVE = frozenset({"G4", "G10", "G28", "G30", "G92"})


@dataclass(frozen=True)
class LineMotion:
    """Where a line ends, per axis named on it, and the distance mode it leaves in force."""

    targets: Mapping[str, float]
    relative_after: bool
    #: The targets are machine coordinates (``G53``); otherwise work coordinates (GRBL adds
    #: its work offset to them).
    machine: bool = False


def line_motion(
    line: str, relative: bool, position: Mapping[str, float], axes: tuple[str, ...]
) -> LineMotion:
    """The targets of ``line`` for a machine at ``position`` in the given distance mode."""
    text = grbl_text(line)  # GRBL's reading: "$ J=" is a jog too
    jog = text.startswith("$J=")
    if jog:
        text = text[3:]
    elif text.startswith("$"):
        return LineMotion({}, relative)
    words = scan_words(text)
    codes = {f"{letter}{number:g}" for letter, number in words if letter in "GM"}
    mode = relative
    if "G90" in codes:
        mode = False
    if "G91" in codes:
        mode = True
    after = relative if jog else mode  # a jog leaves the modal state as it was
    if codes & _NOT_A_MOVE:
        return LineMotion({}, after)
    scale = _INCH if "G20" in codes else 1.0
    machine = "G53" in codes
    targets: dict[str, float] = {}
    for letter, number in words:
        if letter not in axes:
            continue
        value = number * scale
        here = position.get(letter, 0.0)
        targets[letter] = here + value if mode and not machine else value
    return LineMotion(targets, after, machine)
