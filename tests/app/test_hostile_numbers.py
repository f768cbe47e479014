"""Siblings of issue 30's two hostile files, generated: huge, NaN-like and exponent numbers,
repeat counts of any size, and M-code loops, through ``stepdeck check``.

Whatever the number, the file is loaded or refused with ``file:line: reason``,
quickly and without building what it asks for; a refusal never shows a NaN
travel.  (The corpus, tests/helpers/hostile_corpus.py, holds the fixed cases.)
"""

from __future__ import annotations

import io
import re
import tempfile
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from app.cli import check
from app.jobs.formats.excellon import reader

#: The hole bound the repeat tests run under (the real one, reader.MAX_HOLES, is 50 000: a
#: file near it takes seconds to check, too long for a hundred examples).
MAX_HOLES = 300

HEAD = "M48\nMETRIC,TZ\nT01C0.8\n%\nT01\nX1.0Y1.0\n"
REFUSAL = re.compile(r"^[\w.-]+:\d+: \S")


def _check(name: str, text: str, profile: str) -> tuple[int, str]:
    with tempfile.TemporaryDirectory() as folder, pytest.MonkeyPatch.context() as patch:
        patch.setattr(reader, "MAX_HOLES", MAX_HOLES)
        path = Path(folder) / name
        path.write_text(text)
        out, err = io.StringIO(), io.StringIO()
        status = check.main([str(path), "--profile", profile], out, err)
    return status, out.getvalue()


def _no_nan_travel(out: str) -> None:
    for bad in ("nan…", "…nan", "inf…", "…inf"):
        assert bad not in out, out


counts = st.one_of(
    st.integers(0, 12),
    st.integers(MAX_HOLES - 2, MAX_HOLES + 2),
    st.integers(10**6, 10**12),
    st.just(999_999_999),
    st.integers(1, 400).map(lambda n: int("9" * n)),
)


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(counts, st.sampled_from(["X0.01", "Y0.01", "X0.01Y0.01", ""]), st.booleans())
def test_any_repeat_count_is_bounded_before_use(count: int, step: str, zeros: bool) -> None:
    digits = ("000" if zeros else "") + str(count)
    status, out = _check("rep.drl", HEAD + f"R{digits}{step}\nM30\n", "pcb-drill")
    first = out.splitlines()[0]
    if count > MAX_HOLES - 1:  # the hole before the repeat counts too
        assert status == check.REFUSED
        assert first.startswith("rep.drl:7: ") and ("repeat" in first or "holes" in first), first
    else:
        assert status == check.OK, out
        assert first.endswith(f": {1 + 2 * (1 + count)} operations"), first


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.lists(st.integers(1, 180), min_size=1, max_size=4))
def test_repeats_add_up_to_the_bound(each: list[int]) -> None:
    lines = "".join(f"R{n}X0.01\n" for n in each)
    status, out = _check("rep.drl", HEAD + lines + "M30\n", "pcb-drill")
    total = 1 + sum(each)
    if total > MAX_HOLES:
        assert status == check.REFUSED
        running, line = 1, 6
        for n in each:
            running, line = running + n, line + 1
            if running > MAX_HOLES:
                break
        assert out.startswith(f"rep.drl:{line}: "), out.splitlines()[0]
    else:
        assert status == check.OK, out.splitlines()[0]


numbers = st.one_of(
    st.from_regex(r"\A[-+]?[0-9]{1,3}(\.[0-9]{0,3})?[eE][-+]?[0-9]{1,3}\Z"),
    st.integers(1, 75).map(lambda n: "9" * n),
    st.sampled_from(["nan", "NaN", "inf", "-inf", "Infinity", "1e308", "1E-400", "0x10", "1_0"]),
    st.floats(allow_nan=True, allow_infinity=True).map(repr),
)


@settings(max_examples=120, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.sampled_from("XYFPSIJR"), numbers, st.sampled_from(["G1", "G0", "G2", "G4", ""]))
def test_gcode_numbers_of_any_spelling_are_loaded_or_refused_on_their_line(
    letter: str, number: str, command: str
) -> None:
    text = f"G0 X1 Y1 F1000\n{command} {letter}{number}\n"
    status, out = _check("n.gcode", text, "grbl-plotter")
    _no_nan_travel(out)
    if status == check.REFUSED:
        first = out.splitlines()[0]
        assert REFUSAL.match(first) and first.startswith("n.gcode:2: "), first
        if re.search(r"\d[eE][-+]?\d", number) and letter in "XY" and command in ("G0", "G1"):
            assert "exponent" in out, out  # a straight move's only fault: it is read as E…
    else:
        assert status == check.OK, out


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.sampled_from(["M98", "M99", "M47", "M30", "M2", "M97", "G65", "M198"]),
    st.sampled_from(["", " P1", " P100 L999999999", " L" + "9" * 30, " P1e308"]),
    st.sampled_from(["grbl-plotter", "corexy-plotter"]),
)
def test_m_code_loops_never_run(code: str, args: str, profile: str) -> None:
    """Subprogram calls and program repeats: no G-code dialect here loops; each is refused
    on its line or is the program's end, and the check ends at once."""
    status, out = _check("loop.gcode", f"G0 X1 Y1 F1000\n{code}{args}\nG1 X2 Y2\n", profile)
    _no_nan_travel(out)
    if status == check.REFUSED:
        assert out.startswith("loop.gcode:2: ") or out.startswith("loop.gcode:3: "), out
    else:
        assert status == check.OK
        assert re.search(r": [23] operations", out.splitlines()[0]), out


@settings(max_examples=80, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    st.one_of(
        numbers,
        st.text(alphabet="0123456789.+-eE", min_size=1, max_size=12),
    ),
    st.sampled_from(["X{0}Y1.0", "X1.0Y{0}", "R2X{0}", "X1.0Y1.0G85X{0}Y1.0"]),
)
def test_excellon_coordinates_of_any_spelling_are_loaded_or_refused_on_their_line(
    number: str, template: str
) -> None:
    status, out = _check("x.drl", HEAD + template.format(number) + "\nM30\n", "pcb-drill")
    _no_nan_travel(out)
    assert "could not convert" not in out  # Python's words are not a reason
    if status == check.REFUSED:
        first = out.splitlines()[0]
        assert first.startswith("x.drl:7: ") and REFUSAL.match(first), first
    else:
        assert status == check.OK, out
