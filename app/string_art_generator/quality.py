"""How close the thread picture is to the photo: mean absolute error and SSIM on the board.

Both are measured on the darkness images at the generator's raster, inside
the nails' outline only (outside it no thread can go, and counting it would
flatter every method alike).  SSIM is scikit-image's, over the whole
square, averaged over the pixels inside the outline.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from skimage.metrics import structural_similarity


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
    # Wang et al.'s reference settings: a Gaussian window of sigma 1.5, population variances.
    _mean, ssim_map = structural_similarity(  # type: ignore[no-untyped-call]
        a,
        b,
        data_range=1.0,
        full=True,
        gaussian_weights=True,
        sigma=1.5,
        use_sample_covariance=False,
    )
    return Quality(mae, float(np.asarray(ssim_map)[mask].mean()))
