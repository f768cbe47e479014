"""Each dialect registered once: its session, its emulated device and what it can do.

The station looks the profile's dialect up here, so a machine family is
added by registering its session and emulator, not by editing the station.
The halves that sit above the sessions are keyed by the same names: the job
driver (:mod:`app.jobs.run.drivers`), the estimate (:mod:`app.jobs.estimate`)
and the window's pages, home buttons and developer boxes
(:mod:`widgets.dialects`, with its stop caption); the layering (sessions below the station, the jobs
and the developer pane) keeps them out of this module, and
``tests/test_dialect_registry.py`` holds the tables together.  No code outside
these tables asks a profile which dialect it speaks: it asks the entry what the
dialect can do (``docs/architecture.md``, "Adding a machine").

The emulators are imported when one is made, not with this module: the
G-code one alone brings its planner and numpy, and the window's first paint
waits for every import of the station's.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

from app.link import Link
from app.machine import MachineModel
from app.machines.drill.session import DrillSession
from app.machines.gcode.session import GcodeSession
from app.machines.session import MachineSession
from app.machines.stage.session import StageSession
from app.machines.usb3.session import Usb3Session
from app.profiles import MachineProfile
from protocol.clock import Clock
from protocol.emulator.device import EmulatedDevice

SessionFactory = Callable[[MachineModel, Link, Clock, MachineProfile, int, bool], MachineSession]
EmulatorFactory = Callable[[Clock, MachineProfile], EmulatedDevice]


@dataclass(frozen=True)
class Dialect:
    """One dialect's machine half, and the facts about it that the layers above act on."""

    #: The profile's ``dialect`` that names it.
    name: str
    session: SessionFactory
    #: The class :attr:`session` makes (the station's typed look-ups go by it).
    session_type: type[MachineSession]
    emulator: EmulatorFactory
    #: The session carries held and stepped jogs: without them the window shows no jog pad
    #: and the arrow keys are not the machine's (a pad shown only to be refused misleads).
    jogs: bool = True
    #: One home command homes every axis ($H / G28; the drill's N): one Home button, not one
    #: per axis that would all do the same thing.
    homes_all_axes: bool = False
    #: The machine is sent G-code text as written (G-code files): a job's pen lines can be
    #: translated into its own pen commands.
    takes_gcode_text: bool = False
    #: Which of the dialect's machines have feed and rapid overrides (GRBL's real-time
    #: bytes and ``Ov:``): the window shows their controls, the API takes ``override``.
    overrides: Callable[[MachineProfile], bool] = lambda profile: False
    #: Which have work coordinate systems (G54…G59, ``G10 L20``): zero here, go to zero.
    work_systems: Callable[[MachineProfile], bool] = lambda profile: False


def _stage_session(
    model: MachineModel,
    link: Link,
    clock: Clock,
    profile: MachineProfile,
    period_ms: int,
    autotick: bool,
) -> MachineSession:
    return StageSession(model, link, clock, period_ms=period_ms, autotick=autotick)


def _usb3_session(
    model: MachineModel,
    link: Link,
    clock: Clock,
    profile: MachineProfile,
    period_ms: int,
    autotick: bool,
) -> MachineSession:
    return Usb3Session(
        model, link, clock, autotick=autotick, stop_command=profile.capabilities.stop_command
    )


def _drill_session(
    model: MachineModel,
    link: Link,
    clock: Clock,
    profile: MachineProfile,
    period_ms: int,
    autotick: bool,
) -> MachineSession:
    return DrillSession(model, link, clock, autotick=autotick)


def _gcode_session(
    model: MachineModel,
    link: Link,
    clock: Clock,
    profile: MachineProfile,
    period_ms: int,
    autotick: bool,
) -> MachineSession:
    if profile.gcode is None:
        raise ValueError(f"profile {profile.name!r} has no [gcode] table")
    session = GcodeSession(model, link, clock, profile.gcode, autotick=autotick)
    session.overrides.available = _grbl_board(profile)
    session.work.available = _grbl_board(profile)
    return session


def _grbl_board(profile: MachineProfile) -> bool:
    """A GRBL 1.1 board (its ``$J`` jogs say so): real-time overrides and G54…G59. The
    CoreXY plotter's and the winder's firmwares have neither."""
    return profile.gcode is not None and "$J" in profile.gcode.words


#: The emulated G-code machine for each kinematics a profile can name: the name of its
#: configuration in :mod:`protocol.emulator.gcode_firmware`.
GCODE_EMULATORS: dict[str, str] = {
    "corexy": "corexy_plotter_config",
    "cartesian": "grbl_plotter_config",
    "cylindrical": "string_art_config",
}


def _stage_emulator(clock: Clock, profile: MachineProfile) -> EmulatedDevice:
    from protocol.emulator.stage_firmware import StageConfig, StageFirmware

    return StageFirmware(clock, StageConfig(axes=len(profile.axes)))


def _usb3_emulator(clock: Clock, profile: MachineProfile) -> EmulatedDevice:
    from protocol.emulator.usb3_firmware import Usb3Firmware

    return Usb3Firmware(clock)


def _drill_emulator(clock: Clock, profile: MachineProfile) -> EmulatedDevice:
    """The plotter with the profile's X/Y travel in microsteps (the host's own conversion).

    And with the profile's timing constants ([timing], FIDELITY S2-06).
    """
    from protocol.emulator.drill_firmware import DrillConfig, DrillFirmware

    x, y = profile.axes[0], profile.axes[1]
    travel = tuple(round(a.travel * a.steps_per_rev * a.microsteps / a.lead) for a in (x, y))
    config = DrillConfig.with_timing(profile.drill_timing, travel=(travel[0], travel[1]))
    return DrillFirmware(clock, config)


def _gcode_emulator(clock: Clock, profile: MachineProfile) -> EmulatedDevice:
    from protocol.emulator import gcode_firmware

    kinematics = profile.gcode.kinematics if profile.gcode is not None else "cartesian"
    config: Callable[[], gcode_firmware.GcodeConfig] = getattr(
        gcode_firmware, GCODE_EMULATORS[kinematics]
    )
    return gcode_firmware.GcodeFirmware(clock, config())


_ENTRIES = (
    Dialect("stage", _stage_session, StageSession, _stage_emulator),
    Dialect("usb3", _usb3_session, Usb3Session, _usb3_emulator),
    Dialect(
        "drill",
        _drill_session,
        DrillSession,
        _drill_emulator,
        homes_all_axes=True,
    ),
    Dialect(
        "gcode",
        _gcode_session,
        GcodeSession,
        _gcode_emulator,
        homes_all_axes=True,
        takes_gcode_text=True,
        overrides=_grbl_board,
        work_systems=_grbl_board,
    ),
)

#: Dialect name (a profile's ``dialect``) → its entry.
DIALECTS: dict[str, Dialect] = {entry.name: entry for entry in _ENTRIES}


def dialect_for(profile: MachineProfile) -> Dialect:
    try:
        return DIALECTS[profile.dialect]
    except KeyError:
        raise ValueError(f"the {profile.dialect!r} dialect is not supported yet") from None
