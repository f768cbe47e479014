"""The face every emulated firmware shows to a transport."""

from __future__ import annotations

from collections.abc import Callable
from typing import Protocol


class EmulatedDevice(Protocol):
    """A device that consumes host bytes and produces reply bytes on its own clock.

    Implementations are thread-safe: the loopback's ticker thread runs them
    while the GUI thread flips emulator controls.
    """

    def set_output(self, sink: Callable[[bytes], None] | None) -> None:
        """Where reply bytes go (called from whichever thread runs the device)."""

    def receive(self, data: bytes) -> None:
        """Bytes from the host, handled in the next control cycle."""

    def run_until(self, t: float) -> None:
        """Run control cycles up to clock time ``t``."""
