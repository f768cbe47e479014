"""G7-11: the emulated GRBL plotter and the estimate plan as GRBL 1.1 plans (issue 34).

The judge is grbl-sim, GRBL's own planner and step-segment preparation
compiled for the PC, fed each program by a perfect character-counting host
(a file on its standard input).  Every figure is machine time from simulated
clocks (grbl-sim's step report, the emulator's :class:`ManualClock`, the
estimate's arithmetic), never the wall clock: a loaded computer makes the test
slower, not different.  The cases are issue 34's, shortened to run in a minute
or two; ``python tools/benchmark.py`` runs them at full length (1500 x 0.1 mm,
a 200-segment zigzag, 100 arcs, 400 lines of a real file) and prints the figures.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests.helpers import grbl_sim_timing

STEPS_PER_MM = 80  # grbl_sim_timing.SETTINGS: the grbl-plotter profile's
TOLERANCE = 0.05
REAL_FILE = Path("realdata") / "gcode" / "Escriba_gcodetools_calibration.gcode"


def _end_mm(program: list[str]) -> tuple[float, float]:
    """The last X and Y the program names (each line here names both or only X)."""
    x = y = 0.0
    for line in program:
        for word in line.split():
            if word[0] == "X":
                x = float(word[1:])
            elif word[0] == "Y":
                y = float(word[1:])
    return x, y


CASES = {
    "collinear 150 x 0.1 mm at F6000": grbl_sim_timing.collinear(150),
    "zigzag of 24 x 2 mm with 90 degree corners": grbl_sim_timing.zigzag(24),
    "12 half circles G2/G3 of 2 mm radius": grbl_sim_timing.arcs(12),
}


@pytest.mark.parametrize("name", [*CASES, "head of a real file"])
def test_g7_11_emulator_and_estimate_take_grbls_time_within_5_percent(
    name: str, timing_sim: Path, data_dir: Path
) -> None:
    program = (
        grbl_sim_timing.motion_lines(data_dir / REAL_FILE, limit=40)
        if name == "head of a real file"
        else CASES[name]
    )
    grbl = grbl_sim_timing.grbl_sim_seconds(timing_sim, program)
    # grbl-sim ran the whole program: it ends where the program ends (whole steps).
    x, y = _end_mm(program)
    assert grbl.end_steps[:2] == (round(x * STEPS_PER_MM), round(y * STEPS_PER_MM))
    assert grbl.seconds > 0.3  # a run long enough for 5 % to mean something
    emulated = grbl_sim_timing.emulator_seconds(program)
    estimated = grbl_sim_timing.estimate_seconds(program)
    assert emulated / grbl.seconds == pytest.approx(1.0, abs=TOLERANCE), (emulated, grbl)
    assert estimated / grbl.seconds == pytest.approx(1.0, abs=TOLERANCE), (estimated, grbl)


def test_g7_11_the_step_report_is_read_from_the_first_step_to_the_last() -> None:
    """Samples before the first step and the closing sample bound the motion."""
    report = (
        "# block number 0\n"
        "     1.00100 0, 0, 0, 0\n"
        "     1.00150 0, 0, 0, 0\n"
        "     1.00200 3, 0, 0, 0\n"
        "# block number 1\n"
        "     1.20000 80, 8, 0, 0\n"
        "     1.25000 80, 8, 0, 0\n"
    )
    motion = grbl_sim_timing.step_report_motion(report)
    assert motion.seconds == pytest.approx(1.2 - 1.0015)
    assert motion.end_steps == (80, 8, 0)
