"""How close the thread picture is to the photo: mean absolute error and SSIM on the board.

Both are measured on the darkness images at the generator's raster, inside
the nails' outline only (outside it no thread can go, and counting it would
flatter every method alike).  SSIM is Wang et al.'s, with their reference
settings as scikit-image computes them (a Gaussian window of sigma 1.5 cut
at 3.5 sigma, edges mirrored, population variances), written out here in
numpy: one figure did not justify scikit-image and scipy in every install.
The map is averaged over the pixels inside the outline.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

FloatImage = npt.NDArray[np.float64]

SIGMA = 1.5
TRUNCATE = 3.5  # the window's half-width in sigmas (scikit-image's choice: 11 x 11 pixels)
K1, K2 = 0.01, 0.03  # the stabilising constants of the SSIM paper, times the data range


@dataclass(frozen=True)
class Quality:
    mae: float  # mean |thread - photo| darkness on the board, 0 (same) … 1
    ssim: float  # structural similarity on the board, 1 (same) … -1

    def __str__(self) -> str:
        return f"MAE {self.mae:.4f}, SSIM {self.ssim:.4f}"


def measure(target: np.ndarray, darkness: np.ndarray, mask: np.ndarray) -> Quality:
    a = np.asarray(target, dtype=np.float64)
    b = np.asarray(darkness, dtype=np.float64)
    mae = float(np.abs(a - b)[mask].mean())
    return Quality(mae, float(ssim_map(a, b)[mask].mean()))


def ssim_map(a: FloatImage, b: FloatImage, data_range: float = 1.0) -> FloatImage:
    """The structural similarity of two images at every pixel (same shape), 1 where equal."""
    c1 = (K1 * data_range) ** 2
    c2 = (K2 * data_range) ** 2
    mean_a, mean_b = gaussian_blur(a), gaussian_blur(b)
    var_a = gaussian_blur(a * a) - mean_a * mean_a
    var_b = gaussian_blur(b * b) - mean_b * mean_b
    cov = gaussian_blur(a * b) - mean_a * mean_b
    luminance = (2 * mean_a * mean_b + c1) / (mean_a**2 + mean_b**2 + c1)
    structure = (2 * cov + c2) / (var_a + var_b + c2)
    result: FloatImage = luminance * structure
    return result


def gaussian_kernel(sigma: float = SIGMA, truncate: float = TRUNCATE) -> FloatImage:
    """The normalised 1-D Gaussian window, ``int(truncate * sigma + 0.5)`` taps either side."""
    radius = int(truncate * sigma + 0.5)
    x = np.arange(-radius, radius + 1, dtype=np.float64)
    weights = np.exp(-0.5 * (x / sigma) ** 2)
    kernel: FloatImage = weights / weights.sum()
    return kernel


def gaussian_blur(image: FloatImage, sigma: float = SIGMA) -> FloatImage:
    """A separable Gaussian blur with mirrored edges (``d c b a | a b c d | d c b a``)."""
    kernel = gaussian_kernel(sigma)
    radius = len(kernel) // 2
    out = np.asarray(image, dtype=np.float64)
    for axis in (0, 1):
        pad = [(0, 0), (0, 0)]
        pad[axis] = (radius, radius)
        padded = np.pad(out, pad, mode="symmetric")
        size = out.shape[axis]
        out = sum(
            (w * np.take(padded, np.arange(i, i + size), axis=axis) for i, w in enumerate(kernel)),
            np.zeros_like(out),
        )
    return out
