"""Job files read with bounds: regular files only, a size cap, and the text's encoding named.

Every loader reads through here, so that no job file, however hostile, can
hang the station (a named pipe, a terminal), exhaust its memory (a link to
``/dev/zero``, a gigabyte of digits) or come out as mojibake (UTF-16 saved
by a Windows editor).  Refusals are :class:`~app.jobs.program.JobFileError`
on line 0 with a reason that says what to do.

* Only regular files are opened: the type is checked before opening and
  again on the open descriptor (opened non-blocking, so a pipe swapped in
  between cannot block the open).
* At most :data:`MAX_JOB_BYTES` are read; a larger file is refused by its size.
* A UTF-8 byte-order mark is dropped; UTF-16 (with or without its mark) is
  refused as UTF-16, because every job format here is ASCII at heart; a NUL
  byte anywhere else marks binary data (an image, an archive), refused on
  its line.
"""

from __future__ import annotations

import codecs
import os
import stat
from pathlib import Path

from app.jobs.program import JobFileError
from app.jobs.texts import translate

#: The largest job file read (a million-line G-code file is about 30 MB).
MAX_JOB_BYTES = 100_000_000
#: How much of a file the format sniffers see.
HEAD_BYTES = 16_384


def _kind(mode: int) -> str:
    """What a file that is not a regular file is, in the operator's language."""
    if stat.S_ISDIR(mode):
        return translate("JobFile", "a folder")
    if stat.S_ISFIFO(mode):
        return translate("JobFile", "a named pipe")
    if stat.S_ISCHR(mode):
        return translate("JobFile", "a device")
    if stat.S_ISBLK(mode):
        return translate("JobFile", "a block device")
    if stat.S_ISSOCK(mode):
        return translate("JobFile", "a socket")
    return translate("JobFile", "not a regular file")


def _megabytes(size: int) -> str:
    return f"{size / 1e6:.1f} MB"


def read_job_bytes(path: Path, limit: int = MAX_JOB_BYTES, *, first: int | None = None) -> bytes:
    """The bytes of ``path`` if it is a regular file of at most ``limit`` bytes.

    ``first``: only that many bytes from the start are read (the size is still checked).
    """
    name = path.name or str(path)
    try:
        mode = os.stat(path).st_mode
    except OSError as exc:
        raise JobFileError(name, 0, _cannot_read(exc)) from None
    if not stat.S_ISREG(mode):
        raise JobFileError(name, 0, _not_a_file(mode))
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except OSError as exc:
        raise JobFileError(name, 0, _cannot_read(exc)) from None
    try:
        info = os.fstat(fd)
        if not stat.S_ISREG(info.st_mode):  # swapped for something else since the check
            raise JobFileError(name, 0, _not_a_file(info.st_mode))
        if info.st_size > limit:
            raise JobFileError(
                name,
                0,
                translate("JobFile", "too large: {0}; job files are read up to {1}").format(
                    _megabytes(info.st_size), _megabytes(limit)
                ),
            )
        chunks: list[bytes] = []
        total = 0
        want = limit + 1 if first is None else min(first, limit + 1)
        while total < want:
            chunk = os.read(fd, min(1 << 22, want - total))
            if not chunk:
                break
            chunks.append(chunk)
            total += len(chunk)
        if total > limit:  # grew while being read
            raise JobFileError(
                name,
                0,
                translate("JobFile", "too large: over {0}; job files are read up to that").format(
                    _megabytes(limit)
                ),
            )
        return b"".join(chunks)
    except OSError as exc:
        raise JobFileError(name, 0, _cannot_read(exc)) from None
    finally:
        os.close(fd)


def _cannot_read(exc: OSError) -> str:
    return translate("JobFile", "cannot read: {0}").format(exc.strerror or exc)


def _not_a_file(mode: int) -> str:
    return translate("JobFile", "cannot read: {0}, not a job file").format(_kind(mode))


def utf16_reason(raw: bytes) -> str | None:
    """Why ``raw`` reads as UTF-16 (its byte-order mark or its NUL bytes), or None."""
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        if raw.startswith(codecs.BOM_UTF16_LE):
            return translate(
                "JobFile", "UTF-16 text (little-endian byte-order mark): save it as UTF-8 or ASCII"
            )
        return translate(
            "JobFile", "UTF-16 text (big-endian byte-order mark): save it as UTF-8 or ASCII"
        )
    head = raw[:512]
    if len(head) >= 4 and head.count(0) * 3 >= len(head):
        return translate(
            "JobFile", "UTF-16 text (every other byte is zero): save it as UTF-8 or ASCII"
        )
    return None


def _binary(raw: bytes, name: str) -> None:
    """Refuse ``raw`` when it holds a NUL byte: no job format has one; binary data has many."""
    at = raw.find(b"\x00")
    if at >= 0:
        line = raw.count(b"\n", 0, at) + 1
        reason = translate(
            "JobFile", "binary data (a zero byte at offset {0}): not a job file"
        ).format(at)
        raise JobFileError(name, line, reason)


def decode_job_text(raw: bytes, name: str, *, latin1_fallback: bool = False) -> str:
    """``raw`` as text: UTF-8 (its byte-order mark dropped); UTF-16 refused as such.

    ``latin1_fallback``: bytes that are not UTF-8 are read as Latin-1 (Excellon
    comments written by old CAM tools) instead of refused on their line.
    """
    reason = utf16_reason(raw)
    if reason is not None:
        raise JobFileError(name, 0, reason)
    _binary(raw, name)
    if raw.startswith(codecs.BOM_UTF8):
        raw = raw[len(codecs.BOM_UTF8) :]
    try:
        return raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        if latin1_fallback:
            return raw.decode("latin-1")
        line = raw.count(b"\n", 0, exc.start) + 1
        reason = translate("JobFile", "not UTF-8 text (byte 0x{0:02x})")
        raise JobFileError(name, line, reason.format(raw[exc.start])) from None


def read_job_text(path: Path, limit: int = MAX_JOB_BYTES, *, latin1_fallback: bool = False) -> str:
    """The text of job file ``path`` (see the module notes for what is refused)."""
    raw = read_job_bytes(path, limit)
    return decode_job_text(raw, path.name or str(path), latin1_fallback=latin1_fallback)


def read_job_head(path: Path, chars: int = HEAD_BYTES) -> str:
    """The start of ``path`` as text for the sniffers (a cut character at the end is dropped)."""
    raw = read_job_bytes(path, first=chars + 4)
    reason = utf16_reason(raw)
    if reason is not None:
        raise JobFileError(path.name or str(path), 0, reason)
    _binary(raw, path.name or str(path))
    return raw.removeprefix(codecs.BOM_UTF8).decode("utf-8", errors="replace")[:chars]
