"""Which G-code lines may go out now: ping-pong or character counting (docs/protocols.md §4).

A board acknowledges every line, in order, with ``ok`` or ``error:<n>``, and
drops bytes that do not fit its receive buffer.  Ping-pong waits for each
acknowledgement before the next line; character counting keeps the buffer
full, which keeps the board's planner fed on short segments, by sending
while the bytes of the unacknowledged lines stay below the buffer's size.

Pure bookkeeping, no I/O and no clock: the session writes what
:meth:`LineStreamer.sendable` hands out and calls
:meth:`LineStreamer.acknowledge` for every ``ok`` and ``error`` it reads, so
the same logic serves the real link, the emulator and the tests.
"""

from __future__ import annotations

import enum
from collections import deque
from typing import Generic, TypeVar

from protocol.gcode.codec import RX_BUFFER, TERMINATOR

T = TypeVar("T")


class StreamMode(enum.Enum):
    COUNTING = "counting"
    PING_PONG = "ping-pong"


class LineStreamer(Generic[T]):
    """Queued and in-flight lines, each with the caller's ``tag`` (e.g. a job's operation).

    In COUNTING mode at most ``rx_buffer - 1`` bytes are ever unacknowledged:
    GRBL's ring buffer keeps one slot empty, so a full 128 would overflow it.

    ``spare_line``: keep room for one more copy of the longest line in flight
    besides.  No wire here has a checksum, and a line that arrives twice (a
    repeating adapter) or an answer that does (``ok`` twice: the count one line
    short) puts that many bytes more in the board than counted; a buffer filled
    to the byte then overflows, and a line glued from two halves may run (relay
    corexy-plotter seeds 19, 61, 85: a stroke not in the job).  With the room
    kept, one such fault overflows nothing: the board holds more than counted,
    which its ``Bf:`` shows, or it answers one line more than it was sent.  A
    line goes anyway when nothing is in flight (it must go some time).
    """

    def __init__(
        self, mode: StreamMode, rx_buffer: int = RX_BUFFER, *, spare_line: bool = False
    ) -> None:
        if rx_buffer < 2:
            raise ValueError(f"a receive buffer holds at least one line byte, got {rx_buffer}")
        self.mode = mode
        self.rx_buffer = rx_buffer
        self.spare_line = spare_line
        self._queued: deque[tuple[bytes, T]] = deque()
        self._in_flight: deque[tuple[bytes, T]] = deque()
        self._in_flight_bytes = 0

    @property
    def capacity(self) -> int:
        """Bytes that may be unacknowledged at once, and the longest line that can go."""
        return self.rx_buffer - 1

    def queue(self, line: bytes, tag: T) -> None:
        """Add an encoded line (ending in ``\\n``) behind the others.

        A line that could never fit the board's buffer is refused here rather
        than left to block the queue forever.
        """
        if not line.endswith(TERMINATOR):
            raise ValueError(f"an encoded line ends with \\n: {line!r}")
        if len(line) > self.capacity:
            raise ValueError(
                f"a line of {len(line)} bytes never fits a {self.rx_buffer}-byte receive buffer"
            )
        self._queued.append((line, tag))

    def sendable(self) -> list[tuple[bytes, T]]:
        """Take every queued line that may go out now; they count as in flight from here."""
        out: list[tuple[bytes, T]] = []
        queued, in_flight, capacity = self._queued, self._in_flight, self.capacity
        ping_pong = self.mode is StreamMode.PING_PONG
        # The longest line in flight, worked out once a call (a job asks for every answer).
        longest = max((len(line) for line, _ in in_flight), default=0) if self.spare_line else 0
        while queued:
            length = len(queued[0][0])
            if ping_pong:
                if in_flight:
                    break
            elif self._in_flight_bytes + length > capacity:
                break
            elif self.spare_line and in_flight and self._over_spare(length, longest):
                break
            entry = queued.popleft()
            in_flight.append(entry)
            self._in_flight_bytes += length
            longest = max(longest, length)
            out.append(entry)
        return out

    def _over_spare(self, length: int, longest: int) -> bool:
        """Whether a line of ``length`` bytes leaves no room for a copy of the longest
        (``longest``: of the lines in flight)."""
        return self._in_flight_bytes + length + max(length, longest) > self.capacity

    def acknowledge(self) -> tuple[bytes, T] | None:
        """The oldest line in flight, now acknowledged; None for an ``ok`` nobody waited for."""
        if not self._in_flight:
            return None
        entry = self._in_flight.popleft()
        self._in_flight_bytes -= len(entry[0])
        return entry

    def unanswered_tags(self) -> list[T]:
        """The tags of the lines sent and not yet answered, oldest first."""
        return [tag for _, tag in self._in_flight]

    def unanswered_lengths(self) -> list[int]:
        """The bytes of each line sent and not yet answered, oldest first."""
        return [len(raw) for raw, _ in self._in_flight]

    @property
    def in_flight_bytes(self) -> int:
        return self._in_flight_bytes

    @property
    def in_flight(self) -> int:
        return len(self._in_flight)

    @property
    def queued(self) -> int:
        return len(self._queued)

    @property
    def idle(self) -> bool:
        """Nothing waits to go and nothing waits for its acknowledgement."""
        return not self._queued and not self._in_flight

    def clear(self) -> list[T]:
        """Forget everything, e.g. after a soft reset emptied the board's buffers.

        The tags come back oldest first: those in flight, then those queued.
        """
        tags = [tag for _, tag in self._in_flight] + [tag for _, tag in self._queued]
        self._in_flight.clear()
        self._queued.clear()
        self._in_flight_bytes = 0
        return tags

    def discard_queued(self) -> list[T]:
        """Drop the lines not yet sent (oldest first); those in flight still await their replies."""
        tags = [tag for _, tag in self._queued]
        self._queued.clear()
        return tags
