"""A job file's G-code lines read for the parser: its patterns and its cached tokenizer.

The lexing itself (comments, ``N`` numbers, checksums, words) is
:mod:`protocol.gcode.words`, the one lexer the emulator and the console's
gate read lines with too; what is here is what only a job file has: the
lines the station handles itself (``$`` commands, waits, messages,
real-time bytes), those it refuses (parameters, expressions), the CoreXY
plotter's bare values as a file may write them, and the refusal a
malformed line gets, with its file and line.
"""

from __future__ import annotations

import re

from PySide6.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from app.jobs.names import quoted
from app.jobs.program import JobFileError
from protocol.gcode.words import (
    NUMBER,
    SPACES,
    WORD,
    Word,
    split_comment,
    split_words,
    words_or_none,
)

#: The longest line a board takes, without its line end (docs/protocols.md §4: 80 bytes).
MAX_LINE_CHARS = 79

#: A word whose number is written with an exponent (``X1e308``): G-code reads it as two words.
EXPONENT = re.compile(rf"([A-DF-Za-df-z][ \t]*{NUMBER})([eE][-+]?[0-9]+)")
SYSTEM = re.compile(r"\$([A-Za-z]+|\$|#|\d+)?")
WAIT_RE = re.compile(r"[Mm]0*([01])(?![\d.])[ \t]*")
MESSAGE_RE = re.compile(r"[Mm]0*(11[78])(?![\d.])")
PARAMETERS = re.compile(
    r"[#\[\]]|^[Oo]|[Gg]0*6[5-7](?![\d.])|\b(?:IF|WHILE|GOTO|DO|END)\b", re.IGNORECASE
)
#: ``M98 800`` / ``M99 90``: the CoreXY plotter's step interval and servo level
#: (docs/protocols.md §4.5), the only codes a bare value (a number with no letter) follows.
BARE_VALUE_CODES = frozenset({98.0, 99.0})
#: A bare value as a file may write it: unsigned, a digit first.
BARE_VALUE = re.compile(r"[0-9]+(?:\.[0-9]*)?")
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


def normal(letter: str, value: float) -> str:
    """A command word spelled one way: G00 == G0, M03 == M3, G92.1 stays G92.1."""
    if value.is_integer():
        return f"{letter}{int(value)}"
    return f"{letter}{value:g}"


def plain_code(line: str) -> str:
    """A plain move's text as sent: without its trailing comment and surrounding spaces."""
    if ";" in line or "(" in line:
        return split_comment(line)[0].strip()
    return line.strip()


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
        result = words_or_none(code)
        if result is not None and len(self.cache) < TOKEN_CACHE_SIZE:
            self.cache[code] = result
        return result

    def words(self, code: str, number: int) -> tuple[Word, ...]:
        """The words of line ``number``; JobFileError (file:line) where it is not G-code."""
        words = self.words_or_none(code)
        if words is None:
            words = bare_value_words(code)
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


def bare_value_words(code: str) -> tuple[Word, Word] | None:
    """``M98 <µs>`` / ``M99 <pwm>`` alone on a line, read as M98/M99 and P; None: not that.

    The CoreXY plotter's own codes take a value with no letter (the lexer's
    bare values); a file may write nothing else on such a line, the code as
    one word and the value unsigned, a digit first.
    """
    words = split_words(code, bare_values=True)
    if isinstance(words, list) and len(words) == 2:
        code_word, value = words
        if (
            code_word.letter == "M"
            and code_word.value in BARE_VALUE_CODES
            and code_word.text.isdigit()
            and code.lstrip(" \t")[1:2].isdigit()  # written "M98", not "M 98"
            and value.letter == ""
            and BARE_VALUE.fullmatch(value.text)
        ):
            return Word("M", code_word.value, f"{code_word.value:g}"), Word(
                "P", value.value, value.text
            )
    return None
