"""String art from a photo: quality against plain greedy, speed, and the window's responsiveness.

Run through ``python tools/benchmark.py`` (or this file alone).  Figures only,
never asserted: the test suite checks that the weighted method beats the
baseline, this prints by how much and how fast.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from dataclasses import replace
from pathlib import Path

import numpy as np

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
ROOT = Path(__file__).resolve().parent.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from app.jobs.formats.string_art.reader import StringArtParams  # noqa: E402
from app.string_art_generator.baseline import plain_greedy  # noqa: E402
from app.string_art_generator.greedy import Settings, run  # noqa: E402
from app.string_art_generator.quality import Quality, measure  # noqa: E402
from app.string_art_generator.render import render_darkness  # noqa: E402
from app.string_art_generator.target import Adjust, target_darkness  # noqa: E402
from tests.helpers.string_art_images import TEST_IMAGES, face  # noqa: E402

#: The board of the cardioid sample: a circle of 200 nails, 14.5 cm radius.
BOARD = StringArtParams(0, 200, 14.5)
SOURCE_PX = 512
TICK_MS = 5


def bench_quality() -> list[str]:
    settings = Settings(lines=4000)
    skip = settings.skip_for(BOARD.nails)
    lines = [
        f"string art quality: {BOARD.nails} nails, {BOARD.radius_cm:g} cm board, budget "
        f"{settings.lines}, thread {settings.thread_mm:g} mm, skip {skip}, raster "
        f"{settings.resolution} px; error of the thread picture against the target on the board"
    ]
    images = dict(TEST_IMAGES)
    try:
        import skimage.data  # noqa: F401  (the bench extra: pip install -e '.[bench]')

        images["camera photo"] = _camera
    except ImportError:
        lines.append("  camera photo: scikit-image not installed (pip install -e '.[bench]')")
    for name, make in images.items():
        target = target_darkness(make(SOURCE_PX), Adjust(), settings.resolution)
        result = run(BOARD, target, settings)
        weighted = measure(target, result.darkness, result.mask)
        start = time.perf_counter()
        plain = plain_greedy(BOARD, target, settings.lines, settings.thread_mm, skip)
        plain_s = time.perf_counter() - start
        baseline = _measured(target, plain, settings, result.mask)
        # Plain greedy cut to the weighted method's thread count: fewer threads, less overdrawn.
        short = _measured(target, plain[: result.lines + 1], settings, result.mask)
        better = all(weighted.mae < b.mae and weighted.ssim > b.ssim for b in (baseline, short))
        lines.append(
            f"  {name:13s}: weighted {result.lines:4d} lines {weighted} ({result.seconds:.2f} s)"
            f" | plain greedy {len(plain) - 1} lines {baseline} ({plain_s:.2f} s)"
            f" | plain greedy {result.lines} lines {short}"
            f" | weighted {'better' if better else 'NOT better'}"
        )
    return lines


def _camera(_size: int) -> np.ndarray:
    """A real photo: scikit-image's bundled "camera" (512², a man with a camera on a tripod)."""
    from skimage import data

    photo: np.ndarray = data.camera().astype(np.float32) / 255.0
    return photo


def _measured(
    target: np.ndarray, sequence: tuple[int, ...], settings: Settings, mask: np.ndarray
) -> Quality:
    darkness = render_darkness(BOARD, sequence, settings.resolution, settings.thread_mm)
    return measure(target, darkness, mask)


def _usage() -> tuple[int, int, int]:
    """Voluntary switches, major page faults and involuntary switches so far (0 without
    the ``resource`` module, off Unix)."""
    try:
        import resource
    except ImportError:
        return 0, 0, 0
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_nvcsw, usage.ru_majflt, usage.ru_nivcsw


def bench_speed() -> list[str]:
    """The whole budget (no early stop), cold (line table built) and warm (table cached)."""
    lines = []
    for nails, budget in ((200, 4000), (300, 6000)):
        params = StringArtParams(0, nails, 14.5)
        settings = Settings(lines=budget, stop_when_no_gain=False)
        target = target_darkness(face(SOURCE_PX), Adjust(), settings.resolution)
        before = _usage()
        start, cpu = time.perf_counter(), time.process_time()
        run(params, target, settings)
        cold, cold_cpu = time.perf_counter() - start, time.process_time() - cpu
        start, cpu = time.perf_counter(), time.process_time()
        run(params, target, settings)
        warm, warm_cpu = time.perf_counter() - start, time.process_time() - cpu
        after = _usage()
        lines.append(
            f"string art speed: {nails} nails x {budget} lines on {settings.resolution} px: "
            f"{cold:.2f} s ({cold_cpu:.2f} s processor) with the line table built, "
            f"{warm:.2f} s ({warm_cpu:.2f} s processor) with it cached "
            f"(goal <= {10 if nails == 200 else 30} s); "
            # Why wall time exceeds processor time: waits of its own (voluntary switches:
            # I/O, locks, sleeps; page faults from disk) or other processes taking the
            # processor (involuntary switches: the machine's load).
            f"waited: {after[0] - before[0]} voluntary switches, "
            f"{after[1] - before[1]} page faults from disk, preempted "
            f"{after[2] - before[2]} times"
        )
    return lines


def bench_event_loop() -> list[str]:
    """300 nails x 6000 lines in the dialog, its worker running, a 5 ms timer on the GUI thread.

    The stall is the longest gap between two ticks beyond the 5 ms interval:
    how long the window could not react while the generator ran beside it
    (the line table built first, then every thread chosen, the picture shown
    as it grows).
    """
    from PIL import Image
    from PySide6.QtCore import QEventLoop, QTimer
    from PySide6.QtWidgets import QApplication

    from widgets.jobs.string_art_generator_dialog import StringArtGeneratorDialog

    app = QApplication.instance() or QApplication([])
    with tempfile.TemporaryDirectory() as folder:
        photo = Path(folder) / "face.png"
        Image.fromarray(np.round(face(SOURCE_PX) * 255).astype(np.uint8)).save(photo)
        dialog = StringArtGeneratorDialog(lambda _path: False, choose_image=lambda _w: photo)
        dialog.show()
        dialog.ask_image()
        while dialog.generate_button.isEnabled() is False:
            app.processEvents()
            time.sleep(0.01)
        dialog.nails.setValue(300)
        dialog.lines.setValue(6000)
        shown = dialog.settings
        # The whole budget: the dialog stops when more thread no longer helps.
        dialog.settings = lambda: replace(shown(), stop_when_no_gain=False)  # type: ignore
        ticks: list[float] = []
        loop = QEventLoop()
        timer = QTimer()
        timer.setInterval(TICK_MS)
        timer.timeout.connect(lambda: ticks.append(time.perf_counter()))
        shown_count: list[int] = []
        dialog.threadsShown.connect(shown_count.append)
        watcher = QTimer()
        watcher.setInterval(20)
        watcher.timeout.connect(lambda: None if dialog.running else loop.quit())
        start = time.perf_counter()
        timer.start()
        dialog.start()
        watcher.start()
        loop.exec()
        elapsed = time.perf_counter() - start
        timer.stop()
        watcher.stop()
        finished = dialog.finished_result
        dialog.close()
        dialog.deleteLater()
        app.processEvents()
    gaps = np.diff(ticks) * 1000.0 - TICK_MS
    made = finished.result.lines if finished is not None else 0
    return [
        f"string art in the dialog: 300 nails x {made} lines in {elapsed:.2f} s on the worker; "
        f"GUI thread: {len(ticks)} ticks of {TICK_MS} ms, longest stall {gaps.max():.1f} ms, "
        f"99th percentile {np.percentile(gaps, 99):.1f} ms (goal <= 100 ms); "
        f"picture redrawn {len(shown_count)} times"
    ]


def bench_string_art_generator() -> list[str]:
    return [*bench_quality(), *bench_speed(), *bench_event_loop()]


if __name__ == "__main__":
    for line in bench_string_art_generator():
        print(line, flush=True)
