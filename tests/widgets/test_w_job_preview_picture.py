"""A huge path is painted on a worker thread into an image; the preview's other items stay."""

from __future__ import annotations

import itertools
from collections.abc import Iterator

import numpy as np
import pytest
from PySide6.QtCore import QRectF
from PySide6.QtGui import QColor
from pytestqt.qtbot import QtBot

import widgets.jobs.path_picture as path_picture
import widgets.jobs.preview_items as preview_items
from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from tests.helpers.harness import StationHarness
from widgets.jobs.path_picture import PathLayer, PathPicture, paint_layers
from widgets.jobs.preview import JobPreview
from widgets.jobs.preview_items import WORK_COLOUR, travel_pen, work_pen

NAN = float("nan")
#: The "huge" size for these tests: the preview paints more vertices than this as an image.
SMALL_LIMIT = 40


def zigzag(rows: int) -> Program:
    """A travel to the start, then, pen down, a zigzag of ``rows`` rows across 0…40 mm."""
    at = SourceRef("job.gcode", 1)
    ops: list[Operation] = [
        move(at, X=0.0, Y=0.0),
        move(at, X=5.0, Y=5.0),
        Operation(OpKind.PEN_DOWN, at),
    ]
    for row in range(rows):
        y = 5.0 + row * 0.5
        ops.append(move(at, X=45.0 if row % 2 == 0 else 5.0, Y=y))
        ops.append(move(at, X=45.0 if row % 2 == 0 else 5.0, Y=y + 0.5))
    return Program("zigzag", tuple(ops))


def pixel(picture: PathPicture, x: float, y: float) -> QColor:
    """The picture's colour at the plot point (x, y)."""
    sx, sy = picture.scale
    col = int((x - picture.rect.left()) * sx)
    row = int((y - picture.rect.top()) * sy)
    return picture.image.pixelColor(col, row)


def test_layers_are_painted_where_the_path_runs_and_not_across_its_gaps(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Two runs, cut into pieces of 3 vertices: the pieces join, the NaN stays a gap.
    monkeypatch.setattr(path_picture, "POINTS_PER_CALL", 3)
    x = np.array([0.0, 2.0, 4.0, 6.0, 8.0, 10.0, NAN, 0.0, 10.0])
    y = np.array([1.0, 1.0, 1.0, 1.0, 1.0, 1.0, NAN, 9.0, 9.0])
    picture = paint_layers((PathLayer(x, y, work_pen()),), QRectF(0, 0, 10, 10), (10.0, 10.0))
    assert picture is not None
    assert picture.image.width() == 100 and picture.image.height() == 100
    blue = QColor(WORK_COLOUR)
    for along in (0.5, 3.0, 5.5, 7.0, 9.5):
        assert pixel(picture, along, 1.0).rgb() == blue.rgb()
        assert pixel(picture, along, 9.0).rgb() == blue.rgb()
    # Nothing joins the end of the first run to the start of the second.
    for along in (2.0, 5.0, 8.0):
        assert pixel(picture, along, 5.0).alpha() == 0


def test_long_lines_are_cut_into_pieces_of_bounded_pixels(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(path_picture, "PIXELS_PER_CALL", 1000)
    x = np.tile([0.0, 900.0], 10)
    y = np.arange(20, dtype=np.float64)
    pieces = path_picture._pieces(x, y)
    assert pieces[0][0] == 0 and pieces[-1][1] == len(x) - 1
    # Consecutive: each piece starts where the one before ended, every segment drawn once.
    assert all(a[1] == b[0] for a, b in itertools.pairwise(pieces))
    assert len(pieces) >= 10  # a 900-pixel line each, 1000 pixels a piece


@pytest.fixture
def preview(
    qtbot: QtBot, harness: StationHarness, monkeypatch: pytest.MonkeyPatch
) -> Iterator[JobPreview]:
    monkeypatch.setattr(preview_items, "PICTURE_MIN_POINTS", SMALL_LIMIT)
    widget = JobPreview(harness.station, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(widget)
    widget.resize(600, 500)
    widget.show()
    qtbot.waitExposed(widget)
    yield widget


def test_a_huge_path_is_shown_as_a_picture_with_the_markers_over_it(
    qtbot: QtBot, preview: JobPreview
) -> None:
    program = zigzag(40)
    preview.set_program(program)
    item = preview.path_picture
    # The curves hold nothing: the GUI thread strokes no vertex of the path.
    assert preview.work_curve.getData()[0] is None or len(preview.work_curve.getData()[0]) == 0
    qtbot.waitUntil(lambda: item.picture is not None, timeout=10_000)
    picture = item.picture
    assert picture is not None
    # The zigzag's rows are in the picture where the path runs, in the work's colour.
    assert pixel(picture, 25.0, 5.0).rgb() == QColor(WORK_COLOUR).rgb()
    assert pixel(picture, 25.0, 10.0).rgb() == QColor(WORK_COLOUR).rgb()
    # The done part, the step marker and the candidates are still drawn as items.
    preview.set_done(20)
    x, _y = preview.done_work_curve.getData()
    assert x is not None and len(x) > 0
    preview.mark_step((25.0, 10.0))
    assert [tuple(p) for p in zip(*preview.step_marker.getData(), strict=True)] == [(25.0, 10.0)]
    preview.mark_candidates(10, 14)
    cx, _cy = preview.candidate_curve.getData()
    assert cx is not None and len(cx) == 5  # from the vertex before line 10 to line 13's end
    preview.mark_question(12)
    assert len(preview.question_marker.getData()[0]) == 1
    highlights = (preview.step_marker, preview.candidate_curve, preview.question_marker)
    assert all(h.isVisible() for h in highlights)
    # Cleared, they are hidden: no bounds asked nor paint for an empty item every frame.
    preview.mark_step(None)
    preview.mark_candidates(None)
    preview.mark_question(None)
    assert not any(h.isVisible() for h in highlights)


def test_a_small_path_stays_plot_curves(qtbot: QtBot, preview: JobPreview) -> None:
    preview.set_program(zigzag(5))
    x, _y = preview.work_curve.getData()
    assert x is not None and len(x) > 0
    assert preview.path_picture.layers == ()


def test_zooming_in_paints_the_view_again_at_its_scale(qtbot: QtBot, preview: JobPreview) -> None:
    preview.set_program(zigzag(40))
    item = preview.path_picture
    qtbot.waitUntil(lambda: item.picture is not None, timeout=10_000)
    first = item.picture
    assert first is not None
    preview.plot.getViewBox().setRange(xRange=(20, 30), yRange=(10, 20), padding=0)
    qtbot.waitUntil(
        lambda: item.picture is not None and item.picture.scale[0] > 2 * first.scale[0],
        timeout=10_000,
    )
    zoomed = item.picture
    assert zoomed is not None and zoomed.rect.contains(QRectF(20, 10, 10, 10))
    # Another program drops the picture at once: no stale path is shown for it.
    preview.set_program(None)
    assert item.picture is None and item.layers == ()


def test_the_travel_is_painted_in_its_own_pen(qtbot: QtBot, preview: JobPreview) -> None:
    preview.set_program(zigzag(40))
    layers = preview.path_picture.layers
    assert [layer.pen.color().name() for layer in layers] == [
        travel_pen().color().name(),
        work_pen().color().name(),
    ]
    # The travel from the origin to the zigzag's start is in the travel layer.
    assert np.nanmax(layers[0].x) == pytest.approx(5.0)
