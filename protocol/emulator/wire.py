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

    def readable(self, now: float, waiting: int = 0) -> int:
        """Host bytes the device may take off the line now.

        ``waiting``: bytes that were left on the line when bytes were last taken; the
        line has been carrying them since, so their time counts in full however
        long ago that was (the serving loop need not wake for every byte).
        """
        return self._to_device.available(now, self.bytes_per_s, waiting)

    def took(self, count: int) -> None:
        self._to_device.spend(count)

    def writable(self, now: float, waiting: int = 0) -> int:
        """Reply bytes the line can carry to the host now (``waiting``: as for readable)."""
        return self._to_host.available(now, self.bytes_per_s, waiting)

    def gave(self, count: int) -> None:
        self._to_host.spend(count)

    def wait_for_byte(self) -> float:
        """Seconds until one more byte fits, for the serving loop's select timeout."""
        return 1.0 / self.bytes_per_s

    def reply_wait(self, now: float, count: int) -> float:
        """Seconds until ``count`` reply bytes (all of them waiting) can have been carried."""
        short = count - self._to_host.peek(now, self.bytes_per_s, count)
        return max(short, 0) / self.bytes_per_s


class _Credit:
    def __init__(self, now: float) -> None:
        self._bytes = 0.0
        self._at = now

    def available(self, now: float, rate: float, waiting: int = 0) -> int:
        self._bytes = self.peek(now, rate, waiting)
        self._at = now
        return int(self._bytes)

    def peek(self, now: float, rate: float, waiting: int = 0) -> float:
        return min(self._bytes + (now - self._at) * rate, MAX_CREDIT_BYTES + waiting)

    def spend(self, count: int) -> None:
        self._bytes -= count
