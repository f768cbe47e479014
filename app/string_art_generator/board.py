"""The board as a square raster: where the nails fall and how big a pixel is in the real world.

The raster covers the board's nail circle (the circle through the nails, or
through a polygon's corners) plus a margin of one pixel, so every line
between two nails lies inside it.  Row 0 is the top of the picture: board
+Y (nail angles counter-clockwise from +X, seen from above) points up.
The physical pixel size is what calibrates the thread: a thread of width
``w`` mm covers ``w / pixel_mm`` of a pixel it crosses.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from app.jobs.formats.string_art.geometry import nail_circle_radius_mm, nail_positions
from app.jobs.formats.string_art.reader import StringArtParams

#: Pixels left free round the nail circle, so anti-aliased edges stay inside the raster.
MARGIN_PX = 1.0


@dataclass(frozen=True)
class BoardRaster:
    """A board drawn ``size`` pixels across (nail circle plus the margin)."""

    params: StringArtParams
    size: int

    @property
    def nail_radius_mm(self) -> float:
        return nail_circle_radius_mm(self.params.radius_cm)

    @property
    def pixel_mm(self) -> float:
        """The real width of one pixel on the board."""
        return 2.0 * self.nail_radius_mm / (self.size - 2.0 * MARGIN_PX - 1.0)

    @cached_property
    def nails_px(self) -> np.ndarray:
        """(nails, 2) nail centres as (column, row) in pixels, floats."""
        p = self.params
        return self.to_px(nail_positions(p.tvar, p.nails, p.radius_cm))

    @cached_property
    def mask(self) -> np.ndarray:
        """(size, size) bool: the pixels inside the nails' outline (what the thread can cover)."""
        rows, columns = np.mgrid[0 : self.size, 0 : self.size].astype(np.float64)
        centre = (self.size - 1) / 2.0
        if self.params.tvar == 0:
            radius = self.nail_radius_mm / self.pixel_mm
            inside: np.ndarray = np.hypot(rows - centre, columns - centre) <= radius + 0.5
            return inside
        inside = np.ones((self.size, self.size), dtype=bool)
        corners = self._corners_px()
        # A convex outline, counter-clockwise on the board (clockwise in image rows).
        for (x0, y0), (x1, y1) in zip(corners, np.roll(corners, -1, axis=0), strict=True):
            cross = (x1 - x0) * (rows - y0) - (y1 - y0) * (columns - x0)
            inside &= cross <= 0.5 * np.hypot(x1 - x0, y1 - y0)
        return inside

    def to_px(self, mm: np.ndarray) -> np.ndarray:
        """(k, 2) board millimetres (+Y up) as (column, row) pixels."""
        centre = (self.size - 1) / 2.0
        return np.column_stack(
            (centre + mm[:, 0] / self.pixel_mm, centre - mm[:, 1] / self.pixel_mm)
        )

    def _corners_px(self) -> np.ndarray:
        sides = self.params.tvar
        angles = 2.0 * np.pi * np.arange(sides) / sides
        r0 = self.nail_radius_mm
        return self.to_px(np.column_stack((r0 * np.cos(angles), r0 * np.sin(angles))))

    def same_edge(self) -> np.ndarray:
        """(nails, nails) bool: pairs on one straight edge of a polygon (a thread along the edge
        would lie on the nails between them); all False on a circle."""
        n = self.params.nails
        result = np.zeros((n, n), dtype=bool)
        sides = self.params.tvar
        if sides == 0:
            return result
        along = np.arange(n) * sides / n
        lower = np.floor(along).astype(np.int64)
        on_vertex = np.isclose(along, lower)
        edges_a = lower % sides
        edges_b = np.where(on_vertex, (lower - 1) % sides, lower % sides)
        for a in (edges_a, edges_b):
            for b in (edges_a, edges_b):
                result |= a[:, None] == b[None, :]
        np.fill_diagonal(result, False)
        return result


def min_gap(nails: int, a: np.ndarray | int, b: np.ndarray | int) -> np.ndarray:
    """How many nails apart ``a`` and ``b`` are round the board (0 … nails // 2)."""
    d = np.abs(np.asarray(a) - np.asarray(b)) % nails
    result: np.ndarray = np.minimum(d, nails - d)
    return result
