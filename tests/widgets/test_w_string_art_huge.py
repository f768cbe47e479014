"""A generator's 2-million-entry poradi.txt through the real jobs dock: loaded right, drawn merged.

The dock reads it on its loading thread (with the runner's checks and
estimate), the runner takes it READY, and the preview draws the thread as
each different chord once, as dark as its windings make it.  The figures
are checked against the file itself, not against what the loader says.
"""

from __future__ import annotations

import gc
import random
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PySide6.QtGui import QImage
from pytestqt.qtbot import QtBot

from app.jobs.formats.string_art import reader as reader_module
from app.jobs.formats.string_art.program import StringArtProgram, build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.jobs.run.runner import JobRunner, JobState
from app.profiles import load_profile
from tests.helpers.harness import StationHarness
from widgets.jobs import loading as loading_module
from widgets.jobs import source_lines as source_lines_module
from widgets.jobs.dock import JobsDock
from widgets.jobs.preview import THREAD_ALPHA
from widgets.jobs.string_art_thread import (
    BAND_EDGES,
    EXACT_CONNECTIONS,
    ThreadGeometry,
    WoundCounter,
    band_alpha,
    band_of,
)

NAILS = 160


def sequence(entries: int, nails: int = NAILS, seed: int = 1) -> list[int]:
    """A random nail order, never the same nail twice in a row (as a generator writes it)."""
    rng = random.Random(seed)
    out = [0]
    for _ in range(entries - 1):
        out.append((out[-1] + rng.randrange(1, nails)) % nails)
    return out


def chord_counts(order: list[int], nails: int = NAILS) -> dict[tuple[int, int], int]:
    """Windings per chord counted straight from the order (the test's own reckoning)."""
    a = np.asarray(order[:-1])
    b = np.asarray(order[1:])
    keys = np.minimum(a, b) * nails + np.maximum(a, b)
    unique, counts = np.unique(keys, return_counts=True)
    return {(int(k // nails), int(k % nails)): int(c) for k, c in zip(unique, counts, strict=True)}


def test_a_2m_entry_poradi_loads_through_the_dock_and_its_thread_is_drawn_merged(
    qtbot: QtBot, tmp_path: Path
) -> None:
    entries = 2_000_000
    order = sequence(entries)
    (tmp_path / "param.txt").write_text(
        f"tvar = 0\npocet_hrebiku = {NAILS}\npolomer_matrice = 12\n"
    )
    poradi = tmp_path / "poradi.txt"
    poradi.write_text(f"{entries}\n" + "\n".join(map(str, order)) + "\n")
    harness = StationHarness(load_profile("string-art"))
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    try:
        assert dock.open_path(poradi, background=True)
        qtbot.waitUntil(lambda: dock._loading is None, timeout=600_000)
        program = runner.program
        assert isinstance(program, StringArtProgram), dock.messages.toPlainText()
        assert runner.state is JobState.READY
        assert list(program.job.sequence) == order
        assert program.job.params == StringArtParams(0, NAILS, 12.0)
        # The checks and estimate made on the loading thread are the runner's own.
        assert runner.progress.estimate is not None and runner.progress.estimate.total_s > 0
        assert runner.progress.estimate.total_s == pytest.approx(
            runner.checker()(program).estimate.total_s  # type: ignore[union-attr]
        )

        extras = dock.preview.string_art
        geometry = extras.geometry
        assert geometry is not None and geometry.merged
        assert extras.thread_segments == entries - 1
        expected = chord_counts(order)
        assert geometry.chords == len(expected)
        drawn = {tuple(sorted(map(int, ends))) for ends in geometry.chord_ends}
        assert drawn == set(expected)
        # Each band holds exactly the chords wound that often, each chord once.
        nails = geometry.nail_xy
        total = 0
        for k, band in enumerate(extras.thread_bands):
            x, _y = band.getData()
            count = 0 if x is None else len(x) // 2
            assert count == sum(1 for c in expected.values() if band_of(np.array([c]))[0] == k)
            assert band.opts["pen"].color().alpha() == band_alpha(THREAD_ALPHA, k)
            total += count
        assert total == len(expected)
        exact_x, _ = extras.thread.getData()
        assert exact_x is None or len(exact_x) == 0  # not drawn one by one
        assert "drawn merged" in dock.messages.toPlainText()
        assert len(nails) == NAILS

        # Wound so far: the chords of the first connections, counted as the job goes.
        first_entry = int(np.flatnonzero(program.entry_of_op == 1001)[0])
        dock.preview.set_done(first_entry)
        wound = chord_counts(order[:1001])
        done_total = 0
        for band in extras.done_bands:
            x, _y = band.getData()
            done_total += 0 if x is None else len(x) // 2
        assert done_total == len(wound)
    finally:
        dock.close()
        runner.deleteLater()
        harness.close()


def test_bands_blend_like_the_windings_they_stand_for() -> None:
    assert band_of(np.array([1, 2, 3, 4, 5, 8, 9, 100])).tolist() == [0, 1, 2, 2, 3, 3, 4, 7]
    assert band_alpha(40, 0) == 40  # one winding: the thread's own opacity
    assert band_alpha(40, 1) > 40  # two windings blend darker
    alphas = [band_alpha(40, k) for k in range(len(BAND_EDGES))]
    assert alphas == sorted(alphas) and alphas[-1] <= 255


def test_a_small_job_stays_exact_and_the_wound_counter_is_append_only() -> None:
    small = build_program(StringArtJob(StringArtParams(0, 8, 10.0), (0, 4, 2, 6)))
    assert isinstance(small, StringArtProgram)
    assert not ThreadGeometry.of(small).merged
    order = sequence(EXACT_CONNECTIONS + 2, nails=12, seed=3)
    big = build_program(StringArtJob(StringArtParams(0, 12, 10.0), tuple(order)))
    assert isinstance(big, StringArtProgram)
    thread = ThreadGeometry.of(big)
    assert thread.merged and thread.chords <= 12 * 11 // 2
    counter = WoundCounter(thread)
    assert counter.advance(500) and counter.advance(1500)
    by_hand = chord_counts(order[:1501], nails=12)
    ends = [tuple(sorted(map(int, e))) for e in thread.chord_ends]
    assert {ends[i]: int(c) for i, c in enumerate(counter.counts) if c} == by_hand
    assert not counter.advance(1500)  # nothing new: nothing redrawn
    assert counter.advance(10)  # a new run: counted again from the start
    assert int(counter.counts.sum()) == 10


@settings(max_examples=400, deadline=None)
@given(
    text=st.text(alphabet="ab\r\n\x0b\x1c\u2028 ", max_size=80),
    chunk=st.integers(min_value=1, max_value=9),
)
def test_the_source_lines_split_in_pieces_are_the_files_lines(text: str, chunk: int) -> None:
    """Split in pieces (the GUI thread gets the lock between them), the lines are the same.

    A piece ends only after an LF, so a CR LF pair is never cut in two and a line
    longer than a piece runs on; whatever the line ends, the result is
    ``splitlines`` of the whole (kept as the text and where each line starts).
    """
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(source_lines_module, "SPLIT_CHUNK_CHARS", chunk)
        lines = source_lines_module.split_lines(text)
        assert list(lines) == text.splitlines()
        assert len(lines) == len(text.splitlines())


def _grey(image: QImage) -> np.ndarray:
    """The image's RGB as integers (rows, columns, 3)."""
    rgb = image.convertToFormat(QImage.Format.Format_RGB32)
    raw = np.frombuffer(rgb.constBits(), np.uint8).reshape(rgb.height(), rgb.bytesPerLine() // 4, 4)
    return raw[:, : rgb.width(), :3].astype(np.int64)


def test_a_merged_thread_loaded_in_the_background_is_shown_painted_as_its_lines_would_be(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """Painted on the loading thread, the chords look as the line bands draw them; zoomed, the
    bands are drawn again (an image scaled up would thicken the one-pixel lines)."""
    order = sequence(EXACT_CONNECTIONS + 5000, nails=60, seed=4)
    (tmp_path / "param.txt").write_text("tvar = 0\npocet_hrebiku = 60\npolomer_matrice = 12\n")
    poradi = tmp_path / "poradi.txt"
    poradi.write_text(f"{len(order)}\n" + ",".join(map(str, order)) + "\n")
    harness = StationHarness(load_profile("string-art"))
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    try:
        dock.resize(900, 700)
        dock.show()
        qtbot.waitExposed(dock)
        assert dock.open_path(poradi, background=True)
        qtbot.waitUntil(lambda: dock._loading is None, timeout=120_000)
        extras = dock.preview.string_art
        assert extras.geometry is not None and extras.geometry.merged
        picture = extras.picture.picture
        assert picture is not None and extras.picture.isVisible()
        assert not any(band.isVisible() for band in extras.thread_bands)
        # The bands still hold the chords (shown when the view strays from the image's scale).
        assert sum(len(band.getData()[0]) // 2 for band in extras.thread_bands) == (
            extras.geometry.chords
        )
        qtbot.wait(200)
        painted = _grey(dock.preview.plot_widget.grab().toImage())
        extras._show_picture(False)
        qtbot.wait(200)
        drawn = _grey(dock.preview.plot_widget.grab().toImage())
        assert painted.shape == drawn.shape
        thread = (drawn != 255).any(axis=2)  # where anything is drawn (grid included)
        assert thread.mean() > 0.05
        # Each chord as dark as its windings: the same picture up to a pixel's placing.
        assert np.abs(painted - drawn).mean() < 2.0
        assert abs(float(painted[thread].mean()) - float(drawn[thread].mean())) < 4.0

        extras._show_picture(True)
        dock.preview.plot.getViewBox().scaleBy((0.3, 0.3))  # zoomed in: lines, not pixels
        qtbot.waitUntil(lambda: not extras.picture.isVisible(), timeout=5000)
        assert all(band.isVisible() for band in extras.thread_bands)
    finally:
        dock.close()
        runner.deleteLater()
        harness.close()


def test_no_automatic_garbage_collection_while_the_dock_loads_a_file(
    qtbot: QtBot, tmp_path: Path
) -> None:
    """A full collection on the loading thread held the interpreter lock (the GUI thread
    waited a tenth of a second and more); it is off while the file loads, on again after."""
    seen: list[bool] = []
    real = loading_module.load_job

    def load_job(*args: object, **kwargs: object) -> object:
        seen.append(gc.isenabled())
        return real(*args, **kwargs)  # type: ignore[arg-type]

    order = sequence(1000, nails=40)
    (tmp_path / "param.txt").write_text("tvar = 0\npocet_hrebiku = 40\npolomer_matrice = 12\n")
    poradi = tmp_path / "poradi.txt"
    poradi.write_text(f"{len(order)}\n" + ",".join(map(str, order)) + "\n")
    harness = StationHarness(load_profile("string-art"))
    runner = JobRunner(harness.station, tmp_path / "checkpoints")
    dock = JobsDock(harness.station, runner, confirm=lambda _t: False, throttle_ms=0)
    qtbot.addWidget(dock)
    collecting = gc.isenabled()  # off for the suite (tests/conftest.py), as in the station
    gc.enable()  # a script's process, say: collection on, and the load must not leave it off
    try:
        with pytest.MonkeyPatch.context() as patch:
            patch.setattr(loading_module, "load_job", load_job)
            assert dock.open_path(poradi, background=True)
            qtbot.waitUntil(lambda: dock._loading is None, timeout=60_000)
        assert seen == [False]
        assert gc.isenabled()
        assert isinstance(runner.program, StringArtProgram)
    finally:
        if not collecting:
            gc.disable()
        dock.close()
        runner.deleteLater()
        harness.close()


@settings(max_examples=50, deadline=None)
@given(
    values=st.lists(st.integers(min_value=0, max_value=10_000), max_size=40),
    chunk=st.integers(min_value=1, max_value=7),
)
def test_the_sequence_converted_in_pieces_is_the_same(values: list[int], chunk: int) -> None:
    """Converted a piece at a time (the GUI thread gets the lock between pieces), the
    sequence and its array are what one conversion gives, and a job's array is its own."""
    with pytest.MonkeyPatch.context() as patch:
        patch.setattr(reader_module, "CONVERT_CHUNK", chunk)
        array = np.asarray(values, dtype=np.int64)
        assert reader_module.int_tuple(array) == tuple(values)
        assert reader_module.int_array(tuple(values)).tolist() == values
        job = StringArtJob(StringArtParams(0, 10_001, 12.0), tuple(values))
        assert job.indices.tolist() == values


def test_a_read_job_keeps_the_files_numbers_as_its_array(tmp_path: Path) -> None:
    order = sequence(500, nails=30)
    (tmp_path / "param.txt").write_text("tvar = 0\npocet_hrebiku = 30\npolomer_matrice = 12\n")
    poradi = tmp_path / "poradi.txt"
    poradi.write_text(f"{len(order)}\n" + ",".join(map(str, order)) + "\n")
    job = reader_module.read_string_art(poradi)
    assert job.sequence == tuple(order)
    assert job.indices.dtype == np.int64 and job.indices.tolist() == order
    assert not job.indices.flags.writeable  # the job's own numbers: nobody changes them
    assert job == StringArtJob(job.params, tuple(order))  # the array is not part of equality
