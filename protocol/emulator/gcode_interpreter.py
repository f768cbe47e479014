"""The emulated board's G-code parser: one line of words into planner blocks, or GRBL's error.

A line is all or nothing, as in GRBL: any error leaves the modal state and
the position untouched and queues no block.  Within a line the words act in
GRBL's order whatever order they were written in: feed rate, spindle or pen,
dwell, units/distance modes, G92 or G28, motion, then ``M0``/``M2``.

Decisions the contract leaves open, made here:

- On a GRBL board (``grbl``) ``G92`` sets a work offset as GRBL 1.1 does: the
  machine position stays, the offset becomes machine position minus the
  given values (per named axis, the others keep theirs), and every absolute
  target from then on is the written value plus the offset; ``G92.1`` clears
  it, and a soft reset too (GRBL's ``gc_init``).  Both reach the planner as a
  :class:`SetOffset` block, because GRBL synchronises on a work-offset change
  (``FORCE_BUFFER_SYNC_DURING_WCO_CHANGE``).  Travel limits stay in machine
  coordinates.  On the plotters' own firmwares ``G92`` says where the tool is
  now: the position itself changes (what their firmwares do).
- ``G28`` goes to 0 on every axis at the rapid rate, through the given
  point first when the line has axis words; ``$H`` (the firmware's) does the
  same without the point.
- ``G4 P`` is in the machine's unit (:attr:`GcodeConfig.dwell_p_seconds`):
  seconds on GRBL, milliseconds on the plotters' own firmwares (the
  contract's); ``G4 S`` seconds.
- ``M98``/``M99`` take their number bare (``M98 500``) or as ``P``; a step
  interval of 0 or less, or a negative servo level, is ``error:4``.  ``M99``
  lifts the pen to that servo level (the plotter's "Zdvihni popisovač …").
- A bare ``G92`` is ``error:26`` as in GRBL, except on the CoreXY plotter
  (``bare_g92``), whose firmware makes the current position the origin.
- ``M2``/``M30`` end the program: G1 and G90 again, and the pen up.
- ``M18`` (the winder only) switches off the drivers of the axes it names
  (``M18 Z0``: an axis word's value is not used, but this parser's words
  need one), every driver when it names none (Marlin's form); it moves
  nothing, and the next move of an axis switches its driver on again.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from protocol.emulator.gcode_machine import GcodeConfig, PenMapping
from protocol.emulator.gcode_planner import (
    Block,
    DriversOff,
    Dwell,
    Move,
    Pause,
    PenChange,
    SetOffset,
    SetPosition,
)
from protocol.emulator.gcode_work_systems import WorkSystems
from protocol.gcode.junctions import axis_limited, unit_vector
from protocol.gcode.words import EXPECTED_COMMAND_LETTER, Word

# GRBL's error codes the parser gives.
NEGATIVE_VALUE = 4
TRAVEL_EXCEEDED = 15
UNSUPPORTED = 20
MODAL_GROUP_VIOLATION = 21
VALUE_NOT_INTEGER = 23
UNDEFINED_FEED_RATE = 22
AXIS_COMMAND_CONFLICT = 24
WORD_REPEATED = 25
NO_AXIS_WORDS = 26
INVALID_LINE_NUMBER = 27
VALUE_WORD_MISSING = 28
UNUSED_WORDS = 36
MAX_VALUE_EXCEEDED = 38
NO_AXIS_WORDS_IN_PLANE = 32
INVALID_TARGET = 33
ARC_RADIUS_ERROR = 34
NO_OFFSETS_IN_PLANE = 35

#: ``G92.1`` (GRBL: clear the work offset), kept in the non-modal group under this number.
G92_1 = 921

_G_GROUPS = {
    **dict.fromkeys((0, 1, 2, 3), "motion"),
    **dict.fromkeys((4, 10, 28, 92, G92_1), "non-modal"),
    17: "plane",
    **dict.fromkeys((20, 21), "units"),
    **dict.fromkeys((90, 91), "distance"),
    94: "feed mode",
    **dict.fromkeys((54, 55, 56, 57, 58, 59), "coordinates"),
}
_M_GROUPS = {
    **dict.fromkeys((0, 1, 2, 30), "flow"),
    **dict.fromkeys((3, 4, 5), "spindle"),
    **dict.fromkeys((8, 9), "coolant"),
    **dict.fromkeys((98, 99), "plotter"),
    18: "drivers",
}
#: Value words besides the axes; each may appear once per line.
_VALUE_LETTERS = "FSPIJR"
#: Letters of axes no machine here has: GRBL calls them unsupported.
_OTHER_AXES = "BCUVW"
_MAX_LINE_NUMBER = 9_999_999
#: GRBL 1.1's largest tool number (MAX_TOOL_NUMBER).
_MAX_TOOL = 255
_MM_PER_INCH = 25.4
#: Radians: GRBL's margin that makes a full circle of an arc ending where it starts.
_ARC_EPS = 5e-7
#: More segments than this is an arc far beyond any travel (a full circle of
#: about 4 m radius at 0.002 mm): refused before flattening it takes forever.
_MAX_ARC_SEGMENTS = 100_000


@dataclass(frozen=True)
class Modal:
    """The parser's modal state (GRBL's ``$G``); feed in mm (or degrees) per minute."""

    motion: int = 0
    absolute: bool = True
    inches: bool = False
    feed: float | None = None
    spindle_on: bool = False
    #: ``M4`` (counter-clockwise) rather than ``M3``: GRBL's ``$G`` and its ``A:C``.
    spindle_ccw: bool = False
    spindle: float = 0.0
    coolant: bool = False  # GRBL's M8 (flood) on, M9 off
    tool: int = 0


@dataclass
class _Words:
    """A line's words sorted by role: G and M codes by modal group, values by letter."""

    g: dict[str, int]
    m: dict[str, int]
    values: dict[str, float]
    bare: float | None


class Interpreter:
    """Modal state and the position the queued blocks end at; :meth:`execute` runs one line."""

    def __init__(self, config: GcodeConfig, position: tuple[float, ...]) -> None:
        self.config = config
        self.position = position
        #: GRBL's G92 work offset (machine minus work position), per axis; always 0 elsewhere.
        self.offset: tuple[float, ...] = (0.0,) * len(position)
        #: GRBL's G54…G59 (gcode_work_systems.py): the stored offsets and the active one.
        self.systems = WorkSystems.zero(len(position))
        self.modal = Modal()
        self.pen_down = False
        self.spindle_level = 0.0
        self.step_rate = config.max_rate
        self.servo_level: float | None = None

    def reset(self, position: tuple[float, ...]) -> None:
        """After a soft reset: GRBL's power-on modes (no G92 offset), the pen up, the tool kept."""
        self.position = position
        self.offset = (0.0,) * len(position)
        self.systems = replace(self.systems, active=0)  # G54; the stored ones are kept
        self.modal = Modal()
        self.pen_down = False
        self.spindle_level = 0.0

    def modes(self) -> str:
        """The ``[GC:...]`` line of ``$G``."""
        m = self.modal
        spindle = ("M4" if m.spindle_ccw else "M3") if m.spindle_on else "M5"
        spindle = spindle if self.config.pen is PenMapping.SPINDLE else ""
        words = [
            f"G{m.motion}",
            f"{self.systems.name} G17",
            "G20" if m.inches else "G21",
            "G90" if m.absolute else "G91",
            "G94",
            spindle or ("M4" if self.pen_down else "M3"),
            "M8" if m.coolant else "M9",
            f"T{m.tool}",
            f"F{(m.feed or 0.0) / (_MM_PER_INCH if m.inches else 1.0):g}",
            f"S{m.spindle:g}",
        ]
        return "[GC:" + " ".join(words) + "]"

    def work_offset(self) -> tuple[float, ...]:
        """GRBL's work coordinate offset (``WCO:``): the active system's plus G92's."""
        return self.systems.total(self.offset)

    def execute(self, words: list[Word]) -> list[Block] | int:
        """The blocks one line queues, in order, or GRBL's error code (and nothing changed)."""
        sorted_words = self._sort(words)
        if isinstance(sorted_words, int):
            return sorted_words
        return self._plan(sorted_words)

    # -- sorting the words -------------------------------------------------------------------

    def _sort(self, words: list[Word]) -> _Words | int:
        line = _Words({}, {}, {}, None)
        seen_n = False
        for word in words:
            letter, value = word.letter, word.value
            if letter in ("G", "M"):
                if (
                    letter == "M"
                    and self.config.grbl
                    and not (value.is_integer() and 0 <= value < 256)
                ):
                    return VALUE_NOT_INTEGER  # GRBL reads an M number into a byte (gcode.c)
                if letter == "G" and value == 92.1 and self.config.grbl:
                    code = G92_1
                elif not value.is_integer():
                    return UNSUPPORTED
                else:
                    code = int(value)
                groups = _G_GROUPS if letter == "G" else _M_GROUPS
                group = groups.get(code)
                if group is None or not self._supported(letter, code):
                    return UNSUPPORTED
                table = line.g if letter == "G" else line.m
                if group in table:
                    return MODAL_GROUP_VIOLATION
                table[group] = code
            elif letter == "N":
                if seen_n:
                    return WORD_REPEATED
                if not value.is_integer() or not 0 <= value <= _MAX_LINE_NUMBER:
                    return INVALID_LINE_NUMBER
                seen_n = True
            elif letter == "":
                if line.bare is not None:
                    return EXPECTED_COMMAND_LETTER
                line.bare = value
            elif (
                letter in _VALUE_LETTERS
                or letter in self.config.axes
                or (letter == "L" and self.config.grbl)
            ):
                if letter in line.values:
                    return WORD_REPEATED
                line.values[letter] = value
            elif letter == "T" and self.config.grbl:
                # GRBL 1.1's order (gcode.c): the bound, the repeat, the sign.  (GRBL truncates
                # a fraction, T1.5 is tool 1; the emulator refuses it as unsupported.)
                if value > _MAX_TOOL:
                    return MAX_VALUE_EXCEEDED
                if letter in line.values:
                    return WORD_REPEATED
                if value < 0:
                    return NEGATIVE_VALUE
                if not value.is_integer():
                    return UNSUPPORTED
                line.values[letter] = value  # GRBL takes a tool number and does nothing with it
            else:
                return UNSUPPORTED  # T, H, L, another machine's axis...
        return line

    def _supported(self, letter: str, code: int) -> bool:
        if letter == "G" and code in (2, 3):
            return self.config.arcs
        if letter == "M" and code in (98, 99):
            return self.config.plotter_codes
        if letter == "M" and code == 18:
            return self.config.drivers_off
        if letter == "M" and code in (8, 9):
            return self.config.grbl  # coolant: GRBL switches a pin, a plotter has none
        if letter == "G" and code in (10, 55, 56, 57, 58, 59):
            return self.config.grbl  # work coordinate systems: GRBL's, not the plotters'

        return True

    # -- planning the line -------------------------------------------------------------------

    def _plan(self, line: _Words) -> list[Block] | int:
        cfg = self.config
        values = line.values
        modal = self.modal
        nonmodal = line.g.get("non-modal")
        inches = line.g["units"] == 20 if "units" in line.g else modal.inches
        absolute = line.g["distance"] == 90 if "distance" in line.g else modal.absolute
        scale = _MM_PER_INCH if inches else 1.0
        used: set[str] = set(cfg.axes) | {"F", "T"}
        blocks: list[Block] = []

        feed = modal.feed
        if "F" in values:
            if values["F"] < 0:
                return NEGATIVE_VALUE
            feed = values["F"] * scale
        dwell_in_s = nonmodal == 4 and "S" in values and "P" not in values
        spindle = modal.spindle
        if "S" in values and not dwell_in_s:
            if values["S"] < 0:
                return NEGATIVE_VALUE
            spindle = values["S"]
            used.add("S")

        plotted = self._plotter_words(line, used)
        if isinstance(plotted, int):
            return plotted
        step_rate, servo, servo_moved = plotted

        spindle_on = modal.spindle_on
        ccw = modal.spindle_ccw
        pen = self.pen_down
        code = line.m.get("spindle")
        if cfg.pen is PenMapping.M3_UP_M4_DOWN:
            if code is not None:
                pen = code == 4
            level = 0.0
        else:
            if code is not None:
                spindle_on = code != 5
                ccw = code == 4
            pen = spindle_on and spindle > 0
            level = spindle if spindle_on else 0.0
        if servo_moved and code is None:
            # "Zdvihni popisovač do polohy odpovídající úrovni PWM z parametru": M99 lifts
            # the pen to that servo level, so the servo moves even if the pen was up.
            pen = False
            blocks.append(PenChange(False, cfg.pen_time, level, ccw=ccw))
        elif pen != self.pen_down or level != self.spindle_level or ccw != modal.spindle_ccw:
            seconds = cfg.pen_time if pen != self.pen_down else 0.0
            blocks.append(PenChange(pen, seconds, level, ccw=ccw))

        if nonmodal == 4:
            dwell = self._dwell(values, dwell_in_s, used)
            if isinstance(dwell, int):
                return dwell
            blocks.append(dwell)

        moved = self._axes(line, absolute, scale, feed, used, blocks)
        if isinstance(moved, int):
            return moved
        motion, position, offset, systems = moved

        if set(values) - used:
            return UNUSED_WORDS

        flow = line.m.get("flow")
        if flow in (2, 30):
            motion, absolute, spindle_on = 1, True, False
            if pen or level:
                blocks.append(PenChange(False, cfg.pen_time if pen else 0.0, 0.0))
            pen, level = False, 0.0
            if cfg.grbl:  # G54 again, the overrides back to 100 %, once the motion is done
                systems = systems.selected(54)
                blocks.append(SetOffset(systems.total(offset), program_end=True))
        elif flow == 0:
            blocks.append(Pause())

        coolant = line.m.get("coolant")
        self.modal = replace(
            modal,
            coolant=modal.coolant if coolant is None else coolant == 8 and flow not in (2, 30),
            tool=int(values["T"]) if "T" in values else modal.tool,
            motion=motion,
            absolute=absolute,
            inches=inches,
            feed=feed,
            spindle_on=spindle_on,
            spindle_ccw=ccw and spindle_on,
            spindle=spindle,
        )
        self.position = position
        self.offset = offset
        self.systems = systems
        self.pen_down = pen
        self.spindle_level = level
        self.step_rate = step_rate
        self.servo_level = servo
        return blocks

    def _plotter_words(
        self, line: _Words, used: set[str]
    ) -> tuple[float, float | None, bool] | int:
        """The plotter's M98 (step interval) and M99 (servo level): the step rate, the
        servo level and whether the servo moves, or the error code."""
        values = line.values
        step_rate, servo = self.step_rate, self.servo_level
        servo_moved = False
        plotter = line.m.get("plotter")
        if plotter is not None:
            argument = line.bare if line.bare is not None else values.get("P")
            if argument is None:
                return VALUE_WORD_MISSING
            used.add("P")
            if plotter == 98:
                if argument <= 0:
                    return NEGATIVE_VALUE
                step_rate = 1e6 / argument
            else:
                if argument < 0:
                    return NEGATIVE_VALUE
                servo = argument
                servo_moved = True
        elif line.bare is not None:
            return EXPECTED_COMMAND_LETTER
        return step_rate, servo, servo_moved

    def _dwell(self, values: dict[str, float], in_s: bool, used: set[str]) -> Dwell | int:
        """G4: P in the firmware's unit (GRBL: seconds), or S in seconds where the firmware
        takes it; the dwell, or the error code."""
        if "P" in values:
            seconds = values["P"] * self.config.dwell_p_seconds
            used.add("P")
        elif in_s:
            seconds = values["S"]
            used.add("S")
        else:
            return VALUE_WORD_MISSING
        if seconds < 0:
            return NEGATIVE_VALUE
        return Dwell(seconds)

    def _axes(
        self,
        line: _Words,
        absolute: bool,
        scale: float,
        feed: float | None,
        used: set[str],
        blocks: list[Block],
    ) -> tuple[int, tuple[float, ...], tuple[float, ...], WorkSystems] | int:
        """What the line's axis words do: G92, G10, G54…G59, G28, a move or an arc (queued on
        ``blocks``), drivers off; the motion mode, position, G92 offset and work systems after
        it, or the error code."""
        cfg = self.config
        values = line.values
        modal = self.modal
        nonmodal = line.g.get("non-modal")
        motion_given = line.g.get("motion")
        motion = modal.motion if motion_given is None else motion_given
        if nonmodal in (10, 28, 92) and motion_given is not None:
            return AXIS_COMMAND_CONFLICT
        # GRBL selects the line's coordinate system before G10, G92 and the motion (gcode.c).
        systems = self.systems
        if "coordinates" in line.g and cfg.grbl:
            systems = systems.selected(line.g["coordinates"])
        wco_changed = systems != self.systems
        axis_words = {a: v for a, v in values.items() if a in cfg.axes}
        position = self.position
        if "drivers" in line.m:
            if motion_given is not None or nonmodal in (28, 92):
                return AXIS_COMMAND_CONFLICT
            named = [cfg.index(a) for a in cfg.axes if a in axis_words]
            blocks.append(DriversOff(tuple(named) or tuple(range(len(cfg.axes)))))
            axis_words = {}
        offset = self.offset
        if nonmodal == 92 and cfg.grbl:
            if not axis_words:
                return NO_AXIS_WORDS
            # GRBL: G92 = MPos - WCS - WPos for the named axes (absolute, in the line's units).
            offset = tuple(
                position[i] - systems.offset[i] - axis_words[a] * (1.0 if a == "A" else scale)
                if a in axis_words
                else offset[i]
                for i, a in enumerate(cfg.axes)
            )
            wco_changed = True
        elif nonmodal == 10:
            millimetres = {
                cfg.index(a): v * (1.0 if a == "A" else scale) for a, v in axis_words.items()
            }
            changed = systems.set_by_g10(values, millimetres, position, offset)
            if isinstance(changed, int):
                return changed
            used |= {"L", "P"}
            wco_changed = True  # GRBL writes its EEPROM once the motion is done
            systems = changed
        elif nonmodal == 92:
            if not axis_words and not cfg.bare_g92:
                return NO_AXIS_WORDS
            if axis_words:
                position = self._target(position, axis_words, True, scale)
            else:  # the CoreXY plotter: "set the current position as origin"
                position = (0.0,) * len(cfg.axes)
            blocks.append(SetPosition(position))
        elif nonmodal == 28:
            wco = systems.total(offset)
            stops = [self._target(position, axis_words, absolute, scale, wco)] if axis_words else []
            stops.append((0.0,) * len(cfg.axes))
            if not all(cfg.within_travel(p) for p in stops):
                return TRAVEL_EXCEEDED
            blocks += self._moves(position, stops, "G28", None)
            position = stops[-1]
        elif axis_words:
            end = self._target(position, axis_words, absolute, scale, systems.total(offset))
            rate: float | None = None
            if motion != 0:
                rate = feed if feed is not None else cfg.default_feed
                if not rate:
                    return UNDEFINED_FEED_RATE
            points: list[tuple[float, ...]] | int = [end]
            if motion in (2, 3):
                if "X" not in axis_words and "Y" not in axis_words:
                    return NO_AXIS_WORDS_IN_PLANE
                points = self._arc(position, end, motion == 2, values, scale)
                used |= {"I", "J", "R"}
            if isinstance(points, int):
                return points
            if not all(cfg.within_travel(p) for p in points):
                return TRAVEL_EXCEEDED
            blocks += self._moves(position, points, f"G{motion}", rate)
            position = end
        elif motion_given in (2, 3):
            return NO_AXIS_WORDS
        if nonmodal == G92_1:
            offset = (0.0,) * len(cfg.axes)
            wco_changed = True
        if wco_changed and cfg.grbl:
            # GRBL synchronises on a work-offset change (FORCE_BUFFER_SYNC_DURING_WCO_CHANGE).
            blocks.append(SetOffset(systems.total(offset)))
        return motion, position, offset, systems

    def _target(
        self,
        base: tuple[float, ...],
        axis_words: dict[str, float],
        absolute: bool,
        scale: float,
        offset: tuple[float, ...] | None = None,
    ) -> tuple[float, ...]:
        """``offset``: the work offset the line's absolute values are in (default: G92's)."""
        wco = self.offset if offset is None else offset
        target = list(base)
        for axis, value in axis_words.items():
            index = self.config.index(axis)
            distance = value * (1.0 if axis == "A" else scale)
            # An absolute value is a work coordinate: the G92 offset makes it a machine one.
            target[index] = distance + wco[index] if absolute else target[index] + distance
        return tuple(target)

    def _moves(
        self,
        start: tuple[float, ...],
        points: list[tuple[float, ...]],
        kind: str,
        feed: float | None,
    ) -> list[Block]:
        """Straight blocks through ``points``; ``feed`` None is the rapid (top) rate."""
        blocks: list[Block] = []
        for end in points:
            if end != start:
                blocks.append(self.move(start, end, kind, feed))
            start = end
        return blocks

    def move(
        self, start: tuple[float, ...], end: tuple[float, ...], kind: str, feed: float | None
    ) -> Move:
        """One straight move, timed on its lead motor at ``feed`` (units/min) or the top rate."""
        cfg = self.config
        steps = max(
            abs(b - a) for a, b in zip(cfg.motor_counts(start), cfg.motor_counts(end), strict=True)
        )
        length = math.dist(start, end)
        rate = self.step_rate
        if cfg.feed_ignored:
            feed = None  # the CoreXY plotter: G0 = G1, one step interval (M98) for both
        if feed is not None and steps > 0 and length > 0:
            rate = min(rate, feed / 60.0 * steps / length)
        if cfg.junction_deviation is None or length <= 0:
            return Move(start, end, steps, rate, cfg.acceleration, length, kind)
        # GRBL: along the path, as fast as the feed and every axis' own limits allow.
        _, unit = unit_vector([b - a for a, b in zip(start, end, strict=True)])
        rapid = axis_limited(cfg.rates(), unit)
        programmed = rapid if feed is None else feed / 60.0
        speed = min(programmed, rapid)
        accel = axis_limited(cfg.accelerations(), unit)
        return Move(
            start, end, steps, rate, cfg.acceleration, length, kind, speed, accel, unit,
            programmed, rapid,
        )  # fmt: skip

    def _arc(
        self,
        start: tuple[float, ...],
        end: tuple[float, ...],
        clockwise: bool,
        values: dict[str, float],
        scale: float,
    ) -> list[tuple[float, ...]] | int:
        """The points an arc is flattened into (GRBL's chord tolerance), ending exactly at ``end``.

        The other axes (a helix's Z) move linearly along the arc.
        """
        ix, iy = self.config.index("X"), self.config.index("Y")
        x0, y0, x1, y1 = start[ix], start[iy], end[ix], end[iy]
        dx, dy = x1 - x0, y1 - y0
        if "R" in values:
            radius = values["R"] * scale
            if dx == 0 and dy == 0:
                return INVALID_TARGET
            h2 = 4.0 * radius * radius - dx * dx - dy * dy
            if h2 < 0:
                if h2 < -1e-9 * radius * radius:
                    return ARC_RADIUS_ERROR
                h2 = 0.0  # a half circle, short of it by rounding only
            h = -math.sqrt(h2) / math.hypot(dx, dy)
            if not clockwise:
                h = -h
            if radius < 0:
                h, radius = -h, -radius
            i, j = 0.5 * (dx - dy * h), 0.5 * (dy + dx * h)
        else:
            if "I" not in values and "J" not in values:
                return NO_OFFSETS_IN_PLANE
            i, j = values.get("I", 0.0) * scale, values.get("J", 0.0) * scale
            radius = math.hypot(i, j)
            mismatch = abs(math.hypot(dx - i, dy - j) - radius)
            if mismatch > 0.005 and (mismatch > 0.5 or mismatch > 0.001 * radius):
                return INVALID_TARGET
        if radius == 0:
            return INVALID_TARGET
        cx, cy = x0 + i, y0 + j
        angle = math.atan2(-i * (y1 - cy) + j * (x1 - cx), -i * (x1 - cx) - j * (y1 - cy))
        if clockwise and angle >= -_ARC_EPS:
            angle -= 2.0 * math.pi
        elif not clockwise and angle <= _ARC_EPS:
            angle += 2.0 * math.pi
        tolerance = self.config.arc_tolerance
        segments = 1
        if 2.0 * radius > tolerance:
            chord = math.sqrt(tolerance * (2.0 * radius - tolerance))
            exact = abs(0.5 * angle * radius) / chord
            if exact > _MAX_ARC_SEGMENTS:
                return INVALID_TARGET
            segments = max(math.floor(exact), 1)
        first = math.atan2(-j, -i)
        points: list[tuple[float, ...]] = []
        for k in range(1, segments):
            fraction = k / segments
            point = [a + (b - a) * fraction for a, b in zip(start, end, strict=True)]
            theta = first + angle * fraction
            point[ix] = cx + radius * math.cos(theta)
            point[iy] = cy + radius * math.sin(theta)
            points.append(tuple(point))
        points.append(end)
        return points
