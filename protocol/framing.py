"""What every dialect's reader shares: rejected bytes, and a buffering, counting line reader.

Each codec knows its own messages and terminator; how a byte stream is cut
into them, how garbage is dropped and counted, and how an over-long run is
discarded once rather than per byte is the same for all of them.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Generic, TypeVar

_M = TypeVar("_M")


@dataclass(frozen=True, slots=True)
class Rejected:
    """Bytes that did not form a message, with the reason (for counters and the log)."""

    raw: bytes
    reason: str


#: ``(used, result)``: ``used == 0`` means "need more"; ``result`` None means only
#: separators were skipped.
DecodeResult = tuple[int, _M | Rejected | None]


class LineDecoder(Generic[_M]):
    """Stateful reader for a byte stream: buffers, resynchronises on the terminator, counts.

    A run of garbage too long to be a message is rejected once and then
    discarded up to and including its terminator, so however long it is, it
    costs one reject (and the device one error reply), like any other bad line.
    """

    def __init__(
        self, decode: Callable[[bytes | bytearray], DecodeResult[_M]], terminator: bytes
    ) -> None:
        self._decode = decode
        self._terminator = terminator
        self._buffer = bytearray()
        self._discarding = False
        self.messages = 0
        self.rejected = 0
        self.last_rejected: Rejected | None = None

    def feed(self, data: bytes) -> list[_M | Rejected]:
        """Decode everything complete in ``data``; rejected bytes are returned too."""
        self._buffer += data
        results: list[_M | Rejected] = []
        while self._buffer:
            if self._discarding and not self._discard():
                break
            used, result = self._decode(self._buffer)
            if used == 0:
                break
            del self._buffer[:used]
            if isinstance(result, Rejected):
                self.rejected += 1
                self.last_rejected = result
                self._discarding = result.raw[-1:] != self._terminator
            elif result is not None:
                self.messages += 1
            if result is not None:
                results.append(result)
        return results

    def _discard(self) -> bool:
        """Drop the rest of an over-long run; True once its terminator has gone too."""
        end = self._buffer.find(self._terminator)
        if end < 0:
            self._buffer.clear()
            return False
        del self._buffer[: end + 1]
        self._discarding = False
        return True

    def reset(self) -> None:
        """Forget a partial line, e.g. after the link was reopened."""
        self._buffer.clear()
        self._discarding = False
