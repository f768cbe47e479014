"""A move timed after override bytes on grbl-sim and on the emulator, in simulated time.

grbl-sim reads the program from a file on its standard input (a perfect
character-counting host, :mod:`tests.helpers.grbl_sim_timing`): it reads a byte as soon
as GRBL's receive buffer has room, so real-time bytes close together in the file reach
GRBL together, and bytes of one kind in one pass of its real-time loop count once (five
-10 % bytes one newline apart made ``Ov:90``).  So each byte here is followed by more
empty lines than the buffer holds: it is read only once GRBL has taken most of them, each
in a pass of its own.  The emulator gets the same bytes, a control cycle apart.  Used by
``tests/e2e/test_e2e_overrides_grbl_sim.py`` and ``tools/bench_overrides.py``.
"""

from __future__ import annotations

import shutil
import subprocess
import tempfile
from pathlib import Path

from protocol.clock import ManualClock
from protocol.emulator.gcode_firmware import GcodeFirmware, grbl_plotter_config
from protocol.gcode.overrides import FEED_MINUS_10
from tests.helpers import grbl_sim, grbl_sim_timing

MOVE = "G1 X50 F600"  # 5 s at 10 mm/s, 10 s at 50 %
#: More empty lines than GRBL's receive buffer holds: what follows is read after them.
PAD = b"\n" * 200
HALF = (FEED_MINUS_10 + PAD) * 5
#: Three status reports: the first after the reset carries WCO:, Ov: comes in the next.
REPORTS = (b"?" + PAD) * 3


def run_sim(exe: Path, before: bytes, move: str = MOVE) -> tuple[float, str]:
    """grbl-sim's motion time for ``move`` after ``before`` (override bytes), its replies."""
    settings = "\n".join(grbl_sim_timing.SETTINGS).encode("ascii") + b"\n"
    program = settings + before + REPORTS + move.encode("ascii") + b"\n"
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", folder / "EEPROM.DAT")
        stream = folder / "program.nc"
        stream.write_bytes(program + grbl_sim_timing.TAIL.encode("ascii"))
        steps = folder / "steps.txt"
        prefix = ["taskset", "-c", "0"] if shutil.which("taskset") else []
        with stream.open("rb") as stdin:
            result = subprocess.run(
                [*prefix, str(exe), "-n", "-t", "100", "-b", "/dev/null", "-r",
                 str(grbl_sim_timing.SAMPLE_S), "-s", str(steps)],
                cwd=folder, stdin=stdin, capture_output=True, timeout=600, check=True,
            )  # fmt: skip
        motion = grbl_sim_timing.step_report_motion(steps.read_text(encoding="ascii"))
        assert motion.end_steps[0] == round(float(move.split("X")[1].split()[0]) * 80)
        return motion.seconds, result.stdout.decode("ascii", "replace")


def run_emulator(before: bytes, move: str = MOVE) -> tuple[float, list[str]]:
    """The emulated GRBL plotter: ``move``'s time from its log, and its status reports."""
    clock = ManualClock(start=0.0)
    fw = GcodeFirmware(clock, grbl_plotter_config())
    out = bytearray()
    fw.set_output(out.extend)

    def cycle() -> None:
        clock.advance(grbl_sim_timing.CYCLE)
        fw.run_until(clock.now())

    cycle()
    for line in grbl_sim_timing.SETTINGS:
        fw.receive(line.encode("ascii") + b"\n")
        cycle()
    for chunk in (before + REPORTS).split(b"\n"):  # a byte or a line each cycle
        fw.receive(chunk + b"\n")
        cycle()
    fw.receive(move.encode("ascii") + b"\n")
    while fw.busy or fw.state != "Idle":
        cycle()
        assert clock.now() < 60.0
    moves = [e for e in fw.event_log if e["event"] == "move"]
    started = [e for e in fw.event_log if e["event"] == "reply" and e["line"] == move]
    reports = [r for r in out.decode("ascii").split() if r.startswith("<")]
    return float(moves[-1]["t"]) - float(started[0]["t"]), reports
