"""Job preview: travel and work curves, the done part, the position marker, click-to-move."""

from __future__ import annotations

from collections.abc import Iterator
from types import MappingProxyType

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from pytestqt.qtbot import QtBot

from app.jobs.program import Operation, OpKind, Program, SourceRef, move
from protocol.stage.codec import CommandId
from tests.helpers.harness import StationHarness
from widgets.jobs.preview import JobPreview

LEFT = Qt.MouseButton.LeftButton
NAN = float("nan")


class Confirm:
    """Stands in for the Yes/No box: records each question, answers ``answer``."""

    def __init__(self, answer: bool) -> None:
        self.answer = answer
        self.asked: list[str] = []

    def __call__(self, text: str) -> bool:
        self.asked.append(text)
        return self.answer


def op(kind: OpKind, line: int) -> Operation:
    return Operation(kind, SourceRef("job.txt", line), MappingProxyType({}))


def sample_program() -> Program:
    """Travel to a square's corner, draw two sides, lift, travel, drill."""
    at = [SourceRef("job.txt", n) for n in range(1, 9)]
    return Program(
        "job",
        (
            move(at[0], X=0.0, Y=0.0),  # 0
            move(at[1], X=10.0, Y=0.0),  # 1 travel
            op(OpKind.PEN_DOWN, 3),  # 2
            move(at[3], X=10.0, Y=10.0),  # 3 work
            move(at[4], X=0.0, Y=10.0),  # 4 work
            op(OpKind.PEN_UP, 6),  # 5
            move(at[6], X=5.0, Y=5.0),  # 6 travel
            op(OpKind.DRILL, 8),  # 7
        ),
    )


def data(curve: object) -> tuple[np.ndarray, np.ndarray]:
    x, y = curve.getData()  # type: ignore[attr-defined]
    return (np.empty(0), np.empty(0)) if x is None else (np.asarray(x), np.asarray(y))


def scatter(item: object) -> list[tuple[float, float]]:
    x, y = item.getData()  # type: ignore[attr-defined]
    return [(float(a), float(b)) for a, b in zip(x, y, strict=True)]


@pytest.fixture
def confirm() -> Confirm:
    return Confirm(True)


@pytest.fixture
def preview(qtbot: QtBot, harness: StationHarness, confirm: Confirm) -> Iterator[JobPreview]:
    widget = JobPreview(harness.station, confirm=confirm, throttle_ms=0)
    qtbot.addWidget(widget)
    widget.resize(600, 500)
    widget.show()
    qtbot.waitExposed(widget)
    yield widget


def click_at(qtbot: QtBot, preview: JobPreview, x: float, y: float) -> QPointF:
    """A real left click on the plot where (x, y) is drawn; returns the data point hit."""
    view = preview.plot.getViewBox()
    scene = view.mapViewToScene(QPointF(x, y))
    pixel: QPoint = preview.plot_widget.mapFromScene(scene)
    qtbot.mouseClick(preview.plot_widget.viewport(), LEFT, pos=pixel)
    hit: QPointF = view.mapSceneToView(preview.plot_widget.mapToScene(pixel))
    return hit


def moves_sent(harness: StationHarness) -> list[tuple[int, int]]:
    return [
        (c.axis, c.data) for c in harness.emulator.command_log if c.command == CommandId.MOVE_ABS
    ]


def test_travel_and_work_are_separate_curves(preview: JobPreview) -> None:
    preview.set_program(sample_program())
    tx, ty = data(preview.travel_curve)
    np.testing.assert_array_equal(tx, [0, 10, NAN, 0, 5, NAN])
    np.testing.assert_array_equal(ty, [0, 0, NAN, 10, 5, NAN])
    wx, wy = data(preview.work_curve)
    np.testing.assert_array_equal(wx, [10, 10, 0, NAN])
    np.testing.assert_array_equal(wy, [0, 10, 10, NAN])
    assert scatter(preview.work_markers) == [(5.0, 5.0)]  # the drill hole
    assert preview.travel_curve.opts["pen"].style() == Qt.PenStyle.DashLine
    assert preview.work_curve.opts["pen"].style() == Qt.PenStyle.SolidLine
    assert preview.build_seconds > 0


def test_a_point_list_marks_its_points_as_work(preview: JobPreview) -> None:
    at = SourceRef("scan.csv", 1)
    program = Program("scan", (move(at, X=1.0, Y=2.0), move(at, X=3.0, Y=4.0)))
    preview.set_program(program)
    assert scatter(preview.work_markers) == [(1.0, 2.0), (3.0, 4.0)]
    assert len(data(preview.work_curve)[0]) == 0
    preview.set_program(None)
    assert len(data(preview.travel_curve)[0]) == 0 and scatter(preview.work_markers) == []


def test_done_part_grows_with_progress(preview: JobPreview) -> None:
    preview.set_program(sample_program())
    assert len(data(preview.done_travel_curve)[0]) == 0
    preview.set_done(2)  # the first travel move is done
    np.testing.assert_array_equal(data(preview.done_travel_curve)[0][:2], [0, 10])
    assert len(data(preview.done_work_curve)[0]) <= 1  # at most where it will start: no line
    preview.set_done(4)  # and the first drawn side
    wx, wy = data(preview.done_work_curve)
    np.testing.assert_array_equal(wx, [10, 10])
    np.testing.assert_array_equal(wy, [0, 10])
    assert scatter(preview.done_markers) == []
    preview.set_done(8)
    np.testing.assert_array_equal(data(preview.done_work_curve)[0], data(preview.work_curve)[0])
    assert scatter(preview.done_markers) == [(5.0, 5.0)]


def test_position_marker_follows_a_move(harness: StationHarness, preview: JobPreview) -> None:
    harness.connect()
    harness.run(1.0)
    assert scatter(preview.position_marker) == [(0.0, 0.0)]
    harness.session.move_absolute(0, 12.0)
    harness.session.move_absolute(1, 7.5)
    harness.run_until(lambda: scatter(preview.position_marker) == [(12.0, 7.5)])


def test_position_redraws_are_throttled(qtbot: QtBot, harness: StationHarness) -> None:
    preview = JobPreview(harness.station, confirm=Confirm(False), throttle_ms=200)
    qtbot.addWidget(preview)
    for k in range(1, 50):
        harness.station.model.update_axis(0, position=float(k))
    # The first change is drawn at once, the rest wait for the interval and come as one.
    assert scatter(preview.position_marker) == [(1.0, 0.0)]
    qtbot.waitUntil(lambda: scatter(preview.position_marker) == [(49.0, 0.0)], timeout=2000)


def test_click_inside_the_limits_asks_and_moves(
    qtbot: QtBot, harness: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    harness.connect()
    harness.run(1.0)
    hit = click_at(qtbot, preview, 20.0, 30.0)
    assert len(confirm.asked) == 1 and confirm.asked[0].startswith("Move to X ")
    assert hit.x() == pytest.approx(20.0, abs=0.5) and hit.y() == pytest.approx(30.0, abs=0.5)
    axes = harness.emulator.axes
    harness.run(0.2)
    harness.run_until(lambda: not any(a.moving for a in axes))
    # Where the click landed, to within a pixel (about 0.1 mm at this size).
    assert axes[0].position_um / 1000 == pytest.approx(hit.x(), abs=0.2)
    assert axes[1].position_um / 1000 == pytest.approx(hit.y(), abs=0.2)
    target = [round(a.position_um) / 1000 for a in axes]
    harness.run_until(lambda: scatter(preview.position_marker) == [pytest.approx(tuple(target))])
    assert preview.last_message.startswith("Moving to X")


def test_click_answered_no_sends_nothing(
    qtbot: QtBot, harness: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    confirm.answer = False
    harness.connect()
    harness.run(1.0)
    click_at(qtbot, preview, 20.0, 30.0)
    harness.run(1.0)
    assert len(confirm.asked) == 1
    assert moves_sent(harness) == []
    assert [a.position_um for a in harness.emulator.axes] == [0.0, 0.0]


def test_click_outside_the_limits_refuses_without_asking(
    qtbot: QtBot, harness: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    harness.connect()
    harness.run(1.0)
    preview.plot.getViewBox().setRange(xRange=(-30, 80), yRange=(-30, 80), padding=0)
    click_at(qtbot, preview, 65.0, 25.0)
    harness.run(1.0)
    assert confirm.asked == []
    assert moves_sent(harness) == []
    assert "outside 0…50" in preview.last_message and "X 6" in preview.last_message


def test_click_while_motion_is_locked_refuses(
    qtbot: QtBot, preview: JobPreview, confirm: Confirm
) -> None:
    click_at(qtbot, preview, 20.0, 30.0)  # never connected
    assert confirm.asked == []
    assert "not connected" in preview.last_message


def test_a_drag_pans_and_does_not_move(
    qtbot: QtBot, harness: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    harness.connect()
    harness.run(1.0)
    viewport = preview.plot_widget.viewport()
    before = preview.plot.getViewBox().viewRange()
    start = viewport.rect().center()
    qtbot.mousePress(viewport, LEFT, pos=start)
    for dx in range(5, 60, 5):
        qtbot.mouseMove(viewport, start + QPoint(dx, dx))
    qtbot.mouseRelease(viewport, LEFT, pos=start + QPoint(60, 60))
    assert preview.plot.getViewBox().viewRange() != before
    assert confirm.asked == []
    qtbot.mouseClick(preview.fit_button, LEFT)
    assert (
        preview.plot.getViewBox().viewRange()[0][0]
        < 0
        < preview.plot.getViewBox().viewRange()[0][1]
    )


def test_the_cached_axes_and_grid_follow_every_change_of_the_view(
    qtbot: QtBot, preview: JobPreview
) -> None:
    """The axes are painted once into a pixmap (a running job's frame cost two thirds less):
    after a pan or zoom they must look as freshly drawn ones do, never as the old picture."""
    from PySide6.QtWidgets import QGraphicsItem

    preview.set_program(sample_program())
    view = preview.plot.getViewBox()
    axes = [preview.plot.getAxis(side) for side in ("left", "bottom")]
    cached = QGraphicsItem.CacheMode.DeviceCoordinateCache
    assert all(axis.cacheMode() == cached for axis in axes)
    first = preview.plot_widget.grab().toImage()
    view.setRange(xRange=(100, 200), yRange=(-50, 50), padding=0)
    qtbot.wait(50)
    moved = preview.plot_widget.grab().toImage()
    assert moved != first
    for axis in axes:
        axis.setCacheMode(QGraphicsItem.CacheMode.NoCache)  # drawn afresh, for comparison
    qtbot.wait(50)
    assert preview.plot_widget.grab().toImage() == moved
