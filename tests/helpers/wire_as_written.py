"""A profile whose job lines go on the wire as written, not compact.

The wire-fault scenarios these tests replay (relay seeds) were met with lines
as written: a space flipped into a feed hold, a line cut after ``"G1 X"``, a
number of lines still waiting to go.  Replayed on compact lines, the fault
would land elsewhere; the scenarios keep the wire they were found on (a
profile may send lines so: ``[gcode] compact = false``).
"""

from __future__ import annotations

from dataclasses import replace

from app.profiles import MachineProfile


def as_written(profile: MachineProfile) -> MachineProfile:
    """``profile`` with its G-code job lines sent as written."""
    if profile.gcode is None:
        return profile
    return replace(profile, gcode=replace(profile.gcode, compact=False))
