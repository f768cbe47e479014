"""The words of a G-code line: the patterns, comments, ``N`` numbers, checksums and tokens.

A line is read as words (a letter and a number, spaces allowed between and
around them) once its comments (``( … )`` and ``; …``), its ``N`` number and
its ``*`` checksum are taken off.  The text a machine is sent is the line as
written without those, so the helpers here keep the spacing of what remains.
"""

from __future__ import annotations

import re
from typing import NamedTuple

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.jobs.names import quoted
from app.jobs.program import JobFileError

#: The longest line a board takes, without its line end (docs/protocols.md §4: 80 bytes).
MAX_LINE_CHARS = 79

#: A number as G-code writes it: ``1``, ``-1.``, ``+.5``, ``12.345``.
NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)"
#: A word whose number is written with an exponent (``X1e308``): G-code reads it as two words.
EXPONENT = re.compile(r"([A-DF-Za-df-z][ \t]*[-+]?(?:\d+\.?\d*|\.\d+))([eE][-+]?\d+)")
WORD = re.compile(rf"[ \t]*([A-Za-z])[ \t]*({NUMBER})(?![\d.])")
WORDS = re.compile(rf"(?:[ \t]*[A-Za-z][ \t]*{NUMBER}(?![\d.]))*[ \t]*")
COMMENT_RE = re.compile(r"\(([^)]*)\)?|;(.*)")
LINE_NUMBER = re.compile(r"[Nn][ \t]*\d+[ \t]*")
CHECKSUM = re.compile(r"\*[ \t]*\d*[ \t]*\Z")
SYSTEM = re.compile(r"\$([A-Za-z]+|\$|#|\d+)?")
WAIT_RE = re.compile(r"[Mm]0*([01])(?![\d.])[ \t]*")
MESSAGE_RE = re.compile(r"[Mm]0*(11[78])(?![\d.])")
PARAMETERS = re.compile(
    r"[#\[\]]|^[Oo]|[Gg]0*6[5-7](?![\d.])|\b(?:IF|WHILE|GOTO|DO|END)\b", re.IGNORECASE
)
SPACES = re.compile(r"[ \t]{2,}")
#: ``M98 800`` / ``M99 90``: the CoreXY plotter's step interval and servo level
#: (docs/protocols.md §4.5).
BARE_VALUE = re.compile(r"[ \t]*[Mm]0*(9[89])[ \t]+(\d+(?:\.\d*)?)[ \t]*")
#: Their names are translated where they are shown.
REALTIME = {
    "?": str(QT_TRANSLATE_NOOP("JobFile", "status query")),
    "!": str(QT_TRANSLATE_NOOP("JobFile", "feed hold")),
    "~": str(QT_TRANSLATE_NOOP("JobFile", "cycle start")),
    "\x18": str(QT_TRANSLATE_NOOP("JobFile", "soft reset")),
}
#: The cached tokenisations (per distinct line text) stop growing here: repeated lines
#: (pen commands, dwells) are what the cache is for.
TOKEN_CACHE_SIZE = 20_000


class Word(NamedTuple):
    letter: str  # upper case
    text: str  # the number as written
    value: float


def normal(letter: str, value: float) -> str:
    """A command word spelled one way: G00 == G0, M03 == M3, G92.1 stays G92.1."""
    if value.is_integer():
        return f"{letter}{int(value)}"
    return f"{letter}{value:g}"


def split_comment(raw: str) -> tuple[str, str]:
    """The code of a line and its first comment (``( … )`` or ``; …``)."""
    if "(" not in raw and ";" not in raw:
        return raw, ""
    comments: list[str] = []

    def drop(match: re.Match[str]) -> str:
        text = match.group(1) if match.group(1) is not None else match.group(2)
        comments.append((text or "").strip())
        return ""

    code = SPACES.sub(" ", COMMENT_RE.sub(drop, raw))  # no double space where one was
    return code, next((c for c in comments if c), "")


def plain_code(line: str) -> str:
    """A plain move's text as sent: without its trailing comment and surrounding spaces."""
    if ";" in line or "(" in line:
        return split_comment(line)[0].strip()
    return line.strip()


def line_code(raw: str) -> str:
    """The code of a line without its comment, ``N`` number, checksum and surrounding spaces."""
    code = split_comment(raw)[0].strip()
    match = LINE_NUMBER.match(code)
    if match:
        code = code[match.end() :]
    return CHECKSUM.sub("", code).strip()


def render(code: str, removed: set[int]) -> str:
    """The code with its words number ``removed`` cut out, spacing otherwise as written."""
    spans = [(m.start(1), m.end()) for m in WORD.finditer(code)]
    parts: list[str] = []
    at = 0
    for index in sorted(removed):
        start, end = spans[index]
        parts.append(code[at:start])
        at = end
    parts.append(code[at:])
    return SPACES.sub(" ", "".join(parts)).strip()


class Tokenizer:
    """The words of a file's lines, cached per distinct line text."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.cache: dict[str, tuple[Word, ...]] = {}

    def words_or_none(self, code: str) -> tuple[Word, ...] | None:
        """The words of ``code`` (a line without comment, ``N`` and checksum); None: not words."""
        cached = self.cache.get(code)
        if cached is not None:
            return cached
        if not WORDS.fullmatch(code):
            return None
        result = tuple(
            Word(letter.upper(), number, float(number)) for letter, number in WORD.findall(code)
        )
        if len(self.cache) < TOKEN_CACHE_SIZE:
            self.cache[code] = result
        return result

    def words(self, code: str, number: int) -> tuple[Word, ...]:
        """The words of line ``number``; JobFileError (file:line) where it is not G-code."""
        words = self.words_or_none(code)
        if words is None and (bare := BARE_VALUE.fullmatch(code)) is not None:
            # The CoreXY plotter's own M98 <µs> / M99 <pwm>: a value with no letter.
            value = bare.group(2)
            words = (
                Word("M", bare.group(1), float(bare.group(1))),
                Word("P", value, float(value)),
            )
        if words is None:
            at = 0
            upper = code.upper()
            while (match := WORD.match(upper, at)) is not None:
                at = match.end()
            rest = code[at:].strip()
            raise JobFileError(
                self.file,
                number,
                QCoreApplication.translate("JobFile", "malformed G-code at {0} in {1}").format(
                    repr(rest[:20]), quoted(code)
                ),
            )
        return words
