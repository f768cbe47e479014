"""Which loader turns a job file into a :class:`~app.jobs.program.Program`.

The jobs dock opens whatever the operator picks; this registry decides how
to read it, so adding a job type (Excellon, string art, G-code) is one
``register_loader`` call here and no change to the dock.  The decision, in
order (never a silent guess):

1. the format the operator chose (``JobOptions.format``, ``--format``);
2. the file's name: ``param.txt`` and ``poradi.txt`` are the string-art
   pair whatever they hold (so a malformed one is refused as string art,
   not read as something else);
3. the extension, when only one type claims it;
4. the content: the sniffers of the types that share the extension (every
   type's, for an unknown extension) look at the head of the file.  One
   answer decides; several, or none among types that claim the extension,
   raise :class:`AmbiguousFormat`, and the dock (or ``stepdeck check
   --format``) asks.

Files are read through :mod:`app.jobs.reading` (regular files only, a size
cap, UTF-8 with or without a byte-order mark).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

from PySide6.QtCore import QCoreApplication

from app.jobs.formats.excellon.reader import (
    DrillMode,
    build_drill_program,
    read_drill_file,
    sniff_dri,
    sniff_excellon,
)
from app.jobs.formats.gcode.loader import load_gcode, sniff_gcode
from app.jobs.formats.points.reader import load_points, sniff_point_list
from app.jobs.formats.string_art.program import load_string_art_program
from app.jobs.formats.string_art.reader import (
    PARAM_NAME,
    PORADI_NAME,
    StringArtParams,
    sniff_string_art,
)
from app.jobs.program import JobFileError, Program
from app.jobs.reading import read_job_head
from app.jobs.scaling import scaled
from app.profiles import GcodeSettings

__all__ = ["sniff_point_list"]


@dataclass(frozen=True)
class JobOptions:
    """The operator's choices that change how a file becomes a program."""

    draw: bool = False  # drill files: drawn with the pen (Kresli … Zvedni per bit), not drilled
    draw_crosses: bool = False  # drill files, drawn: a pen cross at each hole instead
    excellon_step_inch: float = 1e-4  # drill files with bare integer coordinates
    #: Drill files: prompt the bits smallest first instead of in the file's tool order.
    smallest_first: bool = False
    #: Drill files: every hole with the one bit in the spindle, no bit-change prompt (the
    #: original drill's way; a profile's ``[drill] one_bit``, FIDELITY S2-40).
    one_bit: bool = False
    #: Drill files: what the teacher's Excellon step makes of their coordinates (its ratio to
    #: 1/10000 inch), and per axis name the ratio of the teacher's microsteps a mm to the
    #: profile's, every job's (FIDELITY S2-42).  1: the profile's constants.
    excellon_scale: float = 1.0
    axis_scale: tuple[tuple[str, float], ...] = ()
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
    #: The job type's key when the operator chose it (an ambiguous file); None: detected.
    format: str | None = None


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
    #: The short name ``--format`` takes and a chosen format is stored as.
    key: str = ""


class AmbiguousFormat(JobFileError):
    """The name and the content leave more than one job type (or none): the operator chooses."""

    def __init__(self, path: Path, choices: Sequence[JobType], why: str) -> None:
        keys = "|".join(t.key for t in choices)
        super().__init__(
            path.name,
            0,
            QCoreApplication.translate(
                "JobFile", "which format? {0}: {1} (choose one: {2})"
            ).format(
                why,
                QCoreApplication.translate("JobFile", " or ").join(t.description for t in choices),
                keys,
            ),
        )
        self.path = path
        self.choices = tuple(choices)


#: Lower-case extension (with the dot) → loader; the dock's first choice.
JOB_LOADERS: dict[str, JobLoader] = {}
#: Every registered job type in registration order: file-dialog filters and sniffing.
JOB_TYPES: list[JobType] = []


def register_loader(
    description: str,
    extensions: Sequence[str],
    load: JobLoader,
    sniff: Sniffer | None = None,
    key: str = "",
) -> JobType:
    """Make ``load`` the reader for ``extensions`` (".csv"…) and, with ``sniff``, for content."""
    job_type = JobType(
        description,
        tuple(e.lower() for e in extensions),
        load,
        sniff,
        key or description.split()[0].lower(),
    )
    JOB_TYPES.append(job_type)
    for extension in job_type.extensions:
        JOB_LOADERS.setdefault(extension, load)  # the first registered keeps a shared extension
    return job_type


def job_type(key: str) -> JobType:
    """The job type ``--format`` names; KeyError lists the keys."""
    for candidate in JOB_TYPES:
        if candidate.key == key:
            return candidate
    raise KeyError(f"no job format {key!r} (known: {', '.join(t.key for t in JOB_TYPES)})")


def type_for(path: Path, chosen: str | None = None) -> JobType:
    """The job type of ``path``: chosen, by name, by extension, else by content (module notes)."""
    if chosen is not None:
        return job_type(chosen)
    if path.name.lower() in (PARAM_NAME, PORADI_NAME):
        return STRING_ART
    extension = path.suffix.lower()
    candidates = [t for t in JOB_TYPES if extension in t.extensions]
    if len(candidates) == 1:
        return candidates[0]
    head = read_job_head(path, SNIFF_CHARS)
    if not head.strip():
        raise JobFileError(path.name, 0, QCoreApplication.translate("JobFile", "the file is empty"))
    pool = candidates or JOB_TYPES
    matches = [t for t in pool if t.sniff is not None and t.sniff(head)]
    if len(matches) == 1:
        return matches[0]
    if matches:
        raise AmbiguousFormat(
            path,
            matches,
            QCoreApplication.translate("JobFile", "its content fits several job types"),
        )
    if candidates:
        raise AmbiguousFormat(
            path,
            candidates,
            QCoreApplication.translate("JobFile", "its content fits no {0} job type").format(
                extension
            ),
        )
    raise JobFileError(
        path.name,
        0,
        QCoreApplication.translate("JobFile", "not a job file this station knows (unknown type)"),
    )


def loader_for(path: Path) -> JobLoader:
    """The loader of ``path``'s job type (see :func:`type_for`)."""
    return type_for(path).load


def load_job(path: Path, axis_names: Sequence[str], options: JobOptions | None = None) -> Program:
    """Read any known job file for a machine with ``axis_names``; JobFileError says why not."""
    options = options or JobOptions()
    program = type_for(path, options.format).load(path, axis_names, options)
    factors = dict(options.axis_scale)
    if all(factor == 1.0 for factor in factors.values()):
        return program
    note = QCoreApplication.translate(
        "JobFile", "teaching: microsteps a mm changed, the job lands x {0} of its size"
    ).format(", ".join(f"{name} {factor:.4g}" for name, factor in factors.items()))
    return scaled(program, factors, note)


def file_dialog_filter() -> str:
    """The Open dialog's filter list: every job type, then all files (sniffed)."""
    # Each pattern once: several types read .txt, and a list naming it three times reads
    # as a mistake.
    unique = dict.fromkeys(f"*{e}" for t in JOB_TYPES for e in t.extensions)
    patterns = " ".join(unique)
    parts = [f"Job files ({patterns})"] if patterns else []
    parts += [f"{t.description} ({' '.join('*' + e for e in t.extensions)})" for t in JOB_TYPES]
    parts.append("All files (*)")
    return ";;".join(parts)


# --- point lists ---------------------------------------------------------------


def load_point_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A point list on the machine's first axes (as many as its columns)."""
    return load_points(path, axis_names)


POINT_LIST = register_loader(
    "Point lists", (".csv", ".txt"), load_point_job, sniff_point_list, key="points"
)


# --- Excellon drill files ------------------------------------------------------------
# A ``.txt`` is a drill file when its sniffer alone recognises it; extension-less EAGLE
# drill files are found by the sniffer alone.


def load_drill_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A drill file (or ``.dri`` pair) as a drill or draw program on the first two axes."""
    if len(axis_names) < 2:
        raise JobFileError(
            path.name,
            0,
            QCoreApplication.translate("JobFile", "a drill job needs a machine with X and Y axes"),
        )
    job = read_drill_file(path, excellon_step_inch=options.excellon_step_inch)
    axes = (axis_names[0], axis_names[1])
    mode: DrillMode = ("cross" if options.draw_crosses else "draw") if options.draw else "drill"
    program = build_drill_program(
        job, mode=mode, axes=axes, smallest_first=options.smallest_first, one_bit=options.one_bit
    )
    scale = options.excellon_scale
    note = QCoreApplication.translate(
        "JobFile", "teaching: read with an Excellon step of {0:g} inch (coordinates x {1:g})"
    ).format(scale * 1e-4, scale)
    return scaled(program, {axes[0]: scale, axes[1]: scale}, note)


EXCELLON = register_loader(
    "Excellon drill files",
    (".drl", ".drd", ".txt", ".xln"),
    load_drill_job,
    sniff_excellon,
    key="excellon",
)
EAGLE_DRILL_INFO = register_loader(
    "EAGLE drill info (.dri)", (".dri",), load_drill_job, sniff_dri, key="dri"
)


# --- string-art jobs ---------------------------------------------------------------------
# param.txt / poradi.txt (either file of the pair, chosen by name) and bare nail lists from
# generators (chosen by content: neither the point-list nor the drill sniffer takes a
# "key = value" file or a long run of whole numbers; a nail list too short to tell from a point
# list, fewer than four numbers, is a point list).


def load_string_art_job(path: Path, axis_names: Sequence[str], options: JobOptions) -> Program:
    """A string-art job for the winder (A, X, Z); NeedsNailCount when the board is unknown."""
    return load_string_art_program(path, axis_names, options.string_art)


STRING_ART = register_loader(
    "String-art jobs (param.txt, poradi.txt)",
    (".txt",),
    load_string_art_job,
    sniff_string_art,
    key="string-art",
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
    "G-code",
    (".gcode", ".nc", ".ngc", ".gc", ".g", ".tap"),
    load_gcode_job,
    sniff_gcode,
    key="gcode",
)
