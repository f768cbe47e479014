"""Machine profiles: what the station knows about a machine before it talks to it.

A profile is a TOML file in ``resources/machines`` (package data, see
app/resources.py); the station reads the dialect, link defaults, axes and
capabilities from it, so supporting another machine of a known family is a
file, not code.
"""

from __future__ import annotations

import math
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from types import MappingProxyType
from typing import Any

from app.resources import MACHINES_DIR as MACHINES_DIR  # where callers find the shipped ones
from protocol.drill.timing import DrillTiming
from protocol.stage.driver import DEFAULT_RSENSE_OHM, DEFAULT_VFS_V, STEP_CLOCK_HZ

DEFAULT_PROFILE = "xy-stage"
DIALECTS = ("stage", "usb3", "drill", "gcode")
#: How far a reported position may stray from the path of the moves sent ([supervision]
#: tolerance_mm): a few steps, a rounded report and a report read while the move went on.
DEFAULT_SUPERVISION_TOLERANCE_MM = 0.5
TRANSPORTS = ("emulator", "serial", "ble")


class ProfileError(ValueError):
    """A profile file that cannot be used, with the file and the reason."""


@dataclass(frozen=True)
class AxisProfile:
    name: str
    kind: str = "linear"
    unit: str = "mm"
    travel: float = 50.0
    steps_per_rev: int = 200
    microsteps: int = 16
    lead: float = 1.0
    max_speed: float = 100.0
    max_acceleration: float = 1000.0


@dataclass(frozen=True)
class LinkDefaults:
    transport: str = "emulator"
    baud: int = 115200
    ble_service_uuid: str = ""
    ble_write_uuid: str = ""
    ble_notify_uuid: str = ""
    ble_name_prefix: str = ""


@dataclass(frozen=True)
class Capabilities:
    home: bool = False
    sleep: bool = False
    subscribers: bool = False
    stop_command: bool = False
    speed_select: bool = False  # a fast/slow pair the operator switches between
    parameters: bool = False  # device-stored dynamics the Dynamics page reads and writes
    pen: bool = False
    drill: bool = False


@dataclass(frozen=True)
class DriverSettings:
    """The stage's TMC2130 drivers and step timer ([driver] in the profile).

    The wire carries the current scale CS (0…31) and speeds in µm/s; what the
    motor gets follows from these: IRMS from VFS and Rsense (FIDELITY S3-18),
    the real step rate from the timer clock (S3-28).  The original gives no
    VFS or Rsense: the defaults are the TMC2130's VSENSE = 0 full scale
    (0.32 V) and the usual 0.11 Ω sense resistor.
    """

    vfs_v: float = DEFAULT_VFS_V
    rsense_ohm: float = DEFAULT_RSENSE_OHM
    step_clock_hz: int = STEP_CLOCK_HZ


#: What a GRBL-compatible board executes (docs/protocols.md §4 plus the usual GRBL extras).
GRBL_WORDS = (
    "G0", "G1", "G2", "G3", "G4", "G17", "G20", "G21", "G28", "G90", "G91", "G92",
    "M0", "M1", "M2", "M3", "M4", "M5", "M8", "M9", "M30", "$H", "$X", "$$", "$I", "$G", "$J",
)  # fmt: skip


@dataclass(frozen=True)
class GcodeSettings:
    """How a G-code machine is fed and what it executes ([gcode] in the profile).

    ``words`` is the firmware's repertoire: a job line using anything else is
    refused before the job runs, with its line number.  The pen commands are
    the machine's own (the CoreXY plotter lifts with M3 and lowers with M4;
    GRBL servo plotters lower with ``M3 S<n>`` and lift with M5).
    """

    #: "counting" (at most rx_buffer - 1 bytes unacknowledged) or "ping-pong"
    streaming: str = "counting"
    rx_buffer: int = 128
    words: tuple[str, ...] = GRBL_WORDS
    pen_up: str = "M5"
    pen_down: str = "M3 S1000"
    z_is_pen: bool = False  # files' Z heights mean pen up (> 0) / down (≤ 0) on this machine
    kinematics: str = "cartesian"  # "cartesian", "corexy" or "cylindrical"
    status_ms: int = 200  # how often the station asks "?"
    #: G1/G2/G3 need a feed rate set first (GRBL's error:22); False: the firmware has a default.
    feed_required: bool = True
    #: The unit of ``G4 P``: "s" on GRBL (P150 is two and a half minutes), "ms" on firmwares
    #: that read it as Marlin does.  The loader, the estimate and the emulator follow it.
    dwell_p: str = "s"
    #: GRBL's ``$11`` (mm): the board joins moves at their junction speed, planning
    #: ``planner_blocks`` ahead, and the estimate plans as it does; None (firmwares without
    #: a look-ahead planner): every move starts and ends at rest.
    junction_deviation: float | None = None
    planner_blocks: int = 15
    #: A bare ``G92`` makes the current position the origin (the CoreXY plotter's firmware);
    #: False: GRBL's, which refuses it (error:26) and needs the axes named.
    bare_g92: bool = False
    #: The board answers a line only once its motion is done (the CoreXY plotter), not once
    #: planned (GRBL): every answered line ran, and an unanswered one is at most the one
    #: under way — what a resume after a fault can take as proven.
    ok_when_done: bool = False
    #: A firmware that ignores F and runs G0 as G1, stepping its lead motor at one interval
    #: that only ``M98 <µs>`` changes (the CoreXY plotter, FIDELITY S1-01): its power-on
    #: interval in µs.  None: F sets the speed (GRBL, the winder).
    step_interval_us: float | None = None
    #: A GRBL board's job lines go compact (:attr:`compact_lines`); False: as written.
    compact: bool = True

    @property
    def feed_ignored(self) -> bool:
        """F words mean nothing to this firmware: the step interval alone sets the speed."""
        return self.step_interval_us is not None

    @property
    def compact_lines(self) -> bool:
        """A job's lines go on the wire without spaces and in upper case, as GRBL's own
        ``stream.py`` sends them: GRBL's serial layer drops both before its parser, so the
        board reads the same line in fewer bytes (a wire-bound job is delivered sooner).
        Not for firmwares that read spaces (the CoreXY plotter's ``M98 500``)."""
        return self.compact and "$J" in self.words

    @property
    def dwell_p_seconds(self) -> float:
        """Seconds one unit of ``G4 P`` is on this machine."""
        return 0.001 if self.dwell_p == "ms" else 1.0


def _source(_context: str, text: str) -> str:
    return text


_translator: Callable[[str, str], str] = _source


def translate(context: str, text: str) -> str:
    """``text`` in the language installed: profiles are read where there is no Qt (the CLI)."""
    return _translator(context, text)


def use(translator: Callable[[str, str], str]) -> None:
    """Say titles through ``translator`` from now on (:func:`app.i18n.install` hands it over)."""
    global _translator
    _translator = translator


def shipped_titles() -> tuple[str, ...]:
    """The shipped machines' titles (resources/machines/*.toml), in the language installed.

    Each goes through ``translate`` here so that lupdate lists it: the window says a
    machine's title in the operator's language.  A profile of one's own keeps its title
    as written.
    """
    return (
        translate("MachineProfile", "XY positioning stage"),
        translate("MachineProfile", "Three-axis USB unit"),
        translate("MachineProfile", "PCB drill/plotter"),
        translate("MachineProfile", "String-art winder"),
        translate("MachineProfile", "CoreXY pen plotter"),
        translate("MachineProfile", "GRBL pen plotter"),
    )


@dataclass(frozen=True)
class MachineProfile:
    name: str
    title: str
    dialect: str
    axes: tuple[AxisProfile, ...]
    link: LinkDefaults = field(default_factory=LinkDefaults)
    capabilities: Capabilities = field(default_factory=Capabilities)
    period_ms: int = 100
    source: Path | None = None
    gcode: GcodeSettings | None = None
    #: Where a job ends ([park] in the profile: mm per axis name), or None: it stays where
    #: it finished.  Judged against the travel when the profile is read, and again by the
    #: motion gate when the job goes there.
    park: Mapping[str, float] | None = None
    driver: DriverSettings = field(default_factory=DriverSettings)
    #: The drill's timing constants ([timing] in the profile, FIDELITY S2-06): the
    #: emulator runs them, the estimate and the session's timeouts count with them.
    drill_timing: DrillTiming = field(default_factory=DrillTiming)
    #: ``[drill] one_bit``: every hole of a drill file with the one bit in the spindle and no
    #: bit-change prompt, as the original drill worked (FIDELITY S2-40); False: a prompt per
    #: diameter, the station's deliberate deviation.
    drill_one_bit: bool = False
    #: How far a reported position may be from the path of the moves in flight before the
    #: station stops the machine (mm, or degrees on a rotary axis).
    supervision_tolerance_mm: float = DEFAULT_SUPERVISION_TOLERANCE_MM

    @property
    def shown_title(self) -> str:
        """The title in the operator's language (the file's, English, stays :attr:`title`)."""
        return translate("MachineProfile", self.title)

    def travel_limits(self) -> dict[str, tuple[float, float]]:
        """Per axis name, where a job may send it: 0…travel; a rotary axis turns freely."""
        return {
            axis.name: (-math.inf, math.inf) if axis.kind == "rotary" else (0.0, axis.travel)
            for axis in self.axes
        }

    def axis_index(self, name: str) -> int:
        for i, axis in enumerate(self.axes):
            if axis.name == name:
                return i
        raise KeyError(name)


def available_profiles(directory: Path = MACHINES_DIR) -> list[str]:
    return sorted(p.stem for p in directory.glob("*.toml"))


def load_profile(name_or_path: str | Path, directory: Path = MACHINES_DIR) -> MachineProfile:
    """Load a shipped profile by name, or any profile file by path."""
    path = Path(name_or_path)
    if path.suffix != ".toml":
        path = directory / f"{name_or_path}.toml"
    if not path.is_file():
        known = ", ".join(available_profiles(directory)) or "none"
        raise ProfileError(f"no machine profile {name_or_path!r} (known: {known})")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise ProfileError(f"{path}: {exc}") from exc
    return _profile_from(data, path)


def _section(data: dict[str, Any], key: str, path: Path) -> dict[str, Any]:
    value = data.get(key, {})
    if not isinstance(value, dict):
        raise ProfileError(f"{path}: [{key}] must be a table")
    return value


def _build(cls: type[Any], values: dict[str, Any], path: Path, where: str) -> Any:
    try:
        return cls(**values)
    except TypeError as exc:
        raise ProfileError(f"{path}: {where}: {exc}") from exc


def _profile_from(data: dict[str, Any], path: Path) -> MachineProfile:
    dialect = data.get("dialect")
    if dialect not in DIALECTS:
        raise ProfileError(f"{path}: dialect must be one of {', '.join(DIALECTS)}, not {dialect!r}")
    raw_axes = data.get("axes")
    if not isinstance(raw_axes, list) or not raw_axes:
        raise ProfileError(f"{path}: at least one [[axes]] entry is required")
    axes = tuple(
        _build(AxisProfile, dict(a), path, f"axis {i + 1}") for i, a in enumerate(raw_axes)
    )
    for axis in axes:
        if axis.travel <= 0:
            raise ProfileError(f"{path}: axis {axis.name}: travel must be positive")
    link = _build(LinkDefaults, _section(data, "link", path), path, "[link]")
    if link.transport not in TRANSPORTS:
        raise ProfileError(f"{path}: [link] transport must be one of {', '.join(TRANSPORTS)}")
    capabilities = _build(
        Capabilities, _section(data, "capabilities", path), path, "[capabilities]"
    )
    gcode: GcodeSettings | None = None
    if dialect == "gcode" or "gcode" in data:
        values = dict(_section(data, "gcode", path))
        if "words" in values:
            values["words"] = tuple(str(w).upper() for w in values["words"])
        gcode = _build(GcodeSettings, values, path, "[gcode]")
        if gcode.dwell_p not in ("s", "ms"):
            raise ProfileError(f"{path}: [gcode] dwell_p must be 's' or 'ms'")
        deviation = gcode.junction_deviation
        if deviation is not None and not (isinstance(deviation, int | float) and deviation >= 0):
            raise ProfileError(f"{path}: [gcode] junction_deviation must be a length >= 0 (mm)")
        if not (isinstance(gcode.planner_blocks, int) and gcode.planner_blocks >= 2):
            raise ProfileError(f"{path}: [gcode] planner_blocks must be a whole number >= 2")
        interval = gcode.step_interval_us
        if interval is not None and not (
            isinstance(interval, int | float) and math.isfinite(interval) and interval > 0
        ):
            raise ProfileError(f"{path}: [gcode] step_interval_us must be a time > 0 (µs)")
        if not isinstance(gcode.compact, bool):
            raise ProfileError(f"{path}: [gcode] compact must be true or false")
        if gcode.streaming not in ("counting", "ping-pong"):
            raise ProfileError(f"{path}: [gcode] streaming must be 'counting' or 'ping-pong'")
        if gcode.kinematics not in ("cartesian", "corexy", "cylindrical"):
            raise ProfileError(
                f"{path}: [gcode] kinematics must be cartesian, corexy or cylindrical"
            )
    park = _park_from(_section(data, "park", path), axes, path) if "park" in data else None
    driver = _build(DriverSettings, _section(data, "driver", path), path, "[driver]")
    if not (driver.vfs_v > 0 and driver.rsense_ohm >= 0 and driver.step_clock_hz > 0):
        raise ProfileError(
            f"{path}: [driver] vfs_v and step_clock_hz must be positive, rsense_ohm not negative"
        )
    drill_timing = DrillTiming()
    if "timing" in data:
        if dialect != "drill":
            raise ProfileError(f"{path}: [timing] is for the drill dialect only")
        try:
            drill_timing = DrillTiming.from_table(_section(data, "timing", path))
        except ValueError as exc:
            raise ProfileError(f"{path}: [timing] {exc}") from exc
    drill = _section(data, "drill", path)
    if set(drill) - {"one_bit"}:
        raise ProfileError(f"{path}: [drill] knows only one_bit, not {sorted(set(drill))}")
    one_bit = drill.get("one_bit", False)
    if not isinstance(one_bit, bool):
        raise ProfileError(f"{path}: [drill] one_bit must be true or false")
    supervision = _section(data, "supervision", path)
    unknown = set(supervision) - {"tolerance_mm"}
    if unknown:
        raise ProfileError(f"{path}: [supervision] knows only tolerance_mm, not {sorted(unknown)}")
    tolerance = supervision.get("tolerance_mm", DEFAULT_SUPERVISION_TOLERANCE_MM)
    if (
        isinstance(tolerance, bool)
        or not isinstance(tolerance, int | float)
        or not 0 < tolerance < math.inf
    ):
        raise ProfileError(f"{path}: [supervision] tolerance_mm must be a length > 0 (mm)")
    period = int(data.get("period_ms", 100))
    if not 20 <= period <= 1000:
        raise ProfileError(f"{path}: period_ms must be within 20…1000")
    return MachineProfile(
        name=str(data.get("name", path.stem)),
        title=str(data.get("title", path.stem)),
        dialect=dialect,
        axes=axes,
        link=link,
        capabilities=capabilities,
        period_ms=period,
        source=path,
        gcode=gcode,
        park=park,
        driver=driver,
        drill_timing=drill_timing,
        drill_one_bit=one_bit,
        supervision_tolerance_mm=float(tolerance),
    )


def _park_from(
    values: dict[str, Any], axes: tuple[AxisProfile, ...], path: Path
) -> Mapping[str, float]:
    """The park position: a number inside the travel for every axis it names."""
    travel = {axis.name: axis for axis in axes}
    park: dict[str, float] = {}
    for name, value in values.items():
        axis = travel.get(name)
        if axis is None:
            raise ProfileError(f"{path}: [park] names {name!r}, which is no axis")
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise ProfileError(f"{path}: [park] {name} must be a number, not {value!r}")
        if axis.kind != "rotary" and not 0.0 <= float(value) <= axis.travel:
            raise ProfileError(
                f"{path}: [park] {name} {value} is outside the travel 0…{axis.travel:g}"
            )
        park[name] = float(value)
    if not park:
        raise ProfileError(f"{path}: [park] names no axis")
    return MappingProxyType(park)
