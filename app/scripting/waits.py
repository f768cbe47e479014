"""One operation of the API as a generator of waits, run blocking or awaited.

Each operation sends its intent, then *yields* what it waits for; the
blocking form pumps the station until the wait is over, the asyncio form
awaits between pumps.  So both forms share one implementation, and a
failure seen while waiting (an end switch, a lost link) is raised by the
wait's condition itself, in the caller's frame.
"""

from __future__ import annotations

from collections.abc import Callable, Generator
from contextlib import AbstractContextManager
from dataclasses import dataclass
from typing import Protocol, TypeVar

from app.profiles import MachineProfile
from app.station import Station

T = TypeVar("T")


@dataclass
class Wait:
    """Pump until ``until()`` is true; it may raise to end the wait with the device's reason."""

    until: Callable[[], bool]
    timeout: float
    #: What is awaited, for the timeout's message ("X to reach 10.000 mm").
    what: str
    #: A motion is awaited: when the time is up, the machine is stopped before the raise.
    motion: bool = True
    #: The error raised when the time is up, instead of the generic one.
    on_timeout: Callable[[], Exception] | None = None


Operation = Generator[Wait, None, T]


class MachinePort(Protocol):
    """What the API's parameter and job modules need of a machine (so they need not import it)."""

    @property
    def station(self) -> Station: ...

    @property
    def profile(self) -> MachineProfile: ...

    def axis_index(self, name: str) -> int:
        """The axis called ``name`` (any case); MotionRefused naming the axes if none is."""
        ...

    def explained(self) -> AbstractContextManager[list[str]]:
        """The station's messages said while the block runs (a refusal's reason)."""
        ...

    def check_link(self) -> None:
        """Raise LinkLost when the link is down."""
        ...
