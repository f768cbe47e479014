"""The record of the last completed operation, so an interrupted job resumes exactly.

One JSON file per program, named by the program's fingerprint, replaced
atomically: a crash leaves the old checkpoint or the new one, never half of
one.  The runner writes it after every completed operation and before the
next is sent, so it can never name an operation as done that was not.
"""

from __future__ import annotations

import json
import os
import stat
import tempfile
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from app.jobs.program import Program
from app.jobs.registration import Placement

#: A checkpoint is a few hundred bytes; anything much larger is not one of ours.
MAX_CHECKPOINT_BYTES = 64 * 1024


class CheckpointStore:
    """Checkpoints of programs in one directory."""

    def __init__(self, directory: Path) -> None:
        self.directory = Path(directory)
        self._fingerprint_cache: tuple[Program, str] | None = None
        self._base_cache: tuple[Program, str] | None = None

    def path(self, program: Program) -> Path:
        return self.directory / f"{self.fingerprint(program)}.json"

    def fingerprint(self, program: Program) -> str:
        """The program's fingerprint, hashed once: a checkpoint is written twice a second."""
        cached = self._fingerprint_cache
        if cached is None or cached[0] is not program:
            cached = self._fingerprint_cache = (program, program.fingerprint())
        return cached[1]

    def remember(self, program: Program, fingerprint: str) -> None:
        """``program``'s fingerprint, hashed elsewhere (the dock's loading thread)."""
        self._fingerprint_cache = (program, fingerprint)

    def write(
        self,
        program: Program,
        completed: int,
        placed: tuple[Program, Placement] | None = None,
        sent: int | None = None,
    ) -> None:
        """Record operations ``[0, completed]`` as done; raises OSError when it cannot.

        ``sent``: operations ``[0, sent)`` may have reached the machine (a streaming
        dialect sends ahead of what is proven run): after a restart of the station the
        ones between are those only the operator can judge.

        ``placed`` is the job as its file says and how ``program`` was put on the
        board from it (a registered drill job): kept, so that the file read
        again can be put there again and resumed (:meth:`placement_for`).
        """
        record: dict[str, Any] = {
            "fingerprint": self.fingerprint(program),
            "name": program.name,
            "source": str(program.source) if program.source is not None else None,
            "completed": completed,
            **({"sent": sent} if sent is not None and sent > completed + 1 else {}),
            "time": datetime.now(UTC).isoformat(timespec="seconds"),
        }
        if placed is not None:
            base, placement = placed
            record["placement"] = {"base": self._base_fingerprint(base), **placement.to_record()}
        path = self.path(program)
        self.directory.mkdir(parents=True, exist_ok=True)
        fd, temp = tempfile.mkstemp(prefix=f".{path.stem}.", dir=self.directory)
        try:
            with os.fdopen(fd, "w", encoding="utf-8") as handle:
                json.dump(record, handle)
                handle.flush()
                os.fsync(handle.fileno())
            os.replace(temp, path)
        except BaseException:
            Path(temp).unlink(missing_ok=True)
            raise

    def read(self, program: Program) -> int | None:
        """First operation not completed by an earlier run of this very program, or None.

        Raises OSError or ValueError for a checkpoint that exists but cannot be read.
        """
        path = self.path(program)
        try:
            # Looked at before it is opened: a FIFO would block the read, /dev/zero never end.
            info = path.stat()
        except FileNotFoundError:
            return None
        if not stat.S_ISREG(info.st_mode):
            raise ValueError("not a regular file")
        if info.st_size > MAX_CHECKPOINT_BYTES:
            raise ValueError(f"{info.st_size} bytes, more than a checkpoint ever holds")
        record: Any = json.loads(path.read_text(encoding="utf-8"))
        completed = record.get("completed") if isinstance(record, dict) else None
        if (
            not isinstance(record, dict)
            or record.get("fingerprint") != self.fingerprint(program)
            or not isinstance(completed, int)
            or not -1 <= completed < len(program) - 1
        ):
            return None
        return completed + 1

    def sent(self, program: Program) -> int | None:
        """How far an interrupted run of ``program`` may have sent (see :meth:`write`), if
        its checkpoint says; None otherwise, or for one that cannot be read."""
        try:
            path = self.path(program)
            info = path.stat()
            if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_CHECKPOINT_BYTES:
                return None
            record: Any = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return None
        sent = record.get("sent") if isinstance(record, dict) else None
        if not isinstance(sent, int) or not 0 < sent <= len(program):
            return None
        return sent

    def _base_fingerprint(self, base: Program) -> str:
        cached = self._base_cache
        if cached is None or cached[0] is not base:
            cached = self._base_cache = (base, base.fingerprint())
        return cached[1]

    def placement_for(self, base: Program) -> Placement | None:
        """How an interrupted run of ``base`` (as its file says) was put on the board, if any.

        Unreadable or foreign files are skipped: this only offers a resume.
        """
        if not self.directory.is_dir():
            return None
        candidates: list[tuple[str, object, dict[str, Any]]] = []
        for path in self.directory.glob("*.json"):
            try:
                info = path.stat()
                if not stat.S_ISREG(info.st_mode) or info.st_size > MAX_CHECKPOINT_BYTES:
                    continue
                record: Any = json.loads(path.read_text(encoding="utf-8"))
            except (OSError, ValueError):
                continue
            placement = record.get("placement") if isinstance(record, dict) else None
            if isinstance(placement, dict):
                candidates.append((str(record.get("time", "")), placement.get("base"), placement))
        if not candidates:
            return None  # the common case: no fingerprint of a large job to compute
        wanted = self._base_fingerprint(base)
        newest: tuple[str, Placement] | None = None
        for when, fingerprint, placement in candidates:
            found = Placement.from_record(placement) if fingerprint == wanted else None
            if found is not None and (newest is None or when > newest[0]):
                newest = (when, found)
        return newest[1] if newest is not None else None

    def discard(self, program: Program) -> None:
        self.path(program).unlink(missing_ok=True)
