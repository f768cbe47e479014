"""What the poller needs of a gamepad library: the devices there, one opened, its reading.

The poller (:mod:`app.gamepad.poller`) and the tests' fakes speak only this; SDL is one
implementation (:mod:`app.gamepad.sdl`), imported only when the operator turns the
gamepad on, so a station without the ``gamepad`` extra never loads it.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Protocol

from app.gamepad.mapping import PadReading


class PadUnavailable(RuntimeError):
    """The gamepad library cannot be used here: not installed, or it does not load."""


@dataclass(frozen=True)
class PadDevice:
    """A device as found: the library's handle for it (valid until the next look) and its
    name, which is what the operator chooses and the settings keep."""

    index: int
    name: str


class PadSource(Protocol):
    """One library's view of the game controllers: every call is quick (no I/O wait)."""

    def devices(self) -> list[PadDevice]:
        """The devices attached now (also notices devices plugged in or out since)."""
        ...

    def open(self, device: PadDevice) -> bool:
        """Read ``device`` from now on (closing the one read so far); whether it opened."""
        ...

    def read(self) -> PadReading | None:
        """The opened device's sticks and enable button now; None once it is gone."""
        ...

    def close(self) -> None:
        """Stop reading the device (the library stays loaded)."""
        ...
