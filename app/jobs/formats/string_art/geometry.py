"""Where a string-art board's nails are, and how the base turns between them.

All lengths are millimetres, all angles degrees, counter-clockwise from +X
seen from above the board (the base's A axis).  The board file gives the
board radius R in centimetres; the nails sit ``NAIL_INSET_MM`` (1.5 cm)
inside the board's edge:

* a circle (``tvar = 0``): nail ``k`` at angle ``360·k/n`` on the circle of
  radius ``R - 15 mm``;
* a regular polygon (``tvar = m ≥ 3``): vertex ``j`` at angle ``360·j/m`` on
  the circle of radius ``R - 15 mm`` (vertex 0 on +X), nails spaced evenly
  along the perimeter by linear interpolation between the vertices, nail 0
  on vertex 0.  A nail in the middle of an edge is the closest a nail gets
  to the centre: ``(R - 15 mm)·cos(π/m)``.

The base's angle A is kept unwrapped (a continuous number of degrees, not
reduced to 0…360): every turn goes from where the base is by the shortest
signed difference, so no turn is longer than 180°.
"""

from __future__ import annotations

import math

import numpy as np

#: How far inside the board's edge the nails sit (the original firmware's 1.5 cm).
NAIL_INSET_MM = 15.0
#: How deep each nail hole is drilled, measured square to the board (the firmware's 1 cm).
DRILL_DEPTH_MM = 10.0
#: The drill (Z) axis' tilt to the board; Z is measured along it.
DRILL_AXIS_TILT_DEG = 74.333
#: How high above the board the drill tip waits before and between holes (the firmware's
#: "Vrták se zvedne na výšku 1 cm nad matricí"); Z = 0 is that height.
DRILL_CLEARANCE_MM = 10.0
#: The firmware's ``delay(250)`` at the bottom of every hole.
DRILL_DWELL_S = 0.25
#: How far the needle passes inside the innermost nail and outside the nail it wraps (the
#: firmware's ``min_polomer - 2.0`` and ``modul(f) + 2.0``, in cm).
NEEDLE_CLEARANCE_MM = 20.0


def along_drill_axis_mm(square_mm: float) -> float:
    """A distance square to the board as travel along the tilted Z axis.

    The firmware drills ``moveTo(round(hloubka_cm / sin(uhel_vrtani_stupne·π/180)·…))``:
    a 10 mm deep hole is 10.386 mm of Z.
    """
    return square_mm / math.sin(math.radians(DRILL_AXIS_TILT_DEG))


def nail_circle_radius_mm(radius_cm: float) -> float:
    """The radius of the circle the nails (or the polygon's vertices) sit on."""
    return radius_cm * 10.0 - NAIL_INSET_MM


def nail_positions(tvar: int, nails: int, radius_cm: float) -> np.ndarray:
    """(nails, 2) board coordinates in mm: nail 0 on +X, counter-clockwise."""
    r0 = nail_circle_radius_mm(radius_cm)
    k = np.arange(nails, dtype=np.float64)
    if tvar == 0:
        angles = np.radians(360.0 * k / nails)
        return np.column_stack((r0 * np.cos(angles), r0 * np.sin(angles)))
    sides = tvar
    corners = np.radians(360.0 * np.arange(sides + 1) / sides)
    vertices = np.column_stack((r0 * np.cos(corners), r0 * np.sin(corners)))
    # Position along the perimeter in edge lengths: an exact integer on a vertex.
    along = k * sides / nails
    edge = np.minimum(np.floor(along).astype(np.int64), sides - 1)
    fraction = (along - edge)[:, None]
    points: np.ndarray = vertices[edge] * (1.0 - fraction) + vertices[edge + 1] * fraction
    return points


def nail_polar(tvar: int, nails: int, radius_cm: float) -> tuple[np.ndarray, np.ndarray]:
    """(angle in degrees within 0…360, radius in mm) of every nail."""
    if tvar == 0:
        angles = 360.0 * np.arange(nails, dtype=np.float64) / nails
        return angles, np.full(nails, nail_circle_radius_mm(radius_cm))
    xy = nail_positions(tvar, nails, radius_cm)
    angles = np.degrees(np.arctan2(xy[:, 1], xy[:, 0])) % 360.0
    angles[0] = 0.0  # exactly, whatever the rounding of the vertex
    return angles, np.hypot(xy[:, 0], xy[:, 1])


def half_gaps(
    angles: np.ndarray, positions: np.ndarray | None = None
) -> tuple[np.ndarray, np.ndarray]:
    """Per nail, the angle back to the gap before it and on to the gap after it.

    The needle passes between two nails in the direction of their midpoint, as
    the firmware computes it (FIDELITY S0-26): ``argument_rad_nula_2pi(xy_na_bod(
    (f.x+f_minus_1.x)/2.0, …))`` — the angle of the point halfway between the two
    nails (``positions``, board mm).  On a circle that is the angle halfway between
    them; on a polygon's edge it is not (0.55° off on a 30-nail triangle).  Without
    ``positions`` (or for two nails facing each other across the centre, where the
    midpoint has no direction) the angle halfway is used.  The midpoint lies inside
    the sector between the two nails, so the two parts of a nail add up to less than
    180° with at least three nails round the centre: crossing a nail is always the
    short way round.
    """
    following = np.roll(angles, -1)
    span = (following - angles) % 360.0
    after = span / 2.0
    if positions is not None and len(positions) == len(angles):
        middle = (positions + np.roll(positions, -1, axis=0)) / 2.0
        toward = np.degrees(np.arctan2(middle[:, 1], middle[:, 0]))
        has_direction = np.hypot(middle[:, 0], middle[:, 1]) > 1e-9
        after = np.where(has_direction, (toward - angles) % 360.0, after)
    before = np.roll(span - after, 1)
    return before, after


def shortest_turn(current: float, target: float) -> float:
    """The signed turn (-180…180°) that brings angle ``current`` to ``target`` (mod 360)."""
    return (target - current + 180.0) % 360.0 - 180.0


def polygon_min_radius_mm(tvar: int, radius_cm: float) -> float:
    """The closest a nail can come to the centre: an edge's midpoint (a circle: R - 15 mm)."""
    r0 = nail_circle_radius_mm(radius_cm)
    return r0 if tvar == 0 else r0 * math.cos(math.pi / tvar)
