"""The order a tool's holes are drilled in: short travel, bounded time, never worse than the file.

CAD tools write holes in whatever order their data structures hold them,
and on a slow stepper table the travel between holes is most of a job's
time.  A k-d tree gives every hole its few nearest others at once; nearest
neighbour builds a first tour from those lists (a grid finds the nearest
hole left when they are all drilled); then 2-opt and Or-opt, trying only
moves that join a hole to a listed neighbour, remove crossings and detours
in near-linear time.  The scalar loops are in ``tour_kernels`` (compiled by
numba), so a 50 000-hole board is ordered in a fraction of a second.  The
tour is an open path from the machine's position (the drill does not
return), and the file order wins whenever it is not longer.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt
from scipy.spatial import cKDTree

from app.jobs.formats.excellon import tour_kernels

Points = Sequence[tuple[float, float]] | npt.NDArray[np.float64]

NEIGHBOURS = 10  # candidates per hole for nearest-neighbour steps, 2-opt and Or-opt moves
MAX_POPS_PER_HOLE = 200  # bounds the search on pathological input; real boards stop far sooner
KICK_WORK = 1_000_000  # kicks x holes: each kick may copy the tour back, so big boards get fewer
KICKS_PER_HOLE = 20  # small boards: enough kicks to settle, few enough to stay in milliseconds
_EPS = 1e-9


@dataclass(frozen=True)
class OrderResult:
    order: tuple[int, ...]  # indices into the given points, in drilling order
    length: float  # travel from the start through the holes in that order
    file_length: float  # the same in file order, for the operator's "before / after"


def travel_length(points: Points, start: tuple[float, float] = (0.0, 0.0)) -> float:
    """Travel from ``start`` through ``points`` in the given order (no return)."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    if len(pts) == 0:
        return 0.0
    path = np.vstack([np.asarray(start, dtype=np.float64), pts])
    return float(np.hypot(*np.diff(path, axis=0).T).sum())


def order_holes(
    points: Points,
    *,
    start: tuple[float, float] = (0.0, 0.0),
) -> OrderResult:
    """A short drilling order for ``points`` starting at ``start``; never longer than file order."""
    pts = np.asarray(points, dtype=np.float64).reshape(-1, 2)
    n = len(pts)
    file_length = travel_length(pts, start)
    if n <= 2:
        order = list(range(n))
        if n == 2 and travel_length(pts[::-1], start) < file_length - _EPS:
            order.reverse()
        return OrderResult(tuple(order), travel_length(pts[order], start), file_length)
    neighbours = _neighbour_lists(pts, NEIGHBOURS)
    xs = np.ascontiguousarray(np.append(pts[:, 0], start[0]))
    ys = np.ascontiguousarray(np.append(pts[:, 1], start[1]))
    cell, cells = _grid(pts, 2.0)
    first = int(np.argmin(np.hypot(pts[:, 0] - start[0], pts[:, 1] - start[1])))
    tour = tour_kernels.nearest_neighbour(xs, ys, neighbours, cells, cell, first)
    kicks = min(KICKS_PER_HOLE * n, KICK_WORK // n)
    tour = tour_kernels.local_search(xs, ys, neighbours, tour, MAX_POPS_PER_HOLE * n, kicks, 0)
    length = travel_length(pts[tour], start)
    if length >= file_length:
        return OrderResult(tuple(range(n)), file_length, file_length)
    return OrderResult(tuple(tour.tolist()), length, file_length)


def _grid(pts: npt.NDArray[np.float64], per_cell: float) -> tuple[float, npt.NDArray[np.int64]]:
    """A cell size holding about ``per_cell`` points on average, and every point's (col, row)."""
    low = pts.min(axis=0)
    extent = np.maximum(pts.max(axis=0) - low, 1e-9)
    # Holes all on one line (a connector row) have no area: size the cells from the length,
    # or the grid degenerates into thousands of empty cells that the ring search must walk.
    area = max(float(extent[0] * extent[1]), float(extent.max()) ** 2 / len(pts))
    cell = math.sqrt(area * per_cell / len(pts)) or float(extent.max())
    cell = max(cell, float(extent.max()) / 4096, 1e-9)  # never more than 4096 cells a side
    return cell, np.ascontiguousarray(np.floor((pts - low) / cell).astype(np.int64))


def _neighbour_lists(pts: npt.NDArray[np.float64], k: int) -> npt.NDArray[np.int64]:
    """For every point, up to ``k`` nearest others (nearest first), -1 where there are fewer.

    The point itself may appear among its duplicates; the kernels skip it.
    """
    n = len(pts)
    take = min(k + 1, n)
    _, index = cKDTree(pts).query(pts, k=take)
    index = np.asarray(index, dtype=np.int64).reshape(n, take)
    index[index >= n] = -1
    return np.ascontiguousarray(index)


def compile_kernels() -> None:
    """Compile (or load from numba's cache) the ordering kernels now, on a tiny board.

    The first use in a fresh install compiles them, which takes tens of seconds
    on a slow machine: the install command and the test session do it up
    front, so an operator's first drill file loads at once.
    """
    order_holes([(0.0, 0.0), (1.0, 0.0), (0.0, 1.0), (1.0, 1.0)])


if __name__ == "__main__":
    compile_kernels()
    print("hole-order kernels ready")
