"""GRBL 1.1h's accessory field ``A:`` on grbl-sim and on the emulator, report by report.

``report.c`` writes ``|A:`` only in a report that carries ``Ov:`` (every 10th
idle, 20th busy, and at once after a spindle or coolant change: ``spindle_set_state``
sets ``report_ovr_counter`` to 0), ``S`` for the spindle on clockwise (M3), ``C``
counter-clockwise (M4), ``F`` for flood coolant, and leaves the field out with nothing
on; ``S0`` switches the PWM, and so the ``S``, off.  ``M3``/``M5`` synchronise the
planner first (``spindle_sync``), so their ``ok`` comes once the pen has moved.  The
station supervises the pen by exactly this (``app/machines/gcode/pen_watch.py``).

The same bytes go to both: each line, then a ``?``, each followed by more empty lines
than GRBL's receive buffer holds (read only once GRBL took the line before:
:mod:`tests.helpers.grbl_sim_overrides`).
"""

from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from pathlib import Path

from protocol.clock import ManualClock
from protocol.emulator.gcode_firmware import GcodeFirmware, grbl_plotter_config
from tests.helpers import grbl_sim, grbl_sim_timing
from tests.helpers.grbl_sim_overrides import PAD

#: Lines, each followed by a status report; several reports after some (the refresh count).
SEQUENCE = (
    "G1 X2 F3000",
    "M3 S1000",
    "G1 X4",
    "",
    "",
    "M5",
    "M4 S500",
    "S0",
    "S200",
    "M8",
    "M5",
    "M9",
    "M3 S1000",
    *([""] * 12),
    "M2",
    "",
)


def _program() -> bytes:
    out = b""
    for line in SEQUENCE:
        if line:
            out += line.encode("ascii") + PAD
        out += b"?" + PAD
    return out


def run_sim_bytes(exe: Path, program: bytes) -> str:
    """grbl-sim's replies to the timing settings, then ``program``."""
    settings = "\n".join(grbl_sim_timing.SETTINGS).encode("ascii") + b"\n"
    with tempfile.TemporaryDirectory() as work:
        folder = Path(work)
        shutil.copyfile(grbl_sim.cache_dir() / "EEPROM.DAT", folder / "EEPROM.DAT")
        stream = folder / "program.nc"
        stream.write_bytes(settings + program + grbl_sim_timing.TAIL.encode("ascii"))
        with stream.open("rb") as stdin:
            result = subprocess.run(
                [str(exe), "-n", "-t", "100", "-b", "/dev/null"],
                cwd=folder, stdin=stdin, capture_output=True, timeout=600, check=True,
            )  # fmt: skip
        return result.stdout.decode("ascii", "replace")


def run_emulator_bytes(program: bytes) -> list[str]:
    """The emulated GRBL plotter's status reports: the settings, then ``program`` a line or a
    byte each control cycle (an empty line: a cycle of its own)."""
    clock = ManualClock(start=0.0)
    fw = GcodeFirmware(clock, grbl_plotter_config())
    out = bytearray()
    fw.set_output(out.extend)
    chunks = [line.encode("ascii") for line in grbl_sim_timing.SETTINGS]
    for chunk in [*chunks, *program.split(b"\n")]:
        fw.receive(chunk + b"\n")
        clock.advance(grbl_sim_timing.CYCLE)
        fw.run_until(clock.now())
    return [r for r in out.decode("ascii").split() if r.startswith("<")]


def _fields(reports: list[str]) -> list[str]:
    """Each report's WCO:, Ov: and A: fields, as written (the rest differs in timing only)."""
    keep = re.compile(r"\|((?:WCO|Ov|A):[^|>]*)")
    return [" ".join(keep.findall(r)) for r in reports]


def test_the_accessory_field_comes_as_on_grbl_sim_report_by_report(timing_sim: Path) -> None:
    program = _program()
    sim = _fields([r for r in run_sim_bytes(timing_sim, program).split() if r.startswith("<")])
    emulated = _fields(run_emulator_bytes(program))
    assert len(sim) == len(SEQUENCE)
    assert emulated == sim
    # What GRBL said, so that the same change on both sides cannot pass unseen.
    by_line = dict(reversed(list(zip(SEQUENCE, sim, strict=True))))  # each line's first report
    assert by_line["M3 S1000"] == "Ov:100,100,100 A:S"  # at once after the change
    assert by_line["G1 X4"] == ""  # and not in the next report
    assert by_line["M4 S500"] == "Ov:100,100,100 A:C"
    assert by_line["S0"] == "Ov:100,100,100"  # S0: the PWM off, the field left out
    assert by_line["M8"] == "Ov:100,100,100 A:CF"
    assert by_line["M5"] == "Ov:100,100,100"  # the first M5: nothing on
    assert sim.count("Ov:100,100,100 A:S") == 3  # M3 twice, then the idle refresh (10th)
