"""The job preview on a cylindrical machine (the string-art winder): the work's plane, not A-by-X.

The winder turns the board by A degrees and holds the tool X mm from the
centre, so the preview draws where things are on the board: the reach as a
disc of X's travel, the machine at (X·cos A, X·sin A), and a click as a
point to reach by the shorter turn of A and a move of X.  Clicks are real
mouse clicks on the plot, the moves are judged from the emulated winder.
"""

from __future__ import annotations

import math
from collections.abc import Iterator

import numpy as np
import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.program import build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.jobs.program import Program, SourceRef, move
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.preview import ARC_STEP_DEG, JobPreview

LEFT = Qt.MouseButton.LeftButton
REACH = 250.0  # the winder's X travel
#: A board of 10 cm radius: 8 nails on the circle of 85 mm.
BOARD = StringArtJob(StringArtParams(0, 8, 10.0), (0, 4, 2, 6))


class Confirm:
    """Stands in for the Yes/No box: records each question, answers ``answer``."""

    def __init__(self, answer: bool) -> None:
        self.answer = answer
        self.asked: list[str] = []

    def __call__(self, text: str) -> bool:
        self.asked.append(text)
        return self.answer


def points(item: object) -> np.ndarray:
    x, y = item.getData()  # type: ignore[attr-defined]
    if x is None:
        return np.empty((0, 2))
    return np.column_stack((np.asarray(x, dtype=float), np.asarray(y, dtype=float)))


@pytest.fixture
def winder(qapp: object) -> Iterator[StationHarness]:
    harness = StationHarness(load_profile("string-art"))
    yield harness
    harness.close()


@pytest.fixture
def confirm() -> Confirm:
    return Confirm(True)


@pytest.fixture
def preview(qtbot: QtBot, winder: StationHarness, confirm: Confirm) -> Iterator[JobPreview]:
    widget = JobPreview(winder.station, confirm=confirm, throttle_ms=0)
    qtbot.addWidget(widget)
    widget.resize(600, 600)
    widget.show()
    qtbot.waitExposed(widget)
    yield widget
    widget.close()


def connected(winder: StationHarness) -> None:
    winder.connect()
    winder.run_until(lambda: winder.gcode_session.planner_size > 0, timeout=1)
    winder.run(0.5)


def click_at(qtbot: QtBot, preview: JobPreview, x: float, y: float) -> QPointF:
    """A real left click where board point (x, y) is drawn; returns the point hit."""
    view = preview.plot.getViewBox()
    pixel: QPoint = preview.plot_widget.mapFromScene(view.mapViewToScene(QPointF(x, y)))
    qtbot.mouseClick(preview.plot_widget.viewport(), LEFT, pos=pixel)
    hit: QPointF = view.mapSceneToView(preview.plot_widget.mapToScene(pixel))
    return hit


def settle(winder: StationHarness) -> dict[str, float]:
    winder.run(0.5)
    winder.run_until(lambda: winder.gcode_emulator.state == "Idle", timeout=60)
    winder.run(0.5)  # and a status report to the station
    return winder.gcode_emulator.position()


def view_range(preview: JobPreview) -> tuple[float, float, float, float]:
    (x0, x1), (y0, y1) = preview.plot.getViewBox().viewRange()
    return x0, x1, y0, y1


def test_the_limits_are_the_disc_the_tool_reaches(preview: JobPreview) -> None:
    outline = points(preview.limits_curve)
    assert len(outline) > 100
    assert np.allclose(np.hypot(outline[:, 0], outline[:, 1]), REACH)
    assert outline[:, 0].min() == pytest.approx(-REACH) and outline[:, 1].min() < -REACH + 1
    assert "reach" in preview.hint_label.text()
    assert preview.plot.getAxis("bottom").labelUnits == "mm"
    # Without a job, Fit shows the whole reach, centred on the turntable.
    x0, x1, y0, y1 = view_range(preview)
    assert x0 < -REACH and x1 > REACH and y0 < -REACH and y1 > REACH


def test_fit_shows_the_board_not_the_reach(qtbot: QtBot, preview: JobPreview) -> None:
    preview.set_program(build_program(BOARD))
    x0, x1, y0, y1 = view_range(preview)
    # The board's edge (100 mm) and the winding's start 2 cm outside it (S0-26), with a
    # margin: nowhere near the 250 mm reach.
    for low, high in ((x0, x1), (y0, y1)):
        assert -135 < low <= -100 and 100 <= high < 135
    preview.plot.getViewBox().setRange(xRange=(0, 20), yRange=(0, 20))
    qtbot.mouseClick(preview.fit_button, LEFT)
    assert view_range(preview) == pytest.approx((x0, x1, y0, y1))


def test_the_machine_marker_is_where_the_tool_is_over_the_board(
    winder: StationHarness, preview: JobPreview
) -> None:
    connected(winder)
    assert np.allclose(points(preview.position_marker), [[0.0, 0.0]])
    winder.gcode_session.move_absolute(0, 120.0)  # A, degrees
    winder.gcode_session.move_absolute(1, 80.0)  # X, mm from the centre
    settle(winder)
    expected = [80.0 * math.cos(math.radians(120.0)), 80.0 * math.sin(math.radians(120.0))]
    assert np.allclose(points(preview.position_marker), [expected], atol=1e-3)


def test_a_click_turns_the_shorter_way_then_moves_the_tool_out(
    qtbot: QtBot, winder: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    connected(winder)
    preview.plot.getViewBox().setRange(xRange=(-150, 150), yRange=(-150, 150), padding=0)
    hit = click_at(qtbot, preview, -60.0, -60.0)  # bearing -135°: a turn back, not 225° on
    bearing = math.degrees(math.atan2(hit.y(), hit.x()))
    radius = math.hypot(hit.x(), hit.y())
    assert bearing == pytest.approx(-135.0, abs=1.0) and radius == pytest.approx(84.85, abs=1.0)
    assert len(confirm.asked) == 1
    question = confirm.asked[0]
    assert question.startswith(f"Turn A by {bearing:+.1f}° to {bearing:.3f} deg")
    assert question.endswith(f"then move X to {radius:.3f} mm?")
    where = settle(winder)
    assert where["A"] == pytest.approx(bearing, abs=1e-3)
    assert where["X"] == pytest.approx(radius, abs=1e-3)
    assert preview.last_message == f"Moving to A {bearing:.3f} deg, X {radius:.3f} mm"
    # The marker is where the click was.
    assert np.allclose(points(preview.position_marker), [[hit.x(), hit.y()]], atol=1e-2)


def test_a_click_across_zero_keeps_turning_the_short_way(
    qtbot: QtBot, winder: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    """The base at 350°: a point at 10° is 20° on (A 370), not 340° back to A 10."""
    connected(winder)
    winder.gcode_session.move_absolute(0, 350.0)
    winder.gcode_session.move_absolute(1, 50.0)
    settle(winder)
    preview.plot.getViewBox().setRange(xRange=(-150, 150), yRange=(-150, 150), padding=0)
    point = (100.0 * math.cos(math.radians(10.0)), 100.0 * math.sin(math.radians(10.0)))
    hit = click_at(qtbot, preview, *point)
    bearing = math.degrees(math.atan2(hit.y(), hit.x()))
    assert bearing == pytest.approx(10.0, abs=1.0)
    where = settle(winder)
    assert where["A"] == pytest.approx(360.0 + bearing, abs=1e-3)
    assert where["X"] == pytest.approx(math.hypot(hit.x(), hit.y()), abs=1e-3)
    assert confirm.asked[0].startswith(f"Turn A by +{bearing + 10.0:.1f}°")
    moved = [e["pos"]["A"] for e in winder.gcode_emulator.event_log if e["event"] == "move"]
    assert moved[-2:] == [pytest.approx(360.0 + bearing, abs=1e-3)] * 2  # A, then X there


def test_a_click_beyond_the_reach_is_refused_without_asking(
    qtbot: QtBot, winder: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    connected(winder)
    preview.plot.getViewBox().setRange(xRange=(-300, 300), yRange=(-300, 300), padding=0)
    click_at(qtbot, preview, 200.0, 200.0)  # 283 mm from the centre
    winder.run(1.0)
    assert confirm.asked == []
    assert winder.gcode_emulator.position() == {"A": 0.0, "X": 0.0, "Z": 0.0}
    assert "beyond X's travel 0…250" in preview.last_message


def test_a_click_answered_no_or_while_not_connected_moves_nothing(
    qtbot: QtBot, winder: StationHarness, preview: JobPreview, confirm: Confirm
) -> None:
    preview.plot.getViewBox().setRange(xRange=(-150, 150), yRange=(-150, 150), padding=0)
    click_at(qtbot, preview, 50.0, 0.0)
    assert confirm.asked == [] and "not connected" in preview.last_message
    connected(winder)
    confirm.answer = False
    click_at(qtbot, preview, 50.0, 0.0)
    winder.run(1.0)
    assert len(confirm.asked) == 1 and preview.last_message == "Click-to-move cancelled"
    assert winder.gcode_emulator.position() == {"A": 0.0, "X": 0.0, "Z": 0.0}


def test_a_plain_program_is_projected_with_its_turns_drawn_as_arcs(preview: JobPreview) -> None:
    """A job in A and X (not a string-art one, which draws its own plane) lands on the board."""
    at = SourceRef("turns.txt", 1)
    program = Program(
        "turns",
        (move(at, A=0.0, X=100.0), move(at, A=90.0, X=100.0), move(at, A=90.0, X=50.0)),
    )
    preview.set_program(program)
    drawn = points(preview.work_markers)  # a plain point list's points are its work
    assert drawn[0] == pytest.approx([100.0, 0.0])
    assert drawn[-1] == pytest.approx([0.0, 50.0], abs=1e-9)
    # The quarter turn at 100 mm is an arc through the points between, not a chord.
    turn = drawn[1 : 1 + round(90.0 / ARC_STEP_DEG)]
    assert np.allclose(np.hypot(turn[:, 0], turn[:, 1]), 100.0)
    assert turn[-1] == pytest.approx([0.0, 100.0], abs=1e-9)


def test_a_string_art_job_is_drawn_in_its_own_plane(preview: JobPreview) -> None:
    program = build_program(BOARD)
    preview.set_program(program)
    own = program.preview_path("A", "X")
    travel = points(preview.travel_curve)
    finite = travel[np.isfinite(travel[:, 0])]
    # Every drawn travel point is one of the program's own board-plane vertices.
    assert len(finite) and all(np.isclose(own.coords, p).all(axis=1).any() for p in finite)


def test_a_cartesian_gcode_machine_keeps_its_rectangle(qtbot: QtBot, qapp: object) -> None:
    harness = StationHarness(load_profile("corexy-plotter"))
    try:
        widget = JobPreview(harness.station, confirm=Confirm(False), throttle_ms=0)
        qtbot.addWidget(widget)
        assert widget.polar is None
        outline = points(widget.limits_curve)
        travel = [axis.travel for axis in harness.station.profile.axes[:2]]
        corners = [[0, 0], [travel[0], 0], [travel[0], travel[1]], [0, travel[1]], [0, 0]]
        assert np.allclose(outline, corners)
        widget.close()
    finally:
        harness.close()
