"""The G-code codec against docs/protocols.md §4 and GRBL 1.1's reply forms.

Every wire line below is written out by hand the way GRBL (or the CoreXY
plotter, which says ``OK``) sends it, CR LF included.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.gcode import (
    ALARM_MESSAGES,
    CYCLE_START,
    ERROR_MESSAGES,
    FEED_HOLD,
    MAX_LINE_BYTES,
    RX_BUFFER,
    SOFT_RESET,
    STATUS_QUERY,
    AlarmReply,
    Banner,
    ErrorReply,
    Feedback,
    GcodeReply,
    Ok,
    Rejected,
    StatusReport,
    decode,
    encode_line,
    make_decoder,
    with_work_offset,
)
from protocol.gcode.codec import GRBL_BANNER, PLOTTER_BANNER
from protocol.gcode.words import Word, WordError, split_words, strip_comments


def test_the_contracts_constants() -> None:
    assert (STATUS_QUERY, FEED_HOLD, CYCLE_START, SOFT_RESET) == (b"?", b"!", b"~", b"\x18")
    assert (MAX_LINE_BYTES, RX_BUFFER) == (80, 128)


# -- encoding ----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "wire"),
    [
        ("G1 X10 Y20 F500", b"G1 X10 Y20 F500\n"),
        ("  G0 X0\r\n", b"G0 X0\n"),
        ("$H", b"$H\n"),
        ("G1 X1 (pen\tdown) ; comment", b"G1 X1 (pen\tdown) ; comment\n"),
        ("", b"\n"),
    ],
)
def test_lines_are_stripped_and_end_in_lf(text: str, wire: bytes) -> None:
    assert encode_line(text) == wire


def test_the_longest_line_is_79_characters_and_its_lf() -> None:
    assert len(encode_line("G" * 79)) == 80
    with pytest.raises(ValueError, match="81 bytes"):
        encode_line("G" * 80)


@pytest.mark.parametrize(
    ("text", "reason"),
    [
        ("G1 X10 é", "ASCII"),
        ("G1 X1\nG1 X2", "control byte"),
        ("G1 X1\rG1 X2", "control byte"),
        ("G1 X1 (what?)", "real-time"),
        ("M0 (stop!)", "real-time"),
        ("G1 ~X1", "real-time"),
        ("G1 X1\x18", "real-time"),
        ("G1\x00X1", "control byte"),
    ],
)
def test_lines_that_would_corrupt_the_stream_are_refused(text: str, reason: str) -> None:
    with pytest.raises(ValueError, match=reason):
        encode_line(text)


@pytest.mark.parametrize("code", range(128))
def test_every_ascii_character_inside_a_line_is_sent_or_refused_by_its_kind(code: int) -> None:
    """Printable characters and the tab go; control bytes, DEL and real-time bytes never."""
    char = chr(code)
    realtime = code in (ord("?"), ord("!"), ord("~"), 0x18)
    control = (code < 0x20 and char != "\t") or code == 0x7F
    if realtime:
        with pytest.raises(ValueError, match="real-time"):
            encode_line(f"G1{char}X1")
    elif control:
        with pytest.raises(ValueError, match="control byte"):
            encode_line(f"G1{char}X1")
    else:
        assert encode_line(f"G1{char}X1") == f"G1{char}X1\n".encode("ascii")


# -- decoding every reply form ------------------------------------------------------------


@pytest.mark.parametrize(
    ("wire", "reply"),
    [
        (b"ok\r\n", Ok()),
        (b"OK\r\n", Ok()),
        (b"Ok\n", Ok()),
        (b"error:20\r\n", ErrorReply(20)),
        (b"ERROR:20\r\n", ErrorReply(20)),
        (b"Error:2\r\n", ErrorReply(2)),
        (b"error: Bad number format\r\n", ErrorReply(0)),
        (b"ALARM:1\r\n", AlarmReply(1)),
        (b"alarm:9\r\n", AlarmReply(9)),
        (b"Grbl 1.1h ['$' for help]\r\n", Banner(GRBL_BANNER)),
        (f"{PLOTTER_BANNER}\r\n".encode(), Banner(PLOTTER_BANNER)),
        (
            b"GrblHAL 1.1f ['$' or '$HELP' for help]\r\n",
            Banner("GrblHAL 1.1f ['$' or '$HELP' for help]"),
        ),
        (b"[MSG:Caution: Unlocked]\r\n", Feedback("[MSG:Caution: Unlocked]")),
        (
            b"[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]\r\n",
            Feedback("[GC:G0 G54 G17 G21 G90 G94 M5 M9 T0 F0 S0]"),
        ),
        (b"$100=250.000\r\n", Feedback("$100=250.000")),
        (b">G54:ok\r\n", Feedback(">G54:ok")),
    ],
)
def test_every_reply_form_decodes(wire: bytes, reply: GcodeReply) -> None:
    assert decode(wire) == (len(wire), reply)


def test_error_and_alarm_codes_carry_grbls_meaning() -> None:
    assert set(range(1, 18)) | set(range(20, 39)) <= set(ERROR_MESSAGES)
    assert set(range(1, 11)) <= set(ALARM_MESSAGES)
    assert "unsupported" in ErrorReply(20).meaning.lower()
    assert "bad number" in ErrorReply(2).meaning.lower()
    assert "line overflow" in ErrorReply(11).meaning.lower()
    assert "travel exceeded" in ErrorReply(15).meaning.lower()
    assert "hard limit" in AlarmReply(1).meaning.lower()
    assert ErrorReply(99).meaning == "unknown error 99"
    assert AlarmReply(77).meaning == "unknown alarm 77"


def test_a_status_report_decodes_into_its_fields() -> None:
    wire = b"<Idle|MPos:1.000,2.000,0.000|FS:500,0|Bf:15,128>\r\n"
    assert decode(wire) == (
        len(wire),
        StatusReport(
            state="Idle",
            mpos=(1.0, 2.0, 0.0),
            feed=500.0,
            spindle=0.0,
            planner_free=15,
            rx_free=128,
            fields={"MPos": "1.000,2.000,0.000", "FS": "500,0", "Bf": "15,128"},
            wpos=(1.0, 2.0, 0.0),
        ),
    )


def test_g8_03_wco_gives_the_work_position_and_wpos_the_machine_position() -> None:
    """GRBL: WPos = MPos - WCO, whichever of the two $10 makes it report."""
    _, report = decode(b"<Idle|MPos:20.000,10.000,0.000|FS:0,0|WCO:15.000,5.000,0.000>\n")
    assert isinstance(report, StatusReport)
    assert report.mpos == (20.0, 10.0, 0.0)
    assert report.wpos == (5.0, 5.0, 0.0)
    assert report.wco == (15.0, 5.0, 0.0)
    _, report = decode(b"<Run|WPos:5.000,5.000,0.000|FS:600,0|WCO:15.000,5.000,0.000>\n")
    assert isinstance(report, StatusReport)
    assert (report.mpos, report.wpos, report.work_reported) == ((20.0, 10.0, 0.0), (5, 5, 0), True)
    # Most reports carry no WCO: the offset last heard completes them.
    _, bare = decode(b"<Run|WPos:6.000,5.000,0.000|FS:600,0>\n")
    assert isinstance(bare, StatusReport) and bare.wco is None
    done = with_work_offset(bare, (15.0, 5.0, 0.0))
    assert (done.mpos, done.wpos) == ((21.0, 10.0, 0.0), (6.0, 5.0, 0.0))
    _, machine = decode(b"<Idle|MPos:21.000,10.000,0.000|FS:0,0>\n")
    assert isinstance(machine, StatusReport)
    assert with_work_offset(machine, (15.0, 5.0, 0.0)).wpos == (6.0, 5.0, 0.0)
    assert with_work_offset(machine, None).wpos == (21.0, 10.0, 0.0)  # none heard: 0
    assert isinstance(decode(b"<Idle|MPos:1,2,3|WCO:1,x,0>\n")[1], Rejected)


def test_a_hold_report_carries_its_substate_and_wpos_is_accepted() -> None:
    _, report = decode(b"<Hold:0|WPos:-1.5,0.250,3.000|FS:0,1000|Ov:100,100,100>\n")
    assert isinstance(report, StatusReport)
    assert (report.state, report.substate) == ("Hold", "0")
    assert report.mpos == (-1.5, 0.25, 3.0)
    assert (report.feed, report.spindle) == (0.0, 1000.0)
    assert (report.planner_free, report.rx_free) == (None, None)
    assert report.fields["Ov"] == "100,100,100" and "MPos" not in report.fields


def test_a_four_axis_report_and_an_f_only_rate() -> None:
    _, report = decode(b"<Run|MPos:90.000,10.000,5.000,0.000|F:1200>\n")
    assert isinstance(report, StatusReport)
    assert report.mpos == (90.0, 10.0, 5.0, 0.0) and report.feed == 1200.0


@pytest.mark.parametrize(
    "wire",
    [
        b"hello\r\n",
        b"<Idle|FS:0,0>\r\n",  # no position
        b"<Idle|MPos:1,x,0>\r\n",
        b"<Idle|MPos:0,0,0|Bf:15>\r\n",
        b"<Idle|MPos:0,0,0\r\n",  # unterminated
        b"<|MPos:0,0,0>\r\n",
        b"<Idle|MPos>\r\n",
        b"\xff\xfeok\r\n",
    ],
)
def test_garbage_is_rejected_with_a_reason(wire: bytes) -> None:
    used, result = decode(wire)
    assert used == len(wire)
    assert isinstance(result, Rejected) and result.raw == wire and result.reason


def test_a_partial_line_needs_more_and_empty_lines_are_skipped() -> None:
    assert decode(b"o") == (0, None)
    assert decode(b"ok\r") == (0, None)
    assert decode(b"\r\n\r\nok\r\n") == (4, None)
    assert decode(b"   \r\n") == (5, None)


def test_split_and_glued_lines_through_the_reader() -> None:
    wire = b"ok\r\nerror:20\r\n<Run|MPos:0.000,0.000,0.000|FS:0,0>\r\nALARM:2\r\nOK\r\n"
    whole = make_decoder().feed(wire)
    assert whole == [
        Ok(),
        ErrorReply(20),
        StatusReport(
            "Run",
            (0.0, 0.0, 0.0),
            0.0,
            0.0,
            None,
            None,
            {"MPos": "0.000,0.000,0.000", "FS": "0,0"},
            wpos=(0.0, 0.0, 0.0),
        ),
        AlarmReply(2),
        Ok(),
    ]
    for cut in range(1, len(wire)):
        decoder = make_decoder()
        assert decoder.feed(wire[:cut]) + decoder.feed(wire[cut:]) == whole
    decoder = make_decoder()
    assert [m for b in wire for m in decoder.feed(bytes([b]))] == whole


def test_garbage_is_counted_once_and_the_next_reply_decodes() -> None:
    decoder = make_decoder()
    assert decoder.feed(b"zz top\r\nok\r\n") == [
        Rejected(b"zz top\r\n", "not a G-code board reply"),
        Ok(),
    ]
    assert (decoder.rejected, decoder.messages) == (1, 1)


def test_an_over_long_run_costs_one_reject_and_is_dropped_to_its_lf() -> None:
    decoder = make_decoder()
    results = decoder.feed(b"x" * 300) + decoder.feed(b"y" * 300 + b"\nok\n")
    assert len(results) == 2 and isinstance(results[0], Rejected) and results[1] == Ok()
    assert decoder.rejected == 1


@given(st.lists(st.binary(max_size=40), max_size=20))
def test_the_reader_never_raises(chunks: list[bytes]) -> None:
    decoder = make_decoder()
    for chunk in chunks:
        decoder.feed(chunk)
    assert decoder.feed(b"\nok\n")[-1] == Ok()


# -- words ---------------------------------------------------------------------------------


def test_comments_are_stripped_grbls_way() -> None:
    assert strip_comments("G1 X1 (pen down) Y2 ; the rest") == "G1 X1  Y2 "
    assert strip_comments("G1 X1 (never closed Y2") == "G1 X1 "


def test_words_take_spaces_case_and_signs() -> None:
    assert split_words("g1x 10 Y-2.5 f+.5") == [
        Word("G", 1.0, "1"),
        Word("X", 10.0, "10"),
        Word("Y", -2.5, "-2.5"),
        Word("F", 0.5, "+.5"),
    ]
    assert split_words("M98 500") == [Word("M", 98.0, "98"), Word("", 500.0, "500")]


@pytest.mark.parametrize(
    ("line", "code"), [("G1 X", 2), ("G1 X-", 2), ("G1 X.", 2), ("G1 #1", 1), ("=", 1)]
)
def test_what_is_not_a_word_is_grbls_error(line: str, code: int) -> None:
    result = split_words(line)
    assert isinstance(result, WordError) and result.code == code


def test_odd_numbers_are_cut_the_way_grbl_reads_them() -> None:
    # No exponents: "1e3" is 1 and then the word E3 (which no machine supports).
    assert split_words("X1e3") == [Word("X", 1.0, "1"), Word("E", 3.0, "3")]
    # A second decimal point starts a bare number, which only M98/M99 may take.
    assert split_words("X1.2.3") == [Word("X", 1.2, "1.2"), Word("", 0.3, ".3")]
