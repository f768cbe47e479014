"""The done part of a long job is drawn append-only: what is drawn stays, only the tail grows."""

from __future__ import annotations

import itertools

import numpy as np
from pytestqt.qtbot import QtBot

from app.jobs.program import Program, SourceRef, move
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.preview import TRAIL_PIECE_POINTS, JobPreview


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


def _dots_preview(
    qtbot: QtBot, count: int, per_row: int = 50, step: float = 1.0
) -> tuple[StationHarness, JobPreview]:
    harness = StationHarness(load_profile("xy-stage"))
    preview = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(preview)
    preview.resize(600, 400)
    preview.show()
    ops = tuple(
        move(SourceRef("dots.csv", i + 1), X=step * (i % per_row), Y=step * (i // per_row))
        for i in range(count)
    )
    preview.set_program(Program("dots", ops))
    return harness, preview


def test_the_done_dots_of_a_plain_point_job_are_each_painted_once(qtbot: QtBot) -> None:
    """A plain point list gets a dot per point; a done dot is painted once into the
    picture, not restyled and drawn again on every step (a 10 000-point job's scatter
    cost the window's thread most of its preview work); going back paints from the start."""
    harness, preview = _dots_preview(qtbot, 500)
    dots = preview.done_dots
    stamped: list[tuple[int, int]] = []
    original = dots._stamp

    def counted(*args: object) -> None:
        stamped.append((int(args[2]), int(args[3])))  # type: ignore[call-overload]
        original(*args)  # type: ignore[arg-type]

    dots._stamp = counted  # type: ignore[method-assign]
    try:
        markers = preview.path_geometry.markers  # type: ignore[union-attr]
        assert len(markers.x) == 500
        for done in (100, 150, 151, 400, 500):
            preview.set_done(done)
            n = markers.done_count(done)
            x, y = preview.done_markers.getData()
            np.testing.assert_array_equal(x, markers.x[:n])
            np.testing.assert_array_equal(y, markers.y[:n])
            preview.grab()  # a frame
        painted = sorted(stamped)
        assert painted[0][0] == 0 and painted[-1][1] == markers.done_count(500)
        # Consecutive, never overlapping: each dot once.
        assert all(a[1] == b[0] for a, b in itertools.pairwise(painted))
        stamped.clear()
        preview.set_done(3)  # a new run: drawn again from the start
        preview.grab()
        assert stamped == [(0, markers.done_count(3))]
        assert len(preview.done_markers.getData()[0]) == markers.done_count(3)
    finally:
        preview.close()
        harness.close()


def _green_at(preview: JobPreview, x: float, y: float) -> bool:
    """Whether the preview shows the done colour (green, not the work's blue) about plot
    point (x, y)."""
    from PySide6.QtCore import QPointF
    from PySide6.QtGui import QColor

    from widgets.jobs.preview_items import DONE_COLOUR

    view = preview.plot.getViewBox()
    scene = view.mapViewToScene(QPointF(x, y))
    widget = preview.plot_widget
    at = widget.mapTo(preview, widget.mapFromScene(scene))
    image = preview.grab().toImage()
    near = [image.pixelColor(at.x() + dx, at.y() + dy) for dx in (-1, 0, 1) for dy in (-1, 0, 1)]
    assert QColor(DONE_COLOUR).hue() == 120  # green: what is asked of each pixel below
    return sum(abs(c.hue() - 120) <= 10 and c.saturation() > 100 for c in near) >= 5


def test_the_done_dots_are_painted_again_where_a_zoom_puts_them(qtbot: QtBot) -> None:
    """The picture is of the view: after a zoom the done dots are where the plot's
    points now are, and the dots not done are not green."""
    harness, preview = _dots_preview(qtbot, 100, per_row=10, step=5.0)
    try:
        preview.set_done(15)  # the first row (y 0) and five of the second (y 5)
        assert _green_at(preview, 40.0, 0.0)
        preview.plot.setXRange(0.0, 40.0, padding=0.0)  # another zoom
        preview.plot.setYRange(-5.0, 15.0, padding=0.0)
        qtbot.waitUntil(lambda: _green_at(preview, 10.0, 5.0))
        assert _green_at(preview, 5.0, 5.0)
        assert not _green_at(preview, 35.0, 5.0)  # dot 18: not done
        assert not _green_at(preview, 10.0, 10.0)  # dot 23: not done
    finally:
        preview.close()
        harness.close()


def test_the_done_dots_bounds_hold_whole_dots_at_every_zoom(qtbot: QtBot) -> None:
    """The dots' area (what is repainted for them) is padded in pixels: after a zoom it
    is worked out again for the new scale, so no dot's edge is cut off."""
    harness, preview = _dots_preview(qtbot, 100, per_row=10, step=5.0)
    dots = preview.done_dots

    def holds_whole_dots() -> bool:
        rect = dots.boundingRect()
        x, y = dots.done_xy()
        px, py = abs(dots.pixelWidth()), abs(dots.pixelHeight())
        half = dots.size / 2  # a dot reaches this many pixels from its centre
        return bool(
            rect.left() <= x.min() - half * px
            and rect.right() >= x.max() + half * px
            and rect.top() <= y.min() - half * py
            and rect.bottom() >= y.max() + half * py
        )

    try:
        preview.set_done(15)
        preview.grab()
        assert holds_whole_dots()
        fitted = dots.boundingRect()
        preview.plot.setXRange(0.0, 4.0, padding=0.0)  # zoomed in: a pixel is less
        preview.plot.setYRange(0.0, 4.0, padding=0.0)
        qtbot.waitUntil(lambda: dots.boundingRect().width() < fitted.width())
        assert holds_whole_dots()
        preview.fit()  # out again: a pixel is more, so is the padding in the plot's units
        qtbot.waitUntil(lambda: dots.boundingRect().width() == fitted.width())
        assert holds_whole_dots()
    finally:
        preview.close()
        harness.close()
