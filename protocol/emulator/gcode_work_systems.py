"""GRBL 1.1's work coordinate systems G54…G59 and ``G10 L2``/``L20``, for the emulated board.

GRBL keeps six systems in its EEPROM (they survive a reset and a power
cycle; a reset, like ``M2``, selects G54 again) and the G92 offset in RAM.
A work position is the machine position minus the active system's offset
minus the G92 offset; ``WCO:`` reports their sum.  ``G10 L2 Pn`` stores the
values given as system n's offset (in machine coordinates), ``G10 L20 Pn``
stores what makes the tool's present place the values given in system n
(``gcode.c``: WCS = MPos - G92 - WPos).  ``P0`` is the active system.  Only
the axes named change.

Errors as GRBL gives them: no axis word ``error:26``, no ``P`` or ``L``
``error:28``, ``P`` beyond 6 ``error:29``, an ``L`` other than 2 or 20 (or
``L2`` with ``R``) ``error:20``, a negative ``P`` ``error:4``.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

#: GRBL's N_COORDINATE_SYSTEM: G54…G59.
SYSTEMS = 6
UNSUPPORTED = 20
NO_AXIS_WORDS = 26
VALUE_WORD_MISSING = 28
UNSUPPORTED_COORD_SYS = 29
NEGATIVE_VALUE = 4


@dataclass(frozen=True)
class WorkSystems:
    """The six stored offsets (machine coordinates) and the active one (0 is G54)."""

    stored: tuple[tuple[float, ...], ...]
    active: int = 0

    @classmethod
    def zero(cls, axes: int) -> WorkSystems:
        return cls(((0.0,) * axes,) * SYSTEMS)

    @property
    def offset(self) -> tuple[float, ...]:
        """The active system's offset."""
        return self.stored[self.active]

    @property
    def name(self) -> str:
        return f"G{54 + self.active}"

    def selected(self, code: int) -> WorkSystems:
        """``G54``…``G59``."""
        return replace(self, active=code - 54)

    def total(self, g92: tuple[float, ...]) -> tuple[float, ...]:
        """The work coordinate offset (``WCO:``): the active system's plus G92's."""
        return tuple(a + b for a, b in zip(self.offset, g92, strict=True))

    def set_by_g10(
        self,
        values: dict[str, float],
        axis_words: dict[int, float],
        machine: tuple[float, ...],
        g92: tuple[float, ...],
    ) -> WorkSystems | int:
        """``G10``: ``values`` holds the line's L, P (and R); ``axis_words`` the axes named,
        by index, in mm.  The new systems, or GRBL's error code."""
        if not axis_words:
            return NO_AXIS_WORDS
        if "P" not in values or "L" not in values:
            return VALUE_WORD_MISSING
        if values["P"] < 0:
            return NEGATIVE_VALUE
        number = int(values["P"])  # GRBL truncates P
        if number > SYSTEMS:
            return UNSUPPORTED_COORD_SYS
        level = values["L"]
        if level not in (2.0, 20.0) or (level == 2.0 and "R" in values):
            return UNSUPPORTED
        index = number - 1 if number > 0 else self.active
        offset = list(self.stored[index])
        for axis, value in axis_words.items():
            offset[axis] = value if level == 2.0 else machine[axis] - g92[axis] - value
        stored = list(self.stored)
        stored[index] = tuple(offset)
        return replace(self, stored=tuple(stored))
