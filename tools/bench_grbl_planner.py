"""G7-11: the GRBL planner cases of issue 34 on grbl-sim, the emulator and the estimate.

Full length (the suite's ``tests/e2e/test_grbl_planner_vs_grbl_sim.py`` runs them
shortened): 1500 collinear 0.1 mm moves at F6000, a 200-segment 2 mm zigzag with
90° corners, 100 half circles (``G2``/``G3``, ``$12=0.002``), and the first 400
motion lines of the gcodetools file.  Every figure is machine time from a
simulated clock (:mod:`tests.helpers.grbl_sim_timing`); only the last column,
how long grbl-sim took, is wall time.  Needs a C compiler and make (grbl-sim is
built once into the cache).  Run by ``tools/benchmark.py``.
"""

from __future__ import annotations

import time
from pathlib import Path

from tests.helpers import grbl_sim, grbl_sim_timing

ROOT = Path(__file__).resolve().parent.parent
REAL_FILE = ROOT / "tests" / "data" / "realdata" / "gcode" / "Escriba_gcodetools_calibration.gcode"


def bench_grbl_planner_vs_grbl_sim() -> list[str]:
    if grbl_sim.compiler() is None:
        return ["GRBL planner vs grbl-sim: skipped (no C compiler and make)"]
    exe = grbl_sim_timing.build(ROOT / "tests" / "third_party" / "grbl")
    cases = [
        ("1500 x 0.1 mm at F6000", grbl_sim_timing.collinear(1500)),
        ("zigzag 200 x 2 mm, 90 deg", grbl_sim_timing.zigzag(200)),
        ("100 half circles r 2 mm", grbl_sim_timing.arcs(100)),
        ("gcodetools file, 400 lines", grbl_sim_timing.motion_lines(REAL_FILE, limit=400)),
    ]
    lines = [
        "GRBL planner vs grbl-sim (machine time, s; ratio to grbl-sim):",
        f"  {'case':28} {'grbl-sim':>9} {'emulator':>9} {'ratio':>6} "
        f"{'estimate':>9} {'ratio':>6} {'wall':>7}",
    ]
    for name, program in cases:
        began = time.perf_counter()
        grbl = grbl_sim_timing.grbl_sim_seconds(exe, program).seconds
        wall = time.perf_counter() - began
        emulated = grbl_sim_timing.emulator_seconds(program)
        estimated = grbl_sim_timing.estimate_seconds(program)
        lines.append(
            f"  {name:28} {grbl:9.3f} {emulated:9.3f} {emulated / grbl:6.3f} "
            f"{estimated:9.3f} {estimated / grbl:6.3f} {wall:6.0f}s"
        )
    return lines


if __name__ == "__main__":
    print("\n".join(bench_grbl_planner_vs_grbl_sim()))
