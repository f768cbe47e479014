"""The runner's checkpoint: written as the job goes, offered back when it stopped short.

The store (:mod:`app.jobs.run.checkpoint`) keeps the files; this keeps what
the runner knows of them: the job's placement to record with it, the
operation a checkpoint of the loaded program offers to resume from, and, while
a resumed run begins, how far the interrupted one sent.  A checkpoint that
cannot be read is ignored with a message (the job can still start over); one
that cannot be written is the runner's to act on (it fails the job rather
than run on without one).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

from app.jobs.program import Program
from app.jobs.registration import Placement
from app.jobs.run.checkpoint import CheckpointStore


class CheckpointKeeper:
    """The loaded program's checkpoint, as the runner writes, offers and discards it."""

    def __init__(self, directory: Path, message: Callable[[str], None]) -> None:
        self.directory = Path(directory)
        self.store = CheckpointStore(self.directory)
        self._message = message
        #: The job as its file says and how the program was put on the board from it.
        self.placed: tuple[Program, Placement] | None = None
        #: Index to resume from when a checkpoint of this program waits for the operator.
        self.resume_available: int | None = None
        #: While a run resumed from its checkpoint begins: how far the interrupted one sent.
        self.sent: int | None = None

    def loaded(
        self, program: Program, fingerprint: str, placed: tuple[Program, Placement] | None
    ) -> None:
        """``program`` is the job now: its checkpoint, if any, is offered."""
        self.placed = placed if placed is not None and placed[1] else None
        self.store.remember(program, fingerprint)
        self.resume_available = self.read(program)

    def write(self, program: Program, completed: int, sent: int | None = None) -> None:
        """Record operations ``[0, completed]`` as done; raises OSError when it cannot."""
        self.store.write(program, completed, self.placed, sent)

    def read(self, program: Program) -> int | None:
        try:
            return self.store.read(program)
        except (OSError, ValueError) as exc:
            name = self.store.path(program).name
            self._message(f"Ignoring an unreadable checkpoint {name}: {exc}")
            return None

    def offer(self, program: Program | None) -> None:
        """After an abort or failure: resuming is the operator's choice, from what is on disk."""
        if program is not None:
            self.resume_available = self.read(program)

    def take_resume(self, program: Program) -> int | None:
        """The operation to resume from, no longer offered; what the interrupted run sent
        is kept in :attr:`sent` meanwhile."""
        index, self.resume_available = self.resume_available, None
        self.sent = self.store.sent(program)
        return index

    def discard(self, program: Program, failure: str) -> bool:
        """Forget the interrupted run (``failure``: the message if the file stays)."""
        try:
            self.store.discard(program)
        except OSError as exc:
            self._message(failure.format(exc))
            return False
        self.resume_available = None
        return True

    def placement_for(self, base: Program) -> Placement | None:
        return self.store.placement_for(base)
