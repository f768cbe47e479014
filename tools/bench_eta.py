"""The G-code estimate against the emulator's run time and against real GRBL (grbl-sim).

For each real file of ``tests/data/realdata/gcode`` as the GRBL plotter runs it
(``grbl-plotter`` profile, the station's translation of its pen commands):

* ``ETA``: :func:`app.jobs.estimate.gcode.estimate_gcode`;
* ``emulator``: the emulated GRBL board on a manual clock, fed by a
  character-counting sender as the station feeds it, from the first line
  parsed to the end of the last move;
* ``grbl-sim`` (only with ``STEPDECK_SLOW=1``, a C compiler and make: it runs
  at half of real time at best, so this takes a quarter of an hour or more):
  GRBL 1.1h itself with the profile's settings (80 steps/mm, 6000 mm/min,
  1000 mm/s², ``$11=0.010``) fed as the station feeds it, from its first
  planned block to the last step (its step log every 10 ms).

The files' ``G4`` lines are left out of all three: GRBL reads ``G4 P150`` as
150 s (the Unicorn file would wait 15 h), and a dwell adds the same time to
each anyway.  Run by ``tools/benchmark.py``.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

DATA = ROOT / "tests" / "data"
CYCLE = 0.005
#: GRBL's settings matching the grbl-plotter profile (and the emulated board).
GRBL_SETTINGS = (
    "$100=80", "$101=80", "$102=80", "$110=6000", "$111=6000", "$112=6000",
    "$120=1000", "$121=1000", "$122=1000", "$11=0.010", "$12=0.002",
)  # fmt: skip
_DWELL = re.compile(r"\s*[Gg]0*4(?![0-9.])")


def _lines_without_dwells(path: Path, directory: Path) -> Path:
    kept = [
        line for line in path.read_text(errors="replace").splitlines() if not _DWELL.match(line)
    ]
    out = directory / path.name
    out.write_text("\n".join(kept) + "\n", encoding="utf-8")
    return out


def _emulated_seconds(texts: list[str]) -> float:
    """The emulated GRBL board fed as the station feeds it (at most 127 bytes unanswered)."""
    from protocol.clock import ManualClock
    from protocol.emulator.gcode_firmware import GcodeFirmware

    clock = ManualClock(start=0.0)
    board = GcodeFirmware(clock)
    out = bytearray()
    board.set_output(out.extend)
    clock.advance(CYCLE)
    board.run_until(clock.now())  # the banner
    out.clear()
    lines = [text.encode("ascii") + b"\n" for text in texts]
    unanswered: list[int] = []
    sent = 0
    while sent < len(lines) or unanswered or board.busy or board.state != "Idle":
        while sent < len(lines) and sum(unanswered) + len(lines[sent]) <= 127:
            board.receive(lines[sent])
            unanswered.append(len(lines[sent]))
            sent += 1
        clock.advance(CYCLE)
        board.run_until(clock.now())
        for reply in bytes(out).decode("ascii").splitlines():
            if reply == "ok" or reply.startswith("error"):
                unanswered.pop(0)
        out.clear()
    events = board.event_log
    began = next(e["t"] for e in events if e["event"] == "reply")
    ended = [e["t"] for e in events if e["event"] == "move"][-1]
    return float(ended - began)


def _grbl_sim_seconds(exe: Path, texts: list[str], directory: Path) -> float:
    """GRBL's own planner and stepper: first block to last step, from its 10 ms step log.

    Fed as the station feeds a board (at most 127 bytes unanswered) through a
    pipe: with its whole input at once on a file it stalled mid-file here.
    """
    import select
    import time

    from tests.helpers import grbl_sim

    # From a written EEPROM (a first start without one plans moves it never runs).
    shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", directory / "EEPROM.DAT")
    steps = directory / "steps.out"
    # One core (BUILD.md: its two threads race on two), stdin unbuffered.
    prefix = ["taskset", "-c", "0"] if shutil.which("taskset") else []
    prefix += ["stdbuf", "-i0", "-oL"] if shutil.which("stdbuf") else []
    sim = subprocess.Popen(
        [*prefix, str(exe), "-n", "-t", "1", "-r", "0.01", "-s", str(steps), "-b", os.devnull],
        cwd=directory,
        stdin=subprocess.PIPE,
        stdout=subprocess.PIPE,
        bufsize=0,
    )
    assert sim.stdin is not None and sim.stdout is not None
    lines = [line.encode("ascii") + b"\n" for line in (*GRBL_SETTINGS, *texts)]
    unanswered: list[int] = []
    sent = 0
    received = b""
    deadline = time.monotonic() + 3600
    try:
        while sent < len(lines) or unanswered:
            while sent < len(lines) and sum(unanswered) + len(lines[sent]) <= 127:
                sim.stdin.write(lines[sent])
                unanswered.append(len(lines[sent]))
                sent += 1
            if select.select([sim.stdout], [], [], 0.5)[0]:
                received += os.read(sim.stdout.fileno(), 4096)
                *replies, rest = received.split(b"\n")
                received = rest
                for reply in replies:
                    text = reply.strip()
                    if (text == b"ok" or text.startswith(b"error")) and unanswered:
                        unanswered.pop(0)
            if time.monotonic() > deadline:
                raise RuntimeError(f"grbl-sim answered {sent - len(unanswered)} lines only")
        while time.monotonic() < deadline:  # until it reports Idle
            sim.stdin.write(b"?")
            time.sleep(1.0)
            if select.select([sim.stdout], [], [], 0.5)[0]:
                if b"<Idle" in os.read(sim.stdout.fileno(), 65536):
                    break
    finally:
        sim.terminate()
        sim.wait(timeout=10)
    samples: list[tuple[float, str]] = []
    for line in steps.read_text().splitlines():
        if line.startswith("#") or not line.strip():
            continue
        t, _, where = line.strip().partition(" ")
        samples.append((float(t), where.rsplit(",", 1)[0]))  # the spindle's PWM left out
    pairs = zip(samples[1:], samples, strict=False)
    moving = [t for (t, where), (_, before) in pairs if where != before]
    return moving[-1] - samples[0][0]


def bench_gcode_eta() -> list[str]:
    from app.jobs.estimate.gcode import estimate_gcode
    from app.jobs.formats.gcode.program import GcodeProgram
    from app.jobs.loaders import JobOptions, load_job
    from app.profiles import load_profile
    from tests.helpers import grbl_sim

    profile = load_profile("grbl-plotter")
    options = JobOptions(gcode=profile.gcode, machine_title=profile.title)
    slow = os.environ.get("STEPDECK_SLOW") == "1" and grbl_sim.compiler() is not None
    exe = grbl_sim.build(ROOT / "tests" / "third_party" / "grbl") if slow else None
    out = ["G-code ETA (grbl-plotter, junction planner; the files' G4 dwells left out):"]
    with tempfile.TemporaryDirectory() as name:
        directory = Path(name)
        for source in sorted((DATA / "realdata" / "gcode").glob("*.gcode")):
            path = _lines_without_dwells(source, directory)
            program = load_job(path, [axis.name for axis in profile.axes], options)
            assert isinstance(program, GcodeProgram)
            texts = [t for t in program.data.texts if t and not t.startswith("$")]
            eta = estimate_gcode(program, profile).total_s
            emulated = _emulated_seconds(texts)
            line = (
                f"  {source.name[:40]}: ETA {eta:.1f} s, emulator {emulated:.1f} s: "
                f"ETA / emulator {eta / emulated:.3f}"
            )
            if exe is not None:
                run = directory / f"sim-{source.stem}"
                run.mkdir()
                real = _grbl_sim_seconds(exe, texts, run)
                line += f"; grbl-sim {real:.1f} s: ETA / grbl-sim {eta / real:.3f}"
            out.append(line + " (goal: within 5 %)")
    if exe is None:
        out.append("  grbl-sim: set STEPDECK_SLOW=1 (needs cc and make; 15 min or more)")
    return out


if __name__ == "__main__":
    for text in bench_gcode_eta():
        print(text)
