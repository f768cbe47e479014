"""One core kept busy by another process, for as long as the tests need a loaded machine.

Issue 31: tests must pass on any machine, a busy one too.  ``STEPDECK_BUSY_CORE=1``
makes ``tests/conftest.py`` start one of these for the whole session, so the
suite runs with one core taken, as on a developer's laptop compiling
something, or a CI runner shared with other jobs; ``STEPDECK_BUSY_CORE=N``
takes N cores.  The busy process spins in pure Python at normal priority, so
it competes for the CPU as another program would, and it ends with the
session (or with the test process, should that die: it watches its parent).
"""

from __future__ import annotations

import os
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager

#: Spins until its parent is gone (its parent's pid changes when it dies).
_SPIN = """
import os, sys
parent = int(sys.argv[1])
n = 0
while True:
    n += 1
    if n % 2_000_000 == 0 and os.getppid() != parent:
        break
"""


def cores_wanted(value: str | None = None) -> int:
    """Cores to keep busy by ``STEPDECK_BUSY_CORE`` (unset, empty or 0: none)."""
    raw = os.environ.get("STEPDECK_BUSY_CORE", "") if value is None else value
    try:
        return max(0, int(raw.strip() or "0"))
    except ValueError:
        return 1 if raw.strip().lower() in ("yes", "true", "on") else 0


def start(cores: int = 1) -> list[subprocess.Popen[bytes]]:
    """``cores`` spinning processes, started now."""
    return [
        subprocess.Popen(
            [sys.executable, "-c", _SPIN, str(os.getpid())],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
        )
        for _ in range(cores)
    ]


def stop(processes: list[subprocess.Popen[bytes]]) -> None:
    for process in processes:
        if process.poll() is None:
            process.kill()
        process.wait()


@contextmanager
def busy_cores(cores: int = 1) -> Iterator[list[subprocess.Popen[bytes]]]:
    """``cores`` cores kept busy while the block runs."""
    processes = start(cores)
    try:
        yield processes
    finally:
        stop(processes)
