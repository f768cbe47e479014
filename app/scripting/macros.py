"""``machine.macros()`` and ``machine.run_macro(name)``: the window's macro buttons, from a script.

The macros are those the window keeps for the machine's profile (the
station's settings file, or one the script names); a script may also run a
snippet of its own by giving ``code``.  A run is refused exactly as the
macro bar refuses it (``macro "Park":2: X 900 is outside the travel 0…300``),
before a byte is sent, and otherwise runs as a job does
(:func:`~app.scripting.job.run_program`): progress, prompts and a lost link
answered the same way.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

from PySide6.QtCore import QSettings

from app.jobs.run.runner import JobRunner
from app.macros.machines import macros_available
from app.macros.runner import MacroRefused, macro_checkpoint_dir, prepare_macro
from app.macros.store import Macro, MacroError, MacroStore, checked_macro, find
from app.scripting.errors import JobRefused, Unsupported
from app.scripting.job import JobResult, run_program
from app.scripting.waits import MachinePort, Operation
from app.settings import StationSettings, default_settings


def kept_macros(profile: str, settings: str | Path | None = None) -> list[Macro]:
    """``profile``'s macros from the window's settings (``settings``: an INI file instead)."""
    store = QSettings(str(settings), QSettings.Format.IniFormat) if settings else None
    return MacroStore(StationSettings(store or default_settings()), profile).load()


def macro_table(profile: str, settings: str | Path | None = None) -> dict[str, str]:
    return {macro.name: macro.code for macro in kept_macros(profile, settings)}


def run_macro(
    machine: MachinePort,
    name: str,
    *,
    code: str | None = None,
    settings: str | Path | None = None,
    options: Mapping[str, Any] | None = None,
) -> Operation[JobResult]:
    """Run the kept macro ``name`` (or ``code`` under that name); JobRefused says why not."""
    station = machine.station
    if not macros_available(station.profile):
        raise Unsupported(f"{station.profile.title} takes no G-code macros")
    if code is None:
        macro = find(kept_macros(station.profile.name, settings), name)
        if macro is None:
            raise JobRefused(f"no macro {name!r} is kept for {station.profile.name}")
    else:
        try:
            macro = checked_macro(name, code)
        except MacroError as exc:
            raise JobRefused(f"macro {name!r}: {exc}") from None
    checkpoints = macro_checkpoint_dir()
    checker = JobRunner(station, checkpoints)
    try:
        program, _ = prepare_macro(station, checker, macro)
    except MacroRefused as exc:
        raise JobRefused(str(exc)) from None
    finally:
        checker.deleteLater()
    return run_program(
        machine, program, resume=False, checkpoint_dir=checkpoints, **dict(options or {})
    )
