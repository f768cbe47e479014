"""A serial line's speed for a pseudo-terminal, which has none of its own.

A pty moves bytes as fast as the processes at both ends allow, so streaming
figures measured on one say nothing about a 115200-baud cable.  With
``--baud`` the emulator takes host bytes off the pty no faster than a UART
would deliver them (10 bits a byte: start, 8 data, stop) and hands its
replies back at the same pace, so the receive buffer fills and drains as on
the real board and a sender's throughput can be read as a share of the wire.
"""

from __future__ import annotations

#: Bits on the wire per byte: one start bit, eight data bits, one stop bit.
BITS_PER_BYTE = 10
#: Bytes the wire may owe when nobody used it for a while (a UART's FIFO, not a burst).
MAX_CREDIT_BYTES = 16


class PacedWire:
    """Byte credit in each direction at ``baud / 10`` bytes a second of real time."""

    def __init__(self, baud: int, now: float) -> None:
        if baud <= 0:
            raise ValueError("baud must be positive")
        self.bytes_per_s = baud / BITS_PER_BYTE
        self._to_device = _Credit(now)
        self._to_host = _Credit(now)

    def readable(self, now: float) -> int:
        """Host bytes the device may take off the line now."""
        return self._to_device.available(now, self.bytes_per_s)

    def took(self, count: int) -> None:
        self._to_device.spend(count)

    def writable(self, now: float) -> int:
        """Reply bytes the line can carry to the host now."""
        return self._to_host.available(now, self.bytes_per_s)

    def gave(self, count: int) -> None:
        self._to_host.spend(count)

    def wait_for_byte(self) -> float:
        """Seconds until one more byte fits, for the serving loop's select timeout."""
        return 1.0 / self.bytes_per_s


class _Credit:
    def __init__(self, now: float) -> None:
        self._bytes = 0.0
        self._at = now

    def available(self, now: float, rate: float) -> int:
        self._bytes = min(self._bytes + (now - self._at) * rate, MAX_CREDIT_BYTES)
        self._at = now
        return int(self._bytes)

    def spend(self, count: int) -> None:
        self._bytes -= count
