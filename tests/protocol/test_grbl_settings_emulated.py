"""The emulated GRBL board's ``$$`` and ``$N=value`` against GRBL 1.1h's own rules.

The expected answers are read off GRBL 1.1h's ``system_execute_line`` and
``settings_store_global_setting`` (tests/third_party/grbl/grbl), and the same
lines are sent to grbl-sim in tests/e2e/test_e2e_grbl_settings.py.
"""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from protocol.emulator import grbl_settings
from protocol.emulator.gcode_firmware import grbl_plotter_config
from protocol.gcode import ErrorReply, Feedback, Ok
from tests.protocol.test_gcode_firmware import Bench


def listed(bench: Bench) -> dict[str, str]:
    lines = [r.text for r in bench.do("$$") if isinstance(r, Feedback)]
    return dict(line.split("=", 1) for line in lines)


@pytest.mark.parametrize(
    ("line", "code"),
    [
        ("$0=2", 6),  # step pulse under 3 µs
        ("$1=-1", 4),  # negative
        ("$20=1", 10),  # soft limits without homing (homing off first, below)
        ("$14=1", 3),  # no such setting
        ("$103=5", 3),  # GRBL 1.1h has three axes
        ("$140=5", 3),
        ("$256=1", 3),
        ("$1=5x", 3),  # something after the value
        ("$1=", 2),  # no number
        ("$1=1e3", 3),  # no exponent: the 'e' is left over
        ("$Q=1", 2),
        ("$G1", 3),
        ("$1", 3),  # a setting is not read by its number in GRBL 1.1
    ],
)
def test_a_bad_setting_line_gets_grbls_error(line: str, code: int) -> None:
    bench = Bench(grbl_plotter_config())
    assert bench.do("$22=0") == [Ok()]
    before = listed(bench)
    assert bench.do(line) == [ErrorReply(code)]
    assert listed(bench) == before


def test_settings_are_kept_as_grbl_keeps_them() -> None:
    bench = Bench(grbl_plotter_config())
    assert bench.do("$1=256", "$4=7", "$11=0.0126", "$30=1000.6", "$110=1234.5678") == [Ok()] * 5
    now = listed(bench)
    assert now["$1"] == "0"  # one byte: 256 wraps
    assert now["$4"] == "1"  # a switch
    assert now["$11"] == "0.013"  # three decimals printed
    assert now["$30"] == "1001"  # RPM: none
    assert now["$110"] == "1234.568"
    assert list(now) == [f"${n}" for n in (0, 1, 2, 3, 4, 5, 6, 10, 11, 12, 13, 20, 21,
                                                   22, 23, 24, 25, 26, 27, 30, 31, 32)] + [
        f"${100 + 10 * g + a}" for g in range(4) for a in range(3)
    ]  # fmt: skip


def test_homing_off_turns_soft_limits_off() -> None:
    bench = Bench(grbl_plotter_config())
    assert bench.do("$22=1", "$20=1") == [Ok(), Ok()]
    assert bench.do("$22=0") == [Ok()]
    assert listed(bench)["$20"] == "0"


def test_no_setting_is_written_or_listed_while_the_machine_moves() -> None:
    bench = Bench(grbl_plotter_config())
    bench.send("G1 X50 F3000")
    bench.run(0.2)
    assert bench.fw.state == "Run"
    bench.send("$110=500", "$$")
    replies = bench.run(0.05)
    assert [r for _, r in replies if isinstance(r, ErrorReply)] == [ErrorReply(8), ErrorReply(8)]
    bench.run_until_idle()
    assert listed(bench)["$110"] != "500.000"


def test_settings_may_be_written_in_alarm_as_grbl_allows() -> None:
    bench = Bench(grbl_plotter_config())
    bench.fw.trigger_alarm(1)
    bench.fw.receive(b"\x18")  # a limit's alarm answers nothing until its reset
    bench.replies()
    assert bench.fw.state == "Alarm"
    assert bench.do("$1=100") == [Ok()]
    assert listed(bench)["$1"] == "100"


@given(st.floats(min_value=0, max_value=4000, allow_nan=False).map(lambda v: round(v, 3)))
def test_a_decimal_setting_reads_back_as_written_to_three_decimals(value: float) -> None:
    stored = grbl_settings.read_float(f"{value:.3f}")
    assert stored is not None and stored[1] == ""
    assert float(grbl_settings.print_float(stored[0], 3)) == pytest.approx(value, abs=0.0011)
