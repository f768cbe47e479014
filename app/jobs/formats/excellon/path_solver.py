"""Hole order for the tools real boards have: fast-tsp's compiled local search on a distance matrix.

fast-tsp (MIT, a 0.35 MB wheel with no dependencies, compiled ahead of time
for every common platform) runs Or-opt and Lin-Kernighan moves with
LKH-style candidate lists inside a time budget, and on a few hundred holes
it reaches the tour that OR-Tools' guided local search needs seconds for in
a few milliseconds.  It solves closed tours on a symmetric integer matrix,
so the drill's job is posed as one:

- the open path from the machine's position is a closed tour through a
  dummy node at distance 0 from the start and farther than any edge from
  every hole but the last tool's: a tour pays least by going from the dummy
  to the start and coming back from the end;
- the tools are drilled one after another, and where one ends is where the
  next begins, so the whole board is one tour: an edge between one tool's
  holes and the next tool's costs its length plus more than any edge can,
  one between tools further apart (or back) more still.  The shortest tour
  changes tools as few times as it can, in order, and chooses each tool's
  last hole for the next tool's sake, which ordering tool by tool cannot.
"""

from __future__ import annotations

import math
import time
from types import ModuleType

import numpy as np
import numpy.typing as npt

fast_tsp: ModuleType | None
try:
    import fast_tsp
except ImportError:  # pragma: no cover - a platform without its wheel orders with batch_search
    fast_tsp = None

IntArray = npt.NDArray[np.int64]
FloatArray = npt.NDArray[np.float64]

AVAILABLE = fast_tsp is not None
LARGEST = 3000  # holes on a board: the matrix is (n+2)^2 4-byte integers, 36 MB here
HOP = 15_000  # the longest distance in matrix units, and the price of a change of tool
FORBIDDEN = 63_000  # an edge no good tour takes (the solver takes integers up to 65 535)
BUDGET_BASE_S = 0.05  # a board of a few hundred holes settles in 5-20 ms of it
BUDGET_PER_HOLE_S = 50e-6
BUDGET_MAX_S = 0.2
TRIES = 3  # a budget mostly spent waiting for the processor is given again, up to this often
STRETCH_MAX_S = 1.0  # and stretched by the share of the processor the thread got, up to this


def budget_for(holes: int) -> float:
    """Seconds of search for a tool of ``holes`` holes."""
    return min(BUDGET_BASE_S + BUDGET_PER_HOLE_S * holes, BUDGET_MAX_S)


def board_path(
    pts: FloatArray, tool: IntArray, start: tuple[float, float]
) -> tuple[IntArray, bool]:
    """Indices of ``pts`` in drilling order from ``start`` (tool 0's holes, 1's...), and if whole.

    ``tool`` gives each point's place in the tool order (0, 1, ... with no
    gaps).  Should the search leave a tool's holes apart (a budget cut
    short by a busy machine), it runs once more for longer, and then each
    tool's holes are taken in the order the tour met them, and the tour is
    not whole (the caller may do better tool by tool).
    """
    if fast_tsp is None:  # pragma: no cover - see the import
        raise RuntimeError("fast-tsp is not installed")
    n = len(pts)
    group = np.append(np.asarray(tool, dtype=np.int16), -1)  # the start: before the first tool
    nodes = np.vstack([pts, np.asarray(start, dtype=np.float64)[None, :]]).astype(np.float32)
    dx = nodes[:, 0, None] - nodes[None, :, 0]
    dy = nodes[:, 1, None] - nodes[None, :, 1]
    dist = np.hypot(dx, dy)
    del dx, dy
    unit = HOP / max(float(dist.max()), 1e-9)
    step = np.abs(group[:, None] - group[None, :])
    matrix = np.full((n + 2, n + 2), FORBIDDEN, dtype=np.int32)
    inner = np.rint(dist * unit).astype(np.int32)
    matrix[: n + 1, : n + 1] = np.where(
        step == 0, inner, np.where(step == 1, inner + HOP, FORBIDDEN)
    )
    del dist, inner, step
    last_tool = group[:n] == group[:n].max()
    matrix[n + 1, :n] = matrix[:n, n + 1] = np.where(last_tool, 2 * HOP, FORBIDDEN)
    matrix[n + 1, n] = matrix[n, n + 1] = 0
    matrix[n + 1, n + 1] = 0
    xy = nodes.astype(np.float64)
    budget = budget_for(n)
    for _ in range(2):  # a search cut short may leave a tool split: once more, given longer
        order = _cut_at_start(_solve(matrix, budget), n, xy[:, 0] + 1j * xy[:, 1])
        if not np.any(np.diff(group[order]) < 0):
            return order, True
        budget *= 3
    # still split: each tool's holes in the order the tour met them, the tools in order
    return order[np.argsort(group[order], kind="stable")], False


def _solve(matrix: npt.NDArray[np.int32], budget: float) -> list[int]:
    """fast-tsp's best tour in about ``budget`` seconds of this thread's processor time.

    fast-tsp's budget is wall-clock: on a loaded machine most of it may pass
    with the thread waiting, and the tour would depend on the load.  When
    less than half of it was spent computing, the search runs again with the
    wall-clock budget stretched by the share the thread got (at most
    ``STRETCH_MAX_S``), and the shorter tour is kept.
    """
    assert fast_tsp is not None
    best: list[int] = []
    best_length = math.inf
    wall = budget
    for _ in range(TRIES):
        cpu = time.thread_time()
        tour = [int(c) for c in fast_tsp.find_tour(matrix, duration_seconds=wall)]
        used = time.thread_time() - cpu
        length = float(matrix[tour, np.roll(tour, -1)].sum(dtype=np.int64))
        if length < best_length:
            best, best_length = tour, length
        if used >= 0.5 * budget:
            break
        wall = min(wall * budget / max(used, budget / 50), STRETCH_MAX_S)
    return best


def _cut_at_start(cycle: list[int], n: int, z: npt.NDArray[np.complex128]) -> IntArray:
    """The holes of a closed tour through start ``n`` and dummy ``n + 1``, as a path from start.

    The dummy is beside the start in any tour worth having; were it ever
    left elsewhere, the cycle is cut at the start and walked the
    shorter way round.
    """
    ring = [c for c in cycle if c != n + 1]
    at = ring.index(n)
    ring = ring[at:] + ring[:at]
    forward = np.asarray(ring[1:], dtype=np.int64)
    backward = forward[::-1].copy()

    def length(order: IntArray) -> float:
        return float(np.abs(np.diff(z[np.concatenate([[n], order])])).sum())

    return forward if length(forward) <= length(backward) else backward
