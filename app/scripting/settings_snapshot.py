"""Stored settings (GRBL's ``$$``, the usb3 unit's EEPROM) as TOML snapshots: save, diff, restore.

The same shape as the stage's parameter snapshots (:mod:`app.scripting.
parameters`): a format number, a ``[machine]`` table (profile, title, date)
so another machine's file is noticed before it is written, then the values,
one a line, each with its name as a comment::

    format = 1
    kind = "grbl"

    [machine]
    profile = "grbl-plotter"
    ...
    firmware = "1.1h.20190825"

    [settings]
    "$0" = 10  # Step pulse time [µs]
    "$110" = 6000.0  # X maximum rate [mm/min]

The file's reading, its format number and the machine check are the stage
snapshots' own (:func:`~app.scripting.parameters.read_snapshot_file`,
:func:`~app.scripting.parameters.check_machine`).  A restore writes only
what differs, through the same checks as any write
(:class:`~app.machines.settings_access.SettingsAccess`): a file edited by
hand to hold a value out of range is refused whole, with the reason.

``firmware`` is the version the device said it runs (GRBL's ``$I`` or
banner; absent where the device cannot say, as the usb3 unit).  A restore
onto a board that runs another version is not refused, but
:func:`firmware_change` names both: a setting may mean something else there.
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path

from app.machines.gcode.grbl_version import same_version
from app.machines.settings_access import SettingsAccess
from app.machines.stored_settings import Kind, StoredSetting
from app.profiles import MachineProfile
from app.scripting.errors import StepdeckError
from app.scripting.parameters import SNAPSHOT_FORMAT, read_snapshot_file
from app.scripting.parameters import check_machine as check_machine


@dataclass(frozen=True)
class SettingsSnapshot:
    kind: str
    profile: str
    title: str
    date: str
    values: dict[str, float]
    #: The firmware version the device said it ran when the snapshot was saved ("": unknown).
    firmware: str = ""


@dataclass(frozen=True)
class SettingDifference:
    """One setting whose snapshot value is not the device's."""

    key: str
    label: str
    unit: str
    device: float | None
    wanted: float
    spec: StoredSetting = field(repr=False, compare=False)

    def __str__(self) -> str:
        now = "—" if self.device is None else self.spec.shown_value(self.device)
        text = f"{self.key} {self.label}: {now} → {self.spec.shown_value(self.wanted)}"
        return f"{text} {self.unit}".rstrip()


def _number(spec: StoredSetting, value: float) -> str:
    return repr(float(value)) if spec.kind is Kind.DECIMAL else str(int(value))


def save_snapshot(path: Path, profile: MachineProfile, access: SettingsAccess) -> Path:
    """Write every value the device last said it holds; refused when one was never read."""
    missing = [spec.key for spec in access.specs if spec.key not in access.values]
    if missing:
        raise StepdeckError(
            f"not read yet: {', '.join(missing[:4])}{'…' if len(missing) > 4 else ''}"
        )
    lines = [
        "# StepDeck settings snapshot: Machine.load_settings / the Settings page",
        f"format = {SNAPSHOT_FORMAT}",
        f"kind = {json.dumps(access.kind)}",
        "",
        "[machine]",
        f"profile = {json.dumps(profile.name)}",
        f"title = {json.dumps(profile.title)}",
        f"date = {json.dumps(datetime.now(UTC).isoformat(timespec='seconds'))}",
    ]
    if access.firmware:
        lines.append(f"firmware = {json.dumps(access.firmware)}")
    lines += ["", "[settings]"]
    for spec in access.specs:
        label = spec.label.format(spec.axis) if spec.axis else spec.label
        unit = f" [{spec.unit}]" if spec.unit else ""
        value = access.values[spec.key]
        lines.append(f"{json.dumps(spec.key)} = {_number(spec, value)}  # {label}{unit}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def load_snapshot(path: Path, access: SettingsAccess) -> SettingsSnapshot:
    """Read a snapshot of ``access``'s kind; a file that is not one is refused with the reason."""
    data = read_snapshot_file(path, "settings")
    machine = data.get("machine")
    settings = data.get("settings")
    if data.get("format") != SNAPSHOT_FORMAT or not isinstance(machine, dict):
        raise StepdeckError(f"{path}: not a StepDeck settings snapshot (format {SNAPSHOT_FORMAT})")
    if data.get("kind") != access.kind:
        raise StepdeckError(
            f"{path}: a snapshot of {data.get('kind')!r} settings, this machine keeps "
            f"{access.kind!r} ones"
        )
    if not isinstance(settings, dict):
        raise StepdeckError(f"{path}: no [settings] in the snapshot")
    firmware = machine.get("firmware", "")
    if not isinstance(firmware, str):
        raise StepdeckError(f"{path}: firmware = {firmware!r} is not a version")
    values: dict[str, float] = {}
    for key, value in settings.items():
        if key not in access.by_key:
            raise StepdeckError(f"{path}: {key} is no setting of this machine")
        if isinstance(value, bool) or not isinstance(value, int | float):
            raise StepdeckError(f"{path}: {key} = {value!r} is not a number")
        values[key] = float(value)
    return SettingsSnapshot(
        kind=access.kind,
        profile=str(machine.get("profile", "")),
        title=str(machine.get("title", "")),
        date=str(machine.get("date", "")),
        values=values,
        firmware=firmware,
    )


def firmware_change(snapshot: SettingsSnapshot, access: SettingsAccess) -> tuple[str, str] | None:
    """(the snapshot's version, the device's) when both are known and differ, else None."""
    device = access.firmware
    if not snapshot.firmware or not device or same_version(snapshot.firmware, device):
        return None
    return snapshot.firmware, device


def diff(snapshot: SettingsSnapshot, access: SettingsAccess) -> list[SettingDifference]:
    """The settings whose snapshot value differs from what the device holds, in table order."""
    return differences(snapshot.values, access.values, access)


def differences(
    wanted: Mapping[str, float], held: Mapping[str, float], access: SettingsAccess
) -> list[SettingDifference]:
    out = []
    for spec in access.specs:
        if spec.key not in wanted:
            continue
        now = held.get(spec.key)
        if now is not None and spec.same(wanted[spec.key], now):
            continue
        out.append(
            SettingDifference(
                spec.key, spec.shown_label(), spec.shown_unit(), now, wanted[spec.key], spec
            )
        )
    return out
