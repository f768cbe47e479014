"""Which bit the operator inserts when: one prompt per distinct drill, in a chosen order.

A drill file often defines the same diameter twice (two tools of 0.80 mm from
two footprint libraries) or a tool without a diameter.  Prompting for each
would have the operator change a bit for an identical one, or insert a bit
of "0.00 mm": so a duplicate is drilled with the first tool of its diameter
and flagged, and a tool without a diameter is flagged and its holes left out
(no bit can be named for them; the note says how many and where the tool is
defined, so the file can be fixed rather than the board ruined by a guess).

Smallest first is the bench habit: small bits break least when the board is
still held by every hole-free area, and the large holes, drilled last, do
not leave the small ones' copper unsupported.
"""

from __future__ import annotations

from dataclasses import dataclass

from PySide6.QtCore import QCoreApplication

#: Diameters closer than this (mm) are the same bit.
SAME_BIT_MM = 0.0005


@dataclass(frozen=True)
class BitGroup:
    """One bit change: the tool named in the prompt and the tools drilled with its bit."""

    tool: str
    diameter_mm: float
    tools: tuple[str, ...]  # the prompted tool first, then its duplicates in file order


@dataclass(frozen=True)
class BitPlan:
    groups: tuple[BitGroup, ...]
    #: Tools whose holes are not drilled (no diameter).
    left_out: tuple[str, ...]
    #: What the operator is told: each duplicate and each tool without a diameter.
    flags: tuple[str, ...]


def plan_bits(
    tools: list[tuple[str, float, str]],
    counts: dict[str, int],
    *,
    smallest_first: bool = False,
    one_bit: bool = False,
) -> BitPlan:
    """Group ``tools`` (name, diameter mm, where defined) that drill holes into bit changes.

    Tools without holes are neither prompted nor flagged: CAD tools list
    every tool of the library, and that is no mistake of the file.

    ``one_bit`` is the original drill's way ("nepocita s vymenou vrtaku",
    FIDELITY S2-40): every hole, whatever its tool says, is drilled with the
    one bit in the spindle, so every tool with holes is one group and nothing
    is flagged (a duplicate or a missing diameter changes nothing then).
    """
    if one_bit:
        used = [(name, diameter) for name, diameter, _where in tools if counts.get(name, 0)]
        if not used:
            return BitPlan((), (), ())
        first, diameter = used[0]
        group = BitGroup(first, diameter, tuple(name for name, _d in used))
        return BitPlan((group,), (), ())
    groups: list[BitGroup] = []
    left_out: list[str] = []
    flags: list[str] = []
    for name, diameter, where in tools:
        holes = counts.get(name, 0)
        if holes == 0:
            continue
        if not diameter > 0:
            left_out.append(name)
            flags.append(
                QCoreApplication.translate(
                    "JobFile",
                    "{0}: {1} has no diameter: its {2} hole(s) are not drilled "
                    "(give the tool a diameter in the file)",
                ).format(where, name, holes)
            )
            continue
        for index, group in enumerate(groups):
            if abs(group.diameter_mm - diameter) < SAME_BIT_MM:
                groups[index] = BitGroup(group.tool, group.diameter_mm, (*group.tools, name))
                flags.append(
                    QCoreApplication.translate(
                        "JobFile",
                        "{0}: {1} is {2:.2f} mm like {3}: its {4} hole(s) are drilled "
                        "with {3}'s bit, no change",
                    ).format(where, name, diameter, group.tool, holes)
                )
                break
        else:
            groups.append(BitGroup(name, diameter, (name,)))
    if smallest_first:
        groups.sort(key=lambda g: g.diameter_mm)  # stable: equal sizes keep file order
    return BitPlan(tuple(groups), tuple(left_out), tuple(flags))
