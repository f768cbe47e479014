"""The benchmark's independent string-art score, and the generator judged by it.

The score (tools/string_art_score.py) draws a sequence its own way; these
check that its drawing holds the thread's real area, that threads stack as
filters, that a perfect picture scores perfectly, and that StepDeck's
generator beats the plain greedy by it (RMSE and SSIM both).
"""

from __future__ import annotations

import itertools

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.baseline import plain_greedy
from app.string_art_generator.greedy import Settings, run
from app.string_art_generator.target import Adjust, target_darkness
from tests.helpers.string_art_images import face
from tools.string_art_score import (
    BOARD_MM,
    SIZE,
    THREAD_MM,
    board_mask,
    nail_points,
    score,
    thread_picture,
)

NAILS = 120


@settings(max_examples=25, deadline=None)
@given(a=st.integers(0, NAILS - 1), gap=st.integers(3, NAILS // 2))
def test_a_chord_holds_the_threads_area_whatever_its_slope(a: int, gap: int) -> None:
    b = (a + gap) % NAILS
    darkness = thread_picture([a, b], NAILS)
    points = nail_points(NAILS)
    length_px = float(np.hypot(*(points[b] - points[a])))
    area = length_px * THREAD_MM / (BOARD_MM / SIZE)
    # Single-thread opacities are small, so darkness adds up to the covered area
    # (less the last fraction of a pixel at either end).
    assert abs(darkness.sum() - area) <= 0.01 * area + 0.6


def test_threads_stack_as_filters() -> None:
    once = thread_picture([0, 40], NAILS)
    twice = thread_picture([0, 40, 0], NAILS)
    np.testing.assert_allclose(twice, 1.0 - (1.0 - once) ** 2, atol=1e-9)
    assert twice.max() > once.max() > 0.0


def test_no_thread_on_a_white_photo_is_perfect_and_one_thread_is_not() -> None:
    white = np.ones((64, 64), dtype=np.float32)
    bare = score([0], NAILS, white)
    assert bare.rmse == 0.0 and bare.ssim == 1.0
    wound = score([0, 40], NAILS, white)
    assert wound.rmse > 0.0 and wound.ssim < 1.0


def test_the_mask_is_the_nail_circle() -> None:
    mask = board_mask()
    assert mask[SIZE // 2, SIZE // 2] and not mask[0, 0]
    assert 0.77 < mask.mean() < 0.79  # pi / 4 of the square


def test_the_generator_beats_the_plain_greedy_by_the_independent_score() -> None:
    photo = face(256)
    params = StringArtParams(0, NAILS, 14.5)
    for lines in (1000, 1500):
        chosen = Settings(lines=lines, stop_when_no_gain=False)
        target = target_darkness(photo, Adjust(), chosen.resolution)
        ours = score(run(params, target, chosen).sequence, NAILS, photo)
        skip = chosen.skip_for(NAILS)
        plain = score(plain_greedy(params, target, lines, chosen.thread_mm, skip), NAILS, photo)
        assert ours.rmse < plain.rmse and ours.ssim > plain.ssim, (lines, ours, plain)


def test_the_kaspar98_peer_pulls_only_lines_that_help_and_stops_when_none_does() -> None:
    pytest.importorskip("skimage")
    from tools.string_art_kaspar98 import SIDE, STRENGTH, canvas_target, kaspar98, nail_pixels

    photo = np.full((64, 64), 0.8, dtype=np.float32)  # its target: 0.72 everywhere
    order = kaspar98(photo, 40, 100_000)
    assert order[0] == 0 and 1 < len(order) < 100_000  # stopped on its own, well short
    from skimage.draw import line_aa

    points = nail_pixels(40)
    target = canvas_target(photo)
    canvas = np.ones((SIDE, SIDE))
    for a, b in itertools.pairwise(order):
        rr, cc, val = line_aa(*points[min(a, b)], *points[max(a, b)])
        after = np.clip(canvas[rr, cc] - STRENGTH * val, 0.0, 1.0)
        gain = np.sum((canvas[rr, cc] - target[rr, cc]) ** 2 - (after - target[rr, cc]) ** 2)
        assert gain > 0.0
        canvas[rr, cc] = after
