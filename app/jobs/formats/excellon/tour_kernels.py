"""The inner loops of hole ordering, compiled by numba when it is installed.

Local search is a long run of tiny scalar steps (a few distances, a
compare, now and then a short array shift), the one kind of work that numpy
cannot vectorise and that CPython does a hundred times too slowly for a
50 000-hole board.  The functions here are plain Python over numpy arrays so
that they still run, slowly but identically, where numba has no wheel; with
numba they compile once (cached on disk) and run at native speed.

City ``n`` is the depot (the machine's position): it sits at tour position 0
and never moves; the tour is an open path, so the last hole has no successor.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from typing import Any, TypeVar, cast

import numpy as np
import numpy.typing as npt

F = TypeVar("F", bound=Callable[..., Any])

try:
    from numba import njit as _njit

    def _jit(function: F) -> F:
        return cast(F, _njit(cache=True, nogil=True)(function))

    COMPILED = True
except ImportError:  # pragma: no cover - depends on the platform's wheels

    def _jit(function: F) -> F:
        return function

    COMPILED = False

IntArray = npt.NDArray[np.int64]
FloatArray = npt.NDArray[np.float64]
_EPS = 1e-9


@_jit
def _dist(xs: FloatArray, ys: FloatArray, a: int, b: int) -> float:
    return math.hypot(xs[a] - xs[b], ys[a] - ys[b])


@_jit
def nearest_neighbour(
    xs: FloatArray,
    ys: FloatArray,
    neighbours: IntArray,
    cells: IntArray,
    cell_size: float,
    first: int,
) -> IntArray:
    """Greedy tour from ``first``: the nearest unvisited hole, from the neighbour list or the grid.

    When every listed neighbour is drilled the grid is searched in rings of
    cells around the hole; cells whose holes are all drilled are skipped by a
    live count, so the rings stay cheap as the board empties.
    """
    n = cells.shape[0]
    cols = cells[:, 0].max() + 1
    rows = cells[:, 1].max() + 1
    cell_id = cells[:, 1] * cols + cells[:, 0]
    items = np.argsort(cell_id, kind="mergesort")
    counts = np.bincount(cell_id, minlength=cols * rows)
    starts = np.zeros(cols * rows + 1, dtype=np.int64)
    starts[1:] = np.cumsum(counts)
    alive = counts.copy()
    visited = np.zeros(n, dtype=np.bool_)
    tour = np.empty(n, dtype=np.int64)
    current = first
    tour[0] = current
    visited[current] = True
    alive[cell_id[current]] -= 1
    max_ring = max(cols, rows)
    for step in range(1, n):
        following = -1
        for c in neighbours[current]:
            if c >= 0 and not visited[c]:
                following = c
                break
        if following < 0:
            hx, hy = cells[current, 0], cells[current, 1]
            best_d = math.inf
            for ring in range(max_ring + 1):
                if following >= 0 and (ring - 1) * cell_size > best_d:
                    break
                for side in range(4):
                    # the ring's cells: top and bottom rows in full, the sides without corners
                    span = 2 * ring + 1 if side < 2 else 2 * ring - 1
                    if ring == 0:
                        span = 1 if side == 0 else 0
                    for s in range(span):
                        if side == 0:
                            cx, cy = hx - ring + s, hy + ring
                        elif side == 1:
                            cx, cy = hx - ring + s, hy - ring
                        elif side == 2:
                            cx, cy = hx - ring, hy - ring + 1 + s
                        else:
                            cx, cy = hx + ring, hy - ring + 1 + s
                        if cx < 0 or cy < 0 or cx >= cols or cy >= rows:
                            continue
                        cid = cy * cols + cx
                        if alive[cid] == 0:
                            continue
                        for k in range(starts[cid], starts[cid + 1]):
                            m = items[k]
                            if not visited[m]:
                                d = _dist(xs, ys, current, m)
                                if d < best_d:
                                    best_d = d
                                    following = m
        tour[step] = following
        visited[following] = True
        alive[cell_id[following]] -= 1
        current = following
    return tour


@_jit
def _push(city: int, n: int, queue: IntArray, queued: npt.NDArray[np.bool_], tail: int) -> int:
    if 0 <= city < n and not queued[city]:
        queued[city] = True
        queue[tail % n] = city
        return tail + 1
    return tail


@_jit
def _or_gain(
    xs: FloatArray, ys: FloatArray, t: IntArray, pos: IntArray, i: int, e: int, c: int
) -> tuple[float, int, bool]:
    """Best move of segment t[i..e] next to city ``c``: (gain, after-position, reversed)."""
    last = t.shape[0] - 1
    prev = t[i - 1]
    s1, sl = t[i], t[e]
    removed = _dist(xs, ys, prev, s1)
    if e < last:
        nxt = t[e + 1]
        removed += _dist(xs, ys, sl, nxt) - _dist(xs, ys, prev, nxt)
    best, best_k, best_rev = _EPS, -1, False
    q = pos[c]
    for k in (q - 1, q):
        if k < 0 or (i - 1 <= k <= e):
            continue
        u = t[k]
        for rev in (False, True):
            head, tail_ = (sl, s1) if rev else (s1, sl)
            added = _dist(xs, ys, u, head)
            if k < last:
                w = t[k + 1]
                added += _dist(xs, ys, tail_, w) - _dist(xs, ys, u, w)
            g = removed - added
            if g > best:
                best, best_k, best_rev = g, k, rev
    return best, best_k, best_rev


@_jit
def _move_segment(t: IntArray, pos: IntArray, i: int, e: int, k: int, rev: bool) -> None:
    """Cut t[i..e] out and put it back after position ``k`` (outside it), reversed if asked."""
    length = e - i + 1
    seg = t[i : e + 1].copy()
    if rev:
        seg = seg[::-1].copy()
    if k > e:
        for p in range(e + 1, k + 1):
            t[p - length] = t[p]
        t[k - length + 1 : k + 1] = seg
        low, high = i, k
    else:
        for p in range(i - 1, k, -1):
            t[p + length] = t[p]
        t[k + 1 : k + 1 + length] = seg
        low, high = k + 1, e
    for p in range(low, high + 1):
        pos[t[p]] = p


@_jit
def _improve(
    xs: FloatArray,
    ys: FloatArray,
    neighbours: IntArray,
    t: IntArray,
    pos: IntArray,
    queue: IntArray,
    queued: npt.NDArray[np.bool_],
    head: int,
    tail: int,
    max_pops: int,
) -> float:
    """Apply improving moves for the queued holes until none is left; return the total gain."""
    n = t.shape[0] - 1
    last = n
    pops = 0
    total = 0.0
    while head < tail and pops < max_pops:
        a = queue[head % n]
        head += 1
        pops += 1
        queued[a] = False
        p = pos[a]
        improved = False
        # 2-opt: reverse t[i+1..j] so that a and c become neighbours
        d_succ = _dist(xs, ys, a, t[p + 1]) if p < last else 0.0
        d_pred = _dist(xs, ys, t[p - 1], a)
        reach = max(d_succ, d_pred)
        for c in neighbours[a]:
            if c < 0 or c == a:
                continue
            if _dist(xs, ys, a, c) >= reach:
                break
            q = pos[c]
            low, high = min(p, q), max(p, q)
            best_gain, bi, bj = _EPS, -1, -1
            for i, j in ((low, high), (low - 1, high - 1)):
                if j <= i + 1 or i < 0:
                    continue
                u, v, w = t[i], t[i + 1], t[j]
                g = _dist(xs, ys, u, v) - _dist(xs, ys, u, w)
                if j < last:
                    z = t[j + 1]
                    g += _dist(xs, ys, w, z) - _dist(xs, ys, v, z)
                if g > best_gain:
                    best_gain, bi, bj = g, i, j
            if bi < 0:
                continue
            tail = _push(t[bi], n, queue, queued, tail)
            tail = _push(t[bi + 1], n, queue, queued, tail)
            tail = _push(t[bj], n, queue, queued, tail)
            if bj < last:
                tail = _push(t[bj + 1], n, queue, queued, tail)
            lo, hi = bi + 1, bj
            while lo < hi:
                t[lo], t[hi] = t[hi], t[lo]
                pos[t[lo]] = lo
                pos[t[hi]] = hi
                lo += 1
                hi -= 1
            total += best_gain
            improved = True
            break
        if improved:
            continue
        # Or-opt: move a segment of 1-3 holes that starts or ends at a next to a neighbour
        best_gain, bi, be, bk, brev = _EPS, -1, -1, -1, False
        for length in range(1, 4):
            for i in (p, p - length + 1):
                e = i + length - 1
                if i < 1 or e > last:
                    continue
                prev = t[i - 1]
                removed = _dist(xs, ys, prev, t[i])
                if e < last:
                    removed += _dist(xs, ys, t[e], t[e + 1]) - _dist(xs, ys, prev, t[e + 1])
                for end in (t[i], t[e]):
                    for c in neighbours[end]:
                        if c < 0 or c == end or i <= pos[c] <= e:
                            continue
                        if _dist(xs, ys, end, c) >= removed:
                            break  # nearest first: no farther neighbour can pay for the move
                        g, k, rev = _or_gain(xs, ys, t, pos, i, e, c)
                        if g > best_gain:
                            best_gain, bi, be, bk, brev = g, i, e, k, rev
                if length == 1:
                    break
        if bi < 0:
            continue
        for city in (t[bi - 1], t[bi], t[be], t[bk]):
            tail = _push(city, n, queue, queued, tail)
        if be < last:
            tail = _push(t[be + 1], n, queue, queued, tail)
        if bk < last:
            tail = _push(t[bk + 1], n, queue, queued, tail)
        _move_segment(t, pos, bi, be, bk, brev)
        total += best_gain
        tail = _push(a, n, queue, queued, tail)
    while head < tail:  # out of pops: leave the queue clean for the next call
        queued[queue[head % n]] = False
        head += 1
    return total


@_jit
def _path_length(xs: FloatArray, ys: FloatArray, t: IntArray) -> float:
    total = 0.0
    for p in range(t.shape[0] - 1):
        total += _dist(xs, ys, t[p], t[p + 1])
    return total


@_jit
def local_search(
    xs: FloatArray,
    ys: FloatArray,
    neighbours: IntArray,
    tour: IntArray,
    max_pops: int,
    kicks: int,
    seed: int,
) -> IntArray:
    """2-opt and Or-opt (segments of 1-3 holes, either way round) with neighbour lists, then kicks.

    Only moves that make a hole adjacent to one of its listed neighbours are
    tried, and a work queue revisits only holes whose edges changed, so one
    pass costs O(n·k) and the whole search is near-linear; ``max_pops``
    bounds the worst case.  Each of the ``kicks`` then swaps two short
    neighbouring stretches of the tour (a local double bridge, which 2-opt
    and Or-opt cannot undo in one move), repairs around it, and keeps the
    result only if the path got shorter: iterated local search, which closes
    most of the gap left to a full solver on board-sized problems.
    """
    n = tour.shape[0]
    t = np.empty(n + 1, dtype=np.int64)
    t[0] = n
    t[1:] = tour
    pos = np.empty(n + 1, dtype=np.int64)
    for p in range(n + 1):
        pos[t[p]] = p
    queue = np.empty(n, dtype=np.int64)
    queued = np.ones(n, dtype=np.bool_)
    for p in range(n):
        queue[p] = tour[p]
    _improve(xs, ys, neighbours, t, pos, queue, queued, 0, n, max_pops)
    if kicks <= 0 or n < 8:
        return t[1:].copy()
    np.random.seed(seed)
    length = _path_length(xs, ys, t)
    saved_t = t.copy()
    saved_pos = pos.copy()
    for _ in range(kicks):
        # positions 1 <= p1 < p2 < p3 <= n: t[p1..p2-1] and t[p2..p3-1] swap places
        span = min(n - 1, 30)
        p1 = np.random.randint(1, n - span + 1)
        a = np.random.randint(1, span)
        b = np.random.randint(a + 1, span + 1)
        p2, p3 = p1 + a, p1 + b
        before = _dist(xs, ys, t[p1 - 1], t[p1]) + _dist(xs, ys, t[p2 - 1], t[p2])
        after = _dist(xs, ys, t[p1 - 1], t[p2]) + _dist(xs, ys, t[p3 - 1], t[p1])
        if p3 <= n:  # always, as drawn: the last hole stays last
            before += _dist(xs, ys, t[p3 - 1], t[p3])
            after += _dist(xs, ys, t[p2 - 1], t[p3])
        window = np.concatenate((t[p2:p3], t[p1:p2]))
        t[p1:p3] = window
        for p in range(p1, p3):
            pos[t[p]] = p
        tail = 0
        for p in (p1 - 1, p1, p1 + (p3 - p2) - 1, p1 + (p3 - p2), p3 - 1, p3):
            if 0 <= p <= n:
                tail = _push(t[p], n, queue, queued, tail)
        gain = _improve(xs, ys, neighbours, t, pos, queue, queued, 0, tail, 50 * n)
        candidate = length - (before - after) - gain
        if candidate < length - _EPS:
            length = candidate
            saved_t[:] = t
            saved_pos[:] = pos
        else:
            t[:] = saved_t
            pos[:] = saved_pos
    return t[1:].copy()
