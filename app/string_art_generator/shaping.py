"""What the greedy aims at: the photo's darkness with its edges sharpened, toned to the budget.

Two changes to the target, both because of how string art is seen:

* **Edges.**  A thread picture is judged by its structure as much as its
  tone: an eye finds the edges of a face in a few threads that lie along
  them.  The squared error alone spreads threads over a dark area's inside
  as readily as along its border.  An unsharp mask (the target plus
  ``sharpen`` times its difference from a ~1 mm Gaussian blur of itself)
  makes the border count more, so threads line up with edges; flat areas
  keep their tone, because the difference is zero there.
* **The budget's tone.**  When the operator asks for the whole budget
  (``stop_when_no_gain`` off), more thread than the photo's tone needs has
  to go somewhere; left to the squared error it piles up wherever it spoils
  least, and builds nothing.  Instead the target is darkened so that the
  budget's thread just covers it: threads stack as filters, so a darkness
  ``t`` wants a thread density ``-ln(1 - t)``, and scaling every density by
  the ratio ``k`` of the budget's thread to the density wanted turns ``t``
  into ``1 - (1 - t)^k`` -- the same picture, uniformly deeper, the extra
  thread following its shapes.  The greedy does this by counting each
  thread as ``1 / k`` of its opacity against the photo's own tone (the same
  line counts, as ``1 - (1 - a/k)^n`` is ``1 - ((1 - a)^n)^(1/k)`` to first
  order), which keeps the squared error in the photo's terms: deepening the
  target instead would squash its dark end against 1.  With the early stop
  on (the default) every thread counts whole.
"""

from __future__ import annotations

import numpy as np

from app.string_art_generator.lines import LineTable
from app.string_art_generator.quality import gaussian_blur

#: The blur the edges are found against, in mm on the board (a few thread widths).
SHARPEN_SIGMA_MM = 1.0
#: Darkness counted as full when working out the thread density wanted (ln(1 - 1) is -inf).
DARKEST = 0.98


def sharpened(target: np.ndarray, mask: np.ndarray, amount: float, pixel_mm: float) -> np.ndarray:
    """``target`` with its edges deepened by an unsharp mask of ``amount``, kept to 0 … 1."""
    if amount <= 0.0:
        return target
    blurred = gaussian_blur(target, sigma=SHARPEN_SIGMA_MM / pixel_mm)
    result: np.ndarray = np.clip(target + amount * (target - blurred), 0.0, 1.0)
    return np.where(mask, result, 0.0)


def budget_ratio(target: np.ndarray, mask: np.ndarray, table: LineTable, lines: int) -> float:
    """The budget's thread over the thread the target's tone wants (both in pixel areas).

    A line's thread is its length times its width in pixels; the budget's,
    the mean of the board's lines times ``lines``.
    """
    raster = table.key.raster
    thread_px = table.key.thread_mm / raster.pixel_mm
    lengths = np.concatenate([block.lengths for block in table.nails])
    if not len(lengths):
        return 1.0
    supplied = lines * float(lengths.mean()) * thread_px
    wanted = float(-np.log1p(-np.minimum(target[mask], DARKEST)).sum())
    return supplied / wanted if wanted > 0.0 else 1.0


def aim(
    target: np.ndarray, mask: np.ndarray, table: LineTable, *, sharpen: float, fill_budget: int
) -> tuple[np.ndarray, float]:
    """The darkness the greedy works towards, and the share of a thread's opacity it counts.

    ``fill_budget`` 0 keeps the photo's tone (every thread counted whole).
    """
    pixel_mm = table.key.raster.pixel_mm
    work = np.asarray(sharpened(np.where(mask, target, 0.0), mask, sharpen, pixel_mm), np.float32)
    ratio = budget_ratio(work, mask, table, fill_budget) if fill_budget else 1.0
    return work, 1.0 / max(ratio, 1.0)
