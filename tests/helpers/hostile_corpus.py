"""A corpus of malformed and hostile job files, generated at test time, each with its outcome.

Every case is one job file (plus the files beside it), the machine profile it
is checked against, the ``stepdeck check`` options, and what must happen:

* :class:`Refused`: the first line printed is ``file:line: …`` and holds the
  reason word (and nothing loads in the dock);
* :class:`Loaded`: the job passes with exactly this many operations;
* :class:`Asked`: the format is ambiguous; the dock asks with these choices.

The files are written by :func:`materialise` (special files too: a named
pipe, a link to ``/dev/zero``, a folder, a sparse file over the size cap).
The expected operation counts follow the programs' documented shapes:
a point list is one operation per line, a G-code file one per line here, a
drill job one WAIT per tool and a MOVE and a DRILL per hole, a string-art
job ``4·nails + 4·entries + 3`` (see :func:`winder_operations`).
"""

from __future__ import annotations

import codecs
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

#: A file's content, or how to make a special one.
PIPE = "<named pipe>"
DEV_ZERO = "<link to /dev/zero>"
FOLDER = "<folder>"
SPARSE = "<sparse file of 200 MB>"
MISSING = "<missing>"


@dataclass(frozen=True)
class Refused:
    where: str  # "file:line"
    word: str  # a word of the reason


@dataclass(frozen=True)
class Loaded:
    operations: int
    note: str = ""  # a word one of the program's notes holds (a library warning)


@dataclass(frozen=True)
class Asked:
    choices: tuple[str, ...]  # job type keys


Outcome = Refused | Loaded | Asked


@dataclass(frozen=True)
class Case:
    id: str
    job: str  # the file name opened
    content: bytes | str
    profile: str
    expect: Outcome
    beside: dict[str, bytes] = field(default_factory=dict)
    args: tuple[str, ...] = ()


def winder_operations(nails: int, entries: int) -> int:
    """A string-art program as the firmware runs it: a comment, the drill to 1 cm above the
    board, per nail four moves and the 250 ms dwell, back to nail 0 (turn, radius); a
    comment, drivers off, the wait, out, turn, in, turn back, the drill's driver off; four
    moves per further entry; the closing comment."""
    return 1 + 1 + 5 * nails + 2 + 1 + 1 + 1 + 4 + 1 + 4 * (entries - 1) + 1


def materialise(case: Case, folder: Path) -> Path:
    """Write ``case``'s files into ``folder``; the path of the job file."""
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / case.job
    for name, data in case.beside.items():
        (folder / name).write_bytes(data)
    content = case.content
    if content == PIPE:
        os.mkfifo(path)
    elif content == DEV_ZERO:
        path.symlink_to("/dev/zero")
    elif content == FOLDER:
        path.mkdir()
    elif content == SPARSE:
        with path.open("wb") as handle:
            handle.truncate(200_000_000)
    elif content == MISSING:
        pass
    else:
        path.write_bytes(content.encode() if isinstance(content, str) else content)
    return path


def _param(tvar: object = 0, nails: object = 6, radius: object = 10) -> bytes:
    return f"tvar = {tvar}\npocet_hrebiku = {nails}\npolomer_matrice = {radius}\n".encode()


def _poradi(*entries: object, count: object | None = None) -> bytes:
    head = str(len(entries) if count is None else count)
    return "\n".join([head, *map(str, entries)]).encode() + b"\n"


GOOD_PARAM = _param()
EXCELLON_HEAD = "M48\nMETRIC,TZ\nT01C0.8\n%\nT01\n"
GCODE_OK = "G0 X1 Y1 F1000\nG1 X10 Y10\nG1 X20 Y5\n"
UTF16_GCODE = codecs.BOM_UTF16_LE + GCODE_OK.encode("utf-16-le")


def _cases() -> list[Case]:
    c: list[Case] = []
    add = c.append
    sa = "string-art"

    # --- 1. the file's name decides: param.txt / poradi.txt are string art ----------
    add(
        Case(
            "poradi-two-nails",
            "poradi.txt",
            _poradi(0, 3),
            sa,
            Loaded(winder_operations(6, 2)),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "param-opens-its-poradi",
            "param.txt",
            GOOD_PARAM,
            sa,
            Loaded(winder_operations(6, 3)),
            {"poradi.txt": _poradi(0, 3, 1)},
        )
    )
    add(
        Case(
            "poradi-upper-case-name",
            "PORADI.TXT",
            _poradi(1, 4),
            sa,
            Loaded(winder_operations(6, 2)),
            {"Param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-malformed-not-a-point-list",
            "poradi.txt",
            b"2\n0\nfive\n",
            sa,
            Refused("poradi.txt:3", "whole"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-on-the-stage",
            "poradi.txt",
            _poradi(0, 3),
            "xy-stage",
            Refused("poradi.txt:0", "winder"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-two-numbers-a-line",
            "poradi.txt",
            b"2\n0, 3\n",
            sa,
            Loaded(winder_operations(6, 2)),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-without-param",
            "poradi.txt",
            _poradi(0, 3, 1),
            sa,
            Refused("poradi.txt:0", "board"),
        )
    )
    add(
        Case(
            "poradi-without-param-board-given",
            "poradi.txt",
            _poradi(0, 3, 1),
            sa,
            Loaded(winder_operations(8, 3)),
            args=("--board", "0,8,10"),
        )
    )
    add(Case("param-without-poradi", "param.txt", GOOD_PARAM, sa, Refused("param.txt:0", "beside")))
    add(
        Case(
            "param-malformed",
            "param.txt",
            b"tvar = 0\npocet_hrebiku six\n",
            sa,
            Refused("param.txt:2", "key"),
        )
    )
    add(
        Case(
            "param-not-a-number",
            "param.txt",
            _param(nails="six"),
            sa,
            Refused("param.txt:2", "number"),
            {"poradi.txt": _poradi(0, 1)},
        )
    )
    add(
        Case(
            "poradi-count-disagrees",
            "poradi.txt",
            _poradi(0, 3, count=5),
            sa,
            Refused("poradi.txt:1", "count"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-nail-to-itself",
            "poradi.txt",
            _poradi(0, 2, 2),
            sa,
            Refused("poradi.txt:4", "twice"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-one-nail",
            "poradi.txt",
            _poradi(3),
            sa,
            Refused("poradi.txt:1", "fewer"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "poradi-empty",
            "poradi.txt",
            b"",
            sa,
            Refused("poradi.txt:0", "no nail"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "bare-list-by-content",
            "sequence.txt",
            b"0,3,1,4,2,5\n",
            sa,
            Loaded(winder_operations(6, 6)),
            args=("--board", "0,6,10"),
        )
    )
    add(
        Case(
            "bare-list-asks-the-board",
            "sequence.txt",
            b"0,3,1,4,2,5\n",
            sa,
            Refused("sequence.txt:0", "board"),
        )
    )

    # --- 2, 3. nail indices too large for any integer or any board --------------------
    add(
        Case(
            "index-above-2-63",
            "poradi.txt",
            _poradi(0, 2**64),
            sa,
            Refused("poradi.txt:3", "digits"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "index-4301-digits",
            "poradi.txt",
            _poradi(0, "7" * 4301),
            sa,
            Refused("poradi.txt:3", "digits"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "index-out-of-range",
            "poradi.txt",
            _poradi(0, 6),
            sa,
            Refused("poradi.txt:3", "range"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "index-negative",
            "poradi.txt",
            _poradi(0, -1),
            sa,
            Refused("poradi.txt:3", "range"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "count-huge",
            "poradi.txt",
            _poradi(0, 1, count=10**40),
            sa,
            Refused("poradi.txt:1", "digits"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "bare-list-index-beyond-any-board",
            "sequence.txt",
            b"0,3,1,99999999\n",
            sa,
            Refused("sequence.txt:1", "range"),
        )
    )
    add(
        Case(
            "bare-list-huge-index",
            "sequence.txt",
            b"0,3,1," + b"9" * 30 + b"\n",
            sa,
            Refused("sequence.txt:1", "digits"),
        )
    )
    add(
        Case(
            "index-with-sign-inside",
            "poradi.txt",
            b"2\n0\n1-2\n",
            sa,
            Refused("poradi.txt:3", "whole"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "index-lone-sign",
            "poradi.txt",
            b"2\n0\n-\n",
            sa,
            Refused("poradi.txt:3", "whole"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "index-decimal",
            "poradi.txt",
            b"2\n0\n1.5\n",
            sa,
            Refused("poradi.txt:3", "whole"),
            {"param.txt": GOOD_PARAM},
        )
    )

    # --- 4. every board number bounded --------------------------------------------------
    for nails, word in ((10**9, "most"), (10**40, "most"), (10_001, "most"), (2, "least")):
        add(
            Case(
                f"nails-{nails:.0e}",
                "param.txt",
                _param(nails=nails),
                sa,
                Refused("param.txt:2", word),
                {"poradi.txt": _poradi(0, 1)},
            )
        )
    add(
        Case(
            "nails-overflowing-float",
            "param.txt",
            _param(nails="9" * 400),
            sa,
            Refused("param.txt:2", "large"),
            {"poradi.txt": _poradi(0, 1)},
        )
    )
    for tvar, word in ((1001, "sides"), (10**12, "sides"), (2, "shape"), (-3, "shape")):
        add(
            Case(
                f"tvar-{tvar}",
                "param.txt",
                _param(tvar=tvar),
                sa,
                Refused("param.txt:1", word),
                {"poradi.txt": _poradi(0, 1)},
            )
        )
    for radius, word in ((1e6, "most"), (1, "larger"), ("nan", "number"), ("-4", "larger")):
        add(
            Case(
                f"radius-{radius}",
                "param.txt",
                _param(radius=radius),
                sa,
                Refused("param.txt:3", word),
                {"poradi.txt": _poradi(0, 1)},
            )
        )
    add(
        Case(
            "radius-beyond-travel",
            "param.txt",
            _param(radius=30),
            sa,
            Refused("param.txt:2", "outside"),
            {"poradi.txt": _poradi(0, 1)},
        )
    )
    add(
        Case(
            "board-flag-malformed",
            "sequence.txt",
            b"0,3,1,4\n",
            sa,
            Refused("", "usage"),
            args=("--board", "0,ten,10"),
        )
    )

    # --- 5. G-code that GRBL refuses is refused before anything moves -------------------
    g = "grbl-plotter"
    add(Case("gcode-ok", "ok.gcode", GCODE_OK, g, Loaded(3)))
    # "X1e308" is X1 and E308 to G-code (no exponents): the refusal names E 308 and says so
    # (issue 30: it said "E 308 is outside nan…nan").
    add(
        Case(
            "gcode-exponent",
            "e.gcode",
            "G0 X1 Y1 F1000\nG1 X1e308\n",
            g,
            Refused("e.gcode:2", "no E axis"),
        )
    )
    add(
        Case(
            "gcode-huge",
            "far.gcode",
            "G0 X1 Y1 F1000\nG1 X" + "9" * 70 + "\n",
            g,
            Refused("far.gcode:2", "outside 0…"),
        )
    )
    add(
        Case(
            "arc-end-off-circle",
            "arc.gcode",
            "G0 X10 Y10 F600\nG2 X30 Y10 I5 J0\n",
            g,
            Refused("arc.gcode:2", "error:33"),
        )
    )
    add(Case("arc-end-on-circle", "arc.gcode", "G0 X10 Y10 F600\nG2 X20 Y10 I5 J0\n", g, Loaded(2)))
    add(
        Case(
            "arc-radius-too-small",
            "r.gcode",
            "G0 X10 Y10 F600\nG2 X30 Y10 R5\n",
            g,
            Refused("r.gcode:2", "error:34"),
        )
    )
    add(
        Case(
            "arc-no-offsets",
            "o.gcode",
            "G0 X10 Y10 F600\nG2 X30 Y10\n",
            g,
            Refused("o.gcode:2", "error:35"),
        )
    )
    add(
        Case(
            "arc-r-to-itself",
            "s.gcode",
            "G0 X10 Y10 F600\nG2 X10 Y10 R5\n",
            g,
            Refused("s.gcode:2", "error:33"),
        )
    )
    add(
        Case(
            "arc-without-axes",
            "a.gcode",
            "G0 X10 Y10 F600\nG2 I5 J0\n",
            g,
            Refused("a.gcode:2", "error:26"),
        )
    )
    add(
        Case(
            "feed-negative",
            "f.gcode",
            "G0 X1 Y1\nG1 X10 Y10 F-100\n",
            g,
            Refused("f.gcode:2", "error:4"),
        )
    )
    add(
        Case(
            "feed-negative-alone",
            "f.gcode",
            "G0 X1 Y1\nF-100\n",
            g,
            Refused("f.gcode:2", "error:4"),
        )
    )
    add(
        Case(
            "feed-never-set",
            "f.gcode",
            "G0 X1 Y1\nG1 X10 Y10\n",
            g,
            Refused("f.gcode:2", "error:22"),
        )
    )
    add(
        Case(
            "feed-zero", "f.gcode", "G0 X1 Y1 F0\nG1 X10 Y10\n", g, Refused("f.gcode:2", "error:22")
        )
    )
    add(
        Case(
            "feed-never-set-arc",
            "f.gcode",
            "G0 X10 Y10\nG3 X20 Y10 I5 J0\n",
            g,
            Refused("f.gcode:2", "error:22"),
        )
    )
    add(Case("feed-set-on-rapid", "f.gcode", "G0 X1 Y1 F500\nG1 X10 Y10\n", g, Loaded(2)))
    add(
        Case(
            "feed-not-needed-on-corexy",
            "f.gcode",
            "G0 X1 Y1\nG1 X10 Y10\n",
            "corexy-plotter",
            Loaded(2),
        )
    )
    add(Case("dwell-negative", "d.gcode", "G0 X1 Y1\nG4 P-5\n", g, Refused("d.gcode:2", "error:4")))
    add(Case("word-repeated", "w.gcode", "G0 X1 X2 Y1\n", g, Refused("w.gcode:1", "error:25")))
    add(
        Case(
            "two-motion-words", "m.gcode", "G0 G1 X1 Y1 F100\n", g, Refused("m.gcode:1", "error:21")
        )
    )
    add(
        Case(
            "unsupported-word",
            "u.gcode",
            "G0 X1 Y1\nG38.2 X5 Y5 F100\n",
            g,
            Refused("u.gcode:2", "cannot execute"),
        )
    )
    add(
        Case(
            "line-too-long",
            "l.gcode",
            "G0 X1 Y1 F100\nG1 X1.0000000000000000000000000000000000"
            "00000000000000 Y2.000000000000000000000000000000000000\n",
            g,
            Refused("l.gcode:2", "at most 79"),
        )
    )
    add(
        Case(
            "gcode-outside-travel",
            "t.gcode",
            "G0 X1 Y1\nG0 X400 Y1\n",
            g,
            Refused("t.gcode:2", "outside"),
        )
    )
    add(
        Case(
            "gcode-malformed",
            "x.gcode",
            "G0 X1 Y1\nG1 X1..2\n",
            g,
            Refused("x.gcode:2", "malformed"),
        )
    )
    # Digits are ASCII, as GRBL reads them: an Arabic-Indic one is no number (it crashed the
    # plain-move fast path before the one lexer).
    add(
        Case(
            "gcode-non-ascii-digit",
            "d.gcode",
            "G0 X1 Y1 F100\nG1 X\u0661 Y1\n",
            g,
            Refused("d.gcode:2", "malformed"),
        )
    )
    # An unclosed comment runs to the end of the line, as on GRBL: Y500 is no destination.
    add(
        Case("gcode-unclosed-comment", "c.gcode", "G0 X1 Y1 F100\nG1 X5 (note Y500\n", g, Loaded(2))
    )
    # Spaces inside a number: GRBL reads X10, the parser refuses the line rather than guess.
    add(
        Case(
            "gcode-space-inside-number",
            "s.gcode",
            "G0 X1 Y1 F100\nG1 X1 0\n",
            g,
            Refused("s.gcode:2", "malformed"),
        )
    )

    add(
        Case(
            "tool-number-above-255",
            "t.gcode",
            "G0 X1 Y1\nT256 M6\n",
            g,
            Refused("t.gcode:2", "error:38"),
        )
    )
    add(
        Case(
            "line-number-above-max",
            "n.gcode",
            "N10 G0 X1 Y1\nN10000001 G0 X2 Y2\n",
            g,
            Refused("n.gcode:2", "error:27"),
        )
    )
    add(
        Case(
            "line-number-5000-digits",
            "n.gcode",
            "G0 X1 Y1\nN" + "9" * 5000 + " G0 X2 Y2\n",
            g,
            Refused("n.gcode:2", "error:27"),
        )
    )
    add(
        Case(
            # The value is 7, and the N number is not sent: the line is short on the wire.
            "line-number-leading-zeros",
            "n.gcode",
            "N" + "0" * 5000 + "7 G0 X2 Y2 F100\n",
            g,
            Loaded(1),
        )
    )

    long_line = "G1 X1 Y1 Q" + "7" * 3_000_000 + "\n"
    add(
        Case(
            "malformed-line-of-3-mb",
            "long.gcode",
            "G0 X1 Y1 F100\n" + long_line,
            g,
            Refused("long.gcode:2", "characters)"),
        )
    )

    # --- 10. huge arcs are refused fast, not drawn with millions of vertices -------------
    huge = "G0 X10 Y10 F600\n" + "G2 X10 Y10 I-900000 J0\n" * 2000
    add(Case("huge-arcs", "huge.gcode", huge, g, Refused("huge.gcode:2", "arc too long")))
    # Full circles of 90 mm: GRBL's 0.002 mm chord tolerance gives each ``chords`` chords, and
    # the file's arcs may have 4 000 000 inner vertices in all: the arc that passes that is refused.
    chords = math.ceil(math.tau / (2 * math.acos(1 - 0.002 / 90)))
    over = 4_000_000 // (chords - 1) + 1
    many = "G0 X100 Y100 F600\n" + "G2 X100 Y100 I90 J0\n" * (over + 10)
    add(
        Case(
            "arcs-over-the-budget",
            "many.gcode",
            many,
            g,
            Refused(f"many.gcode:{over + 1}", "arcs too many"),
        )
    )

    # --- 6, 7, 8, 14. Excellon ------------------------------------------------------------
    d = "pcb-drill"
    add(Case("excellon-ok", "ok.drl", EXCELLON_HEAD + "X1.0Y1.0\nX2.0Y2.0\nM30\n", d, Loaded(5)))
    add(
        Case(
            "g85-without-end",
            "slot.drl",
            EXCELLON_HEAD + "X1.0Y1.0\nX2.0Y2.0G85\nM30\n",
            d,
            Refused("slot.drl:7", "G85"),
        )
    )
    add(
        Case("g85-with-end", "slot.drl", EXCELLON_HEAD + "X1.0Y1.0G85X3.0Y1.0\nM30\n", d, Loaded(5))
    )
    add(
        Case(
            "routed-arc",
            "route.drl",
            EXCELLON_HEAD + "G00X1.0Y1.0\nM15\nG02X3.0Y1.0A1.0\nM16\nM30\n",
            d,
            Refused("route.drl:8", "routed arcs"),
        )
    )
    add(
        Case(
            "tool-zero-diameter",
            "zero.drl",
            "M48\nMETRIC,TZ\nT01C0.0\n%\nT01\nX1.0Y1.0\nM30\n",
            d,
            Refused("zero.drl:3", "diameter"),
        )
    )
    add(
        Case(
            "tool-negative-diameter",
            "neg.drl",
            "M48\nMETRIC,TZ\nT01C-0.5\n%\nT01\nX1.0Y1.0\nM30\n",
            d,
            Refused("neg.drl:3", "diameter"),
        )
    )
    add(
        Case(
            "tool-number-huge",
            "tool.drl",
            "M48\nMETRIC,TZ\nT1000C0.8\n%\nT1000\nX1.0Y1.0\nM30\n",
            d,
            Refused("tool.drl:3", "tool number"),
        )
    )
    add(
        Case(
            "tool-number-4000-digits",
            "tool.drl",
            f"M48\nMETRIC,TZ\nT{'9' * 4000}C0.8\n%\nX1.0Y1.0\nM30\n",
            d,
            Refused("tool.drl:3", "tool number"),
        )
    )
    add(
        Case(
            "tool-defined-twice",
            "twice.drl",
            "M48\nMETRIC,TZ\nT01C0.8\nT01C1.0\n%\nT01\nX1.0Y1.0\nM30\n",
            d,
            Loaded(3, note="twice.drl:4: warning"),
        )
    )
    add(
        Case(
            "excellon-undefined-tool",
            "undef.drl",
            EXCELLON_HEAD + "T02\nX1.0Y1.0\nM30\n",
            d,
            Refused("undef.drl:6", "tool"),
        )
    )
    add(
        Case(
            "excellon-hole-before-tool",
            "early.drl",
            "M48\nMETRIC,TZ\nT01C0.8\n%\nX1.0Y1.0\nM30\n",
            d,
            Refused("early.drl:5", "before any tool"),
        )
    )
    add(
        Case(
            "excellon-coordinate-overflow",
            "far.drl",
            EXCELLON_HEAD + "X" + "9" * 400 + ".0Y1.0\nM30\n",
            d,
            Refused("far.drl:6", "large"),
        )
    )
    add(
        Case(
            "excellon-no-holes",
            "none.drl",
            "M48\nMETRIC,TZ\nT01C0.8\n%\nM30\n",
            d,
            Refused("none.drl:0", "no holes"),
        )
    )
    # Repeats: a count is bounded before gerbonara makes its holes one by one (issue 30:
    # R999999999 in a 9-line file ran past 60 s at 3.9 GB).
    add(
        Case(
            "excellon-repeat-flood",
            "rep.drl",
            EXCELLON_HEAD + "X1.0Y1.0\nR999999999X0.1\nX2.0Y2.0\nM30\n",
            d,
            Refused("rep.drl:7", "repeat"),
        )
    )
    add(
        Case(
            "excellon-repeat-digit-flood",
            "rep.drl",
            EXCELLON_HEAD + "X1.0Y1.0\nR" + "9" * 5000 + "X0.1\nM30\n",
            d,
            Refused("rep.drl:7", "repeat"),
        )
    )
    add(
        Case(
            "excellon-repeats-add-up",
            "rep.drl",
            EXCELLON_HEAD + "X1.0Y1.0\nR30000X0.001\nR30000Y0.001\nM30\n",
            d,
            Refused("rep.drl:8", "50,000"),
        )
    )
    add(
        Case(
            "excellon-repeat-ok",
            "rep.drl",
            EXCELLON_HEAD + "X1.0Y1.0\nR3X1.0\nM30\n",
            d,
            Loaded(1 + 2 * 4),
        )
    )
    add(
        Case(
            "excellon-pattern-repeat",
            "pat.drl",
            EXCELLON_HEAD + "M25\nX1.0Y1.0\nM01\nM02X10.0Y0\nM08\nM30\n",
            d,
            Refused("pat.drl:6", "M25"),
        )
    )

    # --- 9. encodings ----------------------------------------------------------------------
    bom = codecs.BOM_UTF8
    add(
        Case(
            "bom-excellon",
            "bom.drl",
            bom + (EXCELLON_HEAD + "X1.0Y1.0\nM30\n").encode(),
            d,
            Loaded(3),
        )
    )
    add(Case("bom-point-list", "bom.csv", bom + b"1, 2\n3, 4\n", "xy-stage", Loaded(2)))
    add(Case("bom-gcode", "bom.gcode", bom + GCODE_OK.encode(), g, Loaded(3)))
    add(
        Case(
            "bom-param",
            "param.txt",
            bom + GOOD_PARAM,
            sa,
            Loaded(winder_operations(6, 2)),
            {"poradi.txt": bom + _poradi(0, 3)},
        )
    )
    add(
        Case(
            "bom-poradi",
            "poradi.txt",
            bom + _poradi(0, 3),
            sa,
            Loaded(winder_operations(6, 2)),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(Case("utf16-gcode", "u16.gcode", UTF16_GCODE, g, Refused("u16.gcode:0", "UTF-16")))
    add(
        Case(
            "utf16-be-excellon",
            "u16.drl",
            codecs.BOM_UTF16_BE + (EXCELLON_HEAD + "M30\n").encode("utf-16-be"),
            d,
            Refused("u16.drl:0", "UTF-16"),
        )
    )
    add(
        Case(
            "utf16-without-bom-csv",
            "u16.csv",
            "1, 2\n3, 4\n".encode("utf-16-le"),
            "xy-stage",
            Refused("u16.csv:0", "UTF-16"),
        )
    )
    add(
        Case(
            "utf16-poradi",
            "poradi.txt",
            codecs.BOM_UTF16_LE + "2\n0\n3\n".encode("utf-16-le"),
            sa,
            Refused("poradi.txt:0", "UTF-16"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(
        Case(
            "latin1-gcode", "l1.gcode", b"G0 X1 Y1\n(caf\xe9)\n", g, Refused("l1.gcode:2", "UTF-8")
        )
    )

    # A PNG's signature ends its second line ("\r\n", "\x1a\n"): the first zero is on line 3.
    png = b"\x89PNG\r\n\x1a\n\x00\x00\x00\rIHDR" + bytes(range(256))
    add(Case("binary-gcode", "image.gcode", png, g, Refused("image.gcode:3", "binary")))
    add(Case("binary-txt", "image.txt", png, "xy-stage", Refused("image.txt:3", "binary")))
    add(
        Case(
            "binary-after-good-lines",
            "tail.csv",
            b"1, 2\n3, 4\n\x00\x01\x02\n",
            "xy-stage",
            Refused("tail.csv:3", "binary"),
        )
    )
    add(
        Case(
            "utf16-without-bom-poradi",
            "poradi.txt",
            "2\n0\n3\n".encode("utf-16-le"),
            sa,
            Refused("poradi.txt:0", "UTF-16"),
            {"param.txt": GOOD_PARAM},
        )
    )

    # --- 11. special files and sizes -----------------------------------------------------------
    add(Case("named-pipe", "pipe.gcode", PIPE, g, Refused("pipe.gcode:0", "pipe")))
    add(Case("named-pipe-txt", "pipe.txt", PIPE, "xy-stage", Refused("pipe.txt:0", "pipe")))
    add(Case("link-to-dev-zero", "zero.nc", DEV_ZERO, g, Refused("zero.nc:0", "device")))
    add(
        Case(
            "link-to-dev-zero-poradi",
            "poradi.txt",
            DEV_ZERO,
            sa,
            Refused("poradi.txt:0", "device"),
            {"param.txt": GOOD_PARAM},
        )
    )
    add(Case("folder", "dir.gcode", FOLDER, g, Refused("dir.gcode:0", "folder")))
    add(Case("over-the-size-cap", "big.gcode", SPARSE, g, Refused("big.gcode:0", "too large")))
    add(Case("missing", "gone.gcode", MISSING, g, Refused("gone.gcode:0", "cannot read")))
    add(Case("empty-txt", "empty.txt", b"", "xy-stage", Refused("empty.txt:0", "empty")))

    # --- the format: by extension, by content, asked when neither tells ----------------------
    add(Case("unknown-extension-gcode", "job.out", GCODE_OK, g, Loaded(3)))
    add(
        Case("unknown-extension-excellon", "DRILL", EXCELLON_HEAD + "X1.0Y1.0\nM30\n", d, Loaded(3))
    )
    add(
        Case(
            "unknown-extension-nonsense",
            "notes.out",
            b"hello world\n",
            g,
            Refused("notes.out:0", "unknown type"),
        )
    )
    add(
        Case(
            "txt-fits-nothing",
            "notes.txt",
            b"hello world\n",
            "xy-stage",
            Asked(("points", "excellon", "string-art")),
        )
    )
    add(
        Case(
            "txt-chosen-as-points",
            "notes.txt",
            b"1, 2\n3, x\n",
            "xy-stage",
            Refused("notes.txt:2", "number"),
            args=("--format", "points"),
        )
    )
    add(Case("txt-point-list", "route.txt", b"1, 2\n3, 4\n5, 6\n", "xy-stage", Loaded(3)))
    add(Case("txt-excellon", "drill.txt", EXCELLON_HEAD + "X1.0Y1.0\nM30\n", d, Loaded(3)))

    # --- point lists ----------------------------------------------------------------------------
    s = "xy-stage"
    add(Case("points-nan", "p.csv", b"1, 2\nnan, 4\n", s, Refused("p.csv:2", "finite")))
    add(Case("points-inf", "p.csv", b"1, 2\n1e999, 4\n", s, Refused("p.csv:2", "finite")))
    add(Case("points-columns", "p.csv", b"1, 2\n3, 4, 5, 6\n", s, Refused("p.csv:2", "expected")))
    add(Case("points-outside", "p.csv", b"1, 2\n3, 400\n", s, Refused("p.csv:2", "outside")))
    add(
        Case("points-wait-and-comment", "p.csv", b"# start\n1, 2\nwait: look\n3, 4\n", s, Loaded(4))
    )
    add(Case("points-none", "p.csv", b"# only a comment\n", s, Refused("p.csv:0", "no positions")))

    # --- 13. file names go into messages escaped ------------------------------------------------
    add(
        Case(
            "name-with-newline",
            "evil\nname.gcode",
            "G0 X1 Y1\nG1 X2 Y2\n",
            g,
            Refused("evil\\nname.gcode:2", "error:22"),
        )
    )
    add(
        Case(
            "name-with-escape",
            "red\x1b[31m.gcode",
            "G0 X1 Y1\nG1 X2 Y2\n",
            g,
            Refused("red\\x1b[31m.gcode:2", "error:22"),
        )
    )
    add(
        Case(
            "name-with-bidi",
            "a\u202egnp.nc",
            "G0 X1 Y1\nG1 X2 Y2\n",
            g,
            Refused("a\\u202egnp.nc:2", "error:22"),
        )
    )
    return c


CASES = _cases()
