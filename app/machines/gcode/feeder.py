"""The G-code streaming loop, run where the replies arrive: on the transport's reader thread.

Character counting keeps the board's receive buffer full only if the next
line goes out as soon as an ``ok`` frees room.  When that waited for the GUI
thread (a paint, a busy machine), a job of short lines ran at a fraction of
the wire.  So the bytes the transport reads are decoded here, on its reader
thread: every ``ok``/``error`` is matched to its line in the
:class:`~protocol.gcode.streaming.LineStreamer` (the ``ok`` accounting) and
the lines queued behind are written at once.  A running job goes further
(:class:`JobLines`): its next lines are pulled from the program here as room
frees, and each ``ok`` is counted against the job's operations here, so the
wire stays full whatever the GUI thread is doing.  The GUI thread gets the
decoded replies, each with the line it answered, in batches; it keeps every
decision (job states, when the job may be pulled, pause, abort).

What keeps the machine from moving when nobody asked:

* only lines the GUI queued, or a job's lines while the GUI thread lets the
  job be pulled, are ever sent; one lock covers queueing, pulling, sending and
  taking back, and taking back the queue also stops the pulling
  (:meth:`LineFeeder.discard_queued`, :meth:`LineFeeder.clear`), so a pause,
  a stop or a reset stops the feeding at once, and only the GUI thread lets a
  job be pulled again;
* after an ``error`` or an ``ALARM`` nothing more is sent until the GUI
  thread has seen it (:meth:`LineFeeder.release`): a job that fails stops
  with nothing more written than before;
* after a soft reset nothing is sent until the board's banner (as before); a
  banner nobody here asked for (the board reset itself) drops the queue and
  stops the pulling before anything more could go;
* the transport writes nothing once the link is closed;
* a job held for its set-up's confirmation (:class:`PullGate`) is let go
  here only by the reply to that very line, with nothing refused, alarmed or
  reset since, and only if the reply says what the GUI thread would accept;
  anything that takes back or holds the job disarms it.

Where a job starts no GUI turn is waited for either: the set-up's
confirmation lets the job go as it is read (above).  Its end is not asked
for at once as its last answer is read: asked then, the board may report
``Idle`` before its last move has begun (the job was declared done with the
machine still on its way: tests/e2e/test_macros_pty.py, 2 runs in 10); the
next status poll asks.

Plain Python, no Qt; in tests on a manual clock the transport calls it on
the GUI thread itself, so everything stays synchronous.
"""

from __future__ import annotations

import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Generic, Protocol, TypeVar

from app.machines.gcode.byte_shortfall import Held, QueryMarks
from protocol.clock import Clock
from protocol.gcode.codec import (
    FEED_HOLD,
    AlarmReply,
    Banner,
    ErrorReply,
    Ok,
    Rejected,
    StatusReport,
)
from protocol.gcode.streaming import LineStreamer

T = TypeVar("T")

#: After a soft reset, answers are dropped and lines held until the banner, this long at most.
BANNER_AFTER_RESET_S = 1.0
#: A pulled job keeps this many lines queued: more than the board's buffer can take at once
#: (127 bytes are at most 63 two-byte lines), and nothing of it is on the wire yet.
PULL_AHEAD = 64


class JobLines(Protocol[T]):
    """A running job as the reader thread sees it: its next lines, and its ``ok`` accounting.

    Both are called under the feeder's lock, on whichever thread holds it.
    """

    def take(self, count: int) -> list[tuple[bytes, T]]:
        """At most ``count`` next lines, encoded, each with its tag (fewer: the job stops
        there for now: its end, a wait for the operator, a line it cannot send)."""
        ...

    def count_answer(self, tag: T) -> bool:
        """An ``ok`` for the line ``tag``: True when it is the job's (counted there)."""
        ...

    def reported(self) -> object:
        """What the job has as a status report is read (the report's snapshot of it)."""
        ...


@dataclass(frozen=True)
class PullGate(Generic[T]):
    """A held job goes once the reply to one line says so (a set-up's ``$G``): at once, on
    the thread that read it, instead of a GUI turn later.

    ``asks``: whether the oldest unanswered line is the one asked (its reply comes while
    it is); ``lets_go``: whether that reply lets the job go.  The first reply read while
    that line is the oldest decides, once; a "no" leaves the job held for the GUI thread.
    """

    asks: Callable[[T], bool]
    lets_go: Callable[[object], bool]


class Stale:
    """The verdict on an ``ok``/``error`` that came while a reset's banner was awaited."""


STALE = Stale()


class Wrote:
    """In a merged read's replies: the lines written after the replies before it (verdict)."""


WROTE = Wrote()


@dataclass(frozen=True)
class Answer(Generic[T]):
    """The verdict on an ``ok``/``error``: the line it answers (None: a reply for no line).

    ``counted``: an ``ok`` the running job has counted already (:meth:`JobLines.count_answer`).
    """

    entry: tuple[bytes, T] | None
    counted: bool = False


@dataclass(frozen=True)
class ReportSeen(Generic[T]):
    """The verdict on a status report: what was unanswered as it was read, and the job's
    snapshot then (:meth:`JobLines.reported`; None without a job)."""

    unanswered: list[T]
    job: object = None
    #: The bytes of those lines (what the board's receive buffer can hold at most).
    unanswered_bytes: int | None = None
    #: Nothing waited to go and nothing for its answer as it was read: only then can the
    #: report show the board standing after every line (those sent later went after it).
    idle: bool | None = None
    #: The lines the board must hold as it made the report (byte_shortfall.py; None: unknown).
    held: Held | None = None


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
    #: :class:`BannerSeen`, :class:`ReportSeen`, or None (and, merged, :data:`WROTE`).
    replies: list[tuple[object, object]] = field(default_factory=list)
    #: The lines written after these replies freed room, in order.
    written: list[tuple[bytes, T]] = field(default_factory=list)
    #: What went wrong reading these bytes (a bug, not the device's words): sending is held,
    #: as after an error, until the GUI thread has stopped the machine.
    failure: Exception | None = None
    #: A status report among them was read with nothing unanswered: it can end a job (or
    #: a wait), so the window hears of this read at once (:func:`settles`).
    settles: bool = False


def settles(result: object) -> bool:
    """Whether the window must hear of a read at once (:meth:`Link.set_tap`'s ``urgent``):
    a report that may show the machine standing after everything sent; the reads between,
    hundreds a second while a job streams, wait for the window's next batch."""
    return isinstance(result, Received) and result.settles


def merged(results: list[object]) -> list[object]:
    """Reads the window takes in one go, made one (:meth:`Link.set_tap`'s ``merge``).

    Consecutive reads join: their bytes, and their replies in order, each
    read's lines let go after its replies (as :data:`WROTE`, so a line is told
    as sent before its answer is).  A read that failed stays apart (the window
    stops the machine on it, after the replies before it).
    """
    out: list[object] = []
    for result in results:
        last = out[-1] if out else None
        if (
            isinstance(last, Received)
            and isinstance(result, Received)
            and last.failure is None
            and result.failure is None
        ):
            between = [(WROTE, last.written)] if last.written else []
            out[-1] = Received(
                last.data + result.data,
                last.replies + between + result.replies,
                result.written,
            )
        else:
            out.append(result)
    return out


class LineFeeder(Generic[T]):
    """The streamer, the decoder and the sending, shared by the reader and the GUI thread."""

    def __init__(
        self,
        streamer: LineStreamer[T],
        decoder: object,
        clock: Clock,
        write: Callable[[bytes], None],
        write_here: Callable[[list[bytes]], None] | None = None,
        holds_on_refusal: Callable[[T], bool] | None = None,
    ) -> None:
        self.lock = threading.RLock()
        self.streamer = streamer
        self.decoder = decoder
        self.clock = clock
        self._write = write
        #: How :meth:`receive` writes the lines an answer let go, on the thread that read:
        #: all at once (default: one ``write`` each).
        self._write_here = write_here
        #: Whether a refusal of this line holds the board at once (a job's line), even
        #: when the job is not being pulled right then.
        self._holds_on_refusal = holds_on_refusal
        #: A soft reset was sent at this time and its banner has not come yet.
        self.reset_sent_at: float | None = None
        #: Errors and alarms read here that the GUI thread has not seen yet: nothing is
        #: sent while any is.  A count, not a flag: the GUI thread having seen the first
        #: must not let lines go past a second it has not seen.
        self.unseen = 0
        #: The running job: its answers are counted here while it is set.
        self.job: JobLines[T] | None = None
        #: Whether the job's next lines may be pulled (only the GUI thread sets it, or the
        #: reply its gate waits for; anything that takes back the queue clears it).
        self.pulling = False
        #: What lets the held job go where its set-up's answer is read (:meth:`pull_when`).
        self.gate: PullGate[T] | None = None
        #: The lines written before each ``?`` (byte_shortfall.py): noted under the lock.
        self.marks = QueryMarks()

    def follow(self, job: JobLines[T] | None) -> None:
        """Count the answers of ``job`` here from now on (None: no job); it is not pulled."""
        with self.lock:
            self.job = job
            self.pulling = False
            self.gate = None

    def pull(self) -> list[tuple[bytes, T]]:
        """Let the job's next lines be pulled as room frees; the lines written now."""
        with self.lock:
            self.pulling = self.job is not None
            self.gate = None
            return self.pump()

    def pull_when(self, gate: PullGate[T]) -> None:
        """Held until the reply ``gate`` waits for lets the job be pulled, where it is read.

        Already let go (that reply was read before the GUI thread caught up): it
        stays so.  The GUI thread still judges the reply too, and fails the job on
        a "no"; this only spares the "yes" a turn of the GUI thread.
        """
        with self.lock:
            if not self.pulling:
                self.gate = gate if self.job is not None else None

    def hold(self) -> None:
        """Pull no more of the job until :meth:`pull` (lines already queued stay)."""
        with self.lock:
            self.pulling = False
            self.gate = None

    def discard_queued(self) -> list[T]:
        """Take back the lines not yet sent, and stop pulling the job (oldest first)."""
        with self.lock:
            self.pulling = False
            self.gate = None
            return self.streamer.discard_queued()

    def clear(self) -> list[T]:
        """Forget every line (the board lost them: a reset, a lost link); stop pulling."""
        with self.lock:
            self.pulling = False
            self.gate = None
            return self.streamer.clear()

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
            job, streamer = self.job, self.streamer
            if self.pulling and job is not None and streamer.queued < PULL_AHEAD // 2:
                for raw, tag in job.take(PULL_AHEAD - streamer.queued):
                    streamer.queue(raw, tag)
            out = streamer.sendable()
            self.marks.wrote(len(out))
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

    def acknowledge(self) -> Answer[T]:
        """An ``ok`` for the oldest line in flight, counted by the job when it is its line."""
        with self.lock:
            entry = self.streamer.acknowledge()
            job = self.job
            counted = entry is not None and job is not None and job.count_answer(entry[1])
            return Answer(entry, counted)

    def _match(self, data: bytes, received: Received[T]) -> None:
        """Decode ``data`` into ``received``: each reply with its verdict (under the lock)."""
        for reply in self.decoder.feed(data):  # type: ignore[attr-defined]
            verdict: object = None
            if isinstance(reply, Rejected):
                pass
            elif isinstance(reply, Ok | ErrorReply):
                if self.awaiting_banner():
                    verdict = STALE  # an answer from before the reset: its line is gone
                elif isinstance(reply, ErrorReply):
                    entry = self.streamer.acknowledge()
                    verdict = Answer(entry)
                    self.unseen += 1
                    self.gate = None
                    judge = self._holds_on_refusal
                    ours = entry is not None and judge is not None and judge(entry[1])
                    if self.pulling or ours:
                        # A job line refused mid-stream: the board goes straight on to the
                        # lines behind it, which may draw a stroke the job never had (a pen
                        # change in the refused line).  Held here, on the thread that read
                        # it, not a GUI-thread turn later; the job's stop follows.
                        self.pulling = False
                        if self._write_here is not None:
                            self._write_here([FEED_HOLD])
                        else:
                            self._write(FEED_HOLD)
                else:
                    verdict = self.acknowledge()
            elif isinstance(reply, StatusReport):
                # The lines unanswered as the report is read: those written later
                # went after it, so it says nothing about them (lost answers).
                job = self.job
                idle = self.streamer.idle
                verdict = ReportSeen(
                    self.streamer.unanswered_tags(),
                    None if job is None else job.reported(),
                    self.streamer.in_flight_bytes,
                    idle,
                    self.marks.seen(self.streamer.unanswered_lengths()),
                )
                received.settles = received.settles or idle
            elif isinstance(reply, AlarmReply):
                self.unseen += 1
                self.gate = None
            elif isinstance(reply, Banner):
                self.gate = None  # the board restarted: what it was set up as is gone
                ours = self.reset_sent_at is not None
                self.reset_sent_at = None
                # A board that reset itself lost what it had: nothing more of the job goes
                # before the GUI thread has seen that.
                lost = [] if ours else self.clear()
                verdict = BannerSeen(ours, lost)
            elif self.gate is not None:
                self._gate_hears(reply)
            received.replies.append((reply, verdict))

    def _gate_hears(self, reply: object) -> None:
        """A reply that answers no line: the held job goes if it is the one its gate waits
        for, and says so (under the lock, on the thread that read it)."""
        gate = self.gate
        if gate is None or self.job is None or self.halted:
            return
        tags = self.streamer.unanswered_tags()
        if not tags or not gate.asks(tags[0]):
            return
        self.gate = None  # this reply decides, once
        if gate.lets_go(reply):
            self.pulling = True  # the pump that follows the read sends the job's lines
