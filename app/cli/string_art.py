"""``stepdeck string-art IMAGE --board TVAR,NAILS,RADIUS_CM --lines N --out DIR``.

The station's generator without the window: reads the photo, makes the
nail sequence for the board, writes ``param.txt`` + ``poradi.txt`` (the
winder's SD-card pair) and ``string-art.png`` (the thread picture at the
board's real thread width) into DIR, and prints the quality figures and the
time taken.  Nothing is written unless the whole sequence was made; the
exit code is 0 on success, 2 on bad arguments or an unreadable image, 1
when the folder cannot be written, 130 when interrupted (Ctrl+C).
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from collections.abc import Sequence
from pathlib import Path
from typing import TextIO

from app.jobs.formats.string_art.reader import StringArtParams
from app.string_art_generator.greedy import Settings, default_skip, run
from app.string_art_generator.output import job_of, picture, write_job
from app.string_art_generator.quality import measure
from app.string_art_generator.target import Adjust, ImageError, load_image, target_darkness

PNG_SIZE = 800


def board(text: str) -> StringArtParams:
    """``TVAR,NAILS,RADIUS_CM`` as ``param.txt`` has them (e.g. ``0,200,14.5``)."""
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 3:
        raise argparse.ArgumentTypeError(f"{text!r}: expected TVAR,NAILS,RADIUS_CM")
    try:
        params = StringArtParams(int(parts[0]), int(parts[1]), float(parts[2]))
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"{text!r}: {exc}") from exc
    reason = params.check()
    if reason is not None:
        raise argparse.ArgumentTypeError(reason)
    return params


def centre(text: str) -> tuple[float, float]:
    try:
        x, y = (float(p) for p in text.split(","))
    except ValueError as exc:
        raise argparse.ArgumentTypeError(f"{text!r}: expected X,Y (fractions 0…1)") from exc
    return x, y


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="stepdeck string-art",
        description="String art from a photo: the winder's param.txt + poradi.txt and a PNG.",
    )
    parser.add_argument("image", type=Path, help="the photo (PNG, JPEG, …)")
    parser.add_argument(
        "--board",
        type=board,
        required=True,
        metavar="TVAR,NAILS,RADIUS_CM",
        help="shape (0 circle, n ≥ 3 an n-gon), nail count, board radius in cm, e.g. 0,200,14.5",
    )
    parser.add_argument("--lines", type=int, default=Settings.lines, help="line budget")
    parser.add_argument("--out", type=Path, required=True, metavar="DIR", help="output folder")
    parser.add_argument(
        "--thread-mm", type=float, default=Settings.thread_mm, help="thread width in mm"
    )
    parser.add_argument(
        "--skip", type=int, help="least nails between two ends of a thread (default nails/20)"
    )
    parser.add_argument(
        "--resolution", type=int, default=Settings.resolution, help="raster pixels across"
    )
    parser.add_argument("--contrast", type=float, default=1.0)
    parser.add_argument("--brightness", type=float, default=0.0)
    parser.add_argument("--zoom", type=float, default=1.0, help="crop: 1 fits the shorter side")
    parser.add_argument(
        "--centre", type=centre, default=(0.5, 0.5), metavar="X,Y", help="crop centre, 0…1"
    )
    parser.add_argument("--invert", action="store_true", help="light thread on a dark board")
    parser.add_argument(
        "--full-budget",
        action="store_true",
        help="wind the whole budget even when more thread no longer helps",
    )
    parser.add_argument("--png-size", type=int, default=PNG_SIZE, help="PNG pixels across")
    return parser


def main(argv: Sequence[str] | None = None, out: TextIO | None = None) -> int:
    out = out or sys.stdout
    parser = build_parser()
    args = parser.parse_args(argv)
    params: StringArtParams = args.board
    settings = Settings(
        lines=args.lines,
        thread_mm=args.thread_mm,
        min_skip=args.skip,
        resolution=args.resolution,
        stop_when_no_gain=not args.full_budget,
    )
    if args.resolution == Settings.resolution:  # not chosen: coarser for many nails
        settings = dataclasses.replace(settings, resolution=settings.fitted_resolution(params))
    reason = settings.check(params)
    if reason is None and not 16 <= args.png_size <= 8000:
        reason = f"--png-size {args.png_size}: must be 16 … 8000"
    if reason is not None:
        parser.error(reason)
    adjust = Adjust(
        centre_x=args.centre[0],
        centre_y=args.centre[1],
        zoom=args.zoom,
        contrast=args.contrast,
        brightness=args.brightness,
        invert=args.invert,
    )
    begun = time.perf_counter()
    try:
        lightness = load_image(args.image)
    except (ImageError, OSError) as exc:
        print(f"stepdeck string-art: {exc}", file=sys.stderr)
        return 2
    target = target_darkness(lightness, adjust, settings.resolution)
    try:
        result = run(params, target, settings)
    except KeyboardInterrupt:
        print("stepdeck string-art: interrupted, nothing written", file=sys.stderr)
        return 130
    generated = time.perf_counter()
    quality = measure(result.target, result.darkness, result.mask)
    job = job_of(result)
    try:
        paths = write_job(job, args.out, picture(result, args.png_size))
    except OSError as exc:
        print(f"stepdeck string-art: nothing written to {args.out}: {exc}", file=sys.stderr)
        return 1
    skip = settings.min_skip if settings.min_skip is not None else default_skip(params.nails)
    ended = "stopped early: no further line lowers the error" if result.stopped_early else "budget"
    print(
        f"board: {params.nails} nails on a {params.shape} of {params.radius_cm:g} cm, "
        f"skip {skip}, thread {settings.thread_mm:g} mm",
        file=out,
    )
    print(f"lines: {result.lines} of {settings.lines} ({ended})", file=out)
    print(f"thread: {job.thread_length_mm() / 1000:.1f} m", file=out)
    print(f"quality on {settings.resolution} px: {quality}", file=out)
    print(
        f"time: {generated - begun:.2f} s to generate, {time.perf_counter() - begun:.2f} s in all",
        file=out,
    )
    for path in paths:
        print(f"wrote {path}", file=out)
    return 0
