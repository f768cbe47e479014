"""GRBL 1.1's spindle as its reports show it (``A:``) and as the lines sent leave it.

A servo pen plotter on GRBL moves its pen with the spindle (``M3 S1000``
down, ``M5`` up), so the spindle state GRBL reports is the pen's.  What
GRBL 1.1h does (``report.c``, ``spindle_control.c``, ``gcode.c``):

* ``|A:`` is written only in a report that carries ``|Ov:``, right after it:
  ``S`` for the spindle on clockwise (M3), ``C`` counter-clockwise (M4), then
  ``F`` (flood, M8) and ``M`` (mist, M7); the field is left out when nothing
  is on.  A report with ``Ov:`` and no ``A:`` says the spindle is off; one
  without ``Ov:`` says nothing.
* The spindle is "on" while its PWM runs: ``S0`` switches it off although
  ``M3`` is in force.
* ``Ov:`` comes every 10th report idle, every 20th busy, and in the first
  report after any spindle or coolant change (``spindle_set_state`` sets the
  refresh counter to 0) — the second when that first one carries ``WCO:``.
* A spindle change synchronises the planner first (``spindle_sync``): the
  ``ok`` of an ``M3``/``M5`` line comes once every move before it has run and
  the spindle has changed.  GRBL calls it when the line changes the spindle
  mode (M3/M4/M5), or its speed while the spindle is on; at a program end
  (``M2``/``M30``) always.  A soft reset switches it off and sets S to 0.

The station (``app/machines/gcode/pen_watch.py``) follows the lines it sends
with :class:`Spindle` and compares with :func:`reported_spindle`.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from protocol.gcode.words import WordError, grbl_text, split_words

#: The spindle modes: GRBL's M3 (clockwise), M4 (counter-clockwise), M5 (off).
CW, CCW, OFF = 3, 4, 5


def reported_spindle(fields: Mapping[str, str]) -> str | None:
    """What a report says of the spindle: "S", "C", "" (off), or None (no ``Ov:``: nothing,
    or an ``A:`` field that is no accessory state GRBL writes)."""
    if "Ov" not in fields:
        return None
    text = fields.get("A", "")
    letters = set(text)
    if len(letters) != len(text) or not letters <= set("SCFM") or {"S", "C"} <= letters:
        return None
    return "S" if "S" in letters else "C" if "C" in letters else ""


@dataclass(frozen=True, slots=True)
class SpindleWords:
    """What one line does to the spindle: its M3/M4/M5 and S words, a program end."""

    mode: int | None = None
    speed: float | None = None
    program_end: bool = False
    #: The line leaves the spindle in a state these words cannot tell (``$C``: check mode).
    unknown: bool = False

    @property
    def touches(self) -> bool:
        return self.mode is not None or self.speed is not None or self.program_end or self.unknown


NOTHING = SpindleWords()


def spindle_words(line: str) -> SpindleWords:
    """The spindle words of a line as GRBL reads it (comments and spaces dropped)."""
    text = grbl_text(line).upper()
    if text.startswith("$"):
        if text == "$C":
            return SpindleWords(unknown=True)  # check mode: nothing runs, its end resets
        if text == "$SLP":
            return SpindleWords(mode=OFF)  # sleep: spindle and coolant off
        return NOTHING  # settings, jogs ($J= has no M or S), homing, unlock
    words = split_words(text, bare_values=False)
    if isinstance(words, WordError):
        return NOTHING  # refused (error:1/2): it runs not
    mode: int | None = None
    speed: float | None = None
    end = False
    for word in words:
        if word.letter == "M" and word.value in (CW, CCW, OFF):
            mode = int(word.value)
        elif word.letter == "M" and word.value in (2, 30):
            end = True
        elif word.letter == "S":
            speed = word.value
    return SpindleWords(mode, speed, end)


@dataclass(frozen=True, slots=True)
class Spindle:
    """GRBL's spindle mode and speed (None: not known)."""

    mode: int | None = None
    speed: float | None = None

    @property
    def seen(self) -> str | None:
        """What ``A:`` shows of it: "S", "C", "" (off), None (not known)."""
        if self.mode == OFF:
            return ""
        if self.mode is None or self.speed is None:
            return None
        if self.speed <= 0:
            return ""
        return "S" if self.mode == CW else "C"

    def after(self, words: SpindleWords) -> Spindle:
        """The spindle once a line with ``words`` has run."""
        if words.unknown:
            return UNKNOWN
        speed = self.speed if words.speed is None else words.speed
        mode = self.mode if words.mode is None else words.mode
        if words.program_end:
            mode = OFF
        return Spindle(mode, speed)

    def refreshes(self, words: SpindleWords) -> bool | None:
        """Whether GRBL calls ``spindle_set_state`` for the line (and so reports ``Ov:`` at
        once); None where the state before it is not known."""
        if words.program_end:
            return True
        if words.unknown:
            return None
        if words.mode is not None and words.mode != self.mode:
            return self.mode is not None or None
        if words.speed is not None and words.speed != self.speed:
            if self.mode is None or self.speed is None:
                return None
            return self.mode != OFF  # a new S while off is only kept
        return False


UNKNOWN = Spindle()
#: After a reset or power-up: off, S0.
AT_RESET = Spindle(OFF, 0.0)
