"""G2/G3 arcs flattened for the preview and the limit check: their inner vertices."""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np

from app.jobs.program import JobFileError

#: Largest chord error of a flattened arc (mm) and the fewest segments one gets.
ARC_TOLERANCE_MM = 0.02
MIN_ARC_SEGMENTS = 4
MAX_ARC_SEGMENTS = 20_000


def flatten_arc(
    file: str,
    number: int,
    code: str,
    start: list[float],
    target: Mapping[int, float],
    offsets: Mapping[str, float],
    clockwise: bool,
    columns: int,
) -> np.ndarray:
    """The inner vertices of an XY arc, chord error at most ARC_TOLERANCE_MM.

    ``start`` and ``target`` are machine positions by column (0: X, 1: Y), the
    result has ``columns`` columns; the other axes move linearly along the arc.
    """
    sx = 0.0 if math.isnan(start[0]) else start[0]
    sy = 0.0 if math.isnan(start[1]) else start[1]
    ex, ey = target[0], target[1]
    if "R" in offsets:
        radius = offsets["R"]
        dx, dy = ex - sx, ey - sy
        chord = math.hypot(dx, dy)
        if chord == 0.0:
            raise JobFileError(file, number, f"an R arc needs distinct ends: {code!r}")
        h2 = 4 * radius * radius - dx * dx - dy * dy
        if h2 < -1e-6 * max(1.0, radius * radius):
            raise JobFileError(file, number, f"arc radius too small: {code!r}")
        h = -math.sqrt(max(h2, 0.0)) / chord
        if not clockwise:
            h = -h
        if radius < 0:
            h = -h
        cx, cy = sx + 0.5 * (dx - dy * h), sy + 0.5 * (dy + dx * h)
    elif "I" in offsets or "J" in offsets:
        cx, cy = sx + offsets.get("I", 0.0), sy + offsets.get("J", 0.0)
    else:
        raise JobFileError(file, number, f"an arc needs I/J or R: {code!r}")
    if not all(math.isfinite(v) for v in (sx, sy, ex, ey, cx, cy)):
        raise JobFileError(file, number, f"arc coordinates too large to draw: {code!r}")
    r0 = math.hypot(sx - cx, sy - cy)
    r1 = math.hypot(ex - cx, ey - cy)
    a0 = math.atan2(sy - cy, sx - cx)
    a1 = math.atan2(ey - cy, ex - cx)
    if clockwise:
        sweep = (a0 - a1) % math.tau
    else:
        sweep = (a1 - a0) % math.tau
    if sweep < 1e-12 and "R" not in offsets:
        sweep = math.tau  # same start and end with a centre: a full circle
    radius = max(r0, r1)
    if radius > ARC_TOLERANCE_MM:
        step = 2 * math.acos(1 - ARC_TOLERANCE_MM / radius)
        # A radius so large that the step rounds to nothing gets the most segments.
        segments = math.ceil(sweep / step) if step > 0 else MAX_ARC_SEGMENTS
    else:
        segments = 1
    segments = min(max(segments, MIN_ARC_SEGMENTS), MAX_ARC_SEGMENTS)
    t = np.arange(1, segments) / segments
    angles = a0 + (-sweep if clockwise else sweep) * t
    radii = r0 + (r1 - r0) * t
    points = np.empty((len(t), columns))
    for c in range(columns):
        a = start[c] if c < len(start) else math.nan
        b = target.get(c, a)
        points[:, c] = a + (b - a) * t if not math.isnan(a) else b
    points[:, 0] = cx + radii * np.cos(angles)
    points[:, 1] = cy + radii * np.sin(angles)
    return points
