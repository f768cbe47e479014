"""G-code lines cut into words, the way GRBL reads them.

Shared by the emulator, which executes the words, and by whoever checks a
job's lines before sending them.  A word is a letter and a number; spaces
between them do not matter (``X 10`` is ``X10``), case does not either.  The
CoreXY plotter's own codes take a number without a letter (``M98 500``), so a
bare number is returned as a word with an empty letter and the interpreter
decides whether it belongs to anything.  Nothing here raises on a line:
what is not a word comes back as a :class:`WordError` carrying GRBL's code.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

#: GRBL's error codes for a line that cannot even be cut into words.
EXPECTED_COMMAND_LETTER = 1
BAD_NUMBER_FORMAT = 2

#: GRBL's number format: a sign, digits and one decimal point; no exponent.
_NUMBER = re.compile(r"[ \t]*([+-]?(?:[0-9]+\.?[0-9]*|\.[0-9]+))")
_SPACE = " \t\r\n"


@dataclass(frozen=True, slots=True)
class Word:
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


def strip_comments(line: str) -> str:
    """The line without ``( ... )`` comments and without everything from ``;`` on.

    An unclosed parenthesis comments out the rest of the line, as in GRBL.
    """
    out: list[str] = []
    in_paren = False
    for char in line:
        if in_paren:
            in_paren = char != ")"
        elif char == "(":
            in_paren = True
        elif char == ";":
            break
        else:
            out.append(char)
    return "".join(out)


def split_words(line: str) -> list[Word] | WordError:
    """The words of a comment-free line, in order; a WordError for the first thing that is none."""
    words: list[Word] = []
    pos = 0
    while pos < len(line):
        char = line[pos]
        if char in _SPACE:
            pos += 1
            continue
        if char.isascii() and char.isalpha():
            match = _NUMBER.match(line, pos + 1)
            if match is None:
                return WordError(BAD_NUMBER_FORMAT, f"{char.upper()} without a number")
            words.append(Word(char.upper(), float(match[1]), match[1]))
        else:
            match = _NUMBER.match(line, pos)
            if match is None:
                return WordError(EXPECTED_COMMAND_LETTER, f"{char!r} where a letter belongs")
            words.append(Word("", float(match[1]), match[1]))
        pos = match.end()
    return words
