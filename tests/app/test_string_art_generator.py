"""The string-art generator: valid sequences, the thread model, budget, determinism, quality.

Expected values come from the thread model itself (lines.py): a thread
``w`` mm wide on pixels ``p`` mm across lays ``w / p`` pixel-widths of
darkness along every pixel of its length, whatever its slope; threads
over one pixel let through ``(1 - a1)(1 - a2)…`` of the light.  Quality
comparisons use the three pictures of ``tests/helpers/string_art_images.py``
on small boards so that each generation takes a fraction of a second.
"""

from __future__ import annotations

import dataclasses
import math
import os
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from PIL import Image

from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams, read_string_art
from app.string_art_generator import output
from app.string_art_generator.baseline import plain_greedy
from app.string_art_generator.board import BoardRaster, min_gap
from app.string_art_generator.greedy import Settings, default_skip, generate, run
from app.string_art_generator.lines import (
    LineKey,
    build_table,
    cached_table,
    line_table,
    rasterise,
)
from app.string_art_generator.quality import measure
from app.string_art_generator.render import render_darkness
from app.string_art_generator.shaping import aim
from app.string_art_generator.target import (
    Adjust,
    ImageError,
    crop_box,
    darkness,
    load_image,
    target_darkness,
)
from tests.helpers.string_art_images import TEST_IMAGES, face, logo

SMALL = StringArtParams(0, 60, 10.0)
HEXAGON = StringArtParams(6, 60, 10.0)
RES = 96


def target_of(picture: np.ndarray, size: int = RES) -> np.ndarray:
    return target_darkness(picture, Adjust(), size)


def assert_valid(sequence: tuple[int, ...], params: StringArtParams, skip: int) -> None:
    """What poradi.txt must be for the winder, and what the generator promises on top."""
    order = np.asarray(sequence)
    assert len(order) >= 2
    assert order.min() >= 0 and order.max() < params.nails
    assert not np.any(order[1:] == order[:-1]), "a nail twice in a row"
    gaps = min_gap(params.nails, order[1:], order[:-1])
    assert gaps.min() >= skip, f"a thread between nails {gaps.min()} apart (skip {skip})"


# --- the sequence ------------------------------------------------------------------------------


@settings(max_examples=15, deadline=None)
@given(
    tvar=st.sampled_from([0, 3, 4, 6, 8]),
    nails=st.integers(min_value=24, max_value=90),
    skip=st.integers(min_value=1, max_value=9),
    lines=st.integers(min_value=1, max_value=120),
    which=st.sampled_from(sorted(TEST_IMAGES)),
)
def test_every_sequence_is_a_valid_poradi_for_its_board(
    tvar: int, nails: int, skip: int, lines: int, which: str
) -> None:
    params = StringArtParams(tvar, nails, 9.0)
    result = run(
        params,
        target_of(TEST_IMAGES[which](64), 48),
        Settings(lines=lines, min_skip=skip, resolution=48, stop_when_no_gain=False),
    )
    assert result.lines == lines
    assert_valid(result.sequence, params, skip)
    if tvar:
        # Never along a polygon's edge: the thread would lie on the nails between.
        same = BoardRaster(params, 48).same_edge()
        order = np.asarray(result.sequence)
        assert not same[order[:-1], order[1:]].any()


def test_the_sequence_reads_back_through_the_winders_checks(tmp_path: Path) -> None:
    params = StringArtParams(6, 90, 12.0)
    result = run(params, target_of(face(200)), Settings(lines=300, resolution=RES))
    written = output.write_job(output.job_of(result), tmp_path)
    job = read_string_art(tmp_path / "poradi.txt")  # count, range and repeats, on their lines
    assert job.params == params and job.sequence == result.sequence
    assert [p.name for p in written] == ["param.txt", "poradi.txt"]


def test_the_budget_is_a_ceiling_and_the_full_budget_winds_every_line() -> None:
    target = target_of(logo(200))
    free = run(SMALL, target, Settings(lines=5000, resolution=RES))
    assert free.stopped_early and 0 < free.lines < 5000
    full = run(SMALL, target, Settings(lines=700, resolution=RES, stop_when_no_gain=False))
    assert full.lines == 700 and not full.stopped_early
    short = run(SMALL, target, Settings(lines=25, resolution=RES))
    assert short.lines == 25 and not short.stopped_early
    assert short.sequence == free.sequence[:26]  # the same choices, cut at the budget


def test_stopping_early_means_no_line_lowers_the_error_any_more() -> None:
    target = target_of(face(200))
    result = run(SMALL, target, Settings(lines=5000, resolution=RES))
    table = line_table(LineKey(BoardRaster(SMALL, RES), 0.15, default_skip(60)))
    # The error against what the greedy aims at: the photo with its edges deepened.
    aimed, opacity = aim(target, result.mask, table, sharpen=Settings().sharpen, fill_budget=0)
    assert opacity == 1.0
    block = table.nails[result.sequence[-1]]
    light = 1.0 - result.darkness.ravel()
    for k in range(len(block.others)):
        pixels, alpha = block.line(k)
        now = result.darkness.ravel()[pixels]
        want = aimed.ravel()[pixels]
        after = now + light[pixels] * alpha
        assert np.sum((want - after) ** 2) >= np.sum((want - now) ** 2) - 1e-4


def test_the_same_photo_and_settings_give_the_same_sequence() -> None:
    target = target_of(face(200))
    first = run(SMALL, target, Settings(lines=400, resolution=RES, thread_mm=0.2))
    second = run(SMALL, target.copy(), Settings(lines=400, resolution=RES, thread_mm=0.2))
    assert first.sequence == second.sequence
    started = run(SMALL, target, Settings(lines=400, resolution=RES, thread_mm=0.2, start_nail=7))
    assert started.sequence[0] == 7 and started.sequence != first.sequence


def test_settings_that_cannot_make_a_sequence_are_refused_before_any_work() -> None:
    target = target_of(face(100))
    for bad, words in (
        (Settings(lines=0, resolution=RES), "budget"),
        (Settings(thread_mm=0.0, resolution=RES), "thread width"),
        (Settings(min_skip=30, resolution=RES), "skip"),
        (Settings(start_nail=60, resolution=RES), "start nail"),
    ):
        with pytest.raises(ValueError, match=words):
            run(SMALL, target, bad)
    with pytest.raises(ValueError, match="raster"):
        run(SMALL, target_of(face(100), 64), Settings(resolution=RES))
    with pytest.raises(ValueError, match=r"about 8\.6 GB for the lines"):
        run(StringArtParams(0, 1000, 30.0), target, Settings(resolution=1000))


# --- quality ----------------------------------------------------------------------------------


@pytest.mark.parametrize("which", sorted(TEST_IMAGES))
def test_weighted_greedy_beats_plain_greedy_and_random_threads(which: str) -> None:
    """Same nails, skip, budget and thread; rendered with the same model; errors compared."""
    params = StringArtParams(0, 120, 14.5)
    settings = Settings(lines=2000, resolution=128)
    target = target_of(TEST_IMAGES[which](256), 128)
    result = run(params, target, settings)
    skip = default_skip(params.nails)
    weighted = measure(target, result.darkness, result.mask)
    plain = plain_greedy(params, target, settings.lines, settings.thread_mm, skip)
    baseline = measure(target, render_darkness(params, plain, 128, settings.thread_mm), result.mask)
    rng = np.random.default_rng(0)
    steps = rng.integers(skip, params.nails - skip + 1, size=result.lines)
    random_order = tuple(int(v) for v in np.cumsum(np.concatenate(([0], steps))) % params.nails)
    chance = measure(
        target, render_darkness(params, random_order, 128, settings.thread_mm), result.mask
    )
    assert weighted.mae < baseline.mae and weighted.ssim > baseline.ssim, (weighted, baseline)
    # Also against plain greedy stopped at the weighted method's thread count.
    cut = render_darkness(params, plain[: result.lines + 1], 128, settings.thread_mm)
    short = measure(target, cut, result.mask)
    assert weighted.mae < short.mae and weighted.ssim > short.ssim, (weighted, short)
    assert weighted.mae < chance.mae and weighted.ssim > chance.ssim, (weighted, chance)


def test_quality_figures_are_zero_error_for_a_perfect_copy_and_worse_for_a_blank() -> None:
    target = target_of(face(200))
    mask = BoardRaster(SMALL, RES).mask
    same = measure(target, target, mask)
    assert same.mae == 0.0 and same.ssim == pytest.approx(1.0)
    blank = measure(target, np.zeros_like(target), mask)
    assert blank.mae == pytest.approx(float(target[mask].mean()), rel=1e-6)
    assert blank.ssim < 0.5


# --- the thread model -------------------------------------------------------------------------


@pytest.mark.parametrize("angle", [0.0, 17.0, 45.0, 63.0, 90.0, 151.0])
def test_a_thread_lays_its_width_along_its_length_whatever_its_slope(angle: float) -> None:
    length, width_px = 60.0, 0.3
    start = np.array([[64.3, 50.7]])  # the whole line inside the 128² raster
    turn = math.radians(angle)
    end = start + length * np.array([[math.cos(turn), math.sin(turn)]])
    lines = rasterise(start, end, 128, width_px)
    # Darkness laid = width times length (in pixel units), to the one sample an end may add.
    assert float(lines.alpha.sum()) == pytest.approx(width_px * length, abs=2 * width_px * 1.5)
    rows, columns = np.divmod(lines.pixels, 128)
    # Every pixel it darkens is within a pixel of the true line.
    direction = (end - start)[0] / length
    offset = np.column_stack((columns - start[0, 0], rows - start[0, 1]))
    distance = np.abs(offset[:, 0] * direction[1] - offset[:, 1] * direction[0])
    assert distance[lines.alpha > 0].max() < 1.0 + 1e-9


def test_the_table_size_estimate_is_near_the_real_size() -> None:
    """The memory guard's estimate: close on a circle, on the safe side on a polygon."""
    for params, chosen, low, high in (
        (StringArtParams(0, 60, 10.0), Settings(resolution=96), 0.9, 1.1),
        (StringArtParams(0, 150, 10.0), Settings(resolution=160), 0.9, 1.1),
        (StringArtParams(6, 90, 10.0), Settings(resolution=128, min_skip=3), 1.0, 1.3),
    ):
        raster = BoardRaster(params, chosen.resolution)
        key = LineKey(raster, chosen.thread_mm, chosen.skip_for(params.nails))
        real = line_table(key).entries
        assert low * real <= chosen.table_entries(params) <= high * real


def test_the_opacity_is_the_real_thread_width_over_the_real_pixel() -> None:
    board = StringArtParams(0, 60, 16.5)  # nails on a circle of 150 mm radius
    for thread_mm, size in ((0.15, 100), (0.15, 200), (0.3, 200)):
        raster = BoardRaster(board, size)
        table = line_table(LineKey(raster, thread_mm, 2))
        pixels, alpha = table.between(0, 30)  # a diameter: 300 mm of thread
        laid_mm2 = float(alpha.sum()) * raster.pixel_mm**2
        assert laid_mm2 == pytest.approx(thread_mm * 300.0, rel=0.02)
        # Both ends hold the same pixels for the same line.
        back_pixels, back_alpha = table.between(30, 0)
        assert np.array_equal(pixels, back_pixels) and np.array_equal(alpha, back_alpha)


def test_the_preview_is_the_model_the_lines_were_chosen_by() -> None:
    """Rendering the finished sequence afresh gives the darkness the greedy built up."""
    result = run(SMALL, target_of(face(200)), Settings(lines=300, resolution=RES))
    again = render_darkness(SMALL, result.sequence, RES, result.settings.thread_mm)
    assert np.abs(again - result.darkness).max() < 1e-4
    # Threads over one pixel: 1 - (1 - a)² for two, whatever the order.
    twice = render_darkness(SMALL, (0, 30, 0), RES, 0.15)
    once = render_darkness(SMALL, (0, 30), RES, 0.15)
    assert np.allclose(twice, 1.0 - (1.0 - once) ** 2, atol=1e-6)


# --- cancelling, the cache ------------------------------------------------------------------


def test_a_cancelled_table_is_not_cached_and_a_finished_one_is() -> None:
    key = LineKey(BoardRaster(StringArtParams(0, 37, 11.0), 80), 0.2, 3)
    steps = build_table(key)
    assert [next(steps) for _ in range(5)] == [1, 2, 3, 4, 5]
    steps.close()
    assert cached_table(key) is None
    table = line_table(key)
    assert cached_table(key) is table and len(table.nails) == 37


def test_a_generation_stopped_half_way_reports_progress_and_keeps_nothing() -> None:
    params = StringArtParams(0, 41, 10.0)
    progress = generate(params, target_of(face(200)), Settings(lines=400, resolution=RES))
    seen = [next(progress) for _ in range(60)]
    progress.close()
    assert [p.phase for p in seen[:41]] == ["lines"] * 41
    threads = [p for p in seen if p.phase == "threads"]
    assert threads and all(p.result is None for p in seen)
    assert [p.done for p in threads] == sorted(p.done for p in threads)
    assert threads[-1].darkness is not None and threads[-1].darkness.max() > 0


def test_an_interrupted_write_leaves_no_file_of_the_set(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    job = StringArtJob(SMALL, (0, 20, 40, 5))
    real_replace = os.replace
    calls: list[str] = []

    def failing(src: str | Path, dst: str | Path) -> None:
        calls.append(str(dst))
        if len(calls) == 2:
            raise OSError("disk full")
        real_replace(src, dst)

    monkeypatch.setattr(output.os, "replace", failing)
    picture = np.zeros((10, 10), dtype=np.uint8)
    with pytest.raises(OSError, match="disk full"):
        output.write_job(job, tmp_path / "out", picture)
    left = sorted(p.name for p in (tmp_path / "out").iterdir())
    assert all(not name.endswith(".part") for name in left)
    assert "poradi.txt" not in left and "string-art.png" not in left


# --- the photo --------------------------------------------------------------------------------


def test_a_photo_is_read_cropped_and_given_contrast(tmp_path: Path) -> None:
    wide = np.zeros((100, 300), dtype=np.uint8)
    wide[:, 200:] = 255  # black on the left two thirds, white on the right third
    Image.fromarray(wide).save(tmp_path / "wide.png")
    lightness = load_image(tmp_path / "wide.png")
    assert lightness.shape == (100, 300)
    assert crop_box(lightness.shape, Adjust()) == (100.0, 0.0, 200.0, 100.0)
    assert crop_box(lightness.shape, Adjust(centre_x=1.0)) == (200.0, 0.0, 300.0, 100.0)
    assert crop_box(lightness.shape, Adjust(centre_x=1.0, zoom=2.0)) == (250.0, 25.0, 300.0, 75.0)
    # The middle is black, the right white (Lanczos reaches a pixel past the crop's edge).
    assert target_darkness(lightness, Adjust(), 16)[:, :-2].min() > 0.99
    assert target_darkness(lightness, Adjust(centre_x=1.0), 16)[:, 2:].max() < 0.01
    grey = np.array([[0.25, 0.5, 0.75]], dtype=np.float32)
    assert np.allclose(darkness(grey, Adjust(contrast=2.0)), [[1.0, 0.5, 0.0]])
    assert np.allclose(darkness(grey, Adjust(invert=True)), [[0.25, 0.5, 0.75]])
    assert np.allclose(darkness(grey, Adjust(brightness=0.25)), [[0.5, 0.25, 0.0]])


def test_what_is_not_a_photo_is_refused_with_its_name(tmp_path: Path) -> None:
    bad = tmp_path / "notes.png"
    bad.write_text("not a picture")
    with pytest.raises(ImageError, match=r"notes\.png"):
        load_image(bad)
    with pytest.raises(ImageError, match=r"missing\.jpg"):
        load_image(tmp_path / "missing.jpg")


@pytest.mark.parametrize("nails", [200, 370, 500, 580, 1200])
def test_the_fitted_raster_is_the_finest_that_can_be_built(nails: int) -> None:
    from app.string_art_generator.greedy import Settings as GeneratorSettings

    params = StringArtParams(0, nails, 13.0)
    chosen = GeneratorSettings()
    fitted = dataclasses.replace(chosen, resolution=chosen.fitted_resolution(params))
    assert fitted.check(params) is None
    assert fitted.resolution <= chosen.resolution
    if fitted.resolution < chosen.resolution:  # one pixel finer would not fit
        finer = dataclasses.replace(fitted, resolution=fitted.resolution + 1)
        assert finer.check(params) is not None
