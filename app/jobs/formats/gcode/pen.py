"""Pen conventions: which commands of a G-code file lift or lower the pen on a given machine.

Pen rules, in order: the profile's own pen_up/pen_down (command word, and S
value where the profile gives one); the GRBL servo convention (``M3``/``M4``
with S > 0 down, ``M5`` up) unless the profile gives M3/M4/M5 another meaning
(the CoreXY plotter lifts with M3); servo flavours ``M300 S<n>`` (Unicorn)
and ``M280 P0 S<n>`` (Makelangelo), where of the two S values the file uses
most the smaller lowers the pen (Unicorn S30 down / S50 up, Makelangelo S25 /
S90; any other value, like Unicorn's ``S255`` servo off, is not a pen move, and
a file using a single value does not say which way it moves the pen, so its
servo lines are sent as written);
and on a ``z_is_pen`` machine Z > 0 up, Z ≤ 0 down, but only in a file whose
Z moves go both above and down to 0 (a file that keeps Z at 0 throughout
does not use Z for its pen).  A file without any pen command is previewed
with G0 as travel and G1/G2/G3 as work.
"""

from __future__ import annotations

import math
import re
from collections import Counter
from collections.abc import Mapping, Sequence
from dataclasses import dataclass

from app.jobs.formats.gcode.words import PARAMETERS, Tokenizer, normal
from app.profiles import GcodeSettings
from protocol.gcode.words import WORD, Word, line_code

#: Pen states (as stored per operation: pen down or not).
UP, DOWN = 0, 1

#: A line that may hold a servo pen command (the prescan reads only those).
SERVO_HINT = re.compile(r"[Mm]0*(?:300|280)(?![\d.])")


@dataclass(frozen=True)
class PenCommand:
    word: str
    s: float | None
    state: int
    text: str


def profile_pen(text: str, state: int) -> PenCommand:
    """A profile's pen command: its command word and the S value it names, if any."""
    code = text.strip()
    word, s = "", None
    for match in WORD.finditer(code.upper()):
        letter, value = match.group(1), float(match.group(2))
        if letter in "GM" and not word:
            word = normal(letter, value)
        elif letter == "S":
            s = value
    return PenCommand(word, s, state, code)


def servo_levels(values: Counter[float]) -> tuple[float, float] | None:
    """(down, up) of a servo pen: of the two S values used most, the smaller lowers it."""
    common = [value for value, _ in values.most_common(2)]
    if len(common) < 2:
        return None
    return min(common), max(common)


class PenRules:
    """The pen rules (see the module doc) for one machine and, after :meth:`prescan`, one file."""

    def __init__(self, settings: GcodeSettings) -> None:
        self.z_is_pen = settings.z_is_pen
        self.pen_up = profile_pen(settings.pen_up, UP)
        self.pen_down = profile_pen(settings.pen_down, DOWN)
        # Entries naming an S value first, so "M3 S0" / "M3 S1000" pairs resolve exactly.
        self.pen_map = sorted((self.pen_up, self.pen_down), key=lambda p: p.s is None)
        profile_words = {self.pen_up.word, self.pen_down.word}
        self.grbl_pen = not profile_words & {"M3", "M4", "M5"} or (
            self.pen_up.word == "M5" and self.pen_down.word in ("M3", "M4")
        )
        #: The file's servo (down, up) S values per servo word, where it uses two.
        self.servo: dict[str, tuple[float, float]] = {}
        #: The file's Z heights are its pen (on a ``z_is_pen`` machine).
        self.z_pen = False

    def prescan(self, lines: list[str], tokens: Tokenizer) -> None:
        """What needs the whole file: the servo S values in use, and whether Z is the pen."""
        servo: dict[str, Counter[float]] = {"M300": Counter(), "M280": Counter()}
        z_low, z_high = math.inf, -math.inf
        for raw in lines:
            has_servo = SERVO_HINT.search(raw) is not None
            has_z = self.z_is_pen and ("Z" in raw or "z" in raw)
            if not (has_servo or has_z):
                continue
            code = line_code(raw)
            if not code or code[0] in "$%" or PARAMETERS.search(code):
                continue
            words = tokens.words_or_none(code)
            if words is None:
                continue
            commands = {normal(w.letter, w.value) for w in words if w.letter in "GM"}
            values = {w.letter: w.value for w in words}
            if "M300" in commands and "S" in values:
                servo["M300"][values["S"]] += 1
            if "M280" in commands and values.get("P") == 0 and "S" in values:
                servo["M280"][values["S"]] += 1
            if "Z" in values and not commands & {"G92", "G28", "G10", "G53"}:
                z_low, z_high = min(z_low, values["Z"]), max(z_high, values["Z"])
        for word, counts in servo.items():
            levels = servo_levels(counts)
            if levels is not None:
                self.servo[word] = levels
        self.z_pen = self.z_is_pen and z_low <= 0 < z_high

    def pen_command(
        self, commands: Mapping[str, int], params: Mapping[str, int], words: Sequence[Word]
    ) -> tuple[int | None, set[int]]:
        """The pen state a command word of the line sets, and the words that say so."""
        s = words[params["S"]].value if "S" in params else None
        for word, index in commands.items():
            if word[0] != "M":
                continue
            used = {index} | ({params["S"]} if "S" in params else set())
            for pen in self.pen_map:
                if word == pen.word and (pen.s is None or s == pen.s):
                    return pen.state, used
            if self.grbl_pen and word in ("M3", "M4") and s is not None and s > 0:
                return DOWN, used
            if self.grbl_pen and word == "M5":
                return UP, {index}
            if word in self.servo and s is not None:
                if word == "M280":
                    if "P" not in params or words[params["P"]].value != 0:
                        continue
                    used |= {params[k] for k in ("P", "T") if k in params}
                down, up = self.servo[word]
                if s == down:
                    return DOWN, used
                if s == up:
                    return UP, used
        return None, set()
