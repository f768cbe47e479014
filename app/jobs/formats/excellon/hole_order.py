"""The order a tool's holes are drilled in: short travel, bounded time, never worse than the file.

CAD tools write holes in whatever order their data structures hold them,
and on a slow stepper table the travel between holes is most of a job's
time.  Nearest neighbour gives a decent tour quickly; 2-opt with neighbour
lists (only the few nearest holes are tried as new neighbours, and a work
queue revisits only holes whose edges changed) removes its crossings in
near-linear time, so a 50 000-hole board is ordered in seconds rather than
the hours a full 2-opt would take.  A time budget bounds the worst case.
The tour is an open path from the machine's position (the drill does not
return), and the file order wins whenever it is not longer.
"""

from __future__ import annotations

import math
import time
from collections import deque
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

Points = Sequence[tuple[float, float]] | npt.NDArray[np.float64]

NEIGHBOURS = 8  # candidates per hole for nearest-neighbour steps and 2-opt moves
DEFAULT_BUDGET_S = 10.0  # wall-clock bound for 2-opt on huge boards; small boards finish far sooner
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
    budget_s: float = DEFAULT_BUDGET_S,
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
    deadline = time.perf_counter() + budget_s
    neighbours = _neighbour_lists(pts, NEIGHBOURS)
    tour = _nearest_neighbour(pts, neighbours, start)
    tour = _two_opt(pts, neighbours, tour, start, deadline)
    length = travel_length(pts[tour], start)
    if length >= file_length:
        return OrderResult(tuple(range(n)), file_length, file_length)
    return OrderResult(tuple(int(i) for i in tour), length, file_length)


def _grid(pts: npt.NDArray[np.float64], per_cell: float) -> tuple[float, npt.NDArray[np.int64]]:
    """A cell size holding about ``per_cell`` points on average, and every point's (col, row)."""
    low = pts.min(axis=0)
    extent = np.maximum(pts.max(axis=0) - low, 1e-9)
    # Holes all on one line (a connector row) have no area: size the cells from the length,
    # or the grid degenerates into thousands of empty cells that the ring search must walk.
    area = max(float(extent[0] * extent[1]), float(extent.max()) ** 2 / len(pts))
    cell = math.sqrt(area * per_cell / len(pts)) or float(extent.max())
    cell = max(cell, float(extent.max()) / 4096, 1e-9)  # never more than 4096 cells a side
    return cell, np.floor((pts - low) / cell).astype(np.int64)


def _neighbour_lists(pts: npt.NDArray[np.float64], k: int) -> list[list[int]]:
    """For every point, up to ``k`` nearest others (nearest first), searched in the 3 by 3 cells."""
    _, cells = _grid(pts, 2.0)
    buckets: dict[tuple[int, int], list[int]] = {}
    for index, (cx, cy) in enumerate(cells.tolist()):
        buckets.setdefault((cx, cy), []).append(index)
    arrays = {key: np.asarray(members) for key, members in buckets.items()}
    result: list[list[int]] = [[] for _ in range(len(pts))]
    for (cx, cy), members in arrays.items():
        around = [
            arrays[key]
            for dx in (-1, 0, 1)
            for dy in (-1, 0, 1)
            if (key := (cx + dx, cy + dy)) in arrays
        ]
        candidates = np.concatenate(around)
        diff = pts[members][:, None, :] - pts[candidates][None, :, :]
        dist = np.hypot(diff[..., 0], diff[..., 1])
        dist[members[:, None] == candidates[None, :]] = np.inf  # not itself
        take = min(k, len(candidates) - 1)
        if take <= 0:
            continue
        nearest = np.argsort(dist, axis=1, kind="stable")[:, :take]
        for row, member in enumerate(members.tolist()):
            result[member] = candidates[nearest[row]].tolist()
    return result


def _nearest_neighbour(
    pts: npt.NDArray[np.float64], neighbours: list[list[int]], start: tuple[float, float]
) -> list[int]:
    """Greedy tour: the nearest unvisited hole each time (neighbour list first, then the grid)."""
    n = len(pts)
    xs, ys = pts[:, 0].tolist(), pts[:, 1].tolist()
    cell, cells = _grid(pts, 2.0)
    buckets: dict[tuple[int, int], list[int]] = {}
    for index, (cx, cy) in enumerate(cells.tolist()):
        buckets.setdefault((cx, cy), []).append(index)
    max_ring = int(cells.max()) + 1
    visited = bytearray(n)
    current = int(np.argmin(np.hypot(pts[:, 0] - start[0], pts[:, 1] - start[1])))
    tour = [current]
    visited[current] = 1
    for _ in range(n - 1):
        following = next((c for c in neighbours[current] if not visited[c]), -1)
        if following < 0:  # every listed neighbour is drilled: search the grid in rings
            x, y = xs[current], ys[current]
            home_x, home_y = (int(v) for v in cells[current])
            best, best_d = -1, math.inf
            for ring in range(max_ring + 1):
                if best >= 0 and (ring - 1) * cell > best_d:
                    break
                for key in _ring(home_x, home_y, ring):
                    members = buckets.get(key)
                    if not members:
                        continue
                    members[:] = [m for m in members if not visited[m]]
                    for m in members:
                        d = math.hypot(xs[m] - x, ys[m] - y)
                        if d < best_d:
                            best, best_d = m, d
            following = best
        tour.append(following)
        visited[following] = 1
        current = following
    return tour


def _ring(cx: int, cy: int, r: int) -> list[tuple[int, int]]:
    if r == 0:
        return [(cx, cy)]
    top = [(cx + dx, cy + r) for dx in range(-r, r + 1)]
    bottom = [(cx + dx, cy - r) for dx in range(-r, r + 1)]
    sides = [(cx + s, cy + dy) for s in (-r, r) for dy in range(-r + 1, r)]
    return top + bottom + sides


def _two_opt(
    pts: npt.NDArray[np.float64],
    neighbours: list[list[int]],
    tour: list[int],
    start: tuple[float, float],
    deadline: float,
) -> list[int]:
    """2-opt on the open path depot→tour, trying only neighbour-list edges, until none improves.

    The depot (the start position) is city ``n`` at position 0 and never
    moves.  Reversing positions i+1…j replaces edges (t[i],t[i+1]) and
    (t[j],t[j+1]) with (t[i],t[j]) and (t[i+1],t[j+1]); at the open end
    t[j+1] does not exist and that edge costs nothing.
    """
    n = len(pts)
    xs = [*pts[:, 0].tolist(), start[0]]
    ys = [*pts[:, 1].tolist(), start[1]]
    t = np.asarray([n, *tour], dtype=np.int64)
    pos = np.empty(n + 1, dtype=np.int64)
    pos[t] = np.arange(n + 1)
    last = n  # the last position

    def dist(a: int, b: int) -> float:
        return math.hypot(xs[a] - xs[b], ys[a] - ys[b])

    def gain(i: int, j: int) -> float:
        a, b, c = int(t[i]), int(t[i + 1]), int(t[j])
        if j < last:
            d = int(t[j + 1])
            return dist(a, b) + dist(c, d) - dist(a, c) - dist(b, d)
        return dist(a, b) - dist(a, c)

    queue = deque(tour)
    queued = bytearray([1] * n + [0])
    checks = 0
    while queue:
        checks += 1
        if checks % 1024 == 0 and time.perf_counter() > deadline:
            break
        a = queue.popleft()
        queued[a] = 0
        p = int(pos[a])
        d_succ = dist(a, int(t[p + 1])) if p < last else 0.0
        d_pred = dist(int(t[p - 1]), a)
        reach = max(d_succ, d_pred)
        for c in neighbours[a]:
            if dist(a, c) >= reach:
                break
            q = int(pos[c])
            low, high = min(p, q), max(p, q)
            moves = [(low, high), (low - 1, high - 1)]  # new edge (a,c) on either side
            best_gain, best = _EPS, None
            for i, j in moves:
                if j > i + 1 and (g := gain(i, j)) > best_gain:
                    best_gain, best = g, (i, j)
            if best is None:
                continue
            i, j = best
            touched = [int(t[i]), int(t[i + 1]), int(t[j])] + ([int(t[j + 1])] if j < last else [])
            t[i + 1 : j + 1] = t[i + 1 : j + 1][::-1].copy()
            pos[t[i + 1 : j + 1]] = np.arange(i + 1, j + 1)
            for city in touched:
                if city != n and not queued[city]:
                    queued[city] = 1
                    queue.append(city)
            break
    return [int(v) for v in t[1:]]
