"""The one G-code lexer: a line cut into its comments, ``N`` number, checksum and words.

Three readers build on it, so they agree on what a word is: the emulator,
which executes the words as a board would; the job parser, which checks a
file's lines before any is sent; and the console's motion gate, which places
a typed line before it goes.  GRBL 1.1 (its ``protocol.c`` and ``gcode.c``)
is the judge where they could differ:

* a word is a letter and a number, case and spaces between them aside
  (``x 10`` is ``X10``); a number is a sign, digits and one decimal point,
  ASCII digits only, never an exponent (``X1e3`` is ``X1`` and ``E3``);
* ``( … )`` and ``; …`` are comments; an unclosed parenthesis comments out
  the rest of the line;
* GRBL's serial layer drops the comments and every space, control
  character and ``/`` before its parser sees the line, so on GRBL ``X1 0``
  is ``X10`` (:func:`grbl_text`).

What differs between the readers are options, not code: the CoreXY plotter's
own codes take a number without a letter (``M98 500``: ``bare_values``); a job
file's lines may carry an ``N`` number and a ``*`` checksum the station takes
off before sending (:func:`line_code`); the gate reads what a line could move
and skips what is not a word (:func:`scan_words`), where the others refuse
the line.  Nothing here raises on a line: what is not a word comes back as a
:class:`WordError` carrying GRBL's code.
"""

from __future__ import annotations

import re
import string
from dataclasses import dataclass
from typing import NamedTuple

#: GRBL's error codes for a line that cannot even be cut into words.
EXPECTED_COMMAND_LETTER = 1
BAD_NUMBER_FORMAT = 2

#: A number as G-code writes it: ``1``, ``-1.``, ``+.5``, ``12.345`` (ASCII digits, as GRBL).
NUMBER = r"[-+]?(?:[0-9]+\.?[0-9]*|\.[0-9]+)"
#: One word, with the spaces before it; the look-ahead keeps ``X1..2`` from being a word.
WORD = re.compile(rf"[ \t]*([A-Za-z])[ \t]*({NUMBER})(?![0-9.])")
#: A line that is words and nothing else.
WORDS = re.compile(rf"(?:[ \t]*[A-Za-z][ \t]*{NUMBER}(?![0-9.]))*[ \t]*")
#: A comment: ``( … )`` (unclosed: to the end) or ``; …``.
COMMENT = re.compile(r"\(([^)]*)\)?|;(.*)", re.DOTALL)
#: A leading ``N`` number and a trailing ``*`` checksum (job files; GRBL has no checksum).
LINE_NUMBER = re.compile(r"[Nn][ \t]*[0-9]+[ \t]*")
CHECKSUM = re.compile(r"\*[ \t]*[0-9]*[ \t]*\Z")
SPACES = re.compile(r"[ \t]{2,}")

#: What GRBL's serial layer drops from a line: spaces, control characters, block delete.
_GRBL_DROPPED = re.compile(r"[\x00- /]")
#: GRBL upper-cases ``a``-``z`` and nothing else.
_ASCII_UPPER = str.maketrans(string.ascii_lowercase, string.ascii_uppercase)
_NUMBER_AT = re.compile(rf"[ \t]*({NUMBER})")
_SPACE = " \t"
#: A word anywhere, for the gate's lenient reading.
_ANY_WORD = re.compile(rf"([A-Z])({NUMBER})")


class Word(NamedTuple):
    """``letter`` upper case, or "" for a number that follows no letter; ``text`` as written."""

    letter: str
    value: float
    text: str

    def __str__(self) -> str:
        return f"{self.letter}{self.text}"


@dataclass(frozen=True, slots=True)
class WordError:
    """Why a line is not words: GRBL's ``code`` and a reason for people."""

    code: int
    reason: str


def split_comment(raw: str) -> tuple[str, str]:
    """The code of a line and its first comment (``( … )`` or ``; …``).

    Where a comment stood, runs of spaces are closed up, so the code a
    machine is sent has no double space where one was.
    """
    if "(" not in raw and ";" not in raw:
        return raw, ""
    comments: list[str] = []

    def drop(match: re.Match[str]) -> str:
        text = match.group(1) if match.group(1) is not None else match.group(2)
        comments.append((text or "").strip())
        return ""

    code = SPACES.sub(" ", COMMENT.sub(drop, raw))
    return code, next((c for c in comments if c), "")


def strip_comments(line: str) -> str:
    """The line without its comments, spacing otherwise as written."""
    if "(" not in line and ";" not in line:
        return line
    return COMMENT.sub("", line)


def take_line_number(code: str) -> tuple[str | None, str]:
    """A leading ``N`` number's digits (None: there is none) and the code after it."""
    match = LINE_NUMBER.match(code)
    if match is None:
        return None, code
    return match.group().strip()[1:].strip(), code[match.end() :]


def strip_checksum(code: str) -> str:
    """The code without a trailing ``*`` checksum."""
    return CHECKSUM.sub("", code) if "*" in code else code


def line_code(raw: str) -> str:
    """The code of a line without its comment, ``N`` number, checksum and surrounding spaces."""
    code = split_comment(raw)[0].strip()
    return strip_checksum(take_line_number(code)[1]).strip()


def grbl_text(line: str) -> str:
    """The line as GRBL 1.1's serial layer hands it to its parser, upper-cased.

    Comments, spaces, control characters and ``/`` (block delete, which GRBL
    does not support) are dropped as the bytes arrive, so they never count
    towards GRBL's line buffer either.
    """
    code = strip_comments(line)
    if code.isascii() and code.isprintable() and "/" not in code:
        return code.replace(" ", "").upper()  # the common case, five times faster
    return _GRBL_DROPPED.sub("", code).translate(_ASCII_UPPER)


def words_or_none(code: str) -> tuple[Word, ...] | None:
    """The words of a comment-free line that is words and nothing else; None where it is not.

    The strict reading (no bare values, spaces kept) that :func:`split_words`
    gives with ``bare_values=False``, in two regular expressions: the job
    parser reads every line of a file through it.
    """
    if not WORDS.fullmatch(code):
        return None
    return tuple(
        Word(letter.upper(), float(number), number) for letter, number in WORD.findall(code)
    )


def split_words(line: str, *, bare_values: bool = True) -> list[Word] | WordError:
    """The words of a comment-free line, in order; a WordError for the first thing that is none.

    ``bare_values``: a number that follows no letter is a word with the
    letter "" (the interpreter decides whether it belongs to anything);
    otherwise it is GRBL's "expected command letter".  Spaces separate words
    here (a CoreXY plotter's ``M98 500``); a line for GRBL goes through
    :func:`grbl_text` first, where they do not.
    """
    words: list[Word] = []
    pos = 0
    while pos < len(line):
        char = line[pos]
        if char in _SPACE:
            pos += 1
            continue
        if char.isascii() and char.isalpha():
            match = _NUMBER_AT.match(line, pos + 1)
            if match is None:
                return WordError(BAD_NUMBER_FORMAT, f"{char.upper()} without a number")
            words.append(Word(char.upper(), float(match[1]), match[1]))
        else:
            match = _NUMBER_AT.match(line, pos) if bare_values else None
            if match is None:
                return WordError(EXPECTED_COMMAND_LETTER, f"{char!r} where a letter belongs")
            words.append(Word("", float(match[1]), match[1]))
        pos = match.end()
    return words


def scan_words(line: str) -> list[tuple[str, float]]:
    """Every word a line holds as GRBL would read it, letter and value; what is no word skipped.

    For a reader that must not miss a move rather than refuse a line: the
    motion gate places what a line could do; whether the board takes the
    line is the board's to answer.
    """
    return scan_grbl_words(grbl_text(line))


def scan_grbl_words(code: str) -> list[tuple[str, float]]:
    """:func:`scan_words` of a line already in GRBL's reading (:func:`grbl_text`'s result):
    a sender's every line is read so once, not twice."""
    return [(letter, float(number)) for letter, number in _ANY_WORD.findall(code)]
