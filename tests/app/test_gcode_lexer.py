"""The one G-code lexer (protocol/gcode/words.py) and its three readers: the job parser, the
console's motion gate and the emulator, which read every line through it and so agree.

GRBL 1.1 (tests/third_party/grbl) is the judge of what a line says; the hostile
corpus (tests/hostile_corpus.py) goes through all three readers here.
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from app.jobs.formats.gcode import parser
from app.jobs.formats.gcode import words as job_words
from app.machines.gcode import line_targets, planned_path
from app.machines.gcode.line_targets import line_motion
from protocol.clock import ManualClock
from protocol.emulator import gcode_firmware
from protocol.emulator.gcode_firmware import (
    GcodeConfig,
    GcodeFirmware,
    corexy_plotter_config,
    grbl_line,
    grbl_plotter_config,
)
from protocol.gcode import ErrorReply, Ok, encode_line, make_decoder
from protocol.gcode import words as lexer
from protocol.gcode.words import (
    Word,
    WordError,
    grbl_text,
    line_code,
    scan_words,
    split_words,
    take_line_number,
    words_or_none,
)
from tests.helpers.hostile_corpus import CASES, Case, Loaded, Refused

REPO = Path(__file__).resolve().parents[2]
LEXER = "protocol.gcode.words"
READERS = {
    "the job parser": ("app/jobs/formats/gcode/parser.py", "app/jobs/formats/gcode/words.py"),
    "the console's gate": ("app/machines/gcode/line_targets.py",),
    "the emulator": ("protocol/emulator/gcode_firmware.py",),
}


def _imports_from(path: Path) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    return {
        node.module for node in ast.walk(tree) if isinstance(node, ast.ImportFrom) and node.module
    }


@pytest.mark.parametrize("reader", READERS)
def test_each_reader_imports_the_one_lexer(reader: str) -> None:
    for relative in READERS[reader]:
        assert LEXER in _imports_from(REPO / relative), f"{relative} does not use the lexer"


def test_the_readers_call_the_lexers_own_functions() -> None:
    """Not copies: the very functions, so a fix in the lexer reaches every reader."""
    assert parser.take_line_number is lexer.take_line_number
    assert parser.split_comment is lexer.split_comment
    assert job_words.words_or_none is lexer.words_or_none
    assert line_targets.scan_words is lexer.scan_words
    assert planned_path.scan_grbl_words is lexer.scan_grbl_words
    assert gcode_firmware.split_words is lexer.split_words
    assert gcode_firmware.grbl_text is lexer.grbl_text


def test_no_other_module_writes_its_own_word_pattern() -> None:
    """A G-code number pattern outside the lexer is a fourth lexer in the making."""
    patterns = (r"\d+\.?\d*|\.\d+", r"[0-9]+\.?[0-9]*|\.[0-9]+")
    found = [
        str(path.relative_to(REPO))
        for top in ("app", "protocol", "widgets", "stepdeck")
        for path in (REPO / top).rglob("*.py")
        if path != REPO / "protocol/gcode/words.py"
        and any(p in path.read_text(encoding="utf-8") for p in patterns)
    ]
    assert found == []


# -- the lexer -------------------------------------------------------------------------------


def test_grbl_text_is_what_grbls_serial_layer_keeps() -> None:
    assert grbl_text("g1 x1 0\t( a (nested ) y2 ; rest") == "G1X10Y2"
    assert grbl_text("G1 X5 (never closed Y500") == "G1X5"
    assert grbl_text("/G0 X1\x07") == "G0X1"  # block delete and control characters dropped
    assert grbl_text("G0 X\u0661") == "G0X\u0661"  # only a-z are upper-cased; the rest stays
    assert grbl_text("g0 xé") == "G0Xé"


def test_the_emulators_grbl_line_is_the_lexers_grbl_text_within_grbls_buffer() -> None:
    assert grbl_line(b"g1 x1 0 (c)\r\n") == "G1X10"
    assert grbl_line(b"G1 X" + b"1" * 76 + b"\n") == "G1X" + "1" * 76  # 79 kept: fits
    assert grbl_line(b"G1 X" + b"1" * 77 + b"\n") is None  # 80 kept: overflows
    assert grbl_line(b"G1 X1" + b" " * 200 + b"(long comment)\n") == "G1X1"


def _grbl_protocol_c(raw: bytes) -> str | None:
    """GRBL 1.1's protocol.c loop, byte by byte: what its parser gets (None: overflow)."""
    kept: list[str] = []
    in_parens = in_semicolon = False
    for byte in raw:
        char = chr(byte)
        if char in "\r\n":
            break
        if in_parens or in_semicolon:
            in_parens = in_parens and char != ")"
            continue
        if byte <= 0x20 or char == "/":
            continue
        if char == "(":
            in_parens = True
        elif char == ";":
            in_semicolon = True
        elif len(kept) >= 80 - 1:
            return None
        else:
            kept.append(char.upper() if "a" <= char <= "z" else char)
    return "".join(kept)


@given(
    st.binary(max_size=100).map(lambda b: b.replace(b"\n", b""))
    | st.text("GXy1 .-()/;\t\ra").map(str.encode)
)
def test_the_lexers_grbl_reading_is_grbls_protocol_loop(raw: bytes) -> None:
    assert grbl_line(raw + b"\n") == _grbl_protocol_c(raw + b"\n")


def test_line_code_takes_off_comment_line_number_and_checksum() -> None:
    assert line_code("N120 G1 X1 (move) *57 ") == "G1 X1"
    assert take_line_number("n 007 G0") == ("007", "G0")
    assert take_line_number("G0 N7") == (None, "G0 N7")


def test_bare_values_are_an_option() -> None:
    assert split_words("M98 500") == [Word("M", 98.0, "98"), Word("", 500.0, "500")]
    refused = split_words("M98 500", bare_values=False)
    assert isinstance(refused, WordError) and refused.code == lexer.EXPECTED_COMMAND_LETTER
    assert words_or_none("M98 500") is None
    assert job_words.bare_value_words("M098 500") == (
        Word("M", 98.0, "98"),
        Word("P", 500.0, "500"),
    )
    assert job_words.bare_value_words("M 98 500") is None  # as the parser always read it
    assert job_words.bare_value_words("M98 -5") is None
    assert job_words.bare_value_words("G1 M98 5") is None


def test_scan_words_skips_what_is_no_word() -> None:
    assert scan_words("G0 X1..2 @ Y 3 Z") == [("G", 0.0), ("X", 1.0), ("Y", 3.0)]
    assert scan_words("G0 X1 000") == [("G", 0.0), ("X", 1000.0)]


_CODE_TEXT = st.text(alphabet="GXYMNFE019.+- \tq*", max_size=14)


@given(_CODE_TEXT)
def test_the_parsers_fast_reading_is_the_strict_split(code: str) -> None:
    """``words_or_none`` (two regular expressions) and ``split_words`` (a scan) are one reading."""
    fast = words_or_none(code)
    scanned = split_words(code, bare_values=False)
    if fast is None:
        assert isinstance(scanned, WordError)
    else:
        assert list(fast) == scanned


@given(st.text(alphabet="GXYM019.- \t()/;a", max_size=16))
def test_the_gate_reads_what_the_emulated_grbl_reads(line: str) -> None:
    """Where GRBL takes a line as words, the gate sees the very same words."""
    words = split_words(grbl_text(line), bare_values=False)
    if isinstance(words, list):
        assert scan_words(line) == [(w.letter, w.value) for w in words]


def test_the_gate_places_a_move_where_grbl_goes() -> None:
    here = {"X": 100.0}
    # Spaces inside a number do not split it on GRBL (the gate read X1 here before).
    assert line_motion("G0 X1 000", False, here, ("X", "Y")).targets == {"X": 1000.0}
    # An unclosed comment hides the rest: G90 is in it, so the line stays relative.
    motion = line_motion("G91 (to G90 X5", False, here, ("X",))
    assert motion.relative_after and motion.targets == {}
    assert line_motion("G91 G0 X5 (G90", False, here, ("X",)).targets == {"X": 105.0}
    # GRBL drops spaces before it looks for "$": this is a jog, and it is placed.
    jog = line_motion(" $ j=g91 x 5 f100", False, here, ("X",))
    assert jog.targets == {"X": 105.0} and not jog.relative_after


# -- the hostile corpus through all three readers --------------------------------------------

_CONFIGS = {"grbl-plotter": grbl_plotter_config, "corexy-plotter": corexy_plotter_config}


def _gcode_cases() -> list[Case]:
    """The corpus's G-code files short enough to send line by line."""
    cases = []
    for case in CASES:
        if case.profile not in _CONFIGS or not isinstance(case.content, str):
            continue
        if case.content.startswith("<") or not case.job.endswith((".gcode", ".nc", ".out")):
            continue
        lines = case.content.splitlines()
        if len(lines) <= 20 and all(len(line) < 80 for line in lines):
            cases.append(case)
    return cases


def _checked(lines: list[str], config: GcodeConfig) -> list[Ok | ErrorReply | None]:
    """Each line's one answer from the emulated board (GRBL in check mode, ``$C``); None: a
    line the station never sends (not ASCII)."""
    clock = ManualClock(start=100.0)
    board = GcodeFirmware(clock, config)
    out = bytearray()
    board.set_output(out.extend)
    decoder = make_decoder()

    def answers() -> list[Ok | ErrorReply]:
        """The answers that come within a minute of the board's time (a move is run out)."""
        got: list[Ok | ErrorReply] = []
        for _ in range(12_000):
            clock.advance(0.005)
            board.run_until(clock.now())
            got += [r for r in decoder.feed(bytes(out)) if isinstance(r, (Ok, ErrorReply))]
            out.clear()
            if got and not board.busy:
                break
        return got

    assert answers() == []  # the banner only
    if config.grbl:
        board.receive(b"$C\n")
        assert answers() == [Ok()]
    replies: list[Ok | ErrorReply | None] = []
    for line in lines:
        try:
            raw = encode_line(line)
        except ValueError:
            replies.append(None)
            continue
        board.receive(raw)
        (reply,) = answers()
        replies.append(reply)
    return replies


def test_the_corpus_has_gcode_for_all_three_readers() -> None:
    assert len(_gcode_cases()) >= 25


@pytest.mark.parametrize("case", _gcode_cases(), ids=lambda c: c.id)
def test_the_hostile_corpus_through_the_emulator_and_the_gate(case: Case) -> None:
    """The parser's verdict (test_hostile_corpus.py) is the board's; the gate places each line.

    A file the parser loads is answered ``ok`` line by line; a line the parser
    refuses with GRBL's ``error:N`` gets that error from the board; a malformed
    line gets GRBL's "expected command letter" or "bad number format" unless
    GRBL reads it as words (``X1 0`` is X10).  The gate never raises and names
    every axis the board would move on a line it takes.
    """
    lines = case.content.splitlines() if isinstance(case.content, str) else []
    config = _CONFIGS[case.profile]()
    replies = _checked(lines, config)
    expect = case.expect
    if isinstance(expect, Loaded):
        assert replies == [Ok()] * len(lines)
    elif isinstance(expect, Refused) and "error:" in expect.word:
        index = int(expect.where.rsplit(":", 1)[1]) - 1
        assert replies[index] == ErrorReply(int(expect.word.split(":")[1]))
    elif isinstance(expect, Refused) and expect.word == "malformed":
        index = int(expect.where.rsplit(":", 1)[1]) - 1
        grbl_reads = isinstance(split_words(grbl_text(lines[index]), bare_values=False), list)
        answers = (Ok(),) if grbl_reads else (ErrorReply(1), ErrorReply(2), None)
        assert replies[index] in answers
    axes = config.axes
    for line, reply in zip(lines, replies, strict=True):
        motion = line_motion(line, False, {}, axes)
        named = {letter for letter, _ in scan_words(line) if letter in axes}
        codes = {f"{letter}{value:g}" for letter, value in scan_words(line) if letter == "G"}
        if reply == Ok() and not codes & {"G4", "G10", "G28", "G30", "G92"}:
            assert set(motion.targets) == named, line
