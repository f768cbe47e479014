"""Benchmark (printed, never asserted): reading a file's own G92 offset when a job resumes.

Resume runs on the GUI thread, so the scan of the lines before the resume
point (:func:`app.jobs.run.gcode_stream.file_offset`) must stay well under
100 ms on a large file: 200 000 moves with a ``G92`` or ``G92.1`` every 1000.
"""

from __future__ import annotations

import tempfile
import time
from pathlib import Path


def bench_resume_file_offset() -> list[str]:
    from app.jobs.loaders import JobOptions, load_job
    from app.jobs.run.gcode_stream import file_offset
    from app.profiles import load_profile

    profile = load_profile("grbl-plotter")
    lines = ["G21 G90", "G1 F3000"]
    for k in range(200_000):
        lines.append(f"G1 X{(k % 100) * 0.5:.3f} Y{(k % 77) * 0.5:.3f}")
        if k % 1000 == 999:
            lines.append("G92 X0 Y0" if k % 2000 == 999 else "G92.1")
    with tempfile.TemporaryDirectory() as folder:
        path = Path(folder) / "offsets.gcode"
        path.write_text("\n".join(lines) + "\n", encoding="utf-8")
        program = load_job(
            path, ["X", "Y"], JobOptions(gcode=profile.gcode, machine_title=profile.title)
        )
    times = []
    for _ in range(5):
        start = time.perf_counter()
        file_offset(program, len(program) - 1, ["X", "Y"])
        times.append(time.perf_counter() - start)
    return [
        f"resume_file_offset: {len(program)} operations, 200 G92/G92.1 lines: "
        f"{min(times) * 1000:.1f} ms (best of 5; goal < 100 ms on the GUI thread)"
    ]


if __name__ == "__main__":
    for line in bench_resume_file_offset():
        print(line)
