"""The winder's geometry exactly as its firmware computes it (issue 34).

The firmware's lines, as the audit quotes them (FIDELITY S0-19, S0-26):

* the gap the needle passes through between nails ``f - 1`` and ``f`` is the
  direction of their midpoint: ``argument_rad_nula_2pi(xy_na_bod((f.x+f_minus_1.x)/2.0,
  (f.y+f_minus_1.y)/2.0))``, not the angle halfway between the two nails (they agree on
  a circle, and differ by 0.55° on a 30-nail triangle, 4.07° on an 8-nail square);
* the winding starts with the needle out at ``polomer_matrice_cm + 2.0``: 2 cm beyond
  the board's edge, not beyond the first nail;
* its drivers run 8 microsteps, and Z is a 12 mm screw (S0-27).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from app.jobs.formats.string_art.geometry import half_gaps, nail_polar, nail_positions
from app.jobs.formats.string_art.program import build_program
from app.jobs.formats.string_art.reader import StringArtJob, StringArtParams
from app.jobs.program import OpKind
from app.profiles import load_profile
from protocol.emulator.gcode_machine import string_art_config

#: (tvar, nails, radius cm): a triangle, a square and a circle.
BOARDS = [(3, 30, 20.0), (4, 8, 20.0), (0, 24, 15.0)]


def firmware_gap_deg(xy: np.ndarray, f: int) -> float:
    """``argument_rad_nula_2pi(xy_na_bod((f.x+f_minus_1.x)/2.0, (f.y+f_minus_1.y)/2.0))``."""
    f_minus_1 = (f - 1) % len(xy)
    x = (xy[f][0] + xy[f_minus_1][0]) / 2.0
    y = (xy[f][1] + xy[f_minus_1][1]) / 2.0
    return math.degrees(math.atan2(y, x)) % 360.0


def mean_gap_deg(angles: np.ndarray, f: int) -> float:
    """StepDeck's former gap: halfway between the two nails' angles."""
    span = (angles[f] - angles[f - 1]) % 360.0
    return float(angles[f - 1] + span / 2.0) % 360.0


def _same_angle(a: float, b: float) -> float:
    return abs((a - b + 180.0) % 360.0 - 180.0)


@pytest.mark.parametrize(("tvar", "nails", "radius_cm"), BOARDS)
def test_s0_26_the_gap_between_two_nails_is_the_direction_of_their_midpoint(
    tvar: int, nails: int, radius_cm: float
) -> None:
    xy = nail_positions(tvar, nails, radius_cm)
    angles, _radii = nail_polar(tvar, nails, radius_cm)
    before, after = half_gaps(angles, xy)
    worst = 0.0
    for f in range(nails):
        gap = firmware_gap_deg(xy, f)
        assert _same_angle(float(angles[f] - before[f]), gap) < 1e-9  # the gap before f
        assert _same_angle(float(angles[f - 1] + after[f - 1]), gap) < 1e-9
        worst = max(worst, _same_angle(gap, mean_gap_deg(angles, f)))
    # What the old halfway angle got wrong, as the audit measured it.
    expected = {3: 0.55, 4: 4.07, 0: 0.0}[tvar]
    assert worst == pytest.approx(expected, abs=0.005)


@pytest.mark.parametrize(("tvar", "nails", "radius_cm"), BOARDS)
def test_s0_26_every_wrap_turns_between_the_firmwares_gaps(
    tvar: int, nails: int, radius_cm: float
) -> None:
    """The program's turn beside a nail and its wrap end at the firmware's gaps."""
    sequence = [0, nails // 2, 1, nails // 3, nails - 1, 2, nails // 2 + 1]
    job = StringArtJob(StringArtParams(tvar, nails, radius_cm), tuple(sequence))
    program = build_program(job)
    xy = job.nail_positions()
    moves = np.zeros(len(program), dtype=bool)
    moves[program.indices_of(OpKind.MOVE)] = True
    for entry in range(1, len(sequence)):
        turn, _out, wrap, _in = np.flatnonzero((program.entry_of_op == entry) & moves)
        nail = sequence[entry]
        gaps = {firmware_gap_deg(xy, nail), firmware_gap_deg(xy, (nail + 1) % nails)}
        a_turn = program[int(turn)].target["A"] % 360.0
        a_wrap = program[int(wrap)].target["A"] % 360.0
        assert min(_same_angle(a_turn, g) for g in gaps) < 1e-6
        assert min(_same_angle(a_wrap, g) for g in gaps) < 1e-6
        assert _same_angle(a_turn, a_wrap) > 1e-6  # across the nail, gap to gap


@pytest.mark.parametrize(("tvar", "nails", "radius_cm"), BOARDS)
def test_s0_19_the_winding_starts_out_at_the_board_radius_plus_2_cm(
    tvar: int, nails: int, radius_cm: float
) -> None:
    """``polomer_matrice_cm + 2.0``: the board's radius, not the first nail's."""
    job = StringArtJob(StringArtParams(tvar, nails, radius_cm), (0, nails // 2))
    program = build_program(job)
    start = program.operations[program.wait_index + 1]
    assert start.target == {"X": pytest.approx(radius_cm * 10.0 + 20.0)}
    assert program.needle_out_radius_mm == pytest.approx(radius_cm * 10.0 + 20.0)
    xy = job.nail_positions()
    turn = program.operations[program.wait_index + 2]
    assert _same_angle(turn.target["A"] % 360.0, firmware_gap_deg(xy, 1)) < 1e-9


def test_s0_27_the_profile_has_the_firmwares_microsteps_and_leads() -> None:
    """8 microsteps on every driver and a 12 mm screw on Z; the steps per unit are the
    emulated winder's (A 9600 a turn, X 32/mm, Z 133.3/mm)."""
    profile = load_profile("string-art")
    axes = {axis.name: axis for axis in profile.axes}
    assert {name: axis.microsteps for name, axis in axes.items()} == {"A": 8, "X": 8, "Z": 8}
    assert axes["Z"].lead == 12.0
    emulated = dict(zip(string_art_config().axes, string_art_config().steps_per_unit, strict=True))
    for name, axis in axes.items():
        per_unit = axis.steps_per_rev * axis.microsteps / axis.lead
        assert per_unit == pytest.approx(emulated[name], rel=5e-4)
