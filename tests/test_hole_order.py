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
def test_real_boards_are_shorter_than_file_order(shared_dir: Path, name: str) -> None:
    plan = plan_drilling(read_drill_file(shared_dir / name))
    assert plan.travel_mm < plan.file_travel_mm
    for tool in plan.tools:
        assert tool.travel_mm <= tool.file_travel_mm
