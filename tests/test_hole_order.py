"""Hole order: never longer than the file's order, and shorter on real boards.

The lengths themselves are printed by ``tests/benchmark.py`` (bench_drill_order);
here only the promises are asserted.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.formats.excellon.hole_order import order_holes, travel_length
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


@pytest.mark.parametrize("name", sorted(PREVIOUS_TRAVEL_MM))
def test_real_boards_no_longer_than_the_previous_order(data_dir: Path, name: str) -> None:
    plan = plan_drilling(read_drill_file(data_dir / name))
    assert plan.travel_mm <= PREVIOUS_TRAVEL_MM[name] + 1e-3


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
