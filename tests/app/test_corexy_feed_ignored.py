"""FIDELITY S1-01: the CoreXY plotter's firmware reads G0 and G1 alike and ignores F.

"Příkaz G0 a G1 je interpretován stejně"; the speed is the step interval set by
``M98`` ("nastav interval mezi kroky").  The emulator, the job's notes and the
estimate follow it: a file from vpype or Inkscape that carries F words runs,
and is timed, at the plotter's own speed.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.formats.gcode.program import GcodeProgram
from app.jobs.loaders import JobOptions, load_job
from app.profiles import load_profile
from protocol.clock import ManualClock
from protocol.emulator.gcode_firmware import GcodeFirmware, corexy_plotter_config

CYCLE = 0.005

WITH_F = """G21 G90
M3
G0 X10 Y5 F9000
M4
G1 X60 Y5 F120
G1 X60 Y45
M98 100
G1 X10 Y45 F6000
G0 X10 Y5
M3
G0 X0 Y0
"""


def _loaded(tmp_path: Path, text: str, name: str = "job.gcode") -> GcodeProgram:
    machine = load_profile("corexy-plotter")
    path = tmp_path / name
    path.write_text(text, encoding="ascii")
    program = load_job(
        path,
        [axis.name for axis in machine.axes],
        JobOptions(gcode=machine.gcode, machine_title=machine.title),
    )
    assert isinstance(program, GcodeProgram)
    return program


def _emulated_seconds(texts: list[str]) -> float:
    """The lines one after the other (the plotter answers once a line is done): to the end."""
    clock = ManualClock(start=0.0)
    fw = GcodeFirmware(clock, corexy_plotter_config())
    out = bytearray()
    fw.set_output(out.extend)
    clock.advance(CYCLE)
    fw.run_until(clock.now())
    out.clear()
    began = clock.now()
    for text in texts:
        fw.receive(text.encode("ascii") + b"\n")
        while b"\n" not in out:
            clock.advance(CYCLE)
            fw.run_until(clock.now())
        assert out.strip() == b"OK", (text, bytes(out))
        out.clear()
    moves = [e for e in fw.event_log if e["event"] == "move"]
    return float(moves[-1]["t"]) - began


def test_s1_01_a_file_with_f_words_is_told_the_plotter_ignores_them(tmp_path: Path) -> None:
    program = _loaded(tmp_path, WITH_F)
    (note,) = [n for n in program.notes if "ignores F" in n]
    assert "3 line(s)" in note and "M98" in note and "25 µs" in note
    plain = _loaded(tmp_path, "G0 X1\nG1 X2\n", "plain.gcode")
    assert all("ignores F" not in n for n in plain.notes)


def test_s1_01_the_estimate_ignores_f_and_follows_m98_as_the_emulator_does(
    tmp_path: Path,
) -> None:
    machine = load_profile("corexy-plotter")
    program = _loaded(tmp_path, WITH_F)
    estimated = estimate_gcode(program, machine).total_s
    stripped = _loaded(tmp_path, WITH_F.replace(" F9000", "").replace(" F120", ""), "b.gcode")
    # F means nothing: the same file without its F words is timed the same.
    assert estimate_gcode(stripped, machine).total_s == pytest.approx(estimated, rel=1e-12)
    # The emulator starts each line in the control cycle after the previous OK, so it
    # loses up to one cycle a line; the moves themselves are the estimate's, but for the
    # emulator's 0.00245 mm a step against the profile's 31.4 mm / 12800 (0.2 %).
    texts = [t for t in program.data.texts if t]
    emulated = _emulated_seconds(texts)
    assert estimated * 0.997 <= emulated <= estimated * 1.003 + len(texts) * CYCLE
    # At F120 (2 mm/s) the 50 mm stroke alone would take 25 s; at 40 000 steps/s the plotter
    # draws it in 0.5 s, and the last three moves after M98 100 at 10 000 steps/s take 4.7 s.
    assert 5.0 < estimated < 6.0
