"""A huge string-art job's preview and estimate are made a chunk at a time: the same results.

The loading thread cuts its numpy passes into chunks so the window gets the
interpreter lock between them; here the chunks are made tiny, and what comes
out is checked against the whole computed in one pass, the plain way.
"""

from __future__ import annotations

import random

import numpy as np
import pytest

import app.jobs.estimate.gcode as estimate_module
import widgets.jobs.string_art_thread as thread_module
from app.jobs.estimate.gcode import estimate_gcode
from app.jobs.formats.string_art.program import StringArtProgram, build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.profiles import load_profile
from widgets.jobs.preview import ProgramGeometry
from widgets.jobs.string_art_thread import EXACT_CONNECTIONS, ThreadGeometry


def order(entries: int, nails: int, seed: int) -> tuple[int, ...]:
    rng = random.Random(seed)
    out = [0]
    for _ in range(entries - 1):
        out.append((out[-1] + rng.randrange(1, nails)) % nails)
    return tuple(out)


@pytest.fixture(scope="module")
def big() -> StringArtProgram:
    nails = 40
    program = build_program(
        StringArtJob(StringArtParams(0, nails, 10.0), order(EXACT_CONNECTIONS + 50, nails, 5)),
        load_profile("string-art"),
    )
    assert isinstance(program, StringArtProgram)
    return program


def test_chords_numbered_in_chunks_are_numpys_unique(
    big: StringArtProgram, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(thread_module, "CHORD_CHUNK", 7)
    thread = ThreadGeometry.of(big)
    sequence = np.asarray(big.job.indices)
    a, b = sequence[:-1], sequence[1:]
    nails = len(thread.nail_xy)
    keys = np.minimum(a, b) * nails + np.maximum(a, b)
    unique, inverse = np.unique(keys, return_inverse=True)
    assert thread.merged
    assert np.array_equal(thread.chord_ends[:, 0] * nails + thread.chord_ends[:, 1], unique)
    assert np.array_equal(thread.chord_of, inverse)


def test_the_estimate_in_chunks_is_the_estimate_in_one(
    big: StringArtProgram, monkeypatch: pytest.MonkeyPatch
) -> None:
    profile = load_profile("string-art")
    whole = estimate_gcode(big, profile)
    monkeypatch.setattr(estimate_module, "ESTIMATE_CHUNK", 97)
    chunked = estimate_gcode(big, profile)
    assert chunked.total_s == pytest.approx(whole.total_s, rel=1e-9)
    assert np.allclose(chunked.cumulative_s, whole.cumulative_s, rtol=1e-9, atol=1e-6)
    # And the steps are each move's own time: the carried value is the axis' last one.
    assert whole.total_s == pytest.approx(big.estimate_s, rel=1e-9)


def test_a_merged_jobs_preview_lays_out_the_travel_not_the_winding(big: StringArtProgram) -> None:
    geometry = ProgramGeometry(big, "A", "X", polar=True)
    full = big.preview_path("A", "X")
    travel = full.coords[~full.pen]
    assert geometry.thread is not None and geometry.thread.merged
    # The drilling's travel as the whole path has it, NaN between its runs only.
    finite = np.isfinite(geometry.travel.x)
    assert np.allclose(geometry.travel.x[finite], travel[:, 0])
    assert np.allclose(geometry.travel.y[finite], travel[:, 1])
    assert len(geometry.work.x) == 0
    # The view's extent holds every point the whole path has (the winding included).
    assert geometry.bounds is not None
    x0, x1, y0, y1 = geometry.bounds
    assert x0 <= np.nanmin(full.coords[:, 0]) and x1 >= np.nanmax(full.coords[:, 0])
    assert y0 <= np.nanmin(full.coords[:, 1]) and y1 >= np.nanmax(full.coords[:, 1])
