"""Hole order for big tools, in numpy alone: a space-filling curve, then batched local search.

A tool of thousands of holes is too big for a distance matrix, and a
Python loop over single moves is a hundred times too slow; what numpy does
fast is the same step for every hole at once.  So each round computes, for
every hole and each of its near neighbours, the gain of the 2-opt moves and
of the insertions that would make the two adjacent, keeps a set of
improving moves that touch disjoint stretches of the tour (best first), and
applies them all with one sort.  Rounds repeat over the holes whose edges
changed until no move pays.  The first tour follows a Hilbert curve, whose
order also gives each hole its neighbour candidates without a k-d tree.

Position 0 of the tour is the machine's position (node ``n``): it never
moves, and the tour is an open path, so the last hole has no successor.
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

IntArray = npt.NDArray[np.int64]
FloatArray = npt.NDArray[np.float64]

NEIGHBOURS = 6  # candidates per hole for the moves
WINDOW = 5  # holes either side along each curve from which the candidates are picked
# four Hilbert curves over the board shifted by these fractions of its size: their folds differ
SHIFTS = ((0.0, 0.0), (0.37, 0.61), (0.71, 0.23), (0.13, 0.87))
MAX_ROUNDS = 40  # most of the gain comes in 15-20 rounds; later ones each move a few holes
LONG_PER_ROUND = 32  # reversals longer than SHORT_SPAN are taken one by one, the best first
SHORT_SPAN = 24  # reversals up to this many holes are chosen all at once, like insertions
_EPS = 1e-9
_BITS = 16  # a coarser grid leaves holes tied in a cell in index order: 4 % longer tours


def hilbert_keys(pts: FloatArray, low: FloatArray, extent: float) -> IntArray:
    """Each point's index along a Hilbert curve over the square at ``low`` of side ``extent``."""
    side = 1 << _BITS
    q = np.clip(((pts - low) / extent * (side - 1)).astype(np.int64), 0, side - 1)
    x, y = q[:, 0].copy(), q[:, 1].copy()
    d = np.zeros(len(pts), dtype=np.int64)
    s = side >> 1
    while s > 0:
        rx = (x & s) > 0
        ry = (y & s) > 0
        d += s * s * ((3 * rx.astype(np.int64)) ^ ry.astype(np.int64))
        flip = ~ry & rx
        x = np.where(flip, side - 1 - x, x)
        y = np.where(flip, side - 1 - y, y)
        x, y = np.where(ry, x, y), np.where(ry, y, x)
        s >>= 1
    return d


def neighbour_candidates(pts: FloatArray, k: int = NEIGHBOURS) -> tuple[IntArray, FloatArray]:
    """For every point, ``k`` near others (-1 where fewer) and their distances, off four curves.

    Points near each other in space are mostly near each other along a
    Hilbert curve, except across the curve's folds; curves over shifted
    points have their folds elsewhere.  The nearest ``k`` of the points
    within ``WINDOW`` places on either curve are close to the true nearest.
    """
    n = len(pts)
    low = pts.min(axis=0)
    extent = float((pts.max(axis=0) - low).max()) or 1.0
    offsets = np.concatenate([np.arange(-WINDOW, 0), np.arange(1, WINDOW + 1)])
    found = []
    for shift in SHIFTS:
        keys = hilbert_keys(pts + np.asarray(shift) * extent, low, 2.0 * extent)
        order = np.argsort(keys, kind="stable")
        rank = np.empty(n, dtype=np.int64)
        rank[order] = np.arange(n)
        found.append(order[np.clip(rank[:, None] + offsets[None, :], 0, n - 1)])
    cand = np.concatenate(found, axis=1)
    z = pts[:, 0] + 1j * pts[:, 1]
    dist = np.abs(z[cand] - z[:, None])
    dist[cand == np.arange(n)[:, None]] = np.inf
    by_dist = np.argsort(dist, axis=1, kind="stable")
    cand = np.take_along_axis(cand, by_dist, axis=1)
    dist = np.take_along_axis(dist, by_dist, axis=1)
    repeat = np.zeros(cand.shape, dtype=bool)
    repeat[:, 1:] = (cand[:, 1:] == cand[:, :-1]) & (dist[:, 1:] == dist[:, :-1])
    dist[repeat] = np.inf
    keep = np.argsort(dist, axis=1, kind="stable")[:, :k]
    out = np.take_along_axis(cand, keep, axis=1)
    near = np.take_along_axis(dist, keep, axis=1)
    out[~np.isfinite(near)] = -1
    return np.ascontiguousarray(out), np.ascontiguousarray(near)


def first_tour(pts: FloatArray, start: tuple[float, float]) -> IntArray:
    """The holes along a Hilbert curve, entered at the end nearer the start."""
    low = pts.min(axis=0)
    extent = float((pts.max(axis=0) - low).max()) or 1.0
    tour = np.argsort(hilbert_keys(pts, low, extent), kind="stable")
    if math.dist(start, pts[tour[-1]]) < math.dist(start, pts[tour[0]]):
        tour = tour[::-1]
    return np.ascontiguousarray(tour, dtype=np.int64)


def order_big(pts: FloatArray, start: tuple[float, float]) -> IntArray:
    """A short open path from ``start`` through ``pts`` (indices), for tools of any size."""
    n = len(pts)
    z = np.append(pts[:, 0] + 1j * pts[:, 1], complex(start[0], start[1]))
    neighbours, near = neighbour_candidates(pts)
    tour = np.concatenate([[n], first_tour(pts, start)]).astype(np.int64)
    return improve(z, neighbours, near, tour)[1:]


def improve(
    z: npt.NDArray[np.complex128], neighbours: IntArray, near: FloatArray, tour: IntArray
) -> IntArray:
    """Batched 2-opt and insertion over neighbour pairs until no move pays (see the module)."""
    size = len(tour)
    last = size - 1
    n, k = neighbours.shape
    everyone = np.arange(n)
    active = everyone
    full = True
    for _ in range(MAX_ROUNDS):
        if len(active) == 0:
            # settled on the holes that changed: one look at them all before stopping
            if full:
                break
            active = everyone
        full = len(active) == n
        pos = np.empty(size, dtype=np.int64)
        pos[tour] = np.arange(size)
        zt = z[tour]
        edge = np.zeros(size)
        edge[:-1] = np.abs(np.diff(zt))
        a = np.repeat(active, k)
        c = neighbours[active].reshape(-1)
        d_ac = near[active].reshape(-1)
        listed = c >= 0
        a, c, d_ac = a[listed], c[listed], d_ac[listed]
        p, q = pos[a], pos[c]
        moves = _moves(zt, edge, p, q, d_ac, last)
        accepted = None if moves is None else _disjoint(*moves, last)
        if moves is None or accepted is None or len(accepted) == 0:
            if full:
                break
            active = everyone
            continue
        kind, low, high = moves
        key = np.arange(size, dtype=np.float64)
        kind, low, high = kind[accepted], low[accepted], high[accepted]
        for which, side in ((1, 0.5), (2, -0.5)):  # insertions: after / before the neighbour
            chosen = kind == which
            key[low[chosen]] = high[chosen] + side
        rev = kind == 0
        lengths = high[rev] - low[rev] + 1
        within = np.arange(lengths.sum()) - np.repeat(np.cumsum(lengths) - lengths, lengths)
        key[np.repeat(low[rev], lengths) + within] = np.repeat(high[rev], lengths) - within
        # the holes whose edges changed, and their neighbours, are looked at again
        touched = np.concatenate([low - 1, low, low + 1, high - 1, high, high + 1])
        moved = tour[np.clip(touched, 1, last)]
        moved = moved[moved < n]
        again = np.unique(np.concatenate([moved, neighbours[moved].ravel()]))
        active = again[again >= 0]
        tour = tour[np.argsort(key, kind="stable")]
    return tour


def _moves(
    zt: npt.NDArray[np.complex128],
    edge: FloatArray,
    p: IntArray,
    q: IntArray,
    d_ac: FloatArray,
    last: int,
) -> tuple[IntArray, IntArray, IntArray] | None:
    """Improving moves, best first, as (kind, low, high).

    Kind 0 reverses positions low..high (2-opt); kind 1 moves the hole at
    ``low`` to just after position ``high``, kind 2 to just before it.
    """
    i, j = np.minimum(p, q), np.maximum(p, q)
    j1 = np.minimum(j + 1, last)
    im = np.maximum(i - 1, 0)
    # 2-opt joining a and c: reverse t[i+1..j] (drops edges i and j) or t[i..j-1] (i-1 and j-1)
    gain_a = edge[i] - d_ac + np.where(j < last, edge[j] - np.abs(zt[i + 1] - zt[j1]), 0.0)
    gain_a[j <= i + 1] = -1.0
    gain_b = edge[im] + edge[j - 1] - np.abs(zt[im] - zt[j - 1]) - d_ac
    gain_b[(i < 1) | (j <= i + 1)] = -1.0
    # insertion of the hole at p next to the one at q
    p1 = np.minimum(p + 1, last)
    removed = edge[p - 1] + np.where(p < last, edge[p] - np.abs(zt[p - 1] - zt[p1]), 0.0)
    q1 = np.minimum(q + 1, last)
    after = removed - d_ac - np.where(q < last, np.abs(zt[p] - zt[q1]) - edge[q], 0.0)
    after[(q == p) | (q == p - 1)] = -1.0
    qm = np.maximum(q - 1, 0)
    before = removed - d_ac - np.abs(zt[p] - zt[qm]) + edge[qm]
    before[(q < 1) | (q == p) | (q == p + 1)] = -1.0
    kinds, gains, lows, highs = [], [], [], []
    for kind, gain, low, high in (
        (0, gain_a, i + 1, j),
        (0, gain_b, i, j - 1),
        (1, after, p, q),
        (2, before, p, q),
    ):
        good = gain > _EPS
        kinds.append(np.full(int(good.sum()), kind, dtype=np.int64))
        gains.append(gain[good])
        lows.append(low[good])
        highs.append(high[good])
    gain = np.concatenate(gains)
    if len(gain) == 0:
        return None
    best = np.argsort(-gain, kind="stable")
    return np.concatenate(kinds)[best], np.concatenate(lows)[best], np.concatenate(highs)[best]


def _disjoint(kind: IntArray, low: IntArray, high: IntArray, last: int) -> IntArray:
    """Moves (given best first) that touch no position another chosen, better move touches.

    Long reversals are taken greedily, one by one; the rest claim their few
    positions at once and keep them only where no better move claimed one.
    """
    count = len(kind)
    span = high - low
    long = np.flatnonzero((kind == 0) & (span > SHORT_SPAN))
    used = np.zeros(last + 1, dtype=bool)
    taken: list[int] = []
    for m in long[:LONG_PER_ROUND].tolist():
        lo, hi = max(int(low[m]) - 1, 0), min(int(high[m]) + 1, last)
        if not used[lo : hi + 1].any():
            used[lo : hi + 1] = True
            taken.append(m)
    short = np.flatnonzero((kind != 0) | (span <= SHORT_SPAN))
    # claimed positions: a reversal low-1..high+1; an insertion p-1..p+1 and its gap's two ends
    width = np.where(kind[short] == 0, span[short] + 3, 5)
    move = np.repeat(short, width)
    step = np.arange(width.sum()) - np.repeat(np.cumsum(width) - width, width)
    mk, ml, mh = kind[move], low[move], high[move]
    gap_start = np.where(mk == 1, mh, mh - 1)
    claim = np.where((mk == 0) | (step < 3), ml - 1 + step, gap_start + step - 3)
    claim = np.clip(claim, 0, last)
    owner = np.full(last + 1, count, dtype=np.int64)
    free = np.ones(count, dtype=bool)
    np.logical_and.at(free, move, ~used[claim])
    np.minimum.at(owner, claim[free[move]], move[free[move]])
    won = free.copy()
    np.logical_and.at(won, move, owner[claim] == move)
    chosen = short[won[short]]
    return np.concatenate([np.asarray(taken, dtype=np.int64), chosen])
