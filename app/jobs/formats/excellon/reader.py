"""Excellon drill files (EAGLE, KiCad, Altium, EasyEDA…) read into holes, and drill jobs built.

The reading is gerbonara's (pinned to 1.5.0, the newest that installs on
Python 3.11): a maintained parser knows far more dialects than a guesser we
would write.  This module only does what gerbonara 1.5.0 does not:

* **line numbers**: gerbonara's objects carry none, so the parser's
  ``objects`` and ``tools`` containers are replaced by ones that note the
  line being parsed whenever something is added — every hole can point the
  operator at its file line;
* **number format**: gerbonara guesses ``2:4`` from a bare ``INCH``/``M72``
  and says so only in a warning.  We decide it ourselves before parsing and
  pass it in: from the file's own format line when there is one, else from
  the EAGLE ``.dri`` info file, else from the "Excellon step" setting (the
  original tool's 1/10000 inch);
* **G85 slots**: 1.5.0 rejects ``X…Y…G85X…Y…`` as an unknown statement, so
  such lines reach gerbonara as their end point only (keeping its modal
  position right) and the start point is read here with gerbonara's own
  number settings;
* **refusals**: holes gerbonara drops with a mere warning (coordinates before
  any tool, or outside the header/body) are refused here with file, line and
  reason, because a silently missing hole is a ruined board.  So are lines
  gerbonara 1.5.0 mishandles, found before it sees them: a ``G85`` with no
  end point (it would drop the slot), routed arcs ``G02``/``G03`` (it fails
  with an internal error), a tool with a zero or negative diameter, a tool
  number above :data:`MAX_TOOL_NUMBER`, coordinates too large for a number,
  and more than :data:`MAX_HOLES` holes, a repeat's (``R…``) counted before
  gerbonara makes them one by one;
* **warnings**: everything else gerbonara warns about (a tool defined twice,
  commands after the end…) is kept with its line in ``DrillJob.notes`` and
  shown to the operator with the program's notes.
"""

from __future__ import annotations

import math
import re
import warnings
from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any, Literal

from gerbonara.apertures import ExcellonTool
from gerbonara.cam import FileSettings
from gerbonara.excellon import ExcellonParser
from gerbonara.graphic_objects import Arc, Flash, Line
from gerbonara.utils import MM, Inch
from PySide6.QtCore import QCoreApplication

from app.jobs.formats.excellon.bits import plan_bits
from app.jobs.names import quoted, shown
from app.jobs.program import JobFileError, Operation, OpKind, Program, SourceRef
from app.jobs.reading import read_job_text
from app.jobs.texts import localized_format

DEFAULT_EXCELLON_STEP_INCH = 1e-4
#: The highest tool number a drill file may use (Excellon writes two or three digits).
MAX_TOOL_NUMBER = 999
#: The most holes (slot ends counted) a drill file may ask for, repeats (``R…``) included:
#: boards have tens to a few thousand holes; 50 000 (the benchmark's board) still checks in
#: seconds, where a repeat count of nine digits made gerbonara build holes until memory ran out.
MAX_HOLES = 50_000
MM_PER_INCH = 25.4


@dataclass(frozen=True)
class Tool:
    name: str  # "T01": always two digits, whatever the file wrote, so messages look alike
    number: int
    diameter_mm: float
    source: SourceRef  # the definition line (in the drill file, or in the .dri)


@dataclass(frozen=True)
class Hole:
    x_mm: float
    y_mm: float
    tool: str
    diameter_mm: float
    source: SourceRef


@dataclass(frozen=True)
class Slot:
    """A ``G85`` (or routed ``M15``…``M16``) slot: shown, and drilled as its two end holes."""

    x0_mm: float
    y0_mm: float
    x1_mm: float
    y1_mm: float
    tool: str
    diameter_mm: float
    source: SourceRef


@dataclass(frozen=True)
class DrillJob:
    """Everything read from one drill file (and its ``.dri``), in file order, in millimetres."""

    name: str
    path: Path
    unit: Literal["inch", "mm"]  # the unit the file is written in
    number_format: tuple[int | None, int | None]  # integer, decimal digits of bare integers
    zeros: str  # "leading suppressed (TZ)", "trailing suppressed (LZ)"
    format_from: str  # where the number format came from: the file, the .dri, the step setting
    tools: tuple[Tool, ...]
    holes: tuple[Hole, ...]
    slots: tuple[Slot, ...] = ()
    notes: tuple[str, ...] = ()  # gerbonara's warnings and our own remarks, "line: text"
    info_file: Path | None = None

    def tool(self, name: str) -> Tool:
        return next(t for t in self.tools if t.name == name)

    def holes_for(self, tool: str) -> list[Hole]:
        return [h for h in self.holes if h.tool == tool]

    def hole_counts(self) -> dict[str, int]:
        """Holes per tool (slots not included), every defined tool listed."""
        counts = {t.name: 0 for t in self.tools}
        for hole in self.holes:
            counts[hole.tool] += 1
        return counts


# --- the EAGLE info file ----------------------------------------------------------


@dataclass(frozen=True)
class DriInfo:
    """What an EAGLE ``.dri`` says about its drill file."""

    unit: Literal["inch", "mm"]
    step: float  # one coordinate unit, in ``unit``
    absolute: bool
    tools: dict[int, tuple[float, int, int]]  # number → (diameter in unit, holes used, line)
    drill_file: str | None


_DRI_UNITS = re.compile(r"Units\s*:\s*1/(\d+)\s*(inch|mm)", re.IGNORECASE)
_DRI_TOOL = re.compile(r"T(\d+)\s+([0-9.]+)\s*(inch|mm)\s+(\d+)", re.IGNORECASE)


def read_dri(path: Path) -> DriInfo:
    """Units, tool list and drill-file name from an EAGLE drill station info file."""
    text = _read_text(path)
    unit: Literal["inch", "mm"] | None = None
    step = 0.0
    absolute = True
    tools: dict[int, tuple[float, int, int]] = {}
    drill_file: str | None = None
    in_plotfiles = False
    for number, raw in enumerate(text.splitlines(), start=1):
        line = raw.strip()
        if match := _DRI_UNITS.search(line):
            unit = "inch" if match[2].lower() == "inch" else "mm"
            step = 1 / int(match[1])
        elif line.lower().startswith("data mode"):
            absolute = "incremental" not in line.lower()
        elif match := _DRI_TOOL.match(line):
            diameter = float(match[2])
            if match[3].lower() != "inch" and unit == "inch":
                diameter /= MM_PER_INCH
            tools[int(match[1])] = (diameter, int(match[4]), number)
        elif line.lower().startswith("plotfiles"):
            in_plotfiles = True
        elif in_plotfiles and line:
            drill_file = re.split(r"[\\/]", line)[-1]
            in_plotfiles = False
    if unit is None:
        raise JobFileError(
            path.name,
            0,
            QCoreApplication.translate(
                "JobFile", "no 'Units : 1/10000 Inch' line: not an EAGLE .dri"
            ),
        )
    return DriInfo(unit, step, absolute, tools, drill_file)


def _drill_file_of(dri: Path, info: DriInfo) -> Path:
    """The drill file a ``.dri`` describes: the one it names, else its stem beside it."""
    candidates = [dri.parent / info.drill_file] if info.drill_file else []
    candidates += [dri.with_suffix(""), dri.with_suffix(".drd"), dri.with_suffix(".drl")]
    for candidate in candidates:
        if candidate.is_file() and candidate != dri:
            return candidate
    raise JobFileError(
        dri.name,
        0,
        QCoreApplication.translate("JobFile", "its drill file {0} is missing").format(
            repr(info.drill_file or dri.stem)
        ),
    )


# --- reading ------------------------------------------------------------------------


class _Tracked(list[Any]):
    """gerbonara's object list, noting the line being parsed as each object is added."""

    def __init__(self, parser: ExcellonParser) -> None:
        super().__init__()
        self.parser = parser
        self.lines: list[int] = []

    def append(self, item: Any) -> None:
        super().append(item)
        self.lines.append(int(self.parser.lineno or 0))


class _TrackedTools(dict[int, Any]):
    """gerbonara's tool table, noting each definition's line."""

    def __init__(self, parser: ExcellonParser) -> None:
        super().__init__()
        self.parser = parser
        self.lines: dict[int, int] = {}

    def __setitem__(self, key: int, value: Any) -> None:
        super().__setitem__(key, value)
        self.lines[key] = int(self.parser.lineno or 0)


class _Parser(ExcellonParser):  # type: ignore[misc]
    """gerbonara's parser with line tracking, and its warnings collected instead of emitted."""

    def __init__(self, settings: FileSettings, external_tools: dict[int, Any]) -> None:
        super().__init__(settings, external_tools=external_tools)
        self.objects = _Tracked(self)
        self.tools = _TrackedTools(self)
        self.remarks: list[tuple[int, str, str, Any]] = []  # line, text, message, state

    def warn(self, msg: str) -> None:
        self.remarks.append((int(self.lineno or 0), self.line, msg, self.program_state))


_FORMAT_IN_FILE = re.compile(
    r";\s*FILE_FORMAT=\d:\d|^(INCH|METRIC|M71|M72),(LZ|TZ)?,?0*\.0*$|;FORMAT=\{\d+:\d+",
    re.IGNORECASE,
)
_METRIC = re.compile(r"^(METRIC|M71)\b")
_INCH = re.compile(r"^(INCH|M72)\b")
_G85 = re.compile(r"^(?P<start>(?:X[-+]?[0-9.]*)?(?:Y[-+]?[0-9.]*)?)G85(?P<end>.*)$")
_COORD = re.compile(r"(?:X([-+]?)([0-9.]*))?(?:Y([-+]?)([0-9.]*))?")


_TOOL_LINE = re.compile(r"^T0*(\d+)(?![\d])(.*)$")
_TOOL_DIAMETER = re.compile(r"C([-+]?[0-9.]*)")
_ROUTED_ARC = re.compile(r"^G0?[23](?![0-9])")
_REPEAT = re.compile(r"^R([0-9]*)")
_HOLE_WORD = re.compile(r"[XY][-+]?[0-9.]")


def _read_text(path: Path) -> str:
    return read_job_text(path, latin1_fallback=True)


def _prescan(name: str, lines: Sequence[str]) -> None:
    """Refuse what gerbonara 1.5.0 would drop, mangle or fail on (see the module notes)."""
    holes = 0  # at most: each coordinate line one hole, a slot two, a repeat its count
    for number, raw in enumerate(lines, start=1):
        line = raw.strip().upper()
        if not line or line.startswith(";"):
            continue
        if (repeat := _REPEAT.match(line)) is not None:
            digits = repeat[1].lstrip("0") or "0"
            count = int(digits) if len(digits) <= 9 else MAX_HOLES + 1  # no int() of a flood
            if count > MAX_HOLES:
                raise JobFileError(
                    name,
                    number,
                    QCoreApplication.translate(
                        "JobFile",
                        "repeat {0} asks for {1} holes; a drill file may have at most {2}",
                    ).format(
                        quoted(line[:24]),
                        f"{count:,}"
                        if len(digits) <= 9
                        else QCoreApplication.translate("JobFile", "{0}… ({1} digits)").format(
                            digits[:6], len(digits)
                        ),
                        f"{MAX_HOLES:,}",
                    ),
                )
            holes += count
        elif _HOLE_WORD.search(line):
            holes += 2 if "G85" in line else 1
        if holes > MAX_HOLES:
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate(
                    "JobFile", "more than {0} holes by this line; a drill file may have at most {0}"
                ).format(f"{MAX_HOLES:,}"),
            )
        if (tool := _TOOL_LINE.match(line)) is not None:
            index = tool[1]
            if len(index) > 6 or int(index) > MAX_TOOL_NUMBER:
                shown = (
                    index
                    if len(index) <= 12
                    else QCoreApplication.translate("JobFile", "{0}… ({1} digits)").format(
                        index[:6], len(index)
                    )
                )
                raise JobFileError(
                    name,
                    number,
                    QCoreApplication.translate("JobFile", "tool number T{0} is above T{1}").format(
                        shown, MAX_TOOL_NUMBER
                    ),
                )
            diameter = _TOOL_DIAMETER.search(tool[2])
            if diameter is not None:
                try:
                    value = float(diameter[1])
                except ValueError:
                    raise JobFileError(
                        name,
                        number,
                        QCoreApplication.translate(
                            "JobFile", "tool diameter {0} is not a number"
                        ).format(repr(diameter[1])),
                    ) from None
                if not value > 0 or not math.isfinite(value):
                    raise JobFileError(
                        name,
                        number,
                        QCoreApplication.translate(
                            "JobFile",
                            "tool diameter of T{0:02d} is {1:g}: a drill must be wider than 0",
                        ).format(int(index), value),
                    )
        elif _ROUTED_ARC.match(line):
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate("JobFile", "routed arcs (G02/G03) cannot be drilled"),
            )
        elif (slot := _G85.match(line)) is not None and not slot["end"].strip():
            raise JobFileError(
                name,
                number,
                QCoreApplication.translate(
                    "JobFile", "G85 slot without an end point: nothing to cut to"
                ),
            )


def _step_format(step: float, unit: str) -> tuple[int, int]:
    """The (integer, decimal) digits that make a bare integer count ``step`` units."""
    decimals = -math.log10(step)
    if step <= 0 or abs(decimals - round(decimals)) > 1e-9 or not 0 <= round(decimals) <= 7:
        raise ValueError(f"the Excellon step must be a power of ten (1e-4, 1e-3…), not {step!r}")
    return (2 if unit == "inch" else 3), round(decimals)


def _number_format(
    path: Path,
    lines: Sequence[str],
    dri: Path | None,
    info: DriInfo | None,
    excellon_step_inch: float,
    notes: list[str],
) -> tuple[FileSettings, str]:
    """The number format, chosen before gerbonara would (see the module docstring), and
    where it comes from."""
    explicit = any(_FORMAT_IN_FILE.search(line.strip()) for line in lines[:200])
    metric = any(_METRIC.match(line.strip()) for line in lines[:200])
    inch = any(_INCH.match(line.strip()) for line in lines[:200])
    if explicit:
        settings = FileSettings(unit=MM if metric else Inch, zeros="leading")
        format_from = path.name
    elif info is not None:
        settings = FileSettings(
            unit=Inch if info.unit == "inch" else MM,
            number_format=_step_format(info.step, info.unit),
            zeros="leading",
            notation="absolute" if info.absolute else "incremental",
        )
        format_from = f"{dri.name if dri else ''} (1/{round(1 / info.step)} {info.unit})"
    elif metric:
        # A metric file with bare integers and no format is ambiguous; gerbonara refuses its
        # first such coordinate and we pass the refusal on with its line.
        settings = FileSettings(unit=MM, zeros="leading")
        format_from = path.name
    else:
        settings = FileSettings(
            unit=Inch, number_format=_step_format(excellon_step_inch, "inch"), zeros="leading"
        )
        format_from = f"Excellon step setting ({excellon_step_inch:g} inch)"
        if not inch:
            notes.append(
                "0: "
                + QCoreApplication.translate(
                    "JobFile", "no unit in the file; inch assumed, as the Excellon step is"
                )
            )
    return settings, format_from


def _parse(
    path: Path, lines: Sequence[str], settings: FileSettings, info: DriInfo | None
) -> tuple[_Parser, dict[int, str], list[warnings.WarningMessage]]:
    """gerbonara's parse of the file, its refusal as a JobFileError with the line; the
    starts of G85 slots by line, and the warnings it gave."""
    # G85 slots: gerbonara 1.5.0 only gets the end point; the start is ours to read.
    slot_starts: dict[int, str] = {}
    fed: list[str] = []
    for number, raw in enumerate(lines, start=1):
        match = _G85.match(raw.strip())
        if match:
            slot_starts[number] = match["start"]
            fed.append(match["end"])
        else:
            fed.append(raw)

    external: dict[int, Any] = {}
    if info is not None:
        unit = Inch if info.unit == "inch" else MM
        external = {n: ExcellonTool(diameter=d, unit=unit) for n, (d, _, _) in info.tools.items()}
    parser = _Parser(settings, external)
    try:
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            parser.do_parse("\n".join(fed), filename=path.name)
    except SyntaxError as exc:
        cause = exc.__cause__ or exc
        reason = str(cause.args[0] if cause.args else cause)
        if isinstance(cause, ValueError) and "Unknown excellon statement" in reason:
            reason = QCoreApplication.translate("JobFile", "not an Excellon statement: {0}").format(
                quoted(lines[parser.lineno - 1].strip())
            )
        elif "Undefined tool" in reason:
            reason = QCoreApplication.translate(
                "JobFile", "unknown tool: {0} is not defined"
            ).format(quoted(lines[parser.lineno - 1].strip()))
        elif "No number format" in reason:
            reason = QCoreApplication.translate(
                "JobFile", "integer coordinates, but the file gives no number format (metric)"
            )
        elif isinstance(cause, ValueError) and "could not convert" in reason:
            reason = QCoreApplication.translate(
                "JobFile", "a coordinate is not a number: {0}"
            ).format(quoted(lines[parser.lineno - 1].strip()))
        raise JobFileError(path.name, int(parser.lineno or 0), reason) from exc
    except Exception as exc:  # gerbonara's own failure: the line it was on, and what it said
        line = int(parser.lineno or 0)
        text_ = lines[line - 1].strip()[:60] if 0 < line <= len(lines) else ""
        raise JobFileError(
            path.name,
            line,
            QCoreApplication.translate(
                "JobFile", "the Excellon reader cannot read {0} ({1})"
            ).format(repr(text_), exc),
        ) from exc
    return parser, slot_starts, caught


def _check_remarks(path: Path, parser: _Parser, notes: list[str]) -> None:
    """What gerbonara remarked: coordinates where none may be are refused, the rest noted."""
    for line, text_, message, state in parser.remarks:
        if "before first tool" in message:
            reason = QCoreApplication.translate(
                "JobFile", "coordinates before any tool is selected: {0}"
            ).format(quoted(text_))
            raise JobFileError(path.name, line, reason)
        if message.startswith("Bare coordinate after end"):
            reason = (
                QCoreApplication.translate("JobFile", "coordinates before the header: {0}")
                if state is None
                else QCoreApplication.translate(
                    "JobFile", "coordinates after the end of the program: {0}"
                )
            )
            raise JobFileError(path.name, line, reason.format(quoted(text_)))
        if "implicit number format" not in message:  # we chose the format ourselves
            if "{index}" in message:  # gerbonara 1.5.0 forgets to fill it in
                tool = _TOOL_LINE.match(text_.strip().upper())
                message = message.replace("{index}", f"T{int(tool[1]):02d}" if tool else "")
            notes.append(f"{line}: {message}")


def read_drill_file(
    path: Path,
    *,
    dri: Path | None = None,
    excellon_step_inch: float = DEFAULT_EXCELLON_STEP_INCH,
) -> DrillJob:
    """Read a drill file (or an EAGLE ``.dri`` and the drill file it names) into a DrillJob.

    ``excellon_step_inch`` is the original tool's setting: what one count of a
    bare integer coordinate is worth when neither the file nor a ``.dri``
    states a number format.  Raises JobFileError (file, line, reason) for a
    file the station must not drill.
    """
    if path.suffix.lower() == ".dri":
        dri = path
        path = _drill_file_of(path, read_dri(path))
    elif dri is None and path.with_suffix(".dri").is_file() and path.suffix.lower() != ".dri":
        dri = path.with_suffix(".dri")
    info = read_dri(dri) if dri is not None else None

    text = _read_text(path)
    lines = text.splitlines()
    notes: list[str] = []
    _prescan(path.name, lines)

    settings, format_from = _number_format(path, lines, dri, info, excellon_step_inch, notes)

    parser, slot_starts, caught = _parse(path, lines, settings, info)
    notes += [f"0: {warning.message}" for warning in caught]

    _check_remarks(path, parser, notes)

    return _assemble(path, dri, info, parser, lines, slot_starts, format_from, notes)


def _tool_table(
    path: Path, dri: Path | None, info: DriInfo | None, parser: _Parser
) -> tuple[dict[int, str], list[Tool]]:
    """The tools the file (or its ``.dri``) defines, and each gerbonara aperture's name."""
    file_unit = parser.settings.unit or Inch
    names: dict[int, str] = {}
    tools: list[Tool] = []
    defined: dict[int, Any] = dict(parser.tools) or dict(parser.external_tools)
    for number, tool in defined.items():
        unit = tool.unit or file_unit
        diameter = float(unit.convert_to(MM, tool.diameter or 0.0))
        if number in parser.tools:
            source = SourceRef(path.name, parser.tools.lines[number])
        else:
            assert info is not None and dri is not None
            source = SourceRef(dri.name, info.tools[number][2])
        name = f"T{number:02d}"
        names[id(tool)] = name
        tools.append(Tool(name, number, diameter, source))
    return names, tools


def _assemble(
    path: Path,
    dri: Path | None,
    info: DriInfo | None,
    parser: _Parser,
    lines: Sequence[str],
    slot_starts: dict[int, str],
    format_from: str,
    notes: list[str],
) -> DrillJob:
    settings = parser.settings
    file_unit = settings.unit or Inch
    names, tools = _tool_table(path, dri, info, parser)
    by_name = {t.name: t for t in tools}
    holes: list[Hole] = []
    slots: list[Slot] = []
    previous = (0.0, 0.0)  # in file units: where a modal (X or Y only) slot start continues from
    for obj, line in zip(parser.objects, parser.objects.lines, strict=True):
        tool = by_name[names[id(obj.aperture)]]
        where = SourceRef(path.name, line)
        unit = obj.unit or file_unit

        def mm(value: float, unit: Any = unit, line: int = line) -> float:
            converted = float(unit.convert_to(MM, value))
            if not math.isfinite(converted):
                raise JobFileError(
                    path.name,
                    line,
                    QCoreApplication.translate("JobFile", "a coordinate too large for a number"),
                )
            return converted

        if isinstance(obj, Flash) and line in slot_starts:
            if not settings.is_absolute:
                raise JobFileError(path.name, line, "G85 slots in incremental mode: not supported")
            x0, y0 = _parse_point(slot_starts[line], settings, previous)
            slots.append(
                Slot(mm(x0), mm(y0), mm(obj.x), mm(obj.y), tool.name, tool.diameter_mm, where)
            )
            previous = (obj.x, obj.y)
        elif isinstance(obj, Flash):
            holes.append(Hole(mm(obj.x), mm(obj.y), tool.name, tool.diameter_mm, where))
            previous = (obj.x, obj.y)
        elif isinstance(obj, Line):
            slots.append(
                Slot(
                    mm(obj.x1),
                    mm(obj.y1),
                    mm(obj.x2),
                    mm(obj.y2),
                    tool.name,
                    tool.diameter_mm,
                    where,
                )
            )
            previous = (obj.x2, obj.y2)
        elif isinstance(obj, Arc):
            raise JobFileError(
                path.name,
                line,
                QCoreApplication.translate("JobFile", "routed arcs (G02/G03) cannot be drilled"),
            )

    if not holes and not slots:
        raise JobFileError(
            path.name,
            0,
            QCoreApplication.translate("JobFile", "no holes in the file: nothing to drill"),
        )
    if info is not None and dri is not None:
        _check_against_dri(path, dri, info, tools, holes)
    zeros = "leading suppressed (TZ)"
    if settings.zeros == "trailing":
        zeros = "trailing suppressed (LZ)"
    return DrillJob(
        name=path.stem if path.suffix else path.name,
        path=path,
        unit="mm" if file_unit == MM else "inch",
        number_format=tuple(settings.number_format),
        zeros=zeros,
        format_from=format_from,
        tools=tuple(tools),
        holes=tuple(holes),
        slots=tuple(slots),
        notes=tuple(notes),
        info_file=dri,
    )


def _parse_point(
    text: str, settings: FileSettings, previous: tuple[float, float]
) -> tuple[float, float]:
    """``X…Y…`` in file units by gerbonara's number rules; a missing axis keeps its last value."""
    match = _COORD.fullmatch(text)
    assert match is not None  # _G85 only accepts X/Y words before G85
    x_sign, x, y_sign, y = match.groups()
    x_value = settings.parse_gerber_value(x)
    y_value = settings.parse_gerber_value(y)
    return (
        previous[0] if x_value is None else (-x_value if x_sign == "-" else x_value),
        previous[1] if y_value is None else (-y_value if y_sign == "-" else y_value),
    )


def _check_against_dri(
    path: Path, dri: Path, info: DriInfo, tools: Iterable[Tool], holes: Sequence[Hole]
) -> None:
    """The .dri and its drill file must agree: a mismatch means one of them is from another run."""
    factor = MM_PER_INCH if info.unit == "inch" else 1.0
    counts: dict[str, int] = {}
    for hole in holes:
        counts[hole.tool] = counts.get(hole.tool, 0) + 1
    for tool in tools:
        if tool.number not in info.tools:
            raise JobFileError(
                dri.name,
                0,
                QCoreApplication.translate("JobFile", "{0} of {1} is not in the tool list").format(
                    tool.name, path.name
                ),
            )
        diameter, used, line = info.tools[tool.number]
        if abs(diameter * factor - tool.diameter_mm) > 0.0005:
            raise JobFileError(
                dri.name,
                line,
                QCoreApplication.translate(
                    "JobFile", "{0} is {1:.3f} mm here but {2:.3f} mm in {3}"
                ).format(tool.name, diameter * factor, tool.diameter_mm, path.name),
            )
        if used != counts.get(tool.name, 0):
            raise JobFileError(
                dri.name,
                line,
                QCoreApplication.translate(
                    "JobFile",
                    "{0} drills {1} holes here but {2} in {3}: the files do not belong together",
                ).format(tool.name, used, counts.get(tool.name, 0), path.name),
            )


# --- sniffing ---------------------------------------------------------------------------

_SNIFF_TOOL = re.compile(r"^T\d+C[0-9.]", re.MULTILINE)


def sniff_excellon(head: str) -> bool:
    """A tool definition (``T01C0.0315``), or ``M48`` and a tool, in the first lines.

    ``M48`` alone is not enough: a header without a tool is no drill job, and
    other files' sniffers deserve the chance.
    """
    top = "\n".join(line.strip() for line in head.splitlines()[:40])
    if _SNIFF_TOOL.search(top):
        return True
    return bool(re.search(r"^M48\b", top, re.MULTILINE) and re.search(r"^T\d+", top, re.MULTILINE))


def sniff_dri(head: str) -> bool:
    return "Drill Station Info File" in head or bool(_DRI_UNITS.search(head))


# --- programs -------------------------------------------------------------------------------


@dataclass(frozen=True)
class ToolPlan:
    """One bit's holes in drilling order, with the travel that order saves.

    ``tool`` is the tool the operator is asked for; ``also`` names the
    duplicate tools (same diameter) whose holes are drilled with its bit.
    """

    tool: Tool
    holes: tuple[Hole, ...]
    file_travel_mm: float
    travel_mm: float
    also: tuple[str, ...] = ()


@dataclass(frozen=True)
class DrillPlan:
    job: DrillJob
    tools: tuple[ToolPlan, ...] = field(default_factory=tuple)
    #: Duplicate tools and tools without a diameter, "file:line: text" (see bits.py).
    flags: tuple[str, ...] = ()

    @property
    def file_travel_mm(self) -> float:
        return sum(t.file_travel_mm for t in self.tools)

    @property
    def travel_mm(self) -> float:
        return sum(t.travel_mm for t in self.tools)


def _holes_of(job: DrillJob, tool: str) -> list[Hole]:
    """The tool's holes, each slot as its two end holes (a drill cannot rout)."""
    holes = job.holes_for(tool)
    for slot in job.slots:
        if slot.tool == tool:
            holes.append(Hole(slot.x0_mm, slot.y0_mm, slot.tool, slot.diameter_mm, slot.source))
            holes.append(Hole(slot.x1_mm, slot.y1_mm, slot.tool, slot.diameter_mm, slot.source))
    return holes


def plan_drilling(
    job: DrillJob,
    *,
    start: tuple[float, float] = (0.0, 0.0),
    smallest_first: bool = False,
    one_bit: bool = False,
) -> DrillPlan:
    """Holes grouped by bit (file order of tools, or smallest first), each group's order optimised.

    Slots are drilled as their two end holes: each end becomes a hole on
    the slot's line, so the operator sees where it came from and the
    preview still shows the slot.  Tools of one diameter share a bit and a
    prompt; a tool without a diameter is flagged and left out (bits.py).
    Each bit's tour starts where the previous one ended, as the machine will.
    """
    holes_by_tool = {t.name: _holes_of(job, t.name) for t in job.tools}
    bits = plan_bits(
        [(t.name, t.diameter_mm, str(t.source)) for t in job.tools],
        {name: len(holes) for name, holes in holes_by_tool.items()},
        smallest_first=smallest_first,
        one_bit=one_bit,
    )
    # Imported here, not with the module: the window does not need the optimiser (and
    # fast-tsp) until a drill file is read (issue #23, launch).
    from app.jobs.formats.excellon.hole_order import order_tools

    plans: list[ToolPlan] = []
    groups = [[h for name in g.tools for h in holes_by_tool[name]] for g in bits.groups]
    results = order_tools([[(h.x_mm, h.y_mm) for h in holes] for holes in groups], start=start)
    for group, holes, result in zip(bits.groups, groups, results, strict=True):
        ordered = tuple(holes[i] for i in result.order)
        plans.append(
            ToolPlan(
                job.tool(group.tool), ordered, result.file_length, result.length, group.tools[1:]
            )
        )
    return DrillPlan(job, tuple(plans), bits.flags)


# How a drill file becomes a program: drilled; drawn as the original drew (the pen down
# at the first hole of each bit and along the following ones, FIDELITY S2-12); or a pen
# cross at each hole (the station's own, an explicit option).
DrillMode = Literal["drill", "draw", "cross"]


def bit_prompt(plan: ToolPlan, mode: DrillMode = "drill") -> str:
    """What the operator reads at a bit change: "insert T02, 0.80 mm, 34 holes".

    Translated when the program is built: one text per mode and English number
    (the translations word the count so that one text fits every number).
    """
    count = len(plan.holes)
    also = (
        QCoreApplication.translate("JobFile", " (also {0})").format(", ".join(plan.also))
        if plan.also
        else ""
    )
    if mode == "drill":
        text = (
            QCoreApplication.translate("JobFile", "insert {0}, {1:.2f} mm, {2} hole{3}")
            if count == 1
            else QCoreApplication.translate("JobFile", "insert {0}, {1:.2f} mm, {2} holes{3}")
        )
    else:
        text = (
            QCoreApplication.translate("JobFile", "pen for {0}, {1:.2f} mm, {2} hole{3}")
            if count == 1
            else QCoreApplication.translate("JobFile", "pen for {0}, {1:.2f} mm, {2} holes{3}")
        )
    return localized_format(text, plan.tool.name, plan.tool.diameter_mm, count, also)


def _drawn_along(holes: Sequence[Hole], ax: str, ay: str) -> list[Operation]:
    """Pen down at the first hole, X then Y to each following one, pen up (S2-12)."""
    if not holes:
        return []
    first = holes[0]
    ops = [
        Operation(OpKind.MOVE, first.source, MappingProxyType({ax: first.x_mm, ay: first.y_mm})),
        Operation(OpKind.PEN_DOWN, first.source),
    ]
    x, y = first.x_mm, first.y_mm
    for hole in holes[1:]:
        for name, value, now in ((ax, hole.x_mm, x), (ay, hole.y_mm, y)):
            if value != now:
                ops.append(Operation(OpKind.MOVE, hole.source, MappingProxyType({name: value})))
        x, y = hole.x_mm, hole.y_mm
    ops.append(Operation(OpKind.PEN_UP, holes[-1].source))
    return ops


def build_drill_program(
    job: DrillJob,
    *,
    mode: DrillMode = "drill",
    start: tuple[float, float] = (0.0, 0.0),
    axes: tuple[str, str] = ("X", "Y"),
    smallest_first: bool = False,
    one_bit: bool = False,
) -> Program:
    """The job as operations: per bit a WAIT to insert it, then MOVE + DRILL per hole.

    ``draw``, the original's ``Kresli``/``Zvedni`` (FIDELITY S2-12): per bit the
    pen goes down at its first hole, is drawn along the following holes in the
    order they would be drilled, and comes up after the last.  The drill moves
    one axis at a time (``X`` then ``Y``), so the pen draws each step from hole
    to hole as an X stroke then a Y stroke; the program says so, one MOVE per
    axis, and the preview shows the very strokes the pen will draw.  ``cross``
    (the station's own, chosen explicitly): a pen cross as wide as each hole,
    to try the job on paper before a board is risked.  Every operation keeps
    its hole's file line.

    ``one_bit`` (a profile's ``[drill] one_bit``, FIDELITY S2-40): the
    original's behaviour, every hole with the bit in the spindle, one tour
    over all of them and no prompt to change the bit (nor the pen).
    """
    plan = plan_drilling(job, start=start, smallest_first=smallest_first, one_bit=one_bit)
    ax, ay = axes
    ops: list[Operation] = []

    def goto(where: SourceRef, x: float, y: float) -> Operation:
        return Operation(OpKind.MOVE, where, MappingProxyType({ax: x, ay: y}))

    for tool_plan in plan.tools:
        tool = tool_plan.tool
        if not one_bit:
            ops.append(Operation(OpKind.WAIT, tool.source, message=bit_prompt(tool_plan, mode)))
        for hole in tool_plan.holes:
            where = hole.source
            if mode == "drill":
                ops += [goto(where, hole.x_mm, hole.y_mm), Operation(OpKind.DRILL, where)]
                continue
            if mode == "draw":
                continue
            r = hole.diameter_mm / 2
            ops += [
                goto(where, hole.x_mm - r, hole.y_mm),
                Operation(OpKind.PEN_DOWN, where),
                goto(where, hole.x_mm + r, hole.y_mm),
                Operation(OpKind.PEN_UP, where),
                goto(where, hole.x_mm, hole.y_mm - r),
                Operation(OpKind.PEN_DOWN, where),
                goto(where, hole.x_mm, hole.y_mm + r),
                Operation(OpKind.PEN_UP, where),
            ]
        if mode == "draw":
            ops += _drawn_along(tool_plan.holes, ax, ay)
    saved = plan.file_travel_mm - plan.travel_mm
    note = localized_format(
        QCoreApplication.translate(
            "JobFile",
            "travel between holes: {0:.1f} mm in file order, {1:.1f} mm optimised "
            "({2:.1f} mm saved)",
        ),
        plan.file_travel_mm,
        plan.travel_mm,
        saved,
    )
    # gerbonara's warnings and our remarks, "line: text", as file:line: text for the operator.
    name = shown(job.path.name)
    warning = QCoreApplication.translate("JobFile", ": warning: ")
    remarks = tuple(f"{name}:{text.replace(': ', warning, 1)}" for text in job.notes)
    return Program(job.name, tuple(ops), job.path, notes=(*remarks, *plan.flags, note))
