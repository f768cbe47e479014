"""Issue 33: a feed override of 50 % on grbl-sim and on the emulator, in simulated time.

Prints ``G1 X50 F600``'s motion time at 100 % and after five -10 % bytes, on
real GRBL 1.1h (grbl-sim) and on the emulated GRBL plotter, and the Ov: each
reported (:mod:`tests.helpers.grbl_sim_overrides`).  Needs a C compiler and
make.  ``python tools/bench_overrides.py``.
"""

from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from tests.helpers import grbl_sim, grbl_sim_timing  # noqa: E402
from tests.helpers.grbl_sim_overrides import HALF, MOVE, run_emulator, run_sim  # noqa: E402


def bench_feed_override() -> list[str]:
    if grbl_sim.compiler() is None:
        return ["feed override vs grbl-sim: skipped (no C compiler and make)"]
    exe = grbl_sim_timing.build(ROOT / "tests" / "third_party" / "grbl")
    full_sim, _ = run_sim(exe, b"")
    half_sim, replies = run_sim(exe, HALF)
    full_emu, _ = run_emulator(b"")
    half_emu, reports = run_emulator(HALF)
    ov_sim = next((w for w in replies.replace("|", " ").split() if w.startswith("Ov:")), "-")
    ov_emu = next((w for r in reports for w in r.replace("|", " ").split() if "Ov:" in w), "-")
    return [
        f"{MOVE}: grbl-sim {full_sim:.3f} s at 100 %, {half_sim:.3f} s after -10 % x 5 "
        f"({ov_sim}), ratio {half_sim / full_sim:.3f}",
        f"{MOVE}: emulator {full_emu:.3f} s at 100 %, {half_emu:.3f} s after -10 % x 5 "
        f"({ov_emu.rstrip('>')}), ratio {half_emu / full_emu:.3f}; "
        f"emulator / grbl-sim at 50 %: {half_emu / half_sim:.4f}",
    ]


if __name__ == "__main__":
    for line in bench_feed_override():
        print(line)
