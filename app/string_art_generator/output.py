"""A generated sequence as the winder's job, written whole or not at all.

The pair is the SD-card format of :mod:`app.jobs.formats.string_art.export`
(byte for byte as the samples), plus optionally a PNG of the thread picture.
Every file is written under a temporary name in the target folder first and
renamed into place only when all of them are complete, so a cancelled or
failed write leaves no half-written ``poradi.txt`` for the winder to run.
"""

from __future__ import annotations

import os
import uuid
from pathlib import Path

import numpy as np
from PIL import Image

from app.jobs.formats.string_art.export import param_text, poradi_text
from app.jobs.formats.string_art.reader import PARAM_NAME, PORADI_NAME, StringArtJob
from app.string_art_generator.greedy import Result
from app.string_art_generator.render import render_darkness, to_grey

PNG_NAME = "string-art.png"


def job_of(result: Result) -> StringArtJob:
    """The generated sequence as a job on its board (no files yet)."""
    return StringArtJob(result.params, result.sequence)


def picture(result: Result, size: int) -> np.ndarray:
    """(size, size) 8-bit grey thread picture, with the generator's thread model."""
    darkness = render_darkness(result.params, result.sequence, size, result.settings.thread_mm)
    return to_grey(darkness)


def write_job(job: StringArtJob, directory: Path, png: np.ndarray | None = None) -> list[Path]:
    """``param.txt``, ``poradi.txt`` (and ``string-art.png``) in ``directory``; OSError if not.

    All or nothing: on an error no file of the set is left changed or half-written.
    """
    directory.mkdir(parents=True, exist_ok=True)
    contents: list[tuple[str, bytes]] = [
        (PARAM_NAME, param_text(job).encode("ascii")),
        (PORADI_NAME, poradi_text(job).encode("ascii")),
    ]
    staged: list[tuple[Path, Path]] = []
    try:
        for name, data in contents:
            staged.append((_stage(directory, name, data), directory / name))
        if png is not None:
            temporary = _temporary(directory, PNG_NAME)
            staged.append((temporary, directory / PNG_NAME))
            Image.fromarray(np.ascontiguousarray(png, dtype=np.uint8)).save(temporary, format="PNG")
        for temporary, final in staged:
            os.replace(temporary, final)
    finally:
        for temporary, _final in staged:
            temporary.unlink(missing_ok=True)
    return [final for _temporary, final in staged]


def _temporary(directory: Path, name: str) -> Path:
    """A new empty file beside ``name`` (created with the usual permissions, unlike mkstemp)."""
    path = directory / f".{name}.{os.getpid()}.{uuid.uuid4().hex[:12]}.part"
    path.open("xb").close()
    return path


def _stage(directory: Path, name: str, data: bytes) -> Path:
    path = _temporary(directory, name)
    try:
        with path.open("wb") as handle:
            handle.write(data)
            handle.flush()
            os.fsync(handle.fileno())
    except BaseException:
        path.unlink(missing_ok=True)
        raise
    return path
