"""``stepdeck check JOB [JOB…] --profile P``: job files loaded and checked, no window needed.

For operators (is this file safe to run on this machine?) and for CI
pipelines that produce job files.  Each job is read as the jobs dock reads
it and checked as the runner checks it before a run: the G-code pre-flight,
the machine's repertoire and capabilities, and its travel.  A job that
passes prints its summary (operations, extent, estimated time); a refused
one prints every refusal as ``file:line: reason``.

Exit status: 0 when every job passed, 2 when any was refused, 1 for a usage
error (an unknown profile or format, a malformed ``--board``).
"""

from __future__ import annotations

import argparse
import math
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import TextIO

import numpy as np

from app.cli.usage import UsageError, UsageParser
from app.jobs.estimate import estimate
from app.jobs.formats.string_art.reader import NeedsNailCount, StringArtParams
from app.jobs.loaders import JOB_TYPES, AmbiguousFormat, JobOptions, load_job
from app.jobs.names import shown
from app.jobs.program import JobFileError, LimitViolation, Program, check_limits
from app.jobs.run.driver import capability_refusals
from app.jobs.run.drivers import driver_for
from app.profiles import MachineProfile, ProfileError, available_profiles, load_profile

OK, USAGE, REFUSED = 0, 1, 2
#: Refusals printed per job (the count of the rest follows).
SHOWN_REFUSALS = 50


def build_parser() -> argparse.ArgumentParser:
    parser = UsageParser(
        prog="stepdeck check",
        description="Load and check job files against a machine profile (no window).",
        epilog="Exit status: 0 fine, 2 refused, 1 usage error.",
    )
    parser.add_argument("jobs", nargs="+", metavar="JOB", type=Path, help="job files to check")
    parser.add_argument(
        "--profile", required=True, help=f"machine profile ({', '.join(available_profiles())})"
    )
    parser.add_argument(
        "--board",
        metavar="TVAR,NAILS,RADIUS_CM",
        help="the board of a bare nail list (param.txt's tvar, pocet_hrebiku, polomer_matrice)",
    )
    parser.add_argument(
        "--format",
        choices=[t.key for t in JOB_TYPES],
        help="read the jobs as this type (for files whose name and content do not tell)",
    )
    parser.add_argument(
        "--draw", action="store_true", help="drill files: draw along the holes with the pen"
    )
    parser.add_argument(
        "--crosses", action="store_true", help="drill files, with --draw: a pen cross per hole"
    )
    parser.add_argument(
        "--skip-unsupported",
        action="store_true",
        help="G-code: lines the machine cannot execute become comments instead of refusals",
    )
    parser.add_argument(
        "--excellon-step",
        type=float,
        default=1e-4,
        metavar="INCH",
        help="drill files with bare integer coordinates: one count in inch (default 1e-4)",
    )
    return parser


def parse_board(text: str) -> StringArtParams:
    """``TVAR,NAILS,RADIUS_CM`` as a board, checked like a param.txt; UsageError if not."""
    parts = [p.strip() for p in text.split(",")]
    if len(parts) != 3:
        raise UsageError(f"--board wants TVAR,NAILS,RADIUS_CM, not {text!r}")
    try:
        board = StringArtParams(int(parts[0]), int(parts[1]), float(parts[2]))
    except ValueError:
        raise UsageError(f"--board wants two whole numbers and a radius, not {text!r}") from None
    reason = board.check()
    if reason is not None:
        raise UsageError(f"--board: {reason}")
    return board


def _clock(seconds: float) -> str:
    whole = round(seconds)
    hours, rest = divmod(whole, 3600)
    minutes, secs = divmod(rest, 60)
    return f"{hours}:{minutes:02d}:{secs:02d}" if hours else f"{minutes:02d}:{secs:02d}"


def summary(program: Program, profile: MachineProfile) -> list[str]:
    """Operations, extent per axis and the model's time for a job that passed."""
    names = [axis.name for axis in profile.axes]
    lines = [f"{len(program)} operations"]
    path = program.path(names)
    extent: list[str] = []
    for column, axis in enumerate(profile.axes):
        values = path.coords[:, column] if len(path) else np.empty(0)
        values = values[~np.isnan(values)]
        if len(values):
            low, high = float(values.min()), float(values.max())
            extent.append(f"{axis.name} {low:g}…{high:g} {axis.unit}")
    if extent:
        lines.append("extent " + ", ".join(extent))
    period_s = profile.period_ms / 1000
    seconds = estimate(program, profile, {}, period_s).total_s
    if math.isfinite(seconds):
        lines.append(f"estimated time {_clock(seconds)}")
    return lines


def check_one(path: Path, profile: MachineProfile, options: JobOptions, out: TextIO) -> bool:
    """Load and check ``path``; prints its summary or its refusals; True when it passed."""
    axis_names = [axis.name for axis in profile.axes]
    try:
        program = load_job(path, axis_names, options)
    except NeedsNailCount as exc:
        print(f"{exc} (give --board TVAR,NAILS,RADIUS_CM)", file=out)
        return False
    except AmbiguousFormat as exc:
        print(f"{exc} (give --format)", file=out)
        return False
    except JobFileError as exc:
        refusals = (exc, *exc.more)
        for refusal in refusals[:SHOWN_REFUSALS]:
            print(refusal, file=out)
        if len(refusals) > SHOWN_REFUSALS:
            print(f"{shown(path.name)}: … and {len(refusals) - SHOWN_REFUSALS} more", file=out)
        return False
    refused: list[LimitViolation] = check_limits(program, profile.travel_limits())
    takes_gcode = bool(getattr(driver_for(profile.dialect), "takes_gcode", False))
    refused += capability_refusals(program, profile, takes_gcode=takes_gcode)
    refused.sort(key=lambda v: (v.operation.source.line, v.index))
    if refused:
        for violation in refused[:SHOWN_REFUSALS]:
            print(violation, file=out)
        if len(refused) > SHOWN_REFUSALS:
            print(f"{shown(path.name)}: … and {len(refused) - SHOWN_REFUSALS} more", file=out)
        return False
    name = shown(path.name)
    for line in summary(program, profile):
        print(f"{name}: {line}", file=out)
    for note in program.notes:
        print(f"{name}: note: {note}", file=out)
    return True


def main(argv: Sequence[str], out: TextIO | None = None, err: TextIO | None = None) -> int:
    out = out or sys.stdout
    err = err or sys.stderr
    try:
        args = build_parser().parse_args(list(argv))
        board = parse_board(args.board) if args.board else None
        try:
            profile = load_profile(args.profile)
        except ProfileError as exc:
            raise UsageError(str(exc)) from None
    except UsageError as exc:
        print(f"stepdeck check: {exc}", file=err)
        return USAGE
    options = JobOptions(
        draw=args.draw,
        draw_crosses=args.crosses,
        excellon_step_inch=args.excellon_step,
        skip_unsupported=args.skip_unsupported,
        gcode=profile.gcode,
        machine_title=profile.title,
        one_bit=profile.drill_one_bit,
        string_art=board,
        format=args.format,
    )
    results = [check_one(path, profile, options, out) for path in args.jobs]
    return OK if all(results) else REFUSED
