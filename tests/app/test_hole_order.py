"""Hole order: never longer than the file's order, and shorter on real boards.

The lengths themselves are printed by ``tools/benchmark.py`` (bench_drill_order);
here only the promises are asserted.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.formats.excellon import batch_search, path_solver
from app.jobs.formats.excellon.hole_order import order_holes, order_tools, travel_length
from app.jobs.formats.excellon.reader import plan_drilling, read_drill_file

coordinate = st.floats(-200, 200, allow_nan=False, allow_infinity=False)
point_sets = st.lists(st.tuples(coordinate, coordinate), min_size=0, max_size=120)


def test_travel_length_from_start() -> None:
    assert travel_length([(3.0, 4.0), (3.0, 10.0)]) == pytest.approx(11.0)
    assert travel_length([(3.0, 4.0)], start=(3.0, 0.0)) == pytest.approx(4.0)
    assert travel_length([]) == 0.0


@settings(max_examples=150, deadline=None)
@given(point_sets, st.tuples(coordinate, coordinate))
def test_optimised_never_longer_than_file_order(
    points: list[tuple[float, float]], start: tuple[float, float]
) -> None:
    result = order_holes(points, start=start)
    assert sorted(result.order) == list(range(len(points)))
    assert result.file_length == pytest.approx(travel_length(points, start))
    assert result.length == pytest.approx(travel_length([points[i] for i in result.order], start))
    assert result.length <= result.file_length


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 5), st.integers(0, 5)), min_size=1, max_size=60))
def test_duplicates_and_grids_keep_every_hole(points: list[tuple[int, int]]) -> None:
    pts = [(float(x), float(y)) for x, y in points]
    result = order_holes(pts)
    assert sorted(result.order) == list(range(len(pts)))
    assert result.length <= result.file_length


def test_random_board_is_much_shorter() -> None:
    pts = np.random.default_rng(7).uniform(0, 100, size=(2000, 2))
    result = order_holes(pts)
    # a random order is ~n * 52 mm; a good tour is about 0.7 * sqrt(n * area)
    assert result.length < 1.0 * math.sqrt(2000 * 100 * 100)


REAL_BOARDS = [
    "samples/pcb-driver/driver",
    "realdata/excellon/tracespace_eagle_arduino-uno.drd",
    "realdata/excellon/tracespace_eagle_BusPirate-v3.6a-SSOP.drd",
    "realdata/excellon/tracespace_core.TXT",
    "realdata/excellon/tracespace_kicad_mchck.drl",
    "realdata/excellon/pcb2gcode_kicad4_slots_G85.drl",
]


@pytest.mark.parametrize("name", REAL_BOARDS)
def test_real_boards_are_shorter_than_file_order(data_dir: Path, name: str) -> None:
    plan = plan_drilling(read_drill_file(data_dir / name))
    assert plan.travel_mm < plan.file_travel_mm
    for tool in plan.tools:
        assert tool.travel_mm <= tool.file_travel_mm


# Travel per board (mm, all tools, from (0, 0)) with the previous ordering (nearest neighbour +
# neighbour-list 2-opt, commit a660dc7), measured once when it was replaced: the new order must
# never be longer on these real boards.
PREVIOUS_TRAVEL_MM = {
    "samples/pcb-driver/driver": 632.638,
    "realdata/excellon/pcb2gcode_kicad4_slots_G85.drl": 301.603,
    "realdata/excellon/tracespace_core.TXT": 267.746,
    "realdata/excellon/tracespace_eagle_BusPirate-v3.6a-SSOP.drd": 695.398,
    "realdata/excellon/tracespace_eagle_arduino-uno.drd": 1005.412,
    "realdata/excellon/tracespace_kicad_mchck.drl": 293.339,
}


# The same with the order it replaced (numba-compiled iterated 2-opt/Or-opt per tool, commit
# 50271ad), measured on the day: the board-wide fast-tsp order must be no longer on any board.
NUMBA_TRAVEL_MM = {
    "samples/pcb-driver/driver": 630.937,
    "realdata/excellon/pcb2gcode_kicad4_slots_G85.drl": 301.603,
    "realdata/excellon/tracespace_core.TXT": 242.911,
    "realdata/excellon/tracespace_eagle_BusPirate-v3.6a-SSOP.drd": 655.382,
    "realdata/excellon/tracespace_eagle_arduino-uno.drd": 975.461,
    "realdata/excellon/tracespace_kicad_mchck.drl": 271.030,
}


@pytest.mark.parametrize("name", sorted(PREVIOUS_TRAVEL_MM))
def test_real_boards_no_longer_than_the_previous_order(data_dir: Path, name: str) -> None:
    plan = plan_drilling(read_drill_file(data_dir / name))
    assert plan.travel_mm <= PREVIOUS_TRAVEL_MM[name] + 1e-3
    assert plan.travel_mm <= NUMBA_TRAVEL_MM[name] + 1e-3


def test_every_real_board_has_a_previous_figure(data_dir: Path) -> None:
    on_disk = {f"realdata/excellon/{p.name}" for p in (data_dir / "realdata/excellon").iterdir()}
    assert on_disk <= set(PREVIOUS_TRAVEL_MM)


@pytest.mark.parametrize("name", REAL_BOARDS)
def test_every_hole_once_and_tools_grouped(data_dir: Path, name: str) -> None:
    job = read_drill_file(data_dir / name)
    plan = plan_drilling(job)
    names = [t.tool.name for t in plan.tools]
    assert len(names) == len(set(names))  # each tool one contiguous group, drilled once
    for tool_plan in plan.tools:
        expected = [(h.x_mm, h.y_mm) for h in job.holes_for(tool_plan.tool.name)]
        for slot in job.slots:
            if slot.tool == tool_plan.tool.name:
                expected += [(slot.x0_mm, slot.y0_mm), (slot.x1_mm, slot.y1_mm)]
        got = [(h.x_mm, h.y_mm) for h in tool_plan.holes]
        assert sorted(got) == sorted(expected)
        assert all(h.tool == tool_plan.tool.name for h in tool_plan.holes)


def test_many_tools_of_many_holes_each_keep_every_hole() -> None:
    rng = np.random.default_rng(3)
    here = (0.0, 0.0)
    for _ in range(3):
        pts = rng.uniform(0, 300, size=(5000, 2))
        result = order_holes(pts, start=here)
        assert sorted(result.order) == list(range(len(pts)))
        # neighbour-list 2-opt + Or-opt lands within ~10 % of 0.7124 * sqrt(n * area)
        assert result.length < 0.85 * math.sqrt(5000 * 300 * 300)
        here = (float(pts[result.order[-1], 0]), float(pts[result.order[-1], 1]))


def test_clustered_board_with_far_outliers() -> None:
    """Rows of pins plus a few far holes: the grid fallback must still reach every hole."""
    row = [(10.0 + 2.54 * i, 20.0 + 2.54 * j) for i in range(40) for j in range(2)]
    far = [(290.0, 290.0), (0.5, 280.0), (280.0, 1.0)]
    pts = row + far + row[:5]  # duplicates too
    result = order_holes(pts, start=(150.0, 150.0))
    assert sorted(result.order) == list(range(len(pts)))
    assert result.length <= result.file_length


# --- the board as one tour, and the numpy-only search for big tools ---------------------------


def _chained(tools: list[np.ndarray], results: list, start: tuple[float, float]) -> float:
    """Travel of the plan as the machine drives it: each tool from the last one's end."""
    here, total = start, 0.0
    for pts, result in zip(tools, results, strict=True):
        ordered = pts[list(result.order)]
        total += travel_length(ordered, here)
        if len(ordered):
            here = (float(ordered[-1, 0]), float(ordered[-1, 1]))
    return total


@settings(max_examples=40, deadline=None)
@given(st.lists(point_sets, min_size=1, max_size=5), st.tuples(coordinate, coordinate))
def test_tools_keep_their_holes_and_their_order(
    tools: list[list[tuple[float, float]]], start: tuple[float, float]
) -> None:
    arrays = [np.asarray(t, dtype=np.float64).reshape(-1, 2) for t in tools]
    results = order_tools(tools, start=start)
    assert len(results) == len(tools)
    for pts, result in zip(arrays, results, strict=True):
        assert sorted(result.order) == list(range(len(pts)))
        assert result.length <= result.file_length
    assert sum(r.length for r in results) == pytest.approx(_chained(arrays, results, start))


def test_a_tool_ends_where_the_next_one_is_cheap_to_reach() -> None:
    """Two rows, the second beside the first's left end: the first row is drilled towards it."""
    first = [(10.0 + i, 0.0) for i in range(10)]  # from x = 10 to 19
    second = [(0.0, float(j)) for j in range(1, 11)]  # a column at x = 0
    results = order_tools([first, second], start=(15.0, 0.0))
    ordered = [first[i] for i in results[0].order]
    assert ordered[-1] == (10.0, 0.0)  # 5 mm right, 9 mm back: ends next to the column


def test_a_split_board_tour_is_joined_tool_by_tool(monkeypatch: pytest.MonkeyPatch) -> None:
    """A search cut short may interleave two tools: each tool's holes are taken in turn."""
    pts = np.asarray([(0.0, 0.0), (1.0, 0.0), (2.0, 0.0), (3.0, 0.0)])
    tool = np.asarray([0, 1, 0, 1])
    # the cycle: dummy 5, start 4, then the holes along the line: tools 0 1 0 1
    monkeypatch.setattr(path_solver, "_solve", lambda matrix, budget: [5, 4, 0, 1, 2, 3])
    order, whole = path_solver.board_path(pts, tool, (-1.0, 0.0))
    assert not whole
    assert order.tolist() == [0, 2, 1, 3]


def test_without_fast_tsp_every_size_is_ordered_by_the_numpy_search(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    monkeypatch.setattr(path_solver, "AVAILABLE", False)
    pts = np.random.default_rng(11).uniform(0, 100, size=(400, 2))
    result = order_holes(pts)
    assert sorted(result.order) == list(range(400))
    assert result.length < 0.85 * math.sqrt(400 * 100 * 100)


@settings(max_examples=60, deadline=None)
@given(point_sets.filter(lambda p: len(p) >= 3), st.tuples(coordinate, coordinate))
def test_numpy_search_returns_every_hole_once(
    points: list[tuple[float, float]], start: tuple[float, float]
) -> None:
    pts = np.asarray(points, dtype=np.float64)
    tour = batch_search.order_big(pts, start)
    assert sorted(tour.tolist()) == list(range(len(pts)))


@settings(max_examples=30, deadline=None)
@given(st.lists(st.tuples(st.integers(0, 4), st.integers(0, 4)), min_size=3, max_size=80))
def test_numpy_search_on_grids_and_duplicates(points: list[tuple[int, int]]) -> None:
    pts = np.asarray(points, dtype=np.float64)
    tour = batch_search.order_big(pts, (0.0, 0.0))
    assert sorted(tour.tolist()) == list(range(len(pts)))
    first = batch_search.first_tour(pts, (0.0, 0.0))
    assert travel_length(pts[tour]) <= travel_length(pts[first]) + 1e-9


def test_numpy_search_shortens_a_big_random_board() -> None:
    """Above path_solver.LARGEST: within ~15 % of 0.7124 * sqrt(n * area) (random uniform)."""
    n = path_solver.LARGEST + 2000
    pts = np.random.default_rng(4).uniform(0, 300, size=(n, 2))
    result = order_holes(pts)
    assert sorted(result.order) == list(range(n))
    assert result.length < 0.82 * math.sqrt(n * 300 * 300)


def test_hilbert_curve_visits_neighbouring_cells_in_turn() -> None:
    """On a 4 x 4 grid the curve's order moves one cell at a time (a Hilbert curve's property)."""
    grid = np.asarray([(x, y) for x in range(4) for y in range(4)], dtype=np.float64)
    centres = (grid + 0.5) / 4  # in the unit square, one point in each of its 4 x 4 cells
    order = np.argsort(batch_search.hilbert_keys(centres, np.zeros(2), 1.0))
    steps = np.abs(np.diff(grid[order], axis=0)).sum(axis=1)
    assert np.all(steps == 1.0)


def test_neighbour_candidates_are_mostly_the_true_nearest() -> None:
    pts = np.random.default_rng(9).uniform(0, 100, size=(3000, 2))
    found, near = batch_search.neighbour_candidates(pts, 6)
    d = np.hypot(pts[:, None, 0] - pts[None, :, 0], pts[:, None, 1] - pts[None, :, 1])
    np.fill_diagonal(d, np.inf)
    nearest = np.argmin(d, axis=1)
    assert np.mean([nearest[i] in found[i] for i in range(len(pts))]) > 0.95
    assert np.all(found != np.arange(len(pts))[:, None])
    assert np.allclose(near, d[np.arange(len(pts))[:, None], found])
