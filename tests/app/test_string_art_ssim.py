"""The string-art quality figure's SSIM, written in numpy: checked on cases with known answers.

Where scikit-image happens to be installed (it is no dependency), the map is
also compared with its ``structural_similarity`` at the same settings.
"""

from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from app.string_art_generator.quality import (
    K1,
    K2,
    gaussian_blur,
    gaussian_kernel,
    measure,
    ssim_map,
)

images = arrays(
    np.float64,
    st.tuples(st.integers(1, 24), st.integers(1, 24)),
    elements=st.floats(0, 1, allow_nan=False),
)


def test_kernel_is_the_normalised_gaussian_of_eleven_taps() -> None:
    kernel = gaussian_kernel(1.5)
    assert len(kernel) == 11  # int(3.5 * 1.5 + 0.5) = 5 taps either side
    assert kernel.sum() == pytest.approx(1.0)
    assert kernel[5] / kernel[6] == pytest.approx(np.exp(0.5 / 1.5**2))
    assert np.allclose(kernel, kernel[::-1])


def test_blur_of_one_pixel_is_the_kernel_squared() -> None:
    image = np.zeros((31, 31))
    image[15, 15] = 1.0
    kernel = gaussian_kernel(1.5)
    expected = np.zeros((31, 31))
    expected[10:21, 10:21] = np.outer(kernel, kernel)
    assert np.allclose(gaussian_blur(image), expected, atol=1e-15)


def test_blur_mirrors_the_edges() -> None:
    """A ramp mirrored at its edge: the blurred edge pixel is the mean of itself and its mirror."""
    ramp = np.tile(np.arange(20, dtype=np.float64), (5, 1))
    blurred = gaussian_blur(ramp)
    kernel = gaussian_kernel(1.5)
    # the column 0 sees columns 4 3 2 1 0 | 0 1 2 3 4 5
    mirrored = np.array([4, 3, 2, 1, 0, 0, 1, 2, 3, 4, 5], dtype=np.float64)
    assert blurred[2, 0] == pytest.approx(float(kernel @ mirrored))
    assert blurred[2, 10] == pytest.approx(10.0)  # a ramp away from the edges stays itself


@settings(max_examples=60, deadline=None)
@given(images)
def test_an_image_is_perfectly_like_itself(image: np.ndarray) -> None:
    assert np.allclose(ssim_map(image, image), 1.0)


@settings(max_examples=60, deadline=None)
@given(st.floats(0, 1), st.floats(0, 1))
def test_two_flat_images_compare_by_luminance_alone(a: float, b: float) -> None:
    """No variance, no covariance: SSIM = (2ab + C1) / (a² + b² + C1) everywhere."""
    c1 = K1**2
    got = ssim_map(np.full((12, 9), a), np.full((12, 9), b))
    assert np.allclose(got, (2 * a * b + c1) / (a * a + b * b + c1))


def test_an_inverted_checkerboard_is_structurally_opposite() -> None:
    """Mean 0.5 both, equal variances, covariance -variance: SSIM = (C2 - 2v) / (2v + C2) inside."""
    board = (np.indices((40, 40)).sum(axis=0) % 2).astype(np.float64)
    got = ssim_map(board, 1.0 - board)
    inside = got[10:30, 10:30]
    mean = gaussian_blur(board)[10:30, 10:30]
    var = gaussian_blur(board * board)[10:30, 10:30] - mean**2
    c1, c2 = K1**2, K2**2
    luminance = (2 * mean * (1 - mean) + c1) / (mean**2 + (1 - mean) ** 2 + c1)
    assert np.allclose(inside, luminance * (c2 - 2 * var) / (2 * var + c2))
    assert inside.max() < -0.9


@settings(max_examples=40, deadline=None)
@given(images, images)
def test_symmetric_and_bounded(a: np.ndarray, b: np.ndarray) -> None:
    if a.shape != b.shape:
        b = np.resize(b, a.shape)
    ab, ba = ssim_map(a, b), ssim_map(b, a)
    assert np.allclose(ab, ba)
    assert np.all(ab <= 1.0 + 1e-12) and np.all(ab >= -1.0 - 1e-12)


def test_measure_counts_only_the_board() -> None:
    target = np.zeros((30, 30))
    darkness = np.zeros((30, 30))
    darkness[:, 20:] = 1.0  # wrong only outside the mask
    mask = np.zeros((30, 30), dtype=bool)
    mask[:, :5] = True
    quality = measure(target, darkness, mask)
    assert quality.mae == 0.0
    assert quality.ssim == pytest.approx(1.0)


def test_same_as_scikit_image_where_it_is_installed() -> None:
    # scikit-image is only in the bench extra (not a runtime or test dependency any more):
    # the analytic cases above always run; this cross-check runs where it is installed.
    metrics = pytest.importorskip("skimage.metrics")
    rng = np.random.default_rng(5)
    a = rng.uniform(0, 1, (64, 48))
    b = np.clip(a + rng.normal(0, 0.2, a.shape), 0, 1)
    _, theirs = metrics.structural_similarity(
        a,
        b,
        data_range=1.0,
        full=True,
        gaussian_weights=True,
        sigma=1.5,
        use_sample_covariance=False,
    )
    assert np.allclose(ssim_map(a, b), theirs, atol=1e-12)
