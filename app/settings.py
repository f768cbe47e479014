"""Settings that survive a restart, each read through one layer that knows its type and range.

The settings file may hold anything: a value from an older version, one
edited by hand, a file half overwritten.  A remembered baud rate too large
for an int once stopped the station at every launch, and a period of -5 ms
ran a 1 ms timer.  So every persisted value has a :class:`Spec` here (type,
range or choices, default), every read checks the stored value against it,
and a bad one yields the default plus a warning naming the key and the
file.  A file Qt cannot read at all gives defaults and one warning naming
it; a copy is kept beside it, because Qt overwrites a malformed file on the
next save.  The warnings are collected, not raised: the window shows them
once at start (:meth:`StationSettings.take_warnings`).

Settings that concern the machine (the last link, the arrow keys' step,
skipping lines it cannot run) are kept per machine profile, under
``machines/<profile>/``: "1 mm per tap" chosen on the drill must not come back
as "1 deg per tap" on the winder, nor the drill's serial port on the
emulated stage.  Those that concern the person (theme, language, the
window) stay global.  A file from before keeps its global values as the
first values of the machine it was last used with (:meth:`_migrate`).

Tests pass their own QSettings file so they never touch the operator's.
"""

from __future__ import annotations

import dataclasses
import logging
import math
import re
import shutil
from collections.abc import Callable, Collection, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Generic, TypeVar

from PySide6.QtCore import QT_TRANSLATE_NOOP, QByteArray, QCoreApplication, QSettings

from app.machines.drill.conversion import (
    EXCELLON_STEP_BOUNDS,
    MICROSTEPS_PER_MM_BOUNDS,
    DrillConversion,
)
from app.profiles import DEFAULT_PROFILE, TRANSPORTS, available_profiles
from protocol.drill.timing import INTEGER_CONSTANTS, TIMING_BOUNDS, DrillTiming

ORGANISATION = "StepDeck"
APPLICATION = "StepDeck"

#: Baud rates a serial port can be asked for (pyserial's own bounds on Linux).
BAUD_RANGE = (50, 4_000_000)
#: The stage's command frame period, as ``--period`` and the profiles allow it.
PERIOD_RANGE = (20, 1000)
#: Window geometry and dock layout blobs are a few hundred bytes; more is not ours.
_BLOB_LIMIT = 64 * 1024
_TEXT_LIMIT = 512
#: Suffix of the copy kept of a settings file Qt could not read.
UNREADABLE_SUFFIX = ".unreadable"

_log = logging.getLogger(__name__)

T = TypeVar("T")
T_co = TypeVar("T_co", covariant=True)


class BadValue(ValueError):
    """A stored value that is not what its key holds."""


def default_settings() -> QSettings:
    return QSettings(ORGANISATION, APPLICATION)


@dataclass(frozen=True)
class Spec(Generic[T_co]):
    """One persisted value: where it is stored, what it may be, and what to use instead.

    A default of None means "not stored: the profile decides" (period, baud).
    """

    key: str
    default: T_co
    #: What the value must be, in words for the warning ("an integer within 20…1000").
    expects: str
    #: The stored value as a ``T``; raises :class:`BadValue` for anything else.
    convert: Callable[[object], T_co]


# --- converters: what a stored value may look like (INI files keep text) ------------------


def _integer(lo: int, hi: int) -> Callable[[object], int]:
    def convert(value: object) -> int:
        if isinstance(value, bool):
            raise BadValue("a truth value")
        if isinstance(value, str):
            text = value.strip()
            digits = text.lstrip("+-")
            if not digits.isascii() or not digits.isdigit() or len(digits) > 12:
                raise BadValue("not an integer")
            number = int(text)
        elif isinstance(value, int):
            number = value
        else:
            raise BadValue(f"a {type(value).__name__}")
        if not lo <= number <= hi:
            raise BadValue(f"{number} is out of range")
        return number

    return convert


def _truth(value: object) -> bool:
    if isinstance(value, bool):
        return value
    if isinstance(value, str) and value.strip().lower() in ("true", "false"):
        return value.strip().lower() == "true"
    raise BadValue("not true or false")


def _choice(choices: Callable[[], Collection[str]]) -> Callable[[object], str]:
    def convert(value: object) -> str:
        if isinstance(value, str) and value in choices():
            return value
        raise BadValue("not one of the choices")

    return convert


def _number_choice(choices: Collection[float]) -> Callable[[object], float]:
    def convert(value: object) -> float:
        if isinstance(value, bool) or not isinstance(value, int | float | str):
            raise BadValue("not a number")
        try:
            number = float(value)
        except (ValueError, OverflowError) as exc:
            raise BadValue("not a number") from exc
        for choice in choices:
            if math.isclose(number, choice, rel_tol=1e-9):
                return choice
        raise BadValue("not one of the choices")

    return convert


def _text(value: object) -> str:
    if not isinstance(value, str):
        raise BadValue(f"a {type(value).__name__}")
    if len(value) > _TEXT_LIMIT or not value.isprintable():
        raise BadValue("not a short printable text")
    return value


def _blob(value: object) -> QByteArray:
    if isinstance(value, QByteArray):
        data = value
    elif isinstance(value, bytes):
        data = QByteArray(value)
    else:
        raise BadValue(f"a {type(value).__name__}")
    if data.size() > _BLOB_LIMIT:
        raise BadValue("too large")
    return data


# --- every key the station stores -----------------------------------------------------------

PROFILE = Spec(
    "station/profile", DEFAULT_PROFILE, "a machine profile name", _choice(available_profiles)
)
PERIOD_MS: Spec[int | None] = Spec(
    "station/period_ms",
    None,
    f"an integer within {PERIOD_RANGE[0]}…{PERIOD_RANGE[1]} (ms)",
    _integer(*PERIOD_RANGE),
)
TRANSPORT = Spec(
    "link/transport", "emulator", f"one of {', '.join(TRANSPORTS)}", _choice(lambda: TRANSPORTS)
)
DEVICE = Spec("link/device", "", "a port path or a BLE address", _text)
BAUD: Spec[int | None] = Spec(
    "link/baud",
    None,
    f"an integer within {BAUD_RANGE[0]}…{BAUD_RANGE[1]}",
    _integer(*BAUD_RANGE),
)
GEOMETRY: Spec[QByteArray | None] = Spec("main_window/geometry", None, "window geometry", _blob)
WINDOW_STATE: Spec[QByteArray | None] = Spec("main_window/state", None, "window layout", _blob)
#: The page shown; the window has fewer, and checks the index again against its own count.
PAGE = Spec("main_window/page", 0, "a page number within 0…31", _integer(0, 31))
# The docks shown when the window was last closed, by object name, comma-separated: the
# window builds its docks on first use, and these at start (None: a state saved before).
DOCKS_SHOWN: Spec[str | None] = Spec("main_window/docks_shown", None, "dock names", _text)
#: Excellon steps the jobs dock offers, in inches.
EXCELLON_STEPS = (1e-4, 1e-3, 1e-5)
#: The jobs dock's reading options, by option name.
JOB_OPTIONS: Mapping[str, Spec[object]] = {
    "draw": Spec("job_options/draw", False, "true or false", _truth),
    "draw_crosses": Spec("job_options/draw_crosses", False, "true or false", _truth),
    "smallest_first": Spec("job_options/smallest_first", False, "true or false", _truth),
    "translate_pen": Spec("job_options/translate_pen", True, "true or false", _truth),
    "skip_unsupported": Spec("job_options/skip_unsupported", False, "true or false", _truth),
    "excellon_step_inch": Spec(
        "job_options/excellon_step_inch",
        1e-4,
        "one of 0.0001, 0.001, 0.00001 (inch)",
        _number_choice(EXCELLON_STEPS),
    ),
}


def _bounded(lo: float, hi: float, whole: bool) -> Callable[[object], float]:
    """A number within ``lo…hi`` (a whole one for ``whole``), stored as a number or text."""

    def convert(value: object) -> float:
        if isinstance(value, bool):
            raise BadValue("a truth value")
        try:
            number = float(value) if isinstance(value, int | float | str) else math.nan
        except ValueError:
            raise BadValue("not a number") from None
        if not math.isfinite(number) or not lo <= number <= hi:
            raise BadValue(f"{number:g} is out of range")
        if whole and number != int(number):
            raise BadValue("not a whole number")
        return int(number) if whole else number

    return convert


#: The drill's timing constants as the operator set them in the station (FIDELITY S2-06),
#: by constant name; absent: the profile's.
DRILL_TIMING: Mapping[str, Spec[float]] = {
    name: Spec(
        f"drill_timing/{name}",
        math.nan,
        f"a number within {lo:g}…{hi:g}",
        _bounded(lo, hi, name in INTEGER_CONSTANTS),
    )
    for name, (lo, hi) in TIMING_BOUNDS.items()
}
#: The drill's conversion constants as the teacher set them (FIDELITY S2-42), kept per
#: machine profile (``machines/<profile>/drill_conversion/…``); absent: the profile's.
EXCELLON_STEP = Spec(
    "drill_conversion/excellon_step_inch",
    math.nan,
    f"a number within {EXCELLON_STEP_BOUNDS[0]:g}…{EXCELLON_STEP_BOUNDS[1]:g} (inch)",
    _bounded(*EXCELLON_STEP_BOUNDS, False),
)


def microsteps_per_mm_spec(axis: str) -> Spec[float]:
    """The teacher's microsteps a millimetre of ``axis`` (kept per machine profile)."""
    low, high = MICROSTEPS_PER_MM_BOUNDS
    return Spec(
        f"drill_conversion/microsteps_per_mm_{machine_scope(axis)}",
        math.nan,
        f"a number within {low:g}…{high:g}",
        _bounded(low, high, False),
    )


#: What one tap of an arrow key moves (mm, or degrees on a rotary axis); 0: held, continuous.
JOG_STEPS = (0.0, 0.1, 1.0, 10.0)
JOG_STEP = Spec("jog/key_step", 0.0, "one of 0 (continuous), 0.1, 1, 10", _number_choice(JOG_STEPS))
#: How many job files File → Recent jobs lists.
RECENT_JOBS_KEPT = 8
#: The job files opened last, newest first ("" where there is none).
RECENT_JOBS: tuple[Spec[str], ...] = tuple(
    Spec(f"recent_jobs/{index}", "", "a file path", _text) for index in range(RECENT_JOBS_KEPT)
)
#: The window's colours: as the desktop says, or always light or dark.
THEMES = ("system", "light", "dark")
THEME = Spec("view/theme", "system", f"one of {', '.join(THEMES)}", _choice(lambda: THEMES))
#: The language: the system locale's (English where it is none of these) or a fixed one.
LANGUAGE_CHOICES = ("system", "en", "cs", "sk")
LANGUAGE = Spec(
    "view/language",
    "system",
    f"one of {', '.join(LANGUAGE_CHOICES)}",
    _choice(lambda: LANGUAGE_CHOICES),
)
#: The jobs dock's options that concern the machine: stored per profile.
MACHINE_JOB_OPTIONS = frozenset({"skip_unsupported"})
#: Every value kept per machine profile; each key here is also where a file from before
#: kept it for every machine (read once, then moved: see ``StationSettings._migrate``).
MACHINE_SPECS: tuple[Spec[object], ...] = (
    TRANSPORT,
    DEVICE,
    BAUD,
    JOG_STEP,
    *(JOB_OPTIONS[name] for name in sorted(MACHINE_JOB_OPTIONS)),
)
#: Where the per-machine values live: ``machines/<profile>/<key>``.
MACHINES_GROUP = "machines"


def machine_scope(profile: str) -> str:
    """The profile's name as a settings group: a name from any file cannot leave its group."""
    safe = re.sub(r"[^A-Za-z0-9_-]", "_", profile)[:64]
    return safe or "_"


def machine_spec(spec: Spec[T], profile: str) -> Spec[T]:
    """``spec`` as kept for one machine profile."""
    return dataclasses.replace(spec, key=f"{MACHINES_GROUP}/{machine_scope(profile)}/{spec.key}")


#: Every key, for the tests (and for anyone wondering what the file may hold).
ALL_SPECS: tuple[Spec[object], ...] = (
    PROFILE,
    JOG_STEP,
    PERIOD_MS,
    TRANSPORT,
    DEVICE,
    BAUD,
    GEOMETRY,
    WINDOW_STATE,
    DOCKS_SHOWN,
    PAGE,
    *JOB_OPTIONS.values(),
    *RECENT_JOBS,
    THEME,
    LANGUAGE,
)


class _MemoryStore:
    """Stands in for QSettings when a window is built without one (tests, benchmarks)."""

    def __init__(self) -> None:
        self._values: dict[str, object] = {}

    def value(self, key: str, default: object = None) -> object:
        return self._values.get(key, default)

    def setValue(self, key: str, value: object) -> None:
        self._values[key] = value

    def contains(self, key: str) -> bool:
        return key in self._values

    def remove(self, key: str) -> None:
        self._values.pop(key, None)

    def fileName(self) -> str:
        return "(memory)"

    def sync(self) -> None:
        pass


#: The warnings, translated when they are taken (see StationSettings.take_warnings).
_BAD_VALUE = str(
    QT_TRANSLATE_NOOP(
        "Settings", "Setting {0} in {1} was {2}; it should be {3}, so the default is used"
    )
)
_MALFORMED = str(QT_TRANSLATE_NOOP("Settings", "Settings file {0} is malformed: defaults are used"))
_MALFORMED_KEPT = str(
    QT_TRANSLATE_NOOP(
        "Settings", "Settings file {0} is malformed: defaults are used; a copy is kept as {1}"
    )
)
_NOT_READABLE = str(
    QT_TRANSLATE_NOOP("Settings", "Settings file {0} is not readable: defaults are used")
)


class StationSettings:
    """The station's remembered values, each read checked against its :class:`Spec`."""

    def __init__(self, store: QSettings | None) -> None:
        self.store: QSettings | _MemoryStore = store if store is not None else _MemoryStore()
        #: Each warning as its English template and values: it is translated when it is
        #: taken, because the settings are read before the language (itself a setting)
        #: is installed.
        self._warnings: list[tuple[str, tuple[object, ...]]] = []
        self._warned: set[str] = set()
        if isinstance(self.store, QSettings):
            self._check_file(self.store)
        self._migrate()

    @property
    def file_name(self) -> str:
        return self.store.fileName()

    # --- the one way in and out ---------------------------------------------------------

    def read(self, spec: Spec[T]) -> T:
        """The stored value if it is what ``spec`` allows; otherwise the default, and a warning."""
        try:
            if not self.store.contains(spec.key):
                return spec.default
            value = self.store.value(spec.key)
        except Exception as exc:  # a value Qt itself cannot turn into Python
            return self._bad(spec, f"unreadable ({type(exc).__name__})")
        if value is None:
            return spec.default
        try:
            return spec.convert(value)
        except BadValue as exc:
            return self._bad(spec, f"{_shown(value)} ({exc})")

    def write(self, spec: Spec[T], value: T) -> None:
        """Store ``value``; one the spec refuses is a bug in the caller, so it raises."""
        if value is None:
            self.store.remove(spec.key)
            return
        try:
            spec.convert(value)
        except BadValue as exc:
            raise ValueError(f"{spec.key}: {value!r} is not {spec.expects}") from exc
        self.store.setValue(spec.key, value)

    def _migrate(self) -> None:
        """Global values of the machine's settings, from before, become one machine's.

        They were set on the machine last used, so they are the first values of
        that profile (kept if it has its own already); the others start from
        the defaults.  A bad one is warned about and dropped, as any read.
        """
        try:
            legacy = [spec for spec in MACHINE_SPECS if self.store.contains(spec.key)]
        except Exception:  # a store that cannot even say what it holds: nothing to move
            return
        if not legacy:
            return
        owner = self.profile
        for spec in legacy:
            value = self.read(spec)
            scoped = machine_spec(spec, owner)
            try:
                if value is not None and not self.store.contains(scoped.key):
                    self.write(scoped, value)
                self.store.remove(spec.key)
            except Exception as exc:  # never a reason not to start
                _log.warning("settings: %s not moved to %s (%s)", spec.key, scoped.key, exc)

    def machine(self, profile: str) -> MachineSettings:
        """The settings of one machine profile (its link, arrow keys, skipped lines)."""
        return MachineSettings(self, profile)

    def take_warnings(self) -> list[str]:
        """The warnings not shown yet (each is shown once, at start)."""
        taken, self._warnings = self._warnings, []
        return [QCoreApplication.translate("Settings", text).format(*args) for text, args in taken]

    def _bad(self, spec: Spec[T], what: str) -> T:
        if spec.key not in self._warned:
            self._warned.add(spec.key)
            args = (spec.key, self.file_name, what, spec.expects)
            _log.warning(_BAD_VALUE.format(*args))
            self._warnings.append((_BAD_VALUE, args))
        return spec.default

    def _check_file(self, store: QSettings) -> None:
        store.allKeys()  # Qt reads the file, and learns its status, on the first access
        status = store.status()
        if status is QSettings.Status.NoError:
            return
        path = Path(store.fileName())
        text = _MALFORMED if status is QSettings.Status.FormatError else _NOT_READABLE
        kept = ""
        if status is QSettings.Status.FormatError and path.is_file():
            copy = path.with_name(path.name + UNREADABLE_SUFFIX)
            try:
                shutil.copyfile(path, copy)
                text = _MALFORMED_KEPT
                kept = str(copy)
            except OSError:
                pass
        _log.warning(text.format(path, kept))
        self._warnings.append((text, (path, kept)))

    # --- named values ---------------------------------------------------------------

    @property
    def profile(self) -> str:
        return self.read(PROFILE)

    @profile.setter
    def profile(self, name: str) -> None:
        self.write(PROFILE, name)

    @property
    def period_ms(self) -> int | None:
        return self.read(PERIOD_MS)

    @period_ms.setter
    def period_ms(self, value: int) -> None:
        self.write(PERIOD_MS, int(value))

    def _job_option(self, name: str, profile: str) -> Spec[object]:
        spec = JOB_OPTIONS[name]
        return machine_spec(spec, profile) if name in MACHINE_JOB_OPTIONS else spec

    def job_options(self, profile: str) -> dict[str, object]:
        """The jobs dock's reading options that are stored (and valid), by option name.

        Those that concern the machine (skipping lines it cannot run) are ``profile``'s.
        """
        specs = {name: self._job_option(name, profile) for name in JOB_OPTIONS}
        return {
            name: self.read(spec) for name, spec in specs.items() if self.store.contains(spec.key)
        }

    def set_job_options(self, values: Mapping[str, object], profile: str) -> None:
        for name, value in values.items():
            self.write(self._job_option(name, profile), value)

    def drill_timing(self, base: DrillTiming) -> DrillTiming:
        """``base`` (the profile's) with the constants the operator set and stored."""
        stored = {
            name: self.read(spec)
            for name, spec in DRILL_TIMING.items()
            if self.store.contains(spec.key)
        }
        values: dict[str, Any] = {
            name: value for name, value in stored.items() if not math.isnan(value)
        }
        if not values:
            return base
        try:
            return dataclasses.replace(base, **values)
        except ValueError:  # each is in bounds, so only a future cross-check could refuse
            return base

    def set_drill_timing(self, timing: DrillTiming | None) -> None:
        """Store ``timing``'s constants; None: forget them (the profile's apply again)."""
        for name, spec in DRILL_TIMING.items():
            if timing is None:
                self.store.remove(spec.key)
            else:
                self.write(spec, getattr(timing, name))

    def recent_jobs(self) -> list[str]:
        """The job files opened last, newest first (unusable entries left out)."""
        paths = (self.read(spec) for spec in RECENT_JOBS)
        return [path for path in paths if path]

    def add_recent_job(self, path: str) -> None:
        """Put ``path`` first in the list; the oldest falls off.  Too long a path is not kept."""
        try:
            _text(path)
        except BadValue:
            return
        paths = [path, *(p for p in self.recent_jobs() if p != path)]
        self.set_recent_jobs(paths)

    def set_recent_jobs(self, paths: list[str]) -> None:
        for index, spec in enumerate(RECENT_JOBS):
            if index < len(paths):
                self.write(spec, paths[index])
            else:
                self.store.remove(spec.key)

    @property
    def theme(self) -> str:
        return self.read(THEME)

    @theme.setter
    def theme(self, value: str) -> None:
        self.write(THEME, value)

    @property
    def language(self) -> str:
        return self.read(LANGUAGE)

    @language.setter
    def language(self, value: str) -> None:
        self.write(LANGUAGE, value)

    def sync(self) -> None:
        self.store.sync()


class MachineSettings:
    """One machine profile's settings: read and written through its station's checks."""

    def __init__(self, settings: StationSettings, profile: str) -> None:
        self.settings = settings
        self.profile = profile

    def _read(self, spec: Spec[T]) -> T:
        return self.settings.read(machine_spec(spec, self.profile))

    def _write(self, spec: Spec[T], value: T) -> None:
        self.settings.write(machine_spec(spec, self.profile), value)

    @property
    def transport(self) -> str:
        """The link last used with this machine: emulator, serial or ble."""
        return self._read(TRANSPORT)

    @transport.setter
    def transport(self, value: str) -> None:
        self._write(TRANSPORT, value)

    @property
    def device(self) -> str:
        """Last serial port or BLE address used with this machine."""
        return self._read(DEVICE)

    @device.setter
    def device(self, value: str) -> None:
        self._write(DEVICE, value)

    @property
    def baud(self) -> int | None:
        return self._read(BAUD)

    @baud.setter
    def baud(self, value: int) -> None:
        self._write(BAUD, int(value))

    @property
    def jog_step(self) -> float:
        """What a tap of an arrow key moves on this machine; 0: the key jogs while held."""
        return self._read(JOG_STEP)

    @jog_step.setter
    def jog_step(self, value: float) -> None:
        self._write(JOG_STEP, float(value))

    def drill_conversion(self, base: DrillConversion, axes: tuple[str, ...]) -> DrillConversion:
        """``base`` (the profile's) with the constants the teacher set and this machine kept."""
        step = self._read(EXCELLON_STEP)
        per_mm = tuple(
            self._read(microsteps_per_mm_spec(name)) for name in axes[: len(base.microsteps_per_mm)]
        )
        try:
            return dataclasses.replace(
                base,
                excellon_step_inch=base.excellon_step_inch if math.isnan(step) else step,
                microsteps_per_mm=tuple(
                    kept if value is None or math.isnan(value) else value
                    for value, kept in zip(per_mm, base.microsteps_per_mm, strict=False)
                )
                + base.microsteps_per_mm[len(per_mm) :],
            )
        except ValueError:  # each is in bounds, so only a future cross-check could refuse
            return base

    def set_drill_conversion(
        self, conversion: DrillConversion | None, axes: tuple[str, ...]
    ) -> None:
        """Keep ``conversion``'s constants for this machine; None: forget them (the profile's)."""
        specs = [EXCELLON_STEP, *(microsteps_per_mm_spec(name) for name in axes)]
        if conversion is None:
            for spec in specs:
                self.settings.store.remove(machine_spec(spec, self.profile).key)
            return
        self._write(EXCELLON_STEP, conversion.excellon_step_inch)
        for name, value in zip(axes, conversion.microsteps_per_mm, strict=False):
            self._write(microsteps_per_mm_spec(name), value)


def _shown(value: object) -> str:
    """A stored value as the warning quotes it: short, one line."""
    text = repr(value)
    return text if len(text) <= 40 else text[:37] + "…"
