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

import contextlib
import fcntl
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import time
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


def build(source: Path) -> Path:
    """``grbl_sim.exe`` built from a copy of ``source`` (GRBL with grbl-sim), once (a lock guards
    parallel runs)."""
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
        shutil.copytree(source, tree)
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

    def restart(self) -> None:
        """The board restarted: nothing is unanswered any more, no line half read."""
        self.pending.clear()
        self.host.clear()
        self.device.clear()
        self._write({"event": "restart"})

    def close(self) -> None:
        self.file.close()


class Board:
    """The simulator as an Arduino GRBL board on its USB port: it may be unplugged, and
    with ``restart_on_open`` it restarts whenever the port is opened (DTR resets it).

    The port is a pty the helper does not hold open itself, so it sees when the
    station opens it (the master's hang-up ends); a short boot later (the
    bootloader's, during which the host's bytes are lost) a fresh simulator
    starts from the EEPROM in WORKDIR: its position is 0, its planner empty,
    and its banner the first thing the station reads.  Unplugged (SIGUSR1), the
    port vanishes from ``link``; plugged back (SIGUSR2), a new one appears there
    and the board restarts as a USB board powers up.  While unplugged the board
    runs on, and the helper asks it ``?`` now and then, so its reports in the
    wire log say when it stands idle.
    """

    BOOT_S = 0.3
    ASK_EVERY_S = 0.2

    def __init__(self, exe: Path, workdir: Path, link: Path | None, restart_on_open: bool):
        self.exe, self.workdir, self.link = exe, workdir, link
        self.restart_on_open = restart_on_open
        self.log = WireLog(workdir / "wire.log")
        steps = os.environ.get(STEPS_ENV)
        # The step reports go to the simulator's standard error, which C leaves unbuffered:
        # nothing is lost when the board is switched off (terminated) mid-move.
        self.steps_file = open(steps, "ab") if steps else None
        self.sim = self._start_sim()
        self.master: int | None = None
        self.slave: int | None = None
        self.opened = False
        self.boot_at: float | None = None
        self.asked_at = 0.0
        self.plug()

    def _start_sim(self) -> subprocess.Popen[bytes]:
        sim = subprocess.Popen(
            command(self.exe, steps=self.steps_file is not None),
            cwd=self.workdir,
            stdin=subprocess.PIPE,
            stdout=subprocess.PIPE,
            stderr=self.steps_file,
            bufsize=0,
        )
        assert sim.stdout is not None
        os.set_blocking(sim.stdout.fileno(), False)
        return sim

    def restart(self) -> None:
        """A power-up: a new simulator from the EEPROM (settings kept, position 0)."""
        self._stop_sim()
        self.log.restart()
        self.sim = self._start_sim()

    def _stop_sim(self) -> None:
        if self.sim.poll() is None:
            self.sim.terminate()
            try:
                self.sim.wait(timeout=3)
            except subprocess.TimeoutExpired:
                self.sim.kill()
                self.sim.wait()

    def plug(self) -> None:
        master, slave = os.openpty()
        tty.setraw(slave)
        os.set_blocking(master, False)
        self.master = master
        path = os.ttyname(slave)
        if self.restart_on_open:
            # Not held open here: the master hangs up until the station opens the port.
            os.close(slave)
        else:
            self.slave = slave
        self.opened = False
        if self.link is not None:
            staging = self.link.with_name(f".{self.link.name}.new")
            staging.unlink(missing_ok=True)
            staging.symlink_to(path)
            staging.replace(self.link)
        self.path = path

    def unplug(self) -> None:
        if self.link is not None:
            self.link.unlink(missing_ok=True)
        for fd in (self.master, self.slave):
            if fd is not None:
                with contextlib.suppress(OSError):
                    os.close(fd)
        self.master = self.slave = None

    def step(self) -> None:
        """One turn of the relay: the port's state, the host's bytes, the board's."""
        now = time.monotonic()
        master = self.master
        sim_out = self.sim.stdout
        assert sim_out is not None
        if master is not None and self.restart_on_open:
            events = dict(_poll(master))
            hung_up = bool(events.get(master, 0) & select.POLLHUP)
            if not hung_up and not self.opened:
                self.opened = True
                self.boot_at = now + self.BOOT_S  # the reset line pulled: the board reboots
            elif hung_up and self.opened:
                self.opened = False
        if self.boot_at is not None and now >= self.boot_at:
            self.boot_at = None
            self.restart()
            sim_out = self.sim.stdout
            assert sim_out is not None
        if master is None and now - self.asked_at >= self.ASK_EVERY_S:
            self.asked_at = now
            self._to_sim(b"?")  # unplugged: the helper watches the board stand idle
        readable = [sim_out] + ([master] if master is not None else [])
        try:
            ready, _, _ = select.select(readable, [], [], 0.02)
        except (InterruptedError, ValueError, OSError):
            return
        if master is not None and master in ready:
            try:
                data = os.read(master, 4096)
            except (BlockingIOError, OSError):
                data = b""
                time.sleep(0.01)  # hung up: nobody has the port open
            if data and self.boot_at is None:
                self.log.from_host(data)
                self._to_sim(data)
        if sim_out in ready:
            try:
                data = os.read(sim_out.fileno(), 4096)
            except (BlockingIOError, OSError):
                data = b""
            if data:
                self.log.from_device(data)
                if self.master is not None and (self.opened or not self.restart_on_open):
                    with contextlib.suppress(OSError):
                        os.write(self.master, data)

    def _to_sim(self, data: bytes) -> None:
        assert self.sim.stdin is not None
        with contextlib.suppress(BrokenPipeError, OSError):
            self.sim.stdin.write(data)

    def close(self) -> None:
        self._stop_sim()
        self.log.close()
        if self.steps_file is not None:
            self.steps_file.close()
        self.unplug()


def _poll(fd: int) -> list[tuple[int, int]]:
    poller = select.poll()
    poller.register(fd, select.POLLIN | select.POLLHUP)
    return poller.poll(0)


def serve(exe: Path, workdir: Path, link: Path | None = None, restart_on_open: bool = False) -> int:
    """Bridge a pty to the simulator until SIGTERM; the exit status.

    SIGUSR1 unplugs the board's USB port, SIGUSR2 plugs it back (see :class:`Board`).
    """
    stopping = False
    wanted: list[str] = []

    def stop(signum: int, frame: FrameType | None) -> None:
        nonlocal stopping
        stopping = True

    signal.signal(signal.SIGTERM, stop)
    signal.signal(signal.SIGINT, stop)
    signal.signal(signal.SIGUSR1, lambda *_: wanted.append("unplug"))
    signal.signal(signal.SIGUSR2, lambda *_: wanted.append("plug"))
    board = Board(exe, workdir, link, restart_on_open)
    print(board.path, flush=True)
    try:
        while not stopping and board.sim.poll() is None:
            while wanted:
                what = wanted.pop(0)
                if what == "unplug" and board.master is not None:
                    board.unplug()
                elif what == "plug" and board.master is None:
                    board.plug()
            board.step()
    finally:
        board.close()
    return 0


def start(
    exe: Path,
    workdir: Path,
    link: Path | None = None,
    *,
    restart_on_open: bool = False,
    steps: Path | None = None,
    fresh: bool = True,
) -> subprocess.Popen[bytes]:
    """The bridge in its own process, its first output line the device path.

    ``link``: the port also appears there (and there again once plugged back);
    ``restart_on_open``: the board restarts whenever the port is opened;
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
    extra = [] if link is None else ["--link", str(link)]
    if restart_on_open:
        extra.append("--restart-on-open")
    return subprocess.Popen(
        [sys.executable, "-m", "tests.helpers.grbl_sim", str(exe), str(workdir), *extra],
        cwd=root,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.DEVNULL,
    )


def cpu_seconds(pid: int) -> float:
    """Processor time the process ``pid`` and its children (the simulator) have used so far.

    The simulator runs without pause, so this is how far it has got: on a busy
    computer it falls behind real time, and a test's waits are measured in it.
    0.0 once the process is gone.
    """
    proc = Path("/proc")
    try:
        fields = (proc / str(pid) / "stat").read_text().rsplit(")", 1)[1].split()
        children = (proc / str(pid) / "task" / str(pid) / "children").read_text().split()
    except OSError:
        return 0.0
    ticks = int(fields[11]) + int(fields[12])
    return ticks / os.sysconf("SC_CLK_TCK") + sum(cpu_seconds(int(child)) for child in children)


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
    _args = sys.argv[1:]
    _link = Path(_args[_args.index("--link") + 1]) if "--link" in _args else None
    sys.exit(serve(Path(_args[0]), Path(_args[1]), _link, "--restart-on-open" in _args))
