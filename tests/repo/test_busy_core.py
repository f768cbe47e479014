"""The test helper that keeps a core busy (``STEPDECK_BUSY_CORE``) does, and stops after."""

from __future__ import annotations

import time
from pathlib import Path

from tests.helpers.busy_core import busy_cores, cores_wanted


def _cpu_ticks(pid: int) -> int:
    """User plus system clock ticks the process has used (Linux's /proc)."""
    fields = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()
    return int(fields[11]) + int(fields[12])


def test_the_setting_reads_as_a_count_of_cores() -> None:
    assert cores_wanted("") == 0
    assert cores_wanted("0") == 0
    assert cores_wanted("1") == 1
    assert cores_wanted("2") == 2
    assert cores_wanted("yes") == 1
    assert cores_wanted("nonsense") == 0


def test_a_busy_core_spins_until_the_block_ends() -> None:
    with busy_cores(1) as processes:
        (process,) = processes
        start = _cpu_ticks(process.pid)
        # Wait on what it does, not on the wall clock: it has used CPU time of its own.
        deadline = time.monotonic() + 60
        while _cpu_ticks(process.pid) - start < 10 and time.monotonic() < deadline:
            time.sleep(0.05)
        assert _cpu_ticks(process.pid) - start >= 10  # a tenth of a second of CPU, at least
        assert process.poll() is None
    assert process.poll() is not None
