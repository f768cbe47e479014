"""The emulated GRBL board's work coordinate systems: G54…G59, G10 L2/L20, $#, $G and WCO:,
as GRBL 1.1h's gcode.c keeps them (WPos = MPos - WCS - G92)."""

from __future__ import annotations

import pytest

from protocol.gcode import ErrorReply, Feedback, Ok
from tests.protocol.test_gcode_firmware import CYCLE, Bench


def feedback(bench: Bench, line: str) -> list[str]:
    return [r.text for r in bench.do(line) if isinstance(r, Feedback)]


def wco(bench: Bench) -> tuple[float, ...]:
    """The next ``WCO:`` the board reports (it comes at once after a change)."""
    for _ in range(12):
        report = bench.status()
        if report.wco is not None and "WCO" in report.fields:
            return report.wco
    raise AssertionError("no WCO: in 12 reports")


def test_g10_l20_makes_here_the_zero_of_the_named_axes_and_moves_nothing() -> None:
    bench = Bench()
    assert bench.do("G0 X30 Y40") == [Ok()]
    assert bench.do("G10 L20 P1 X0 Y0") == [Ok()]
    assert bench.fw.position() == {"X": 30.0, "Y": 40.0, "Z": 0.0}
    assert wco(bench) == (30.0, 40.0, 0.0)
    assert bench.do("G0 Y0") == [Ok()]
    assert bench.fw.position()["Y"] == pytest.approx(40.0)
    assert bench.do("G0 X5") == [Ok()]  # work X 5 is machine X 35
    assert bench.fw.position()["X"] == pytest.approx(35.0)
    assert "[G54:30.000,40.000,0.000]" in feedback(bench, "$#")


def test_g10_l2_stores_another_system_and_g55_selects_it() -> None:
    bench = Bench()
    assert bench.do("G10 L2 P2 X10 Y20", "G55", "G0 X0 Y0") == [Ok()] * 3
    assert bench.fw.position() == {"X": 10.0, "Y": 20.0, "Z": 0.0}
    assert feedback(bench, "$G")[0].startswith("[GC:G0 G55 G17")
    listed = feedback(bench, "$#")
    assert listed[:2] == ["[G54:0.000,0.000,0.000]", "[G55:10.000,20.000,0.000]"]
    assert wco(bench) == (10.0, 20.0, 0.0)


def test_g92_adds_to_the_system_and_wco_is_their_sum() -> None:
    bench = Bench()
    assert bench.do("G10 L2 P1 X10", "G0 X20", "G92 X0") == [Ok()] * 3
    assert bench.fw.position()["X"] == 30.0
    assert wco(bench)[0] == pytest.approx(30.0)
    listed = feedback(bench, "$#")
    assert "[G92:20.000,0.000,0.000]" in listed  # G92 = MPos - WCS - WPos = 30 - 10 - 0
    # L20 with a G92 in force: WCS = MPos - G92 - WPos.
    assert bench.do("G10 L20 P0 X5") == [Ok()]
    assert "[G54:5.000,0.000,0.000]" in feedback(bench, "$#")
    assert bench.status().wpos[0] == pytest.approx(5.0)


def test_a_soft_reset_selects_g54_keeps_the_stored_systems_and_drops_g92() -> None:
    bench = Bench()
    assert bench.do("G10 L2 P3 X7", "G56", "G92 Y3") == [Ok()] * 3
    bench.fw.receive(b"\x18")
    bench.run(CYCLE * 2)
    assert feedback(bench, "$G")[0].startswith("[GC:G0 G54 ")
    listed = feedback(bench, "$#")
    assert "[G56:7.000,0.000,0.000]" in listed and "[G92:0.000,0.000,0.000]" in listed


def test_program_end_selects_g54_again() -> None:
    bench = Bench()
    assert bench.do("G10 L2 P2 X10", "G55", "M2") == [Ok()] * 3
    assert feedback(bench, "$G")[0].startswith("[GC:G1 G54 ")


@pytest.mark.parametrize(
    ("line", "code"),
    [
        ("G10 L2 P1", 26),  # no axis words
        ("G10 P1 X0", 28),  # no L
        ("G10 L20 X0", 28),  # no P
        ("G10 L20 P7 X0", 29),  # G59.1 and beyond: not supported
        ("G10 L3 P1 X0", 20),
        ("G10 L2 P1 R1 X0", 20),
        ("G10 L20 P-1 X0", 4),
        ("G10 L20 P1 G0 X0", 24),  # G10 and a motion both want the axis words
        ("G54 G55", 21),
        ("G1 X1 L2 F100", 36),  # L without G10: unused
    ],
)
def test_g10_errors_are_grbls_and_change_nothing(line: str, code: int) -> None:
    bench = Bench()
    assert bench.do(line) == [ErrorReply(code)]
    assert feedback(bench, "$#")[0] == "[G54:0.000,0.000,0.000]"
    assert bench.fw.position()["X"] == 0.0


def test_the_corexy_plotter_has_no_work_systems() -> None:
    from protocol.emulator.gcode_firmware import corexy_plotter_config

    bench = Bench(corexy_plotter_config())
    assert bench.do("G10 L20 P1 X0") == [ErrorReply(20)]
    assert bench.do("G55") == [ErrorReply(20)]
