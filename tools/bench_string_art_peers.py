"""String art against the generators we can run, scored by tools/string_art_score.py.

Rows: skimage's ``camera`` and ``astronaut`` photos, boards of 200 and 300
nails (a 26 cm nail circle), 1500 chords and the default budget.  Each
generator gets the photo and the chord count and nothing else:

* StepDeck: ``app.string_art_generator`` at its default settings, drawing
  the whole budget (``stop_when_no_gain`` off), so the counts are equal;
* a plain darkest-line greedy (``app.string_art_generator.baseline``), on
  the same raster and line table;
* kaspar98/StringArt (tools/string_art_kaspar98.py), on its own 300² canvas;
  it may stop before the count when no line helps (the count it drew is shown).

Every figure comes from the same independent render, with the processor
time each generator took.  Needs the ``bench`` extra (scikit-image, for the
photos and for kaspar98's ``line_aa``).  ``python tools/bench_string_art_peers.py
--picture PATH`` also saves the photo and the three results side by side.
"""

from __future__ import annotations

import os
import sys
import time
from collections.abc import Callable
from pathlib import Path

import numpy as np

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from app.jobs.formats.string_art.reader import StringArtParams  # noqa: E402
from app.string_art_generator.baseline import plain_greedy  # noqa: E402
from app.string_art_generator.greedy import Settings, run  # noqa: E402
from app.string_art_generator.target import Adjust, target_darkness  # noqa: E402

#: A 26 cm nail circle: 14.5 cm board radius less the 15 mm nail inset.
RADIUS_CM = 14.5
NAILS = (200, 300)
CHORDS = (1500, Settings().lines)


def photos() -> dict[str, np.ndarray]:
    """The two photos as lightness 0 … 1 (scikit-image's bundled test images)."""
    from skimage import color, data

    return {
        "camera": np.asarray(data.camera(), dtype=np.float32) / 255.0,
        "astronaut": np.asarray(color.rgb2gray(data.astronaut()), dtype=np.float32),
    }


def _timed(make: Callable[[], tuple[int, ...] | list[int]]) -> tuple[list[int], float]:
    start = time.process_time()
    sequence = list(make())
    return sequence, time.process_time() - start


def generators(photo: np.ndarray, nails: int, chords: int) -> dict[str, tuple[list[int], float]]:
    """Each generator's sequence for ``photo`` and the processor seconds it took."""
    from tools.string_art_kaspar98 import kaspar98

    params = StringArtParams(0, nails, RADIUS_CM)
    settings = Settings(lines=chords, stop_when_no_gain=False)
    target = target_darkness(photo, Adjust(), settings.resolution)
    skip = settings.skip_for(nails)
    return {
        "StepDeck": _timed(lambda: run(params, target, settings).sequence),
        "plain greedy": _timed(
            lambda: plain_greedy(params, target, chords, settings.thread_mm, skip)
        ),
        "kaspar98": _timed(lambda: kaspar98(photo, nails, chords)),
    }


def bench_string_art_peers() -> list[str]:
    try:
        import skimage  # noqa: F401
    except ImportError:
        return ["string art vs peers: scikit-image not installed (pip install -e '.[bench]')"]
    from tools.string_art_score import BLUR_PX, BOARD_MM, SIZE, THREAD_MM, score

    lines = [
        f"string art vs peers, independent score: {THREAD_MM} mm thread on a {BOARD_MM:g} mm "
        f"board drawn {SIZE} px across, blurred {BLUR_PX:g} px, RMSE / SSIM inside the circle "
        "(lower / higher is better); processor seconds"
    ]
    for name, photo in photos().items():
        for nails in NAILS:
            for chords in CHORDS:
                made = generators(photo, nails, chords)
                scores = {who: score(seq, nails, photo) for who, (seq, _) in made.items()}
                ours = scores["StepDeck"]
                wins = all(
                    ours.rmse < s.rmse and ours.ssim > s.ssim
                    for who, s in scores.items()
                    if who != "StepDeck"
                )
                cells = " | ".join(
                    f"{who} {len(seq) - 1} {scores[who]} ({seconds:.1f} s)"
                    for who, (seq, seconds) in made.items()
                )
                lines.append(
                    f"  {name:9s} {nails} nails x {chords:4d}: {cells} | "
                    f"StepDeck {'better on both' if wins else 'NOT better on both'}"
                )
    return lines


def save_picture(path: Path, name: str = "camera", nails: int = 200) -> None:
    """The photo and each generator's result at the default budget, side by side, as a PNG."""
    from PIL import Image, ImageDraw

    from app.string_art_generator.quality import gaussian_blur
    from tools.string_art_score import BLUR_PX, board_mask, photo_darkness, thread_picture

    photo = photos()[name]
    chords = CHORDS[-1]
    made = generators(photo, nails, chords)
    panels = [("photo", photo_darkness(photo))]
    panels += [
        (f"{who}, {len(seq) - 1} chords", gaussian_blur(thread_picture(seq, nails), BLUR_PX))
        for who, (seq, _) in made.items()
    ]
    side = 360
    mask = board_mask()
    sheet = Image.new("L", (side * len(panels), side + 24), 255)
    draw = ImageDraw.Draw(sheet)
    for k, (label, darkness) in enumerate(panels):
        grey = np.where(mask, 1.0 - np.clip(darkness, 0.0, 1.0), 1.0)
        tile = Image.fromarray(np.round(grey * 255.0).astype(np.uint8))
        sheet.paste(tile.resize((side, side), Image.Resampling.LANCZOS), (k * side, 24))
        draw.text((k * side + 8, 6), label, fill=0)
    sheet.save(path, optimize=True)


if __name__ == "__main__":
    import argparse

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0] if __doc__ else None)
    parser.add_argument("--picture", type=Path, help="save the side-by-side picture here")
    args = parser.parse_args()
    if args.picture:
        save_picture(args.picture)
    else:
        for line in bench_string_art_peers():
            print(line, f"[load {os.getloadavg()[0]:.2f}/{os.getloadavg()[1]:.2f}]", flush=True)
