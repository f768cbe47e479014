"""The G-code lines sent, read as the board will run them: legs of the envelope, in machine
coordinates.

Status reports give the machine position (``MPos``, or ``WPos`` with the last
``WCO``); the lines give work coordinates in the modes in force.  This reads
just enough G-code to turn each line into where the machine will go: G0/G1
(modal), G2/G3 arcs (as their bounding box in the XY plane), G90/G91, G20/G21,
G53, ``$J=`` jogs (their own modes, the board's left alone), and ``G92``: on a
GRBL board a new work offset (the machine stays), on the plotters' own
firmwares a new machine position (the reports jump there).  ``G28`` on those
firmwares goes to 0 through the point given.

What the station cannot place it does not guess: homing (``$H``), GRBL's
``G28``/``G30`` (stored positions), probing, other coordinate systems or their
settings (``G54``…, ``G10``), ``G92.1`` and planes other than G17 *release*
the envelope, and nothing is judged until the machine next stands idle with
every line answered, where the session anchors it again.

Lines are read by the one G-code lexer as GRBL reads them
(:func:`protocol.gcode.words.scan_grbl_words` of its GRBL reading), as the console's gate
reads them.

Pure logic, no Qt: the session feeds it the lines it wrote.
"""

from __future__ import annotations

import math

from app.machines.envelope import Envelope, arc_box
from protocol.gcode.words import grbl_text, scan_grbl_words

_INCH = 25.4
#: G codes whose motion or coordinates the station cannot follow: the envelope lets go.
_UNFOLLOWED = frozenset(
    {10.0, 18.0, 19.0, 28.1, 30.0, 30.1, 38.2, 38.3, 38.4, 38.5, 43.1, 49.0, 92.1, 92.2, 92.3}
    | {54.0, 55.0, 56.0, 57.0, 58.0, 59.0, 59.1, 59.2, 59.3}
)
#: M codes with axis words that are no destination (drivers off on the winder).
_NO_MOTION_M = frozenset({17.0, 18.0, 84.0})


class PlannedPath:
    """Feeds ``envelope`` with the path of the lines sent, for a board with ``axes``.

    ``grbl``: ``G92`` is a work offset and ``G28`` a stored position (GRBL
    1.1); otherwise the plotters' own firmwares' meaning (see the module).
    """

    def __init__(self, envelope: Envelope, axes: tuple[str, ...], *, grbl: bool) -> None:
        self.envelope = envelope
        self.axes = axes
        self.grbl = grbl
        #: The work offset (machine minus work position) the lines sent leave in force.
        self.offset = [0.0] * len(axes)
        self.reset_modes()

    def reset_modes(self) -> None:
        """A board's power-on (and reset) modes: G0, G90, G21."""
        self.relative = False
        self.inch = False
        self.motion = 0.0

    def anchor(self, machine: tuple[float, ...], offset: tuple[float, ...]) -> None:
        """The board stands at ``machine`` with every line answered, ``offset`` in force."""
        self.envelope.anchor(machine[: len(self.axes)])
        self.offset = list(offset[: len(self.axes)]) + [0.0] * (len(self.axes) - len(offset))

    def line(self, text: str, label: str, tag: object = None) -> None:
        """One line written to the board: its motion joins the envelope."""
        code = grbl_text(text)  # GRBL's reading: "$ J=" is a jog, "$ H" homing
        jog = code.startswith("$J=")
        if jog:
            code = code[3:]
        elif code.startswith("$"):
            if code.startswith(("$H", "$RST", "$C")):
                self.envelope.release()  # homing, settings reset, check mode: not followed
            return
        words = scan_grbl_words(code)
        g_codes: set[float] = set()
        m_codes: set[float] = set()
        for letter, value in words:
            if letter == "G":
                g_codes.add(round(value, 1))
            elif letter == "M":
                m_codes.add(round(value, 1))
        relative, inch, motion = self.relative, self.inch, self.motion
        if g_codes:  # most of a drawing's lines are axis words alone: no mode changes
            if 90.0 in g_codes:
                relative = False
            if 91.0 in g_codes:
                relative = True
            if 20.0 in g_codes:
                inch = True
            if 21.0 in g_codes:
                inch = False
            for candidate in (0.0, 1.0, 2.0, 3.0):
                if candidate in g_codes:
                    motion = candidate
        if not jog:  # a jog leaves the board's modes as they were
            self.relative, self.inch, self.motion = relative, inch, motion
        else:
            motion = 1.0
        if g_codes & _UNFOLLOWED or (self.grbl and 28.0 in g_codes):
            self.envelope.release()
            return
        scale = _INCH if inch else 1.0
        named = {
            letter: value * (1.0 if letter == "A" else scale)
            for letter, value in words
            if letter in self.axes
        }
        if m_codes & _NO_MOTION_M:
            return
        here = self.envelope.end
        if here is None:
            return  # not followed until the board is anchored again
        if 92.0 in g_codes:
            self._set_position(here, named, label, tag)
            return
        work = [h - o for h, o in zip(here, self.offset, strict=True)]
        if 28.0 in g_codes:  # the plotters' firmwares: through the point given, then to 0
            if named:
                self.envelope.add_line(self._target(work, named, relative), label, tag)
            self.envelope.add_line((0.0,) * len(self.axes), label, tag)
            return
        if not named or 4.0 in g_codes:
            return
        if 53.0 in g_codes:
            target = tuple(named.get(a, h) for a, h in zip(self.axes, here, strict=True))
        else:
            target = self._target(work, named, relative)
        if motion in (2.0, 3.0) and not jog:
            self._arc(here, target, words, scale, label, tag)
        else:
            self.envelope.add_line(target, label, tag)

    def _target(
        self, work: list[float], named: dict[str, float], relative: bool
    ) -> tuple[float, ...]:
        """Machine coordinates of a line's axis words from the work position ``work``."""
        out = []
        for axis, (w, offset) in enumerate(zip(work, self.offset, strict=True)):
            name = self.axes[axis]
            value = named.get(name)
            end = w if value is None else (w + value if relative else value)
            out.append(end + offset)
        return tuple(out)

    def _set_position(
        self, here: tuple[float, ...], named: dict[str, float], label: str, tag: object
    ) -> None:
        if self.grbl:
            # A new work offset: the machine stays; absolute targets shift from now on.
            for axis, name in enumerate(self.axes):
                if name in named:
                    self.offset[axis] = here[axis] - named[name]
            return
        # The plotters' firmwares: the position itself becomes what is named (a bare G92:
        # the origin), so the reports jump there once the moves before are done.
        if named:
            point = tuple(named.get(a, h) for a, h in zip(self.axes, here, strict=True))
        else:
            point = (0.0,) * len(self.axes)
        self.envelope.jump(point, label, tag)

    def _arc(
        self,
        here: tuple[float, ...],
        target: tuple[float, ...],
        words: list[tuple[str, float]],
        scale: float,
        label: str,
        tag: object,
    ) -> None:
        """An arc in the XY plane: its circle's box (both centres' of an R arc)."""
        if "X" not in self.axes or "Y" not in self.axes:
            self.envelope.release()
            return
        x, y = self.axes.index("X"), self.axes.index("Y")
        values = dict(words)
        centres: list[tuple[float, float]] = []
        if "R" in values:
            radius = abs(values["R"] * scale)
            dx, dy = target[x] - here[x], target[y] - here[y]
            chord = math.hypot(dx, dy)
            if chord == 0.0 or chord > 2 * radius + 1e-6:
                self.envelope.release()  # the board refuses or draws what is not known
                return
            rise = math.sqrt(max(0.0, radius**2 - (chord / 2) ** 2))
            mid_x, mid_y = (here[x] + target[x]) / 2, (here[y] + target[y]) / 2
            for sign in (1.0, -1.0):
                centres.append((mid_x - sign * rise * dy / chord, mid_y + sign * rise * dx / chord))
        else:
            centres.append(
                (here[x] + values.get("I", 0.0) * scale, here[y] + values.get("J", 0.0) * scale)
            )
        lows, highs = [], []
        for cx, cy in centres:
            centre = list(here)
            centre[x], centre[y] = cx, cy
            low, high = arc_box(here, target, centre, (x, y))
            lows.append(low)
            highs.append(high)
        low = tuple(min(c) for c in zip(*lows, strict=True))
        high = tuple(max(c) for c in zip(*highs, strict=True))
        self.envelope.add_box(low, high, target, label, tag)
