"""One running G-code job on its way to the board: its lock, its lines, their encode.

A job's lines are pulled on the transport's reader thread (the feeder, as
each ``ok`` frees room in the board's buffer) and, for a single step, on the
GUI thread.  Both go through one object per running job, :class:`JobFeed`:
it reads the next lines from a plain line source (:class:`JobSource`, one
``next_lines(n)`` for the pull and the step alike), encodes each one here,
and queues it.  The job driver starts it (:meth:`GcodeSession.start_job`),
lets it be pulled or holds it, reads the source under its lock
(:meth:`JobFeed.locked`), and releases it when the job ends.

Why nothing written from the reader thread can race (the argument
``tests/test_gcode_job_feed.py`` stresses):

* The lock is the feeder's one re-entrant lock.  The reader thread runs only
  :meth:`LineFeeder.receive`, which holds it from the first byte decoded to
  the last line written; everything it calls (:meth:`JobFeed.take`, the
  source's ``next_lines``/``count_answer``/``reported``, :meth:`JobFeed._encode`)
  runs inside that hold.
* What the reader thread writes is therefore written under the lock: the
  feeder's and the streamer's state; the source's bookkeeping; and, per line
  encoded, the session's serial counter, its "seen idle" flag, the console
  gate's distance mode and the hand-zeroing release
  (:meth:`GcodeSession.note_queued`).
* The GUI thread writes those same attributes only under the lock too: a
  line sent (serial, queue and its notes in one hold, so the serials are in
  queue order and the distance mode is the last queued line's), a status
  report marking the board idle (checked against the streamer in the same
  hold), a reset or a link change, and the driver's reads and changes of the
  source (:meth:`JobFeed.locked`).  What reads two of them together reads
  them in one hold too (``GcodeSession.settled``: the streamer idle, and the
  board seen idle since).

Plain Python, no Qt.
"""

from __future__ import annotations

from collections.abc import Iterator
from contextlib import contextmanager
from typing import Protocol

from app.link import Link
from app.machines.gcode.feeder import LineFeeder, PullGate
from app.machines.gcode.lines import SentLine
from protocol.gcode.codec import encode_line
from protocol.gcode.streaming import LineStreamer
from protocol.gcode.words import grbl_text


def wire_text(line: str) -> str:
    """A job's line as it goes to a GRBL board: without comments and spaces, upper case.

    GRBL's serial layer drops spaces and comments and upper-cases the letters
    before its parser sees a line (``protocol.c``), and grbl's own ``stream.py``
    sends lines so; sent as written, a drawing's short lines cost about 1.14
    times the bytes.  Everything else keeps the line as written: the file, the
    log, the console, the checkpoint and the resume (:class:`SentLine` carries
    that text), and the operator never sees the compact one.
    A line that is nothing once compacted (a lone ``/``) goes as written: the
    board answers it as it would have.
    """
    return grbl_text(line) or line


class JobSource(Protocol):
    """A job's lines in order, as text (no wire, no session): what a :class:`JobFeed` sends.

    Every call is made under the feed's lock, on whichever thread holds it.
    """

    def next_lines(self, count: int) -> list[tuple[int, str]]:
        """Take at most ``count`` next lines to send, each with its operation's index (fewer:
        the job stops there for now: its end, a wait for the operator, a refusal)."""
        ...

    def refuse(self, index: int, why: str) -> None:
        """Operation ``index``'s line, taken, cannot be sent: it and what followed it go
        back, and the job stops there (it fails once everything before is answered)."""
        ...

    def count_answer(self, sent: SentLine) -> bool:
        """An ``ok`` for ``sent``: True when it is this job's line (counted there)."""
        ...

    def reported(self) -> object:
        """The source as a status report is read (the report's snapshot of it)."""
        ...


class WrittenLines(Protocol):
    """Where lines written are told (the session's status follower follows their path)."""

    def written(self, written: list[tuple[bytes, SentLine]]) -> None: ...


class FeedPort(Protocol):
    """What a job's feed uses of its session (the G-code session)."""

    @property
    def feeder(self) -> LineFeeder[SentLine]: ...
    @property
    def streamer(self) -> LineStreamer[SentLine]: ...
    @property
    def link(self) -> Link: ...
    @property
    def serials(self) -> Iterator[int]: ...
    def note_queued(self, line: str, origin: str) -> None: ...
    @property
    def follower(self) -> WrittenLines: ...
    def pump(self) -> None: ...


class JobFeed:
    """One running job between its line source and the feeder (the feeder follows it)."""

    def __init__(self, session: FeedPort, source: JobSource, *, compact: bool = False) -> None:
        self._session = session
        self._feeder = session.feeder
        self.source = source
        #: Lines go on the wire as GRBL reads them (:func:`wire_text`); tagged as written.
        self._compact = compact

    @contextmanager
    def locked(self) -> Iterator[JobSource]:
        """The source, held against the reader thread for as long as the block runs."""
        with self._feeder.lock:
            yield self.source

    # --- the feeder's side (reader thread, under the lock) ---------------------------

    def take(self, count: int) -> list[tuple[bytes, SentLine]]:
        """At most ``count`` next lines, encoded and tagged: the feeder queues them.

        Called with the lock held (the feeder's pump, or :meth:`step`).
        """
        out: list[tuple[bytes, SentLine]] = []
        encode, source = self._encode, self.source
        for index, text in source.next_lines(count):
            made = encode(text, index)
            if isinstance(made, str):
                source.refuse(index, f"{text!r} cannot be sent: {made}")
                break
            out.append(made)
        return out

    def count_answer(self, tag: SentLine) -> bool:
        return self.source.count_answer(tag)

    def reported(self) -> object:
        return self.source.reported()

    def _encode(self, text: str, index: int) -> tuple[bytes, SentLine] | str:
        """Operation ``index``'s line made ready to queue (a str: why it cannot go)."""
        session = self._session
        line = text.strip()
        try:
            # What is counted against the board's buffer and its 80-byte line limit is
            # what goes: the compact line, when it is sent compact.
            raw = encode_line(wire_text(line) if self._compact else line)
        except ValueError as exc:
            return str(exc)
        streamer = session.streamer
        if len(raw) > streamer.capacity:
            return f"{len(raw)} bytes never fit the board's {streamer.rx_buffer}-byte buffer"
        session.note_queued(line, "job")
        return raw, SentLine(next(session.serials), line, "job", index)

    # --- the driver's side (GUI thread) ----------------------------------------------

    def pull(self) -> None:
        """Let the lines go as the board frees room, from the reader thread.

        Anything that takes back the queue (a pause, a stop, a reset, a lost link)
        stops that again; only this lets the job go on.
        """
        if self._session.link.is_open:
            self._session.follower.written(self._feeder.pull())

    def hold(self) -> None:
        """Pull nothing more (what is queued stays: see :meth:`GcodeSession.discard_queued`)."""
        self._feeder.hold()

    def pull_when(self, gate: PullGate[SentLine]) -> None:
        """Held until the reply ``gate`` waits for lets it be pulled, on the thread that reads
        it (:meth:`LineFeeder.pull_when`): the set-up's confirmation, spared a GUI turn."""
        self._feeder.pull_when(gate)

    def step(self) -> None:
        """One line of the job queued and sent (a single step), as the pull would send it."""
        session = self._session
        if not session.link.is_open:
            return
        with self._feeder.lock:
            for raw, sent in self.take(1):
                session.streamer.queue(raw, sent)
        session.pump()

    def release(self) -> None:
        """The job is over (or another follows): its answers are no longer counted here."""
        with self._feeder.lock:
            if self._feeder.job is self:
                self._feeder.follow(None)
