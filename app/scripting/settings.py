"""``machine.settings()``: a device's stored settings for scripts, read, written, saved, restored.

GRBL's ``$N`` and the usb3 unit's EEPROM values go through
:class:`~app.machines.settings_access.SettingsAccess`, the object the
Settings page uses: the same checks before anything is sent, the same
read-back after.  A refusal raises :class:`~app.scripting.errors.SettingRefused`
with every reason; nothing of a refused write reaches the wire.
"""

from __future__ import annotations

import warnings
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import TypeVar

from app.machines.settings_access import Outcome, SettingsAccess
from app.scripting import settings_snapshot as snapshots
from app.scripting.errors import SettingRefused, Unsupported
from app.scripting.settings_snapshot import SettingDifference
from app.scripting.waits import MachinePort, Operation, Wait
from app.stored_access import settings_access

T = TypeVar("T")
#: How long a write waits for the board to settle (the answer to a line just sent).
SETTLE_S = 3.0


def access_of(machine: MachinePort) -> SettingsAccess:
    access = settings_access(machine.station.session)
    if access is None:
        raise Unsupported(
            f"{machine.profile.title} keeps no settings the station edits "
            "(the stage's stored parameters: read_parameters)"
        )
    return access


def run(machine: MachinePort, access: SettingsAccess, start: Callable[[], str | None],
        what: str, timeout: float) -> Operation[Outcome]:  # fmt: skip
    """Wait for a quiet moment (a little), start, wait for the device; the outcome or a raise."""
    clock = machine.station.clock
    settle_until = clock.now() + min(SETTLE_S, timeout)
    yield Wait(
        lambda: access.why_not_now() is None or clock.now() > settle_until,
        SETTLE_S + 1,
        "a quiet moment",
        motion=False,
    )
    refusal = start()
    if refusal is not None:
        raise SettingRefused(refusal)

    def done() -> bool:
        machine.check_link()
        return access.busy is None

    yield Wait(done, timeout, what, motion=False)
    outcome = access.last
    assert outcome is not None
    if not outcome.ok:
        raise SettingRefused("; ".join(outcome.refusals), outcome.values)
    return outcome


def read(machine: MachinePort, timeout: float) -> Operation[dict[str, float]]:
    """Every setting, freshly read."""
    access = access_of(machine)
    yield from run(machine, access, access.read, "the settings", timeout)
    return dict(access.values)


def write(
    machine: MachinePort, changes: Mapping[str, float], timeout: float
) -> Operation[dict[str, float]]:
    """Write ``changes`` and read them back; the values the device kept as written."""
    access = access_of(machine)
    outcome = yield from run(
        machine,
        access,
        lambda: access.write(changes),
        "the settings to be written and read back",
        timeout,
    )
    return outcome.values


class MachineSettings:
    """The stored settings of a connected machine, as last read (see :meth:`read`).

    ``values`` maps each key (``"$110"``, ``"X.thread"``) to its number.
    """

    def __init__(
        self,
        machine: MachinePort,
        drive: Callable[[Operation[dict[str, float]]], dict[str, float]],
        timeout: float,
    ) -> None:
        self._machine = machine
        self._drive = drive
        self.timeout = timeout
        self.access = access_of(machine)

    @property
    def values(self) -> dict[str, float]:
        return dict(self.access.values)

    @property
    def kind(self) -> str:
        """``"grbl"`` or ``"usb3-eeprom"``: what a snapshot of them is of."""
        return self.access.kind

    def __getitem__(self, key: str) -> float:
        return self.access.values[key]

    def describe(self, key: str) -> str:
        """The setting's name, unit, range and meaning, in the station's language."""
        spec = self.access.by_key[key]
        unit = f" [{spec.shown_unit()}]" if spec.unit else ""
        allowed = (
            " | ".join(f"{n} = {spec.shown_value(n)}" for n, _ in spec.choices)
            if spec.choices
            else f"{spec.low:g}…{spec.high:g}"
        )
        return f"{key} {spec.shown_label()}{unit}, {allowed}: {spec.shown_description()}"

    def read(self, *, timeout: float | None = None) -> dict[str, float]:
        """Every setting, freshly read from the device."""
        return self._drive(read(self._machine, self._t(timeout)))

    def write(
        self, changes: Mapping[str, float], *, timeout: float | None = None
    ) -> dict[str, float]:
        """Write ``changes`` (checked whole first), then read back; returns what was written.

        Raises SettingRefused with every reason when the station refuses the write
        (nothing is sent), or when the device refused or reads back a value otherwise.
        """
        return self._drive(write(self._machine, changes, self._t(timeout)))

    def save(self, path: str | Path) -> Path:
        """Save the values last read to a TOML snapshot (read first: :meth:`read`)."""
        return snapshots.save_snapshot(Path(path), self._machine.profile, self.access)

    def diff(self, path: str | Path, *, other_machine: bool = False) -> list[SettingDifference]:
        """What loading the snapshot would change, against the values last read.

        A snapshot saved on another firmware version is not refused: a warning names
        both versions (a setting may mean something else on the other one).
        """
        snapshot = snapshots.load_snapshot(Path(path), self.access)
        snapshots.check_machine(snapshot, self._machine.profile, other_machine=other_machine)
        change = snapshots.firmware_change(snapshot, self.access)
        if change is not None:
            warnings.warn(
                f"{path}: saved on firmware {change[0]}, the device runs {change[1]}: "
                "check that each value means the same there",
                stacklevel=2,
            )
        return snapshots.diff(snapshot, self.access)

    def load(
        self, path: str | Path, *, other_machine: bool = False, timeout: float | None = None
    ) -> list[SettingDifference]:
        """Read the device, write what differs from the snapshot, read back; the differences.

        Another machine's snapshot is refused unless ``other_machine=True``.
        """
        self.read(timeout=timeout)
        differences = self.diff(path, other_machine=other_machine)
        if differences:
            self.write({d.key: d.wanted for d in differences}, timeout=timeout)
        return differences

    def _t(self, timeout: float | None) -> float:
        return self.timeout if timeout is None else timeout
