"""The G-code streaming loop, run where the replies arrive: on the transport's reader thread.

Character counting keeps the board's receive buffer full only if the next
line goes out as soon as an ``ok`` frees room.  When that waited for the GUI
thread (a paint, a busy machine), a job of short lines ran at a fraction of
the wire.  So the bytes the transport reads are decoded here, on its reader
thread: every ``ok``/``error`` is matched to its line in the
:class:`~protocol.gcode.streaming.LineStreamer` (the ``ok`` accounting) and
the lines queued behind are written at once.  The GUI thread gets the
decoded replies, each with the line it answered, in batches; it keeps every
decision (job states, what to queue, pause, abort).

What keeps the machine from moving when nobody asked:

* only lines the GUI queued are ever sent, and one lock covers queueing,
  sending and taking back, so a pause or abort (which takes back the queue
  under the lock) stops the feeding at once;
* after an ``error`` or an ``ALARM`` nothing more is sent until the GUI
  thread has seen it (:meth:`LineFeeder.release`): a job that fails stops
  with nothing more written than before;
* after a soft reset nothing is sent until the board's banner (as before);
* the transport writes nothing once the link is closed.

Plain Python, no Qt; in tests on a manual clock the transport calls it on
the GUI thread itself, so everything stays synchronous.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Generic, TypeVar

from protocol.clock import Clock
from protocol.gcode.codec import AlarmReply, Banner, ErrorReply, Ok, Rejected, StatusReport
from protocol.gcode.streaming import LineStreamer

T = TypeVar("T")

#: After a soft reset, answers are dropped and lines held until the banner, this long at most.
BANNER_AFTER_RESET_S = 1.0


class Stale:
    """The verdict on an ``ok``/``error`` that came while a reset's banner was awaited."""


STALE = Stale()


@dataclass(frozen=True)
class Answer(Generic[T]):
    """The verdict on an ``ok``/``error``: the line it answers (None: a reply for no line)."""

    entry: tuple[bytes, T] | None


@dataclass(frozen=True)
class BannerSeen(Generic[T]):
    """The verdict on a banner: whether a reset of ours caused it, and the lines it lost."""

    ours: bool
    lost: list[T]


@dataclass
class Received(Generic[T]):
    """One read from the transport, as the GUI thread gets it."""

    data: bytes
    #: The decoded replies in order, each with its verdict: :class:`Answer`, :data:`STALE`,
    #: :class:`BannerSeen`, a status report's unanswered lines, or None.
    replies: list[tuple[object, object]] = field(default_factory=list)
    #: The lines written after these replies freed room, in order.
    written: list[tuple[bytes, T]] = field(default_factory=list)
    #: What went wrong reading these bytes (a bug, not the device's words): sending is held,
    #: as after an error, until the GUI thread has stopped the machine.
    failure: Exception | None = None


class LineFeeder(Generic[T]):
    """The streamer, the decoder and the sending, shared by the reader and the GUI thread."""

    def __init__(
        self,
        streamer: LineStreamer[T],
        decoder: object,
        clock: Clock,
        write: Callable[[bytes], None],
        write_here: Callable[[list[bytes]], None] | None = None,
    ) -> None:
        self.lock = threading.RLock()
        self.streamer = streamer
        self.decoder = decoder
        self.clock = clock
        self._write = write
        #: How :meth:`receive` writes the lines an answer let go, on the thread that read:
        #: all at once (default: one ``write`` each).
        self._write_here = write_here
        #: A soft reset was sent at this time and its banner has not come yet.
        self.reset_sent_at: float | None = None
        #: Errors and alarms read here that the GUI thread has not seen yet: nothing is
        #: sent while any is.  A count, not a flag: the GUI thread having seen the first
        #: must not let lines go past a second it has not seen.
        self.unseen = 0

    @property
    def halted(self) -> bool:
        """An error or alarm not yet seen by the GUI thread holds the sending."""
        return self.unseen > 0

    def reset_halt(self) -> None:
        """A fresh link: nothing from before it is waiting to be seen."""
        with self.lock:
            self.unseen = 0

    def awaiting_banner(self) -> bool:
        with self.lock:
            sent = self.reset_sent_at
            if sent is not None and self.clock.now() - sent > BANNER_AFTER_RESET_S:
                self.reset_sent_at = sent = None  # a board that says nothing when it resets
            return sent is not None

    def pump(self, *, here: bool = False) -> list[tuple[bytes, T]]:
        """Write every queued line that fits now; the lines written.

        ``here``: on the thread that read the answer (:meth:`receive`), in one write.
        """
        with self.lock:
            if self.halted or self.awaiting_banner():
                return []
            out = self.streamer.sendable()
            if here and self._write_here is not None:
                if out:
                    self._write_here([raw for raw, _tag in out])
            else:
                for raw, _tag in out:
                    self._write(raw)
            return out

    def release(self) -> list[tuple[bytes, T]]:
        """The GUI thread has seen the error or alarm: sending may go on (what it queued)."""
        with self.lock:
            self.unseen = max(0, self.unseen - 1)
            return self.pump()

    def receive(self, data: bytes) -> Received[T]:
        """Decode ``data``, match each answer to its line, and send what now fits."""
        received: Received[T] = Received(data)
        with self.lock:
            try:
                self._match(data, received)
                received.written = self.pump(here=True)
            except Exception as exc:  # raised here, it would end the reader thread
                # The link would go silent for good (no more reads, never "connected"),
                # and what was matched so far may be wrong: hold, and let the GUI stop.
                received.failure = exc
                self.unseen += 1
        return received

    def _match(self, data: bytes, received: Received[T]) -> None:
        """Decode ``data`` into ``received``: each reply with its verdict (under the lock)."""
        for reply in self.decoder.feed(data):  # type: ignore[attr-defined]
            verdict: object = None
            if isinstance(reply, Rejected):
                pass
            elif isinstance(reply, Ok | ErrorReply):
                if self.awaiting_banner():
                    verdict = STALE  # an answer from before the reset: its line is gone
                else:
                    verdict = Answer(self.streamer.acknowledge())
                    if isinstance(reply, ErrorReply):
                        self.unseen += 1
            elif isinstance(reply, StatusReport):
                # The lines unanswered as the report is read: those written later
                # went after it, so it says nothing about them (lost answers).
                verdict = self.streamer.unanswered_tags()
            elif isinstance(reply, AlarmReply):
                self.unseen += 1
            elif isinstance(reply, Banner):
                ours = self.reset_sent_at is not None
                self.reset_sent_at = None
                lost = [] if ours else self.streamer.clear()
                verdict = BannerSeen(ours, lost)
            received.replies.append((reply, verdict))
