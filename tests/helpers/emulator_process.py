"""The emulator in its own process on a pseudo-terminal, for end-to-end tests and benchmarks.

``python -m protocol.emulator --pty`` prints the device path on its first
line; everything here waits for it with a bound, and always ends the process
(terminate, then kill) whatever the test did.
"""

from __future__ import annotations

import selectors
import subprocess
import sys
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent.parent
STARTUP_TIMEOUT_S = 15.0


def start_emulator(*args: str) -> subprocess.Popen[bytes]:
    """``stepdeck-emulator --pty`` with ``args``, its stdout readable for the device path."""
    return subprocess.Popen(
        [sys.executable, "-m", "protocol.emulator", "--pty", *args],
        cwd=ROOT,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
    )


def device_path(process: subprocess.Popen[bytes], timeout: float = STARTUP_TIMEOUT_S) -> str:
    """The pty the emulator printed; fails the test when it prints nothing in time."""
    assert process.stdout is not None
    with selectors.DefaultSelector() as selector:
        selector.register(process.stdout, selectors.EVENT_READ)
        if not selector.select(timeout):
            raise AssertionError("the emulator printed no device path")
    path = process.stdout.readline().decode().strip()
    if not path:
        raise AssertionError(f"the emulator ended (status {process.poll()})")
    return path


def stop(process: subprocess.Popen[bytes]) -> None:
    if process.poll() is None:
        process.terminate()
    try:
        process.wait(timeout=5)
    except subprocess.TimeoutExpired:
        process.kill()
        process.wait()
    if process.stdout is not None:
        process.stdout.close()


@contextmanager
def emulator_on_pty(*args: str) -> Iterator[str]:
    """The device path of an emulator started with ``args``, stopped on leaving."""
    process = start_emulator(*args)
    try:
        yield device_path(process)
    finally:
        stop(process)
