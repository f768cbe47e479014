"""The order a tool's holes are drilled in: short travel, bounded time, never worse than the file.

CAD tools write holes in whatever order their data structures hold them,
and on a slow stepper table the travel between holes is most of a job's
time.  Two searches, chosen by measurement (docs/manual/benchmarks.md), share
the work, and neither compiles anything on the operator's machine:

- up to ``path_solver.LARGEST`` holes a board (every real board we have,
  and the 22-3000 holes boards people drill), fast-tsp's compiled
  Lin-Kernighan search on a distance matrix of the whole board, tools in
  order, in milliseconds: shorter than OR-Tools' guided local search given
  seconds a tool;
- above that, where a matrix no longer fits (and where fast-tsp has no
  wheel), tool by tool, a numpy-only batched 2-opt and insertion search from
  a Hilbert curve (``batch_search``): 50 000 holes in 0.4-0.5 s of processor
  time, some 12 % above the expected optimum on random boards.

The tour is an open path from the machine's position (the drill does not
return), and the file order wins whenever it is not longer.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from app.jobs.formats.excellon import batch_search, path_solver

Points = Sequence[tuple[float, float]] | npt.NDArray[np.float64]
FloatArray = npt.NDArray[np.float64]
IntArray = npt.NDArray[np.int64]

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
    return order_tools([points], start=start)[0]


def order_tools(
    tools: Sequence[Points], *, start: tuple[float, float] = (0.0, 0.0)
) -> list[OrderResult]:
    """Each tool's order, tool after tool, each starting where the one before ended.

    A board small enough for a matrix is ordered as one tour with the tools
    in the given order (``path_solver.board_path``); otherwise, or if that
    search left a tool split, tool by tool (and the shorter plan is kept).
    Then, tool by tool, the file order replaces any order that is not shorter
    from where that tool begins.
    """
    arrays = [np.asarray(points, dtype=np.float64).reshape(-1, 2) for points in tools]
    filled = [pts for pts in arrays if len(pts)]
    total = sum(len(pts) for pts in filled)
    board: list[OrderResult] | None = None
    if path_solver.AVAILABLE and 2 < total <= path_solver.LARGEST:
        tool = np.concatenate([np.full(len(p), i, dtype=np.int64) for i, p in enumerate(filled)])
        order, whole = path_solver.board_path(np.vstack(filled), tool, start)
        ends = np.cumsum([0, *(len(pts) for pts in filled)])
        pieces = iter([order[ends[i] : ends[i + 1]] - ends[i] for i in range(len(filled))])
        tours = [next(pieces) if len(pts) else np.zeros(0, dtype=np.int64) for pts in arrays]
        board = _chain(arrays, start, lambda index, _pts, _here: tours[index])
        if whole:
            return board
    by_tool = _chain(arrays, start, lambda _index, pts, here: _tool_tour(pts, here))
    if board is not None and _total(board) <= _total(by_tool):
        return board
    return by_tool


def _total(plan: list[OrderResult]) -> float:
    return sum(result.length for result in plan)


def _chain(
    arrays: list[FloatArray],
    start: tuple[float, float],
    tour_of: Callable[[int, FloatArray, tuple[float, float]], IntArray],
) -> list[OrderResult]:
    """Tool after tool from ``start``: each tool's tour, or its file order where not longer."""
    results = []
    here = start
    for index, pts in enumerate(arrays):
        result = _never_worse(pts, tour_of(index, pts, here), here)
        results.append(result)
        if result.order:
            x, y = pts[result.order[-1]]
            here = (float(x), float(y))
    return results


def _tool_tour(pts: FloatArray, start: tuple[float, float]) -> IntArray:
    n = len(pts)
    if n <= 2:
        return np.arange(n, dtype=np.int64)  # _never_worse tries it both ways
    if path_solver.AVAILABLE and n <= path_solver.LARGEST:
        return path_solver.board_path(pts, np.zeros(n, dtype=np.int64), start)[0]
    return batch_search.order_big(pts, start)


def _never_worse(pts: FloatArray, tour: IntArray, start: tuple[float, float]) -> OrderResult:
    """``tour`` (or its reverse, for two holes), or the file order where that is not longer."""
    n = len(pts)
    file_length = travel_length(pts, start)
    candidates = [tour, tour[::-1]] if n == 2 else [tour]
    best = min(candidates, key=lambda order: travel_length(pts[order], start))
    length = travel_length(pts[best], start)
    if length >= file_length - _EPS:
        return OrderResult(tuple(range(n)), file_length, file_length)
    return OrderResult(tuple(int(i) for i in best), length, file_length)
