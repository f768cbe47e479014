"""Which loader turns a job file into a :class:`~app.jobs.program.Program`.

The jobs dock opens whatever the operator picks; this registry decides how
to read it, so adding a job type (Excellon, string art, G-code) is one
``register_loader`` call in the new loader's module and no change to the
dock.  The extension decides first, because it is what the operator chose
the file by.  When several types share an extension (``.txt`` is a point
list, a string-art ``param.txt`` and many a drill export) their sniffers
choose among them; when the extension is unknown (an extension-less export)
every sniffer is asked, and the first to recognise the text wins.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from app.jobs.formats.excellon.reader import (
    build_drill_program,
    read_drill_file,
    sniff_dri,
    sniff_excellon,
)
from app.jobs.formats.gcode.loader import load_gcode, sniff_gcode
from app.jobs.formats.string_art.program import load_string_art_program
from app.jobs.formats.string_art.reader import StringArtParams, sniff_string_art
from app.jobs.program import JobFileError, Program, load_point_list
from app.profiles import GcodeSettings


@dataclass(frozen=True)
class JobOptions:
    """The operator's choices that change how a file becomes a program."""

    draw: bool = False  # drill files: draw each hole with the pen instead of drilling it
    excellon_step_inch: float = 1e-4  # drill files with bare integer coordinates
    #: G-code: pen lines of another flavour are sent as the machine's own pen commands.
    translate_pen: bool = True
    #: G-code: lines the machine cannot execute become comments instead of refusing the job.
    skip_unsupported: bool = False
    #: G-code: the machine's repertoire and pen conventions (None: a GRBL board).
    gcode: GcodeSettings | None = None
    #: G-code: the machine's name in refusals ("the CoreXY pen plotter cannot execute M18").
    machine_title: str = ""
    #: String-art nail lists without a param.txt: the board the operator gave (NeedsNailCount).
    string_art: StringArtParams | None = None


#: Reads ``path`` for a machine with these axis names; raises JobFileError with file:line.
JobLoader = Callable[[Path, Sequence[str], JobOptions], Program]
#: Whether the first few kilobytes of a file look like this loader's job type.
Sniffer = Callable[[str], bool]

SNIFF_CHARS = 4096


@dataclass(frozen=True)
class JobType:
    """One kind of job file: what the file dialog calls it, its extensions, how to read it."""

    description: str
    extensions: tuple[str, ...]
    load: JobLoader
    sniff: Sniffer | None = None


#: Lower-case extension (with the dot) → loader; the dock's first choice.
JOB_LOADERS: dict[str, JobLoader] = {}
#: Every registered job type in registration order: file-dialog filters and sniffing.
JOB_TYPES: list[JobType] = []


def register_loader(
    description: str,
    extensions: Sequence[str],
    load: JobLoader,
    sniff: Sniffer | None = None,
) -> JobType:
    """Make ``load`` the reader for ``extensions`` (".csv"…) and, with ``sniff``, for content."""
    job_type = JobType(description, tuple(e.lower() for e in extensions), load, sniff)
    JOB_TYPES.append(job_type)
    for extension in job_type.extensions:
        JOB_LOADERS.setdefault(extension, load)  # the first registered keeps a shared extension
    return job_type


def loader_for(path: Path) -> JobLoader:
    """The loader by extension (sniffing among types that share it), else by content alone."""
    extension = path.suffix.lower()
    candidates = [t for t in JOB_TYPES if extension in t.extensions]
    if len(candidates) == 1:
        return candidates[0].load
    try:
        with path.open(encoding="utf-8", errors="replace") as handle:
            head = handle.read(SNIFF_CHARS)
    except OSError as exc:
        raise JobFileError(path.name, 0, f"cannot read: {exc}") from exc
    for job_type in candidates or JOB_TYPES:
        if job_type.sniff is not None and job_type.sniff(head):
            return job_type.load
    if candidates:
        return JOB_LOADERS[extension]  # its own errors name the line that is wrong
    raise JobFileError(path.name, 0, "not a job file this station knows (unknown type)")


def load_job(path: Path, axis_names: Sequence[str], options: JobOptions | None = None) -> Program:
    """Read any known job file for a machine with ``axis_names``; JobFileError says why not."""
    return loader_for(path)(path, axis_names, options or JobOptions())


def file_dialog_filter() -> str:
    """The Open dialog's filter list: every job type, then all files (sniffed)."""
    patterns = " ".join(f"*{e}" for t in JOB_TYPES for e in t.extensions)
    parts = [f"Job files ({patterns})"] if patterns else []
    parts += [f"{t.description} ({' '.join('*' + e for e in t.extensions)})" for t in JOB_TYPES]
    parts.append("All files (*)")
    return ";;".join(parts)


# --- point lists ---------------------------------------------------------------


def _data_lines(text: str) -> list[str]:
    """Lines that are neither blank, comments nor operator waits: the positions."""
    lines = (line.strip() for line in text.splitlines())
    return [line for line in lines if line and not line.startswith("#") and not _is_wait(line)]


def _is_wait(line: str) -> bool:
    return line.lower().startswith("wait")


def _fields(line: str) -> list[str]:
    return [f.strip() for f in line.replace(";", ",").split(",")]


def _numbers(line: str) -> bool:
    try:
        [float(f) for f in _fields(line)]
    except ValueError:
        return False
    return True


def sniff_point_list(head: str) -> bool:
    """Two or three comma/semicolon-separated numbers per line, the first few lines agreeing."""
    lines = _data_lines(head)[:5]
    if not lines:
        return False
    counts = {len(_fields(line)) for line in lines}
    return len(counts) == 1 and counts <= {2, 3} and all(_numbers(line) for line in lines)


def load_points(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A point list for this machine: as many axes as the first position line has numbers.

    A 2-column list on a 3-axis machine moves X and Y only; a column count
    the machine cannot take falls through to ``load_point_list``, which names
    the line.
    """
    try:
        head = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as exc:
        raise JobFileError(path.name, 0, f"cannot read: {exc}") from exc
    lines = _data_lines(head)
    columns = len(_fields(lines[0])) if lines else len(axis_names)
    axes = tuple(axis_names[:columns]) if columns <= len(axis_names) else tuple(axis_names)
    return load_point_list(path, axes)


POINT_LIST = register_loader("Point lists", (".csv", ".txt"), load_points, sniff_point_list)


# --- Excellon drill files ------------------------------------------------------------
# After the point lists, so a ``.txt`` is a point list unless it sniffs as a drill file;
# extension-less EAGLE drill files are found by the sniffer alone.


def load_drill_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A drill file (or ``.dri`` pair) as a drill or draw program on the first two axes."""
    if len(axis_names) < 2:
        raise JobFileError(path.name, 0, "a drill job needs a machine with X and Y axes")
    job = read_drill_file(path, excellon_step_inch=options.excellon_step_inch)
    axes = (axis_names[0], axis_names[1])
    if options.draw:
        return build_drill_program(job, mode="draw", axes=axes)
    return build_drill_program(job, mode="drill", axes=axes)


EXCELLON = register_loader(
    "Excellon drill files", (".drl", ".drd", ".txt", ".xln"), load_drill_job, sniff_excellon
)
EAGLE_DRILL_INFO = register_loader("EAGLE drill info (.dri)", (".dri",), load_drill_job, sniff_dri)


# --- string-art jobs ---------------------------------------------------------------------
# param.txt / poradi.txt (either file of the pair) and bare nail lists from generators.  After
# the point lists and drill files: their sniffers see a .txt first, and neither takes a
# "key = value" file or a long run of whole numbers; a nail list too short to tell from a point
# list (fewer than four numbers) stays a point list.


def load_string_art_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A string-art job for the winder (A, X, Z); NeedsNailCount when the board is unknown."""
    return load_string_art_program(path, axis_names, options.string_art)


STRING_ART = register_loader(
    "String-art jobs (param.txt, poradi.txt)",
    (".txt",),
    load_string_art_job,
    sniff_string_art,
)


# --- G-code ----------------------------------------------------------------------------


def load_gcode_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A G-code file checked against the machine's repertoire (``options.gcode``)."""
    return load_gcode(
        path,
        axis_names,
        options.gcode,
        translate_pen=options.translate_pen,
        skip_unsupported=options.skip_unsupported,
        machine_title=options.machine_title,
    )


GCODE = register_loader(
    "G-code", (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap"), load_gcode_job, sniff_gcode
)
