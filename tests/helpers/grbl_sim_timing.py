"""Motion time of one G-code program on grbl-sim, on the emulator and in the estimate (G7-11).

All three are timed by a simulated clock, never by the wall clock, so a loaded
computer changes how long a run takes but not its figure:

- **grbl-sim** reads the program from a file on its standard input.  It takes a
  byte only while GRBL's receive buffer has room, so it is a perfect
  character-counting host.  Its step report (``-r``, written to ``-s``) gives
  the machine position against simulated time; the motion time is from the
  last sample at the starting position to the first sample at the final one.
  grbl-sim runs its GRBL thread and its simulated-hardware thread side by side;
  the copy built here (:func:`build`) has its receive ring wrapped as GRBL's and
  its hardware thread paced in short bursts (:data:`RING_FIX`,
  :data:`PACE_FIX`), so the figure is the same on an idle or a loaded computer.
- **The emulator** (``GcodeFirmware`` with the ``grbl-plotter`` configuration)
  runs on a :class:`ManualClock`, fed by a character-counting host, one 5 ms
  control cycle at a time.
- **The estimate** is ``estimate_gcode`` on the ``grbl-plotter`` profile.

The same GRBL settings go to grbl-sim and the emulator (:data:`SETTINGS`: the
profile's 80 steps/mm, 100 mm/s and 1000 mm/s² per axis, ``$11=0.010``,
``$12=0.002``); ``$1=255`` keeps GRBL from waiting its stepper idle delay at
the end, which the emulator does not model and which is not motion.
"""

from __future__ import annotations

import math
import shutil
import subprocess
import tempfile
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from tests.helpers import grbl_sim

#: grbl-sim's stand-in for the receive interrupt wraps GRBL's receive ring at 128, but
#: GRBL 1.1's ring has ``RX_BUFFER_SIZE + 1`` = 129 slots (``serial.c``): when the
#: buffer is full the simulator still takes a byte from its input, and GRBL's interrupt
#: drops it.  A character-counting host never fills the buffer, so the pty tests never
#: meet it; a file on standard input fills it all the time, and lines lose characters
#: (``error:1``/``error:2`` mid-file, or a run that ends early).  The copy built here
#: for timing has that one line wrapped as GRBL wraps it; GRBL's own source is untouched.
RING_FIX = (
    "  if (head==RX_BUFFER_SIZE) { head = 0; }",
    "  if (head==RX_BUFFER_SIZE+1) { head = 0; }",
)
#: grbl-sim's hardware thread catches up with the wall clock (times ``-t``) in one burst
#: whenever it gets the processor, and only then yields to GRBL's thread.  On a busy
#: computer a burst can outlast GRBL's 5 step segments, and the motion stops while
#: GRBL's main loop waits for the processor: a stall a real board never has, seen as a
#: 0.35 to 0.40 s spread on one 0.35 s program.  The timing copy caps a burst at
#: :data:`BURST_TICKS` (25 µs of machine time) and yields after it, so GRBL's main loop
#: (parsing, planning, step-segment preparation) gets its turn at least that often, as the
#: interrupts of a real board leave it; machine time then runs as fast as both threads can
#: go, never ahead of GRBL's own loop.
BURST_TICKS = 400
PACE_FIX = (
    "    simulated_ticks += F_CPU/1e9*ns_elapsed;",
    "    simulated_ticks += F_CPU/1e9*ns_elapsed;\n"
    f"    if (simulated_ticks > sim.masterclock + {BURST_TICKS}) "
    f"{{ simulated_ticks = sim.masterclock + {BURST_TICKS}; }}",
)

#: The same on both boards: the grbl-plotter profile's limits (X and Y) and GRBL's defaults.
SETTINGS = (
    "$1=255",
    "$11=0.010",
    "$12=0.002",
    "$100=80",
    "$101=80",
    "$110=6000",
    "$111=6000",
    "$120=1000",
    "$121=1000",
)
#: After the program: a dwell, which GRBL answers only once the motion has ended, then
#: more blank bytes than GRBL's receive buffer holds, so that the end of the input
#: (which ends the simulator as soon as GRBL stands idle) is read only after that.
TAIL = "G4 P0\n" + "\n" * 300
SAMPLE_S = 0.0005
CYCLE = 0.005


def build(source: Path) -> Path:
    """``grbl_sim.exe`` with :data:`RING_FIX`, built once beside the pty tests' copy."""
    import fcntl

    grbl_sim.build(source)  # the default EEPROM
    out = grbl_sim.cache_dir() / f"timing-{BURST_TICKS}"
    out.mkdir(parents=True, exist_ok=True)
    exe = out / "grbl" / grbl_sim.SIM_DIR / "grbl_sim.exe"
    with open(out / "build.lock", "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if exe.is_file():
            return exe
        tree = out / "grbl"
        if tree.exists():
            shutil.rmtree(tree)
        shutil.copytree(source, tree)
        for name, (old, new) in (("serial.c", RING_FIX), ("simulator.c", PACE_FIX)):
            source_file = tree / grbl_sim.SIM_DIR / name
            text = source_file.read_text(encoding="ascii")
            if text.count(old) != 1:
                raise RuntimeError(f"grbl-sim's {name} is not the one this patch was written for")
            source_file.write_text(text.replace(old, new), encoding="ascii")
        result = subprocess.run(
            ["make", "-C", str(tree / grbl_sim.SIM_DIR), "new", "FLAGS=-g -O3 -fcommon"],
            capture_output=True,
            text=True,
            timeout=600,
        )
        if result.returncode != 0 or not exe.is_file():
            raise RuntimeError(f"grbl-sim did not build:\n{result.stdout[-2000:]}{result.stderr}")
        return exe


def collinear(segments: int, step: float = 0.1, feed: float = 6000.0) -> list[str]:
    """``segments`` short moves on one line (issue 34: 1500 x 0.1 mm at F6000)."""
    return ["G21 G90", f"G1 F{feed:g}"] + [f"G1 X{step * (i + 1):.3f}" for i in range(segments)]


def zigzag(segments: int, size: float = 2.0, feed: float = 6000.0) -> list[str]:
    """A square wave of ``size`` mm sides: a 90° corner between every two moves."""
    lines = ["G21 G90", f"G1 F{feed:g}"]
    x = y = 0.0
    for i in range(segments):
        if i % 2 == 0:
            x += size
        else:
            y = size if y == 0.0 else 0.0
        lines.append(f"G1 X{x:.3f} Y{y:.3f}")
    return lines


def arcs(count: int, radius: float = 2.0, feed: float = 3000.0) -> list[str]:
    """Half circles alternately above (``G2``) and below (``G3``) the line Y10."""
    lines = ["G21 G90", "G0 Y10", f"G1 F{feed:g}"]
    for i in range(count):
        x = 2 * radius * (i + 1)
        lines.append(f"{'G2' if i % 2 == 0 else 'G3'} X{x:.3f} Y10 I{radius:g} J0")
    return lines


def motion_lines(path: Path, limit: int | None = None) -> list[str]:
    """A real file's motion: its G0/G1/G2/G3 lines without Z (the profile has no Z axis,
    the plotter lifts its pen with M3/M5), comments and everything else left out."""
    out: list[str] = ["G21 G90"]
    for raw in path.read_text(encoding="ascii", errors="replace").splitlines():
        text = raw.split(";", 1)[0]
        while "(" in text:
            head, _, rest = text.partition("(")
            text = head + rest.partition(")")[2]
        words = text.upper().split()
        if not words or words[0] not in ("G0", "G00", "G1", "G01", "G2", "G02", "G3", "G03"):
            continue
        kept = [w for w in words if not w.startswith("Z")]
        if any(w[0] in "XYIJ" for w in kept[1:]):
            out.append(" ".join(kept))
        if limit is not None and len(out) > limit:
            break
    return out


@dataclass(frozen=True)
class SimMotion:
    """grbl-sim's motion: its machine time and where it ended, in steps (X, Y, Z)."""

    seconds: float
    end_steps: tuple[int, ...]


def grbl_sim_seconds(
    exe: Path, program: Sequence[str], time_scale: float = 100.0, timeout: float = 3600.0
) -> SimMotion:
    """grbl-sim's simulated motion time for ``program`` (see the module's docstring).

    ``time_scale`` (``-t``) only says how fast machine time may run against the wall
    clock; with :data:`PACE_FIX` the figure does not depend on it."""
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", folder / "EEPROM.DAT")
        stream = folder / "program.nc"
        stream.write_text("\n".join([*SETTINGS, *program]) + "\n" + TAIL, encoding="ascii")
        steps = folder / "steps.txt"
        prefix = ["taskset", "-c", "0"] if shutil.which("taskset") else []
        with stream.open("rb") as stdin:
            result = subprocess.run(
                [
                    *prefix,
                    str(exe),
                    "-n",
                    "-t",
                    str(time_scale),
                    "-b",
                    "/dev/null",
                    "-r",
                    str(SAMPLE_S),
                    "-s",
                    str(steps),
                ],
                cwd=folder,
                stdin=stdin,
                capture_output=True,
                timeout=timeout,
            )
        if result.returncode != 0:
            raise RuntimeError(f"grbl-sim ended with status {result.returncode}")
        replies = result.stdout.decode("ascii", "replace").split()
        errors = [r for r in replies if r.startswith("error")]
        if errors:
            raise RuntimeError(f"grbl-sim refused lines: {errors[:5]}")
        return step_report_motion(steps.read_text(encoding="ascii"))


def step_report_motion(report: str) -> SimMotion:
    """From the last sample at the start position to the first at the final position."""
    samples: list[tuple[float, tuple[int, ...]]] = []
    for line in report.splitlines():
        if not line.strip() or line.startswith("#"):
            continue
        t, _, rest = line.strip().partition(" ")
        samples.append((float(t), tuple(int(v) for v in rest.replace(",", " ").split()[:3])))
    if not samples:
        raise RuntimeError("grbl-sim reported no motion")
    first, final = samples[0][1], samples[-1][1]
    start = samples[0][0]
    for t, where in samples:
        if where != first:
            break
        start = t
    end = next(t for t, where in samples if where == final)
    return SimMotion(end - start, final)


def emulator_seconds(program: Sequence[str]) -> float:
    """The emulated GRBL plotter's motion time on a manual clock (first move to last)."""
    from protocol.clock import ManualClock
    from protocol.emulator.gcode_firmware import GcodeFirmware, grbl_plotter_config

    clock = ManualClock(start=0.0)
    fw = GcodeFirmware(clock, grbl_plotter_config())
    out = bytearray()
    fw.set_output(out.extend)
    queue = [line.encode("ascii") + b"\n" for line in [*SETTINGS, *program]]
    unanswered: list[int] = []
    settings_done = len(SETTINGS)
    limit = 3600.0
    clock.advance(CYCLE)
    fw.run_until(clock.now())
    out.clear()
    while queue or unanswered or fw.busy or fw.state != "Idle":
        while queue and sum(unanswered) + len(queue[0]) <= 127:
            line = queue.pop(0)
            unanswered.append(len(line))
            fw.receive(line)
        clock.advance(CYCLE)
        fw.run_until(clock.now())
        for reply in bytes(out).decode("ascii").splitlines():
            if reply == "ok" or reply.startswith("error"):
                if reply.startswith("error"):
                    raise RuntimeError(f"the emulator refused a line: {reply}")
                unanswered.pop(0)
        out.clear()
        if clock.now() > limit:
            raise RuntimeError(f"the emulator still {fw.state} after {limit} s")
    moves = [e for e in fw.event_log if e["event"] == "move"]
    replies = [e for e in fw.event_log if e["event"] == "reply"]
    began = float(replies[settings_done]["t"])
    # The first move starts in the cycle that parsed the program's first lines.
    return float(moves[-1]["t"]) - began


def estimate_seconds(program: Sequence[str]) -> float:
    """``estimate_gcode`` on the grbl-plotter profile."""
    from app.jobs.estimate.gcode import estimate_gcode
    from app.jobs.formats.gcode.program import GcodeProgram
    from app.jobs.loaders import JobOptions, load_job
    from app.profiles import load_profile

    machine = load_profile("grbl-plotter")
    with tempfile.TemporaryDirectory() as work:
        path = Path(work) / "program.gcode"
        path.write_text("\n".join(program) + "\n", encoding="ascii")
        loaded = load_job(
            path,
            [axis.name for axis in machine.axes],
            JobOptions(gcode=machine.gcode, machine_title=machine.title),
        )
    assert isinstance(loaded, GcodeProgram)
    return estimate_gcode(loaded, machine).total_s


def ratio(a: float, b: float) -> float:
    return a / b if b > 0 else math.nan
