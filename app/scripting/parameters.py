"""Stored device parameters for scripts and snapshots: read, verified writes, TOML files, diffs.

The stage keeps its dynamics, currents and mechanics per axis (docs/protocols.md
§1.4).  A snapshot saves all of them with the machine, its firmware and the
date, so a restore can first show what differs and write only that: a
blind restore of another machine's settings has broken machines before
(a grblHAL restore, the UGS settings import).

Values are in the units the Dynamics page shows; the wire's integers are
got back with the parameter table's own scale, so a value read, saved and
restored is written as the very integer that was read.
"""

from __future__ import annotations

import json
import tomllib
from collections.abc import Mapping
from dataclasses import dataclass
from datetime import UTC, datetime
from pathlib import Path
from typing import Any, Protocol

from app.machine import MachineModel, ParameterState
from app.machines.stage.parameters import BY_TYPE, STAGE_PARAMETERS, StageParameter
from app.machines.stage.session import StageSession
from app.profiles import MachineProfile
from app.scripting.errors import ParameterRefused, StepdeckError, Unsupported, WrongMachine
from app.scripting.waits import MachinePort, Operation, Wait
from app.station import Station
from protocol.stage.codec import PARAMETERS, Subscriber

#: The snapshot format's version, written into every file.
SNAPSHOT_FORMAT = 1
#: A snapshot is a few kilobytes; a larger file is not one.
MAX_SNAPSHOT_BYTES = 256 * 1024

BY_NAME: dict[str, StageParameter] = {p.type.name.lower(): p for p in STAGE_PARAMETERS}


def name_of(parameter: StageParameter) -> str:
    return parameter.type.name.lower()


def shown(parameter: StageParameter, wire: int) -> float:
    value = parameter.to_shown(wire)
    return int(value) if parameter.scale == 1 else value


def values_of(model: MachineModel) -> dict[str, dict[str, float]]:
    """Every parameter the model holds a value for, per axis name, in shown units."""
    out: dict[str, dict[str, float]] = {}
    for index, axis in enumerate(model.axes):
        row: dict[str, float] = {}
        for parameter in STAGE_PARAMETERS:
            value = model.parameter(index, parameter.type).value
            if value is not None:
                row[name_of(parameter)] = shown(parameter, value)
        out[axis.name] = row
    return out


def _stage(machine: MachinePort) -> Any:
    session = machine.station.session_as(StageSession)
    if session is None:
        raise Unsupported(f"{machine.profile.title} has no stored parameters the station reads")
    return session


def read_all(machine: MachinePort, timeout: float) -> Operation[None]:
    """Ask every parameter of every axis again; wait until each one has answered."""
    session = _stage(machine)
    model = machine.station.model
    waiting = {(axis, int(p)) for axis in range(len(model.axes)) for p in PARAMETERS}

    def heard(axis: int, parameter: int) -> None:
        waiting.discard((axis, parameter))

    model.parameterChanged.connect(heard)
    try:
        session.read_all_parameters()
        yield Wait(lambda: not waiting, timeout, "reading the parameters", motion=False)
    finally:
        model.parameterChanged.disconnect(heard)


def write(
    machine: MachinePort, values: Mapping[str, Mapping[str, float]], timeout: float
) -> Operation[dict[str, dict[str, float]]]:
    """Write each value and wait for the device's verdict; refusals raise after all were tried."""
    session = _stage(machine)
    model = machine.station.model
    refusals: list[str] = []
    pending: list[tuple[int, StageParameter, int]] = []
    for axis_name, row in values.items():
        axis = machine.axis_index(axis_name)
        for key, value in row.items():
            parameter = BY_NAME.get(key.lower())
            if parameter is None:
                refusals.append(f"{axis_name} {key}: no such parameter ({', '.join(BY_NAME)})")
                continue
            if not parameter.writable:
                refusals.append(f"{axis_name} {parameter.label}: read-only")
                continue
            # The device judges its own ranges and says what it keeps (the session checks
            # only what the device cannot know: the mechanical travel).
            pending.append((axis, parameter, parameter.to_wire(float(value))))
    written: dict[str, dict[str, float]] = {}
    for axis, parameter, wire in pending:
        name = model.axes[axis].name
        with machine.explained() as heard:
            sent = session.write_parameter(axis, parameter.type, wire)
        if not sent:
            refusals.append("; ".join(heard) or f"{name} {parameter.label}: not written")
            continue

        def answered(axis: int = axis, parameter: StageParameter = parameter) -> bool:
            machine.check_link()
            return model.parameter(axis, parameter.type).state is not ParameterState.PENDING

        yield Wait(answered, timeout, f"{name} {parameter.label} to be confirmed", motion=False)
        entry = model.parameter(axis, parameter.type)
        if entry.state is ParameterState.CONFIRMED:
            written.setdefault(name, {})[name_of(parameter)] = shown(parameter, wire)
        else:
            kept = "?" if entry.value is None else f"{shown(parameter, entry.value):g}"
            refusals.append(
                f"{name} {parameter.label}: the device refused {shown(parameter, wire):g} "
                f"and keeps {kept} {parameter.unit}".rstrip()
            )
    if refusals:
        raise ParameterRefused("; ".join(refusals), written)
    return written


def read_firmware(machine: MachinePort, timeout: float) -> Operation[None]:
    """Have the stage report its firmware version (a subscriber asked for once)."""
    session = _stage(machine)
    model = machine.station.model
    plotted = session.subscribers.plotted
    model.telemetry.pop("firmware_version", None)
    session.set_plotted_subscriber(Subscriber.FIRMWARE_VERSION)
    try:
        yield Wait(
            lambda: "firmware_version" in model.telemetry,
            timeout,
            "the firmware version",
            motion=False,
        )
    finally:
        session.set_plotted_subscriber(plotted)


# --- snapshots ------------------------------------------------------------------------


@dataclass(frozen=True)
class Snapshot:
    profile: str
    title: str
    firmware: str
    date: str
    values: dict[str, dict[str, float]]


@dataclass(frozen=True)
class Difference:
    """One parameter whose snapshot value is not the device's."""

    axis: str
    name: str
    label: str
    unit: str
    device: float | None
    wanted: float
    writable: bool

    def __str__(self) -> str:
        now = "—" if self.device is None else f"{self.device:g}"
        note = "" if self.writable else " (read-only, not written)"
        return f"{self.axis} {self.label}: {now} → {self.wanted:g} {self.unit}".rstrip() + note


def firmware_of(station: Station) -> str:
    value = station.model.telemetry.get("firmware_version")
    if value is None:
        return "unknown"
    number = round(value)  # 010200 is 1.2.0 (docs/protocols.md §1.5)
    return f"{number // 10000}.{number // 100 % 100}.{number % 100}"


def save_snapshot(path: Path, station: Station, values: Mapping[str, Mapping[str, float]]) -> Path:
    """Write the snapshot as TOML (strings quoted as JSON, which TOML reads the same)."""
    profile = station.profile
    lines = [
        "# StepDeck device-parameter snapshot: stepdeck load_parameters / the Dynamics page",
        f"format = {SNAPSHOT_FORMAT}",
        "",
        "[machine]",
        f"profile = {json.dumps(profile.name)}",
        f"title = {json.dumps(profile.title)}",
        f"firmware = {json.dumps(firmware_of(station))}",
        f"date = {json.dumps(datetime.now(UTC).isoformat(timespec='seconds'))}",
    ]
    for axis, row in values.items():
        lines += ["", f"[axes.{json.dumps(axis)}]"]
        for name, value in row.items():
            if BY_NAME[name].writable:  # the encoder is a position, not a setting
                lines.append(f"{name} = {value!r}")
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def read_snapshot_file(path: Path, what: str) -> dict[str, Any]:
    """A snapshot file's TOML (``what``: "parameter", "settings"), or the reason it is none.

    Shared with the stored settings' snapshots (:mod:`app.scripting.settings_snapshot`).
    """
    try:
        if path.stat().st_size > MAX_SNAPSHOT_BYTES:
            raise StepdeckError(f"{path}: too large for a {what} snapshot")
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, tomllib.TOMLDecodeError) as exc:
        raise StepdeckError(f"{path}: not a readable snapshot ({exc})") from None


def load_snapshot(path: Path) -> Snapshot:
    """Read a snapshot; a file that is not one is refused with the reason."""
    data = read_snapshot_file(path, "parameter")
    machine = data.get("machine")
    axes = data.get("axes")
    if data.get("format") != SNAPSHOT_FORMAT or not isinstance(machine, dict):
        raise StepdeckError(f"{path}: not a StepDeck parameter snapshot (format {SNAPSHOT_FORMAT})")
    if not isinstance(axes, dict):
        raise StepdeckError(f"{path}: no [axes] in the snapshot")
    values: dict[str, dict[str, float]] = {}
    for axis, row in axes.items():
        if not isinstance(row, dict):
            raise StepdeckError(f"{path}: [axes.{axis}] is not a table")
        for name, value in row.items():
            if name not in BY_NAME:
                raise StepdeckError(f"{path}: {axis} {name} is no parameter")
            if isinstance(value, bool) or not isinstance(value, int | float):
                raise StepdeckError(f"{path}: {axis} {name} = {value!r} is not a number")
        values[str(axis)] = {str(k): float(v) for k, v in row.items()}
    return Snapshot(
        profile=str(machine.get("profile", "")),
        title=str(machine.get("title", "")),
        firmware=str(machine.get("firmware", "unknown")),
        date=str(machine.get("date", "")),
        values=values,
    )


class OfMachine(Protocol):
    """A snapshot's machine (a parameter or a settings snapshot)."""

    @property
    def profile(self) -> str: ...

    @property
    def title(self) -> str: ...


def check_machine(snapshot: OfMachine, profile: MachineProfile, *, other_machine: bool) -> None:
    """Another machine's snapshot is refused unless ``other_machine``."""
    if snapshot.profile != profile.name and not other_machine:
        raise WrongMachine(
            f"the snapshot is of {snapshot.title or snapshot.profile!r}, this is "
            f"{profile.title}; pass other_machine=True to load it anyway"
        )


def diff(snapshot: Snapshot, device: Mapping[str, Mapping[str, float]]) -> list[Difference]:
    """The parameters whose snapshot value differs from the device's, in table order."""
    out: list[Difference] = []
    for axis, row in snapshot.values.items():
        here = device.get(axis)
        if here is None:
            raise StepdeckError(f"the snapshot has an axis {axis} this machine does not")
        for parameter in STAGE_PARAMETERS:
            name = name_of(parameter)
            if name not in row:
                continue
            wanted = row[name]
            now = here.get(name)
            if now is not None and parameter.to_wire(now) == parameter.to_wire(wanted):
                continue
            out.append(
                Difference(
                    axis,
                    name,
                    parameter.label,
                    parameter.unit,
                    now,
                    wanted,
                    parameter.writable and parameter.type in BY_TYPE,
                )
            )
    return out
