"""The stage's stored parameters, as blocking calls of :class:`~app.scripting.machine.Machine`.

They are one seam of the Machine's surface (read, write, undo, snapshot,
diff, restore) and share nothing with its motion calls but the way an
operation is driven, so they live apart and the Machine inherits them.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import TYPE_CHECKING, TypeVar, cast

from app.scripting import parameters as params
from app.scripting.errors import StepdeckError

if TYPE_CHECKING:
    from app.scripting.operations import Operations
    from app.scripting.waits import MachinePort, Operation
    from app.station import Station

T = TypeVar("T")


class StageParameterCalls:
    """Read, write, undo, save, diff and load the stage's stored parameters."""

    station: Station
    operations: Operations

    def _drive(self, operation: Operation[T]) -> T:
        """The Machine pumps an operation's waits until it ends (its own clock and timeout)."""
        raise NotImplementedError

    def read_parameters(self, *, timeout: float = 10.0) -> dict[str, dict[str, float]]:
        """Every stored parameter of every axis, freshly read (``{"X": {"fast_speed": 10.0}}``).

        Values are in the units the Dynamics page shows (mm, mm/s, mm/s², counts).
        """
        return self._drive(self.operations.read_parameters(timeout))

    def write_parameters(
        self, values: Mapping[str, Mapping[str, float]], *, timeout: float = 10.0
    ) -> dict[str, dict[str, float]]:
        """Write parameters, each verified by the device's answer; returns what was written.

        Raises :class:`~app.scripting.errors.ParameterRefused` naming every
        refusal (the station's or the device's, with the value it keeps) after
        trying all of them.  :meth:`undo_last_write` puts back what was there.
        """
        return self._drive(self.operations.write_parameters(values, timeout))

    def undo_last_write(self, *, timeout: float = 10.0) -> dict[str, dict[str, float]]:
        """Write back the values the last :meth:`write_parameters` replaced."""
        ops = self.operations
        if not ops.undo:
            raise StepdeckError("no parameter write to undo")
        previous, ops.undo = ops.undo, None
        result = self._drive(self.operations.write_parameters(previous, timeout, remember=False))
        return result

    def save_parameters(self, path: str | Path, *, timeout: float = 10.0) -> Path:
        """Save every stored parameter to a TOML snapshot (machine, firmware, date)."""
        values = self.read_parameters(timeout=timeout)
        self._drive(params.read_firmware(cast("MachinePort", self), timeout))
        return params.save_snapshot(Path(path), self.station, values)

    def parameter_diff(
        self, path: str | Path, *, other_machine: bool = False, timeout: float = 10.0
    ) -> list[params.Difference]:
        """What loading a snapshot would change: the parameters that differ from the device."""
        snapshot = params.load_snapshot(Path(path))
        params.check_machine(snapshot, self.station.profile, other_machine=other_machine)
        return params.diff(snapshot, self.read_parameters(timeout=timeout))

    def load_parameters(
        self, path: str | Path, *, other_machine: bool = False, timeout: float = 10.0
    ) -> list[params.Difference]:
        """Write what differs between a snapshot and the device, each write verified.

        Another machine's snapshot is refused unless ``other_machine=True``.
        Returns the differences written; refusals raise ParameterRefused after
        every write was tried.  :meth:`undo_last_write` reverts it.
        """
        differences = self.parameter_diff(path, other_machine=other_machine, timeout=timeout)
        changes: dict[str, dict[str, float]] = {}
        for difference in differences:
            if difference.writable:
                changes.setdefault(difference.axis, {})[difference.name] = difference.wanted
        if changes:
            self.write_parameters(changes, timeout=timeout)
        return [d for d in differences if d.writable]
