"""Real GRBL 1.1h (grbl-sim, GRBL's own source compiled for the PC) on a pseudo-terminal.

Test-only: the source stays in ``tests/third_party/grbl`` (GPL) and is built once per
machine into a cache directory outside the repository, with the system C
compiler, as ``tests/third_party/grbl/BUILD.md`` says.  ``python -m
tests.helpers.grbl_sim EXE WORKDIR`` then serves it like the emulator's
``--pty``: it prints the device path on its first line and copies bytes both
ways until SIGTERM.  Every byte from the host and every line from GRBL goes
to ``WORKDIR/wire.log`` as JSON (``{"event": "line", "text", "unacknowledged"}``
for a host line, with the bytes unanswered once it arrived, ``{"event":
"reply", "text"}`` for GRBL's), so a test judges the run as it judges the
emulator's log.  The simulator runs with a fresh EEPROM in WORKDIR, so with
the defaults of a new board (``$10=1``: no ``Bf:``; ``$20=0``; ``$22=0``).
"""

from __future__ import annotations

import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import tty
from collections import deque
from pathlib import Path
from types import FrameType

#: GRBL's real-time bytes: they never enter its line buffer (a line's own bytes do).
REALTIME = frozenset(b"?!~\x18") | frozenset(range(0x80, 0x100))
SIM_DIR = Path("grbl") / "grbl-sim"


def compiler() -> str | None:
    """The system C compiler and make, or None when either is missing."""
    cc = shutil.which("cc") or shutil.which("gcc")
    return cc if cc is not None and shutil.which("make") is not None else None


def cache_dir() -> Path:
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(tempfile.gettempdir(), "cache")
    return Path(base) / f"stepdeck-grbl-sim-{os.getuid()}"


def build(shared_grbl: Path) -> Path:
    """``grbl_sim.exe`` built from a copy of ``shared_grbl``, once (a lock guards parallel runs)."""
    out = cache_dir()
    out.mkdir(parents=True, exist_ok=True)
    exe = out / "grbl" / SIM_DIR / "grbl_sim.exe"
    with open(out / "build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if exe.is_file():
            if not (out / "EEPROM.DAT").is_file():
                _write_default_eeprom(exe, out / "EEPROM.DAT")
            return exe
        tree = out / "grbl"
        if tree.exists():
            shutil.rmtree(tree)
        shutil.copytree(shared_grbl, tree)
        result = subprocess.run(
            ["make", "-C", str(tree / SIM_DIR), "new", "FLAGS=-g -O3 -fcommon"],
            capture_output=True,
            text=True,
            timeout=600,
        )
        if result.returncode != 0 or not exe.is_file():
            raise RuntimeError(f"grbl-sim did not build:\n{result.stdout[-2000:]}{result.stderr}")
        _write_default_eeprom(exe, out / "EEPROM.DAT")
        return exe


#: With this set (a path), the simulator appends where the machine stands to that file:
#: every ``STEPS_EVERY_S`` of machine time and at each block's end (``-r``: ``time x, y, z,
#: spindle PWM`` in steps, a ``# block number N`` line as each block starts).
STEPS_ENV = "STEPDECK_GRBL_SIM_STEPS"
STEPS_EVERY_S = 0.005


def command(exe: Path, steps: bool = False) -> list[str]:
    """The simulator pinned to one core, its stdin unbuffered (BUILD.md's known quirks)."""
    prefix = []
    if shutil.which("taskset"):
        prefix += ["taskset", "-c", "0"]
    if shutil.which("stdbuf"):
        prefix += ["stdbuf", "-i0", "-oL"]
    time_scale = os.environ.get("GRBL_SIM_TIME", "1")
    report = ["-r", str(STEPS_EVERY_S)] if steps else []
    return [*prefix, str(exe), "-n", "-t", time_scale, "-b", os.devnull, *report]


class WireLog:
    """Host lines with the bytes unanswered at their arrival, and GRBL's replies, as JSON."""

    def __init__(self, path: Path) -> None:
        self.file = path.open("w", encoding="utf-8")
        self.pending: deque[int] = deque()  # lengths of host lines not yet answered
        self.host = bytearray()
        self.device = bytearray()

    def _write(self, event: dict[str, object]) -> None:
        self.file.write(json.dumps(event) + "\n")
        self.file.flush()

    def from_host(self, data: bytes) -> None:
        for byte in data:
            if byte in REALTIME:
                continue
            self.host.append(byte)
            if byte in b"\r\n":
                raw = bytes(self.host)
                self.host.clear()
                text = raw.decode("ascii", "replace").strip()
                if text:  # GRBL answers an empty line with nothing, so it is not counted
                    self.pending.append(len(raw))
                    self._write(
                        {"event": "line", "text": text, "unacknowledged": sum(self.pending)}
                    )

    def from_device(self, data: bytes) -> None:
        self.device += data
        while b"\n" in self.device:
            raw, _, rest = self.device.partition(b"\n")
            self.device = bytearray(rest)
            text = raw.decode("ascii", "replace").strip()
            if not text:
                continue
            if (text == "ok" or text.startswith("error:")) and self.pending:
                self.pending.popleft()
            elif text.startswith("Grbl "):
                self.pending.clear()
            self._write({"event": "reply", "text": text})

    def close(self) -> None:
        self.file.close()


def serve(exe: Path, workdir: Path) -> int:
    """Bridge a new pty to the simulator until SIGTERM; the exit status."""
    stopping = False

    def stop(signum: int, frame: FrameType | None) -> None:
        nonlocal stopping
        stopping = True

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    master, slave = os.openpty()
    tty.setraw(slave)
    os.set_blocking(master, False)
    steps = os.environ.get(STEPS_ENV)
    # The step reports go to the simulator's standard error, which C leaves unbuffered:
    # nothing is lost when the board is switched off (terminated) mid-move.
    steps_file = open(steps, "ab") if steps else None
    sim = subprocess.Popen(
        command(exe, steps=steps_file is not None),
        cwd=workdir,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        stderr=steps_file,
        bufsize=0,
    )
    assert sim.stdin is not None and sim.stdout is not None
    log = WireLog(workdir / "wire.log")
    print(os.ttyname(slave), flush=True)
    try:
        while not stopping and sim.poll() is None:
            try:
                readable, _, _ = select.select([master, sim.stdout], [], [], 0.05)
            except InterruptedError:
                continue
            if master in readable:
                try:
                    data = os.read(master, 4096)
                except (BlockingIOError, OSError):
                    data = b""
                if data:
                    log.from_host(data)
                    sim.stdin.write(data)
            if sim.stdout in readable:
                data = os.read(sim.stdout.fileno(), 4096)
                if data:
                    log.from_device(data)
                    os.write(master, data)
    finally:
        if sim.poll() is None:
            sim.terminate()
            try:
                sim.wait(timeout=3)
            except subprocess.TimeoutExpired:
                sim.kill()
                sim.wait()
        log.close()
        if steps_file is not None:
            steps_file.close()
        os.close(master)
        os.close(slave)
    return 0


def start(
    exe: Path, workdir: Path, *, steps: Path | None = None, fresh: bool = True
) -> subprocess.Popen[bytes]:
    """The bridge in its own process, its first output line the device path.

    ``fresh``: a new board's EEPROM (False: the one in ``workdir``, as a board
    that restarts keeps its settings); ``steps``: where the machine stands,
    appended to that file (see :data:`STEPS_ENV`).
    """
    if fresh:
        shutil.copyfile(cache_dir() / "EEPROM.DAT", workdir / "EEPROM.DAT")  # written by build()
    root = Path(__file__).resolve().parent.parent.parent
    env = dict(os.environ)
    if steps is not None:
        env[STEPS_ENV] = str(steps)
    return subprocess.Popen(
        [sys.executable, "-m", "tests.helpers.grbl_sim", str(exe), str(workdir)],
        cwd=root,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
        env=env,
    )


def _write_default_eeprom(exe: Path, target: Path) -> None:
    """GRBL's defaults as a fresh board writes them on its first start.

    The simulator's very first start (no EEPROM file) restores the defaults but
    then plans moves it never runs; from a written EEPROM it behaves, so each
    test starts from this copy of a freshly initialised one.
    """
    with tempfile.TemporaryDirectory() as first:
        subprocess.run(
            [str(exe), "-n", "-b", os.devnull],
            cwd=first,
            input=b"\r\n$$\n\x06",
            capture_output=True,
            timeout=30,
        )
        shutil.copyfile(Path(first) / "EEPROM.DAT", target)


if __name__ == "__main__":
    sys.exit(serve(Path(sys.argv[1]), Path(sys.argv[2])))
