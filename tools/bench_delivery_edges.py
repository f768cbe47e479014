"""Where the delivery row's job spends its time besides the wire: its start and its end.

``tools/benchmark.py --only gcode_delivery_edges``.  The delivery row
(:func:`tools.bench_streaming.bench_gcode_delivery`) compares whole times,
which on a loaded machine swing by seconds from run to run with the stream
itself; this row runs the same job once more and times its two ends on the
station's own clock, where they happen:

* start: from Run to the first line of the file written, through the
  set-up (``G90 G21 G17``, ``$G``) and the ``[GC:…]`` answer read;
* end: from the last answer read to the job done (the machine seen idle),
  through the ``?`` asked for it.

The points are taken by wrapping the link's writes, the feeder's reads and
the runner's start and finish for this run only (undone after it): each
wrapper costs a function call per write or read, so this row's job time is
not the delivery row's figure.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from typing import Any

from tools.bench_streaming import GRBL_PROFILE, JOB_LINES, grbl_lines, job_run


@contextmanager
def _wrapped(owner: type, name: str, before: Callable[..., None]) -> Iterator[None]:
    """``owner.name`` calls ``before`` with its arguments first, until the block ends."""
    original = getattr(owner, name)

    def wrapper(self: object, *args: Any, **kwargs: Any) -> Any:
        before(*args)
        return original(self, *args, **kwargs)

    setattr(owner, name, wrapper)
    try:
        yield
    finally:
        setattr(owner, name, original)


def bench_gcode_delivery_edges() -> list[str]:
    """The delivery row's job, its start and end timed where they happen (see the module)."""
    from contextlib import ExitStack

    from app.jobs.run.driver_side import DriverSide
    from app.jobs.run.runner import JobRunner
    from app.link import Link
    from app.machines.gcode.feeder import LineFeeder

    points: dict[str, float] = {}
    asked: list[float] = []

    def wrote(data: bytes) -> None:
        now = time.perf_counter()
        if "run" in points and "first" not in points and b"G1X" in data:
            points["first"] = now
        if data == b"?" and "last ok" in points:
            asked.append(now)

    def read(data: bytes) -> None:
        if "run" not in points:
            return
        if b"[GC:" in data and "modes" not in points:
            points["modes"] = time.perf_counter()
        if b"ok" in data:
            points["last ok"] = time.perf_counter()
            asked.clear()

    with ExitStack() as stack:
        stack.enter_context(
            _wrapped(JobRunner, "start", lambda: points.setdefault("run", time.perf_counter()))
        )
        stack.enter_context(
            _wrapped(DriverSide, "finish", lambda: points.setdefault("done", time.perf_counter()))
        )
        stack.enter_context(_wrapped(Link, "write", lambda data: wrote(bytes(data))))
        stack.enter_context(_wrapped(Link, "write_from_tap", lambda parts: wrote(b"".join(parts))))
        stack.enter_context(_wrapped(LineFeeder, "receive", read))
        job = job_run(grbl_lines(JOB_LINES), GRBL_PROFILE)

    def ms(a: str, b: str | float) -> str:
        end = points[b] if isinstance(b, str) else b
        return f"{(end - points[a]) * 1000:.1f} ms"

    ask = ms("last ok", asked[0]) if asked else "none"
    return [
        f"the delivery row's job once more ({JOB_LINES:,} lines, {job.elapsed:.2f} s with the "
        "timing hooks), its two ends on the station's clock:",
        f"  start, Run to the file's first line written: {ms('run', 'first')} (the set-up's "
        f"[GC:…] read at {ms('run', 'modes')}); end, last answer read to the job done: "
        f"{ms('last ok', 'done')} ('?' written at {ask}) {job.load}",
    ]
