"""G2/G3 arcs checked as GRBL 1.1 checks them, and flattened for the preview and the limit check.

GRBL refuses an arc whose end is not on its circle (``error:33``), an
``R`` arc whose radius is shorter than half its chord (``error:34``), an
``R`` arc to where it starts (``error:33``) and an ``I``/``J`` arc without
an offset in its plane (``error:35``); so does the loader, on the arc's line,
before anything moves (gcode.c, "Arc definition error").

The flattening follows GRBL's model: chords at most ``ARC_TOLERANCE_MM``
(GRBL's ``$12`` default, 0.002 mm) from the arc.  Its vertex count is
bounded: an arc needing more than ``MAX_ARC_SEGMENTS`` chords is longer
than any machine's travel (over 50 m at a 1 m radius) and is refused, and a
file's arcs together get at most ``MAX_ARC_VERTICES`` vertices (the budget
the caller passes), so no file can make the preview allocate gigabytes.
"""

from __future__ import annotations

import math
from collections.abc import Mapping

import numpy as np
from PySide6.QtCore import QCoreApplication

from app.jobs.names import quoted
from app.jobs.program import JobFileError

#: Largest chord error of a flattened arc (mm, GRBL's $12) and the fewest segments one gets.
ARC_TOLERANCE_MM = 0.002
MIN_ARC_SEGMENTS = 4
#: The most chords one arc becomes; an arc needing more is refused.
MAX_ARC_SEGMENTS = 20_000
#: The most inner vertices all the arcs of one file become.
MAX_ARC_VERTICES = 4_000_000
#: GRBL's arc definition check: the end's radius may differ from the start's by this much…
ARC_RADIUS_SLACK_MM = 0.005
#: …and beyond it by at most 0.5 mm and 0.1 % of the radius (gcode.c).
ARC_RADIUS_ERROR_MM = 0.5
ARC_RADIUS_ERROR_RATIO = 0.001


def _centre(
    file: str,
    number: int,
    code: str,
    ends: tuple[float, float, float, float],
    offsets: Mapping[str, float],
    clockwise: bool,
) -> tuple[float, float]:
    """The arc's centre from R (the shorter way for R > 0, as GRBL takes it) or I/J;
    refused as GRBL would refuse it (error:33, 34, 35)."""
    sx, sy, ex, ey = ends
    if "R" in offsets:
        radius = offsets["R"]
        dx, dy = ex - sx, ey - sy
        chord = math.hypot(dx, dy)
        if chord == 0.0:
            raise JobFileError(
                file,
                number,
                QCoreApplication.translate(
                    "JobFile", "arc target invalid: an R arc needs distinct ends (error:33): {0}"
                ).format(quoted(code)),
            )
        h2 = 4 * radius * radius - dx * dx - dy * dy
        if h2 < -1e-6 * max(1.0, radius * radius):
            raise JobFileError(
                file,
                number,
                QCoreApplication.translate(
                    "JobFile",
                    "arc radius error: R {0:g} mm is less than half the chord {1:g} mm "
                    "(error:34): {2}",
                ).format(abs(radius), chord, quoted(code)),
            )
        h = -math.sqrt(max(h2, 0.0)) / chord
        if not clockwise:
            h = -h
        if radius < 0:
            h = -h
        cx, cy = sx + 0.5 * (dx - dy * h), sy + 0.5 * (dy + dx * h)
    elif "I" in offsets or "J" in offsets:
        cx, cy = sx + offsets.get("I", 0.0), sy + offsets.get("J", 0.0)
    else:
        raise JobFileError(
            file,
            number,
            QCoreApplication.translate(
                "JobFile", "arc without offsets: it needs I/J or R (error:35): {0}"
            ).format(quoted(code)),
        )
    return cx, cy


def _segments(file: str, number: int, radius: float, sweep: float, budget: int) -> int:
    """How many chords the arc needs at ARC_TOLERANCE_MM; refused past the bounds."""
    if radius > ARC_TOLERANCE_MM:
        step = 2 * math.acos(1 - ARC_TOLERANCE_MM / radius)
        # A radius so large that the step rounds to nothing gets the most segments.
        segments = math.ceil(sweep / step) if step > 0 else MAX_ARC_SEGMENTS + 1
    else:
        segments = 1
    if segments > MAX_ARC_SEGMENTS:
        raise JobFileError(
            file,
            number,
            QCoreApplication.translate(
                "JobFile",
                "arc too long: {0:.4g} m of radius {1:.4g} mm needs {2} chords at {3:g} mm (at "
                "most {4}); no machine's travel holds it",
            ).format(radius * sweep / 1000, radius, segments, ARC_TOLERANCE_MM, MAX_ARC_SEGMENTS),
        )
    segments = max(segments, MIN_ARC_SEGMENTS)
    if segments - 1 > budget:
        raise JobFileError(
            file,
            number,
            QCoreApplication.translate(
                "JobFile",
                "arcs too many: the file's arcs need more than {0:,} vertices at {1:g} mm",
            ).format(MAX_ARC_VERTICES, ARC_TOLERANCE_MM),
        )
    return segments


def flatten_arc(
    file: str,
    number: int,
    code: str,
    start: list[float],
    target: Mapping[int, float],
    offsets: Mapping[str, float],
    clockwise: bool,
    columns: int,
    budget: int = MAX_ARC_VERTICES,
    *,
    grbl_rules: bool = True,
) -> np.ndarray:
    """The inner vertices of an XY arc, chord error at most ARC_TOLERANCE_MM.

    ``start`` and ``target`` are machine positions by column (0: X, 1: Y), the
    result has ``columns`` columns; the other axes move linearly along the arc.
    ``budget`` is how many vertices the file's arcs may still have; ``grbl_rules``:
    the end must be on the circle (on a machine that runs the arc).  Raises
    JobFileError on the arc's line where GRBL would refuse it or the bounds
    are exceeded.
    """
    sx = 0.0 if math.isnan(start[0]) else start[0]
    sy = 0.0 if math.isnan(start[1]) else start[1]
    ex, ey = target[0], target[1]
    cx, cy = _centre(file, number, code, (sx, sy, ex, ey), offsets, clockwise)
    if not all(math.isfinite(v) for v in (sx, sy, ex, ey, cx, cy)):
        raise JobFileError(
            file,
            number,
            QCoreApplication.translate("JobFile", "arc coordinates too large to draw: {0}").format(
                quoted(code)
            ),
        )
    r0 = math.hypot(sx - cx, sy - cy)
    r1 = math.hypot(ex - cx, ey - cy)
    if "R" not in offsets and grbl_rules:
        delta = abs(r1 - r0)
        if delta > ARC_RADIUS_SLACK_MM and (
            delta > ARC_RADIUS_ERROR_MM or delta > ARC_RADIUS_ERROR_RATIO * r0
        ):
            raise JobFileError(
                file,
                number,
                QCoreApplication.translate(
                    "JobFile",
                    "arc end not on its circle: radius {0:.4g} mm at the start, {1:.4g} mm at the "
                    "end (error:33): {2}",
                ).format(r0, r1, quoted(code)),
            )
    a0 = math.atan2(sy - cy, sx - cx)
    a1 = math.atan2(ey - cy, ex - cx)
    if clockwise:
        sweep = (a0 - a1) % math.tau
    else:
        sweep = (a1 - a0) % math.tau
    if sweep < 1e-12 and "R" not in offsets:
        sweep = math.tau  # same start and end with a centre: a full circle
    radius = max(r0, r1)
    segments = _segments(file, number, radius, sweep, budget)
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
