"""The done part of a long job is drawn append-only: what is drawn stays, only the tail grows."""

from __future__ import annotations

import numpy as np
from pytestqt.qtbot import QtBot

from app.jobs.program import Program, SourceRef, move
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.preview import DOTS_PIECE_POINTS, TRAIL_PIECE_POINTS, JobPreview


def drawn(preview: JobPreview, kind: int) -> tuple[np.ndarray, np.ndarray]:
    """Every point the done trail of ``kind`` (0 travel, 1 work) draws, pieces joined."""
    trail = preview.done_trails[kind]
    xs: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    for item in [*trail.frozen, trail.tail]:
        x, y = item.getData()
        if x is None or not len(x):
            continue
        if xs:  # each piece starts where the last one ended
            assert x[0] == xs[-1][-1] and y[0] == ys[-1][-1]
            x, y = x[1:], y[1:]
        xs.append(np.asarray(x))
        ys.append(np.asarray(y))
    return (np.concatenate(xs), np.concatenate(ys)) if xs else (np.empty(0), np.empty(0))


def test_a_long_done_part_grows_in_frozen_pieces_and_starts_over_on_a_new_run(
    qtbot: QtBot,
) -> None:
    harness = StationHarness(load_profile("xy-stage"))
    preview = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(preview)
    count = 3 * TRAIL_PIECE_POINTS
    ops = tuple(
        move(SourceRef("long.csv", i + 1), X=float(i % 100), Y=float(i // 100))
        for i in range(count)
    )
    try:
        preview.set_program(Program("long", ops))
        travel = preview.path_geometry.travel  # type: ignore[union-attr]
        preview.set_done(TRAIL_PIECE_POINTS + 10)
        trail = preview.done_trails[0]
        first_pieces = list(trail.frozen)
        assert len(first_pieces) == 1
        frozen_data = [np.asarray(p.getData()[0]).copy() for p in first_pieces]
        preview.set_done(count - 5)
        assert trail.frozen[: len(first_pieces)] == first_pieces  # the same items, untouched
        assert np.array_equal(np.asarray(first_pieces[0].getData()[0]), frozen_data[0])
        assert len(trail.frozen) == 2
        n = travel.done_count(count - 5)
        x, y = drawn(preview, 0)
        np.testing.assert_array_equal(x, travel.x[:n])
        np.testing.assert_array_equal(y, travel.y[:n])
        assert len(np.asarray(trail.tail.getData()[0])) <= TRAIL_PIECE_POINTS + 1

        preview.set_done(3)  # a new run: drawn again from the start
        assert trail.frozen == []
        x, _ = drawn(preview, 0)
        np.testing.assert_array_equal(x, travel.x[: travel.done_count(3)])
    finally:
        preview.close()
        harness.close()


def test_the_done_dots_of_a_plain_point_job_grow_append_only(qtbot: QtBot) -> None:
    """A plain point list gets a dot per point; the done dots are added, never all rebuilt
    (a rebuild per progress step cost a 10 000-point job several ms a step)."""
    harness = StationHarness(load_profile("xy-stage"))
    preview = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(preview)
    ops = tuple(
        move(SourceRef("dots.csv", i + 1), X=float(i % 50), Y=float(i // 50)) for i in range(500)
    )
    try:
        preview.set_program(Program("dots", ops))
        markers = preview.path_geometry.markers  # type: ignore[union-attr]
        assert len(markers.x) == 500
        preview.set_done(100)
        rebuilt: list[object] = []
        original = preview.done_markers.setData
        preview.done_markers.setData = lambda *a, **k: rebuilt.append(k) or original(*a, **k)  # type: ignore[method-assign]
        for done in (150, 151, 400, 500):
            preview.set_done(done)
            n = markers.done_count(done)
            shown = preview.done_markers.data
            np.testing.assert_array_equal(shown["x"], markers.x[:n])
            np.testing.assert_array_equal(shown["y"], markers.y[:n])
        assert rebuilt == []
        preview.set_done(3)  # a new run: drawn again from the start
        assert len(rebuilt) == 1
        assert len(preview.done_markers.data) == markers.done_count(3)
    finally:
        preview.close()
        harness.close()


def test_the_done_dots_of_a_long_point_job_freeze_in_pieces_painted_once(qtbot: QtBot) -> None:
    """Past a piece's worth, done dots go to frozen items drawn from a pixmap: the growing
    item stays small, and together they show exactly the done points, in order."""
    from PySide6.QtWidgets import QGraphicsItem

    harness = StationHarness(load_profile("xy-stage"))
    preview = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(preview)
    count = 2 * DOTS_PIECE_POINTS + 100
    ops = tuple(
        move(SourceRef("dots.csv", i + 1), X=float(i % 100), Y=float(i // 100))
        for i in range(count)
    )

    def dots() -> tuple[np.ndarray, np.ndarray]:
        items = [*preview.done_dots.frozen, preview.done_markers]
        return (
            np.concatenate([np.asarray(item.data["x"]) for item in items]),
            np.concatenate([np.asarray(item.data["y"]) for item in items]),
        )

    try:
        preview.set_program(Program("dots", ops))
        markers = preview.path_geometry.markers  # type: ignore[union-attr]
        preview.set_done(DOTS_PIECE_POINTS + 10)
        first = list(preview.done_dots.frozen)
        assert len(first) == 1
        assert first[0].cacheMode() == QGraphicsItem.CacheMode.DeviceCoordinateCache
        kept = np.asarray(first[0].data["x"]).copy()
        preview.set_done(count)
        assert preview.done_dots.frozen[:1] == first  # the same item, untouched
        np.testing.assert_array_equal(np.asarray(first[0].data["x"]), kept)
        assert len(preview.done_dots.frozen) == 2
        assert len(preview.done_markers.data) <= DOTS_PIECE_POINTS
        x, y = dots()
        n = markers.done_count(count)
        assert n == count
        np.testing.assert_array_equal(x, markers.x[:n])
        np.testing.assert_array_equal(y, markers.y[:n])

        preview.set_done(3)  # a new run: drawn again from the start, the pieces gone
        assert preview.done_dots.frozen == []
        assert all(item not in preview.plot.items for item in first)
        x, _ = dots()
        np.testing.assert_array_equal(x, markers.x[: markers.done_count(3)])
    finally:
        preview.close()
        harness.close()


def test_a_frozen_piece_of_dots_works_out_its_bounds_once_per_view(qtbot: QtBot) -> None:
    """Every frame asks every item for its bounds: a frozen piece answers from what it
    worked out for this view, and works them out again when the view changes (its pixel
    padding, in the plot's units, depends on the zoom)."""
    import pyqtgraph as pg

    harness = StationHarness(load_profile("xy-stage"))
    preview = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(preview)
    preview.resize(600, 400)
    preview.show()
    count = DOTS_PIECE_POINTS + 50
    ops = tuple(
        move(SourceRef("dots.csv", i + 1), X=float(i % 40), Y=float(i // 40)) for i in range(count)
    )
    try:
        preview.set_program(Program("dots", ops))
        preview.set_done(count)
        (piece,) = preview.done_dots.frozen
        first = piece.boundingRect()
        assert piece.boundingRect() is first  # the same answer, not worked out again
        assert first == pg.ScatterPlotItem.boundingRect(piece)
        preview.plot.setXRange(0.0, 4.0, padding=0.0)  # another zoom
        preview.plot.setYRange(0.0, 4.0, padding=0.0)
        qtbot.waitUntil(lambda: piece.boundingRect() is not first)
        again = piece.boundingRect()
        assert again == pg.ScatterPlotItem.boundingRect(piece)  # as the scatter says now
        assert again != first  # the padding changed with the view
    finally:
        preview.close()
        harness.close()
