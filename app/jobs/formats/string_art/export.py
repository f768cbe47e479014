"""Write a string-art job back for the winder's standalone firmware.

* :func:`export_sd_files` — ``param.txt`` and ``poradi.txt`` as the original
  firmware reads them from its SD card, formatted as the sample files are:
  ``key = value`` lines, and one line of comma-separated integers (the count
  first), each file ending in a newline.  Reading them back gives an equal
  job (the radius is written in Python's shortest round-trip form).
* :func:`export_gcode` — a program (any :class:`~app.jobs.program.Program`,
  typically the winder's) as a G-code file: header comments, ``G90``, one
  line per move with only the axes it moves and the feed of its slowest
  axis (the profile's top speed, units per minute), ``M0 (message)`` where
  the operator has to act, ``(comment)`` lines; every line within 79
  characters plus its newline.
"""

from __future__ import annotations

import textwrap
from collections.abc import Iterator
from pathlib import Path

from app.jobs.formats.string_art.reader import PARAM_NAME, PORADI_NAME, StringArtJob
from app.jobs.program import OpKind, Program
from app.jobs.render.gcode import MAX_LINE, comment, feed_for, render_operation
from app.profiles import GcodeSettings, MachineProfile


def param_text(job: StringArtJob) -> str:
    p = job.params
    return f"tvar = {p.tvar}\npocet_hrebiku = {p.nails}\npolomer_matrice = {p.radius_cm!r}\n"


def poradi_text(job: StringArtJob) -> str:
    return ",".join(str(v) for v in (len(job.sequence), *job.sequence)) + "\n"


def export_sd_files(job: StringArtJob, directory: Path) -> tuple[Path, Path]:
    """``directory/param.txt`` and ``directory/poradi.txt`` (created or replaced)."""
    directory.mkdir(parents=True, exist_ok=True)
    param = directory / PARAM_NAME
    poradi = directory / PORADI_NAME
    param.write_text(param_text(job), encoding="ascii", newline="\n")
    poradi.write_text(poradi_text(job), encoding="ascii", newline="\n")
    return param, poradi


def gcode_lines(program: Program, profile: MachineProfile) -> Iterator[str]:
    """The program's G-code, line by line (no newlines)."""
    settings = profile.gcode or GcodeSettings()
    order = [axis.name for axis in profile.axes]
    yield comment(f"StepDeck program {program.name} for {profile.title}")
    units = ", ".join(f"{axis.name} {axis.unit}" for axis in profile.axes)
    yield comment(f"axes: {units}; start homed, every axis at 0")
    for note in program.notes:
        for part in textwrap.wrap(note, MAX_LINE - 2):
            yield comment(part)
    yield "G90"
    for op in program:
        if op.kind is OpKind.WAIT:
            yield comment(op.message or "continue when ready", prefix="M0 ")
            continue
        if op.kind is OpKind.COMMENT:
            if op.message:
                yield comment(op.message)
            continue
        line = render_operation(op, settings, feed_for(op.target, profile), axis_order=order)
        if line is None:
            continue
        if len(line.encode()) > MAX_LINE:
            raise ValueError(f"{op.source}: G-code line longer than {MAX_LINE} bytes: {line!r}")
        yield line


def export_gcode(program: Program, path: Path, profile: MachineProfile) -> Path:
    """Write ``program`` as G-code for ``profile``'s machine to ``path``; returns ``path``."""
    text = "\n".join(gcode_lines(program, profile)) + "\n"
    path.write_text(text, encoding="ascii", newline="\n")
    return path
