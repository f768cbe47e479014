"""The preview of a string-art job: nails, faint thread, what is wound and the current nail."""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np
import pytest
from PySide6.QtGui import QColor, QImage
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art.program import StringArtProgram, build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.jobs.program import Program, SourceRef, move
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs.preview import THREAD_ALPHA, JobPreview


def points(item: object) -> np.ndarray:
    x, y = item.getData()  # type: ignore[attr-defined]
    if x is None:
        return np.empty((0, 2))
    return np.column_stack((np.asarray(x), np.asarray(y)))


def job(sequence: list[int], nails: int = 8) -> StringArtJob:
    return StringArtJob(StringArtParams(0, nails, 10.0), tuple(sequence))


@pytest.fixture
def preview(qtbot: QtBot, qapp: object) -> Iterator[JobPreview]:
    harness = StationHarness(load_profile("string-art"))
    widget = JobPreview(harness.station, confirm=lambda _text: False, throttle_ms=0)
    qtbot.addWidget(widget)
    widget.resize(500, 500)
    widget.show()
    qtbot.waitExposed(widget)
    yield widget
    widget.close()
    harness.close()


def test_nails_and_thread_replace_the_needle_path(preview: JobPreview) -> None:
    program = build_program(job([0, 4, 2, 6]))
    preview.set_program(program)
    extras = preview.string_art
    nails = job([0, 1]).nail_positions()  # 8 nails at 85 mm, every 45°
    assert np.allclose(points(extras.nails), nails)
    # Three connections, nail to nail: 0→4, 4→2, 2→6.
    assert np.allclose(points(extras.thread), nails[[0, 4, 4, 2, 2, 6]])
    assert extras.thread.opts["pen"].color().alpha() == THREAD_ALPHA
    assert not preview.work_curve.isVisible() and not preview.work_markers.isVisible()
    assert preview.travel_curve.isVisible()  # the drill phase's travel stays
    assert len(points(extras.current)) == 0  # nothing under way yet
    own = (extras.thread, extras.done_thread, extras.nails, extras.drilled, extras.current)
    assert all(item.isVisible() for item in own)

    preview.set_program(Program("plain", (move(SourceRef("p.txt", 1), A=1.0, X=2.0),)))
    assert preview.work_curve.isVisible() and preview.work_markers.isVisible()
    assert len(points(extras.nails)) == 0 and len(points(extras.thread)) == 0
    # Empty, so hidden: not asked for bounds nor painted on every frame of another job.
    hidden = (*own, *extras.thread_bands, *extras.done_bands, extras.picture)
    assert not any(item.isVisible() for item in hidden)
    preview.set_program(program)  # string art again: shown again
    assert all(item.isVisible() for item in own)


def test_progress_shows_drilled_nails_wound_thread_and_the_current_nail(
    preview: JobPreview,
) -> None:
    program = build_program(job([0, 4, 2, 6]))
    assert isinstance(program, StringArtProgram)
    preview.set_program(program)
    extras = preview.string_art
    nails = job([0, 1]).nail_positions()

    # Operation 0 is the drill phase's comment, 1 the drill to 1 cm above the board; 2…6
    # drill nail 0 (turn, radius, down, 250 ms, up); 7…11 nail 1.
    preview.set_done(8)  # nail 0 drilled, nail 1 under way
    assert np.allclose(points(extras.drilled), nails[:1])
    assert np.allclose(points(extras.current), nails[[1]])
    assert len(points(extras.done_thread)) == 0

    wait = program.wait_index
    preview.set_done(wait)  # waiting for the operator: every nail drilled, nail 0 to tie
    assert len(points(extras.drilled)) == 8
    assert np.allclose(points(extras.current), nails[[0]])

    second = int(np.flatnonzero(program.entry_of_op == 2)[0])
    preview.set_done(second + 1)  # 0→4 wound, 4→2 under way
    assert np.allclose(points(extras.done_thread), nails[[0, 4]])
    assert np.allclose(points(extras.current), nails[[2]])

    preview.set_done(len(program))
    assert np.allclose(points(extras.done_thread), nails[[0, 4, 4, 2, 2, 6]])
    assert np.allclose(points(extras.current), nails[[6]])


def test_another_kind_of_job_after_a_wound_one_shows_none_of_its_progress(
    preview: JobPreview,
) -> None:
    program = build_program(job([0, 4, 2, 6]))
    preview.set_program(program)
    extras = preview.string_art
    preview.set_done(len(program))
    assert len(points(extras.done_thread)) and len(points(extras.drilled))
    plain = Program("plain", tuple(move(SourceRef("p.txt", i + 1), X=float(i)) for i in range(9)))
    preview.set_program(plain)
    for done in (3, 6, 9):  # its progress steps leave the winder's done items empty
        preview.set_done(done)
        assert len(points(extras.done_thread)) == 0
        assert len(points(extras.drilled)) == 0 and len(points(extras.current)) == 0
    preview.set_program(program)  # the wound job again: its progress drawn again
    preview.set_done(8)
    assert len(points(extras.drilled)) == 1 and len(points(extras.current)) == 1


def _darkness(image: QImage, x: int, y: int) -> int:
    colour = QColor(image.pixel(x, y))
    return 3 * 255 - colour.red() - colour.green() - colour.blue()


def test_crossing_threads_look_denser(preview: JobPreview) -> None:
    """The same chord wound six times is darker than wound once: each segment is blended on
    its own, so density shows."""
    view = preview.plot.getViewBox()

    def darkness_at_centre(sequence: list[int]) -> int:
        preview.set_program(build_program(job(sequence)))
        preview.travel_curve.setVisible(False)
        preview.limits_curve.setVisible(False)
        preview.position_marker.setVisible(False)  # the machine sits at the centre
        preview.plot.showGrid(x=False, y=False)
        view.setRange(xRange=(-90, 90), yRange=(-90, 90), padding=0)
        preview.plot_widget.viewport().repaint()
        image = preview.plot_widget.grab().toImage()
        centre = preview.plot_widget.mapFromScene(view.mapViewToScene(view.viewRect().center()))
        return max(
            _darkness(image, centre.x() + dx, centre.y() + dy)
            for dx in range(-2, 3)
            for dy in range(-2, 3)
        )

    once = darkness_at_centre([0, 4])  # one diameter through the centre
    six = darkness_at_centre([0, 4, 0, 4, 0, 4, 0])
    assert 0 < once < six
