"""Benchmark (printed, never asserted): starting a million-line job near its end ("Run from…").

The state the file has reached at line 999 000 (units, modes, feed, its own
``G92``) is read from the 998 999 lines before it.  The window works it out on
a worker thread (:mod:`widgets.jobs.start_planning`); the GUI thread then only
starts the runner, which finds the plan remembered.  Printed: the plan's time
(a worker's, best of 3) and the GUI thread's time for the start with the plan
worked out first, and without it (what the GUI thread spent before the worker).
"""

from __future__ import annotations

import tempfile
import threading
import time
from pathlib import Path

#: The line the start is chosen at.
START_LINE = 999_000


def _write_strokes(path: Path, lines: int) -> None:
    """Plotter strokes of 47 ``G1`` lines between a pen down and up (``tools/benchmark.py``'s
    million-line file, written again here)."""
    import random

    rng = random.Random(1)
    out = ["G21", "G90"]
    while len(out) < lines:
        out.append(f"G0 X{rng.uniform(0, 290):.3f} Y{rng.uniform(0, 190):.3f}")
        out.append("M3 S1000")
        out += [
            f"G1 X{rng.uniform(0, 290):.3f} Y{rng.uniform(0, 190):.3f} F3000" for _ in range(47)
        ]
        out.append("M5")
    path.write_text("\n".join(out[:lines]) + "\n", encoding="ascii")


def _gui_start_s(path: Path, plan_first: bool) -> float:
    """Seconds ``JobRunner.start_from`` takes on the GUI thread at :data:`START_LINE`."""
    from app.jobs.loaders import JobOptions, load_job
    from app.jobs.run.runner import JobRunner, JobState
    from app.jobs.run.start_point import operation_at_line, plan_start
    from app.profiles import load_profile
    from tests.helpers.harness import StationHarness

    profile = load_profile("grbl-plotter")
    axes = [axis.name for axis in profile.axes]
    harness = StationHarness(profile)
    try:
        harness.connect()
        harness.run(0.3)
        program = load_job(path, axes, JobOptions(gcode=profile.gcode))
        with tempfile.TemporaryDirectory() as folder:
            runner = JobRunner(harness.station, Path(folder))
            if runner.load(program):
                raise RuntimeError("the million-line file was refused")
            index = operation_at_line(program, START_LINE)
            if plan_first:
                worker = threading.Thread(target=plan_start, args=(program, index, axes))
                worker.start()
                worker.join()
            start = time.perf_counter()
            runner.start_from(index)
            took = time.perf_counter() - start
            if runner.state is not JobState.RUNNING:
                raise RuntimeError(f"not started: {runner.state}")
            runner.abort()
            harness.run(0.2)
            runner.deleteLater()
    finally:
        harness.close()
    return took


def bench_start_from_1m() -> list[str]:
    from PySide6.QtWidgets import QApplication

    from app.jobs.loaders import JobOptions, load_job
    from app.jobs.run import start_point
    from app.profiles import load_profile

    QApplication.instance() or QApplication([])
    profile = load_profile("grbl-plotter")
    axes = [axis.name for axis in profile.axes]
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "synthetic-1m.gcode"
        _write_strokes(path, 1_000_000)
        program = load_job(path, axes, JobOptions(gcode=profile.gcode))
        index = start_point.operation_at_line(program, START_LINE)
        plans = []
        for k in range(3):  # three starts, each worked out afresh (the last is remembered)
            start = time.perf_counter()
            start_point.plan_start(program, index - k, axes)
            plans.append(time.perf_counter() - start)
        del program
        with_plan = _gui_start_s(path, plan_first=True)
        without = _gui_start_s(path, plan_first=False)
    return [
        f"start_from_1m: a 1,000,000-line file started at line {START_LINE:,}: the state "
        f"there worked out in {min(plans) * 1000:.0f} ms (best of 3, on a worker thread); "
        f"the GUI thread's start {with_plan * 1000:.1f} ms with it worked out first "
        f"(goal <= 100 ms; {without * 1000:.0f} ms when the GUI thread works it out itself)"
    ]


if __name__ == "__main__":
    for line in bench_start_from_1m():
        print(line)
