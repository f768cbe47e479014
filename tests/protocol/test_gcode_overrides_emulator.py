"""The emulated GRBL board's feed and rapid overrides (GRBL 1.1h's protocol.c, planner.c,
report.c), and the override bytes the station computes.

The GRBL plotter moves ``G1 X100 F600`` at 10 mm/s once up to speed (1000 mm/s²: 0.05 mm
to get there); at 50 % it covers 5 mm each second, and G0 (100 mm/s) at 25 % 25 mm/s.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.emulator.gcode_firmware import corexy_plotter_config
from protocol.gcode import Ok, StatusReport
from protocol.gcode.overrides import (
    FEED_MINUS_1,
    FEED_MINUS_10,
    FEED_PLUS_10,
    FEED_RESET,
    RAPID_25,
    Overrides,
    applied,
    feed_bytes,
    parse_overrides,
    rapid_byte,
)
from tests.protocol.test_gcode_firmware import CYCLE, Bench


def speed_over(bench: Bench, seconds: float) -> float:
    before = bench.fw.position()["X"]
    bench.run(seconds)
    return (bench.fw.position()["X"] - before) / seconds


def ov_report(bench: Bench) -> StatusReport:
    """The first report with ``Ov:``: the next one, or the one after a report with ``WCO:``."""
    for _ in range(2):
        report = bench.status()
        if "Ov" in report.fields:
            return report
    raise AssertionError("no Ov: in two reports after a change")


def override(bench: Bench, *codes: bytes) -> None:
    """One byte per control cycle: GRBL counts a kind once per real-time pass."""
    for code in codes:
        bench.fw.receive(code)
        bench.run(CYCLE)


def test_feed_override_of_50_halves_a_feed_move_under_way_and_reports_ov_50() -> None:
    bench = Bench()
    bench.send("G1 X100 F600")
    bench.run(1.0)
    assert speed_over(bench, 1.0) == pytest.approx(10.0, rel=1e-6)
    override(bench, *[FEED_MINUS_10] * 5)
    bench.run(0.1)  # it brakes to 5 mm/s at 1000 mm/s² within 5 ms
    assert speed_over(bench, 1.0) == pytest.approx(5.0, rel=1e-6)
    report = ov_report(bench)
    assert report.fields["Ov"] == "50,100,100"
    assert report.feed == pytest.approx(300.0)
    assert bench.fw.overrides == (50, 100)
    assert [e["feed"] for e in bench.events("override")][-1] == 50


def test_rapid_override_scales_g0_only_and_feed_override_leaves_g0_alone() -> None:
    bench = Bench()
    override(bench, FEED_MINUS_10, RAPID_25)
    assert bench.fw.overrides == (90, 25)
    bench.send("G0 X200")
    bench.run(0.5)
    assert speed_over(bench, 1.0) == pytest.approx(25.0, rel=1e-6)
    bench.run_until_idle()
    bench.send("G1 X0 F1200")
    bench.run(1.0)
    assert speed_over(bench, 1.0) == pytest.approx(-18.0, rel=1e-6)


def test_a_feed_override_never_exceeds_the_rapid_rate() -> None:
    bench = Bench()
    override(bench, *[FEED_PLUS_10] * 10)
    assert bench.fw.overrides == (200, 100)
    bench.send("G1 X250 F4500")  # 75 mm/s, at 200 % 150 mm/s: capped at 100 mm/s
    bench.run(1.0)
    assert speed_over(bench, 1.0) == pytest.approx(100.0, rel=1e-6)


def test_bytes_of_one_kind_in_one_pass_count_once_as_grbl_flags_do() -> None:
    bench = Bench()
    bench.fw.receive(FEED_MINUS_10 * 5 + FEED_MINUS_1 * 3)
    bench.run(CYCLE)
    assert bench.fw.overrides == (89, 100)


def test_limits_soft_reset_and_program_end_restore_100() -> None:
    bench = Bench()
    override(bench, *[FEED_MINUS_10] * 12)
    assert bench.fw.overrides == (10, 100)
    bench.fw.receive(b"\x18")
    bench.run(CYCLE)
    assert bench.fw.overrides == (100, 100)
    override(bench, FEED_MINUS_10, RAPID_25)
    assert bench.do("G1 X5 F600", "M2") == [Ok(), Ok()]
    assert bench.fw.overrides == (100, 100)


def test_ov_is_reported_at_once_after_a_change_then_every_10th_report_idle() -> None:
    bench = Bench()
    reports = [bench.status() for _ in range(25)]
    carrying = [i for i, r in enumerate(reports) if "Ov" in r.fields]
    assert "WCO" in reports[0].fields and "Ov" not in reports[0].fields  # never both
    assert carrying == [2, 12, 22] or carrying == [1, 11, 21]
    override(bench, FEED_RESET, FEED_MINUS_10)
    assert bench.status().fields.get("Ov") == "90,100,100"  # no WCO due: the next report


def test_the_corexy_plotter_ignores_override_bytes_as_its_firmware_has_none() -> None:
    bench = Bench(corexy_plotter_config())
    override(bench, FEED_MINUS_10)
    report = bench.status()
    assert "Ov" not in report.fields and bench.fw.overrides == (100, 100)


# -- the bytes the station sends ----------------------------------------------------------


@given(st.integers(10, 200), st.integers(10, 200))
def test_feed_bytes_reach_the_target_when_each_byte_is_its_own_pass(
    current: int, target: int
) -> None:
    state = Overrides(current)
    for byte in feed_bytes(current, target):
        state = applied(state, frozenset({byte}))
    assert state.feed == target
    assert len(feed_bytes(current, target)) <= 20  # 1 reset, 10 tens, 9 ones at most


def test_feed_bytes_refuse_what_grbl_cannot_take_and_rapid_has_three_levels() -> None:
    with pytest.raises(ValueError):
        feed_bytes(100, 5)
    with pytest.raises(ValueError):
        rapid_byte(75)
    assert feed_bytes(37, 100) == FEED_RESET
    assert feed_bytes(100, 89) == FEED_MINUS_10 + FEED_MINUS_1


def test_grbl_wraps_its_byte_below_zero_to_200_percent() -> None:
    """10 % less 10 and less 1 in one pass: GRBL's uint8_t wraps to 255, clamped to 200."""
    assert applied(Overrides(10), frozenset({FEED_MINUS_10[0], FEED_MINUS_1[0]})).feed == 200


def test_the_ov_field_is_parsed_and_a_bad_one_refused() -> None:
    assert parse_overrides({"Ov": "50,25,100"}) == Overrides(50, 25, 100)
    assert parse_overrides({}) is None
    assert isinstance(parse_overrides({"Ov": "50,x,100"}), str)
    assert isinstance(parse_overrides({"Ov": "0,100,100"}), str)


def test_a_status_report_carries_its_overrides() -> None:
    bench = Bench()
    override(bench, FEED_MINUS_10)
    report = ov_report(bench)
    assert report.overrides == Overrides(90, 100, 100)


def test_a_report_with_a_malformed_ov_is_dropped_as_garbage() -> None:
    from protocol.gcode import Rejected, make_decoder

    decoder = make_decoder()
    good, bad = decoder.feed(
        b"<Idle|MPos:0.000,0.000,0.000|FS:0,0|Ov:90,50,100>\r\n"
        b"<Idle|MPos:0.000,0.000,0.000|FS:0,0|Ov:90,5x,100>\r\n"
    )
    assert isinstance(good, StatusReport) and good.overrides == Overrides(90, 50, 100)
    assert isinstance(bad, Rejected)
