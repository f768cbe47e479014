"""A pen (tool) change in a G-code file: ``M6 T2`` becomes a wait for the operator.

A pen plotter has no tool changer: GRBL 1.1 answers ``M6`` with error:20
(unsupported command), and a file made for a machine with several pens asks
for the next pen with ``M6 Tn`` (or ``Tn M6``).  The station makes that line
what the drill's bit prompts are: the job stops before it, with everything
before it run, and shows "change to pen T2" until the operator goes on; the
job then goes on with the line after it.  The line itself is never sent
(the station, not the board, waits: nothing moves and nothing is on the
wire meanwhile), as the M0/M1 program stops are not (GRBL's M0 is a program
pause that only a cycle start ends, which the station would then have to
send behind the operator's back).

Only a line that is the change and nothing else is one: ``M6`` among other
words stays a line of words (refused where the machine cannot execute it).
"""

from __future__ import annotations

import re

from PySide6.QtCore import QCoreApplication

#: ``M6``, ``M06 T2``, ``T2 M6``, ``m6t02``: the change, with its tool number before or after.
TOOL_CHANGE = re.compile(
    r"(?:[Tt][ \t]*0*([0-9]+)[ \t]*)?[Mm][ \t]*0*6(?![0-9.])[ \t]*(?:[Tt][ \t]*0*([0-9]+)[ \t]*)?\Z"
)
#: The highest tool number GRBL takes (its T is a byte), as the parser refuses above it.
MAX_TOOL = 255


def tool_change(code: str) -> str | None:
    """The tool a change line asks for ("" for none named); None: the line is no change."""
    match = TOOL_CHANGE.match(code)
    if match is None:
        return None
    before, after = match.group(1), match.group(2)
    if before is not None and after is not None:
        return None  # two tool numbers: a line of words, refused as such
    tool = before if before is not None else after
    if tool is not None and int(tool) > MAX_TOOL:
        return None
    return "" if tool is None else str(int(tool))


def tool_prompt(tool: str, comment: str) -> str:
    """What the operator is asked: the pen to put in, and the file's own words for it."""
    if tool:
        text = QCoreApplication.translate("JobFile", "change to pen T{0}").format(tool)
    else:
        text = QCoreApplication.translate("JobFile", "change the pen")
    return f"{text}: {comment}" if comment else text
